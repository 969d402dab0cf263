/* bench_error.c - see bench_error.h. */
#include "bench_error.h"

#include <math.h>
#include <stddef.h>

void bench_error_measure_hdr(const float *a, const float *b, int width, int height, bench_error *out)
{
    size_t n = (size_t)width * (size_t)height;
    double max_abs = 0.0, sum = 0.0, sum2 = 0.0;
    for (size_t i = 0; i < n; i++) {
        for (int c = 0; c < 3; c++) {
            double d = fabs((double)a[4 * i + c] - (double)b[4 * i + c]);
            max_abs = fmax(max_abs, d);
            sum += d;
            sum2 += d * d;
        }
    }
    double values = n ? 3.0 * (double)n : 1.0;
    out->max_abs = max_abs;
    out->mean_abs = sum / values;
    double mse = sum2 / values;
    out->psnr = mse > 0.0 ? fmin(10.0 * log10(1.0 / mse), BENCH_PSNR_CAP) : BENCH_PSNR_CAP;
}
