/* 05_attenuation_radius.c - each light volume gets its own radius: the distance where the light's
 * attenuated brightness falls to the cut-off. Compare with chapter 04 (one fixed radius for all).
 *
 * Taken over: the G-buffer pass (02), the volume mesh, programs and instanced draw (04, now
 * common/light_volumes.c). New here:
 *   - the radius. A point light's brightness at distance d is peak / (kc + kl d + kq d^2), peak its
 *     brightest colour channel times its intensity. Past the distance where that drops below the
 *     cut-off (default 5/256, about the smallest step an 8-bit display shows) the light is treated
 *     as zero, so the volume can stop there. light_radius() (common/light.c) solves
 *     kq r^2 + kl r + kc - peak / cutoff = 0 with the cancellation-free root
 *     2c / (kl + sqrt(kl^2 + 4 kq c)), c = peak / cutoff - kc; gpu_scene_update() calls it for
 *     every light (the forward renderer cuts its lights off at the same radius) and uploads it
 *     beside the light, where the volume shader now reads it instead of a fixed radius;
 *   - the two cases a radius brings: a light that never falls to the cut-off (kl = kq = 0) has an
 *     infinite radius, and a sphere that contains the whole view covers every pixel anyway: both
 *     are drawn as full-screen triangles (light_volumes_sort, light_volumes_draw); a light that
 *     never reaches it (peak / kc <= cut-off) is culled and not drawn at all.
 *
 * The cut is a real discontinuity: a surface just inside the sphere gets up to `cutoff` of light,
 * just outside it gets none. On a dark surface that is a visible ring; --view ring draws it, and
 * --cutoff (or the [ ] keys) moves it: a larger cut-off, smaller volumes, faster, a brighter ring.
 *
 * Still wrong on purpose: no blending, so where two volumes overlap the light drawn last wins,
 * now along the true radii. Chapter 06 adds the lights up. Read docs/05_attenuation_radius.md.
 */
#include "app.h"
#include "gbuffer.h"
#include "light_volumes.h"
#include "log.h"

static const char *const renderers[] = {"deferred", "forward", NULL};
static const char *const views[] = {"lit", "ring", NULL};

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "05_attenuation_radius",
    .summary =
        "Chapter 05: each light volume's radius solved from its attenuation and the cut-off.",
    .renderers = renderers,
    .views = views,
};

/* The volumes' fixed-function state, as in chapter 04: back faces only, no blending, no depth test. */
static const gl_pass_state volume_pass = {.cull = GL_FRONT};

static struct {
    gbuffer g;
    light_volumes lv;     /* compiled OVERWRITE: each fragment writes its pixel */
    double logged_cutoff; /* radii are logged (with --verbose) when the cut-off changes */
} state;

static bool init(app *a)
{
    state.logged_cutoff = -1.0;
    return gbuffer_create(&state.g, a->width, a->height) && light_volumes_create(&state.lv, "OVERWRITE 1");
}

static bool resize(app *a) { return gbuffer_resize(&state.g, a->width, a->height); }

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
    if (!app_renderer_is(a, "deferred"))
        return app_render_forward(a);
    if (a->cutoff != state.logged_cutoff)
        log_radii(a);

    /* 1. geometry pass */
    if (!gbuffer_render(&state.g, &a->gs))
        return false;

    /* 2. lighting pass, straight into the target: ambient, then every volume at its own radius
     * (finite volumes in one instanced draw, then the full-screen ones) */
    glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
    glViewport(0, 0, a->width, a->height);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    light_volumes_draw_ambient(&state.lv, &state.g, &a->gs);
    if (!light_volumes_sort(&state.lv, &a->gs))
        return false;
    light_volumes_bind(&state.lv, &state.g, &a->gs,
                       app_view_is(a, "ring") ? LIGHT_VOLUMES_VIEW_RING : LIGHT_VOLUMES_VIEW_LIT);
    gl_samples_begin(a->query, a->options->bench);
    light_volumes_draw(&state.lv, &a->gs, &volume_pass);
    a->shaded_pixels = gl_samples_end(a->query, a->options->bench);
    return gl_check("05 frame");
}

static void cleanup(app *a)
{
    (void)a;
    light_volumes_destroy(&state.lv);
    gbuffer_destroy(&state.g);
}

int main(int argc, char **argv)
{
    const app_desc desc = {.cli = cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup};
    return app_run(&desc, argc, argv);
}
