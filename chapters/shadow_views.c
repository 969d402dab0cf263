/* shadow_views.c - chapter 14's views of its atlas (shadow_views.h; shaders/shadow_debug.*). */
#include "shadow_views.h"

#include "log.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DISC_RADIUS_PIXELS 6.0f

bool shadow_views_create(shadow_views *v)
{
    memset(v, 0, sizeof *v);
    v->program = gl_program_load("shadow_debug.vert", "shadow_debug.frag", NULL);
    v->vertex_array = gl_vertex_array_create();
    v->item_buffer = gl_buffer_create(), v->item_texture = gl_texture_create();
    return v->program && gl_check("shadow views");
}

void shadow_views_destroy(shadow_views *v)
{
    gl_program_destroy(&v->program);
    gl_vertex_array_destroy(&v->vertex_array);
    gl_buffer_destroy(&v->item_buffer), gl_texture_destroy(&v->item_texture);
    free(v->items);
    memset(v, 0, sizeof *v);
}

/* Room for n items of two RGBA32F texels; false (logged) when out of memory. */
static bool reserve_items(shadow_views *v, int n)
{
    int texels = 2 * (n > 0 ? n : 1);
    if (texels <= v->item_cap)
        return true;
    float *g = realloc(v->items, 4 * sizeof(float) * (size_t)texels);
    if (!g) {
        log_error("shadow views: out of memory for %d items", n);
        return false;
    }
    v->items = g, v->item_cap = texels;
    return true;
}

/* n items, as two texels each, drawn as n instanced quads in `mode` (shadow_debug.vert). */
static bool draw_items(shadow_views *v, int n, int mode, const float rect[5], const float radius[2])
{
    gl_texture_buffer_upload(v->item_buffer, v->item_texture, GL_RGBA32F, v->items,
                             4 * sizeof(float) * 2 * (size_t)(n > 0 ? n : 1));
    gl_pass_state_apply(&(gl_pass_state){0}); /* drawn over the picture: no depth test, no blending */
    glUseProgram(v->program);
    gl_texture_buffer_bind(v->program, "u_items", 0, v->item_texture);
    glUniform1i(glGetUniformLocation(v->program, "u_atlas_depth"), 1);
    glUniform1i(glGetUniformLocation(v->program, "u_mode"), mode);
    glUniform4fv(glGetUniformLocation(v->program, "u_rect"), 1, rect);
    glUniform1f(glGetUniformLocation(v->program, "u_atlas_size"), rect[4]);
    glUniform2fv(glGetUniformLocation(v->program, "u_radius"), 1, radius);
    glBindVertexArray(v->vertex_array);
    if (n > 0)
        glDrawArraysInstanced(GL_TRIANGLES, 0, 6, n);
    glBindVertexArray(0);
    gl_pass_state_reset();
    return gl_check("shadow views");
}

bool shadow_views_draw_atlas(shadow_views *v, const shadow_atlas *s, int width, int height)
{
    const shadow_plan *p = &s->plan;
    int n = s->enabled ? p->tile_count : 0; /* off: the plan is last frame's, and nothing reads it */
    if (!reserve_items(v, n))
        return false;
    for (int t = 0; t < n; t++) {
        const shadow_tile *tile = &p->tiles[t];
        float *it = &v->items[8 * t];
        it[0] = (float)tile->x, it[1] = (float)tile->y, it[2] = (float)tile->size, it[3] = (float)p->tier[tile->light];
        it[4] = shadow_far_plane(s->lights[tile->light].radius), it[5] = 1.0f, it[6] = it[7] = 0.0f;
    }
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    /* the atlas's square, as large as the picture's shorter side, in its middle */
    float side = (float)(width < height ? width : height);
    const float rect[5] = {-side / (float)width, -side / (float)height, 2.0f * side / (float)width,
                           2.0f * side / (float)height, (float)p->desc.atlas_size};
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, s->target.depth);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE); /* its depths, not comparisons */
    bool ok = draw_items(v, n, 0, rect, (const float[2]){0, 0});
    glActiveTexture(GL_TEXTURE1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    return ok;
}

bool shadow_views_draw_lights(shadow_views *v, const shadow_atlas *s, const gpu_scene *gs, int width, int height)
{
    const shadow_plan *p = &s->plan;
    if (!reserve_items(v, gs->light_count))
        return false;
    int n = 0;
    for (int i = 0; i < gs->light_count; i++) {
        vec4 c;
        glm_mat4_mulv((vec4 *)gs->view.view_proj, (vec4){gs->lights[i].position[0], gs->lights[i].position[1],
                                                          gs->lights[i].position[2], 1.0f}, c);
        if (c[3] <= gs->view.near_plane) /* behind the eye */
            continue;
        bool planned = s->enabled && i < p->light_cap; /* the plan ran this frame for every light */
        float *it = &v->items[8 * n++];
        it[0] = c[0] / c[3], it[1] = c[1] / c[3], it[2] = 0.0f, it[3] = planned ? (float)p->tier[i] : 0.0f;
        it[4] = 0.0f, it[5] = planned && p->status[i] == SHADOW_SHADOWED ? 1.0f : 0.0f, it[6] = it[7] = 0.0f;
    }
    const float radius[2] = {2.0f * DISC_RADIUS_PIXELS / (float)width, 2.0f * DISC_RADIUS_PIXELS / (float)height};
    return draw_items(v, n, 1, (const float[5]){0, 0, 0, 0, 1}, radius);
}

void shadow_views_overlay(const shadow_atlas *s, char *out, size_t size)
{
    const shadow_frame_stats *st = &s->plan.stats;
    if (!s->enabled) {
        snprintf(out, size, "shadows off (K): every light unshadowed, no tile drawn");
        return;
    }
    snprintf(out, size,
             "shadows on (K): %d lights shadowed, %d dropped, %d off, %d not chosen\n"
             "shadow tiles %d, drawn %d (%ld triangles; %ld without culling)",
             st->shadowed, st->dropped, st->off, st->not_chosen, st->tiles, st->tiles_drawn, st->triangles,
             st->triangles_unculled);
}
