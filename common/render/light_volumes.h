/* light_volumes.h - one sphere per light, drawn so that a light shades only the pixels its sphere
 * covers. Written in chapters 04 (the instanced volume, fixed radius) and 05 (each light's own
 * radius, full-screen lights); chapters 05-07 and the benchmark draw with it.
 *
 *   light_volumes_create(lv, defines)     the volume and ambient programs (shaders/light_volume.*,
 *                                         volume_ambient.frag, compiled with `defines`: OVERWRITE,
 *                                         FIXED_RADIUS), the volume mesh, the per-instance index
 *   light_volumes_destroy(lv)
 *   light_volumes_mesh_create(sphere, mesh_scale)
 *                                         the volume mesh alone and its scale 1 / inradius (the
 *                                         volumes view draws it as lines, common/render/debug_views.c)
 *   light_volumes_draw_ambient(lv, g, gs) ambient light at every covered pixel (full-screen triangle)
 *   light_volumes_bind(lv, g, gs, view)   the volume program with the lights, the G-buffer and the
 *                                         camera bound; `view` is a light_volumes_view
 *   light_volumes_sort(lv, gs)            instance order: lights with a finite volume first, then
 *                                         those whose sphere contains the whole view (or is infinite)
 *   light_volumes_draw(lv, gs, state)     after bind and sort: the finite volumes in ONE instanced
 *                                         draw with the pass state `state`, then the others as
 *                                         full-screen triangles (no culling, no depth test);
 *                                         leaves gl_pass_state_reset()'s state
 *
 * The volume is an 80-triangle icosphere (mesh_data_icosphere(m, 1)) scaled by radius / inradius:
 * its vertices lie on the unit sphere and its faces inside it, so only the scaled mesh contains the
 * whole sphere (tests/unit/test_volume_mesh.c). The lighting shader calls shade_light() from
 * shaders/shading.glsl exactly as forward.frag does.
 *
 * Chapter 09's cone volume for spot lights (shaders/cone_volume.glsl places it; docs/09_spot_lights.md):
 *   light_volumes_cone_create(cone)       the template mesh on the GPU and its two scales
 *   light_volumes_cone_destroy(cone)
 *   light_volumes_cone_mesh_data(m)       the template on the CPU: the apex, and a cap of
 *                                         LIGHT_VOLUMES_CONE_RINGS rings of LIGHT_VOLUMES_CONE_SEGMENTS
 *                                         vertices from the tip to the rim (72 triangles)
 *   light_volumes_cone_point(a, cos_outer, side_scale, cap_scale, out)
 *                                         where cone_volume.glsl puts template vertex a, in units of
 *                                         the radius, apex at 0, axis +Z (the same formula, in double)
 *   light_volumes_cone_side_scale()       1 / cos(pi / segments) (with a margin): the pyramid's
 *                                         faces touch the circular cone instead of cutting it
 *   light_volumes_cone_cap_scale(m)       1 / the smallest distance of a cap face from the apex at the
 *                                         widest cone (outer -> 90 degrees; with a margin): every cap
 *                                         face then lies outside the sphere, for every cone
 * With both scales the convex mesh contains the spot's cone cut by its sphere, for every outer angle
 * below 90 degrees (tests/spot/test_cone_mesh.c samples it); with both 1 it cuts into it.
 */
#ifndef COMMON_LIGHT_VOLUMES_H
#define COMMON_LIGHT_VOLUMES_H

#include "gbuffer.h"
#include "gl_util.h"
#include "gpu_scene.h"
#include "mesh.h"

typedef enum light_volumes_view {
    LIGHT_VOLUMES_VIEW_LIT = SHADER_VIEW_LIT,           /* the shaded picture */
    LIGHT_VOLUMES_VIEW_RING = SHADER_VIEW_RING,         /* plus a line where each cut-off sphere meets a surface */
    LIGHT_VOLUMES_VIEW_OVERDRAW = SHADER_VIEW_OVERDRAW, /* 1 / SHADER_OVERDRAW_SCALE per lighting fragment, to be
                                                           added up: the count behind the heat map */
} light_volumes_view;

typedef struct light_volumes {
    GLuint program, ambient_program;
    GLint u_view_proj, u_mesh_scale, u_fixed_radius, u_fullscreen, u_first_instance, u_light_index, u_view;
    mesh sphere;
    float mesh_scale;                   /* 1 / inradius of the icosphere */
    GLuint index_buffer, index_texture; /* per instance: the light's index (finite, then full-screen) */
    int *indices;
    int index_cap;
    int finite_count; /* lights drawn as volumes by the last light_volumes_sort */
} light_volumes;

#define LIGHT_VOLUMES_CONE_SEGMENTS 12 /* around the axis */
#define LIGHT_VOLUMES_CONE_RINGS 3     /* from the tip to the rim */

typedef struct light_volumes_cone {
    mesh mesh;        /* the template: apex (0, 0, -1), cap vertices (cos a, sin a, t) */
    float side_scale; /* light_volumes_cone_side_scale() */
    float cap_scale;  /* light_volumes_cone_cap_scale() */
} light_volumes_cone;

bool light_volumes_create(light_volumes *lv, const char *defines);
void light_volumes_destroy(light_volumes *lv);
bool light_volumes_mesh_create(mesh *sphere, float *mesh_scale);
void light_volumes_draw_ambient(const light_volumes *lv, const gbuffer *g, const gpu_scene *gs);
void light_volumes_bind(const light_volumes *lv, const gbuffer *g, const gpu_scene *gs, light_volumes_view view);
bool light_volumes_sort(light_volumes *lv, const gpu_scene *gs);
void light_volumes_draw(const light_volumes *lv, const gpu_scene *gs, const gl_pass_state *state);

bool light_volumes_cone_create(light_volumes_cone *cone);
void light_volumes_cone_destroy(light_volumes_cone *cone);
bool light_volumes_cone_mesh_data(mesh_data *m);
void light_volumes_cone_point(const float a[3], double cos_outer, double side_scale, double cap_scale,
                              double out[3]);
double light_volumes_cone_side_scale(void);
double light_volumes_cone_cap_scale(const mesh_data *m);

#endif
