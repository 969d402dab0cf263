/* 03_fullscreen_phong.c - deferred shading, complete: a geometry pass fills the G-buffer, then one
 * full-screen triangle lights every pixel with every light.
 *
 * Compare with 00_forward (key R): the picture is the same to 1/255 (tests/chapters/chapters_01_03.cmake),
 * but each pixel is now shaded exactly once, whatever the depth complexity, and the objects are
 * drawn once, whatever the number of lights.
 *
 * Taken over: the G-buffer pass (common/render/gbuffer.c, chapter 02). New here: the lighting pass,
 * shaders/deferred_fullscreen.frag. It reads the surface back (shaders/gbuffer_read.glsl),
 * rebuilds the world position from depth with the inverse view-projection, and calls the same
 * shade_light() as forward.frag, once per light. The pass lives in common/render/deferred_fullscreen.c
 * because chapter 02's lit view and the benchmark draw it too.
 *
 * The cost of this pass is pixels x lights, and most of it is wasted: with a cut-off a light only
 * reaches the points within its radius, and shade_light() returns zero for the others. The reach
 * view (V, or --view reach) shows, per pixel, the fraction of the loop that does any work: grey
 * = lights that reach this pixel / lights looped over. With the city's 757 lights most pixels are
 * near black. Chapter 04 skips those zeros before the shader runs.
 *
 * The overdraw view counts what the loop really evaluates: every light at every covered pixel (the
 * heat map of shaders/heat.glsl, one flat colour; compare chapter 07's). The volumes view draws each
 * light's sphere at its radius as lines: the only place its shading can be non-zero.
 *
 * Try: --view reach --cutoff 0.1 (each light's reach as a grey step), then --cutoff 0 (every light
 * reaches every pixel: white); --bench --lights 256 against --lights 16 (the cost grows with the
 * lights even where they do not reach); R for forward, whose picture this must equal.
 * Read docs/03_fullscreen_phong.md alongside.
 */
#include "app.h"
#include "chapters.h"
#include "debug_views.h"
#include "deferred_fullscreen.h"
#include "gbuffer.h"
#include "log.h"

#include <string.h>

static const char *const renderers[] = {"deferred", "forward", NULL};
/* lit: the lighting pass; reach: the share of its light loop that does any work; overdraw and
 * volumes: the debug views of every chapter from here on (key V). */
static const char *const views[] = {"lit", "reach", "overdraw", "volumes", NULL};

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "03_fullscreen_phong",
    .summary = "Chapter 03: deferred shading with a full-screen lighting pass over all lights.",
    .renderers = renderers,
    .views = views,
};

static struct {
    gbuffer gbuf;
    deferred_fullscreen lighting; /* the lighting pass */
    deferred_fullscreen reach;    /* the same loop, counting the lights that reach each pixel */
    deferred_fullscreen overdraw; /* the same loop, counting the lights it evaluates */
    debug_views views;            /* --view volumes */
} state;

static bool init(app *a)
{
    return gbuffer_create(&state.gbuf, a->width, a->height) &&
           deferred_fullscreen_create(&state.lighting, NULL) &&
           deferred_fullscreen_create(&state.reach, "VIEW_REACH 1") &&
           deferred_fullscreen_create(&state.overdraw, "VIEW_OVERDRAW 1") && debug_views_create(&state.views);
}

static bool resize(app *a) { return gbuffer_resize(&state.gbuf, a->width, a->height); }

/* --verbose: the pass's cost in light evaluations, against what reaches anything. */
static void log_cost(const app *a)
{
    static double logged_cutoff = -1.0;
    if (a->cutoff == logged_cutoff)
        return;
    logged_cutoff = a->cutoff;
    log_debug("lighting pass: every covered pixel loops over %d lights (%d culled by the cut-off %.4g, "
              "%d with an infinite radius)",
              a->gs.light_count, a->gs.culled_count, a->cutoff, a->gs.infinite_count);
}

static bool frame(app *a)
{
    if (!app_renderer_is(a, "deferred"))
        return app_render_forward(a);
    log_cost(a);

    /* 1. geometry pass: every object once, into the G-buffer (albedo, normal + material, depth) */
    if (!gbuffer_render(&state.gbuf, &a->gs))
        return false;

    /* 2. lighting pass: a full-screen triangle into the target, all lights per pixel */
    deferred_fullscreen *pass = app_view_is(a, "reach")      ? &state.reach
                                : app_view_is(a, "overdraw") ? &state.overdraw
                                                             : &state.lighting;
    const deferred_fullscreen_options options = {.count_pixels = a->count_pixels};
    if (!deferred_fullscreen_render(pass, &state.gbuf, &a->gs, a->target.id, options))
        return false;
    a->shaded_pixels = deferred_fullscreen_shaded_pixels(pass);
    a->lights_per_pixel = a->gs.light_count; /* every covered pixel loops over every light */
    /* the volumes view: each light's sphere at its radius, as lines over the picture */
    return !app_view_is(a, "volumes") ||
           debug_views_draw_volumes(&state.views, &state.gbuf, &a->gs, a->target.id, NULL);
}

static void cleanup(app *a)
{
    (void)a;
    debug_views_destroy(&state.views);
    deferred_fullscreen_destroy(&state.overdraw);
    deferred_fullscreen_destroy(&state.reach);
    deferred_fullscreen_destroy(&state.lighting);
    gbuffer_destroy(&state.gbuf);
    memset(&state, 0, sizeof state); /* opened again (the benchmark does), init starts from nothing */
}

const app_desc chapter_03 = {.cli = &cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup};

CHAPTER_MAIN(chapter_03)
