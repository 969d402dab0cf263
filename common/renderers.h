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
 *   renderer_have_compute()                  compute shaders on this context (GLAD_GL_VERSION_4_3),
 *                                            unless $COURSE_NO_COMPUTE is set: the tests run the GL
 *                                            3.3 paths on a newer driver that way
 *   renderer_tile_sphere(light, view, out)   chapter 10's culling, GL-free (the C twin of
 *   renderer_tile_frustum_make(view, x, y, size, depth, f)    shaders/tiled_cull.glsl, for its GL
 *   renderer_tile_sphere_visible(f, sphere)                   3.3 path and deferred-tiled): a light's
 *                                            bounding sphere in view space (a spot's around its cone),
 *                                            grown by 1e-4 of the distances for rounding; the piece of
 *                                            the view behind the size x size pixel tile whose bottom
 *                                            left pixel is (x, y) (cut at the view's edge), its
 *                                            surfaces at view depths depth[0..1]; whether the sphere
 *                                            can reach that piece (conservative)
 *   renderer_tile_bind_view(program, view)   the view uniforms of chapter 10's two culling programs
 *                                            (tiled_cull.comp, tile_depth_bounds.frag), in use
 *
 * The deferred renderers are the final stages of chapters 03, 07, 08 and 10; renderer_volume_pass is
 * chapter 07's pass state, renderer_stencil_pass and renderer_stencil_light_pass chapter 08's, and
 * deferred-stencil draws chapter 08's frame (its batches, the two passes per batch) with them, so
 * the benchmark measures exactly what those chapters draw (agree.08_bench_renderer checks 08's).
 * deferred-tiled draws chapter 10's frame: its compute path where renderer_have_compute(), else its
 * GL 3.3 path, with the chapter's shaders; result->shaded counts its light-loop iterations, and
 * golden.10_work checks that they are the chapter's.
 * forward-plus and deferred-clustered draw chapter 11's two frames (common/clusters.h) with its pass
 * states; result->shaded is the pixels with a surface and result->lights_per_pixel the mean light-loop
 * length there, so their product is the frame's light evaluations (golden.11_work checks them).
 */
#ifndef COMMON_RENDERERS_H
#define COMMON_RENDERERS_H

#include "clusters.h"
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
    RENDERER_DEFERRED_TILED,            /* chapter 10: per-tile light lists, one shading pass */
    RENDERER_FORWARD_PLUS,       /* chapter 11: clustered forward (Forward+): pre-pass, cluster lists */
    RENDERER_DEFERRED_CLUSTERED, /* chapter 11: clustered deferred: cluster lists, one shading pass */
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

/* A tile's piece of the view: four side planes (unit normals, inside >= 0), the depths of its
 * surfaces (distances in front of the eye), the box around it; all in view space. */
typedef struct renderer_tile_frustum {
    vec4 side[4];
    float depth[2];
    vec3 lo, hi;
} renderer_tile_frustum;

/* Chapter 10's frame (chapters/10_tiled_deferred.c has the same, explained): a G-buffer, the tile
 * lists made by a compute shader or by a reduction pass and the CPU, the shading pass. */
typedef struct renderer_tiled {
    gbuffer g;
    bool compute;
    int tiles_x, tiles_y, capacity;
    GLuint cull_program, bounds_program, shade_program;
    fbo bounds;
    GLuint list_buffer, list_texture, range_buffer, range_texture, sphere_buffer, sphere_texture;
    vec4 *spheres;
    float *tile_bounds;
    renderer_tile_frustum *frustums;
    int *ranges, *list;
} renderer_tiled;

typedef struct renderers {
    forward fwd;
    gbuffer g;
    deferred_fullscreen fullscreen;
    deferred_volumes volumes;
    renderer_stencil stencil;
    renderer_tiled tiled;
    clusters clusters;  /* chapter 11's lists, for forward-plus and deferred-clustered (on r->g) */
    bool have_clusters;
    const fbo *accum; /* the last light-volume frame's sum */
    bool have_forward, have_gbuffer, have_fullscreen, have_volumes, have_stencil, have_tiled;
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
bool renderer_have_compute(void);
void renderer_tile_sphere(const gpu_light *light, const frame_view *view, vec4 out);
void renderer_tile_frustum_make(const frame_view *view, int x, int y, int size, const float depth[2],
                                renderer_tile_frustum *f);
void renderer_tile_bind_view(GLuint program, const frame_view *view);
bool renderer_tile_sphere_visible(const renderer_tile_frustum *f, const vec4 sphere);

#endif
