/* 12_transparency.c - glass: objects whose material has an opacity below 1 are shaded FORWARD after
 * the deferred frame, back to front, and blended over it, lit by the SAME cluster lists the deferred
 * pass used. Compare with chapter 11, whose clustered deferred frame this chapter keeps for the
 * opaque objects, and with chapter 00, which draws the glass the same way with per-object lists.
 *
 * The G-buffer holds one surface per pixel: the glass would hide what lies behind it, and the
 * lighting pass could not light both. So the glass stays out of it (gpu_scene_draw draws the opaque
 * objects only), and the frame gains a linear-radiance target and two passes:
 *   the accumulation target: RGBA32F, sharing the G-buffer's depth; chapter 11's lighting pass writes
 *     linear radiance into it (CLUSTERS_VIEW_LINEAR) instead of display values into the window;
 *   the glass pass: every transparent object, shaded by forward_plus.frag (TRANSPARENT: linear
 *     radiance, the opacity A in alpha), each fragment looping over ITS cluster's lights (its own
 *     view depth picks the slice: the lists cover the whole frustum, not only the opaque surfaces),
 *     blended final = A * shaded + (1 - A) * behind in LINEAR radiance, as chapter 00 blends into a
 *     float buffer too;
 *   the present pass: the blended radiance display-encoded once (accum_present.frag, chapter 06).
 * The glass state (glass_back_pass, glass_front_pass): blending {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA},
 * the depth test against the G-buffer's depth (the opaque surfaces hide glass behind them), no depth
 * writes (glass must not hide glass). The order: back to front, by the distance of each object's
 * bounding-sphere centre from the eye (gpu_scene sorts every frame), and within an object its back
 * faces (culling GL_FRONT: its far side) before its front faces (GL_BACK: its near side). Right for
 * convex objects that do not intersect; --sort none draws them in the scene file's order, which is
 * wrong where they overlap.
 * Views: lit; overdraw, the glass fragments per pixel as a heat map (the layers each pixel blends);
 * opaque, the deferred frame alone (chapter 11's picture of a scene with glass).
 * Read docs/12_transparency.md alongside.
 */
#include "app.h"
#include "chapters.h"
#include "clusters.h"
#include "debug_views.h"
#include "gbuffer.h"
#include "log.h"

#include <string.h>

static const char *const renderers[] = {"deferred", "forward", NULL};
static const char *const views[] = {"lit", "overdraw", "opaque", NULL};
static const char *const sorts[] = {"back-to-front", "none", NULL};

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "12_transparency",
    .default_scene = "assets/scenes/glass.scene", /* the glass shows the lesson; the others have none */
    .summary = "Chapter 12: transparent objects shaded forward with the cluster lists, back to front, over "
               "the deferred frame.",
    .renderers = renderers,
    .views = views,
    .extras =
        {
            {"sort", "ORDER", "glass order: back to front, or the scene file's (none: wrong where glass "
             "overlaps)", sorts, "back-to-front"},
        },
};

/* Chapter 11's lighting pass: every pixel written once; no blending, no depth test. */
static const gl_pass_state lighting_pass = {.depth_write = false};

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
    clusters c;          /* chapter 11's grid and lists */
    fbo accum;           /* linear radiance; depth: the G-buffer's */
    present_pass present; /* chapter 06's present pass */
    GLuint query;
    debug_views views;   /* --view overdraw's count target and heat map */
    gpu_scene_order order;
} state;

/* The accumulation target at the G-buffer's size, on its depth texture. */
static bool accum_follow_gbuffer(void)
{
    return gbuffer_follow_target(&state.g, &state.accum, GL_RGBA32F, "linear radiance");
}

static bool init(app *a)
{
    state.order = strcmp(app_extra(a, "sort"), "none") == 0 ? GPU_SCENE_SCENE_ORDER : GPU_SCENE_BACK_TO_FRONT;
    a->pass_state = &glass_front_pass; /* the overlay shows it */
    state.query = gl_query_create();
    /* chapter 11's lists, made where it makes them by default: by compute shaders where the context
     * has them (the same lists as on the CPU, chapters.11_assign_same_*) */
    const clusters_desc lists = {.compute = gl_have_compute()};
    return present_pass_create(&state.present) && gbuffer_create(&state.g, a->width, a->height) &&
           accum_follow_gbuffer() && clusters_create(&state.c, &lists) && debug_views_create(&state.views);
}

static bool resize(app *a)
{
    return gbuffer_resize(&state.g, a->width, a->height) && accum_follow_gbuffer();
}

/* 3. the glass, into the framebuffer bound (it shares the G-buffer's depth): each transparent
 * object in state.order, with each of the two passes, its fragments lit by their clusters' lists */
static bool draw_glass(app *a, const gl_pass_state *back, const gl_pass_state *front, bool overdraw)
{
    const gl_pass_state *const passes[] = {back, front};
    gl_samples_begin(state.query, a->count_pixels);
    bool ok = clusters_shade_glass(&state.c, &a->gs, passes, 2, state.order,
                                   overdraw ? CLUSTERS_VIEW_OVERDRAW : CLUSTERS_VIEW_LINEAR);
    a->shaded_pixels = gl_samples_end(state.query, a->count_pixels);
    return ok;
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

/* 4. present: the blended radiance display-encoded, once, into the window's picture */
static bool present(app *a)
{
    frame_timer_mark("present");
    present_pass_draw(&state.present, state.accum.color[0], a->target.id, a->width, a->height, NULL);
    return gl_check("12 present");
}

static bool frame(app *a)
{
    if (!app_renderer_is(a, "deferred"))
        return app_render_forward(a);

    /* 1. geometry pass: the opaque objects only, and their depth; 2. light assignment (chapter 11) */
    if (!gbuffer_render(&state.g, &a->gs) || !chapter_11_assign(&state.c, &a->gs))
        return false;
    if (app_view_is(a, "overdraw"))
        return draw_overdraw(a);

    /* 3. lighting pass: the opaque surfaces, in linear radiance, into the accumulation target */
    if (!accum_follow_gbuffer())
        return false;
    glBindFramebuffer(GL_FRAMEBUFFER, state.accum.id);
    glViewport(0, 0, state.accum.width, state.accum.height);
    if (!chapter_11_shade_deferred(&state.c, &state.g, &a->gs, &lighting_pass, CLUSTERS_VIEW_LINEAR))
        return false;
    gl_pass_state_reset();

    /* 4. glass pass: forward-shaded, back to front, blended over that radiance */
    if (!app_view_is(a, "opaque") && !draw_glass(a, &glass_back_pass, &glass_front_pass, false))
        return false;

    /* 5. present */
    return present(a);
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
    clusters_destroy(&state.c);
    gl_query_destroy(&state.query);
    present_pass_destroy(&state.present);
    fbo_destroy(&state.accum);
    gbuffer_destroy(&state.g);
    memset(&state, 0, sizeof state); /* opened again (the benchmark does), init starts from nothing */
}

const app_desc chapter_12 = {.cli = &cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup, .draws_glass = true, .key = key};

CHAPTER_MAIN(chapter_12)
