/* cli.h - the one command line every chapter binary shares.
 *
 *   cli_parse(argc, argv, desc, options)   fill options; EXIT_CODE_* or CLI_PARSE_DONE (help printed)
 *   cli_print_help(desc, stream)           the --help text
 *   cli_parse_int(text, lo, hi, out)       the whole of `text` as an integer in [lo, hi]
 *   cli_parse_double(text, lo, hi, out)    the whole of `text` as a finite number in [lo, hi]
 *                                          (both false, without a message, when it is not)
 *
 * A chapter describes what it adds (renderers, views, extra options) in a
 * cli_desc; the parser knows the rest. Values are validated here, before any
 * context or work, so the rest of the course can trust them: numbers and their
 * ranges, choices, and the input files. A relative --scene or --script is
 * looked for in the current folder, then in the data folder (--data-dir is set
 * here for that); the script is read and checked whole (input_script.h).
 * --screenshot's folder is found the same way, and must exist.
 */
#ifndef COMMON_CLI_H
#define COMMON_CLI_H

#include "exit_code.h"
#include "gbuffer_layout_names.h"

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#define CLI_MAX_EXTRAS 10
#define CLI_MAX_SIZE 65536
#define CLI_DEFAULT_SCENE "assets/scenes/default.scene" /* relative to the data folder */ /* a sanity bound; the GL limit is checked once a context exists */

enum { CLI_PARSE_DONE = -1 }; /* cli_parse: --help was printed, exit 0 */

/* What a chapter's option takes when it has no choices: free text, or a number checked here. */
typedef enum cli_number {
    CLI_TEXT,
    CLI_REAL,         /* a finite number in [lo, hi] */
    CLI_WHOLE,        /* a whole number in [lo, hi] */
    CLI_POWER_OF_TWO, /* a whole number in [lo, hi] that is a power of two (sample counts) */
} cli_number;

/* An option a chapter adds: --NAME VALUE, VALUE one of choices (NULL-terminated), a number
 * (number, lo, hi), or free text. */
typedef struct cli_extra {
    const char *name;
    const char *metavar;
    const char *help;
    const char *const *choices;
    const char *default_value;
    cli_number number;
    double lo, hi;
} cli_extra;

typedef struct cli_desc {
    const char *program;             /* "03_fullscreen_phong" */
    const char *summary;             /* one sentence for --help */
    const char *const *renderers;    /* NULL-terminated; the first is the default */
    const char *const *views;        /* NULL-terminated or NULL; the first is the default */
    cli_extra extras[CLI_MAX_EXTRAS];
    double default_cutoff;           /* --cutoff's default (app_run sets the lighting model's) */
    const char *default_scene;       /* the scene that shows the chapter's lesson, relative to the
                                      * data folder; NULL: CLI_DEFAULT_SCENE */
} cli_desc;

typedef struct cli_options {
    backend_kind backend;
    bool headless;
    int width, height;
    int frames;           /* 0: until the window closes (headless: 1) */
    int warmup;           /* frames not timed by --bench */
    const char *screenshot;
    const char *scene_path; /* NULL: CLI_DEFAULT_SCENE in the data folder (common/base/data_dir.h) */
    const char *data_dir;   /* --data-dir, or NULL */
    const char *renderer;
    const char *view;
    int lights;           /* -1: the scene's own */
    uint32_t seed;
    float time;
    double cutoff;
    int anisotropy;       /* --anisotropy: most samples a texture lookup takes along its footprint; 0:
                             the course's default (common/gl/gpu_textures.h) */
    const char *falloff;  /* "hard" or "windowed"; NULL: the scene's (directive `falloff`) */
    const char *gbuffer;  /* one of gbuffer_layout_names (gbuffer_layout_names.h); NULL: the default (common/render/gbuffer.h) */
    const char *camera;   /* "eye X Y Z target X Y Z ...": replaces those of the scene's camera */
    bool bench;
    bool paused;          /* window: start with the animation stopped at --time */
    bool gl_debug;        /* KHR_debug on; a GL error fails the run */
    int resize_cycle;     /* resize N times after the first frame, then check for leaked GL objects */
    int minimise_cycle;   /* window: minimise and restore N times; no frame may be drawn while minimised */
    bool verbose;
    bool quiet;           /* no progress lines while slow frames run (common/base/progress.h) */
    bool gl_info;         /* print the context's renderer, version and limits, and exit */
    const char *script;   /* timed keys and mouse events (common/platform/input_script.h) */
    bool overlay;         /* the overlay on from the start, and in --screenshot */
    const char *compare;  /* "off", "split" or "difference": forward beside the chapter's renderer */
    const char *extra_values[CLI_MAX_EXTRAS];
    char scene_found[4200], script_found[4200]; /* where --scene and --script were found */
    char screenshot_found[4200];                /* --screenshot in the folder that was found */
} cli_options;

int cli_parse(int argc, char **argv, const cli_desc *desc, cli_options *out);
void cli_print_help(const cli_desc *desc, FILE *stream);
const char *cli_extra_value(const cli_desc *desc, const cli_options *options, const char *name);
int cli_choice_index(const char *const *choices, const char *value);
bool cli_parse_int(const char *text, long lo, long hi, int *out);
bool cli_parse_double(const char *text, double lo, double hi, double *out);

#endif
