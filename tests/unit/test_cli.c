/* test_cli.c - the shared command line: defaults, every option, and the mistakes it refuses. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "light.h"
#include "test_util.h"

static const cli_desc desc = {
    .program = "test",
    .summary = "test program",
    .renderers = (const char *const[]){"deferred", "forward", NULL},
    .views = (const char *const[]){"final", "albedo", "normal", NULL},
    .extras = {{.name = "tonemap", .metavar = "NAME", .help = "tone map",
                .choices = (const char *const[]){"none", "reinhard", NULL}, .default_value = "none"},
               {.name = "exposure", .metavar = "E", .help = "exposure", .default_value = "1"}},
    .default_cutoff = LIGHT_DEFAULT_CUTOFF,
};

static int parse(cli_options *o, const char *line)
{
    static char buf[512]; /* cli_options points into argv: keep it alive after parse() */
    char *argv[32];
    int argc = 0;
    snprintf(buf, sizeof buf, "test %s", line);
    for (char *t = strtok(buf, " "); t && argc < 31; t = strtok(NULL, " "))
        argv[argc++] = t;
    argv[argc] = NULL;
    /* stderr noise from refused options is expected here */
    return cli_parse(argc, argv, &desc, o);
}

static void test_defaults(void **state)
{
    (void)state;
    cli_options o;
    assert_int_equal(parse(&o, ""), EXIT_CODE_OK);
    assert_int_equal(o.width, 800);
    assert_int_equal(o.height, 600);
    assert_int_equal(o.frames, 0); /* window: until closed */
    assert_string_equal(o.renderer, "deferred");
    assert_string_equal(o.view, "final");
    assert_int_equal(o.lights, -1);
    assert_true(o.cutoff == LIGHT_DEFAULT_CUTOFF);
    assert_false(o.headless);
    assert_string_equal(cli_extra_value(&desc, &o, "tonemap"), "none");
    assert_string_equal(cli_extra_value(&desc, &o, "exposure"), "1");
    assert_int_equal(parse(&o, "--headless"), EXIT_CODE_OK);
    assert_int_equal(o.frames, 1); /* headless: one frame */
    assert_int_equal(o.backend, BACKEND_EGL);
    assert_int_equal(parse(&o, "--headless --bench"), EXIT_CODE_OK);
    assert_int_equal(o.frames, 10);
}

static void test_every_option(void **state)
{
    (void)state;
    cli_options o;
    assert_int_equal(parse(&o, "--headless=osmesa --size 320x240 --frames 5 --screenshot a.png "
                               "--scene assets/scenes/default.scene "
                               "--renderer forward --view normal --lights 64 --seed 9 --time 2.5 --cutoff 0 "
                               "--bench --warmup 2 --gl-debug --paused --tonemap reinhard --exposure=0.5"),
                     EXIT_CODE_OK);
    assert_int_equal(o.backend, BACKEND_OSMESA);
    assert_int_equal(o.width, 320);
    assert_int_equal(o.height, 240);
    assert_int_equal(o.frames, 5);
    assert_string_equal(o.screenshot, "a.png");
    /* In the current folder, or (from build/tests, where ctest runs it) in the data folder. */
    const char *tail = "/assets/scenes/default.scene";
    assert_true(strlen(o.scene_path) >= strlen(tail));
    assert_string_equal(o.scene_path + strlen(o.scene_path) - strlen(tail), tail);
    assert_string_equal(o.renderer, "forward");
    assert_string_equal(o.view, "normal");
    assert_int_equal(o.lights, 64);
    assert_int_equal(o.seed, 9);
    assert_float_equal(o.time, 2.5f, 0.0f);
    assert_true(o.cutoff == 0.0);
    assert_true(o.bench && o.gl_debug && o.paused);
    assert_int_equal(o.warmup, 2);
    assert_string_equal(cli_extra_value(&desc, &o, "tonemap"), "reinhard");
    assert_string_equal(cli_extra_value(&desc, &o, "exposure"), "0.5");
    assert_int_equal(parse(&o, "--size=1x1"), EXIT_CODE_OK);
    assert_int_equal(o.width, 1);
}

static void test_refused(void **state)
{
    (void)state;
    const char *bad[] = {"--size 0x0",       "--size 100000x100000", "--size 10",        "--size x10",
                         "--size 10x",       "--size -5x5",          "--frames -1",      "--frames 0",
                         "--frames 1.5",     "--cutoff -0.1",        "--cutoff nan",     "--cutoff inf",
                         "--lights -2",      "--lights 1e3",         "--seed -1",        "--time abc",
                         "--renderer fast",  "--view depth",         "--tonemap filmic", "--headless=vulkan",
                         "--bogus",          "stray",                "--size",           "--scene"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        cli_options o;
        int rc = parse(&o, bad[i]);
        if (rc != EXIT_CODE_USAGE)
            fail_msg("'%s' was accepted (rc %d)", bad[i], rc);
    }
}

