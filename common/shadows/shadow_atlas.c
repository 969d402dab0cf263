/* shadow_atlas.c - chapter 14's depth atlas (shadow_atlas.h): the plan's tiles drawn, the tables the
 * shaders read (shaders/shadows.glsl) uploaded.
 */
#include "shadow_atlas.h"

#include "frame_timer.h"
#include "log.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Casters are drawn from both sides (a plane casts too); the depth test keeps the nearest. */
static const gl_pass_state shadow_pass = {.depth_func = GL_LESS, .depth_write = true};

/* *a grown to hold n elements of `size` bytes; false (logged) when out of memory. */
static bool reserve(void **a, int *cap, int n, size_t size)
{
    if (n <= *cap)
        return true;
    int c = n < 16 ? 16 : n;
    void *g = realloc(*a, (size_t)c * size);
    if (!g) {
        log_error("shadow atlas: out of memory for %d entries", c);
        return false;
    }
    *a = g, *cap = c;
    return true;
}

bool shadow_atlas_create(shadow_atlas *s, const shadow_plan_desc *desc, GLenum format, float slope_bias)
{
    memset(s, 0, sizeof *s);
    s->format = format, s->slope_bias = slope_bias, s->enabled = true, s->programs_said = -1;
    snprintf(s->defines, sizeof s->defines, "SHADOWS 1\nSHADOW_PCF %d", desc->pcf);
    const fbo_desc atlas = {.depth_format = format, .name = "shadow atlas"};
    if (!shadow_plan_create(&s->plan, desc) || !fbo_create(&s->target, &atlas, desc->atlas_size, desc->atlas_size))
        return false;
    glBindTexture(GL_TEXTURE_2D, s->target.depth);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR); /* 2 x 2 comparisons, weighted */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glBindTexture(GL_TEXTURE_2D, 0);
    s->depth_program = gl_program_load("forward.vert", "depth_only.frag", NULL);
    s->light_buffer = gl_buffer_create(), s->light_texture = gl_texture_create();
    s->tile_buffer = gl_buffer_create(), s->tile_texture = gl_texture_create();
    return s->depth_program && gl_check("shadow atlas");
}

void shadow_atlas_destroy(shadow_atlas *s)
{
    gl_program_destroy(&s->depth_program);
    gl_buffer_destroy(&s->light_buffer), gl_texture_destroy(&s->light_texture);
    gl_buffer_destroy(&s->tile_buffer), gl_texture_destroy(&s->tile_texture);
    fbo_destroy(&s->target);
    shadow_plan_destroy(&s->plan);
    free(s->light_texels), free(s->tile_texels), free(s->lights), free(s->casters);
    memset(s, 0, sizeof *s);
}

double shadow_atlas_bytes(const shadow_atlas *s)
{
    double side = s->plan.desc.atlas_size;
    return side * side * (s->format == GL_DEPTH_COMPONENT16 ? 2.0 : 4.0);
}

/* What the plan needs of gs: each light (with its scene switch) and each object's world box. */
static bool gather(shadow_atlas *s, const gpu_scene *gs)
{
    const scene *src = gs->src;
    if (!reserve((void **)&s->lights, &s->light_cap, gs->light_count, sizeof *s->lights) ||
        !reserve((void **)&s->casters, &s->caster_cap, src->object_count, sizeof *s->casters))
        return false;
    for (int i = 0; i < gs->light_count; i++) {
        const gpu_light *g = &gs->lights[i];
        shadow_light *l = &s->lights[i];
        *l = (shadow_light){.radius = g->radius, .source = g->source, .shadow_off = src->lights[g->source].shadow_off};
        glm_vec3_copy((float *)g->position, l->position);
        glm_vec3_copy((float *)g->direction, l->direction);
        l->outer_deg = gpu_light_is_spot(g) ? glm_deg(acosf(g->cos_outer)) : 0.0f;
    }
    for (int o = 0; o < src->object_count; o++) {
        const mesh *m = &gs->meshes[src->objects[o].mesh];
        shadow_caster *c = &s->casters[o];
        *c = (shadow_caster){.triangles = m->index_count / 3, .cast_off = src->objects[o].cast_off};
        glm_vec3_fill(c->lo, FLT_MAX), glm_vec3_fill(c->hi, -FLT_MAX);
        for (int k = 0; k < 8; k++) { /* the mesh's box corners into the world */
            vec4 corner = {k & 1 ? m->bounds_max[0] : m->bounds_min[0], k & 2 ? m->bounds_max[1] : m->bounds_min[1],
                           k & 4 ? m->bounds_max[2] : m->bounds_min[2], 1.0f}, w;
            glm_mat4_mulv(gs->world[o], corner, w);
            glm_vec3_minv(c->lo, w, c->lo), glm_vec3_maxv(c->hi, w, c->hi);
        }
    }
    return true;
}

