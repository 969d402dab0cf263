/* bench_storage.h - "what to store per pixel", measured (docs/16_visibility_buffer.md): forward,
 * Forward+, the compact and the reference G-buffer, the light pre-pass (both light buffers) and the
 * visibility buffer, at 1 and 4 samples per pixel, on the default, city, bunnies and teapots scenes
 * (--quick: the default scene), each with its own lights at the default cut-off. Every row is a
 * chapter opened with its arguments (app_embed.h), so what is measured is what the chapter draws.
 *
 * Measured per row:
 *   bytes    written and read per pixel, counted (common/gl/draw_count.h): every draw's
 *            GL_SAMPLES_PASSED times the bytes one sample writes in that draw's state (its
 *            attachments' formats, masks, depth and stencil writes), and the bytes of every 2D
 *            texture its shaders sample per fragment; per pass and in all. The visibility buffer's
 *            shading pass also fetches the triangle's vertices and the object's matrices from
 *            buffers (scene data, not per-pixel storage): counted apart, per covered pixel, from
 *            visibility_shade.frag's fetches
 *   time     the median of each pass and of the frame, CPU clock around glFinish at every pass
 *            boundary (frame_timer.h: llvmpipe's timer queries are wrong)
 *   error    8-bit, against the exact reference (bench_measure.h: forward, fp32, cut-off 0); at 4
 *            samples against chapter 13's forward MSAA at cut-off 0, the exact 4-sample picture
 * A renderer without a 4-sample variant gets a row that says so.
 * Timed only, beside them: chapter 16's visibility pass cut down (--vis-pass no-primitive-id: triangle
 * 0 instead of gl_PrimitiveID; depth-only: no id written), whose pictures are wrong by design: what
 * the visibility pass's time is made of, against the compact G-buffer's geometry pass.
 * Targets printed: the visibility buffer writes at most 8 bytes per sample, depth included, at 1
 * and 4 samples; on the bunnies at 4 samples its first pass is at least 1.5x faster than the
 * compact G-buffer's geometry pass (and the same pass without gl_PrimitiveID against the target).
 *
 *   bench_storage_reset(on, quick)         the defaults: on under --full, off otherwise; quick: the
 *                                          default scene only
 *   bench_storage_parse_option(arg, value) --storage on|off|only: 1 when taken (value used), 0 when
 *                                          arg is another option, -1 on a bad value (one line on
 *                                          stderr)
 *   bench_storage_enabled() / bench_storage_only()
 *   bench_storage_run(st, br, m)           the table (after the other sweeps)
 *   bench_storage_write_csv(st)            OUT/bench_storage.csv: one row per (scene, renderer,
 *                                          samples, pass) and one `total` row each; the timing-only
 *                                          rows after a scene's renderers, bytes and error NA, their
 *                                          note "timing only: ..."
 *   bench_storage_write_md(f, st)          the "## What to store per pixel" section of bench.md (with
 *                                          --storage only: of bench_storage.md), its last part
 *                                          "### What the visibility pass's time is made of"
 *   bench_storage_print_help(f)            the option's --help lines
 */
#ifndef TOOLS_BENCH_STORAGE_H
#define TOOLS_BENCH_STORAGE_H

#include "bench_measure.h"
#include "bench_renderers.h"
#include "bench_state.h"

#include <stdbool.h>
#include <stdio.h>

void bench_storage_reset(bool on, bool quick);
int bench_storage_parse_option(const char *arg, const char *value);
bool bench_storage_enabled(void);
bool bench_storage_only(void);
bool bench_storage_run(const bench_state *st, bench_renderers *br, bench_measure *m);
bool bench_storage_write_csv(const bench_state *st);
void bench_storage_write_md(FILE *f, const bench_state *st);
void bench_storage_print_help(FILE *f);

#endif
