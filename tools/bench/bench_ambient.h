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
 *   bench_ambient_run(o)                   the sweep, then the errors against the references
 *                                          (bench_ambient_error.h); writes OUT/bench_ambient.md and
 *                                          .csv (and the errors' CSV files)
 *   bench_ambient_time(o, gs, count, descs, args, rows)
 *                                          `count` (at most 3) chapters with their arguments (args
 *                                          NULL: none for any) open together on gs and drawn in
 *                                          turn, o->frames frames each after the warm-up: a row each
 *   bench_ambient_print_help(f)            the option's --help lines
 */
#ifndef TOOLS_BENCH_AMBIENT_H
#define TOOLS_BENCH_AMBIENT_H

#include "app.h"
#include "bench_options.h"

#include <stdbool.h>
#include <stdio.h>

/* The passes a row reports (frame_timer_mark's names), in this order; the frame is column 0. */
enum { BENCH_AMBIENT_FRAME, BENCH_AMBIENT_GEOMETRY, BENCH_AMBIENT_ASSIGN, BENCH_AMBIENT_SSAO, BENCH_AMBIENT_BLUR,
       BENCH_AMBIENT_LIGHTING, BENCH_AMBIENT_COLUMNS };

typedef struct bench_ambient_row {
    double ms[BENCH_AMBIENT_COLUMNS]; /* medians; NAN: the chapter has no such pass */
    double first_extra_ms;            /* the first frame over the median */
    double bytes;                     /* what the effect adds on the GPU */
    int frames;
} bench_ambient_row;

void bench_ambient_reset(bool full);
int bench_ambient_parse_option(const char *arg, const char *value);
bool bench_ambient_enabled(void);
bool bench_ambient_only(void);
bool bench_ambient_run(const bench_options *o);
bool bench_ambient_time(const bench_options *o, const gpu_scene *gs, int count, const app_desc *const descs[],
                        const char *const *const args[], bench_ambient_row rows[]);
void bench_ambient_print_help(FILE *f);

#endif
