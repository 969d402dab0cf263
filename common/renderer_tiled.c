/* renderer_tiled.c - see renderer_tiled.h. */
#include "renderer_tiled.h"

#include "frame_timer.h"
#include "log.h"
#include "shader_layout.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- chapter 10's culling, GL-free: the C twin of shaders/tiled_cull.glsl ---- */

void renderer_tile_sphere(const gpu_light *l, const frame_view *view, vec4 out)
{
    /* A spot (cone half-angle a, radius r): the sphere of radius r / (2 cos a) on the axis at that
     * distance from the apex up to 45 degrees (through the apex and the rim), r sin a at r cos a beyond
     * (through the rim). A point light, or a cone of 90 degrees and more: the light's own sphere. */
    float r = l->radius, c = l->cos_outer;
    bool point = c <= 0.0f || r > 1e30f, narrow = c >= 0.70710678f;
    float along = point ? 0.0f : narrow ? r / (2.0f * c) : r * c;
    vec4 world = {l->position[0], l->position[1], l->position[2], 1.0f};
    glm_vec3_muladds((float *)l->direction, along, world);
    glm_mat4_mulv((vec4 *)view->view, world, out);
    out[3] = point ? r : narrow ? along : r * sqrtf(1.0f - c * c);
    out[3] += 1e-4f * (out[3] + glm_vec3_norm(out)); /* float rounding never cuts a light */
}

/* Side plane k is +-(row axis - bound * row 3) of the projection (x_clip >= x0 w_clip, ...); the box
 * holds the corner rays (scaled to z = -1) at both depths. */
void renderer_tile_frustum_make(const frame_view *v, int x, int y, int size, const float depth[2],
                                renderer_tile_frustum *f)
{
    /* the tile's pixel rectangle, cut at the view's edge, in NDC */
    float rect[4] = {(float)x, (float)y, glm_min(x + size, v->width), glm_min(y + size, v->height)};
    for (int k = 0; k < 4; k++)
        rect[k] = rect[k] / (float)(k % 2 ? v->height : v->width) * 2.0f - 1.0f;
    glm_vec3_broadcast(3.0e38f, f->lo);
    glm_vec3_broadcast(-3.0e38f, f->hi);
    for (int k = 0; k < 4; k++) { /* x >= x0, x <= x1, y >= y0, y <= y1 */
        float sign = k % 2 ? -1.0f : 1.0f, bound = rect[k / 2 + 2 * (k % 2)];
        for (int j = 0; j < 4; j++)
            f->side[k][j] = sign * (v->proj[j][k / 2] - bound * v->proj[j][3]);
        glm_vec4_scale(f->side[k], 1.0f / glm_vec3_norm(f->side[k]), f->side[k]);
        vec4 p;
        glm_mat4_mulv((vec4 *)v->inv_proj, (vec4){rect[k % 2 ? 2 : 0], rect[k < 2 ? 1 : 3], 0.0f, 1.0f}, p);
        for (int j = 0; j < 3; j++) {
            float ray = p[j] / -p[2];
            f->lo[j] = glm_min(f->lo[j], glm_min(ray * depth[0], ray * depth[1]));
            f->hi[j] = glm_max(f->hi[j], glm_max(ray * depth[0], ray * depth[1]));
        }
    }
    f->depth[0] = depth[0], f->depth[1] = depth[1];
}

bool renderer_tile_sphere_visible(const renderer_tile_frustum *f, const vec4 s)
{
    if (-s[2] + s[3] < f->depth[0] || -s[2] - s[3] > f->depth[1])
        return false;
    for (int k = 0; k < 4; k++)
        if (glm_vec3_dot((float *)f->side[k], (float *)s) + f->side[k][3] < -s[3])
            return false;
    float outside2 = 0.0f; /* squared distance from the centre to the box */
    for (int j = 0; j < 3; j++) {
        float d = glm_max(glm_max(f->lo[j] - s[j], s[j] - f->hi[j]), 0.0f);
        outside2 += d * d;
    }
    return outside2 <= s[3] * s[3];
}

