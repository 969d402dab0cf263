/* light_volumes.c - see light_volumes.h. */
#include "light_volumes.h"

#include "frame_timer.h"
#include "gl_program.h"
#include "log.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* 80 triangles: measured fastest on llvmpipe (vertex work is not free; 320 was slower). */
#define VOLUME_SUBDIVISIONS 1

static bool load_programs(light_volumes *lv, const char *defines)
{
    lv->program = gl_program_load("light_volume.vert", "light_volume.frag", defines);
    lv->ambient_program = gl_program_load("fullscreen.vert", "volume_ambient.frag", defines);
    if (!lv->program || !lv->ambient_program)
        return false;
    lv->u_view_proj = glGetUniformLocation(lv->program, "u_view_proj");
    lv->u_mesh_scale = glGetUniformLocation(lv->program, "u_mesh_scale");
    lv->u_fixed_radius = glGetUniformLocation(lv->program, "u_fixed_radius");
    lv->u_fullscreen = glGetUniformLocation(lv->program, "u_fullscreen");
    lv->u_first_instance = glGetUniformLocation(lv->program, "u_first_instance");
    lv->u_light_index = glGetUniformLocation(lv->program, "u_light_index");
    lv->u_view = glGetUniformLocation(lv->program, "u_view");
    return true;
}

bool light_volumes_mesh_create(mesh *sphere, float *mesh_scale)
{
    mesh_data data;
    if (!mesh_data_icosphere(&data, VOLUME_SUBDIVISIONS))
        return false;
    *mesh_scale = (float)(1.0 / mesh_data_inradius(&data));
    bool ok = mesh_create(&data, sphere);
    mesh_data_destroy(&data);
    return ok;
}

bool light_volumes_create(light_volumes *lv, const char *defines)
{
    memset(lv, 0, sizeof *lv);
    if (!light_volumes_mesh_create(&lv->sphere, &lv->mesh_scale) || !load_programs(lv, defines)) {
        light_volumes_destroy(lv);
        return false;
    }
    lv->index_buffer = gl_buffer_create();
    lv->index_texture = gl_texture_create();
    return gl_check("light_volumes_create");
}

void light_volumes_destroy(light_volumes *lv)
{
    gl_program_destroy(&lv->program);
    gl_program_destroy(&lv->ambient_program);
    mesh_destroy(&lv->sphere);
    gl_buffer_destroy(&lv->index_buffer);
    gl_texture_destroy(&lv->index_texture);
    free(lv->indices);
    memset(lv, 0, sizeof *lv);
}

void light_volumes_draw_ambient(const light_volumes *lv, const gbuffer *g, const gpu_scene *gs)
{
    frame_timer_mark("lighting");
    glUseProgram(lv->ambient_program);
    gpu_scene_bind_lights(gs, lv->ambient_program, SHADER_UNIT_LIGHTS);
    gbuffer_bind_textures(g, gs, lv->ambient_program, SHADER_UNIT_GBUFFER);
    gl_draw_fullscreen();
}

void light_volumes_bind(const light_volumes *lv, const gbuffer *g, const gpu_scene *gs, light_volumes_view view)
{
    glUseProgram(lv->program);
    gpu_scene_bind_lights(gs, lv->program, SHADER_UNIT_LIGHTS);
    gbuffer_bind_textures(g, gs, lv->program, SHADER_UNIT_GBUFFER);
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_LIGHT_INDEX);
    glBindTexture(GL_TEXTURE_BUFFER, lv->index_texture);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(lv->u_light_index, SHADER_UNIT_LIGHT_INDEX);
    glUniformMatrix4fv(lv->u_view_proj, 1, GL_FALSE, (const float *)gs->view.view_proj);
    glUniform1f(lv->u_mesh_scale, lv->mesh_scale);
    glUniform1i(lv->u_view, (int)view);
}

/* A sphere that contains the whole view frustum covers every pixel: cheaper and safer (no huge
 * coordinates) as one full-screen triangle. */
