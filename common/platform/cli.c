/* cli.c - see cli.h. */
#include "cli.h"

#include "data_dir.h"
#include "input_script.h"
#include "keys.h"
#include "log.h"
#include "progress.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>


int cli_choice_index(const char *const *choices, const char *value)
{
    if (!choices || !value)
        return -1;
    for (int i = 0; choices[i]; i++)
        if (strcmp(choices[i], value) == 0)
            return i;
    return -1;
}

bool cli_parse_int(const char *s, long lo, long hi, int *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (errno || end == s || *end || v < lo || v > hi)
        return false;
    *out = (int)v;
    return true;
}

bool cli_parse_double(const char *s, double lo, double hi, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (errno || end == s || *end || !isfinite(v) || v < lo || v > hi)
        return false;
    *out = v;
    return true;
}

static bool parse_size(const char *s, int *w, int *h)
{
    char buf[64];
    const char *x = strchr(s, 'x');
    if (!x || (size_t)(x - s) >= sizeof buf)
        return false;
    memcpy(buf, s, (size_t)(x - s));
    buf[x - s] = '\0';
    return cli_parse_int(buf, 1, CLI_MAX_SIZE, w) && cli_parse_int(x + 1, 1, CLI_MAX_SIZE, h);
}

static int usage_error(const cli_desc *desc, const char *fmt, const char *arg)
{
    char msg[512];
    snprintf(msg, sizeof msg, fmt, arg);
    log_error("%s: %s (see --help)", desc->program, msg);
    return EXIT_CODE_USAGE;
}

/* "--name value" or "--name=value"; returns the value or NULL. */
static const char *option_value(int argc, char **argv, int *i, const char *name)
{
    const char *a = argv[*i];
    size_t n = strlen(name);
    if (strncmp(a, name, n) != 0)
        return NULL;
    if (a[n] == '=')
        return a + n + 1;
    if (a[n] == '\0' && *i + 1 < argc)
        return argv[++*i];
    return NULL;
}

static bool is_option(const char *arg, const char *name)
{
    size_t n = strlen(name);
    return strncmp(arg, name, n) == 0 && (arg[n] == '\0' || arg[n] == '=');
}

const char *cli_extra_value(const cli_desc *desc, const cli_options *options, const char *name)
{
    for (int i = 0; i < CLI_MAX_EXTRAS && desc->extras[i].name; i++)
        if (strcmp(desc->extras[i].name, name) == 0)
            return options->extra_values[i];
    return NULL;
}

/* Options that take a number: where it goes, its range, and what the message says it must be. */
typedef enum number_kind { NUMBER_INT, NUMBER_SEED, NUMBER_FLOAT, NUMBER_DOUBLE } number_kind;
static const struct number_option {
    const char *name;
    number_kind kind;
    size_t offset;
    double lo, hi;
    const char *expected;
} number_options[] = {
    {"--frames", NUMBER_INT, offsetof(cli_options, frames), 1, INT_MAX, "a whole number >= 1"},
    {"--warmup", NUMBER_INT, offsetof(cli_options, warmup), 0, 100000, "a whole number >= 0"},
    {"--lights", NUMBER_INT, offsetof(cli_options, lights), 0, 1000000, "0..1000000"},
    {"--seed", NUMBER_SEED, offsetof(cli_options, seed), 0, INT_MAX, "a whole number >= 0"},
    {"--time", NUMBER_FLOAT, offsetof(cli_options, time), -1e6, 1e6, "seconds"},
    {"--resize-cycle", NUMBER_INT, offsetof(cli_options, resize_cycle), 0, 100000, "0..100000"},
    {"--minimise-cycle", NUMBER_INT, offsetof(cli_options, minimise_cycle), 0, 1000, "0..1000"},
    {"--cutoff", NUMBER_DOUBLE, offsetof(cli_options, cutoff), 0, 1e6, "a number >= 0"},
    {"--anisotropy", NUMBER_INT, offsetof(cli_options, anisotropy), 1, 16, "a whole number from 1 to 16"},
};

/* Options without a value. */
static const struct flag_option {
    const char *name;
    size_t offset;
} flag_options[] = {
    {"--bench", offsetof(cli_options, bench)},
    {"--paused", offsetof(cli_options, paused)},
    {"--gl-debug", offsetof(cli_options, gl_debug)},
    {"--verbose", offsetof(cli_options, verbose)},
    {"--quiet", offsetof(cli_options, quiet)},
    {"--gl-info", offsetof(cli_options, gl_info)},
    {"--overlay", offsetof(cli_options, overlay)},
};

