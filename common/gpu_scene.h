/* gpu_scene.h - a scene ready to draw: meshes on the GPU, per-frame matrices and the light list.
 *
 *   gpu_scene_create(src, gs)        upload every mesh of the scene
 *   gpu_scene_destroy(gs)
 *   gpu_scene_update(gs, time, cutoff, width, height)
 *                                    camera matrices for the viewport, object matrices and light
 *                                    positions at `time`, light radii for `cutoff`; lights that
 *                                    never reach the cut-off are culled here (radius 0)
 *   gpu_scene_bind_lights(gs, program, unit)
 *                                    u_lights (texture buffer on `unit`), u_light_count, u_ambient
 *   gpu_scene_draw_object(gs, i, loc) set u_model / u_normal_matrix (uniform locations) and draw
 *
 * Light texels (RGBA32F, three per light): position.xyz + radius, radiance (I*colour) + 0,
 * attenuation kc kl kq + 0. An infinite radius is stored as FLT_MAX.
 */
#ifndef COMMON_GPU_SCENE_H
#define COMMON_GPU_SCENE_H

#include "mesh.h"
#include "scene.h"

#include <cglm/cglm.h>

#define GPU_LIGHT_TEXELS 3

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
} gpu_light;

typedef struct gpu_object_uniforms {
    GLint model, normal_matrix;
} gpu_object_uniforms;

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
    GLuint light_buffer, light_texture;
    float *texels;
    frame_view view;
    double cutoff;
    float time;
} gpu_scene;

bool gpu_scene_create(const scene *src, gpu_scene *out);
void gpu_scene_destroy(gpu_scene *gs);
bool gpu_scene_update(gpu_scene *gs, float time, double cutoff, int width, int height);
void gpu_scene_bind_lights(const gpu_scene *gs, GLuint program, int unit);
void gpu_scene_draw_object(const gpu_scene *gs, int index, gpu_object_uniforms loc);

#endif