/* The tiles the plan marked: each cleared inside its square, then its casters, depth only. */
static void draw_tiles(shadow_atlas *s, const gpu_scene *gs)
{
    const shadow_plan *p = &s->plan;
    glBindFramebuffer(GL_FRAMEBUFFER, s->target.id);
    gl_pass_state_apply(&shadow_pass);
    glEnable(GL_SCISSOR_TEST);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(s->slope_bias, 0.0f); /* slope-scaled only: the normal offset does the rest */
    glUseProgram(s->depth_program);
    gpu_scene_bind_objects(gs, s->depth_program, SHADER_UNIT_OBJECTS);
    const GLint first = glGetUniformLocation(s->depth_program, "u_first_object");
    const GLint view_proj = glGetUniformLocation(s->depth_program, "u_view_proj");
    glClearDepth(1.0);
    for (int t = 0; t < p->tile_count; t++) {
        const shadow_tile *tile = &p->tiles[t];
        if (!tile->redraw)
            continue;
        glViewport(tile->x, tile->y, tile->size, tile->size);
        glScissor(tile->x, tile->y, tile->size, tile->size);
        glClear(GL_DEPTH_BUFFER_BIT);
        glUniformMatrix4fv(view_proj, 1, GL_FALSE, (const float *)tile->view_proj);
        for (int k = 0; k < tile->caster_count; k++) {
            int o = tile->casters[k];
            glUniform1i(first, o);
            mesh_draw_instanced(&gs->meshes[gs->src->objects[o].mesh], 1);
        }
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_SCISSOR_TEST);
    gl_pass_state_reset();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

/* The two tables (shader_layout.h): per light its first tile, faces and normal offset (the PCF is a
 * define, SHADOW_PCF); per tile its matrix and its square. */
static bool upload_tables(shadow_atlas *s, int lights)
{
    const shadow_plan *p = &s->plan;
    const int tile_texels = (p->tile_count > 0 ? p->tile_count : 1) * SHADER_SHADOW_TILE_TEXELS;
    if (!reserve((void **)&s->light_texels, &s->light_texel_cap, 4 * (lights > 0 ? lights : 1), sizeof(float)) ||
        !reserve((void **)&s->tile_texels, &s->tile_texel_cap, 4 * tile_texels, sizeof(float)))
        return false;
    s->light_texels[0] = -1.0f; /* a table never empty */
    for (int i = 0; i < lights; i++) {
        float *t = &s->light_texels[4 * i];
        bool shadowed = s->enabled && p->status[i] == SHADOW_SHADOWED; /* disabled: no plan read */
        t[0] = shadowed ? (float)p->first_tile[i] : -1.0f;
        t[1] = shadowed ? (float)p->faces[i] : 0.0f, t[2] = p->desc.normal_offset, t[3] = 0.0f;
    }
    memset(s->tile_texels, 0, 4 * sizeof(float) * (size_t)tile_texels);
    for (int k = 0; k < p->tile_count; k++) {
        const shadow_tile *tile = &p->tiles[k];
        float *t = &s->tile_texels[4 * SHADER_SHADOW_TILE_TEXELS * k];
        memcpy(t, tile->view_proj, 16 * sizeof(float)); /* columns, as GLSL's mat4(c0, c1, c2, c3) */
        t[16] = (float)tile->x, t[17] = (float)tile->y, t[18] = (float)tile->size, t[19] = tile->tan_half;
    }
    gl_texture_buffer_upload(s->light_buffer, s->light_texture, GL_RGBA32F, s->light_texels,
                             4 * sizeof(float) * (size_t)(lights > 0 ? lights : 1));
    gl_texture_buffer_upload(s->tile_buffer, s->tile_texture, GL_RGBA32F, s->tile_texels,
                             4 * sizeof(float) * (size_t)tile_texels);
    return gl_check("shadow tables");
}

bool shadow_atlas_update(shadow_atlas *s, const gpu_scene *gs)
{
    frame_timer_mark("shadows"); /* the shadow pass: the plan, the tiles drawn, the tables */
    if (!gather(s, gs))
        return false;
    if (s->enabled) {
        if (!shadow_plan_frame(&s->plan, gs->view.eye, s->lights, gs->light_count, s->casters, gs->src->object_count))
            return false;
        draw_tiles(s, gs);
        s->frames++, s->tiles_drawn_total += s->plan.stats.tiles_drawn;
    }
    return upload_tables(s, gs->light_count) && gl_check("shadow maps");
}

void shadow_atlas_bind(GLuint program, const void *user)
{
    const shadow_atlas *s = user;
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_SHADOW_ATLAS);
    glBindTexture(GL_TEXTURE_2D, s->target.depth);
    glUniform1i(glGetUniformLocation(program, "u_shadow_atlas"), SHADER_UNIT_SHADOW_ATLAS);
    gl_texture_buffer_bind(program, "u_shadow_lights", SHADER_UNIT_SHADOW_LIGHTS, s->light_texture);
    gl_texture_buffer_bind(program, "u_shadow_tiles", SHADER_UNIT_SHADOW_TILES, s->tile_texture);
    glActiveTexture(GL_TEXTURE0);
}

gl_program_extra shadow_atlas_extra(const shadow_atlas *s)
{
    return (gl_program_extra){.defines = s->defines, .bind = shadow_atlas_bind, .user = s};
}

const gl_program_extra *shadow_atlas_programs(shadow_atlas *s, const gl_program_extra *with,
                                              const gl_program_extra *without)
{
    if (!s->depth_program)
        return without; /* no atlas (--shadows 0 in chapters 15 to 19): nothing to switch, nothing said */
    const bool shadowed = s->enabled && s->plan.stats.shadowed > 0;
    if (s->programs_said != (int)shadowed) /* said once per change */
        log_info("shadows: %s", shadowed ? "the lighting programs built with SHADOWS"
                                         : "no light shadowed: the lighting programs built without SHADOWS");
    s->programs_said = shadowed;
    return shadowed ? with : without;
}