/* ---- chapter 10's frame (chapters/10_tiled_deferred.c: the same steps, explained there) ---- */

enum { TILE_SIZE = 16 };
#define TILED_DEFINES "TILE_SIZE 16\nVIEW_TILES 3"

void tiled_destroy(renderer_tiled *t)
{
    gl_program_destroy(&t->cull_program);
    gl_program_destroy(&t->shade_program);
    gl_program_destroy(&t->bounds_program);
    GLuint *buffers[] = {&t->list_buffer, &t->range_buffer, &t->sphere_buffer};
    GLuint *textures[] = {&t->list_texture, &t->range_texture, &t->sphere_texture};
    for (int i = 0; i < 3; i++)
        gl_buffer_destroy(buffers[i]), gl_texture_destroy(textures[i]);
    fbo_destroy(&t->bounds);
    gbuffer_destroy(&t->g);
    free(t->spheres), free(t->tile_bounds), free(t->frustums), free(t->ranges), free(t->list);
    memset(t, 0, sizeof *t);
}

/* Programs and buffers once; the G-buffer, tiles and lists at the view's size and light count. */
bool ensure_tiled(renderer_set *r, const gpu_scene *gs)
{
    renderer_tiled *t = &r->tiled;
    int w = gs->view.width, h = gs->view.height;
    if (!r->have_tiled) {
        memset(t, 0, sizeof *t);
        t->compute = renderer_have_compute();
        t->shade_program = gl_program_load("fullscreen.vert", "tiled_shade.frag", TILED_DEFINES);
        t->bounds_program = gl_program_load("fullscreen.vert", "tile_depth_bounds.frag", TILED_DEFINES);
        if (t->compute)
            t->cull_program = gl_compute_program_load("tiled_cull.comp", TILED_DEFINES);
        GLuint *buffers[] = {&t->list_buffer, &t->range_buffer, &t->sphere_buffer};
        GLuint *textures[] = {&t->list_texture, &t->range_texture, &t->sphere_texture};
        for (int i = 0; i < 3; i++)
            *buffers[i] = gl_buffer_create(), *textures[i] = gl_texture_create();
        r->have_tiled = t->shade_program && t->bounds_program && (!t->compute || t->cull_program) &&
                        gbuffer_create(&t->g, w, h);
        if (!r->have_tiled) {
            tiled_destroy(t);
            return false;
        }
    }
    if ((t->g.fbo.width != w || t->g.fbo.height != h) && !gbuffer_resize(&t->g, w, h))
        return false;
    int tiles_x = (w + TILE_SIZE - 1) / TILE_SIZE, tiles_y = (h + TILE_SIZE - 1) / TILE_SIZE;
    int tiles = tiles_x * tiles_y, capacity = gs->light_count > 0 ? gs->light_count : 1;
    GLint max_texels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &max_texels);
    capacity = capacity < max_texels / tiles ? capacity : max_texels / tiles;
    if (tiles_x == t->tiles_x && tiles_y == t->tiles_y && capacity == t->capacity)
        return true;
    t->tiles_x = tiles_x, t->tiles_y = tiles_y, t->capacity = capacity;
    t->tile_bounds = realloc(t->tile_bounds, (size_t)tiles * 4 * sizeof(float));
    t->ranges = realloc(t->ranges, (size_t)tiles * 4 * sizeof(int));
    t->frustums = realloc(t->frustums, (size_t)tiles * sizeof *t->frustums);
    fbo_destroy(&t->bounds);
    const fbo_desc bounds = {.color_formats = {GL_RGBA32F}, .color_count = 1, .name = "tile bounds"};
    if (!t->tile_bounds || !t->ranges || !t->frustums || !fbo_create(&t->bounds, &bounds, tiles_x, tiles_y))
        return false;
    if (t->compute) {
        gl_texture_buffer_upload(t->list_buffer, t->list_texture, GL_R32I, NULL,
                                 (size_t)tiles * (size_t)capacity * sizeof(int));
        gl_texture_buffer_upload(t->range_buffer, t->range_texture, GL_RGBA32I, NULL, (size_t)tiles * 4 * sizeof(int));
    }
    return gl_check("renderers: tiled");
}

