/* 17_ssao.c - screen-space ambient occlusion (Mittring 2007): how much of the sky above each pixel's
 * surface its neighbours hide, guessed from the depth buffer alone, scaling the ambient term. Compare
 * with chapter 11, whose clustered deferred frame this chapter runs unchanged around two new passes:
 * with the occlusion off (--ssao off, key O) the picture is chapter 11's to the byte.
 *
 * Taken over: chapter 11's G-buffer pass, light lists and shading pass (chapter_11_*), built with
 * AMBIENT_OCCLUSION (shade_ambient() in shaders/shading.glsl then reads the occlusion); chapter 15's
 * thin pass (light_prepass_thin.frag: the normal in the compact G-buffer's encoding, and the depth)
 * as forward's depth-normal pre-pass; chapter 00's forward renderer, with the same define.
 * New here, two full-screen passes between the geometry and the lighting:
 *   1. SSAO (ssao.frag): per pixel, --ao-samples directions in the hemisphere around its normal,
 *      cosine-weighted (the kernel, made with the course's rng: chapters/ssao_kernel.c), turned by an
 *      angle from a 4 x 4 noise tile (made there too), each marched in SHADER_AO_STEPS points up to --ao-radius against
 *      the depth buffer; the share of open directions
 *   2. blur (ssao_blur.frag): a 2N x 2N window (--ao-blur N; 2 covers the noise tile), only the
 *      neighbours on the same surface (depth- and normal-aware), so edges do not bleed
 * Forward gets it too: a depth-normal pre-pass feeds the SAME two passes, then chapter 00's forward
 * (or chapter 11's Forward+) shades, reading the same occlusion. Views: lit; ao, the raw occlusion;
 * ao-blurred, what the ambient term reads. --bench: ssao_ms and ssao_blur_ms beside lighting_ms.
 * Read docs/17_ssao.md alongside.
 */
#include "app.h"
#include "chapters.h"
#include "clusters.h"
#include "forward.h"
#include "frame_timer.h"
#include "gbuffer.h"
#include "gl_program.h"
#include "gl_util.h"
#include "log.h"
#include "ssao_kernel.h"

#include <string.h>

static const char *const renderers[] = {"deferred", "forward", NULL};
static const char *const views[] = {"lit", "ao", "ao-blurred", NULL};
static const char *const switches[] = {"on", "off", NULL};

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "17_ssao",
    .summary = "Chapter 17: screen-space ambient occlusion on chapter 11's clustered deferred frame "
               "(and on forward, through a depth-normal pre-pass).",
    .renderers = renderers,
    .views = views,
    .extras =
        {
            {"ao-radius", "UNITS", "how far a surface may be and still hide the sky (scene units)", NULL, "0.5",
             CLI_REAL, 1e-3, 1e3},
            {"ao-samples", "N", "directions per pixel, 1 to 64, each marched in 4 steps", NULL, "16", CLI_WHOLE, 1,
             SHADER_AO_MAX_SAMPLES},
            {"ao-blur", "N", "blur window 2N x 2N pixels on the same surface; 0: none", NULL, "2", CLI_WHOLE, 0, 16},
            {"ssao", "ON", "ambient occlusion on or off (off: chapter 11's picture; key O)", switches, "on"},
        },
};

/* Forward's depth-normal pre-pass: chapter 00's pre-pass state (on a tie the object drawn last wins,
 * as in the G-buffer). */
static const gl_pass_state prepass = {.cull = GL_BACK, .depth_func = GL_LEQUAL, .depth_write = true};
/* SSAO, blur, clustered deferred: every pixel written once; no blending, no depth test. */
static const gl_pass_state fullscreen_pass = {.depth_write = false};

static struct {
    gbuffer g;
    clusters c;
    forward fwd;
    fbo normals;         /* forward only: RGBA8 normal (the compact G-buffer's RT1) + D32F depth */
    fbo ao, ao_blurred;  /* RGBA16F, the occlusion in r */
    GLuint ssao_program, blur_program, prepass_program, noise;
    float kernel[SHADER_AO_MAX_SAMPLES][3];
    int samples, blur;
    float radius;
    bool on;
} state;

/* What the shading programs built with AMBIENT_OCCLUSION read: the occlusion the blur left. */
static void bind_occlusion(GLuint program, const void *user)
{
    (void)user;
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_AO);
    glBindTexture(GL_TEXTURE_2D, state.blur > 0 ? state.ao_blurred.color[0] : state.ao.color[0]);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(glGetUniformLocation(program, "u_ao"), SHADER_UNIT_AO);
    glUniform1i(glGetUniformLocation(program, "u_ao_on"), state.on);
}

