/* 02_mrt_gbuffer.c - the geometry pass: one draw per object writes a G-buffer, several render
 * targets at once (multiple render targets, `layout(location = N) out` in shaders/gbuffer.frag).
 *
 * What goes in is only what the shading model reads later (common/render/gbuffer.h has the layout):
 * albedo in sRGB8, an octahedral normal in 2 x 12 bits beside specular and shininess, and
 * depth, from which the lighting pass rebuilds the position. Each target can be looked at
 * (--view or key V): the pictures every deferred tutorial shows. `final` lights the G-buffer
 * with chapter 03's pass, so you can check nothing was lost. Compare with chapter 01 (one
 * colour target) and read docs/02_mrt_gbuffer.md alongside.
 *
 * New here, in mrt_create: two colour textures and a depth texture in one framebuffer, and
 * glDrawBuffers sending fragment output N to colour attachment N. From chapter 03 on the same
 * targets come from gbuffer_create (common/render/gbuffer.c, through common/gl/fbo.c).
 */
#include "app.h"
#include "chapters.h"
#include "deferred_fullscreen.h"
#include "gbuffer.h"
#include "gl_program.h"
#include "gl_util.h"
#include "log.h"

#include <string.h>

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

/* One G-buffer texture: storage only, NEAREST (read texel for pixel, and without mipmaps). Any
 * client format and type will do without data, as long as a depth format gets a depth one. */
static GLuint target_texture(GLenum internal, GLenum format, GLenum type, int width, int height)
{
    GLuint t = gl_texture_create();
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)internal, width, height, 0, format, type, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    return t;
}

/* The G-buffer's framebuffer: the layout's formats (--gbuffer; common/render/gbuffer.c lists them). */
static bool mrt_create(int width, int height)
{
    const gbuffer_layout *l = state.gbuf.desc.layout;
    const GLenum depth = gbuffer_layout_depth_format(l, false);
    const bool stencil = depth == GL_DEPTH24_STENCIL8;
    fbo *f = &state.gbuf.fbo;
    fbo_destroy(f);
    const bool emissive = state.gbuf.desc.emissive; /* a scene with emissive materials (chapter 18) */
    *f = (fbo){.color_count = emissive ? 3 : 2, .owns_depth = true, .width = width, .height = height, .samples = 1};

    /* 1. RT0 albedo (GL_SRGB8_ALPHA8: 8 bits on the sRGB curve), RT1 the octahedral normal,
     *    specular and shininess (GL_RGBA8; half floats in the reference layout) */
    f->color[0] = target_texture(l->albedo_format, GL_RGBA, GL_FLOAT, width, height);
    f->color[1] = target_texture(l->normal_format, GL_RGBA, GL_FLOAT, width, height);
    /*    and RT2, the emissive, only where the scene has some (GBUFFER_EMISSIVE_FORMAT: half floats) */
    if (emissive)
        f->color[2] = target_texture(GBUFFER_EMISSIVE_FORMAT, GL_RGBA, GL_FLOAT, width, height);
    /* 2. depth as a texture, not chapter 01's renderbuffer: the lighting pass reads it back */
    f->depth = stencil ? target_texture(depth, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, width, height)
                       : target_texture(depth, GL_DEPTH_COMPONENT, GL_FLOAT, width, height);

    /* 3. one framebuffer holds all three; glDrawBuffers routes `layout(location = N) out` to
     *    colour attachment N (without it only attachment 0 would be written) */
    f->id = gl_framebuffer_create();
    glBindFramebuffer(GL_FRAMEBUFFER, f->id);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, f->color[0], 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, f->color[1], 0);
    if (emissive)
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, f->color[2], 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, stencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                           GL_TEXTURE_2D, f->depth, 0);
    static const GLenum outputs[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    glDrawBuffers(f->color_count, outputs);
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        log_error("G-buffer framebuffer %dx%d: %s", width, height, fbo_status_name(status));
    return status == GL_FRAMEBUFFER_COMPLETE && gl_check("mrt_create");
}

static bool init(app *a)
{
    if (!gbuffer_create_pass(&state.gbuf, NULL) || !mrt_create(a->width, a->height) ||
        !deferred_fullscreen_create(&state.lighting, NULL))
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
    return mrt_create(a->width, a->height);
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
    memset(&state, 0, sizeof state); /* opened again (the benchmark does), init starts from nothing */
}

const app_desc chapter_02 = {.cli = &cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup};

CHAPTER_MAIN(chapter_02)