#define COUNT(array) ((int)(sizeof array / sizeof array[0]))

static void set_defaults(const cli_desc *desc, cli_options *out)
{
    memset(out, 0, sizeof *out);
    out->width = 800;
    out->height = 600;
    out->frames = -1;
    out->warmup = 3;
    out->renderer = desc->renderers ? desc->renderers[0] : NULL;
    out->view = desc->views ? desc->views[0] : NULL;
    out->lights = -1;
    out->seed = 1;
    out->cutoff = desc->default_cutoff;
#ifndef NDEBUG
    out->gl_debug = true;
#endif
    for (int i = 0; i < CLI_MAX_EXTRAS && desc->extras[i].name; i++)
        out->extra_values[i] = desc->extras[i].default_value;
}

static bool store_number(const struct number_option *o, const char *v, cli_options *out)
{
    char *field = (char *)out + o->offset;
    int n;
    double d;
    switch (o->kind) {
    case NUMBER_INT: return cli_parse_int(v, (long)o->lo, (long)o->hi, (int *)(void *)field);
    case NUMBER_SEED:
        if (!cli_parse_int(v, (long)o->lo, (long)o->hi, &n))
            return false;
        *(uint32_t *)(void *)field = (uint32_t)n;
        return true;
    case NUMBER_FLOAT:
        if (!cli_parse_double(v, o->lo, o->hi, &d))
            return false;
        *(float *)(void *)field = (float)d;
        return true;
    case NUMBER_DOUBLE: return cli_parse_double(v, o->lo, o->hi, (double *)(void *)field);
    }
    return false;
}

/* A flag or a number option at argv[*i]: true when it is one (a bad value sets *rc), false if not. */
static bool parse_table_option(int argc, char **argv, int *i, const cli_desc *desc, cli_options *out, int *rc)
{
    const char *a = argv[*i], *v;
    for (int k = 0; k < COUNT(flag_options); k++) {
        if (strcmp(a, flag_options[k].name) == 0) {
            *(bool *)(void *)((char *)out + flag_options[k].offset) = true;
            return true;
        }
    }
    for (int k = 0; k < COUNT(number_options); k++) {
        const struct number_option *o = &number_options[k];
        if (!is_option(a, o->name))
            continue;
        if (!(v = option_value(argc, argv, i, o->name)) || !store_number(o, v, out)) {
            char fmt[128];
            snprintf(fmt, sizeof fmt, "bad %s '%%s': expected %s", o->name, o->expected);
            *rc = usage_error(desc, fmt, v ? v : "");
        }
        return true;
    }
    return false;
}

/* `value` when it is one of `choices`; otherwise a message that lists them. */
static int parse_choice(const cli_desc *desc, const char *what, const char *value, const char *const *choices,
                        const char **out)
{
    if (value && cli_choice_index(choices, value) >= 0) {
        *out = value;
        return EXIT_CODE_OK;
    }
    char fmt[400];
    int n = snprintf(fmt, sizeof fmt, "unknown %s '%%s' (one of:", what);
    for (int k = 0; choices[k] && n > 0 && n < (int)sizeof fmt - 64; k++)
        n += snprintf(fmt + n, sizeof fmt - (size_t)n, " %s", choices[k]);
    snprintf(fmt + n, sizeof fmt - (size_t)n, ")");
    return usage_error(desc, fmt, value ? value : "");
}

/* "1, 2, 4, 8, 16 or 32": every power of two in [lo, hi], written out. */
static void powers_of_two(double lo, double hi, char *out, size_t size)
{
    size_t n = 0;
    out[0] = '\0';
    for (double p = 1; p <= hi && n + 24 < size; p *= 2)
        if (p >= lo)
            n += (size_t)snprintf(out + n, size - n, "%s%.0f", n ? ", " : "", p);
    char *last = strrchr(out, ',');
    if (last) { /* "1, 2, 4" -> "1, 2 or 4" */
        char tail[32];
        snprintf(tail, sizeof tail, " or%s", last + 1);
        snprintf(last, size - (size_t)(last - out), "%s", tail);
    }
}

