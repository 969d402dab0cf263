/* fuzz_cli.c - libFuzzer target for the shared command-line parser (cli_parse).
 *
 *   LLVMFuzzerTestOneInput(data, size)   split the bytes into arguments at newlines and NULs,
 *                                        parse them with a chapter-like description, and check
 *                                        the promises cli.h makes about a successful parse
 *
 * A seed file is one argument per line, so the corpus is readable: see tests/fuzz/corpus_cli/.
 */
#include "cli.h"

#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "fuzz_util.h"

#define MAX_ARGS 64

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static const char *const MODES[] = {"on", "off", NULL};

static const cli_desc DESC = {
    .program = "fuzz_cli",
    .summary = "command-line fuzzing target",
    .renderers = (const char *const[]){"deferred", "forward", "forward-naive", NULL},
    .views = (const char *const[]){"final", "albedo", "normal", "depth", NULL},
    .extras = {{.name = "mode", .metavar = "M", .help = "a choice", .choices = MODES, .default_value = "on"},
               {.name = "label", .metavar = "TEXT", .help = "free text"}},
};

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = fuzz_text(data, size);
    if (!text)
        return 0;

    char *argv[MAX_ARGS + 2];
    int argc = 0;
    argv[argc++] = "fuzz_cli";
    for (size_t i = 0, start = 0; i <= size && argc < MAX_ARGS + 1; i++) {
        if (i == size || text[i] == '\n' || text[i] == '\0') {
            text[i] = '\0';
            argv[argc++] = text + start;
            start = i + 1;
        }
    }
    argv[argc] = NULL;

    cli_options o;
    int rc = cli_parse(argc, argv, &DESC, &o);
    if (rc != EXIT_CODE_OK && rc != EXIT_CODE_USAGE && rc != CLI_PARSE_DONE)
        abort();
    if (rc == EXIT_CODE_OK) {
        /* What the rest of the course trusts once the parser said yes. */
        if (o.width < 1 || o.width > CLI_MAX_SIZE || o.height < 1 || o.height > CLI_MAX_SIZE)
            abort();
        if (o.frames < 0 || o.warmup < 0 || !(o.cutoff >= 0.0) || (o.scene_path && !*o.scene_path))
            abort(); /* no --scene: NULL, the data folder's default scene */
        if (cli_choice_index(DESC.renderers, o.renderer) < 0 || cli_choice_index(DESC.views, o.view) < 0)
            abort();
        /* --scene and --script were found, and are regular files. */
        struct stat st;
        if ((o.scene_path && (stat(o.scene_path, &st) != 0 || !S_ISREG(st.st_mode))) ||
            (o.script && (stat(o.script, &st) != 0 || !S_ISREG(st.st_mode))))
            abort();
        const char *mode = cli_extra_value(&DESC, &o, "mode");
        if (!mode || cli_choice_index(MODES, mode) < 0)
            abort();
        /* Every string the options point at must be readable. */
        size_t total = strlen(o.renderer) + strlen(o.view);
        const char *paths[] = {o.scene_path, o.screenshot, o.data_dir, o.camera, o.falloff};
        for (size_t i = 0; i < sizeof paths / sizeof paths[0]; i++)
            total += paths[i] ? strlen(paths[i]) : 0;
        const char *label = cli_extra_value(&DESC, &o, "label");
        if (label)
            total += strlen(label);
        (void)total;
    }
    free(text);
    return 0;
}
