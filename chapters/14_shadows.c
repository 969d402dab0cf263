/* 14_shadows.c - shadows for many lights: one depth atlas cut into square tiles, six per point light
 * (the faces of a cube, 90-degree views) and one per spot, the tile's size chosen each frame from the
 * light's importance; each tile draws only the casters that can reach it, and is drawn again only
 * when something it shows changed. Compare with chapter 11, whose clustered deferred frame (and
 * Forward+) this chapter keeps: the light loops now multiply each light by how much of it reaches
 * the point, read from the atlas; chapter 00's forward reads the same atlas (--renderer forward).
 *
 * Taken over: chapter 11's grid, lists and both shading passes (chapters.h), chapter 00's forward
 * renderer, the G-buffer. New here (the plan and the atlas are written in common/shadows/, since
 * chapters 15 to 19 cast the same shadows: shadow_plan.c, shadow_atlas.c; shaders/shadows.glsl;
 * docs/14_shadows.md):
 *   1. the plan: importance = min(1, radius / distance to the eye); tier k (1024 >> k texels) from
 *      importance 0.5 / 2^k, with hysteresis; the --shadows most important lights packed largest
 *      first in Z order; when they do not fit, the least important take the smallest tiles, then go
 *      unshadowed (counted: --bench's 'shadows:' line)
 *   2. the shadow maps: for each tile drawn again (its light, tier or place changed, or a caster in
 *      its sphere moved), its square cleared and every caster whose box meets the light's sphere and
 *      the tile's frustum drawn, depth only, slope-scaled by --slope-bias
 *   3. the frame: chapter 11's, with the programs built with SHADOWS and the atlas bound
 *      (shadow_atlas_extra): a fragment finds the face from the light-to-point vector, moves along
 *      its normal by --normal-offset texels and averages --pcf x --pcf comparisons inside the tile.
 *      A frame with no light shadowed (--shadows 0, every light `shadow off`, or K) runs chapter 11's
 *      own programs, built without SHADOWS: shadows cost nothing while off (frame)
 * Read docs/14_shadows.md alongside.
 */
#include "app.h"
#include "chapters.h"
#include "clusters.h"
#include "forward.h"
#include "frame_timer.h"
#include "gbuffer.h"
#include "gl_program.h"
#include "log.h"
#include "shadow_atlas.h"
#include "shadow_views.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const renderers[] = {"deferred", "forward-plus", "forward", NULL};
static const char *const views[] = {"lit", "visibility", "atlas", "importance", NULL};
static const char *const formats[] = {"d32f", "d16", NULL};
const char *const chapter_14_pcfs[] = {"1", "3", "5", NULL}; /* chapters 15 to 19 offer them too */
static const char *const switches[] = {"on", "off", NULL};

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "14_shadows",
    .summary = "Chapter 14: shadows for many lights: one depth atlas, tiles sized by importance, culled "
               "casters, cached tiles.",
    .renderers = renderers,
    .views = views,
    .extras =
        {
            {"shadow-atlas", "SIZE", "the atlas's side in texels, a power of two from 256 (default 4096)", NULL, "4096",
             CLI_POWER_OF_TWO, 256, 32768},
            {"shadow-format", "FORMAT", "the atlas's depth format", formats, "d32f"},
            {"pcf", "N", "comparisons a side averaged per lookup", chapter_14_pcfs, CHAPTER_14_PCF},
            {"normal-offset", "TEXELS", "receivers moved along their normal by this many texels (0 to 8)", NULL,
             CHAPTER_14_NORMAL_OFFSET, CLI_REAL, 0, 8},
            {"slope-bias", "FACTOR", "glPolygonOffset factor of the shadow pass (0 to 16)", NULL, "2", CLI_REAL, 0, 16},
            {"shadows", "N", "shadow only the N most important lights (default: all)", NULL, NULL, CLI_WHOLE, 0, 1 << 20},
            {"shadow-cull", "ON", "draw only the casters that meet the light's sphere and the tile's frustum",
             switches, "on"},
            {"view-light", "K", "--view visibility counts light K alone (default: every light)", NULL, NULL, CLI_WHOLE,
             0, 1 << 20},
            {"time-step", "SECONDS", "the scene's time advances this much each frame, headless too (default 0)", NULL,
             "0", CLI_REAL, 0, 1e3},
        },
};