void renderer_tile_bind_view(GLuint p, const frame_view *v)
{
    glUniformMatrix4fv(glGetUniformLocation(p, "u_view_matrix"), 1, GL_FALSE, (const float *)v->view);
    glUniformMatrix4fv(glGetUniformLocation(p, "u_proj"), 1, GL_FALSE, (const float *)v->proj);
    glUniformMatrix4fv(glGetUniformLocation(p, "u_inv_proj"), 1, GL_FALSE, (const float *)v->inv_proj);
}

static bool tiled_spheres(renderer_tiled *t, const gpu_scene *gs)
{
    int n = gs->light_count > 0 ? gs->light_count : 1;
    if (!(t->spheres = realloc(t->spheres, (size_t)n * sizeof *t->spheres)))
        return false;
    for (int i = 0; i < gs->light_count; i++)
        renderer_tile_sphere(&gs->lights[i], &gs->view, t->spheres[i]);
    if (t->compute)
        gl_texture_buffer_upload(t->sphere_buffer, t->sphere_texture, GL_RGBA32F, t->spheres, (size_t)n * sizeof(vec4));
    return true;
}

static bool tiled_cull_compute(renderer_tiled *t, const gpu_scene *gs)
{
    frame_timer_mark("tile culling");
    GLuint p = t->cull_program;
    glUseProgram(p);
    gbuffer_bind_textures(&t->g, gs, p, SHADER_UNIT_GBUFFER);
    renderer_tile_bind_view(p, &gs->view);
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_LIGHTS);
    glBindTexture(GL_TEXTURE_BUFFER, t->sphere_texture);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(glGetUniformLocation(p, "u_light_spheres"), SHADER_UNIT_LIGHTS);
    glUniform1i(glGetUniformLocation(p, "u_light_count"), gs->light_count);
    glUniform1i(glGetUniformLocation(p, "u_tile_capacity"), t->capacity);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, t->list_buffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, t->range_buffer);
    glDispatchCompute((GLuint)t->tiles_x, (GLuint)t->tiles_y, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    return gl_check("renderers: tile culling");
}

static bool tiled_depth_bounds(renderer_tiled *t, const gpu_scene *gs)
{
    frame_timer_mark("tile depth bounds");
    glBindFramebuffer(GL_FRAMEBUFFER, t->bounds.id);
    glViewport(0, 0, t->tiles_x, t->tiles_y);
    gl_pass_state_apply(&(gl_pass_state){0});
    glUseProgram(t->bounds_program);
    gbuffer_bind_textures(&t->g, gs, t->bounds_program, SHADER_UNIT_GBUFFER);
    renderer_tile_bind_view(t->bounds_program, &gs->view);
    gl_draw_fullscreen();
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, t->tiles_x, t->tiles_y, GL_RGBA, GL_FLOAT, t->tile_bounds);
    gl_pass_state_reset();
    return gl_check("renderers: tile depth bounds");
}

