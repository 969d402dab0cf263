/* light_volumes.c - see light_volumes.h. */
#include "light_volumes.h"

#include "gl_util.h"
#include "log.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

/* 80 triangles: measured fastest on llvmpipe (vertex work is not free; 320 was slower). */
#define VOLUME_SUBDIVISIONS 1

/* Texture units of the lighting pass. */
enum { UNIT_LIGHTS = 0, UNIT_GBUFFER = 1, UNIT_INDEX = 4 };

bool light_volumes_create(light_volumes *lv, const gbuffer *g)
{
    memset(lv, 0, sizeof *lv);
    lv->shaded_pixels = -1;
    mesh_data sphere;
    if (!mesh_data_icosphere(&sphere, VOLUME_SUBDIVISIONS))
        return false;
    /* The icosphere's vertices lie on the unit sphere and its faces inside it: scaled by
     * 1 / inradius every face plane is outside the sphere (tests/unit/test_volume_mesh.c). */
    lv->mesh_scale = (float)(1.0 / mesh_data_inradius(&sphere));
    bool ok = mesh_create(&sphere, &lv->sphere);
    mesh_data_destroy(&sphere);
    static const char *const defines[2] = {NULL, "OVERWRITE 1"};
    for (int k = 0; k < 2; k++) {
        light_volumes_program *v = &lv->volume[k];
        v->id = gl_program_load("light_volume.vert", "light_volume.frag", defines[k]);
        ok = ok && v->id;
        if (!v->id)
            continue;
        v->view_proj = glGetUniformLocation(v->id, "u_view_proj");
        v->mesh_scale = glGetUniformLocation(v->id, "u_mesh_scale");
        v->fixed_radius = glGetUniformLocation(v->id, "u_fixed_radius");
        v->fullscreen = glGetUniformLocation(v->id, "u_fullscreen");
        v->first_instance = glGetUniformLocation(v->id, "u_first_instance");
        v->light_index = glGetUniformLocation(v->id, "u_light_index");
        v->view = glGetUniformLocation(v->id, "u_view");
    }
    lv->ambient_program = gl_program_load("fullscreen.vert", "volume_ambient.frag", NULL);
    lv->present_program = gl_program_load("fullscreen.vert", "accum_present.frag", NULL);
    if (!ok || !lv->ambient_program || !lv->present_program) {
        light_volumes_destroy(lv);
        return false;
    }
    lv->present_accum = glGetUniformLocation(lv->present_program, "u_accum");
    lv->present_tonemap = glGetUniformLocation(lv->present_program, "u_tonemap");
    lv->present_exposure = glGetUniformLocation(lv->present_program, "u_exposure");
    lv->index_buffer = gl_buffer_create();
    lv->index_texture = gl_texture_create();
    lv->query = gl_query_create();
    if (!light_volumes_resize(lv, g)) {
        light_volumes_destroy(lv);
        return false;
    }
    return gl_check("light_volumes_create");
}

void light_volumes_destroy(light_volumes *lv)
{
    gl_program_destroy(&lv->volume[0].id);
    gl_program_destroy(&lv->volume[1].id);
    gl_program_destroy(&lv->ambient_program);
    gl_program_destroy(&lv->present_program);
    mesh_destroy(&lv->sphere);
    fbo_destroy(&lv->accum);
    gl_buffer_destroy(&lv->index_buffer);
    gl_texture_destroy(&lv->index_texture);
    gl_query_destroy(&lv->query);
    free(lv->indices);
    memset(lv, 0, sizeof *lv);
}

/* The accumulation buffer borrows the G-buffer's depth texture, so the volumes can be depth-tested
 * against the scene without a copy (depth writes stay off while the shader also reads it). */
static bool make_accum(light_volumes *lv, const gbuffer *g, GLenum format)
{
    fbo_destroy(&lv->accum);
    const fbo_desc desc = {.color_formats = {format},
                           .color_count = 1,
                           .depth_format = GL_DEPTH_COMPONENT32F,
                           .shared_depth = g->fbo.depth,
                           .name = "light accumulation"};
    lv->accum_format = format;
    return fbo_create(&lv->accum, &desc, g->fbo.width, g->fbo.height);
}

