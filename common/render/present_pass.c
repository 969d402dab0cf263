/* present_pass.c - see present_pass.h. */
#include "present_pass.h"

#include "gl_program.h"
#include "gl_util.h"
#include "shader_layout.h"

#include <string.h>

bool present_pass_create(present_pass *p)
{
    memset(p, 0, sizeof *p);
    p->program = gl_program_load("fullscreen.vert", "accum_present.frag", NULL);
    if (!p->program)
        return false;
    p->u_accum = glGetUniformLocation(p->program, "u_accum");
    p->u_tonemap = glGetUniformLocation(p->program, "u_tonemap");
    p->u_exposure = glGetUniformLocation(p->program, "u_exposure");
    p->u_view = glGetUniformLocation(p->program, "u_view");
    return true;
}

void present_pass_destroy(present_pass *p)
{
    gl_program_destroy(&p->program);
}

void present_pass_draw(const present_pass *p, GLuint texture, GLuint target, int width, int height,
                       const present_pass_options *options)
{
    const present_pass_options none = {0};
    const present_pass_options *o = options ? options : &none;
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, width, height);
    glUseProgram(p->program);
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_IMAGE);
    glBindTexture(GL_TEXTURE_2D, texture);
    glUniform1i(p->u_accum, SHADER_UNIT_IMAGE);
    glUniform1i(p->u_tonemap, o->tonemap);
    glUniform1f(p->u_exposure, o->exposure > 0.0f ? o->exposure : 1.0f);
    glUniform1i(p->u_view, o->view);
    gl_draw_fullscreen();
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindVertexArray(0);
}
