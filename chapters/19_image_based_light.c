/* 19_image_based_light.c - image-based ambient light from probes: each probe photographs the scene
 * around it into a cube map at start, and the surfaces near it take their ambient light from that
 * picture (diffuse from its irradiance, specular from its prefiltered mip chain) instead of one
 * constant colour. Compare with chapter 11, whose clustered deferred frame this chapter runs
 * unchanged: with the probes off (--ibl off, key I) the picture is chapter 11's to the byte (with its
 * --gbuffer reversed-z, this chapter's default on scenes without metallic-roughness: chapter 17's).
 *
 * Taken over: chapter 11's G-buffer pass, light lists and shading pass (chapter_11_*), built with
 * IMAGE_BASED_LIGHT (shade_ambient_at() in shaders/shading.glsl then reads the probes,
 * shaders/ibl.glsl); chapter 00's forward renderer, with the same define, and once more without it
 * as the probes' camera.
 * New here (chapters/ibl_probes.c, chapters/ibl_sh.c):
 *   at start, the split-sum table (ibl_brdf.frag, once); at the first frame and on key U, per
 *      probe: six forward renders into an RGBA16F cube, its irradiance as 9 spherical-harmonics
 *      coefficients projected on the CPU, its prefiltered mip chain by GGX importance sampling
 *      (ibl_prefilter.frag)
 *   per frame: the IBL_MAX_PICKED most important probes (radius over distance to the eye), blended
 *      per pixel in the shading pass, weight (1 - (d / R)^2)^2; outside every radius, the constant
 * Views: lit; probe, which probe lights each pixel; irradiance; specular (ibl_view.frag, from the
 * G-buffer); ao and ao-blurred, chapter 17's occlusion raw and as read. With --ssao on (key O)
 * chapter 17's occlusion (common/render/ssao.c: its two passes on the G-buffer, or on forward's
 * depth-normal pre-pass; --ao-radius, --ao-samples, --ao-blur as there) scales the whole ambient
 * term, the probes' diffuse and specular light as the constant's; the lights' direct terms never
 * (the page says why).
 * --shadows N (chapter 14's atlas, chapters.h; off by default): the shading programs built with
 * SHADOWS too (gl_program_extra_join), so the lights' direct terms are shadowed; the probes still
 * photograph the unshadowed scene. Key K turns the shadows off and on.
 * Read docs/19_image_based_light.md alongside.
 */
#include "app.h"
#include "chapters.h"
#include "clusters.h"
#include "forward.h"
#include "frame_timer.h"
#include "gbuffer.h"
#include "gl_program.h"
#include "gl_util.h"
#include "ibl_probes.h"
#include "log.h"
#include "ssao.h"

#include <stdio.h>
#include <string.h>

static const char *const renderers[] = {"deferred", "forward", NULL};
static const char *const views[] = {"lit", "probe", "irradiance", "specular", "ao", "ao-blurred", NULL};
static const char *const switches[] = {"on", "off", NULL};

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "19_image_based_light",
    .summary = "Chapter 19: image-based ambient light from probes on chapter 11's clustered deferred frame "
               "(and on forward).",
    .renderers = renderers,
    .views = views,
    .extras =
        {
            {"probe-size", "N", "each probe's cube face in texels, a power of two from 16 to 512", NULL, "128",
             CLI_POWER_OF_TWO, 16, 512},
            {"ibl-samples", "N", "GGX samples per prefiltered texel, 1 to 1024", NULL, "256", CLI_WHOLE, 1, 1024},
            {"ibl", "ON", "probes on or off (off: chapter 11's picture; key I)", switches, "on"},
            {"ssao", "ON", "chapter 17's ambient occlusion on the probes' light, on or off (key O)", switches, "off"},
            {"ao-radius", "UNITS", "how far a surface may be and still hide the sky (scene units)", NULL, "0.5",
             CLI_REAL, 1e-3, 1e3},
            {"ao-samples", "N", "occlusion directions per pixel, 1 to 64, each marched in 4 steps", NULL, "16",
             CLI_WHOLE, 1, SHADER_AO_MAX_SAMPLES},
            {"ao-blur", "N", "occlusion blur window 2N x 2N pixels on the same surface; 0: none", NULL, "2",
             CLI_WHOLE, 0, 16},
            CHAPTER_14_SHADOW_OPTIONS("K"),
        },
};

/* The shading pass and the views: every pixel written once; no blending, no depth test. */
static const gl_pass_state fullscreen_pass = {.depth_write = false};

