/* 00_forward.c - the baseline: forward rendering, every light evaluated while drawing each object.
 *
 * Everything this chapter needs lives in common/forward.c, because every later chapter switches
 * back to it (key R, or --renderer forward) to compare. Here you can turn its two optimisations
 * on and off and watch what they buy:
 *   forward           depth pre-pass + per-object light lists (the default, the best forward)
 *   forward-naive     one pass, every object shaded with every light
 *   forward-prepass   depth pre-pass only: each visible pixel is shaded once
 *   forward-lists     light lists only: each object only loops over the lights that reach it
 * Read docs/00_forward.md alongside.
 */
#include "app.h"

static const char *const renderers[] = {"forward", "forward-naive", "forward-prepass", "forward-lists", NULL};

static bool frame(app *a)
{
    /* 1. one pass per object (after an optional depth pre-pass), all lights in a texture buffer */
    return app_render_forward(a);
}

int main(int argc, char **argv)
{
    const app_desc desc = {
        .cli =
            {
                .program = "00_forward",
                .summary = "Chapter 00: forward rendering, the baseline every deferred chapter is compared with.",
                .renderers = renderers,
                .keys = "  R        next renderer (forward, naive, pre-pass only, light lists only)\n",
            },
        .frame = frame,
    };
    return app_run(&desc, argc, argv);
}
