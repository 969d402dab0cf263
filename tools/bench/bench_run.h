/* bench_run.h - the benchmark's cases: every scene's light sweep and the cut-off sweep. In a case
 * every renderer draws the same frame, frame by frame in turn (round robin), so a noisy moment of
 * the machine hits them all alike; then one untimed frame per renderer gives its work and error.
 * A case predicted too slow from the light counts before it is skipped or given fewer frames.
 *
 *   bench_run_count_cases(options)         how many cases bench_run_all will run
 *   bench_run_all(st, br, m)               every case of st->opt, one row per (case, renderer) added
 *                                          to st, a progress line per row on stderr; false on a GL
 *                                          or file failure (logged)
 */
#ifndef TOOLS_BENCH_RUN_H
#define TOOLS_BENCH_RUN_H

#include "bench_measure.h"
#include "bench_options.h"
#include "bench_renderers.h"
#include "bench_state.h"

#include <stdbool.h>

int bench_run_count_cases(const bench_options *options);
bool bench_run_all(bench_state *st, bench_renderers *br, bench_measure *m);

#endif
