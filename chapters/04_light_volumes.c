/* 04_light_volumes.c - each light is drawn as a sphere around it, so only the pixels the sphere
 * covers run the lighting shader for that light. Compare with chapter 03, where every pixel
 * looped over every light.
 *
 * The G-buffer pass is chapter 01's. The lighting pass is new:
 *   - the volume is an 80-triangle icosphere. Its vertices lie on the unit sphere, so its flat
 *     faces cut inside it; scaled by 1 / inradius the mesh contains the whole sphere (--scale none
 *     draws it unscaled: the light ends in a polygon instead of a circle);
 *   - all lights go in ONE instanced draw: the vertex shader fetches light gl_InstanceID's position
 *     from the same texture buffer the forward renderer reads, and moves and scales the mesh;
 *   - the fragment shader reads the G-buffer at gl_FragCoord and calls shade_light(), exactly as
 *     forward.frag does;
 *   - only the back faces are drawn (front faces culled), so each pixel meets each sphere once,
 *     even with the camera inside it; chapter 07 explains this choice and adds a depth test.
 *
 * Two things are still wrong here, on purpose:
 *   - every volume has the same radius (--radius, default 3): some lights are cut off too early
 *     (the hard circles), others shade pixels they cannot reach. Chapter 05 computes each radius.
 *   - blending is off: a volume fragment REPLACES the pixel, so where two spheres overlap only the
 *     light drawn last survives (the straight seams between two lights). Chapters 05-06 add them.
 * Read docs/04_light_volumes.md alongside.
 */
#include "app.h"
#include "gbuffer.h"
#include "light_volumes.h"
#include "log.h"

static const char *const renderers[] = {"deferred", "forward", NULL};
static const char *const scales[] = {"inradius", "none", NULL};

static struct {
    gbuffer g;
    light_volumes lv;
    light_volumes_options options;
} state;

static bool init(app *a)
{
    state.options = (light_volumes_options){
        .overwrite = true,                /* no blending yet: the last light wins */
        .cull = LIGHT_VOLUMES_CULL_FRONT, /* back faces: one fragment per pixel per light */
        .depth = LIGHT_VOLUMES_DEPTH_OFF, /* no depth test yet (chapter 07) */
        .no_depth_clamp = true,
    };
    if (!light_volumes_options_set(&state.options, "radius", app_extra(a, "radius")) ||
        !light_volumes_options_set(&state.options, "scale", app_extra(a, "scale")))
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

    /* 1. geometry pass: albedo, normal, material and depth of the visible surface per pixel */
    if (!gbuffer_render(&state.g, &a->gs))
        return false;

    /* 2. lighting pass: ambient everywhere, then one sphere per light, into a->target */
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
    if (k != 'S')
        return false;
    state.options.unscaled_mesh = !state.options.unscaled_mesh;
    log_info("volume mesh: %s",
             state.options.unscaled_mesh ? "unscaled (inscribed)" : "scaled by 1 / inradius");
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
                .program = "04_light_volumes",
                .summary =
                    "Chapter 04: one instanced sphere per light; only the pixels it covers are shaded.",
                .renderers = renderers,
                .keys = "  R        switch renderer (deferred light volumes, forward)\n"
                        "  S        scale the volume mesh by 1 / inradius, or not\n",
                .extras =
                    {
                        {"radius", "R", "radius of every light volume (chapter 05 solves one per light)",
                         NULL, "3"},
                        {"scale", "MODE", "volume mesh scale: inradius (contains the sphere) or none", scales,
                         "inradius"},
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
