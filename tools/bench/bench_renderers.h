/* bench_renderers.h - the renderers the benchmark compares, behind one small interface: the rest of
 * the benchmark knows them by index and name only, so the table and the GL objects behind it can
 * change here alone. Every frame ends in one RGBA8 + depth target of the benchmark's frame size.
 *
 *   bench_renderer_count()                 how many renderers there are (at most BENCH_RENDERER_MAX)
 *   bench_renderer_name(r)                 "forward-naive", ... (--renderers, CSV, report)
 *   bench_renderer_find(name)              the index of the renderer called name, -1 when none is
 *   bench_renderer_is_deferred(r)          lights from a G-buffer (the report's forward/deferred split)
 *   bench_renderer_uses_volumes(r)         one light volume per light (the report's targets)
 *   bench_renderer_uses_stencil(r)         stencil light volumes (their own work target, chapter 08)
 *   bench_renderer_uses_tiles(r)           tiled light lists (their own work target, chapter 10: the
 *                                          light-loop iterations, counted as shaded pixels)
 *   bench_renderer_in_cutoff_sweep(r)      whether the cut-off sweep measures r
 *   bench_renderer_reference()             the renderer of the exact reference picture
 *   bench_renderer_depth_source()          the cheapest renderer whose depth is the exact visible surface
 *   bench_renderer_gbuffer_bytes()         G-buffer bytes per pixel of the deferred renderers
 *   bench_renderer_gbuffer_naive_bytes()   the same for a naive layout with world position
 *
 *   bench_renderers_create(width, height, out)
 *                                          every renderer's GL objects and the target; NULL in *out
 *                                          and false on failure (logged)
 *   bench_renderers_destroy(br)            NULL is fine
 *   bench_renderers_close_chapters(br)     close every chapter br has open (they reopen on the next
 *                                          frame), so another caller can open one with its own
 *                                          arguments (a chapter is open once at a time)
 *   bench_renderers_target(br)             the framebuffer every frame ends in (for read-backs)
 *   bench_renderers_read_target(br, img)   that framebuffer's picture, top row first (made here)
 *   bench_render_frame(br, r, gs, count, work)
 *                                          one frame of renderer r into the target; with count, the
 *                                          lighting work into *work (work may be NULL)
 *   bench_read_linear(br, r, gs, rgba)     the linear radiance of r's frame of gs (width x height
 *                                          RGBA floats, bottom row first); false when r has none
 */
#ifndef TOOLS_BENCH_RENDERERS_H
#define TOOLS_BENCH_RENDERERS_H

#include "fbo.h"
#include "gpu_scene.h"
#include "image.h"

#include <stdbool.h>

#define BENCH_RENDERER_MAX 16 /* for arrays indexed by renderer */

typedef struct bench_renderers bench_renderers;

typedef struct bench_frame_work {
    long shaded;          /* GL_SAMPLES_PASSED of the lighting pass, when counted; -1 otherwise */
    double lights_per_px; /* lights each shaded fragment loops over (forward lists: the mean list) */
} bench_frame_work;

int bench_renderer_count(void);
const char *bench_renderer_name(int r);
int bench_renderer_find(const char *name);
bool bench_renderer_is_deferred(int r);
bool bench_renderer_uses_volumes(int r);
bool bench_renderer_uses_stencil(int r);
bool bench_renderer_uses_tiles(int r);
bool bench_renderer_in_cutoff_sweep(int r);
int bench_renderer_reference(void);
int bench_renderer_depth_source(void);
int bench_renderer_gbuffer_bytes(void);
int bench_renderer_gbuffer_naive_bytes(void);

bool bench_renderers_create(int width, int height, bench_renderers **out);
void bench_renderers_destroy(bench_renderers *br);
void bench_renderers_close_chapters(bench_renderers *br);
const fbo *bench_renderers_target(const bench_renderers *br);
bool bench_renderers_read_target(const bench_renderers *br, image *out);
bool bench_render_frame(bench_renderers *br, int r, const gpu_scene *gs, bool count, bench_frame_work *work);
bool bench_read_linear(bench_renderers *br, int r, const gpu_scene *gs, float *rgba);

#endif
