/* bench_storage_rows.h - what the storage table measured (bench_storage.c fills it) and its report
 * reads (bench_storage_report.c): one row per scene, renderer and sample count, and the timing-only
 * rows (chapter 16's visibility pass cut down, --vis-pass) per scene and sample count. Internal to
 * the benchmark.
 */
#ifndef TOOLS_BENCH_STORAGE_ROWS_H
#define TOOLS_BENCH_STORAGE_ROWS_H

#include "app.h"
#include "image.h"

#define STORAGE_RENDERERS 7
#define STORAGE_TIMINGS 2 /* timing-only rows: no bytes, no error (their pictures are wrong by design) */
enum { STORAGE_TIMING_NO_PRIMITIVE_ID, STORAGE_TIMING_DEPTH_ONLY }; /* bench_storage_timings' order */
#define STORAGE_SCENES 4
#define STORAGE_SAMPLE_COUNTS 2
#define STORAGE_MAX_PASSES 10
#define STORAGE_MAX_ARGS 10

/* A chapter and its arguments (NULL-terminated); no chapter: the course has no such variant. */
typedef struct storage_variant {
    const app_desc *chapter;
    const char *const args[STORAGE_MAX_ARGS];
} storage_variant;

typedef struct storage_renderer {
    const char *name;
    const char *first; /* the pass that stores what the renderer keeps per pixel */
    storage_variant at[STORAGE_SAMPLE_COUNTS];
} storage_renderer;

typedef struct storage_pass {
    char name[32];
    int draws;
    double samples_per_px; /* GL_SAMPLES_PASSED / pixels */
    double written_per_px, read_per_px;
    double ms; /* median */
} storage_pass;

typedef struct storage_row {
    const char *renderer;
    int samples;
    bool measured;
    char note[96];
    int frames, pass_count;
    storage_pass passes[STORAGE_MAX_PASSES];
    double written_per_px, read_per_px; /* the passes' sums */
    double scene_read_per_px;           /* buffers of scene data fetched per pixel (visibility buffer) */
    double frame_ms;
    bool have_error;
    image_stats error8; /* against the exact reference */
} storage_row;

typedef struct bench_storage_results {
    storage_row rows[STORAGE_SCENES][STORAGE_RENDERERS][STORAGE_SAMPLE_COUNTS];
    storage_row timings[STORAGE_SCENES][STORAGE_TIMINGS][STORAGE_SAMPLE_COUNTS]; /* timed only */
    bool scene_done[STORAGE_SCENES];
    int scene_lights[STORAGE_SCENES];
    const char *pass_clock;
    bool ran; /* bench_storage_run was called: the report has a section */
} bench_storage_results;

extern bench_storage_results bench_storage_results_now;
extern const storage_renderer bench_storage_renderers[STORAGE_RENDERERS];
extern const storage_renderer bench_storage_timings[STORAGE_TIMINGS];
extern const char *const bench_storage_scene_names[STORAGE_SCENES];
extern const int bench_storage_samples[STORAGE_SAMPLE_COUNTS];
extern const int bench_storage_vis_scene_bytes;

int bench_storage_scene_count(void); /* --quick: the default scene only */
const storage_pass *bench_storage_find_pass(const storage_row *row, const char *name);

#endif