static bool contains_frustum(const frame_view *v, const float centre[3], float radius)
{
    if (!(radius < FLT_MAX))
        return true;
    for (int corner = 0; corner < 8; corner++) {
        vec4 ndc = {corner & 1 ? 1.0f : -1.0f, corner & 2 ? 1.0f : -1.0f, corner & 4 ? 1.0f : -1.0f, 1.0f}, w;
        glm_mat4_mulv((vec4 *)v->inv_view_proj, ndc, w);
        vec3 p = {w[0] / w[3], w[1] / w[3], w[2] / w[3]};
        if (glm_vec3_distance(p, (float *)centre) >= radius)
            return false;
    }
    return true;
}

static bool reserve_indices(light_volumes *lv, int n)
{
    if (n <= lv->index_cap)
        return true;
    int *grown = realloc(lv->indices, (size_t)n * sizeof *grown);
    if (!grown) {
        log_error("out of memory for %d light indices", n);
        return false;
    }
    lv->indices = grown;
    lv->index_cap = n;
    return true;
}

bool light_volumes_sort(light_volumes *lv, const gpu_scene *gs)
{
    if (!reserve_indices(lv, gs->light_count > 0 ? gs->light_count : 1))
        return false;
    int front = 0, back = gs->light_count;
    for (int i = 0; i < gs->light_count; i++) {
        const gpu_light *l = &gs->lights[i];
        if (contains_frustum(&gs->view, l->position, l->radius))
            lv->indices[--back] = i;
        else
            lv->indices[front++] = i;
    }
    lv->finite_count = front;
    if (gs->light_count == 0)
        lv->indices[0] = 0; /* a texture buffer may not be empty */
    gl_texture_buffer_upload(lv->index_buffer, lv->index_texture, GL_R32I, lv->indices,
                             (size_t)(gs->light_count > 0 ? gs->light_count : 1) * sizeof(int));
    return true;
}

void light_volumes_draw(const light_volumes *lv, const gpu_scene *gs, const gl_pass_state *state)
{
    if (lv->finite_count > 0) {
        gl_pass_state_apply(state);
        glUniform1i(lv->u_fullscreen, 0);
        glUniform1i(lv->u_first_instance, 0);
        mesh_draw_instanced(&lv->sphere, lv->finite_count);
    }
    int fullscreen = gs->light_count - lv->finite_count;
    if (fullscreen > 0) {
        /* Every pixel may be lit: no culling, no depth test; the blending stays. */
        gl_pass_state_apply(&(gl_pass_state){.blend = {state->blend[0], state->blend[1]}});
        glUniform1i(lv->u_fullscreen, 1);
        glUniform1i(lv->u_first_instance, lv->finite_count);
        glBindVertexArray(lv->sphere.vao);
        glDrawArraysInstanced(GL_TRIANGLES, 0, 3, fullscreen);
    }
    gl_pass_state_reset();
}

/* ---- chapter 09's cone volume ------------------------------------------------------------------ */

/* Both scales are exact tangencies (a side face touches the cone along a whole line): 0.1 % more
 * keeps float rounding in the vertex shader and the rasteriser on the outside. */
#define CONE_MARGIN 1.001

enum { CONE_SEGMENTS = LIGHT_VOLUMES_CONE_SEGMENTS, CONE_RINGS = LIGHT_VOLUMES_CONE_RINGS };

/* Vertex numbers: the apex, the tip, then ring k (1 = next to the tip, CONE_RINGS = the rim). */
static uint32_t cone_vertex(int ring, int segment)
{
    return ring == 0 ? 1u : (uint32_t)(2 + (ring - 1) * CONE_SEGMENTS + segment % CONE_SEGMENTS);
}

