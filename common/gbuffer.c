/* gbuffer.c - see gbuffer.h. */
#include "gbuffer.h"

#include "frame_timer.h"
#include "gl_util.h"
#include "log.h"

#include <string.h>

static bool make_targets(gbuffer *g, int width, int height)
{
    const GLenum depth_format = g->desc.stencil ? GL_DEPTH32F_STENCIL8 : GL_DEPTH_COMPONENT32F;
    const fbo_desc desc = {
        .color_formats = {GL_SRGB8_ALPHA8, GL_RGBA16F},
        .color_count = 2,
        .depth_format = depth_format,
        .name = "gbuffer",
    };
    /* The copy has the same format: a depth blit needs it. */
    const fbo_desc copy = {.depth_format = depth_format, .name = "gbuffer depth copy"};
    return fbo_create(&g->fbo, &desc, width, height) &&
           (!g->desc.stencil || fbo_create(&g->depth_copy, &copy, width, height));
}

bool gbuffer_create(gbuffer *g, int width, int height) { return gbuffer_create_with(g, width, height, NULL); }

bool gbuffer_create_with(gbuffer *g, int width, int height, const gbuffer_desc *desc)
{
    memset(g, 0, sizeof *g);
    if (desc)
        g->desc = *desc;
    /* forward.vert: the same vertex path as the forward renderer, so both rasterise identically. */
    g->program = gl_program_load("forward.vert", "gbuffer.frag", NULL);
    if (!g->program || !make_targets(g, width, height)) {
        gbuffer_destroy(g);
        return false;
    }
    return gl_check("gbuffer_create");
}

bool gbuffer_resize(gbuffer *g, int width, int height)
{
    fbo_destroy(&g->fbo);
    fbo_destroy(&g->depth_copy);
    return make_targets(g, width, height);
}

void gbuffer_attach_stencil(const gbuffer *g, GLuint framebuffer)
{
    if (!g->desc.stencil) {
        log_error("gbuffer_attach_stencil: this G-buffer has no stencil (gbuffer_desc.stencil)");
        return;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_TEXTURE_2D, g->fbo.depth, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void gbuffer_destroy(gbuffer *g)
{
    fbo_destroy(&g->fbo);
    fbo_destroy(&g->depth_copy);
    gl_program_destroy(&g->program);
    memset(g, 0, sizeof *g);
}

bool gbuffer_render(gbuffer *g, const gpu_scene *gs)
{
    if (g->fbo.width != gs->view.width || g->fbo.height != gs->view.height) {
        log_error("gbuffer is %dx%d but the view is %dx%d (call gbuffer_resize)", g->fbo.width, g->fbo.height,
                  gs->view.width, gs->view.height);
        return false;
    }
    frame_timer_mark("geometry");
    glBindFramebuffer(GL_FRAMEBUFFER, g->fbo.id);
    glViewport(0, 0, g->fbo.width, g->fbo.height);
    /* Zero normal/material and depth 1 mark the background; the lighting pass tests depth. */
    /* Same state as forward_render (GL_LEQUAL: on an exact depth tie the object drawn last wins):
     * an object hides another exactly where it does there. */
    gl_pass_state_apply(&(gl_pass_state){.cull = GL_BACK, .depth_func = GL_LEQUAL, .depth_write = true});
    glClearColor(0, 0, 0, 0);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | (g->desc.stencil ? GL_STENCIL_BUFFER_BIT : 0));
    /* Without this an SRGB8 attachment stores the linear value unconverted (and reads decode it). */
    glEnable(GL_FRAMEBUFFER_SRGB);

    glUseProgram(g->program);
    gpu_scene_bind_objects(gs, g->program, SHADER_UNIT_OBJECTS);
    gpu_scene_draw(gs, g->program);

    glDisable(GL_FRAMEBUFFER_SRGB);
    gl_pass_state_reset();
    if (g->desc.stencil) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, g->fbo.id);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, g->depth_copy.id);
        glBlitFramebuffer(0, 0, g->fbo.width, g->fbo.height, 0, 0, g->fbo.width, g->fbo.height,
                          GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return true;
}

void gbuffer_bind_textures(const gbuffer *g, const gpu_scene *gs, GLuint program, int first_unit)
{
    static const char *const names[3] = {"u_gbuffer_albedo", "u_gbuffer_normal", "u_gbuffer_depth"};
    const GLuint textures[3] = {g->fbo.color[0], g->fbo.color[1],
                                g->desc.stencil ? g->depth_copy.depth : g->fbo.depth};
    glUseProgram(program);
    for (int i = 0; i < 3; i++) {
        glActiveTexture(GL_TEXTURE0 + (GLenum)(first_unit + i));
        glBindTexture(GL_TEXTURE_2D, textures[i]);
        glUniform1i(glGetUniformLocation(program, names[i]), first_unit + i);
    }
    glActiveTexture(GL_TEXTURE0);
    glUniformMatrix4fv(glGetUniformLocation(program, "u_inv_view_proj"), 1, GL_FALSE,
                       (const float *)gs->view.inv_view_proj);
    glUniform3fv(glGetUniformLocation(program, "u_eye"), 1, gs->view.eye);
    glUniform2f(glGetUniformLocation(program, "u_viewport_size"), (float)g->fbo.width, (float)g->fbo.height);
}

int gbuffer_bytes_per_pixel(void)
{
    return 4 /* SRGB8_ALPHA8 */ + 8 /* RGBA16F */ + 4 /* DEPTH_COMPONENT32F */;
}
