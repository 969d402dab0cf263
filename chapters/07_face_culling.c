/* 07_face_culling.c - the light volumes are depth-tested against the scene, so a light shades only
 * the pixels whose surface lies inside its sphere. Compare with chapter 06, which shaded every
 * pixel a sphere covers on screen, in front of it or behind it.
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
 * --view overdraw shows how many lighting fragments each pixel ran (1/16 grey each); --bench
 * prints them as shaded_pixels. Read docs/07_face_culling.md alongside.
 */
#include "app.h"
#include "gbuffer.h"
#include "light_volumes.h"
#include "log.h"

static const char *const renderers[] = {"deferred", "forward", NULL};
static const char *const views[] = {"lit", "overdraw", NULL};
static const char *const culls[] = {"front", "back", "none", NULL};
static const char *const on_off[] = {"on", "off", NULL};

static struct {
    gbuffer g;
    light_volumes lv;
    light_volumes_options options;
} state;

static bool init(app *a)
{
    /* Zeroed options are this chapter's configuration; the command line may pick a broken one. */
    state.options = (light_volumes_options){0};
    if (!light_volumes_options_set(&state.options, "cull", app_extra(a, "cull")) ||
        !light_volumes_options_set(&state.options, "depth-clamp", app_extra(a, "depth-clamp")))
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

    /* 1. geometry pass: also the depth the volumes are tested against */
    if (!gbuffer_render(&state.g, &a->gs))
        return false;

    /* 2. lighting pass: back faces, GL_GREATER, depth writes off, depth clamp; 3. present */
    state.options.view = app_view_is(a, "overdraw") ? LIGHT_VOLUMES_VIEW_OVERDRAW : LIGHT_VOLUMES_VIEW_LIT;
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
    if (k == 'C') {
        const char *next = culls[(state.options.cull + 1) % 3];
        light_volumes_options_set(&state.options, "cull", next);
        log_info("cull %s", next);
    } else if (k == 'D') {
        state.options.no_depth_clamp = !state.options.no_depth_clamp;
        log_info("depth clamp %s", state.options.no_depth_clamp ? "off" : "on");
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
                .program = "07_face_culling",
                .summary = "Chapter 07: back faces of the light volumes, depth-tested against the scene.",
                .renderers = renderers,
                .views = views,
                .keys = "  R        switch renderer (deferred light volumes, forward)\n"
                        "  V        view: lit, or overdraw (lighting fragments per pixel)\n"
                        "  C        cull front faces (right), back faces, or none (both wrong)\n"
                        "  D        depth clamp on / off\n",
                .extras =
                    {
                        {"cull", "FACES", "faces culled: front is right; back and none show bugs", culls,
                         "front"},
                        {"depth-clamp", "ON", "keep volumes that cross the far plane", on_off, "on"},
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
