/* bench_measure.h - everything the benchmark measures except the timed frames themselves: the clock,
 * the exact reference picture, the lighting work a frame does and needs, and its error. Owns the
 * read-back buffers (width x height each), so a case allocates nothing.
 *
 *   bench_measure_create(width, height, m) the read-back buffers; false when out of memory (logged)
 *   bench_measure_destroy(m)               also after a failed create
 *   bench_measure_now_ms()                 CLOCK_MONOTONIC in ms
 *   bench_measure_make_reference(m, br, gs, key, cutoff)
 *                                          the exact reference of gs (8-bit and linear), unless the
 *                                          one kept is already key's; leaves gs updated for cutoff
 *   bench_measure_forget_reference(m)      the next make_reference draws afresh (a new scene)
 *   bench_measure_count_ideal(m, br, gs, out)
 *                                          covered pixels and the (pixel, light) pairs a perfect
 *                                          light volume would shade, from the exact visible depth
 *   bench_measure_fill_row(m, br, gs, want_error, row)
 *                                          one counted frame of row->renderer: its work against
 *                                          row->ideal, and with want_error its error against the
 *                                          reference (make_reference first)
 */
#ifndef TOOLS_BENCH_MEASURE_H
#define TOOLS_BENCH_MEASURE_H

#include "bench_renderers.h"
#include "bench_state.h"

#include "gpu_scene.h"
#include "image.h"

#include <stdbool.h>

#define BENCH_KEY_LEN (NAME_MAX_LEN + 32) /* "scene/own/lights": what a reference was drawn for */

typedef struct bench_measure {
    int width, height;
    float *depth, *hdr; /* read-backs of the frame being measured */
    double *positions;  /* light_work_positions of depth */
    /* the exact reference of the current (scene, lights): 8-bit and linear */
    image ref8;
    float *ref_hdr;
    char ref_key[BENCH_KEY_LEN];
    bool have_ref;
} bench_measure;

typedef struct bench_ideal {
    long long covered; /* pixels with a visible surface */
    long long ideal;   /* (pixel, light) pairs whose surface point lies within the light's radius */
} bench_ideal;

bool bench_measure_create(int width, int height, bench_measure *m);
void bench_measure_destroy(bench_measure *m);
double bench_measure_now_ms(void);
bool bench_measure_make_reference(bench_measure *m, bench_renderers *br, gpu_scene *gs, const char *key,
                                  double cutoff);
void bench_measure_forget_reference(bench_measure *m);
bool bench_measure_count_ideal(bench_measure *m, bench_renderers *br, const gpu_scene *gs, bench_ideal *out);
bool bench_measure_fill_row(bench_measure *m, bench_renderers *br, const gpu_scene *gs, bool want_error,
                            bench_row *row);

#endif
