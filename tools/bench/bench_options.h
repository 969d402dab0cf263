/* bench_options.h - the benchmark's command line: what it sweeps, how long it times, where it writes.
 *
 *   bench_options_parse(argc, argv, out)   defaults, then --quick, then every option in order;
 *                                          returns EXIT_CODE_OK, EXIT_CODE_USAGE (one line on stderr)
 *                                          or CLI_PARSE_DONE (after --help)
 *   bench_options_print_help(stream)       the --help text
 *   bench_options_find_scene(options, name, out, size)
 *                                          the file of a --scenes item: a path as given, else
 *                                          options->scene_dir/NAME.scene
 *   bench_options_label_scene(name, out, size)
 *                                          the name the results use: no folder, no .scene
 */
#ifndef TOOLS_BENCH_OPTIONS_H
#define TOOLS_BENCH_OPTIONS_H

#include "cli.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define MAX_LIST 32
#define NAME_MAX_LEN 64
#define LIGHTS_OWN (-1) /* the scene's own lights, as the scene file has them */

typedef struct bench_options {
    int lights[MAX_LIST];
    int light_list_count;
    char scenes[MAX_LIST][NAME_MAX_LEN];
    int scene_count;
    int renderers[MAX_LIST]; /* indices for bench_renderer_name() and friends */
    int renderer_count;
    double cutoffs[MAX_LIST]; /* in 1/256 units */
    int cutoff_count;
    char cutoff_scene[NAME_MAX_LEN];
    int cutoff_lights;
    char pbr_scenes[MAX_LIST][NAME_MAX_LEN]; /* metallic-roughness scenes, each with its own lights */
    int pbr_scene_count;                     /* 0: no PBR rows (--pbr-scenes none) */
    int pbr_renderers[MAX_LIST];
    int pbr_renderer_count;
    int width, height;
    int frames, warmup, min_frames;
    double max_frame_ms, case_budget_ms;
    int error_max_lights;
    uint32_t seed;
    const char *scene_dir;
    const char *out_dir;
    const char *sweep_name; /* "course" (the default), "full" or "quick" */
    bool quick, plots;
    backend_kind backend;
} bench_options;

int bench_options_parse(int argc, char **argv, bench_options *out);
void bench_options_print_help(FILE *stream);
void bench_options_find_scene(const bench_options *options, const char *name, char *out, size_t size);
void bench_options_label_scene(const char *name, char *out, size_t size);

#endif
