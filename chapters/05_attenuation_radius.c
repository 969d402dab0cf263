/* 05_attenuation_radius.c - each light volume gets its own radius: the distance where the light's
 * attenuated brightness falls to the cut-off. Compare with chapter 04 (one fixed radius for all).
 *
 * Taken over: the G-buffer pass (02), the volume mesh, programs and instanced draw (04, now
 * common/render/light_volumes.c). New here:
 *   - the radius. A point light's brightness at distance d is peak / (kc + kl d + kq d^2), peak its
 *     brightest colour channel times its intensity. Past the distance where that drops below the
 *     cut-off (default 5/256, about the smallest step an 8-bit display shows) the light is treated
 *     as zero, so the volume can stop there. light_radius() (common/scene/light.c) solves
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
 * now along the true radii. Chapter 06 adds the lights up. V also shows the debug views of
 * common/render/debug_views.c: overdraw (fragments per pixel, a heat map) and volumes (the spheres as
 * lines, at the solved radii). Read docs/05_attenuation_radius.md.
 */
#include "app.h"
#include "chapters.h"
#include "debug_views.h"
#include "gbuffer.h"
#include "light_volumes.h"
#include "log.h"

#include <string.h>

static const char *const renderers[] = {"deferred", "forward", NULL};
static const char *const views[] = {"lit", "ring", "overdraw", "volumes", NULL};

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
    debug_views views;    /* --view overdraw and volumes */
} state;

static bool init(app *a)
{
    state.logged_cutoff = -1.0;
    a->pass_state = &volume_pass; /* the overlay shows it */
    return gbuffer_create(&state.g, a->width, a->height) && light_volumes_create(&state.lv, "OVERWRITE 1") &&
           debug_views_create(&state.views);
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

/* 2b. every volume at its own radius, with the state `pass`: the finite volumes in one instanced
 * draw, then the full-screen ones */
static bool draw_volumes(app *a, light_volumes_view view, const gl_pass_state *pass)
{
    if (!light_volumes_sort(&state.lv, &a->gs))
        return false;
    light_volumes_bind(&state.lv, &state.g, &a->gs, view);
    gl_samples_begin(a->query, a->count_pixels);
    light_volumes_draw(&state.lv, &a->gs, pass);
    a->shaded_pixels = gl_samples_end(a->query, a->count_pixels);
    return true;
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

    /* the overdraw view: the same volumes, faces and depth state, each fragment counted (+1) */
    if (app_view_is(a, "overdraw")) {
        gl_pass_state count_pass;
        if (!debug_views_begin_overdraw(&state.views, &state.g, &volume_pass, &count_pass))
            return false;
        if (!draw_volumes(a, LIGHT_VOLUMES_VIEW_OVERDRAW, &count_pass))
            return false;
        return debug_views_end_overdraw(&state.views, a->target.id);
    }

    /* 2. lighting pass, straight into the target: ambient, then every volume at its own radius */
    glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
    glViewport(0, 0, a->width, a->height);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    light_volumes_draw_ambient(&state.lv, &state.g, &a->gs);
    const light_volumes_view view = app_view_is(a, "ring") ? LIGHT_VOLUMES_VIEW_RING : LIGHT_VOLUMES_VIEW_LIT;
    if (!draw_volumes(a, view, &volume_pass))
        return false;
    /* the volumes view: the spheres at their solved radii, as lines over the picture */
    return gl_check("05 frame") &&
           (!app_view_is(a, "volumes") ||
            debug_views_draw_volumes(&state.views, &state.g, &a->gs, a->target.id, NULL));
}

static void cleanup(app *a)
{
    (void)a;
    debug_views_destroy(&state.views);
    light_volumes_destroy(&state.lv);
    gbuffer_destroy(&state.g);
    memset(&state, 0, sizeof state); /* opened again (the benchmark does), init starts from nothing */
}

const app_desc chapter_05 = {.cli = &cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup};

CHAPTER_MAIN(chapter_05)