bool light_volumes_resize(light_volumes *lv, const gbuffer *g)
{
    return make_accum(lv, g, lv->accum_format ? lv->accum_format : GL_RGBA16F);
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

/* Instance i draws light indices[first + i]: finite volumes first, then the full-screen ones. */
static bool upload_indices(light_volumes *lv, const gpu_scene *gs, light_volumes_options o, int *volumes)
{
    if (gs->light_count > lv->index_cap) {
        int *grown = realloc(lv->indices, (size_t)gs->light_count * sizeof *grown);
        if (!grown) {
            log_error("out of memory for %d light indices", gs->light_count);
            return false;
        }
        lv->indices = grown;
        lv->index_cap = gs->light_count;
    }
    int front = 0, back = gs->light_count;
    for (int i = 0; i < gs->light_count; i++) {
        const gpu_light *l = &gs->lights[i];
        float r = o.fixed_radius > 0.0f ? o.fixed_radius : l->radius;
        if (contains_frustum(&gs->view, l->position, r))
            lv->indices[--back] = i;
        else
            lv->indices[front++] = i;
    }
    *volumes = front;
    static const int zero = 0;
    glBindBuffer(GL_TEXTURE_BUFFER, lv->index_buffer);
    glBufferData(GL_TEXTURE_BUFFER,
                 gs->light_count ? (GLsizeiptr)gs->light_count * (GLsizeiptr)sizeof(int)
                                 : (GLsizeiptr)sizeof zero,
                 gs->light_count ? (const void *)lv->indices : &zero, GL_STREAM_DRAW);
    glBindTexture(GL_TEXTURE_BUFFER, lv->index_texture);
    glTexBuffer(GL_TEXTURE_BUFFER, GL_R32I, lv->index_buffer);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    return true;
}

static void set_cull_and_depth(light_volumes_options o)
{
    if (o.cull == LIGHT_VOLUMES_CULL_NONE) {
        glDisable(GL_CULL_FACE);
    } else {
        glEnable(GL_CULL_FACE);
        glCullFace(o.cull == LIGHT_VOLUMES_CULL_FRONT ? GL_FRONT : GL_BACK);
    }
    if (o.depth == LIGHT_VOLUMES_DEPTH_OFF) {
        glDisable(GL_DEPTH_TEST);
    } else {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(o.depth == LIGHT_VOLUMES_DEPTH_GREATER ? GL_GREATER : GL_LEQUAL);
    }
    /* Back faces beyond the far plane would be clipped away, and their light with them. */
    if (o.no_depth_clamp)
        glDisable(GL_DEPTH_CLAMP);
    else
        glEnable(GL_DEPTH_CLAMP);
}

static void draw_lights(light_volumes *lv, const gbuffer *g, const gpu_scene *gs, light_volumes_options o,
                        int volumes)
{
    const light_volumes_program *v = &lv->volume[o.overwrite ? 1 : 0];
    glUseProgram(v->id);
    gpu_scene_bind_lights(gs, v->id, UNIT_LIGHTS);
    gbuffer_bind_textures(g, gs, v->id, UNIT_GBUFFER);
    glActiveTexture(GL_TEXTURE0 + UNIT_INDEX);
    glBindTexture(GL_TEXTURE_BUFFER, lv->index_texture);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(v->light_index, UNIT_INDEX);
    glUniformMatrix4fv(v->view_proj, 1, GL_FALSE, (const float *)gs->view.view_proj);
    glUniform1f(v->mesh_scale, o.unscaled_mesh ? 1.0f : lv->mesh_scale);
    glUniform1f(v->fixed_radius, o.fixed_radius);
    glUniform1i(v->view, (int)o.view);
    if (o.overwrite) {
        glDisable(GL_BLEND);
    } else {
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE);
    }
    glDepthMask(GL_FALSE);
    if (o.count_pixels)
        glBeginQuery(GL_SAMPLES_PASSED, lv->query);
    if (volumes > 0) {
        set_cull_and_depth(o);
        glUniform1i(v->fullscreen, 0);
        glUniform1i(v->first_instance, 0);
        mesh_draw_instanced(&lv->sphere, volumes);
    }
    int fullscreen = gs->light_count - volumes;
    if (fullscreen > 0) {
        /* Every pixel may be lit: no culling, no depth test. */
        glDisable(GL_CULL_FACE);
        glDisable(GL_DEPTH_TEST);
        glUniform1i(v->fullscreen, 1);
        glUniform1i(v->first_instance, volumes);
        glBindVertexArray(lv->sphere.vao);
        glDrawArraysInstanced(GL_TRIANGLES, 0, 3, fullscreen);
    }
    if (o.count_pixels) {
        glEndQuery(GL_SAMPLES_PASSED);
        GLuint samples = 0;
        glGetQueryObjectuiv(lv->query, GL_QUERY_RESULT, &samples);
        lv->shaded_pixels = (long)samples;
    }
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_DEPTH_CLAMP);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
}

