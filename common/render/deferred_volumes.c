/* deferred_volumes.c - see deferred_volumes.h. */
#include "deferred_volumes.h"

#include "frame_timer.h"
#include "log.h"

#include <string.h>

/* The accumulation buffer borrows the G-buffer's depth texture, so the volumes can be depth-tested
 * against the scene without a copy (depth writes stay off while the shader also reads it). */
static bool follow_gbuffer(deferred_volumes *dv, const gbuffer *g, GLenum format)
{
    if (dv->accum_format != format)
        fbo_destroy(&dv->accum);
    dv->accum_format = format;
    return gbuffer_follow_target(g, &dv->accum, format, "light accumulation");
}

bool deferred_volumes_create(deferred_volumes *dv, const gbuffer *g, GLenum accum_format)
{
    memset(dv, 0, sizeof *dv);
    dv->shaded_pixels = -1;
    if (!light_volumes_create(&dv->lv, NULL)) {
        deferred_volumes_destroy(dv);
        return false;
    }
    if (!present_pass_create(&dv->present)) {
        deferred_volumes_destroy(dv);
        return false;
    }
    if (!follow_gbuffer(dv, g, accum_format)) {
        deferred_volumes_destroy(dv);
        return false;
    }
    dv->query = gl_query_create();
    return gl_check("deferred_volumes_create");
}

void deferred_volumes_destroy(deferred_volumes *dv)
{
    light_volumes_destroy(&dv->lv);
    fbo_destroy(&dv->accum);
    present_pass_destroy(&dv->present);
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
    const present_pass_options o = {.tonemap = (int)f->tonemap, .exposure = f->exposure, .view = (int)f->view};
    present_pass_draw(&dv->present, dv->accum.color[0], target, dv->accum.width, dv->accum.height, &o);
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