static bool init(app *a)
{
    double radius, samples, blur;
    if (!app_extra_number(a, "ao-radius", 1e-3, 1e3, &radius) ||
        !app_extra_number(a, "ao-samples", 1, SHADER_AO_MAX_SAMPLES, &samples) ||
        !app_extra_number(a, "ao-blur", 0, 16, &blur))
        return false;
    state.radius = (float)radius, state.samples = (int)samples, state.blur = (int)blur;
    state.on = strcmp(app_extra(a, "ssao"), "on") == 0;
    rng r = rng_seed(17);
    ssao_kernel_make(&r, state.samples, state.kernel);
    state.noise = ssao_noise_create(&r);
    /* chapter 11's lists where it makes them by default; its programs and forward's read the occlusion */
    const gl_program_extra extra = {.defines = "AMBIENT_OCCLUSION 1", .bind = bind_occlusion};
    const clusters_desc lists = {.compute = gl_have_compute(), .extra = extra};
    a->pass_state = &fullscreen_pass; /* the overlay shows it */
    state.ssao_program = gl_program_load("fullscreen.vert", "ssao.frag", NULL);
    state.blur_program = gl_program_load("fullscreen.vert", "ssao_blur.frag", NULL);
    state.prepass_program = gl_program_load("forward.vert", "light_prepass_thin.frag", NULL);
    return state.noise && state.ssao_program && state.blur_program && state.prepass_program &&
           gbuffer_create(&state.g, a->width, a->height) && clusters_create(&state.c, &lists) &&
           forward_create_with(&state.fwd, &extra);
}

/* The occlusion targets (and forward's pre-pass target) at the picture's size. */
static bool targets_follow(const app *a)
{
    if (state.ao.id && state.ao.width == a->width && state.ao.height == a->height)
        return true;
    fbo_destroy(&state.normals), fbo_destroy(&state.ao), fbo_destroy(&state.ao_blurred);
    const fbo_desc normals = {.color_formats = {GL_RGBA8}, .color_count = 1,
                              .depth_format = GL_DEPTH_COMPONENT32F, .name = "depth-normal pre-pass"};
    const fbo_desc ao = {.color_formats = {GL_RGBA16F}, .color_count = 1, .name = "ambient occlusion"};
    return fbo_create(&state.normals, &normals, a->width, a->height) && fbo_create(&state.ao, &ao, a->width, a->height) &&
           fbo_create(&state.ao_blurred, &ao, a->width, a->height);
}

static bool resize(app *a) { return gbuffer_resize(&state.g, a->width, a->height) && targets_follow(a); }

/* Forward's surface for the two passes, in the uniforms gbuffer_read.glsl reads: the pre-pass's
 * normal (encoded as the compact G-buffer's) and depth. */
static void bind_prepass(GLuint p, const gpu_scene *gs)
{
    const GLuint textures[2] = {state.normals.color[0], state.normals.depth};
    const char *const names[2] = {"u_gbuffer_normal", "u_gbuffer_depth"};
    for (int i = 0; i < 2; i++) {
        glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_GBUFFER + 1 + i);
        glBindTexture(GL_TEXTURE_2D, textures[i]);
        glUniform1i(glGetUniformLocation(p, names[i]), SHADER_UNIT_GBUFFER + 1 + i);
    }
    glActiveTexture(GL_TEXTURE0);
    glUniformMatrix4fv(glGetUniformLocation(p, "u_inv_view_proj"), 1, GL_FALSE, (const float *)gs->view.inv_view_proj);
    glUniform1i(glGetUniformLocation(p, "u_gbuffer_normal_encoding"), SHADER_GBUFFER_NORMAL_PACKED);
    glUniform1i(glGetUniformLocation(p, "u_gbuffer_reversed_z"), 0);
    glUniform2f(glGetUniformLocation(p, "u_viewport_size"), (float)state.normals.width, (float)state.normals.height);
}

/* The surface the passes read: the G-buffer's (deferred), or forward's pre-pass. */
static void bind_surface(GLuint p, const gpu_scene *gs, bool deferred)
{
    glUseProgram(p);
    if (deferred)
        gbuffer_bind_textures(&state.g, gs, p, SHADER_UNIT_GBUFFER);
    else
        bind_prepass(p, gs);
    glUniformMatrix4fv(glGetUniformLocation(p, "u_view_proj"), 1, GL_FALSE, (const float *)gs->view.view_proj);
    glUniform1f(glGetUniformLocation(p, "u_radius"), state.radius);
}

