/* 12_transparency.c - glass: objects whose material has an opacity below 1 are shaded FORWARD after
 * the deferred frame, back to front, and blended over it. Compare with chapter 07, whose frame this
 * chapter keeps for the opaque objects, and with chapter 00, which draws the glass the same way.
 *
 * The G-buffer holds one surface per pixel: the glass would hide what lies behind it, and the
 * lighting pass could not light both. So the glass stays out of it (gpu_scene_draw draws the opaque
 * objects only) and, after the lighting pass, before the present pass:
 *   the glass pass: every transparent object, shaded by forward.frag (TRANSPARENT: linear radiance,
 *     the opacity A in alpha) with its per-object light list (forward_build_light_lists, chapter 00),
 *     blended into the accumulation buffer, final = A * shaded + (1 - A) * behind, in LINEAR radiance,
 *     as chapter 00 now blends into a float buffer too; the present pass display-encodes the result;
 *   its state (glass_back_pass, glass_front_pass): blending {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA},
 *     the depth test against the G-buffer's depth (the opaque surfaces hide glass behind them), no
 *     depth writes (glass must not hide glass);
 *   the order: back to front, by the distance of each object's bounding-sphere centre from the eye
 *     (gpu_scene sorts every frame), and within an object its back faces (culling GL_FRONT: its far
 *     side) before its front faces (GL_BACK: its near side). Right for convex objects that do not
 *     intersect; --sort none draws them in the scene file's order, which is wrong where they overlap.
 * Views: lit; overdraw, the glass fragments per pixel as a heat map (the layers each pixel blends);
 * opaque, the deferred frame alone (what the other deferred chapters show of a scene with glass).
 * Read docs/12_transparency.md alongside.
 */
#include "app.h"
#include "debug_views.h"
#include "deferred_volumes.h"
#include "gbuffer.h"
#include "log.h"

#include <string.h>

static const char *const renderers[] = {"deferred", "forward", NULL};
static const char *const views[] = {"lit", "overdraw", "opaque", NULL};
static const char *const sorts[] = {"back-to-front", "none", NULL};

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "12_transparency",
    .summary = "Chapter 12: transparent objects shaded forward, back to front, over the deferred frame.",
    .renderers = renderers,
    .views = views,
    .extras =
        {
            {"sort", "ORDER", "glass order: back to front, or the scene file's (none: wrong where glass "
             "overlaps)", sorts, "back-to-front"},
        },
};

/* The glass: blended over the linear radiance behind it (straight alpha: A * source + (1 - A) *
 * destination), depth-tested against the opaque surfaces, never writing depth. Each object twice:
 * its far side (back faces; culling the front ones), then its near side. A camera inside a glass ball
 * sees only its back faces: the ball is still there, around it. */
static const gl_pass_state glass_back_pass = {
    .blend = {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA},
    .cull = GL_FRONT,
    .depth_func = GL_LEQUAL,
    .depth_write = false,
};
static const gl_pass_state glass_front_pass = {
    .blend = {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA},
    .cull = GL_BACK,
    .depth_func = GL_LEQUAL,
    .depth_write = false,
};

static struct {
    gbuffer g;
    deferred_volumes dv; /* the volumes, the accumulation buffer, the present pass (chapters 06-07) */
    forward fwd;         /* the glass program and the per-object light lists (chapter 00) */
    debug_views views;   /* --view overdraw's count target and heat map */
    gpu_scene_order order;
} state;

static bool init(app *a)
{
    state.order = strcmp(app_extra(a, "sort"), "none") == 0 ? GPU_SCENE_SCENE_ORDER : GPU_SCENE_BACK_TO_FRONT;
    a->pass_state = &glass_front_pass; /* the overlay shows it */
    return gbuffer_create(&state.g, a->width, a->height) &&
           deferred_volumes_create(&state.dv, &state.g, GL_RGBA16F) && forward_create(&state.fwd) &&
           debug_views_create(&state.views);
}