/* A chapter's number option: the value's shape and range, with the range written out. */
static int parse_extra_number(const cli_desc *desc, const cli_extra *e, const char *v, const char **out)
{
    double d = 0.0;
    bool ok = cli_parse_double(v, e->lo, e->hi, &d);
    if (ok && e->number != CLI_REAL)
        ok = d == floor(d) && strpbrk(v, ".eExX") == NULL; /* "4.0" or "4e0" is not written as a count */
    if (ok && e->number == CLI_POWER_OF_TWO)
        ok = d >= 1 && frexp(d, &(int){0}) == 0.5;
    if (ok) {
        *out = v;
        return EXIT_CODE_OK;
    }
    char fmt[400], range[200];
    if (e->number == CLI_POWER_OF_TWO)
        powers_of_two(e->lo, e->hi, range, sizeof range);
    else
        snprintf(range, sizeof range, "%s from %.15g to %.15g", e->number == CLI_WHOLE ? "a whole number" : "a number",
                 e->lo, e->hi);
    snprintf(fmt, sizeof fmt, "bad --%s '%%s': expected %s", e->name, range);
    return usage_error(desc, fmt, v);
}

/* --NAME VALUE of the chapter's own options. */
static int parse_extra(int argc, char **argv, int *i, const cli_desc *desc, cli_options *out)
{
    const char *a = argv[*i], *v;
    for (int k = 0; k < CLI_MAX_EXTRAS && desc->extras[k].name; k++) {
        char opt[80];
        snprintf(opt, sizeof opt, "--%s", desc->extras[k].name);
        if (!is_option(a, opt))
            continue;
        if (!(v = option_value(argc, argv, i, opt)))
            return usage_error(desc, "%s needs a value", opt);
        if (desc->extras[k].number != CLI_TEXT)
            return parse_extra_number(desc, &desc->extras[k], v, &out->extra_values[k]);
        if (!desc->extras[k].choices) {
            out->extra_values[k] = v;
            return EXIT_CODE_OK;
        }
        char what[90];
        snprintf(what, sizeof what, "%s value", opt);
        return parse_choice(desc, what, v, desc->extras[k].choices, &out->extra_values[k]);
    }
    return usage_error(desc, "unknown option '%s'", a);
}

/* --headless[=egl|osmesa]; returns false when argv[i] is not one. */
static bool parse_headless(const char *a, cli_options *out)
{
    if (strcmp(a, "--headless") == 0 || strcmp(a, "--headless=egl") == 0)
        out->backend = BACKEND_EGL;
    else if (strcmp(a, "--headless=osmesa") == 0)
        out->backend = BACKEND_OSMESA;
    else
        return false;
    out->headless = true;
    return true;
}

/* A file name, a renderer or a view. */
static int parse_text_option(int argc, char **argv, int *i, const cli_desc *desc, cli_options *out)
{
    const char *a = argv[*i], *v;
    static const struct {
        const char *name;
        size_t offset;
    } paths[] = {{"--screenshot", offsetof(cli_options, screenshot)},
                 {"--scene", offsetof(cli_options, scene_path)},
                 {"--data-dir", offsetof(cli_options, data_dir)},
                 {"--script", offsetof(cli_options, script)}};
    for (int k = 0; k < COUNT(paths); k++) {
        if (!is_option(a, paths[k].name))
            continue;
        if (!(v = option_value(argc, argv, i, paths[k].name)) || !*v)
            return usage_error(desc, "%s needs a file name", paths[k].name);
        *(const char **)(void *)((char *)out + paths[k].offset) = v;
        return EXIT_CODE_OK;
    }
    if (is_option(a, "--camera")) {
        if (!(out->camera = option_value(argc, argv, i, "--camera")) || !*out->camera)
            return usage_error(desc, "%s needs a pose, e.g. \"eye 0 2 6 target 0 0 0\"", "--camera");
        return EXIT_CODE_OK;
    }
    if (is_option(a, "--falloff")) {
        static const char *const falloffs[] = {"hard", "windowed", NULL};
        return parse_choice(desc, "falloff", option_value(argc, argv, i, "--falloff"), falloffs, &out->falloff);
    }
    if (is_option(a, "--gbuffer"))
        return parse_choice(desc, "G-buffer layout", option_value(argc, argv, i, "--gbuffer"),
                            gbuffer_layout_names, &out->gbuffer);
    if (is_option(a, "--compare")) {
        static const char *const modes[] = {"off", "split", "difference", NULL};
        return parse_choice(desc, "compare mode", option_value(argc, argv, i, "--compare"), modes, &out->compare);
    }
    if (is_option(a, "--renderer")) {
        if (!desc->renderers)
            return usage_error(desc, "%s has a single renderer: --renderer is not available", desc->program);
        v = option_value(argc, argv, i, "--renderer");
        return parse_choice(desc, "renderer", v, desc->renderers, &out->renderer);
    }
    if (is_option(a, "--view")) {
        if (!desc->views)
            return usage_error(desc, "%s has no views: --view is not available", desc->program);
        v = option_value(argc, argv, i, "--view");
        return parse_choice(desc, "view", v, desc->views, &out->view);
    }
    return parse_extra(argc, argv, i, desc, out);
}

