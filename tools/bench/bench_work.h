/* bench_work.h - what the benchmark measures besides time: the least lighting work a frame needs,
 * and how far a picture is from the exact one. No GL here: everything works on read-back arrays.
 *
 *   bench_work_positions(depth, w, h, view_proj, out)   world position of every pixel's visible
 *                                          surface (x, y, z, 1) or (0, 0, 0, 0) for background,
 *                                          unprojected in double with the inverse of view_proj
 *   bench_work_ideal_pairs(pos, w, h, view_proj, lights, count)
 *                                          (pixel, light) pairs whose surface point lies within the
 *                                          light's radius: the work a perfect light volume would do
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

#include <stdbool.h>

typedef struct bench_error {
    double max_abs, mean_abs, psnr; /* psnr is capped at BENCH_PSNR_CAP when the pictures match */
} bench_error;

#define BENCH_PSNR_CAP 100.0

void bench_work_positions(const float *depth, int width, int height, const float *view_proj, double *out);
long long bench_work_ideal_pairs(const double *pos, int width, int height, const float *view_proj,
                                 const gpu_light *lights, int count);
void bench_work_hdr_error(const float *a, const float *b, int width, int height, bench_error *out);

#endif
