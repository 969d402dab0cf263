/* 00_forward.c - the baseline: forward rendering, every light evaluated while drawing each object.
 * Every later chapter is compared with this picture (key R, or --renderer forward).
 *
 * One frame is up to three passes, each written out in frame() below:
 *   1. per-object light lists (CPU): for each object, the lights whose sphere of influence
 *      reaches its bounding sphere, uploaded as a texture buffer of indices;
 *   2. depth pre-pass: every object into the depth buffer only, colour writes off;
 *   3. shading: every object again with shaders/forward.frag, which loops over the object's list
 *      (or over every light) and calls shade_light() from shaders/shading.glsl. After a pre-pass
 *      the depth test is GL_EQUAL with writes off, so only the visible fragment of each pixel
 *      pays for its lights.
 * The passes themselves (forward_build_light_lists, forward_draw_depth, forward_draw_shaded) are
 * in common/render/forward.c, because later chapters switch back to this renderer to compare. A scene with
 * glass (material opacity < 1) is drawn through a float buffer, the glass last, sorted and blended
 * in linear radiance (chapter 12 explains why; docs/12_transparency.md).
 *
 * The renderers of this chapter turn the two optimisations on and off (forward_variants in common/render/forward.c):
 *   forward           depth pre-pass + per-object light lists (the default, the best forward)
 *   forward-naive     one pass, every object shaded with every light
 *   forward-prepass   depth pre-pass only: each visible pixel is shaded once
 *   forward-lists     light lists only: each object only loops over the lights that reach it
 * Read docs/00_forward.md alongside.
 */
#include "app.h"
#include "chapters.h"
#include "gl_util.h"
#include "log.h"

#include <string.h>

static const char *const renderers[] = {"forward", "forward-naive", "forward-prepass", "forward-lists", "forward-plus", NULL};

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "00_forward",
    .summary = "Chapter 00: forward rendering, the baseline every deferred chapter is compared with.",
    .renderers = renderers,
};

/* Every pass draws the scene with GL_LEQUAL, so on an exact depth tie the object drawn last wins,
 * with or without a pre-pass (and in the G-buffer of the deferred chapters alike). */
static const gl_pass_state scene_pass = {.cull = GL_BACK, .depth_func = GL_LEQUAL, .depth_write = true};

/* After the pre-pass the depth buffer is final: shade only the fragment that wrote it. */
static const gl_pass_state shade_after_prepass = {.cull = GL_BACK, .depth_func = GL_EQUAL};

static struct {
    forward fwd;
    long frames_logged; /* the light-list statistics are logged (--verbose) for the first frame */
} state;

static bool init(app *a)
{
    (void)a;
    return forward_create(&state.fwd);
}

/* --verbose: how much the lists save, per frame. */
static void log_lists(const app *a)
{
    int objects = a->scene.object_count;
    log_debug("light lists: %ld (object, light) pairs for %d objects and %d lights: %.1f lights per "
              "object instead of %d",
              state.fwd.list_entries, objects, a->gs.light_count,
              objects ? (double)state.fwd.list_entries / objects : 0.0, a->gs.light_count);
}

static bool frame(app *a)
{
    if (app_renderer_is(a, "forward-plus")) /* chapter 11's Forward+, through the runner */
        return app_render_forward(a);
    const forward_options o = *forward_variant_find(a->cli->renderers[a->renderer]);
    const gpu_scene *gs = &a->gs;

    /* 1. per-object light lists, on the CPU */
    if (o.light_lists && !forward_build_light_lists(&state.fwd, gs))
        return false;
    if (o.light_lists && state.frames_logged++ == 0)
        log_lists(a);

    glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
    glViewport(0, 0, a->width, a->height);
    gl_pass_state_apply(&scene_pass);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    /* 2. depth pre-pass: the nearest depth of every pixel, before any shading */
    if (o.prepass) {
        forward_draw_depth(&state.fwd, gs);
        gl_pass_state_apply(&shade_after_prepass);
    }

    /* 3. shading: every object, each fragment looping over its lights */
    const forward_options shade = {
        .light_lists = o.light_lists, .count_pixels = a->count_pixels, .linear_output = a->linear_output};
    if (!forward_draw_shaded(&state.fwd, gs, shade))
        return false;
    a->shaded_pixels = forward_shaded_pixels(&state.fwd);
    a->lights_per_pixel = forward_lights_per_pixel(&state.fwd, gs, o.light_lists);
    a->linear_written = a->linear_output;
    gl_pass_state_reset();
    return gl_check("00 frame");
}

static void cleanup(app *a)
{
    (void)a;
    forward_destroy(&state.fwd);
    memset(&state, 0, sizeof state); /* opened again (the benchmark does), init starts from nothing */
}

const app_desc chapter_00 = {.cli = &cli, .init = init, .frame = frame, .cleanup = cleanup, .draws_glass = true};

CHAPTER_MAIN(chapter_00)
