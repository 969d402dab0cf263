/* 03_fullscreen_phong.c - deferred shading, complete: a geometry pass fills the G-buffer, then one
 * full-screen triangle lights every pixel with every light.
 *
 * Compare with 00_forward (key R): the picture is the same to 1/255 (tests/chapters_01_03.cmake),
 * but each pixel is now shaded exactly once, whatever the depth complexity, and the objects are
 * drawn once, whatever the number of lights. The lesson is shaders/deferred_fullscreen.frag:
 * it reads the surface back (shaders/gbuffer_read.glsl), rebuilds the world position from depth
 * with the inverse view-projection, and calls the same shade_light() as forward.frag.
 * The two passes live in common/ (gbuffer.c, deferred_fullscreen.c) because chapters 04-07 and
 * the benchmark reuse them. Read docs/03_fullscreen_phong.md alongside.
 */
#include "app.h"
#include "deferred_fullscreen.h"
#include "gbuffer.h"

static const char *const renderers[] = {"deferred", "forward", NULL};

static struct {
    gbuffer gbuf;
    deferred_fullscreen lighting;
} state;

static bool init(app *a)
{
    return gbuffer_create(&state.gbuf, a->width, a->height) && deferred_fullscreen_create(&state.lighting);
}

static bool resize(app *a) { return gbuffer_resize(&state.gbuf, a->width, a->height); }

static bool frame(app *a)
{
    if (app_renderer_is(a, "forward"))
        return app_render_forward(a);

    /* 1. geometry pass: every object once, into the G-buffer (albedo, normal + material, depth) */
    if (!gbuffer_render(&state.gbuf, &a->gs))
        return false;

    /* 2. lighting pass: a full-screen triangle into the target, all lights per pixel */
    glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
    const deferred_fullscreen_options options = {.count_pixels = a->options->bench};
    if (!deferred_fullscreen_render(&state.lighting, &state.gbuf, &a->gs, options))
        return false;
    if (options.count_pixels)
        a->shaded_pixels = deferred_fullscreen_shaded_pixels(&state.lighting);
    return true;
}

static void cleanup(app *a)
{
    (void)a;
    deferred_fullscreen_destroy(&state.lighting);
    gbuffer_destroy(&state.gbuf);
}

int main(int argc, char **argv)
{
    const app_desc desc = {
        .cli =
            {
                .program = "03_fullscreen_phong",
                .summary = "Chapter 03: deferred shading with a full-screen lighting pass over all lights.",
                .renderers = renderers,
                .keys = "  R        switch deferred / forward (the pictures must agree)\n",
            },
        .init = init,
        .resize = resize,
        .frame = frame,
        .cleanup = cleanup,
    };
    return app_run(&desc, argc, argv);
}
