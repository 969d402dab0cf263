/* bench_gbuffer.h - the G-buffer layouts swept (common/render/gbuffer.h): what each costs in bytes and in
 * time, and what it loses against the geometry pass's own floats. One case per scene (the default
 * scene and the city, each with its own lights, at the default cut-off), every layout drawing
 * chapter 07's frame (deferred-volumes) in turn, frame by frame, like the main sweep's renderers.
 *
 * Measured per layout and scene:
 *   bytes        per pixel, from the formats (and with chapter 08's stencil)
 *   time         median frame, geometry and lighting pass (frame_timer's clock)
 *   normal       max and mean angle between the decoded normal and the float normal the geometry
 *                pass computed (a reference pass writes it, and the position, to RGBA32F targets)
 *   position     mean and max distance between the position rebuilt from depth and the float one,
 *                in the nearest, middle and farthest third of the covered pixels
 *   picture      8-bit and HDR error against the exact reference (bench_measure's: forward, fp32,
 *                cut-off 0), and the 8-bit difference from the `reference` layout's picture
 * Pixels where the layout's depth let another surface win (its normal more than 5 degrees off) are
 * counted, and left out of the normal and position figures.
 *
 *   bench_gbuffer_reset(quick)             the defaults: the sweep runs, except under --quick
 *   bench_gbuffer_parse_option(arg, value) --gbuffer-sweep on|off|only: 1 when taken (value used),
 *                                          0 when arg is another option, -1 on a bad value (one
 *                                          line on stderr)
 *   bench_gbuffer_enabled()                whether the sweep runs
 *   bench_gbuffer_only()                   --gbuffer-sweep only: nothing else runs
 *   bench_gbuffer_run(st, br, m)           the sweep (after the main one: it draws its own reference)
 *   bench_gbuffer_write_csv(st)            OUT/bench_gbuffer.csv, one row per (scene, layout)
 *   bench_gbuffer_write_md(f, st)          the "## G-buffer layouts" section of bench.md (with
 *                                          --gbuffer-sweep only: of bench_gbuffer.md)
 *   bench_gbuffer_print_help(f)            the option's --help lines
 */
#ifndef TOOLS_BENCH_GBUFFER_H
#define TOOLS_BENCH_GBUFFER_H

#include "bench_measure.h"
#include "bench_renderers.h"
#include "bench_state.h"

#include <stdbool.h>
#include <stdio.h>

void bench_gbuffer_reset(bool quick);
int bench_gbuffer_parse_option(const char *arg, const char *value);
bool bench_gbuffer_enabled(void);
bool bench_gbuffer_only(void);
bool bench_gbuffer_run(const bench_state *st, bench_renderers *br, bench_measure *m);
bool bench_gbuffer_write_csv(const bench_state *st);
void bench_gbuffer_write_md(FILE *f, const bench_state *st);
void bench_gbuffer_print_help(FILE *f);

#endif