/* 1. SSAO, then 2. the blur, each one full-screen pass into its own target. */
static bool draw_occlusion(const gpu_scene *gs, bool deferred)
{
    frame_timer_mark("ssao");
    gl_pass_state_apply(&fullscreen_pass);
    glBindFramebuffer(GL_FRAMEBUFFER, state.ao.id);
    glViewport(0, 0, state.ao.width, state.ao.height);
    bind_surface(state.ssao_program, gs, deferred);
    glUniform3fv(glGetUniformLocation(state.ssao_program, "u_kernel"), state.samples, &state.kernel[0][0]);
    glUniform1i(glGetUniformLocation(state.ssao_program, "u_samples"), state.samples);
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_IMAGE);
    glBindTexture(GL_TEXTURE_2D, state.noise);
    glUniform1i(glGetUniformLocation(state.ssao_program, "u_noise"), SHADER_UNIT_IMAGE);
    gl_draw_fullscreen();
    if (state.blur > 0) {
        frame_timer_mark("ssao blur");
        glBindFramebuffer(GL_FRAMEBUFFER, state.ao_blurred.id);
        bind_surface(state.blur_program, gs, deferred);
        glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_IMAGE);
        glBindTexture(GL_TEXTURE_2D, state.ao.color[0]);
        glUniform1i(glGetUniformLocation(state.blur_program, "u_ao_raw"), SHADER_UNIT_IMAGE);
        glUniform1i(glGetUniformLocation(state.blur_program, "u_blur"), state.blur);
        gl_draw_fullscreen();
    }
    glActiveTexture(GL_TEXTURE0);
    gl_pass_state_reset();
    return gl_check("17 ssao");
}

/* Forward's depth-normal pre-pass: every opaque object, its normal and depth (chapter 15's thin pass). */
static bool draw_prepass(const gpu_scene *gs)
{
    frame_timer_mark("depth-normal pre-pass");
    glBindFramebuffer(GL_FRAMEBUFFER, state.normals.id);
    glViewport(0, 0, state.normals.width, state.normals.height);
    gl_pass_state_apply(&prepass);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(state.prepass_program);
    gpu_scene_bind_objects(gs, state.prepass_program, SHADER_UNIT_OBJECTS);
    gpu_scene_draw(gs, state.prepass_program);
    gl_pass_state_reset();
    return gl_check("17 depth-normal pre-pass");
}

/* --view ao, ao-blurred: the occlusion itself, grey, into the picture. */
static void show_occlusion(app *a)
{
    const fbo *f = app_view_is(a, "ao") || state.blur == 0 ? &state.ao : &state.ao_blurred;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, f->id);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, a->target.id);
    glBlitFramebuffer(0, 0, f->width, f->height, 0, 0, a->width, a->height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

/* Forward (chapter 00's, pre-pass and lists) or Forward+ (chapter 11's) into target, after the
 * depth-normal pre-pass and the two occlusion passes. */
static bool frame_forward(app *a, GLuint target, bool plus)
{
    if (!targets_follow(a) || (state.on && (!draw_prepass(&a->gs) || !draw_occlusion(&a->gs, false))))
        return false;
    bool ok = plus ? chapter_11_forward_plus.prepass(&state.c, &a->gs, target) &&
                         chapter_11_forward_plus.shade(&state.c, &a->gs, CLUSTERS_VIEW_LIT)
                   : forward_render(&state.fwd, &a->gs, target, (forward_options){.prepass = true, .light_lists = true});
    gl_pass_state_reset();
    return ok;
}

/* Clustered deferred: geometry pass, light assignment, 1. SSAO, 2. blur, one shading pass. */
static bool frame_deferred(app *a)
{
    if (!targets_follow(a) || !gbuffer_render(&state.g, &a->gs) || !chapter_11_assign(&state.c, &a->gs) ||
        (state.on && !draw_occlusion(&a->gs, true)))
        return false;
    glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
    glViewport(0, 0, a->width, a->height);
    clusters_view view = a->linear_output ? CLUSTERS_VIEW_LINEAR : CLUSTERS_VIEW_LIT;
    bool ok = chapter_11_shade_deferred(&state.c, &state.g, &a->gs, &fullscreen_pass, view);
    gl_pass_state_reset();
    a->linear_written = a->linear_output;
    return ok;
}

static bool frame(app *a)
{
    a->shaded_pixels = -1;
    bool ok = app_renderer_is(a, "deferred") ? frame_deferred(a)
                                             : frame_forward(a, a->target.id, app_renderer_is(a, "forward-plus"));
    if (ok && state.on && !app_view_is(a, "lit"))
        show_occlusion(a);
    return ok;
}

/* O: the occlusion on or off; off, the ambient term is chapter 11's. */
static bool key(app *a, int k)
{
    (void)a;
    if (k != 'O')
        return false;
    state.on = !state.on;
    log_info("ambient occlusion: %s", state.on ? "on" : "off");
    return true;
}

/* Compare mode's left side (key M): chapter 00's forward, with its own pre-pass and occlusion. */
static bool draw_forward(app *a, GLuint target) { return frame_forward(a, target, false); }

static void cleanup(app *a)
{
    (void)a;
    forward_destroy(&state.fwd);
    clusters_destroy(&state.c);
    gbuffer_destroy(&state.g);
    fbo_destroy(&state.ao_blurred), fbo_destroy(&state.ao), fbo_destroy(&state.normals);
    glDeleteTextures(1, &state.noise);
    gl_program_destroy(&state.prepass_program);
    gl_program_destroy(&state.blur_program);
    gl_program_destroy(&state.ssao_program);
}

const app_desc chapter_17 = {.cli = &cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup,
                             .key = key, .draw_forward = draw_forward};

CHAPTER_MAIN(chapter_17)
