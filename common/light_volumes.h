/* light_volumes.h - deferred lighting with one sphere per light, so a light shades only the pixels
 * its sphere of influence covers (chapters 04-07; the benchmark's deferred renderer).
 *
 *   light_volumes_create(lv, g)                 programs, the volume mesh, an accumulation buffer
 *                                               sharing g's depth texture
 *   light_volumes_destroy(lv)
 *   light_volumes_resize(lv, g)                 after gbuffer_resize: follow g's new size and depth
 *   light_volumes_render(lv, g, gs, options)    ambient, then every light of gs, from the G-buffer g
 *                                               (already filled by gbuffer_render) into the
 *                                               accumulation buffer; then present it into the
 *                                               framebuffer bound when called
 *   light_volumes_shaded_pixels(lv)             fragments that reached the lighting shader and were
 *                                               kept in the last frame (GL_SAMPLES_PASSED), when
 *                                               options.count_pixels; -1 otherwise
 *   light_volumes_options_set(options, name, value)
 *                                               one option from its command-line text ("cull",
 *                                               "front"); logs and returns false on a bad value
 *
 * The volume is an 80-triangle icosphere (mesh_data_icosphere(m, 1)) scaled by radius / inradius,
 * all lights in ONE instanced draw; each instance fetches its light from the light texture buffer.
 * Lights with an infinite radius (cut-off 0) are full-screen triangles instead. The lighting
 * shader calls shade_light() from shaders/shading.glsl exactly as forward.frag does.
 *
 * Zeroed options are chapter 07's configuration: additive blending into RGBA16F, back faces only
 * (front faces culled), depth test GL_GREATER against the scene with depth writes off and depth
 * clamp on, the solved radius, no tone mapping. The other values reproduce the earlier chapters
 * and their bugs.
 */
#ifndef COMMON_LIGHT_VOLUMES_H
#define COMMON_LIGHT_VOLUMES_H

#include "gbuffer.h"
#include "gpu_scene.h"
#include "mesh.h"

typedef enum light_volumes_cull {
    LIGHT_VOLUMES_CULL_FRONT, /* draw back faces: a camera inside a volume still sees its light */
    LIGHT_VOLUMES_CULL_BACK,  /* draw front faces: the light vanishes once the camera is inside */
    LIGHT_VOLUMES_CULL_NONE,  /* draw both: pixels lit twice */
} light_volumes_cull;

typedef enum light_volumes_depth {
    LIGHT_VOLUMES_DEPTH_GREATER, /* keep volume fragments behind the surface (pairs with back faces);
                                  * strictly: a back face clamped to the far plane misses the background */
    LIGHT_VOLUMES_DEPTH_LEQUAL,  /* keep volume fragments in front of the surface (front faces) */
    LIGHT_VOLUMES_DEPTH_OFF,     /* every pixel the volume covers on screen */
} light_volumes_depth;

typedef enum light_volumes_tonemap {
    LIGHT_VOLUMES_TONEMAP_NONE,     /* clamp at 1: matches the forward renderer */
    LIGHT_VOLUMES_TONEMAP_EXPOSURE, /* scale by the exposure, then clamp */
    LIGHT_VOLUMES_TONEMAP_REINHARD, /* x / (1 + x) after the exposure: never clips */
} light_volumes_tonemap;

typedef enum light_volumes_view {
    LIGHT_VOLUMES_VIEW_LIT,      /* the shaded picture */
    LIGHT_VOLUMES_VIEW_RING,     /* plus a line where each light's cut-off sphere meets a surface */
    LIGHT_VOLUMES_VIEW_OVERDRAW, /* grey level = lighting fragments per pixel (1/16 each) */
} light_volumes_view;

typedef struct light_volumes_options {
    bool overwrite;      /* no blending: each light replaces the pixel (chapter 04) */
    GLenum accum_format; /* 0 = GL_RGBA16F; GL_RGBA8 saturates at 1; GL_RGBA32F (chapter 06) */
    light_volumes_cull cull;
    light_volumes_depth depth;
    bool no_depth_clamp; /* let the far plane clip volumes (chapter 07's bug) */
    bool unscaled_mesh;  /* the inscribed icosphere at radius r: faceted lights (chapter 04) */
    float fixed_radius;  /* > 0: every volume has this radius instead of the solved one */
    light_volumes_tonemap tonemap;
    float exposure; /* 0 means 1 */
    light_volumes_view view;
    bool count_pixels;
} light_volumes_options;

typedef struct light_volumes_program {
    GLuint id;
    GLint view_proj, mesh_scale, fixed_radius, fullscreen, first_instance, light_index, view;
} light_volumes_program;

typedef struct light_volumes {
    light_volumes_program volume[2]; /* [0] additive, [1] overwrite (compiled with OVERWRITE) */
    GLuint ambient_program, present_program;
    mesh sphere;
    float mesh_scale; /* 1 / inradius of the icosphere */
    fbo accum;        /* colour: the accumulation buffer; depth: the G-buffer's */
    GLenum accum_format;
    GLuint index_buffer, index_texture; /* per instance: the light's index (finite, then infinite) */
    int *indices;
    int index_cap;
    GLuint query;
    long shaded_pixels;
    GLint present_accum, present_tonemap, present_exposure;
} light_volumes;

bool light_volumes_create(light_volumes *lv, const gbuffer *g);
void light_volumes_destroy(light_volumes *lv);
bool light_volumes_resize(light_volumes *lv, const gbuffer *g);
bool light_volumes_render(light_volumes *lv, const gbuffer *g, const gpu_scene *gs,
                          light_volumes_options options);
long light_volumes_shaded_pixels(const light_volumes *lv);
bool light_volumes_options_set(light_volumes_options *options, const char *name, const char *value);

#endif
