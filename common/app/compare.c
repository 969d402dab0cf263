/* compare.c - see compare.h. */
#include "compare.h"

#include "gl_program.h"
#include "gl_util.h"

#include <string.h>

static bool make_targets(compare *c, int width, int height)
{
    const fbo_desc forward = {
        .color_formats = {GL_RGBA8}, .color_count = 1, .depth_format = GL_DEPTH_COMPONENT32F, .name = "compare forward"};
    const fbo_desc shown = {.color_formats = {GL_RGBA8}, .color_count = 1, .name = "compare shown"};
    return fbo_create(&c->forward, &forward, width, height) && fbo_create(&c->shown, &shown, width, height);
}

bool compare_create(compare *c, int width, int height)
{
    memset(c, 0, sizeof *c);
    c->program = gl_program_load("fullscreen.vert", "compare.frag", "");
    if (c->program && make_targets(c, width, height))
        return true;
    compare_destroy(c);
    return false;
}

bool compare_resize(compare *c, int width, int height)
{
    fbo_destroy(&c->forward);
    fbo_destroy(&c->shown);
    return make_targets(c, width, height);
}

void compare_destroy(compare *c)
{
    fbo_destroy(&c->forward);
    fbo_destroy(&c->shown);
    gl_program_destroy(&c->program);
}

bool compare_compose(compare *c, const fbo *picture, compare_mode mode, int divider)
{
    glBindFramebuffer(GL_FRAMEBUFFER, c->shown.id);
    glViewport(0, 0, c->shown.width, c->shown.height);
    glUseProgram(c->program);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, c->forward.color[0]);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, picture->color[0]);
    glUniform1i(glGetUniformLocation(c->program, "u_forward"), 0);
    glUniform1i(glGetUniformLocation(c->program, "u_picture"), 1);
    glUniform1i(glGetUniformLocation(c->program, "u_difference"), mode == COMPARE_DIFFERENCE);
    glUniform1i(glGetUniformLocation(c->program, "u_divider"), divider);
    glUniform1i(glGetUniformLocation(c->program, "u_divider_width"), COMPARE_DIVIDER_WIDTH);
    glUniform1i(glGetUniformLocation(c->program, "u_tolerance"), COMPARE_TOLERANCE_LEVELS);
    gl_draw_fullscreen();
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return gl_check("compare_compose");
}

const char *compare_mode_name(compare_mode mode)
{
    static const char *const names[COMPARE_MODE_COUNT] = {"off", "split", "difference"};
    return mode >= 0 && mode < COMPARE_MODE_COUNT ? names[mode] : "?";
}
