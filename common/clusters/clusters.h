/* clusters.h - the parts of chapter 11's clustered shading that chapters 12 and 13 and every chapter's
 * Forward+ reuse: the lists' buffers and programs, the light spheres, the bindings, the count. The
 * stage itself, the grid sizing, the assignment's dispatches and the two shading draws, is written in
 * chapters/11_clustered.c, which exports it (chapters/chapters.h: chapter_11_*).
 *
 *   clusters_create(c, desc)          nothing drawn yet: buffers; the programs are built on first use
 *   clusters_destroy(c)
 *   clusters_light_spheres(c, gs)     every light's bounding sphere (a spot's around its cone) in view
 *                                     space into c->spheres (an infinite one stays infinite), and
 *                                     c->depth_row for the shaders' view depth
 *   clusters_upload_lists(c)          the CPU's lists (c->lists) into the two texture buffers the
 *                                     shading passes read (ranges RG32I, indices R32I)
 *   clusters_check(c, lights, limit)  desc.check: the compute lists read back and compared with the
 *                                     CPU's for the same spheres; false, logging the first cluster
 *                                     that differs
 *   clusters_bind(c, program, first_unit)
 *                                     u_cluster_ranges and u_cluster_lights on first_unit and
 *                                     first_unit + 1, and the uniforms of shaders/clusters.glsl for the
 *                                     grid and the view of the last assignment
 *   clusters_program(c, which)        one of the programs, built on first use; 0 (logged) on failure
 *   clusters_set_extra(c, extra)      desc.extra from the next draw on (NULL: none); each variant's
 *                                     programs built once and kept (chapter 14: its shadows' programs
 *                                     only while a light is shadowed)
 *   clusters_use(c, gs, program, view)
 *                                     `program` in use with the lights, the lists, the eye and the
 *                                     view (what the shader writes: clusters_view), and desc.extra's
 *                                     inputs
 *   clusters_draw_depth(c, gs)        Forward+'s depth pre-pass: every opaque object, depth only,
 *                                     with the caller's depth state (forward.vert + depth_only.frag);
 *                                     the caller names the pass in the frame timer
 *   clusters_shade_glass(c, gs, passes, pass_count, order, view)
 *                                     chapter 12's glass: every transparent object in `order`, with
 *                                     each of `passes` in turn, shaded by forward_plus.frag
 *                                     (TRANSPARENT: linear radiance, the opacity in alpha) with the
 *                                     list of the cluster each fragment falls in, into the (float)
 *                                     framebuffer bound; view CLUSTERS_VIEW_OVERDRAW: one count per
 *                                     fragment (1 / SHADER_OVERDRAW_SCALE) instead
 *   clusters_count_begin(c, gs) / clusters_count_end(c, drawn)
 *                                     around a shading pass drawn with CLUSTERS_VIEW_COUNT: its count
 *                                     target bound and cleared; then (when the pass was drawn: false
 *                                     otherwise) read back and added up into
 *                                     c->evaluations (light-loop iterations, exactly as the shading
 *                                     pass ran them) and c->covered (pixels with a surface)
 *
 * A view (clusters_view) is what the shading pass writes: the lit picture (display-encoded, or linear
 * radiance for a float target), the loop's length per pixel as the heat map, the clusters view
 * (each pixel's cluster list length as the heat map, odd slices darker), or the count.
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
#include "gl_program.h"
#include "gpu_scene.h"

typedef enum clusters_view {
    CLUSTERS_VIEW_LIT,      /* the picture, display-encoded */
    CLUSTERS_VIEW_LINEAR,   /* the picture in linear radiance (a float target) */
    CLUSTERS_VIEW_OVERDRAW, /* the light-loop iterations of each pixel as the heat map */
    CLUSTERS_VIEW_CLUSTERS, /* each pixel's cluster list length, slices in alternating shades */
    CLUSTERS_VIEW_COUNT,    /* into the count target: covered, loop length (clusters_count_begin) */
} clusters_view;

typedef enum clusters_program_id {
    CLUSTERS_PROGRAM_DEPTH,    /* forward.vert + depth_only.frag: Forward+'s pre-pass */
    CLUSTERS_PROGRAM_FORWARD,  /* forward.vert + forward_plus.frag: Forward+'s shading */
    CLUSTERS_PROGRAM_DEFERRED, /* fullscreen.vert + clustered_deferred.frag */
    CLUSTERS_PROGRAM_GLASS,    /* forward_plus.frag with TRANSPARENT (chapter 12) */
    CLUSTERS_PROGRAM_COUNT
} clusters_program_id;

typedef struct clusters_desc {
    int tile_size;     /* pixels; 0: CLUSTERS_TILE_SIZE */
    int slices;        /* 0: cubic clusters (cluster_grid_cubic_slices) */
    int cluster_limit; /* most entries a cluster's list holds (more: every light); 0: no limit */
    bool compute;      /* the lists made by compute shaders (GL 4.3), not on the CPU */
    bool check;        /* with compute: compare them with the CPU's every frame */
    gl_program_extra extra; /* a later chapter's additions to the shading programs (chapter 14) */
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
    gl_program_variants programs[CLUSTERS_PROGRAM_COUNT]; /* each with desc.extra as it was when drawn */
    fbo count_target; /* RGBA32F + depth: the count view */
    float *count_pixels;
    long evaluations, covered;
} clusters;

bool clusters_create(clusters *c, const clusters_desc *desc);
void clusters_destroy(clusters *c);
bool clusters_light_spheres(clusters *c, const gpu_scene *gs);
void clusters_upload_lists(clusters *c);
bool clusters_check(clusters *c, int lights, int limit);
void clusters_bind(const clusters *c, GLuint program, int first_unit);
GLuint clusters_program(clusters *c, clusters_program_id which);
void clusters_set_extra(clusters *c, const gl_program_extra *extra);
void clusters_use(const clusters *c, const gpu_scene *gs, GLuint program, clusters_view view);
bool clusters_draw_depth(clusters *c, const gpu_scene *gs);
bool clusters_shade_glass(clusters *c, const gpu_scene *gs, const gl_pass_state *const passes[], int pass_count,
                          gpu_scene_order order, clusters_view view);
bool clusters_count_begin(clusters *c, const gpu_scene *gs);
bool clusters_count_end(clusters *c, bool drawn);

#endif
