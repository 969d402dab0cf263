/* 06_additive_blending.c - the lights are summed in a floating-point buffer and only the total is
 * turned into display values. Compare with chapter 05, where the light drawn last replaced the
 * others wherever two volumes overlapped.
 *
 * Taken over: the G-buffer pass (02), the volumes from 04, each light's radius from 05 (all in
 * common/render/light_volumes.c). New here (common/render/deferred_volumes.c from this chapter on):
 *   - light adds up: the radiance at a pixel is ambient + the sum of every light's shade_light().
 *     Each volume fragment adds its light with glBlendFunc(GL_ONE, GL_ONE) (the pass state below)
 *     into an accumulation buffer, after one full-screen pass has written the ambient term;
 *   - one full-screen present pass then applies the display transform (tone map, then the sRGB
 *     encoding of display_encode()) to the SUM, as forward.frag does at the end of its loop. This
 *     is the first volume chapter whose picture matches chapter 00's.
 *
 * The buffer's format matters:
 *   rgba16f  half floats: 11 bits of precision at any magnitude, values above 1 kept. The sum of
 *            eight lights differs from the forward renderer's by at most 1/255 after encoding.
 *   rgba8    what an 8-bit buffer does: every blend clamps at 1, so where several lights overlap
 *            the colour saturates to a washed-out white that no later pass can undo; and linear
 *            values in 8 bits leave visible steps in the dark (the sRGB curve spends 13x more
 *            codes there).
 *   rgba32f  full floats: twice the memory and bandwidth of rgba16f, for the last 1/255.
 * With values above 1 kept, the present pass can tone map instead of clipping:
 *   none      clamp to [0, 1]: the forward renderer's transform (the default, checked against it)
 *   exposure  multiply by --exposure first (darker or brighter), then clamp
 *   reinhard  x / (1 + x) after the exposure: bright overlaps roll off instead of clipping
 * V shows the debug views (common/render/debug_views.c): overdraw counts the fragments in the same buffer
 * (an rgba8 one stops counting at 16) and shows them as a heat map; volumes draws the spheres as
 * lines. Read docs/06_additive_blending.md alongside.
 */
#include "app.h"
#include "chapters.h"
#include "debug_views.h"
#include "deferred_volumes.h"
#include "gbuffer.h"
#include "log.h"

#include <string.h>

static const char *const renderers[] = {"deferred", "forward", NULL};
static const char *const views[] = {"lit", "overdraw", "volumes", NULL};
static const char *const accum_names[] = {"rgba16f", "rgba8", "rgba32f", NULL};
static const GLenum accum_formats[] = {GL_RGBA16F, GL_RGBA8, GL_RGBA32F};
static const char *const tonemaps[] = {"none", "exposure", "reinhard", NULL};

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "06_additive_blending",
    .summary = "Chapter 06: lights summed with additive blending in a float buffer, then "
               "tone mapped once.",
    .renderers = renderers,
    .views = views,
    .extras =
        {
            {"accum", "FORMAT", "accumulation buffer format", accum_names, "rgba16f"},
            {"tonemap", "OP", "display transform of the sum", tonemaps, "none"},
            {"exposure", "E", "scale before the exposure / reinhard tone maps", NULL, "1", CLI_REAL, 1e-6, 1e6},
        },
};

/* The volumes' fixed-function state: back faces only as before, and now every fragment is ADDED
 * to what the buffer holds (source * 1 + destination * 1). */
static const gl_pass_state volume_pass = {.blend = {GL_ONE, GL_ONE}, .cull = GL_FRONT};

static struct {
    gbuffer g;
    deferred_volumes dv; /* the volumes, the accumulation buffer, the present pass */
    debug_views views;   /* --view volumes */
    int accum;           /* index into accum_formats */
    deferred_volumes_tonemap tonemap;
    double exposure;
} state;

static bool init(app *a)
{
    state.accum = cli_choice_index(accum_names, app_extra(a, "accum"));
    a->pass_state = &volume_pass; /* the overlay shows it */
    state.tonemap = (deferred_volumes_tonemap)cli_choice_index(tonemaps, app_extra(a, "tonemap"));
    if (!app_extra_number(a, "exposure", 1e-6, 1e6, &state.exposure))
        return false;
    return gbuffer_create(&state.g, a->width, a->height) &&
           deferred_volumes_create(&state.dv, &state.g, accum_formats[state.accum]) &&
           debug_views_create(&state.views);
}

static bool resize(app *a)
{
    return gbuffer_resize(&state.g, a->width, a->height) && deferred_volumes_resize(&state.dv, &state.g);
}

static bool frame(app *a)
{
    if (!app_renderer_is(a, "deferred"))
        return app_render_forward(a);

    /* 1. geometry pass */
    if (!gbuffer_render(&state.g, &a->gs))
        return false;

    /* 2. lighting pass: ambient, then += each light (blend ONE, ONE) in the accumulation buffer;
     * 3. present: tone map and display-encode the sum into the target */
    const deferred_volumes_frame f = {
        .volume_state = &volume_pass,
        .accum_format = accum_formats[state.accum],
        .tonemap = state.tonemap,
        .exposure = (float)state.exposure,
        .view = app_view_is(a, "overdraw") ? LIGHT_VOLUMES_VIEW_OVERDRAW : LIGHT_VOLUMES_VIEW_LIT,
        .count_pixels = a->count_pixels,
    };
    if (!deferred_volumes_render(&state.dv, &state.g, &a->gs, a->target.id, &f))
        return false;
    a->shaded_pixels = deferred_volumes_shaded_pixels(&state.dv);
    /* the volumes view: every sphere as lines over the picture */
    return !app_view_is(a, "volumes") ||
           debug_views_draw_volumes(&state.views, &state.g, &a->gs, a->target.id, NULL);
}

static bool key(app *a, int k)
{
    (void)a;
    if (k == 'B') {
        state.accum = accum_names[state.accum + 1] ? state.accum + 1 : 0;
        log_info("accumulation buffer: %s", accum_names[state.accum]);
    } else if (k == 'T') {
        state.tonemap = (deferred_volumes_tonemap)((state.tonemap + 1) % 3);
        log_info("tone map: %s", tonemaps[state.tonemap]);
    } else if (k == KEY_PAGE_DOWN || k == KEY_PAGE_UP) {
        state.exposure *= k == KEY_PAGE_DOWN ? 0.5 : 2.0;
        log_info("exposure: %g (used by the exposure and reinhard tone maps)", state.exposure);
    } else {
        return false;
    }
    return true;
}

static void cleanup(app *a)
{
    (void)a;
    debug_views_destroy(&state.views);
    deferred_volumes_destroy(&state.dv);
    gbuffer_destroy(&state.g);
    memset(&state, 0, sizeof state); /* opened again (the benchmark does), init starts from nothing */
}

const app_desc chapter_06 = {.cli = &cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup, .key = key};

CHAPTER_MAIN(chapter_06)
