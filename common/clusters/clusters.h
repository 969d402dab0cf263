/* clusters.h - chapter 11's clustered shading: per-cluster light lists, made on the CPU or by compute
 * shaders, and the two renderers that read them, clustered deferred and clustered forward (Forward+).
 *
 *   clusters_create(c, desc)          nothing drawn yet: buffers; the programs are built on first use
 *   clusters_destroy(c)
 *   clusters_assign(c, gs)            the grid for gs's view (cluster_grid.h), every light's bounding
 *                                     sphere in view space, their lists in two texture buffers
 *                                     (ranges RG32I, indices R32I): made on the CPU and uploaded, or
 *                                     with desc.compute made there by cluster_assign_gpu.h's compute
 *                                     passes (GL 4.3: the caller checks); the same lists either way.
 *                                     With desc.check, the compute lists are read back and compared
 *                                     with the CPU's every frame: false, logging the first cluster
 *                                     that differs
 *   clusters_bind(c, program, first_unit)
 *                                     u_cluster_ranges and u_cluster_lights on first_unit and
 *                                     first_unit + 1, and the uniforms of shaders/clusters.glsl for the
 *                                     grid and the view of the last clusters_assign
 *   clusters_draw_depth(c, gs)        Forward+'s depth pre-pass: every opaque object, depth only,
 *                                     with the caller's depth state (forward.vert + depth_only.frag);
 *                                     the caller names the pass in the frame timer
 *   clusters_shade_forward(c, gs, pass, view)
 *                                     Forward+'s shading: every opaque object with forward_plus.frag
 *                                     and the state `pass` (after the pre-pass: GL_EQUAL), into the
 *                                     framebuffer bound
 *   clusters_shade_deferred(c, g, gs, pass, view)
 *                                     the clustered deferred pass: one full-screen triangle reading
 *                                     g once per pixel (clustered_deferred.frag), into the
 *                                     framebuffer bound, with the state `pass`
 *   clusters_shade_glass(c, gs, passes, pass_count, order, view)
 *                                     chapter 12's glass: every transparent object in `order`, with
 *                                     each of `passes` in turn, shaded by forward_plus.frag
 *                                     (TRANSPARENT: linear radiance, the opacity in alpha) with the
 *                                     list of the cluster each fragment falls in, into the (float)
 *                                     framebuffer bound; view CLUSTERS_VIEW_OVERDRAW: one count per
 *                                     fragment (1 / SHADER_OVERDRAW_SCALE) instead
 *   clusters_render_forward_plus(c, fwd, gs, target, view)
 *                                     Forward+'s whole frame into the framebuffer `target` (cleared
 *                                     here): depth pre-pass (clusters_prepass), light assignment,
 *                                     shading (clusters_shade_after_prepass); with fwd, a scene's glass
 *                                     over it with the same lists, in linear radiance: straight into
 *                                     a float target (view CLUSTERS_VIEW_LINEAR), else through
 *                                     forward's linear frame (forward_draw_linear). Written once here
 *                                     because every chapter offers Forward+ (the runner's R key)
 *   clusters_count(c, g, gs)          the light-loop iterations of the last frame, exactly as the
 *                                     shading pass ran them: the same shader in its count view into
 *                                     a float target, read back and added up (g NULL: Forward+, which
 *                                     draws its own pre-pass there). Sets c->evaluations and
 *                                     c->covered (pixels with a surface); false on a GL error
 *
 * A view (clusters_view) is what the shading pass writes: the lit picture (display-encoded, or linear
 * radiance for a float target), the loop's length per pixel as the heat map, or the clusters view
 * (each pixel's cluster list length as the heat map, odd slices darker).
 * Both renderers call the one shading function (shaders/shading.glsl) over the same lists: the
 * difference between them is only where the surface comes from, the G-buffer or the rasteriser.
 * Transparent objects are drawn only by clusters_shade_glass, after the opaque frame: a cluster's
 * list holds every light that can reach any point of the cluster's box, so a glass fragment finds
 * its lights from its own depth, as a Forward+ fragment does.
 */
#ifndef COMMON_CLUSTERS_H
#define COMMON_CLUSTERS_H

#include "cluster_assign_gpu.h"
#include "cluster_grid.h"
#include "cluster_lists.h"
#include "fbo.h"
#include "forward.h"
#include "gbuffer.h"
#include "gpu_scene.h"

typedef enum clusters_view {
    CLUSTERS_VIEW_LIT,      /* the picture, display-encoded */
    CLUSTERS_VIEW_LINEAR,   /* the picture in linear radiance (a float target) */
    CLUSTERS_VIEW_OVERDRAW, /* the light-loop iterations of each pixel as the heat map */
    CLUSTERS_VIEW_CLUSTERS, /* each pixel's cluster list length, slices in alternating shades */
} clusters_view;

typedef struct clusters_desc {
    int tile_size;     /* pixels; 0: CLUSTERS_TILE_SIZE */
    int slices;        /* 0: cubic clusters (cluster_grid_cubic_slices) */
    int cluster_limit; /* most entries a cluster's list holds (more: every light); 0: no limit */
    bool compute;      /* the lists made by compute shaders (GL 4.3), not on the CPU */
    bool check;        /* with compute: compare them with the CPU's every frame */
} clusters_desc;

#define CLUSTERS_TILE_SIZE 32

typedef struct clusters {
    clusters_desc desc;
    cluster_grid grid;
    float depth_row[4]; /* row 2 of the last assigned view's matrix: view depth = -dot(row, (p, 1)) */
    cluster_lists lists;    /* the CPU's lists */
    cluster_lists readback; /* desc.check: the compute passes' lists, read back */
    cluster_assign_gpu gpu;
    float (*spheres)[4]; /* per light, its bounding sphere in view space */
    int sphere_cap;
    GLuint range_buffer, range_texture, list_buffer, list_texture;
    GLuint depth_program, forward_program, deferred_program, glass_program;
    fbo count_target; /* RGBA32F + depth: the count view */
    float *count_pixels;
    long evaluations, covered;
} clusters;

bool clusters_create(clusters *c, const clusters_desc *desc);
void clusters_destroy(clusters *c);
bool clusters_assign(clusters *c, const gpu_scene *gs);
void clusters_bind(const clusters *c, GLuint program, int first_unit);
bool clusters_draw_depth(clusters *c, const gpu_scene *gs);
bool clusters_shade_forward(clusters *c, const gpu_scene *gs, const gl_pass_state *pass, clusters_view view);
bool clusters_shade_deferred(clusters *c, const gbuffer *g, const gpu_scene *gs, const gl_pass_state *pass,
                             clusters_view view);
bool clusters_shade_glass(clusters *c, const gpu_scene *gs, const gl_pass_state *const passes[], int pass_count,
                          gpu_scene_order order, clusters_view view);
/* Forward+'s two passes, chapter 00's: the pre-pass writes the nearest depth (GL_LEQUAL: on a tie the
 * object drawn last wins, as in the G-buffer); then only the fragment that wrote it is shaded. */
extern const gl_pass_state clusters_prepass, clusters_shade_after_prepass;

bool clusters_render_forward_plus(clusters *c, forward *fwd, const gpu_scene *gs, GLuint target, clusters_view view);
bool clusters_count(clusters *c, const gbuffer *g, const gpu_scene *gs);

#endif