bool light_volumes_cone_mesh_data(mesh_data *m)
{
    memset(m, 0, sizeof *m);
    m->vertex_count = 2 + CONE_RINGS * CONE_SEGMENTS;
    m->index_count = 3 * (2 * CONE_SEGMENTS * CONE_RINGS);
    m->vertices = calloc((size_t)m->vertex_count * MESH_VERTEX_FLOATS, sizeof(float));
    m->indices = malloc((size_t)m->index_count * sizeof(uint32_t));
    if (!m->vertices || !m->indices) {
        log_error("out of memory for the cone volume");
        mesh_data_destroy(m);
        return false;
    }
    /* Positions only (the normals stay 0: nothing shades the volume's surface). */
    float *v = m->vertices;
    v[2] = -1.0f;                        /* the apex */
    v[MESH_VERTEX_FLOATS + 0] = 1.0f;    /* the tip: t = 0, its azimuth does not matter */
    for (int k = 1; k <= CONE_RINGS; k++)
        for (int i = 0; i < CONE_SEGMENTS; i++) {
            double a = 2.0 * acos(-1.0) * i / CONE_SEGMENTS;
            float *p = v + (size_t)cone_vertex(k, i) * MESH_VERTEX_FLOATS;
            p[0] = (float)cos(a), p[1] = (float)sin(a), p[2] = (float)k / CONE_RINGS;
        }
    /* Counter-clockwise seen from outside: the tip's fan and the bands (azimuth grows
     * counter-clockwise seen from +Z), then the sides from the apex, which face away from +Z. */
    uint32_t *t = m->indices;
    for (int i = 0; i < CONE_SEGMENTS; i++) {
        *t++ = cone_vertex(0, 0), *t++ = cone_vertex(1, i), *t++ = cone_vertex(1, i + 1);
        for (int k = 1; k < CONE_RINGS; k++) {
            *t++ = cone_vertex(k, i), *t++ = cone_vertex(k + 1, i), *t++ = cone_vertex(k + 1, i + 1);
            *t++ = cone_vertex(k, i), *t++ = cone_vertex(k + 1, i + 1), *t++ = cone_vertex(k, i + 1);
        }
        *t++ = 0, *t++ = cone_vertex(CONE_RINGS, i + 1), *t++ = cone_vertex(CONE_RINGS, i);
    }
    m->bounds_min[0] = m->bounds_min[1] = m->bounds_min[2] = -1.0f;
    m->bounds_max[0] = m->bounds_max[1] = m->bounds_max[2] = 1.0f;
    m->bound_radius = sqrtf(2.0f);
    return true;
}

void light_volumes_cone_point(const float a[3], double cos_outer, double side_scale, double cap_scale,
                              double out[3])
{
    if (a[2] < 0.0f) {
        out[0] = out[1] = out[2] = 0.0;
        return;
    }
    double sin_outer = sqrt(fmax(1.0 - cos_outer * cos_outer, 0.0));
    double polar = a[2] * atan2(side_scale * sin_outer, cos_outer);
    out[0] = cap_scale * sin(polar) * a[0];
    out[1] = cap_scale * sin(polar) * a[1];
    out[2] = cap_scale * cos(polar);
}

double light_volumes_cone_side_scale(void)
{
    return CONE_MARGIN / cos(acos(-1.0) / CONE_SEGMENTS);
}

/* The widest cone (cos(outer) = 0) has the largest cap faces: the nearest of their planes sets the
 * scale that pushes every cap face of every cone out of the unit sphere. */
double light_volumes_cone_cap_scale(const mesh_data *m)
{
    double nearest = INFINITY;
    for (int f = 0; f + 2 < m->index_count; f += 3) {
        double p[3][3];
        bool apex = false;
        for (int c = 0; c < 3; c++) {
            const float *a = m->vertices + (size_t)m->indices[f + c] * MESH_VERTEX_FLOATS;
            apex = apex || a[2] < 0.0f;
            light_volumes_cone_point(a, 0.0, light_volumes_cone_side_scale(), 1.0, p[c]);
        }
        if (apex)
            continue; /* a side face: its plane goes through the apex, the side scale handles it */
        double u[3], w[3];
        for (int k = 0; k < 3; k++)
            u[k] = p[1][k] - p[0][k], w[k] = p[2][k] - p[0][k];
        double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        nearest = fmin(nearest, fabs(n[0] * p[0][0] + n[1] * p[0][1] + n[2] * p[0][2]) / len);
    }
    return CONE_MARGIN / nearest;
}

bool light_volumes_cone_create(light_volumes_cone *cone)
{
    memset(cone, 0, sizeof *cone);
    mesh_data data;
    if (!light_volumes_cone_mesh_data(&data))
        return false;
    cone->side_scale = (float)light_volumes_cone_side_scale();
    cone->cap_scale = (float)light_volumes_cone_cap_scale(&data);
    bool ok = mesh_create(&data, &cone->mesh);
    mesh_data_destroy(&data);
    return ok;
}

void light_volumes_cone_destroy(light_volumes_cone *cone)
{
    mesh_destroy(&cone->mesh);
    memset(cone, 0, sizeof *cone);
}