/* Chapter 11's clustered deferred pass: every pixel written once. */
static const gl_pass_state deferred_pass = {.depth_write = false};

static struct {
    shadow_atlas atlas;
    gl_program_extra extra; /* the atlas's SHADOWS define and inputs (shadow_atlas_extra) */
    gbuffer g;
    clusters c;
    forward fwd;
    GLuint visibility_program; /* --view visibility */
    shadow_views views;        /* --view atlas, --view importance */
    double time_step;
    int view_light; /* --view-light, -1: every light */
} state;

/* The atlas's options, checked against the context's largest texture. */
static bool read_options(app *a, shadow_plan_desc *desc, GLenum *format, float *slope)
{
    double size = 0, offset = 0, bias = 0, shadows = -1; /* the parser fills them, from the defaults too */
    GLint max_size = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
    /* the parser checked every range but the context's own largest texture: past it, an input error too */
    a->input_error = app_extra(a, "shadow-atlas") && atof(app_extra(a, "shadow-atlas")) > max_size;
    if (!app_extra_number(a, "shadow-atlas", 256, max_size, &size) || !app_extra_number(a, "normal-offset", 0, 8, &offset) ||
        !app_extra_number(a, "slope-bias", 0, 16, &bias) ||
        (app_extra(a, "shadows") && !app_extra_number(a, "shadows", 0, 1 << 20, &shadows)) ||
        !app_extra_number(a, "time-step", 0, 1e3, &state.time_step))
        return false;
    state.view_light = app_extra(a, "view-light") ? atoi(app_extra(a, "view-light")) : -1;
    if (state.view_light >= a->scene.light_count) {
        log_error("bad --view-light '%d': the scene has %d lights (0 to %d)", state.view_light, a->scene.light_count,
                  a->scene.light_count - 1);
        return !(a->input_error = true);
    }
    *desc = (shadow_plan_desc){.atlas_size = (int)size, .max_shadowed = (int)shadows, .pcf = atoi(app_extra(a, "pcf")),
                               .normal_offset = (float)offset, .cull = strcmp(app_extra(a, "shadow-cull"), "on") == 0};
    *format = strcmp(app_extra(a, "shadow-format"), "d16") == 0 ? GL_DEPTH_COMPONENT16 : GL_DEPTH_COMPONENT32F;
    *slope = (float)bias;
    return true;
}

static bool init(app *a)
{
    shadow_plan_desc desc;
    GLenum format;
    float slope;
    if (!read_options(a, &desc, &format, &slope) || !shadow_atlas_create(&state.atlas, &desc, format, slope))
        return false;
    /* chapter 11's lists where it makes them by default, its programs built with SHADOWS */
    state.extra = shadow_atlas_extra(&state.atlas);
    const clusters_desc lists = {.compute = gl_have_compute(), .extra = state.extra};
    a->pass_state = &deferred_pass; /* the overlay shows it */
    state.visibility_program = gl_program_load_extra("fullscreen.vert", "shadow_visibility.frag", NULL, &state.extra);
    return state.visibility_program && shadow_views_create(&state.views) &&
           gbuffer_create(&state.g, a->width, a->height) &&
           clusters_create(&state.c, &lists) && forward_create_with(&state.fwd, &state.extra);
}

static bool resize(app *a)
{
    return gbuffer_resize(&state.g, a->width, a->height);
}

