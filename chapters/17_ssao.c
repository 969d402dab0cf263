/* 17_ssao.c - screen-space ambient occlusion (Mittring 2007): how much of the sky above each pixel's
 * surface its neighbours hide, guessed from the depth buffer alone, scaling the ambient term. Compare
 * with chapter 11, whose clustered deferred frame this chapter runs unchanged around two new passes:
 * with the occlusion off (--ssao off, key O) the picture is chapter 11's to the byte (with its
 * --gbuffer reversed-z: this chapter's G-buffer is the compact layout with a reversed depth unless
 * asked otherwise, gbuffer_layout_for_chapter; from standard depth, positions rebuilt far away are
 * 1e-4 off and a few pixels fall across a light's hard cut-off from forward's: docs/17_ssao.md).
 *
 * Taken over: chapter 11's G-buffer pass, light lists and shading pass (chapter_11_*), built with
 * AMBIENT_OCCLUSION (shade_ambient() in shaders/shading.glsl then reads the occlusion); chapter 00's
 * forward renderer, with the same define.
 * New here, two full-screen passes between the geometry and the lighting (written in
 * common/render/ssao.c since chapter 19 reuses them; ssao_draw is where to read them):
 *   1. SSAO (ssao.frag): per pixel, --ao-samples directions in the hemisphere around its normal,
 *      cosine-weighted (the kernel, made with the course's rng), turned by an angle from a 4 x 4
 *      noise tile (made there too), each marched in SHADER_AO_STEPS points up to --ao-radius against
 *      the depth buffer; the share of open directions
 *   2. blur (ssao_blur.frag): a 2N x 2N window (--ao-blur N; 2 covers the noise tile), only the
 *      neighbours on the same surface (depth- and normal-aware), so edges do not bleed
 * Forward gets it too: a depth-normal pre-pass (the geometry pass's shader, its normal target only,
 * in the G-buffer layout's encoding) feeds the SAME two passes, then chapter 00's forward (or
 * chapter 11's Forward+) shades, reading the same occlusion. Views: lit; ao, the raw occlusion;
 * ao-blurred, what the ambient term reads. --bench: ssao_ms and ssao_blur_ms beside lighting_ms.
 * --shadows N (chapter 14's atlas, chapters.h; off by default): the same programs built with SHADOWS
 * too (gl_program_extra_join), so the lights' direct terms are shadowed while the occlusion scales
 * the ambient; key K turns the shadows off and on.
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
#include "ssao.h"

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
            CHAPTER_14_SHADOW_OPTIONS("K"),
        },
};

/* SSAO, blur, clustered deferred: every pixel written once; no blending, no depth test. */
static const gl_pass_state fullscreen_pass = {.depth_write = false};

static struct {
    gbuffer g;
    clusters c;
    forward fwd;
    ssao ao; /* the two passes, their targets and forward's pre-pass (common/render/ssao.c) */
    shadow_atlas atlas;           /* --shadows N: chapter 14's; nothing made without it */
    gl_program_extra_pair extras; /* the occlusion's inputs and the atlas's, for every shading program */
    gl_program_extra occlusion, shadows, both; /* AMBIENT_OCCLUSION, SHADOWS (--shadows N), the two */
} state;

/* This frame's shading programs: built with the occlusion while it is on and with chapter 14's
 * shadows while a light is shadowed, so what is off costs nothing (each variant built once). */
static void use_programs(void)
{
    const gl_program_extra *with = state.ao.on ? &state.both : &state.shadows;
    const gl_program_extra *extra =
        shadow_atlas_programs(&state.atlas, with, state.ao.on ? &state.occlusion : NULL);
    clusters_set_extra(&state.c, extra);
    forward_set_extra(&state.fwd, extra);
}

static bool init(app *a)
{
    double radius, samples, blur;
    if (!app_extra_number(a, "ao-radius", 1e-3, 1e3, &radius) ||
        !app_extra_number(a, "ao-samples", 1, SHADER_AO_MAX_SAMPLES, &samples) ||
        !app_extra_number(a, "ao-blur", 0, 16, &blur))
        return false;
    const ssao_desc desc = {.radius = (float)radius, .samples = (int)samples, .blur = (int)blur};
    /* chapter 11's lists where it makes them by default; its programs and forward's read the occlusion,
     * and with --shadows N chapter 14's atlas */
    state.occlusion = (gl_program_extra){.defines = "AMBIENT_OCCLUSION 1", .bind = ssao_bind, .user = &state.ao};
    if (!chapter_14_shadows_create(a, &state.atlas, &state.shadows))
        return false;
    const gl_program_extra extra = state.both = gl_program_extra_join(&state.extras, &state.occlusion, &state.shadows);
    const clusters_desc lists = {.compute = gl_have_compute(), .extra = extra};
    a->pass_state = &fullscreen_pass; /* the overlay shows it */
    bool ok = ssao_create(&state.ao, &desc) && gbuffer_create(&state.g, a->width, a->height) &&
              clusters_create(&state.c, &lists) && forward_create_with(&state.fwd, &extra);
    state.ao.on = strcmp(app_extra(a, "ssao"), "on") == 0;
    return ok;
}

static bool resize(app *a)
{
    return gbuffer_resize(&state.g, a->width, a->height) && ssao_resize(&state.ao, a->width, a->height);
}

/* Forward (chapter 00's, pre-pass and lists) or Forward+ (chapter 11's) into target, after the
 * depth-normal pre-pass and the two occlusion passes. */
static bool frame_forward(app *a, GLuint target, bool plus)
{
    if (!ssao_resize(&state.ao, a->width, a->height) ||
        (state.ao.on && (!ssao_draw_prepass(&state.ao, &a->gs) || !ssao_draw(&state.ao, NULL, &a->gs))))
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
    if (!ssao_resize(&state.ao, a->width, a->height) || !gbuffer_render(&state.g, &a->gs) ||
        !chapter_11_assign(&state.c, &a->gs) || (state.ao.on && !ssao_draw(&state.ao, &state.g, &a->gs)))
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
    if (!chapter_14_shadows_update(&state.atlas, &a->gs)) /* --shadows N: before anything shades */
        return false;
    use_programs();
    bool ok = app_renderer_is(a, "deferred") ? frame_deferred(a)
                                             : frame_forward(a, a->target.id, app_renderer_is(a, "forward-plus"));
    if (ok && state.ao.on && !app_view_is(a, "lit"))
        ssao_show(&state.ao, app_view_is(a, "ao"), a->target.id, a->width, a->height);
    return ok;
}

/* O: the occlusion on or off; off, the ambient term is chapter 11's. T / Y, J / L, B / N: its radius,
 * directions and blur (ssao_key). K: shadows on / off (with
 * --shadows N). */
static bool key(app *a, int k)
{
    (void)a;
    if (k == 'K')
        return chapter_14_shadows_key(&state.atlas);
    if (ssao_key(&state.ao, k)) /* radius, directions, blur */
        return true;
    if (k != 'O')
        return false;
    state.ao.on = !state.ao.on;
    log_info("ambient occlusion: %s", state.ao.on ? "on" : "off");
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
    ssao_destroy(&state.ao);
    shadow_atlas_destroy(&state.atlas);
    memset(&state, 0, sizeof state); /* opened again (the benchmark does), init starts from nothing */
}

const app_desc chapter_17 = {.cli = &cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup,
                             .key = key, .draw_forward = draw_forward, .takes_reversed_z = true,
                             .prefers_reversed_z = true};

CHAPTER_MAIN(chapter_17)
