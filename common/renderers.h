/* renderers.h - every renderer of the course under one name: the names --renderer takes, the rows
 * of the benchmark's CSV, the hard-case tests and the docs all come from renderer_table.
 *
 *   renderer_find(name)                      its renderer_id, or -1
 *   renderers_create(r)                      nothing yet: each renderer's GL resources are made
 *                                            the first time it draws
 *   renderers_destroy(r)
 *   renderers_draw(r, id, gs, target, options, result)
 *                                            one frame of renderer `id` into the framebuffer
 *                                            `target` (display-encoded RGBA8, or linear radiance
 *                                            for a forward renderer with options.linear_output);
 *                                            result (may be NULL): the lighting pass's work
 *   renderers_accum(r)                       the linear sum of the last light-volume frame
 *                                            (deferred-volumes, -windowed or deferred-stencil)
 *
 * The deferred renderers are the final stages of chapters 03, 07 and 08; renderer_volume_pass is
 * chapter 07's pass state, renderer_stencil_pass and renderer_stencil_light_pass chapter 08's, and
 * deferred-stencil draws chapter 08's frame (its batches, the two passes per batch) with them, so
 * the benchmark measures exactly what those chapters draw (agree.08_bench_renderer checks 08's).
 */
#ifndef COMMON_RENDERERS_H
#define COMMON_RENDERERS_H

#include "deferred_fullscreen.h"
#include "deferred_volumes.h"
#include "forward.h"
#include "light_batches.h"

typedef enum renderer_id {
    RENDERER_FORWARD,         /* chapter 00's default: depth pre-pass + per-object light lists */
    RENDERER_FORWARD_NAIVE,   /* every object with every light, one pass */
    RENDERER_FORWARD_PREPASS, /* depth pre-pass only */
    RENDERER_FORWARD_LISTS,   /* light lists only */
    RENDERER_DEFERRED_FULLSCREEN, /* chapter 03: one full-screen pass, every light per pixel */
    RENDERER_DEFERRED_VOLUMES,    /* chapter 07: one depth-tested volume per light, added up */
    RENDERER_DEFERRED_VOLUMES_WINDOWED, /* the same with the windowed falloff (chapter 05's page) */
    RENDERER_DEFERRED_STENCIL,          /* chapter 08: stencil pass + lighting pass per batch of lights */
    RENDERER_COUNT
} renderer_id;

typedef struct renderer_info {
    const char *name;
    const char *chapter; /* where it is taught */
    const char *summary;
    bool forward;
    forward_options forward_options; /* forward renderers: which optimisations */
} renderer_info;

typedef struct renderer_draw_options {
    bool count_pixels;  /* GL_SAMPLES_PASSED of the lighting pass into result->shaded */
    bool linear_output; /* forward only: linear radiance for a float target */
} renderer_draw_options;

typedef struct renderer_result {
    long shaded;             /* lighting fragments kept, -1 when not counted */
    double lights_per_pixel; /* lights each shaded fragment loops over (lists: the mean length) */
} renderer_result;

/* Chapter 08's frame: a G-buffer with a stencil, its own volumes and accumulation buffer. */
typedef struct renderer_stencil {
    gbuffer g;
    deferred_volumes dv;
    light_batches lb;
    GLuint program; /* the stencil pass: light_volume.vert + depth_only.frag */
    GLint u_first, u_fullscreen;
    GLuint *queries; /* GL_SAMPLES_PASSED per lighting draw */
    int query_count;
} renderer_stencil;

typedef struct renderers {
    forward fwd;
    gbuffer g;
    deferred_fullscreen fullscreen;
    deferred_volumes volumes;
    renderer_stencil stencil;
    const fbo *accum; /* the last light-volume frame's sum */
    bool have_forward, have_gbuffer, have_fullscreen, have_volumes, have_stencil;
} renderer_set;

extern const renderer_info renderer_table[RENDERER_COUNT];
extern const gl_pass_state renderer_volume_pass;
extern const gl_pass_state renderer_stencil_pass, renderer_stencil_light_pass;

int renderer_find(const char *name);
void renderers_create(renderer_set *r);
void renderers_destroy(renderer_set *r);
bool renderers_draw(renderer_set *r, renderer_id id, const gpu_scene *gs, GLuint target,
                    renderer_draw_options options, renderer_result *result);
const fbo *renderers_accum(const renderer_set *r);

#endif