static struct {
    gbuffer g;
    clusters c;
    forward fwd;
    ibl probes;
    ssao ao; /* chapter 17's occlusion, with its options */
    shadow_atlas atlas;           /* --shadows N: chapter 14's; nothing made without it */
    /* the shading programs' additions, by what is on (probes * 2 + occlusion): the ambient's defines
     * and inputs, then the same with chapter 14's atlas (--shadows N) */
    gl_program_extra ambient[4], shadowed[4];
    gl_program_extra_pair pairs[4];
    GLuint view_program;
    bool captured;
} state;

/* The shading programs' extra inputs: the probes, and the occlusion. */
static void bind_ambient(GLuint program, const void *user)
{
    (void)user;
    ibl_probes_bind(program, &state.probes);
    ssao_bind(program, &state.ao);
}

/* This frame's shading programs: built with the probes while they are on, the occlusion while it is
 * on, chapter 14's shadows while a light is shadowed; what is off costs nothing (each variant built
 * once, on first use). */
static void use_programs(void)
{
    int on = 2 * state.probes.on + state.ao.on;
    const gl_program_extra *extra =
        shadow_atlas_programs(&state.atlas, &state.shadowed[on], &state.ambient[on]);
    clusters_set_extra(&state.c, extra);
    forward_set_extra(&state.fwd, extra);
}

static bool init(app *a)
{
    double size, samples, radius, directions, blur;
    if (!app_extra_number(a, "probe-size", 16, 512, &size) || !app_extra_number(a, "ibl-samples", 1, 1024, &samples) ||
        !app_extra_number(a, "ao-radius", 1e-3, 1e3, &radius) ||
        !app_extra_number(a, "ao-samples", 1, SHADER_AO_MAX_SAMPLES, &directions) ||
        !app_extra_number(a, "ao-blur", 0, 16, &blur))
        return false;
    /* five prefiltered levels (roughness 0, 1/4, ... 1), the last one size / 16 texels */
    const ibl_desc desc = {.size = (int)size, .levels = 5, .samples = (int)samples, .brdf_size = 64,
                           .brdf_samples = 512};
    const ssao_desc occlusion = {.radius = (float)radius, .samples = (int)directions, .blur = (int)blur};
    static const char *const ambient_defines[4] = {NULL, "AMBIENT_OCCLUSION 1", "IMAGE_BASED_LIGHT 1",
                                                   "IMAGE_BASED_LIGHT 1\nAMBIENT_OCCLUSION 1"};
    gl_program_extra shadows; /* --shadows N: chapter 14's atlas too */
    if (!chapter_14_shadows_create(a, &state.atlas, &shadows))
        return false;
    for (int i = 0; i < 4; i++) {
        state.ambient[i] = (gl_program_extra){.defines = ambient_defines[i], .bind = bind_ambient};
        state.shadowed[i] = gl_program_extra_join(&state.pairs[i], &state.ambient[i], &shadows);
    }
    const gl_program_extra extra = state.shadowed[3];
    const clusters_desc lists = {.compute = gl_have_compute(), .extra = extra};
    a->pass_state = &fullscreen_pass; /* the overlay shows it */
    state.captured = false;
    state.view_program = gl_program_load("fullscreen.vert", "ibl_view.frag", "IMAGE_BASED_LIGHT 1");
    bool ok = state.view_program && ibl_probes_create(&state.probes, &desc) && ssao_create(&state.ao, &occlusion) &&
              gbuffer_create(&state.g, a->width, a->height) && clusters_create(&state.c, &lists) &&
              forward_create_with(&state.fwd, &extra);
    state.probes.on = strcmp(app_extra(a, "ibl"), "on") == 0;
    state.ao.on = strcmp(app_extra(a, "ssao"), "on") == 0;
    return ok;
}

static bool resize(app *a)
{
    return gbuffer_resize(&state.g, a->width, a->height) && ssao_resize(&state.ao, a->width, a->height);
}

/* At the first frame (the scene's lights placed at its time) and on key U: every probe again. */
static bool capture(const gpu_scene *gs)
{
    if (state.captured)
        return true;
    frame_timer_mark("probe capture");
    state.captured = ibl_probes_capture(&state.probes, gs);
    if (state.captured)
        log_info("19: %d probe%s captured, %.1f MiB, %.0f ms", state.probes.count, state.probes.count == 1 ? "" : "s",
                 ibl_probes_bytes(&state.probes) / 1048576.0, state.probes.capture_ms);
    return state.captured;
}

