/* bench_work.h - what the benchmark measures besides time: the least lighting work a frame needs,
 * and how far a picture is from the exact one. No GL here: everything works on read-back arrays.
 *
 *   (the least work, light_work_positions and light_work_ideal_pairs, is in common/light_work.h:
 *   the window's overlay counts it too)
 *   bench_work_hdr_error(a, b, w, h, stats)
 *                                          max / mean absolute difference and PSNR (peak 1.0) over
 *                                          R, G, B of two linear RGBA float pictures
 *
 * depth is window depth in [0,1] as glReadPixels(GL_DEPTH_COMPONENT, GL_FLOAT) returns it
 * (bottom row first); view_proj is 16 floats, column-major, as cglm and GL store it.
 */
#ifndef TOOLS_BENCH_WORK_H
#define TOOLS_BENCH_WORK_H

#include "gpu_scene.h"
#include "light_work.h"

#include <stdbool.h>

typedef struct bench_error {
    double max_abs, mean_abs, psnr; /* psnr is capped at BENCH_PSNR_CAP when the pictures match */
} bench_error;

#define BENCH_PSNR_CAP 100.0

void bench_work_hdr_error(const float *a, const float *b, int width, int height, bench_error *out);

#endif
