/* 06_additive_blending.c - the lights are summed in a floating-point buffer and only the total is
 * turned into display values. Compare with chapter 05, which did this without saying why.
 *
 * Light adds up: the radiance at a pixel is ambient + the sum of every light's shade_light().
 * Each volume fragment adds its light with glBlendFunc(GL_ONE, GL_ONE) into an accumulation
 * buffer; one full-screen present pass then applies the display transform (tone map, then the
 * sRGB encoding of display_encode()) to the SUM, as forward.frag does at the end of its loop.
 *
 * The buffer's format matters:
 *   rgba16f  half floats: 11 bits of precision at any magnitude, values above 1 kept. The sum of
 *            eight lights differs from the forward renderer's by at most 1/255 after encoding.
 *   rgba8    what an 8-bit buffer does: every blend clamps at 1, so where several lights overlap
 *            the colour saturates to a washed-out white that no later pass can undo; and linear
 *            values in 8 bits leave visible steps in the dark (the sRGB curve spends 13x more
 *            codes there).
 * With values above 1 kept, the present pass can tone map instead of clipping:
 *   none      clamp to [0, 1]: the forward renderer's transform (the default, checked against it)
 *   exposure  multiply by --exposure first (darker or brighter), then clamp
 *   reinhard  x / (1 + x) after the exposure: bright overlaps roll off instead of clipping
 * Read docs/06_additive_blending.md alongside.
 */
#include "app.h"
#include "gbuffer.h"
#include "light_volumes.h"
#include "log.h"

static const char *const renderers[] = {"deferred", "forward", NULL};
static const char *const accum_formats[] = {"rgba16f", "rgba8", "rgba32f", NULL};
static const char *const tonemaps[] = {"none", "exposure", "reinhard", NULL};

static struct {
    gbuffer g;
    light_volumes lv;
    light_volumes_options options;
} state;

static bool init(app *a)
{
    state.options = (light_volumes_options){
        .cull = LIGHT_VOLUMES_CULL_FRONT, /* back faces, as in chapters 04-05 */
        .depth = LIGHT_VOLUMES_DEPTH_OFF, /* no depth test yet (chapter 07) */
        .no_depth_clamp = true,
    };
    if (!light_volumes_options_set(&state.options, "accum", app_extra(a, "accum")) ||
        !light_volumes_options_set(&state.options, "tonemap", app_extra(a, "tonemap")) ||
        !light_volumes_options_set(&state.options, "exposure", app_extra(a, "exposure")))
        return false;
    return gbuffer_create(&state.g, a->width, a->height) && light_volumes_create(&state.lv, &state.g);
}

static bool resize(app *a)
{
    return gbuffer_resize(&state.g, a->width, a->height) && light_volumes_resize(&state.lv, &state.g);
}

static bool frame(app *a)
{
    if (app_renderer_is(a, "forward"))
        return app_render_forward(a);

    /* 1. geometry pass */
    if (!gbuffer_render(&state.g, &a->gs))
        return false;

    /* 2. lighting pass: ambient, then += each light (blend ONE, ONE) in the accumulation buffer;
     * 3. present: tone map and display-encode the sum into a->target */
    state.options.count_pixels = a->options->bench;
    glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
    if (!light_volumes_render(&state.lv, &state.g, &a->gs, state.options))
        return false;
    a->shaded_pixels = light_volumes_shaded_pixels(&state.lv);
    return true;
}

static bool key(app *a, int k)
{
    (void)a;
    light_volumes_options *o = &state.options;
    if (k == 'A') {
        o->accum_format = o->accum_format == GL_RGBA8 ? GL_RGBA16F : GL_RGBA8;
        log_info("accumulation buffer: %s", o->accum_format == GL_RGBA8 ? "rgba8" : "rgba16f");
    } else if (k == 'T') {
        o->tonemap = (light_volumes_tonemap)((o->tonemap + 1) % 3);
        log_info("tone map: %s", tonemaps[o->tonemap]);
    } else if (k == '-' || k == '=') {
        o->exposure = (o->exposure > 0.0f ? o->exposure : 1.0f) * (k == '-' ? 0.5f : 2.0f);
        log_info("exposure: %g (used by the exposure and reinhard tone maps)", o->exposure);
    } else {
        return false;
    }
    return true;
}

static void cleanup(app *a)
{
    (void)a;
    light_volumes_destroy(&state.lv);
    gbuffer_destroy(&state.g);
}

int main(int argc, char **argv)
{
    const app_desc desc = {
        .cli =
            {
                .program = "06_additive_blending",
                .summary = "Chapter 06: lights summed with additive blending in a float buffer, then "
                           "tone mapped once.",
                .renderers = renderers,
                .keys = "  R        switch renderer (deferred light volumes, forward)\n"
                        "  A        accumulation buffer: rgba16f or rgba8 (saturates)\n"
                        "  T        tone map: none, exposure, reinhard\n"
                        "  - =      halve / double the exposure\n",
                .extras =
                    {
                        {"accum", "FORMAT", "accumulation buffer format", accum_formats, "rgba16f"},
                        {"tonemap", "OP", "display transform of the sum", tonemaps, "none"},
                        {"exposure", "E", "scale before the exposure / reinhard tone maps", NULL, "1"},
                    },
            },
        .init = init,
        .resize = resize,
        .frame = frame,
        .cleanup = cleanup,
        .key = key,
    };
    return app_run(&desc, argc, argv);
}
