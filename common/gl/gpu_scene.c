/* gpu_scene.c - see gpu_scene.h. */
#include "gpu_scene.h"

#include "gl_util.h"
#include "light.h"
#include "log.h"
#include "model_import.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static bool load_mesh(const scene *s, const scene_mesh *decl, mesh *out)
{
    mesh_data data;
    if (!mesh_data_from_scene(&data, s, decl))
        return false;
    bool ok = mesh_create(&data, out);
    mesh_data_destroy(&data);
    return ok;
}

bool gpu_scene_create(const scene *src, gpu_scene *out)
{
    memset(out, 0, sizeof *out);
    out->src = src;
    out->falloff = src->falloff;
    out->meshes = calloc((size_t)src->mesh_count + 1, sizeof *out->meshes);
    out->world = calloc((size_t)src->object_count + 1, sizeof *out->world);
    out->normal_matrix = calloc((size_t)src->object_count + 1, sizeof *out->normal_matrix);
    out->bounds = calloc((size_t)src->object_count + 1, sizeof *out->bounds);
    out->batches = calloc((size_t)src->object_count + 1, sizeof *out->batches);
    out->transparent = calloc((size_t)src->object_count + 1, sizeof *out->transparent);
    out->back_to_front = calloc((size_t)src->object_count + 1, sizeof *out->back_to_front);
    out->sort_keys = calloc((size_t)src->object_count + 1, sizeof *out->sort_keys);
    out->object_texels = calloc(((size_t)src->object_count + 1) * SHADER_OBJECT_TEXELS * 4, sizeof(float));
    if (!out->meshes || !out->world || !out->normal_matrix || !out->bounds || !out->batches ||
        !out->transparent || !out->back_to_front || !out->sort_keys || !out->object_texels) {
        log_error("out of memory for the scene's %d objects", src->object_count);
        gpu_scene_destroy(out);
        return false;
    }
    for (int i = 0; i < src->mesh_count; i++) {
        if (!load_mesh(src, &src->meshes[i], &out->meshes[i])) {
            model_import_release();
            gpu_scene_destroy(out);
            return false;
        }
    }
    model_import_release(); /* a model file's meshes are all built: its import is not needed again */
    /* Opaque objects into batches (a batch's objects are consecutive: instance k is object first + k);
     * transparent ones into their own list, drawn one by one in the order the frame needs. */
    for (int i = 0; i < src->object_count; i++) {
        const scene_object *o = &src->objects[i];
        if (src->materials[o->material].opacity < 1.0f) {
            out->transparent[out->transparent_count] = out->back_to_front[out->transparent_count] = i;
            out->transparent_count++;
            continue;
        }
        gpu_batch *last = out->batch_count ? &out->batches[out->batch_count - 1] : NULL;
        if (last && last->mesh == o->mesh && last->first + last->count == i)
            last->count++;
        else
            out->batches[out->batch_count++] = (gpu_batch){.mesh = o->mesh, .first = i, .count = 1};
    }
    if (!gpu_textures_create(src, &out->textures)) {
        gpu_scene_destroy(out);
        return false;
    }
    out->light_buffer = gl_buffer_create();
    out->light_texture = gl_texture_create();
    out->object_buffer = gl_buffer_create();
    out->object_texture = gl_texture_create();
    return gl_check("gpu_scene_create");
}

void gpu_scene_destroy(gpu_scene *gs)
{
    if (gs->meshes && gs->src)
        for (int i = 0; i < gs->src->mesh_count; i++)
            mesh_destroy(&gs->meshes[i]);
    gpu_textures_destroy(&gs->textures);
    gl_buffer_destroy(&gs->light_buffer);
    gl_texture_destroy(&gs->light_texture);
    gl_buffer_destroy(&gs->object_buffer);
    gl_texture_destroy(&gs->object_texture);
    free(gs->meshes);
    free(gs->batches);
    free(gs->transparent);
    free(gs->back_to_front);
    free(gs->sort_keys);
    free(gs->object_texels);
    free(gs->world);
    free(gs->normal_matrix);
    free(gs->bounds);
    free(gs->lights);
    free(gs->texels);
    memset(gs, 0, sizeof *gs);
}