/* --view visibility: per pixel, the share of the lights reaching it that the atlas lets through. */
static bool draw_visibility(app *a)
{
    frame_timer_mark("visibility");
    gl_pass_state_apply(&deferred_pass);
    glUseProgram(state.visibility_program);
    gpu_scene_bind_lights(&a->gs, state.visibility_program, SHADER_UNIT_LIGHTS);
    gbuffer_bind_textures(&state.g, &a->gs, state.visibility_program, SHADER_UNIT_GBUFFER);
    shadow_atlas_bind(state.visibility_program, &state.atlas);
    glUniform1i(glGetUniformLocation(state.visibility_program, "u_view_light"), state.view_light);
    gl_draw_fullscreen();
    return gl_check("14 visibility");
}

/* Clustered deferred: 1. geometry pass; 2. light assignment; 3. one full-screen shading pass. */
static bool frame_deferred(app *a)
{
    if (!gbuffer_render(&state.g, &a->gs) || !chapter_11_assign(&state.c, &a->gs))
        return false;
    glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
    glViewport(0, 0, a->width, a->height);
    bool ok = app_view_is(a, "visibility")
                  ? draw_visibility(a)
                  : chapter_11_shade_deferred(&state.c, &state.g, &a->gs, &deferred_pass, CLUSTERS_VIEW_LIT);
    gl_pass_state_reset();
    return ok;
}

/* Forward (chapter 00's, with its pre-pass and lists) or Forward+ (chapter 11's) into `target`. */
static bool frame_forward(app *a, GLuint target, bool plus)
{
    bool ok;
    if (plus)
        ok = chapter_11_forward_plus.prepass(&state.c, &a->gs, target) &&
             chapter_11_forward_plus.shade(&state.c, &a->gs, CLUSTERS_VIEW_LIT);
    else
        ok = forward_render(&state.fwd, &a->gs, target, (forward_options){.prepass = true, .light_lists = true});
    gl_pass_state_reset();
    return ok;
}

/* --view atlas, --view importance: the atlas's tiles, or the lights over the picture, each in its
 * light's tier colour (chapters/shadow_views.c). */
static bool draw_views(app *a)
{
    frame_timer_mark("view");
    glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
    glViewport(0, 0, a->width, a->height);
    bool ok = app_view_is(a, "atlas") ? shadow_views_draw_atlas(&state.views, &state.atlas, a->width, a->height)
                                      : shadow_views_draw_lights(&state.views, &state.atlas, &a->gs, a->width, a->height);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return ok;
}

static bool frame(app *a)
{
    /* 1., 2.: the plan and the tiles it says changed; then the frame, which reads them */
    if (!shadow_atlas_update(&state.atlas, &a->gs))
        return false;
    /* the frame's programs: with SHADOWS while the plan shadows a light, chapter 11's own while none is
     * (each variant built once, on first use: gl_program_variant) */
    const gl_program_extra *extra = shadow_atlas_programs(&state.atlas, &state.extra, NULL);
    clusters_set_extra(&state.c, extra);
    forward_set_extra(&state.fwd, extra);
    shadow_views_overlay(&state.atlas, a->overlay_lines, sizeof a->overlay_lines);
    a->time += (float)state.time_step; /* --time-step: the next frame's time (the window adds its own) */
    a->shaded_pixels = -1;
    bool ok = true; /* --view atlas shows the atlas alone */
    if (app_renderer_is(a, "deferred") || app_view_is(a, "visibility")) /* the view reads the G-buffer */
        ok = frame_deferred(a);
    else if (!app_view_is(a, "atlas"))
        ok = frame_forward(a, a->target.id, app_renderer_is(a, "forward-plus"));
    return ok && (app_view_is(a, "lit") || app_view_is(a, "visibility") || draw_views(a));
}

/* K: shadows on or off; off, every light is unshadowed and the picture is chapter 11's. */
static bool key(app *a, int k)
{
    (void)a;
    return k == 'K' && chapter_14_shadows_key(&state.atlas);
}

/* Compare mode's left side (key M): chapter 00's forward, reading the same atlas. */
static bool draw_forward(app *a, GLuint target)
{
    return frame_forward(a, target, false);
}

