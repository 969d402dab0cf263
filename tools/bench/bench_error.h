/* bench_error.h - how far a picture is from the exact one, in linear radiance. No GL here: it works
 * on read-back arrays (fbo_read_float). The least lighting work a frame needs, the benchmark's other
 * measure besides time, is common/render/light_work.h (the window's overlay counts it too).
 *
 *   bench_error_measure_hdr(a, b, w, h, out)
 *                                          max / mean absolute difference and PSNR (peak 1.0) over
 *                                          R, G, B of two linear RGBA float pictures of w x h pixels
 */
#ifndef TOOLS_BENCH_ERROR_H
#define TOOLS_BENCH_ERROR_H

typedef struct bench_error {
    double max_abs, mean_abs, psnr; /* psnr is capped at BENCH_PSNR_CAP when the pictures match */
} bench_error;

#define BENCH_PSNR_CAP 100.0

void bench_error_measure_hdr(const float *a, const float *b, int width, int height, bench_error *out);

#endif
