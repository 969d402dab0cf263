/* bench_ambient.h - what the G-buffer's two whole-screen ambient effects cost against the lighting
 * pass: chapter 17's SSAO (its SSAO and blur passes) and chapter 19's probes (their term inside the
 * lighting pass, and their capture at start), each beside chapter 11's clustered frame that both
 * keep, on the default scene and the teapots with probes (teapots_probes.scene), at the run's size.
 * The three chapters draw in turn, frame by frame (round robin, as the main sweep's renderers), and
 * are the chapters themselves, embedded (common/app/app_embed.h).
 *
 * Measured per scene and chapter: the median frame, geometry, light assignment, SSAO, blur and
 * lighting passes (frame_timer's clock); the first frame's extra time over the median (chapter 19:
 * the probes' capture); the GPU memory each effect adds (chapter 17: its occlusion and pre-pass
 * targets; chapter 19: chapter_19_probe_bytes()).
 *
 *   bench_ambient_reset(full)              the default: on under --full, otherwise off
 *   bench_ambient_parse_option(arg, value) --ambient-sweep on|off|only: 1 when taken, 0 when arg is
 *                                          another option, -1 on a bad value (one line on stderr)
 *   bench_ambient_enabled(), bench_ambient_only()
 *   bench_ambient_run(o)                   the sweep; writes OUT/bench_ambient.md and .csv
 *   bench_ambient_print_help(f)            the option's --help lines
 */
#ifndef TOOLS_BENCH_AMBIENT_H
#define TOOLS_BENCH_AMBIENT_H

#include "bench_options.h"

#include <stdbool.h>
#include <stdio.h>

void bench_ambient_reset(bool full);
int bench_ambient_parse_option(const char *arg, const char *value);
bool bench_ambient_enabled(void);
bool bench_ambient_only(void);
bool bench_ambient_run(const bench_options *o);
void bench_ambient_print_help(FILE *f);

#endif
