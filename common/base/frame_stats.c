/* frame_stats.c - see frame_stats.h. */
#include "frame_stats.h"

#include <stdlib.h>

static int compare_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

frame_stats frame_stats_of(double *ms, int n)
{
    qsort(ms, (size_t)n, sizeof *ms, compare_double);
    double sum = 0;
    for (int i = 0; i < n; i++)
        sum += ms[i];
    /* The median of an even count is the mean of the middle two. */
    double median = n % 2 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
    return (frame_stats){.median = median, .min = ms[0], .max = ms[n - 1], .mean = sum / n};
}