static void update_view(gpu_scene *gs, int width, int height)
{
    const scene_camera *c = &gs->src->camera;
    frame_view *v = &gs->view;
    v->width = width;
    v->height = height;
    v->near_plane = c->near_plane;
    v->far_plane = c->far_plane;
    glm_vec3_copy((float *)c->eye, v->eye);
    glm_lookat((float *)c->eye, (float *)c->target, (float *)c->up, v->view);
    glm_perspective(glm_rad(c->fovy_deg), (float)width / (float)height, c->near_plane, c->far_plane, v->proj);
    glm_mat4_mul(v->proj, v->view, v->view_proj);
    glm_mat4_inv(v->proj, v->inv_proj);
    glm_mat4_inv(v->view, v->inv_view);
    glm_mat4_inv(v->view_proj, v->inv_view_proj);
}

static void update_objects(gpu_scene *gs, float time)
{
    const scene *s = gs->src;
    for (int i = 0; i < s->object_count; i++) {
        scene_object_world_at(s, i, time, gs->world[i]);
        mat4 inv;
        glm_mat4_inv(gs->world[i], inv);
        glm_mat4_transpose(inv);
        glm_mat4_pick3(inv, gs->normal_matrix[i]);
        /* Bounding sphere: the mesh's radius about its origin, scaled by the largest axis scale. */
        const scene_object *o = &s->objects[i];
        float smax = fmaxf(fabsf(o->scale[0]), fmaxf(fabsf(o->scale[1]), fabsf(o->scale[2])));
        gs->bounds[i][0] = gs->world[i][3][0];
        gs->bounds[i][1] = gs->world[i][3][1];
        gs->bounds[i][2] = gs->world[i][3][2];
        gs->bounds[i][3] = gs->meshes[o->mesh].bound_radius * smax;

        float *t = gs->object_texels + (size_t)i * SHADER_OBJECT_TEXELS * 4;
        memcpy(t, gs->world[i], 16 * sizeof(float));
        for (int c = 0; c < 3; c++) {
            float *column = t + 4 * (SHADER_OBJECT_TEXEL_NORMAL + c);
            memcpy(column, gs->normal_matrix[i][c], 3 * sizeof(float));
            column[3] = 0.0f;
        }
        const scene_material *m = &s->materials[o->material];
        /* A metallic-roughness material travels as specular = metallic, shininess = -1 - roughness
         * (shaders/shading.glsl: a negative shininess marks it). */
        const float material[4] = {m->albedo[0], m->albedo[1], m->albedo[2], m->pbr ? m->metallic : m->specular};
        const float shininess[4] = {m->pbr ? -1.0f - m->roughness : m->shininess, m->opacity, 0, 0};
        memcpy(t + 4 * SHADER_OBJECT_TEXEL_MATERIAL, material, sizeof material);
        memcpy(t + 4 * SHADER_OBJECT_TEXEL_SHININESS, shininess, sizeof shininess);
        /* The maps: each one's layer in its array (gpu_textures.h), -1 for none. */
        float *maps = t + 4 * SHADER_OBJECT_TEXEL_MAPS;
        for (int k = 0; k < 4; k++)
            maps[k] = m->pbr && m->maps[k] >= 0 ? (float)gs->textures.layer[m->maps[k]] : -1.0f;
        float *emissive = t + 4 * SHADER_OBJECT_TEXEL_EMISSIVE;
        for (int k = 0; k < 3; k++)
            emissive[k] = m->pbr ? m->emissive[k] : 0.0f;
        emissive[3] = m->pbr && m->maps[SCENE_MAP_EMISSIVE] >= 0 ? (float)gs->textures.layer[m->maps[SCENE_MAP_EMISSIVE]]
                                                                 : -1.0f;
    }
    size_t bytes = ((size_t)s->object_count + 1) * SHADER_OBJECT_TEXELS * 4 * sizeof(float);
    gl_texture_buffer_upload(gs->object_buffer, gs->object_texture, GL_RGBA32F, gs->object_texels, bytes);
}

