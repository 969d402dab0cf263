/* 01_fbo_setup.c - render into a framebuffer object you made yourself, then show it.
 *
 * Deferred shading draws its first pass into textures, not to the screen; this chapter is that
 * first step on its own. The FBO here has a colour texture (it will be read back later, so a
 * texture) and a depth renderbuffer (only the depth test reads it, so no texture needed). The
 * scene is chapter 00's forward renderer drawn into it; a full-screen triangle then copies the
 * colour texture into the window. The picture must be chapter 00's, pixel for pixel (key R
 * switches to drawing it directly). common/gl/fbo.c generalises this for later chapters: several
 * colour textures and a depth TEXTURE, because from chapter 02 on a later pass reads the depth.
 * Read docs/01_fbo_setup.md alongside.
 */
#include "app.h"
#include "chapters.h"
#include "gl_program.h"
#include "gl_util.h"
#include "log.h"

#include <string.h>

static const char *const renderers[] = {"offscreen", "forward", NULL};

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "01_fbo_setup",
    .summary = "Chapter 01: render into an offscreen framebuffer, then present it.",
    .renderers = renderers,
};

static struct {
    GLuint fbo, color, depth; /* framebuffer, its colour texture, its depth renderbuffer */
    int width, height;
    GLuint present_program;
} state;

static void offscreen_destroy(void)
{
    gl_framebuffer_destroy(&state.fbo);
    gl_texture_destroy(&state.color);
    gl_renderbuffer_destroy(&state.depth);
}

static bool offscreen_create(int width, int height)
{
    offscreen_destroy();
    state.width = width, state.height = height;

    /* 1. the colour texture: storage only (data NULL); NEAREST because it is read texel for pixel,
     *    and a texture without mipmaps must not use a mipmap filter or it is "incomplete" */
    state.color = gl_texture_create();
    glBindTexture(GL_TEXTURE_2D, state.color);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);

    /* 2. the depth buffer: a renderbuffer, because nothing samples it afterwards */
    state.depth = gl_renderbuffer_create();
    glBindRenderbuffer(GL_RENDERBUFFER, state.depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);

    /* 3. the framebuffer ties them together; drawing goes to colour attachment 0 */
    state.fbo = gl_framebuffer_create();
    glBindFramebuffer(GL_FRAMEBUFFER, state.fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, state.color, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, state.depth);
    glDrawBuffer(GL_COLOR_ATTACHMENT0);

    /* 4. ask the driver whether it can render into this combination, and say what it answered */
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        log_error("offscreen framebuffer %dx%d: %s", width, height, fbo_status_name(status));
        return false;
    }
    log_info("offscreen framebuffer %dx%d (RGBA8 texture + DEPTH_COMPONENT32F renderbuffer): %s", width,
             height, fbo_status_name(status));
    return gl_check("offscreen_create");
}

static bool init(app *a)
{
    state.present_program = gl_program_load("fullscreen.vert", "present.frag", NULL);
    return state.present_program && offscreen_create(a->width, a->height);
}

/* The window changed size: the old textures are the wrong size, make new ones. */
static bool resize(app *a) { return offscreen_create(a->width, a->height); }

static bool frame(app *a)
{
    if (app_renderer_is_forward(a))
        return app_render_forward(a);

    /* 1. draw the scene (chapter 00's forward renderer) into our framebuffer instead of the target */
    if (!app_forward_draw(&a->forward, "forward", &a->gs, state.fbo, (app_forward_options){0}, NULL))
        return false;

    /* 2. present: bind the colour texture and cover the target with one triangle */
    frame_timer_mark("present");
    glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
    glViewport(0, 0, a->width, a->height);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(state.present_program);
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_IMAGE);
    glBindTexture(GL_TEXTURE_2D, state.color);
    glUniform1i(glGetUniformLocation(state.present_program, "u_image"), SHADER_UNIT_IMAGE);
    gl_draw_fullscreen();
    glBindTexture(GL_TEXTURE_2D, 0);
    return gl_check("present");
}

static void cleanup(app *a)
{
    (void)a;
    offscreen_destroy();
    gl_program_destroy(&state.present_program);
    memset(&state, 0, sizeof state); /* opened again (the benchmark does), init starts from nothing */
}

const app_desc chapter_01 = {.cli = &cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup};

CHAPTER_MAIN(chapter_01)
