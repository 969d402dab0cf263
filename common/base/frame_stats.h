/* frame_stats.h - the summary of a run's frame times that the --bench line and the benchmark print.
 *
 *   frame_stats_of(ms, n)   median, min, max and mean of n > 0 times; sorts ms in place
 */
#ifndef COMMON_FRAME_STATS_H
#define COMMON_FRAME_STATS_H

typedef struct frame_stats {
    double median, min, max, mean;
} frame_stats;

frame_stats frame_stats_of(double *ms, int n);

#endif
