/* gpu_scene.h - a scene ready to draw: meshes on the GPU, per-frame matrices and the light list.
 *
 *   gpu_scene_create(src, gs)        upload every mesh of the scene
 *   gpu_scene_destroy(gs)
 *   gpu_scene_update(gs, time, cutoff, width, height)
 *                                    camera matrices for the viewport, object matrices and light
 *                                    positions at `time`, light radii for `cutoff`; lights that
 *                                    never reach the cut-off are culled here (radius 0)
 *   gpu_scene_bind_lights(gs, program, unit)
 *                                    u_lights (texture buffer on `unit`), u_light_count, u_ambient,
 *                                    u_falloff (gs->falloff: the scene's falloff model)
 *   gpu_scene_bind_objects(gs, program, unit)
 *                                    u_objects (texture buffer on `unit`) and u_view_proj, and the
 *                                    materials' images (gpu_textures_bind)
 *   gpu_scene_draw(gs, program)      every OPAQUE object: one instanced draw per batch of consecutive
 *                                    objects that share a mesh (the city's 2,490 cubes are one draw);
 *                                    the transparent ones (material opacity < 1) are left out, so
 *                                    the depth pre-pass and the G-buffer never hold them
 *   gpu_scene_draw_into(gs, framebuffer, width, height, program, state)
 *                                    framebuffer's colour and depth cleared (0, far), then every
 *                                    opaque object with program and state, u_objects on
 *                                    SHADER_UNIT_OBJECTS; leaves gl_pass_state_reset()'s state (SSAO's
 *                                    depth-normal pre-pass, the benchmark's exact surface)
 *   gpu_scene_draw_transparent(gs, program, order, passes, pass_count)
 *                                    every transparent object, one draw per object and pass state:
 *                                    object by object in `order`, each drawn with passes[0], then
 *                                    passes[1], ... (chapter 12: its back faces, then its front faces)
 *   gpu_light_is_spot(l)             whether the light has a cone (cos_outer > -1)
 *
 * Light and object texels: the layout in shader_layout.h (SHADER_LIGHT_TEXELS per light,
 * SHADER_OBJECT_TEXELS per object). A spot is a point light plus a cone (gpu_light_is_spot); a
 * point light has cos_outer = -1, so shade_light() has one code path for both. An infinite radius is stored as FLT_MAX. forward.vert reads them
 * for object u_first_object + gl_InstanceID, so a draw call costs the same for one cube or 2,490.
 *
 * Transparent objects (chapter 12): gpu_scene_update sorts them back to front, by the distance from
 * the eye to the centre of each one's bounding sphere (farthest first; equal distances keep the
 * scene's order). One distance per object: objects that intersect, or one concave object in front of
 * itself, cannot be ordered right this way (docs/12_transparency.md, "Sorting and where it fails").
 */
#ifndef COMMON_GPU_SCENE_H
#define COMMON_GPU_SCENE_H

#include "gl_util.h"
#include "gpu_textures.h"
#include "mesh.h"
#include "scene.h"
#include "shader_layout.h"

#include <cglm/cglm.h>


typedef struct frame_view {
    int width, height;
    mat4 view, proj, view_proj, inv_proj, inv_view, inv_view_proj;
    vec3 eye;
    float near_plane, far_plane;
} frame_view;

typedef struct gpu_light {
    vec3 position;
    float radius;   /* FLT_MAX when infinite */
    vec3 radiance;  /* intensity * colour */
    vec3 attenuation;
    int source;     /* index of the light in the scene */
    vec3 direction; /* a spot's unit axis; 0 for a point light */
    float cos_outer, cos_inner; /* a spot's cone; -1 and -1 for a point light (no cone) */
} gpu_light;

/* Consecutive opaque objects with the same mesh, drawn with one glDrawElementsInstanced. */
typedef struct gpu_batch {
    int mesh, first, count;
} gpu_batch;

/* The order gpu_scene_draw_transparent draws in. */
typedef enum gpu_scene_order {
    GPU_SCENE_BACK_TO_FRONT, /* farthest bounding-sphere centre first: what blending needs */
    GPU_SCENE_SCENE_ORDER,   /* as the scene file lists them (chapter 12's --sort none, a bug) */
} gpu_scene_order;

/* A transparent object's sort key at the last update. */
typedef struct gpu_sort_key {
    float distance2; /* squared distance from the eye to its bounding sphere's centre */
    int object;
} gpu_sort_key;

typedef struct gpu_scene {
    const scene *src;
    mesh *meshes;
    mat4 *world;          /* per object, at the current time */
    mat3 *normal_matrix;  /* inverse transpose of world's upper 3x3 */
    vec4 *bounds;         /* per object world bounding sphere: centre xyz, radius w */
    gpu_light *lights;    /* active lights (radius > 0) */
    int light_count;
    int culled_count;     /* lights dropped because they never reach the cut-off */
    int infinite_count;   /* lights without a finite radius */
    gpu_batch *batches;   /* the opaque objects */
    int batch_count;
    int *transparent;     /* objects whose material has opacity < 1, in the scene's order */
    int *back_to_front;   /* the same, farthest first, at the last gpu_scene_update */
    gpu_sort_key *sort_keys;
    int transparent_count;
    GLuint light_buffer, light_texture;
    GLuint object_buffer, object_texture;
    gpu_textures textures; /* the materials' images (chapter 18) */
    float *texels;
    float *object_texels;
    frame_view view;
    double cutoff;
    float time;
    int falloff; /* SHADER_FALLOFF_*: the scene's at create; a renderer may draw a copy with another */
} gpu_scene;

bool gpu_scene_create(const scene *src, gpu_scene *out);
void gpu_scene_destroy(gpu_scene *gs);
bool gpu_scene_update(gpu_scene *gs, float time, double cutoff, int width, int height);
void gpu_scene_bind_lights(const gpu_scene *gs, GLuint program, int unit);
void gpu_scene_bind_objects(const gpu_scene *gs, GLuint program, int unit);
void gpu_scene_draw(const gpu_scene *gs, GLuint program);
void gpu_scene_draw_into(const gpu_scene *gs, GLuint framebuffer, int width, int height, GLuint program,
                         const gl_pass_state *state);
void gpu_scene_draw_transparent(const gpu_scene *gs, GLuint program, gpu_scene_order order,
                                const gl_pass_state *const passes[], int pass_count);
bool gpu_light_is_spot(const gpu_light *l);

#endif
