/* 02_mrt_gbuffer.c - the geometry pass: one draw per object writes a G-buffer, several render
 * targets at once (multiple render targets, `layout(location = N) out` in shaders/gbuffer.frag).
 *
 * What goes in is only what the shading model reads later (common/render/gbuffer.h has the layout):
 * albedo in sRGB8, an octahedral normal in two half floats beside specular and shininess, and
 * depth, from which the lighting pass rebuilds the position. Each target can be looked at
 * (--view or key V): the pictures every deferred tutorial shows. `final` lights the G-buffer
 * with chapter 03's pass, so you can check nothing was lost. Compare with chapter 01 (one
 * colour target) and read docs/02_mrt_gbuffer.md alongside.
 */
#include "app.h"
#include "chapters.h"
#include "deferred_fullscreen.h"
#include "gbuffer.h"
#include "gl_program.h"
#include "gl_util.h"
#include "log.h"

static const char *const renderers[] = {"deferred", "forward", NULL};
/* Order matches VIEW_* in shaders/gbuffer_view.frag; `final` is last. */
static const char *const views[] = {"albedo", "normal", "depth", "specular", "final", NULL};

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "02_mrt_gbuffer",
    .summary = "Chapter 02: a geometry pass writes the G-buffer through multiple render targets.",
    .renderers = renderers,
    .views = views,
};

static struct {
    gbuffer gbuf;
    GLuint view_program;
    GLint loc_view, loc_near_far;
    deferred_fullscreen lighting;
} state;

static void report_size(int width, int height)
{
    /* The naive layout stores world position (RGBA16F, or RGBA32F to stay exact far from the
     * origin), a 3-channel normal in RGBA16F and albedo in RGBA8, plus the same depth. */
    const int naive32 = GBUFFER_NAIVE_BYTES + 8;
    double mib = 1.0 / (1024.0 * 1024.0), pixels = (double)width * height;
    log_info("G-buffer: %d bytes/pixel (%.1f MiB at %dx%d); naive layout %d bytes/pixel with a 16F position "
             "(%.1f MiB), %d with a 32F position (%.1f MiB)",
             gbuffer_bytes_per_pixel(), gbuffer_bytes_per_pixel() * pixels * mib, width, height,
             GBUFFER_NAIVE_BYTES, GBUFFER_NAIVE_BYTES * pixels * mib, naive32, naive32 * pixels * mib);
}

static bool init(app *a)
{
    if (!gbuffer_create(&state.gbuf, a->width, a->height) || !deferred_fullscreen_create(&state.lighting, NULL))
        return false;
    state.view_program = gl_program_load("fullscreen.vert", "gbuffer_view.frag", NULL);
    if (!state.view_program)
        return false;
    state.loc_view = glGetUniformLocation(state.view_program, "u_view");
    state.loc_near_far = glGetUniformLocation(state.view_program, "u_near_far");
    report_size(a->width, a->height);
    return true;
}

static bool resize(app *a)
{
    report_size(a->width, a->height);
    return gbuffer_resize(&state.gbuf, a->width, a->height);
}

/* Draws one target of the G-buffer as a picture, with a full-screen triangle. */
static bool draw_view(const app *a)
{
    frame_timer_mark("view");
    glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
    glViewport(0, 0, a->width, a->height);
    glDisable(GL_DEPTH_TEST);
    gbuffer_bind_textures(&state.gbuf, &a->gs, state.view_program, SHADER_UNIT_GBUFFER);
    glUniform1i(state.loc_view, SHADER_GBUFFER_VIEW_ALBEDO + a->view); /* views[] is in SHADER_GBUFFER_VIEW_* order */
    glUniform2f(state.loc_near_far, a->gs.view.near_plane, a->gs.view.far_plane);
    gl_draw_fullscreen();
    return gl_check("draw_view");
}

static bool frame(app *a)
{
    if (app_renderer_is_forward(a))
        return app_render_forward(a);

    /* 1. geometry pass: each object once; gbuffer.frag writes location 0 (albedo) and
     *    location 1 (normal, specular, shininess) in the same fragment invocation */
    if (!gbuffer_render(&state.gbuf, &a->gs))
        return false;

    /* 2. look at one target, or light them all (chapter 03's pass) */
    if (!app_view_is(a, "final"))
        return draw_view(a);
    return deferred_fullscreen_render(&state.lighting, &state.gbuf, &a->gs, a->target.id,
                                      (deferred_fullscreen_options){0});
}

static void cleanup(app *a)
{
    (void)a;
    gl_program_destroy(&state.view_program);
    deferred_fullscreen_destroy(&state.lighting);
    gbuffer_destroy(&state.gbuf);
}

const app_desc chapter_02 = {.cli = &cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup};

CHAPTER_MAIN(chapter_02)