static bool tiled_cull_cpu(renderer_tiled *t, const gpu_scene *gs)
{
    frame_timer_mark("light culling");
    const frame_view *v = &gs->view;
    int tiles = t->tiles_x * t->tiles_y, entries = 0;
    for (int k = 0; k < tiles; k++) {
        int x = k % t->tiles_x * TILE_SIZE, y = k / t->tiles_x * TILE_SIZE;
        renderer_tile_frustum_make(v, x, y, TILE_SIZE, &t->tile_bounds[4 * k], &t->frustums[k]);
        int *range = &t->ranges[4 * k];
        range[0] = range[1] = range[3] = 0, range[2] = (int)t->tile_bounds[4 * k + 2];
    }
    for (int sweep = 0; sweep < 2; sweep++) {
        for (int i = 0; i < gs->light_count; i++) {
            const gpu_light *l = &gs->lights[i];
            int px[4] = {0, 0, v->width - 1, v->height - 1};
            if (l->radius < 1e30f)
                light_batches_rect(v, l->position, l->radius, px);
            for (int ty = px[1] / TILE_SIZE; ty <= px[3] / TILE_SIZE; ty++) {
                for (int tx = px[0] / TILE_SIZE; tx <= px[2] / TILE_SIZE; tx++) {
                    int k = ty * t->tiles_x + tx, *range = &t->ranges[4 * k];
                    if (range[2] == 0 || !renderer_tile_sphere_visible(&t->frustums[k], t->spheres[i]))
                        continue;
                    if (sweep == 0)
                        range[1]++;
                    else if (range[1] >= 0)
                        t->list[range[3]++] = i;
                }
            }
        }
        for (int k = 0; sweep == 0 && k < tiles; k++) {
            int *range = &t->ranges[4 * k];
            range[0] = range[3] = entries;
            range[1] = range[1] <= t->capacity ? range[1] : -1;
            entries += range[1] > 0 ? range[1] : 0;
        }
        if (sweep == 0 && !(t->list = realloc(t->list, (size_t)(entries + 1) * sizeof(int))))
            return false;
    }
    gl_texture_buffer_upload(t->range_buffer, t->range_texture, GL_RGBA32I, t->ranges, (size_t)tiles * 4 * sizeof(int));
    gl_texture_buffer_upload(t->list_buffer, t->list_texture, GL_R32I, t->list, (size_t)(entries + 1) * sizeof(int));
    return gl_check("renderers: light culling");
}

static bool tiled_shade(renderer_tiled *t, const gpu_scene *gs, GLuint target)
{
    frame_timer_mark("lighting");
    GLuint p = t->shade_program;
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, gs->view.width, gs->view.height);
    gl_pass_state_apply(&(gl_pass_state){0});
    glUseProgram(p);
    gpu_scene_bind_lights(gs, p, SHADER_UNIT_LIGHTS);
    gbuffer_bind_textures(&t->g, gs, p, SHADER_UNIT_GBUFFER);
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_LIGHT_LIST);
    glBindTexture(GL_TEXTURE_BUFFER, t->list_texture);
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_LIGHT_INDEX);
    glBindTexture(GL_TEXTURE_BUFFER, t->range_texture);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(glGetUniformLocation(p, "u_tile_lights"), SHADER_UNIT_LIGHT_LIST);
    glUniform1i(glGetUniformLocation(p, "u_tile_ranges"), SHADER_UNIT_LIGHT_INDEX);
    glUniform1i(glGetUniformLocation(p, "u_tiles_x"), t->tiles_x);
    glUniform1i(glGetUniformLocation(p, "u_view_mode"), SHADER_VIEW_LIT);
    gl_draw_fullscreen();
    gl_pass_state_reset();
    return gl_check("renderers: tiled shading");
}

/* The light-loop iterations: every covered pixel loops over its tile's whole list. */
static long tiled_evaluations(renderer_tiled *t, const gpu_scene *gs)
{
    int tiles = t->tiles_x * t->tiles_y;
    if (t->compute) {
        glBindBuffer(GL_TEXTURE_BUFFER, t->range_buffer);
        glGetBufferSubData(GL_TEXTURE_BUFFER, 0, (GLsizeiptr)tiles * 4 * (GLsizeiptr)sizeof(int), t->ranges);
        glBindBuffer(GL_TEXTURE_BUFFER, 0);
    }
    long sum = 0;
    for (const int *r = t->ranges; r < t->ranges + 4 * tiles; r += 4)
        sum += (long)r[2] * (r[1] < 0 ? gs->light_count : r[1]);
    return sum;
}

bool draw_tiled(renderer_tiled *t, const gpu_scene *gs, GLuint target, bool count, long *evaluations)
{
    bool ok = gbuffer_render(&t->g, gs) && tiled_spheres(t, gs) &&
              (t->compute ? tiled_cull_compute(t, gs) : tiled_depth_bounds(t, gs) && tiled_cull_cpu(t, gs)) &&
              tiled_shade(t, gs, target);
    *evaluations = ok && count ? tiled_evaluations(t, gs) : -1;
    return ok;
}