/* One argument (and its value): an exit code, EXIT_CODE_OK to go on. */
static int parse_argument(int argc, char **argv, int *i, const cli_desc *desc, cli_options *out)
{
    const char *a = argv[*i], *v;
    int rc = EXIT_CODE_OK;
    if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
        cli_print_help(desc, stdout);
        return CLI_PARSE_DONE;
    }
    if (parse_headless(a, out) || parse_table_option(argc, argv, i, desc, out, &rc))
        return rc;
    if (strncmp(a, "--headless=", 11) == 0)
        return usage_error(desc, "unknown headless backend '%s' (egl or osmesa)", a + 11);
    if (is_option(a, "--size")) {
        if (!(v = option_value(argc, argv, i, "--size")))
            return usage_error(desc, "%s needs a value WxH", a);
        if (!parse_size(v, &out->width, &out->height))
            return usage_error(desc, "bad --size '%s': expected WxH, each 1..65536", v);
        return EXIT_CODE_OK;
    }
    if (strncmp(a, "--", 2) == 0)
        return parse_text_option(argc, argv, i, desc, out);
    return usage_error(desc, "unexpected argument '%s'", a);
}

/* --scene or --script: found in the current folder or the data folder, and a regular file. */
static int find_input(const char *option, const char *what, const char **path, char *found, size_t size)
{
    char tried[9000];
    struct stat st;
    if (!data_dir_find(*path, NULL, found, size, tried, sizeof tried)) {
        log_error("%s: cannot open %s: No such file or directory (looked for %s)", *path, what, tried);
        return EXIT_CODE_USAGE;
    }
    if (stat(found, &st) != 0 || !S_ISREG(st.st_mode)) {
        log_error("%s: cannot open %s: not a regular file%s (%s)", found, what,
                  S_ISDIR(st.st_mode) ? " but a folder" : "", option);
        return EXIT_CODE_USAGE;
    }
    *path = found;
    return EXIT_CODE_OK;
}

/* --screenshot: its folder found in the current folder, then the data folder; the file itself is
 * written later (atomically, image.c), but a folder that is not there is known now. */
static int find_output(const char **path, char *found, size_t size)
{
    char why[9200];
    if (!data_dir_find_output(*path, found, size, why, sizeof why)) {
        log_error("cannot write %s: %s (--screenshot)", *path, why);
        return EXIT_CODE_USAGE;
    }
    *path = found;
    return EXIT_CODE_OK;
}

/* The files the options name: there, readable, and (a script) well formed, before any work. */
static int check_inputs(cli_options *out)
{
    data_dir_set(out->data_dir);
    progress_set_quiet(out->quiet);
    int rc = EXIT_CODE_OK;
    if (out->scene_path)
        rc = find_input("--scene", "scene", &out->scene_path, out->scene_found, sizeof out->scene_found);
    if (rc == EXIT_CODE_OK && out->script)
        rc = find_input("--script", "script", &out->script, out->script_found, sizeof out->script_found);
    if (rc == EXIT_CODE_OK && out->screenshot)
        rc = find_output(&out->screenshot, out->screenshot_found, sizeof out->screenshot_found);
    input_script s;
    if (rc == EXIT_CODE_OK && out->script) {
        if (!input_script_load(out->script, &s))
            return EXIT_CODE_USAGE;
        input_script_destroy(&s);
    }
    return rc;
}

int cli_parse(int argc, char **argv, const cli_desc *desc, cli_options *out)
{
    set_defaults(desc, out);
    for (int i = 1; i < argc; i++) {
        int rc = parse_argument(argc, argv, &i, desc, out);
        if (rc != EXIT_CODE_OK)
            return rc;
    }
    if (out->frames < 0)
        out->frames = out->bench ? 10 : out->headless ? 1 : 0;
    if (out->resize_cycle > 0 && out->bench)
        return usage_error(desc, "%s changes the size between timed frames: not with --bench",
                           "--resize-cycle");
    if (out->minimise_cycle > 0 && out->headless)
        return usage_error(desc, "%s minimises the window: not with --headless", "--minimise-cycle");
    /* --compare is timed apart (forward as one pass the chapter's figure leaves out); these are not */
    if ((out->script || out->overlay) && out->bench)
        return usage_error(desc, "%s draws more than the chapter's frame: not with --bench",
                           out->script ? "--script" : "--overlay");
    if (out->minimise_cycle > 0 && out->bench)
        return usage_error(desc, "%s stops the frames it would time: not with --bench", "--minimise-cycle");
    return check_inputs(out);
}
