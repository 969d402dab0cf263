/* bench_state.h - what one run of the benchmark knows: its options, the machine it runs on and one
 * result row per (case, renderer), in the order the cases ran. The run fills it; the report and the
 * plots only read it.
 *
 *   bench_state_read_machine(st)           the CPU's model and logical cores, the GL renderer and
 *                                          version (a GL context must be current)
 *   bench_state_add_row(st)                a zeroed row at the end; NULL when out of memory (logged).
 *                                          Rows move as they are added: keep indices, not pointers,
 *                                          across calls
 *   bench_state_find_row(st, sweep, scene_name, renderer, own, lights, cutoff)
 *                                          the row of one case and renderer, NULL when none; own
 *                                          ignores lights, cutoff < 0 matches any cut-off
 *   bench_state_destroy(st)                the rows
 */
#ifndef TOOLS_BENCH_STATE_H
#define TOOLS_BENCH_STATE_H

#include "bench_options.h"
#include "bench_error.h"

#include "image.h"

#include <stdbool.h>

/* The passes whose medians get a column of their own (frame_timer's names; a renderer has some). */
#define BENCH_PASSES 6
extern const char *const bench_pass_names[BENCH_PASSES];

typedef enum bench_status {
    BENCH_STATUS_MEASURED,
    BENCH_STATUS_FEW_FRAMES,
    BENCH_STATUS_SKIPPED,
    BENCH_STATUS_NOT_LOADED /* a PBR row whose scene did not load (its note says which) */
} bench_status;

typedef struct bench_row {
    const char *sweep; /* "lights", "cutoff" or "pbr" (a metallic-roughness scene, its own lights) */
    char scene[NAME_MAX_LEN];
    int renderer;    /* bench_renderer_name() and friends take it */
    bool own_lights; /* the scene file's lights, not generated ones */
    int lights, active_lights;
    double cutoff;
    int gbuffer_bytes; /* per pixel of the layout a deferred renderer draws this scene with; 0: forward */
    int frames, warmup;
    double median_ms, min_ms, max_ms;
    double pass_ms[BENCH_PASSES]; /* median per pass on the pass clock; NAN where it has none */
    bench_status status;
    char note[160];
    bool have_work;
    long long shaded, covered, ideal;
    double light_evals, work_ratio;
    bool have_error8, have_error_hdr;
    image_stats error8;
    bench_error error_hdr;
} bench_row;

typedef struct bench_state {
    bench_options opt;
    bench_row *rows;
    int row_count, row_cap;
    int case_index, case_total; /* for the progress lines */
    double start_ms;            /* bench_measure_now_ms() when the sweeps began */
    char cpu[256];
    int cores;
    char gl_renderer[256], gl_version[256];
    const char *pass_clock; /* frame_timer_clock(): "gpu-timer" or "glFinish+monotonic" */
} bench_state;

void bench_state_read_machine(bench_state *st);
bench_row *bench_state_add_row(bench_state *st);
const bench_row *bench_state_find_row(const bench_state *st, const char *sweep, const char *scene_name,
                                      int renderer, bool own, int lights, double cutoff);
void bench_state_destroy(bench_state *st);

#endif