/* Farthest first; at equal distances the scene's order, so every renderer draws the same order. */
static int farther_first(const void *a, const void *b)
{
    const gpu_sort_key *x = a, *y = b;
    if (x->distance2 != y->distance2)
        return x->distance2 > y->distance2 ? -1 : 1;
    return (x->object > y->object) - (x->object < y->object);
}

/* The transparent objects back to front, by their bounding spheres' centres (after update_objects). */
static void sort_transparent(gpu_scene *gs)
{
    for (int k = 0; k < gs->transparent_count; k++) {
        int i = gs->transparent[k];
        gs->sort_keys[k] = (gpu_sort_key){glm_vec3_distance2(gs->view.eye, gs->bounds[i]), i};
    }
    qsort(gs->sort_keys, (size_t)gs->transparent_count, sizeof *gs->sort_keys, farther_first);
    for (int k = 0; k < gs->transparent_count; k++)
        gs->back_to_front[k] = gs->sort_keys[k].object;
}

/* A spot's unit axis and the cosines of its half-angles, in double; a point light: no cone. */
static void light_cone(const scene_light *src, gpu_light *l)
{
    if (!src->spot) {
        glm_vec3_zero(l->direction);
        l->cos_outer = l->cos_inner = -1.0f;
        return;
    }
    double d[3] = {src->direction[0], src->direction[1], src->direction[2]};
    double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int k = 0; k < 3; k++)
        l->direction[k] = (float)(d[k] / len);
    const double to_rad = acos(-1.0) / 180.0;
    l->cos_outer = (float)cos(src->outer_deg * to_rad);
    l->cos_inner = (float)cos(src->inner_deg * to_rad);
}

static bool update_lights(gpu_scene *gs, float time, double cutoff)
{
    const scene *s = gs->src;
    if (s->light_count > 0) {
        gpu_light *l = realloc(gs->lights, (size_t)s->light_count * sizeof *l);
        float *t = realloc(gs->texels, (size_t)s->light_count * SHADER_LIGHT_TEXELS * 4 * sizeof *t);
        if (l)
            gs->lights = l;
        if (t)
            gs->texels = t;
        if (!l || !t) {
            log_error("out of memory for %d lights", s->light_count);
            return false;
        }
    }
    gs->light_count = gs->culled_count = gs->infinite_count = 0;
    for (int i = 0; i < s->light_count; i++) {
        const scene_light *src = &s->lights[i];
        double r = light_radius(src->kc, src->kl, src->kq, light_peak(src->color, src->intensity), cutoff);
        if (!(r > 0.0)) {
            gs->culled_count++;
            continue;
        }
        gpu_light *l = &gs->lights[gs->light_count];
        float *t = gs->texels + (size_t)gs->light_count * SHADER_LIGHT_TEXELS * 4;
        gs->light_count++;
        scene_light_position_at(s, i, time, l->position);
        if (isinf(r) || r > FLT_MAX)
            gs->infinite_count++;
        l->radius = r > FLT_MAX ? FLT_MAX : (float)r;
        glm_vec3_scale((float *)src->color, src->intensity, l->radiance);
        l->attenuation[0] = src->kc, l->attenuation[1] = src->kl, l->attenuation[2] = src->kq;
        l->source = i;
        light_cone(src, l);
        /* one line per texel (common/base/shader_layout.h) */
        const float texels[SHADER_LIGHT_TEXELS * 4] = {
            l->position[0],  l->position[1],  l->position[2],  l->radius,
            l->radiance[0],  l->radiance[1],  l->radiance[2],  l->cos_outer,
            src->kc,         src->kl,         src->kq,         l->cos_inner,
            l->direction[0], l->direction[1], l->direction[2], 0.0f};
        memcpy(t, texels, sizeof texels);
    }
    /* A texture buffer may not be empty: keep one texel so the binding stays valid with 0 lights. */
    static const float zero[4] = {0};
    size_t bytes = (size_t)gs->light_count * SHADER_LIGHT_TEXELS * 4 * sizeof(float);
    gl_texture_buffer_upload(gs->light_buffer, gs->light_texture, GL_RGBA32F,
                             bytes ? (const void *)gs->texels : zero, bytes ? bytes : sizeof zero);
    return true;
}

