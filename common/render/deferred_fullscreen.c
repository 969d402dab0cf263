/* deferred_fullscreen.c - see deferred_fullscreen.h. */
#include "deferred_fullscreen.h"

#include "frame_timer.h"
#include "gl_program.h"
#include "gl_util.h"

#include <string.h>

bool deferred_fullscreen_create(deferred_fullscreen *d, const char *defines)
{
    memset(d, 0, sizeof *d);
    d->shaded_pixels = -1;
    d->program = gl_program_load("fullscreen.vert", "deferred_fullscreen.frag", defines);
    if (!d->program)
        return false;
    d->query = gl_query_create();
    return gl_check("deferred_fullscreen_create");
}

void deferred_fullscreen_destroy(deferred_fullscreen *d)
{
    gl_program_destroy(&d->program);
    gl_query_destroy(&d->query);
    memset(d, 0, sizeof *d);
}

bool deferred_fullscreen_render(deferred_fullscreen *d, const gbuffer *g, const gpu_scene *gs, GLuint target,
                                deferred_fullscreen_options options)
{
    frame_timer_mark("lighting");
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, g->fbo.width, g->fbo.height);
    /* Background pixels are discarded by the shader: they keep this black, as forward's clear. */
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glUseProgram(d->program);
    gpu_scene_bind_lights(gs, d->program, SHADER_UNIT_LIGHTS);
    gbuffer_bind_textures(g, gs, d->program, SHADER_UNIT_GBUFFER);
    gl_samples_begin(d->query, options.count_pixels);
    gl_draw_fullscreen();
    d->shaded_pixels = gl_samples_end(d->query, options.count_pixels);
    return gl_check("deferred_fullscreen_render");
}

long deferred_fullscreen_shaded_pixels(const deferred_fullscreen *d) { return d->shaded_pixels; }
