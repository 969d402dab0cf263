/* bench_plots.h - the benchmark's two plots, drawn by gnuplot when it is installed: time against
 * light count per scene, and speed against error over the cut-off.
 *
 *   bench_plots_make(st, drawn)            OUT/bench_plots.gp (the data inline, so a reader can
 *                                          restyle the plots with `gnuplot OUT/bench_plots.gp`), then
 *                                          OUT/time_vs_lights.png and OUT/speed_vs_error.png (the
 *                                          second with a cut-off sweep only); *drawn says whether
 *                                          they were; true without plots when gnuplot is missing (a
 *                                          warning), false when it fails (logged)
 */
#ifndef TOOLS_BENCH_PLOTS_H
#define TOOLS_BENCH_PLOTS_H

#include "bench_state.h"

#include <stdbool.h>

bool bench_plots_make(const bench_state *st, bool *drawn);

#endif