bool gpu_scene_update(gpu_scene *gs, float time, double cutoff, int width, int height)
{
    gs->time = time;
    gs->cutoff = cutoff;
    update_view(gs, width, height);
    update_objects(gs, time);
    sort_transparent(gs);
    return update_lights(gs, time, cutoff);
}

void gpu_scene_bind_lights(const gpu_scene *gs, GLuint program, int unit)
{
    glActiveTexture(GL_TEXTURE0 + (GLenum)unit);
    glBindTexture(GL_TEXTURE_BUFFER, gs->light_texture);
    glUniform1i(glGetUniformLocation(program, "u_lights"), unit);
    glUniform1i(glGetUniformLocation(program, "u_light_count"), gs->light_count);
    glUniform3fv(glGetUniformLocation(program, "u_ambient"), 1, gs->src->ambient);
    glUniform1i(glGetUniformLocation(program, "u_falloff"), gs->falloff);
    glActiveTexture(GL_TEXTURE0);
}

void gpu_scene_bind_objects(const gpu_scene *gs, GLuint program, int unit)
{
    glActiveTexture(GL_TEXTURE0 + (GLenum)unit);
    glBindTexture(GL_TEXTURE_BUFFER, gs->object_texture);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(glGetUniformLocation(program, "u_objects"), unit);
    gpu_textures_bind(&gs->textures, program); /* the materials' images, on their own two units */
    glUniformMatrix4fv(glGetUniformLocation(program, "u_view_proj"), 1, GL_FALSE, (const float *)gs->view.view_proj);
}

void gpu_scene_draw(const gpu_scene *gs, GLuint program)
{
    GLint first = glGetUniformLocation(program, "u_first_object");
    for (int b = 0; b < gs->batch_count; b++) {
        const gpu_batch *batch = &gs->batches[b];
        glUniform1i(first, batch->first);
        mesh_draw_instanced(&gs->meshes[batch->mesh], batch->count);
    }
}

void gpu_scene_draw_into(const gpu_scene *gs, GLuint framebuffer, int width, int height, GLuint program,
                         const gl_pass_state *state)
{
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, width, height);
    gl_pass_state_apply(state);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(program);
    gpu_scene_bind_objects(gs, program, SHADER_UNIT_OBJECTS);
    gpu_scene_draw(gs, program);
    gl_pass_state_reset();
}

void gpu_scene_draw_transparent(const gpu_scene *gs, GLuint program, gpu_scene_order order,
                                const gl_pass_state *const passes[], int pass_count)
{
    const int *objects = order == GPU_SCENE_BACK_TO_FRONT ? gs->back_to_front : gs->transparent;
    GLint first = glGetUniformLocation(program, "u_first_object");
    for (int k = 0; k < gs->transparent_count; k++) {
        int i = objects[k];
        glUniform1i(first, i);
        for (int p = 0; p < pass_count; p++) {
            gl_pass_state_apply(passes[p]);
            mesh_draw_instanced(&gs->meshes[gs->src->objects[i].mesh], 1);
        }
    }
}

bool gpu_light_is_spot(const gpu_light *l) { return l->cos_outer > -1.0f; }
