/* deferred_volumes.c - see deferred_volumes.h. */
#include "deferred_volumes.h"

#include "frame_timer.h"
#include "log.h"

#include <string.h>

/* The accumulation buffer borrows the G-buffer's depth texture, so the volumes can be depth-tested
 * against the scene without a copy (depth writes stay off while the shader also reads it). */
static bool follow_gbuffer(deferred_volumes *dv, const gbuffer *g, GLenum format)
{
    if (dv->accum.id && dv->accum.depth == g->fbo.depth && dv->accum.width == g->fbo.width &&
        dv->accum.height == g->fbo.height && dv->accum_format == format)
        return true;
    fbo_destroy(&dv->accum);
    const fbo_desc desc = {.color_formats = {format},
                           .color_count = 1,
                           .depth_format = GL_DEPTH_COMPONENT32F,
                           .shared_depth = g->fbo.depth,
                           .name = "light accumulation"};
    dv->accum_format = format;
    return fbo_create(&dv->accum, &desc, g->fbo.width, g->fbo.height);
}

bool deferred_volumes_create(deferred_volumes *dv, const gbuffer *g, GLenum accum_format)
{
    memset(dv, 0, sizeof *dv);
    dv->shaded_pixels = -1;
    if (!light_volumes_create(&dv->lv, NULL)) {
        deferred_volumes_destroy(dv);
        return false;
    }
    dv->present_program = gl_program_load("fullscreen.vert", "accum_present.frag", NULL);
    if (!dv->present_program) {
        deferred_volumes_destroy(dv);
        return false;
    }
    if (!follow_gbuffer(dv, g, accum_format)) {
        deferred_volumes_destroy(dv);
        return false;
    }
    dv->u_accum = glGetUniformLocation(dv->present_program, "u_accum");
    dv->u_tonemap = glGetUniformLocation(dv->present_program, "u_tonemap");
    dv->u_exposure = glGetUniformLocation(dv->present_program, "u_exposure");
    dv->u_view = glGetUniformLocation(dv->present_program, "u_view");
    dv->query = gl_query_create();
    return gl_check("deferred_volumes_create");
}

void deferred_volumes_destroy(deferred_volumes *dv)
{
    light_volumes_destroy(&dv->lv);
    fbo_destroy(&dv->accum);
    gl_program_destroy(&dv->present_program);
    gl_query_destroy(&dv->query);
    memset(dv, 0, sizeof *dv);
}

bool deferred_volumes_resize(deferred_volumes *dv, const gbuffer *g)
{
    return follow_gbuffer(dv, g, dv->accum_format);
}

void deferred_volumes_present(const deferred_volumes *dv, GLuint target, const deferred_volumes_frame *f)
{
    frame_timer_mark("present");
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, dv->accum.width, dv->accum.height);
    glUseProgram(dv->present_program);
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_IMAGE);
    glBindTexture(GL_TEXTURE_2D, dv->accum.color[0]);
    glUniform1i(dv->u_accum, SHADER_UNIT_IMAGE);
    glUniform1i(dv->u_tonemap, (int)f->tonemap);
    glUniform1f(dv->u_exposure, f->exposure > 0.0f ? f->exposure : 1.0f);
    glUniform1i(dv->u_view, (int)f->view);
    gl_draw_fullscreen();
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindVertexArray(0);
}

bool deferred_volumes_render(deferred_volumes *dv, const gbuffer *g, const gpu_scene *gs, GLuint target,
                             const deferred_volumes_frame *f)
{
    if (!follow_gbuffer(dv, g, f->accum_format ? f->accum_format : dv->accum_format) ||
        !light_volumes_sort(&dv->lv, gs))
        return false;
    frame_timer_mark("lighting");
    glBindFramebuffer(GL_FRAMEBUFFER, dv->accum.id);
    glViewport(0, 0, dv->accum.width, dv->accum.height);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);

    /* 1. ambient, once per covered pixel (the overdraw view counts lighting fragments only) */
    if (f->view != LIGHT_VOLUMES_VIEW_OVERDRAW)
        light_volumes_draw_ambient(&dv->lv, g, gs);

    /* 2. every light's volume, added on top */
    light_volumes_bind(&dv->lv, g, gs, f->view);
    gl_samples_begin(dv->query, f->count_pixels);
    light_volumes_draw(&dv->lv, gs, f->volume_state);
    dv->shaded_pixels = gl_samples_end(dv->query, f->count_pixels);

    /* 3. present: tone map + display encoding of the sum (overdraw view: the count as a heat map) */
    deferred_volumes_present(dv, target, f);
    return gl_check("deferred_volumes_render");
}

long deferred_volumes_shaded_pixels(const deferred_volumes *dv) { return dv->shaded_pixels; }