/* --bench: the atlas, the lights it shadows, what the last frame drew and what culling saved. */
static void print_report(const app *a)
{
    const shadow_plan *p = &state.atlas.plan;
    const shadow_frame_stats *s = &p->stats;
    printf("shadows: renderer=%s atlas=%d format=%s atlas_mib=%.2f pcf=%d normal_offset=%g slope_bias=%g cull=%s "
           "shadowed=%d off=%d not_chosen=%d dropped=%d tier_lights=%d/%d/%d/%d tiles=%d tiles_drawn=%d "
           "tiles_drawn_mean=%.2f draws=%ld triangles=%ld draws_unculled=%ld triangles_unculled=%ld\n",
           renderers[a->renderer], p->desc.atlas_size, app_extra(a, "shadow-format"),
           shadow_atlas_bytes(&state.atlas) / (1024.0 * 1024.0), p->desc.pcf, p->desc.normal_offset,
           state.atlas.slope_bias, p->desc.cull ? "on" : "off", s->shadowed, s->off, s->not_chosen, s->dropped,
           s->lights_per_tier[0], s->lights_per_tier[1], s->lights_per_tier[2], s->lights_per_tier[3], s->tiles,
           s->tiles_drawn, state.atlas.frames ? (double)state.atlas.tiles_drawn_total / (double)state.atlas.frames : 0.0,
           s->draws, s->triangles, s->draws_unculled, s->triangles_unculled);
    fflush(stdout);
}

static void cleanup(app *a)
{
    if (a->options->bench && state.atlas.depth_program)
        print_report(a);
    gl_program_destroy(&state.visibility_program);
    shadow_views_destroy(&state.views);
    forward_destroy(&state.fwd);
    clusters_destroy(&state.c);
    gbuffer_destroy(&state.g);
    shadow_atlas_destroy(&state.atlas);
    memset(&state, 0, sizeof state); /* opened again (the benchmark does), init starts from nothing */
}

/* ---- the shadows in a later chapter (chapters.h: chapters 15 to 19, --shadows N) ----------------- */

bool chapter_14_shadows_create(app *a, shadow_atlas *s, gl_program_extra *extra)
{
    double n = 0, size = 4096;
    GLint max_size = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
    memset(s, 0, sizeof *s);
    *extra = (gl_program_extra){0};
    a->input_error = app_extra(a, "shadow-atlas") && atof(app_extra(a, "shadow-atlas")) > max_size;
    if (!app_extra_number(a, "shadows", 0, 1 << 20, &n) || !app_extra_number(a, "shadow-atlas", 256, max_size, &size))
        return false;
    if (n == 0)
        return true; /* no atlas, no define: the chapter's own picture */
    /* chapter 14's defaults for what the later chapters do not offer */
    const shadow_plan_desc desc = {.atlas_size = (int)size, .max_shadowed = (int)n, .pcf = atoi(app_extra(a, "pcf")),
                                   .normal_offset = (float)atof(CHAPTER_14_NORMAL_OFFSET), .cull = true};
    if (!shadow_atlas_create(s, &desc, GL_DEPTH_COMPONENT32F, 2.0f))
        return false;
    *extra = shadow_atlas_extra(s);
    return true;
}

bool chapter_14_shadows_update(shadow_atlas *s, const gpu_scene *gs)
{
    return !s->depth_program || shadow_atlas_update(s, gs);
}

bool chapter_14_shadows_key(shadow_atlas *s)
{
    if (!s->depth_program) {
        log_info("shadows: none (start with --shadows N to shadow the N most important lights)");
        return true;
    }
    s->enabled = !s->enabled;
    log_info("shadows: %s", s->enabled ? "on" : "off");
    return true;
}

const app_desc chapter_14 = {.cli = &cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup,
                             .key = key, .draw_forward = draw_forward};

CHAPTER_MAIN(chapter_14)
