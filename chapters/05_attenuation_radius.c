/* 05_attenuation_radius.c - each light volume gets its own radius: the distance where the light's
 * attenuated brightness falls to the cut-off. Compare with chapter 04 (one fixed radius for all).
 *
 * A point light's brightness at distance d is peak / (kc + kl d + kq d^2), peak its brightest
 * colour channel times its intensity. Past the distance where that drops below the cut-off
 * (default 5/256, about the smallest step an 8-bit display shows) the light is treated as zero,
 * so the volume can stop there. common/light.c solves kq r^2 + kl r + kc - peak / cutoff = 0 with
 * the cancellation-free root 2c / (kl + sqrt(kl^2 + 4 kq c)), c = peak / cutoff - kc, which also
 * covers kq = 0 (linear only), kl = kq = 0 (never falls: infinite radius, drawn full-screen) and
 * peak / kc <= cutoff (never reaches it: the light is culled). gpu_scene_update stores the radius
 * beside each light; the volume's vertex shader scales the mesh by it.
 *
 * The cut is a real discontinuity: a surface just inside the sphere gets up to `cutoff` of light,
 * just outside it gets none. On a dark surface that is a visible ring; --view ring draws it, and
 * --cutoff (or the [ ] keys) moves it: a larger cut-off, smaller volumes, faster, a brighter ring.
 *
 * Chapter 04 drew without blending, so the last light won. Here the volumes are ADDED into a
 * floating-point buffer (glBlendFunc(GL_ONE, GL_ONE)), ambient first, and one present pass
 * display-encodes the sum: the picture now matches chapter 00 (tests/chapters_04_07.cmake).
 * Chapter 06 explains why that buffer must be floating-point. Read docs/05_attenuation_radius.md.
 */
#include "app.h"
#include "gbuffer.h"
#include "light_volumes.h"
#include "log.h"

static const char *const renderers[] = {"deferred", "forward", NULL};
static const char *const views[] = {"lit", "ring", NULL};

static struct {
    gbuffer g;
    light_volumes lv;
    double logged_cutoff; /* radii are logged (with --verbose) when the cut-off changes */
} state;

static bool init(app *a)
{
    state.logged_cutoff = -1.0;
    return gbuffer_create(&state.g, a->width, a->height) && light_volumes_create(&state.lv, &state.g);
}

static bool resize(app *a)
{
    return gbuffer_resize(&state.g, a->width, a->height) && light_volumes_resize(&state.lv, &state.g);
}

/* The solved radii, to compare with the ring on screen. */
static void log_radii(const app *a)
{
    const gpu_scene *gs = &a->gs;
    log_debug("cut-off %.6g: %d lights drawn (%d full-screen), %d culled", a->cutoff, gs->light_count,
              gs->infinite_count, gs->culled_count);
    for (int i = 0; i < gs->light_count; i++) {
        const scene_light *l = &a->scene.lights[gs->lights[i].source];
        log_debug("  light %d: kc %g kl %g kq %g intensity %g -> radius %g", gs->lights[i].source, l->kc,
                  l->kl, l->kq, l->intensity, gs->lights[i].radius);
    }
    state.logged_cutoff = a->cutoff;
}

static bool frame(app *a)
{
    if (app_renderer_is(a, "forward"))
        return app_render_forward(a);
    if (a->cutoff != state.logged_cutoff)
        log_radii(a);

    /* 1. geometry pass */
    if (!gbuffer_render(&state.g, &a->gs))
        return false;

    /* 2. lighting pass: volumes sized by the solved radius, added up, then display-encoded */
    const light_volumes_options options = {
        .cull = LIGHT_VOLUMES_CULL_FRONT, /* back faces, as in chapter 04 */
        .depth = LIGHT_VOLUMES_DEPTH_OFF, /* still no depth test (chapter 07) */
        .no_depth_clamp = true,
        .view = app_view_is(a, "ring") ? LIGHT_VOLUMES_VIEW_RING : LIGHT_VOLUMES_VIEW_LIT,
        .count_pixels = a->options->bench,
    };
    glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
    if (!light_volumes_render(&state.lv, &state.g, &a->gs, options))
        return false;
    a->shaded_pixels = light_volumes_shaded_pixels(&state.lv);
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
                .program = "05_attenuation_radius",
                .summary =
                    "Chapter 05: each light volume's radius solved from its attenuation and the cut-off.",
                .renderers = renderers,
                .views = views,
                .keys = "  R        switch renderer (deferred light volumes, forward)\n"
                        "  V        view: lit, or lit + the cut-off ring of every light\n",
            },
        .init = init,
        .resize = resize,
        .frame = frame,
        .cleanup = cleanup,
    };
    return app_run(&desc, argc, argv);
}
