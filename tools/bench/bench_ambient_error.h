/* bench_ambient_error.h - how far the G-buffer's two ambient effects are from their exact references
 * (tools/reference/), and what chapter 17's settings cost on the way there; --ambient-sweep's second
 * half, after its timings (bench_ambient.h).
 *
 * SSAO, on the default scene: chapter 17 at each number of directions x blur (4, 8, 16, 32, 64
 * directions, blur 0 and 2; --quick: 4, 16, 64), each
 *   timed   at the run's size, at the default radius 0.5 (the passes' cost does not depend on it:
 *           every direction is marched in the same 4 steps), medians as the sweep's;
 *   compared at 160 x 120 (--view ao, or ao-blurred with a blur) with ambient occlusion traced in
 *           double precision (ao_reference.h: 64 x 64 cosine-weighted rays per pixel) at radius
 *           0.25, 0.5 and 1 (--quick: 0.5, on every 4th pixel in x and y, so it takes a second): the
 *           mean and largest error in A over the pixels that see a surface and the share of them
 *           beyond 0.1, as hard.ssao_reference measures (tests/ssao/).
 * Image-based light: probe 0 of the default scene and of teapots_probes (--quick: the default scene),
 * made as chapter 19 makes it at its defaults, read back and compared with the Monte Carlo integral
 * of the full GGX BRDF (split_sum_reference.h: 65,536 samples), by roughness 0, 0.25, ... 1, as
 * hard.ibl_reference measures (tests/ibl/).
 *
 *   bench_ambient_error_run(o)   both; appends the sections "SSAO against traced occlusion" and
 *                                "Split sum against Monte Carlo" to OUT/bench_ambient.md and writes
 *                                OUT/bench_ambient_ssao.csv and OUT/bench_ambient_ibl.csv
 */
#ifndef TOOLS_BENCH_AMBIENT_ERROR_H
#define TOOLS_BENCH_AMBIENT_ERROR_H

#include "bench_options.h"

#include <stdbool.h>

bool bench_ambient_error_run(const bench_options *o);

#endif
