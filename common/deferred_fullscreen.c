/* deferred_fullscreen.c - see deferred_fullscreen.h. */
#include "deferred_fullscreen.h"

#include "gl_util.h"

#include <string.h>

bool deferred_fullscreen_create(deferred_fullscreen *d)
{
    memset(d, 0, sizeof *d);
    d->shaded_pixels = -1;
    d->program = gl_program_load("fullscreen.vert", "deferred_fullscreen.frag", NULL);
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

bool deferred_fullscreen_render(deferred_fullscreen *d, const gbuffer *g, const gpu_scene *gs,
                                deferred_fullscreen_options options)
{
    glViewport(0, 0, g->fbo.width, g->fbo.height);
    /* Background pixels are discarded by the shader: they keep this black, as forward's clear. */
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);

    glUseProgram(d->program);
    gpu_scene_bind_lights(gs, d->program, 0);
    gbuffer_bind_textures(g, gs, d->program, 1);
    if (options.count_pixels)
        glBeginQuery(GL_SAMPLES_PASSED, d->query);
    gl_draw_fullscreen();
    if (options.count_pixels) {
        glEndQuery(GL_SAMPLES_PASSED);
        GLuint samples = 0;
        glGetQueryObjectuiv(d->query, GL_QUERY_RESULT, &samples);
        d->shaded_pixels = (long)samples;
    }
    return gl_check("deferred_fullscreen_render");
}

long deferred_fullscreen_shaded_pixels(const deferred_fullscreen *d) { return d->shaded_pixels; }
