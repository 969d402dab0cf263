/* 07_face_culling.c - the light volumes are depth-tested against the scene, so a light shades only
 * the pixels whose surface lies inside its sphere. Compare with chapter 06, which shaded every
 * pixel a sphere covers on screen, in front of it or behind it.
 *
 * Taken over: the G-buffer pass (02), the volumes from 04, the radius from 05, the additive
 * blending into a float buffer and the present pass from 06 (common/render/deferred_volumes.c). New here:
 * the volume pass's depth state, one literal (volume_pass below).
 *
 * A sphere's pixels come in two layers: its front faces (nearer half) and its back faces. Which
 * layer to draw, and which depth test to pair with it:
 *   front faces culled, back faces drawn, depth test GL_GREATER against the scene's depth with
 *   depth writes off (the default): a back face passes only where it lies behind the visible
 *   surface, i.e. where the surface is in front of the sphere's far side. Each pixel meets each
 *   light once, and a camera INSIDE a sphere still sees its back faces all around.
 *   With GL_DEPTH_CLAMP (core since 3.2) a back face beyond the far plane is kept at depth 1
 *   instead of being clipped, so volumes that cross the far plane still light what is in front.
 * The other choices are kept as options because their bugs are the lesson:
 *   --cull none   both layers, no depth test (no single test fits both): every pixel lit twice
 *   --cull back   front faces with GL_LEQUAL: right from outside, but when the camera enters a
 *                 sphere its front faces are behind the eye and the light vanishes
 *   --depth-clamp off   the far plane clips back faces: lights vanish near the far plane
 * --view overdraw shows how many lighting fragments ran at each pixel as a heat map; --bench prints
 * their total as shaded_pixels. --view volumes draws the spheres as lines over the picture
 * (common/render/debug_views.c). Read docs/07_face_culling.md alongside.
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
static const char *const culls[] = {"front", "back", "none", NULL};
static const char *const on_off[] = {"on", "off", NULL};

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "07_face_culling",
    .summary = "Chapter 07: back faces of the light volumes, depth-tested against the scene.",
    .renderers = renderers,
    .views = views,
    .extras =
        {
            {"cull", "FACES", "faces culled: front is right; back and none show bugs", culls,
             "front"},
            {"depth-clamp", "ON", "keep volumes that cross the far plane", on_off, "on"},
        },
};

/* The volumes' fixed-function state: added up as in chapter 06; back faces, kept only where they
 * lie behind the scene's surface; the scene's depth is read, never written; no far-plane clipping. */
static const gl_pass_state volume_pass = {
    .blend = {GL_ONE, GL_ONE},
    .cull = GL_FRONT,
    .depth_func = GL_GREATER,
    .depth_write = false,
    .depth_clamp = true,
};

/* The two wrong pairings of faces and depth test, for --cull back and --cull none. */
static const gl_pass_state front_faces_pass = {.blend = {GL_ONE, GL_ONE}, .cull = GL_BACK, .depth_func = GL_LEQUAL};
static const gl_pass_state both_faces_pass = {.blend = {GL_ONE, GL_ONE}};

static struct {
    gbuffer g;
    deferred_volumes dv;
    debug_views views;  /* --view volumes */
    gl_pass_state pass; /* volume_pass, or one of the wrong ones */
    int cull;           /* index into culls */
} state;

static void set_cull(int cull, bool depth_clamp)
{
    static const gl_pass_state *const passes[] = {&volume_pass, &front_faces_pass, &both_faces_pass};
    state.cull = cull;
    state.pass = *passes[cull];
    state.pass.depth_clamp = depth_clamp;
}

static bool init(app *a)
{
    set_cull(cli_choice_index(culls, app_extra(a, "cull")), strcmp(app_extra(a, "depth-clamp"), "on") == 0);
    a->pass_state = &state.pass; /* the overlay shows it, X and Z included */
    return gbuffer_create(&state.g, a->width, a->height) &&
           deferred_volumes_create(&state.dv, &state.g, GL_RGBA16F) && debug_views_create(&state.views);
}

static bool resize(app *a)
{
    return gbuffer_resize(&state.g, a->width, a->height) && deferred_volumes_resize(&state.dv, &state.g);
}

static bool frame(app *a)
{
    if (!app_renderer_is(a, "deferred"))
        return app_render_forward(a);

    /* 1. geometry pass: also the depth the volumes are tested against */
    if (!gbuffer_render(&state.g, &a->gs))
        return false;

    /* 2. lighting pass with the depth-tested volumes; 3. present */
    const deferred_volumes_frame f = {
        .volume_state = &state.pass,
        .view = app_view_is(a, "overdraw") ? LIGHT_VOLUMES_VIEW_OVERDRAW : LIGHT_VOLUMES_VIEW_LIT,
        .count_pixels = a->count_pixels,
    };
    if (!deferred_volumes_render(&state.dv, &state.g, &a->gs, a->target.id, &f))
        return false;
    a->shaded_pixels = deferred_volumes_shaded_pixels(&state.dv);
    a->linear = &state.dv.accum; /* the sum in linear radiance, before the present pass */
    /* the volumes view: every sphere as lines over the picture */
    return !app_view_is(a, "volumes") ||
           debug_views_draw_volumes(&state.views, &state.g, &a->gs, a->target.id, NULL);
}

/* This frame with a G-buffer of any layout and `how`'s accumulation format and view, for the
 * benchmark's G-buffer sweep and the tests: a reversed-Z layout mirrors the volumes' depth test and
 * projection (gbuffer_depth_test_begin), a state the chapter's own --gbuffer refuses. */
bool chapter_07_draw_with(gbuffer *g, deferred_volumes *dv, const gpu_scene *gs, GLuint target,
                          deferred_volumes_frame how)
{
    gl_pass_state pass = volume_pass;
    gpu_scene mirrored;
    if (!gbuffer_render(g, gs))
        return false;
    gbuffer_depth_test_begin(g, gs, &mirrored, &pass);
    how.volume_state = &pass;
    bool ok = deferred_volumes_render(dv, g, &mirrored, target, &how);
    gbuffer_depth_test_end(g);
    return ok;
}

static bool key(app *a, int k)
{
    (void)a;
    if (k == 'X') {
        set_cull((state.cull + 1) % 3, state.pass.depth_clamp);
        log_info("cull %s", culls[state.cull]);
    } else if (k == 'Z') {
        state.pass.depth_clamp = !state.pass.depth_clamp;
        log_info("depth clamp %s", state.pass.depth_clamp ? "on" : "off");
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

const app_desc chapter_07 = {.cli = &cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup, .key = key};

CHAPTER_MAIN(chapter_07)