static bool resize(app *a)
{
    return gbuffer_resize(&state.g, a->width, a->height) && deferred_volumes_resize(&state.dv, &state.g);
}

/* 2. lighting: the opaque surfaces' ambient and light volumes, summed in the accumulation buffer
 * with chapter 07's volume state (renderers.c keeps it), without the present pass yet */
static bool light_opaque(app *a)
{
    light_volumes *lv = &state.dv.lv;
    if (!deferred_volumes_resize(&state.dv, &state.g) || !light_volumes_sort(lv, &a->gs))
        return false;
    frame_timer_mark("lighting");
    glBindFramebuffer(GL_FRAMEBUFFER, state.dv.accum.id);
    glViewport(0, 0, state.dv.accum.width, state.dv.accum.height);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    light_volumes_draw_ambient(lv, &state.g, &a->gs);
    light_volumes_bind(lv, &state.g, &a->gs, LIGHT_VOLUMES_VIEW_LIT);
    light_volumes_draw(lv, &a->gs, &renderer_volume_pass);
    return gl_check("12 lighting");
}

/* 3. the glass, into the framebuffer bound (it shares the G-buffer's depth): each transparent
 * object in state.order, with each of `passes` */
static bool draw_glass(app *a, const gl_pass_state *back, const gl_pass_state *front, bool overdraw)
{
    if (!forward_build_light_lists(&state.fwd, &a->gs))
        return false;
    const gl_pass_state *const passes[] = {back, front};
    const forward_glass glass = {
        .passes = passes,
        .pass_count = 2,
        .order = state.order,
        .light_lists = true,
        .count_pixels = a->count_pixels,
        .overdraw = overdraw,
    };
    if (!forward_draw_transparent(&state.fwd, &a->gs, &glass))
        return false;
    a->shaded_pixels = forward_shaded_pixels(&state.fwd);
    return gl_check("12 glass");
}

/* --view overdraw: the glass pass's fragments counted, with its own faces and depth test, added up. */
static bool draw_overdraw(app *a)
{
    gl_pass_state front, back = glass_back_pass;
    if (!debug_views_begin_overdraw(&state.views, &state.g, &glass_front_pass, &front))
        return false;
    back.blend[0] = front.blend[0], back.blend[1] = front.blend[1];
    return draw_glass(a, &back, &front, true) && debug_views_end_overdraw(&state.views, a->target.id);
}

static bool frame(app *a)
{
    if (!app_renderer_is(a, "deferred"))
        return app_render_forward(a);

    /* 1. geometry pass: the opaque objects only, and their depth */
    if (!gbuffer_render(&state.g, &a->gs))
        return false;
    if (app_view_is(a, "overdraw"))
        return draw_overdraw(a);

    /* 2. lighting pass: the opaque surfaces, in linear radiance */
    if (!light_opaque(a))
        return false;

    /* 3. glass pass: forward-shaded, back to front, blended over that radiance */
    glBindFramebuffer(GL_FRAMEBUFFER, state.dv.accum.id);
    if (!app_view_is(a, "opaque") && !draw_glass(a, &glass_back_pass, &glass_front_pass, false))
        return false;

    /* 4. present: the blended radiance display-encoded, once */
    deferred_volumes_present(&state.dv, a->target.id, &(deferred_volumes_frame){0});
    return gl_check("12 present");
}

static bool key(app *a, int k)
{
    (void)a;
    if (k != 'O')
        return false;
    state.order = state.order == GPU_SCENE_BACK_TO_FRONT ? GPU_SCENE_SCENE_ORDER : GPU_SCENE_BACK_TO_FRONT;
    log_info("glass order: %s", sorts[state.order]); /* the enum's values index sorts[] */
    return true;
}

static void cleanup(app *a)
{
    (void)a;
    debug_views_destroy(&state.views);
    forward_destroy(&state.fwd);
    deferred_volumes_destroy(&state.dv);
    gbuffer_destroy(&state.g);
}

int main(int argc, char **argv)
{
    const app_desc desc = {.cli = cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup,
                           .key = key};
    return app_run(&desc, argc, argv);
}
