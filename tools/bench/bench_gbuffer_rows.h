/* bench_gbuffer_rows.h - what the G-buffer sweep measured (bench_gbuffer.c fills it) and its reports
 * read (bench_gbuffer_report.c): one row per scene and layout. Internal to the benchmark.
 */
#ifndef TOOLS_BENCH_GBUFFER_ROWS_H
#define TOOLS_BENCH_GBUFFER_ROWS_H

#include "bench_report.h"

#include "gbuffer.h"
#include "image.h"

#define SCENES 3 /* the default scene, the city and the textured PBR teapots */
#define OTHER_SURFACE_DEG 5.0 /* a normal further off than this belongs to another surface */

/* One third of the covered pixels, by distance from the eye. */
typedef struct band {
    double distance;  /* the median distance of its pixels */
    double mean, max; /* position error, scene units */
} band;

typedef struct layout_row {
    bool measured;
    char note[96];
    int lights, frames;
    double frame_ms, geometry_ms, lighting_ms;
    double normal_max, normal_mean;
    long covered, other_surface;
    band bands[3];
    image_stats vs_forward8; /* against forward at the same cut-off: what the layout alone costs */
    bench_error vs_forward_hdr;
    bool have_exact;    /* the exact reference is drawn up to --error-max-lights lights */
    image_stats error8; /* against the exact reference (forward, fp32, cut-off 0) */
    bench_error error_hdr;
    image_stats vs_reference; /* 8-bit, tolerance 1, against the `reference` layout's picture */
} layout_row;

typedef struct bench_gbuffer_results {
    layout_row rows[SCENES][GBUFFER_LAYOUT_COUNT];
    bool scene_done[SCENES];
    const char *pass_clock; /* frame_timer_clock() of the sweep's timers */
} bench_gbuffer_results;

extern bench_gbuffer_results bench_gbuffer_results_now;
extern const char *const bench_gbuffer_scene_names[SCENES]; /* "default", "city", "pbr_teapots" */
extern const char *const bench_gbuffer_band_names[3];       /* "near", "middle", "far" */

#endif