static void test_help(void **state)
{
    (void)state;
    cli_options o;
    FILE *saved = stdout;
    stdout = fopen("/dev/null", "w");
    int rc = parse(&o, "--help");
    fclose(stdout);
    stdout = saved;
    assert_int_equal(rc, CLI_PARSE_DONE);
}

/* A chapter's number options are checked by the parser: their shape and range (chapter 13's
 * --samples, 11's --tile, 06's --exposure), before any context. */
static const cli_desc numbers = {
    .program = "numbers",
    .summary = "number options",
    .extras = {{"samples", "N", "samples", NULL, "4", CLI_POWER_OF_TWO, 1, 32},
               {"tile", "PIXELS", "tile", NULL, NULL, CLI_WHOLE, 1, 4096},
               {"exposure", "E", "exposure", NULL, "1", CLI_REAL, 1e-6, 1e6}},
};

static int parse_numbers(cli_options *o, const char *line)
{
    static char buf[256];
    char *argv[8];
    int argc = 0;
    snprintf(buf, sizeof buf, "numbers %s", line);
    for (char *t = strtok(buf, " "); t && argc < 7; t = strtok(NULL, " "))
        argv[argc++] = t;
    argv[argc] = NULL;
    return cli_parse(argc, argv, &numbers, o);
}

static void test_number_options(void **state)
{
    (void)state;
    cli_options o;
    const char *good[] = {"--samples 1", "--samples 8", "--samples=32", "--tile 1", "--tile 4096", "--exposure 0.25"};
    for (size_t i = 0; i < sizeof good / sizeof good[0]; i++)
        if (parse_numbers(&o, good[i]) != EXIT_CODE_OK)
            fail_msg("'%s' was refused", good[i]);
    assert_int_equal(parse_numbers(&o, "--samples 16 --tile 32"), EXIT_CODE_OK);
    assert_string_equal(cli_extra_value(&numbers, &o, "samples"), "16");
    const char *bad[] = {"--samples 3",  "--samples 2.5", "--samples 64",  "--samples 0",     "--samples 4.0",
                         "--samples 4e0", "--samples -4",  "--samples x",   "--tile 0",        "--tile 4097",
                         "--tile 1.5",   "--tile 0x10",   "--exposure 0",  "--exposure nan",  "--exposure 1e7"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        if (parse_numbers(&o, bad[i]) != EXIT_CODE_USAGE)
            fail_msg("'%s' was accepted", bad[i]);
}

/* --scene and --script: the current folder first, then the data folder; only regular files. */
static void test_input_files(void **state)
{
    (void)state;
    cli_options o;
    assert_int_equal(parse(&o, "--scene assets/scenes/city.scene"), EXIT_CODE_OK); /* via the data folder */
    assert_non_null(strstr(o.scene_path, "assets/scenes/city.scene"));
    FILE *f = fopen(o.scene_path, "r");
    assert_non_null(f);
    fclose(f);
    assert_int_equal(parse(&o, "--scene assets/scenes/none.scene"), EXIT_CODE_USAGE);
    assert_int_equal(parse(&o, "--scene /tmp"), EXIT_CODE_USAGE); /* a folder */
    assert_int_equal(parse(&o, "--script /tmp"), EXIT_CODE_USAGE);
    char dir[] = "/tmp/test_cli_XXXXXX", script[64], line[128];
    assert_non_null(mkdtemp(dir));
    snprintf(script, sizeof script, "%s/walk.script", dir);
    f = fopen(script, "w");
    assert_non_null(f);
    fputs("0 objects check\n", f); /* no mark before it: refused while parsing the command line */
    fclose(f);
    snprintf(line, sizeof line, "--script %s", script);
    assert_int_equal(parse(&o, line), EXIT_CODE_USAGE);
    f = fopen(script, "w");
    assert_non_null(f);
    fputs("0 objects mark\n1 objects check\n", f);
    fclose(f);
    assert_int_equal(parse(&o, line), EXIT_CODE_OK);
    assert_string_equal(o.script, script);
    /* --screenshot: its folder must be there (the current folder's, else the data folder's). */
    assert_int_equal(parse(&o, "--screenshot /nonexistent-folder/x.png"), EXIT_CODE_USAGE);
    assert_int_equal(parse(&o, "--screenshot /tmp"), EXIT_CODE_USAGE); /* a folder */
    assert_int_equal(parse(&o, "--screenshot /tmp/x.png"), EXIT_CODE_OK);
    assert_int_equal(parse(&o, "--screenshot assets/scenes/x.png"), EXIT_CODE_OK);
    assert_non_null(strstr(o.screenshot, "assets/scenes/x.png"));
    assert_int_equal(parse(&o, "--quiet"), EXIT_CODE_OK);
    assert_true(o.quiet);
    remove(script);
    rmdir(dir);
}

UNIT_TEST_MAIN(NULL, NULL, cmocka_unit_test(test_defaults), cmocka_unit_test(test_every_option),
               cmocka_unit_test(test_refused), cmocka_unit_test(test_help), cmocka_unit_test(test_number_options),
               cmocka_unit_test(test_input_files))