bool light_volumes_render(light_volumes *lv, const gbuffer *g, const gpu_scene *gs, light_volumes_options o)
{
    GLint target = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
    GLenum format = o.accum_format ? o.accum_format : GL_RGBA16F;
    if ((lv->accum.depth != g->fbo.depth || lv->accum.width != g->fbo.width ||
         lv->accum.height != g->fbo.height || lv->accum_format != format) &&
        !make_accum(lv, g, format))
        return false;
    int volumes = 0;
    if (!upload_indices(lv, gs, o, &volumes))
        return false;
    if (!o.count_pixels)
        lv->shaded_pixels = -1;

    glBindFramebuffer(GL_FRAMEBUFFER, lv->accum.id);
    glViewport(0, 0, lv->accum.width, lv->accum.height);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);

    /* 1. ambient, once per covered pixel; background stays black (the overdraw view counts only) */
    if (o.view != LIGHT_VOLUMES_VIEW_OVERDRAW) {
        glUseProgram(lv->ambient_program);
        gpu_scene_bind_lights(gs, lv->ambient_program, UNIT_LIGHTS);
        gbuffer_bind_textures(g, gs, lv->ambient_program, UNIT_GBUFFER);
        gl_draw_fullscreen();
    }

    /* 2. every light's volume, one instanced draw (plus the full-screen lights) */
    if (gs->light_count > 0)
        draw_lights(lv, g, gs, o, volumes);

    /* 3. present: tone map + display encoding into the caller's framebuffer */
    glBindFramebuffer(GL_FRAMEBUFFER, (GLuint)target);
    glViewport(0, 0, lv->accum.width, lv->accum.height);
    glUseProgram(lv->present_program);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, lv->accum.color[0]);
    glUniform1i(lv->present_accum, 0);
    glUniform1i(lv->present_tonemap, (int)o.tonemap);
    glUniform1f(lv->present_exposure, o.exposure > 0.0f ? o.exposure : 1.0f);
    gl_draw_fullscreen();
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindVertexArray(0);
    return gl_check("light_volumes_render");
}

long light_volumes_shaded_pixels(const light_volumes *lv)
{
    return lv->shaded_pixels;
}

static int choice(const char *value, const char *const *names)
{
    for (int i = 0; names[i]; i++)
        if (strcmp(value, names[i]) == 0)
            return i;
    return -1;
}

static bool parse_positive(const char *name, const char *value, float *out)
{
    char *end = NULL;
    double v = strtod(value, &end);
    if (end == value || *end || !(v > 0.0 && v < 1e30)) {
        log_error("bad --%s '%s': expected a number > 0", name, value);
        return false;
    }
    *out = (float)v;
    return true;
}

bool light_volumes_options_set(light_volumes_options *o, const char *name, const char *value)
{
    static const char *const accum[] = {"rgba16f", "rgba8", "rgba32f", NULL};
    static const char *const tonemap[] = {"none", "exposure", "reinhard", NULL};
    static const char *const cull[] = {"front", "back", "none", NULL};
    static const char *const on_off[] = {"on", "off", NULL};
    static const char *const scale[] = {"inradius", "none", NULL};
    int k = -1;
    if (!value) {
        log_error("option --%s has no value", name);
        return false;
    } else if (strcmp(name, "accum") == 0 && (k = choice(value, accum)) >= 0) {
        o->accum_format = k == 0 ? GL_RGBA16F : k == 1 ? GL_RGBA8 : GL_RGBA32F;
    } else if (strcmp(name, "tonemap") == 0 && (k = choice(value, tonemap)) >= 0) {
        o->tonemap = (light_volumes_tonemap)k;
    } else if (strcmp(name, "cull") == 0 && (k = choice(value, cull)) >= 0) {
        /* Each culling mode with the depth test that suits it (none: no single test does). */
        o->cull = (light_volumes_cull)k;
        o->depth = k == 0   ? LIGHT_VOLUMES_DEPTH_GREATER
                   : k == 1 ? LIGHT_VOLUMES_DEPTH_LEQUAL
                            : LIGHT_VOLUMES_DEPTH_OFF;
    } else if (strcmp(name, "depth-clamp") == 0 && (k = choice(value, on_off)) >= 0) {
        o->no_depth_clamp = k == 1;
    } else if (strcmp(name, "scale") == 0 && (k = choice(value, scale)) >= 0) {
        o->unscaled_mesh = k == 1;
    } else if (strcmp(name, "exposure") == 0) {
        return parse_positive(name, value, &o->exposure);
    } else if (strcmp(name, "radius") == 0) {
        return parse_positive(name, value, &o->fixed_radius);
    } else {
        log_error("bad --%s '%s'", name, value);
        return false;
    }
    return true;
}