/* --view probe, irradiance, specular: one full-screen pass over the G-buffer. */
static bool draw_view(app *a)
{
    const gpu_scene *gs = &a->gs;
    if (!gbuffer_render(&state.g, gs))
        return false;
    frame_timer_mark("ibl view");
    glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
    glViewport(0, 0, a->width, a->height);
    gl_pass_state_apply(&fullscreen_pass);
    GLuint p = state.view_program;
    glUseProgram(p);
    gbuffer_bind_textures(&state.g, gs, p, SHADER_UNIT_GBUFFER);
    gpu_scene_bind_lights(gs, p, SHADER_UNIT_LIGHTS);
    ibl_probes_bind(p, &state.probes);
    glUniform1i(glGetUniformLocation(p, "u_ibl_view"), app_view_is(a, "probe") ? 1 : app_view_is(a, "irradiance") ? 2 : 3);
    glUniform1iv(glGetUniformLocation(p, "u_probe_scene_index"), SHADER_IBL_MAX_PICKED, state.probes.picked);
    gl_draw_fullscreen();
    gl_pass_state_reset();
    return gl_check("19 ibl view");
}

/* Forward (chapter 00's, pre-pass and lists) or Forward+ (chapter 11's) into target; with the
 * occlusion on, after chapter 17's depth-normal pre-pass and its two passes. */
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

/* Clustered deferred: geometry pass, light assignment, (SSAO, blur,) one shading pass (the probes
 * in its ambient). */
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
    if (!capture(&a->gs) || !chapter_14_shadows_update(&state.atlas, &a->gs)) /* before anything shades */
        return false;
    use_programs();
    ibl_probes_pick(&state.probes, a->gs.view.eye);
    snprintf(a->overlay_lines, sizeof a->overlay_lines, "probes: %d, %d picked; captured in %.0f ms, %.1f MiB",
             state.probes.count, state.probes.picked_count, state.probes.capture_ms,
             ibl_probes_bytes(&state.probes) / 1048576.0);
    bool ao_view = app_view_is(a, "ao") || app_view_is(a, "ao-blurred");
    if (!app_view_is(a, "lit") && !ao_view)
        return draw_view(a);
    bool was_on = state.ao.on;
    state.ao.on |= ao_view; /* the occlusion views draw it even when the picture does not use it */
    bool ok = app_renderer_is(a, "deferred") ? frame_deferred(a)
                                             : frame_forward(a, a->target.id, app_renderer_is(a, "forward-plus"));
    if (ok && ao_view)
        ssao_show(&state.ao, app_view_is(a, "ao"), a->target.id, a->width, a->height);
    state.ao.on = was_on;
    return ok;
}

/* I: the probes on or off (off: chapter 11's constant ambient); U: capture every probe again;
 * T / Y, J / L, B / N: the occlusion's radius, directions and blur (ssao_key);
 * O: the occlusion on or off; K: shadows on / off (with --shadows N). */
static bool key(app *a, int k)
{
    (void)a;
    if (k == 'K')
        return chapter_14_shadows_key(&state.atlas);
    if (ssao_key(&state.ao, k)) /* radius, directions, blur */
        return true;
    if (k == 'I') {
        state.probes.on = !state.probes.on;
        log_info("image-based light: %s", state.probes.on ? "on" : "off");
        return true;
    }
    if (k == 'O') {
        state.ao.on = !state.ao.on;
        log_info("ambient occlusion: %s", state.ao.on ? "on" : "off");
        return true;
    }
    if (k == 'U') {
        state.captured = false;
        log_info("image-based light: capturing the probes again");
        return true;
    }
    return false;
}

/* Compare mode's left side (key M): chapter 00's forward, with the same probes. */
static bool draw_forward(app *a, GLuint target)
{
    if (!capture(&a->gs))
        return false;
    ibl_probes_pick(&state.probes, a->gs.view.eye);
    return frame_forward(a, target, false);
}

static void cleanup(app *a)
{
    (void)a;
    forward_destroy(&state.fwd);
    clusters_destroy(&state.c);
    gbuffer_destroy(&state.g);
    ibl_probes_destroy(&state.probes);
    ssao_destroy(&state.ao);
    shadow_atlas_destroy(&state.atlas);
    gl_program_destroy(&state.view_program);
    memset(&state, 0, sizeof state); /* opened again (the benchmark does), init starts from nothing */
}

/* The GPU memory the probes and the table take (the benchmark's ambient rows). */
long chapter_19_probe_bytes(void) { return ibl_probes_bytes(&state.probes); }

const app_desc chapter_19 = {.cli = &cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup,
                             .key = key, .draw_forward = draw_forward, .takes_reversed_z = true,
                             .prefers_reversed_z = true};

CHAPTER_MAIN(chapter_19)
