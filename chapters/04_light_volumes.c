/* 04_light_volumes.c - each light is drawn as a sphere around it, so only the pixels the sphere
 * covers run the lighting shader for that light. Compare with chapter 03, where every pixel
 * looped over every light.
 *
 * Taken over: the G-buffer pass (common/render/gbuffer.c, written in chapter 02). New here, in this file:
 *   - the volume is an 80-triangle icosphere. Its vertices lie on the unit sphere, so its flat
 *     faces cut inside it; scaled by 1 / inradius the mesh contains the whole sphere (--scale none
 *     draws it unscaled: the light ends in a polygon instead of a circle);
 *   - all lights go in ONE instanced draw (glDrawElementsInstanced below): the vertex shader
 *     fetches light gl_InstanceID's position from the same texture buffer the forward renderer
 *     reads, and moves and scales the mesh (shaders/light_volume.vert, FIXED_RADIUS);
 *   - the fragment shader reads the G-buffer at gl_FragCoord and calls shade_light(), exactly as
 *     forward.frag does, and writes the display-encoded result straight into the 8-bit target
 *     (shaders/light_volume.frag, OVERWRITE);
 *   - only the back faces are drawn (front faces culled), so each pixel meets each sphere once,
 *     even with the camera inside it; chapter 07 explains this choice and adds a depth test.
 *
 * Two things are still wrong here, on purpose:
 *   - every volume has the same radius (--radius, default 3): some lights are cut off too early
 *     (the hard circles), others shade pixels they cannot reach. Chapter 05 solves each radius.
 *   - blending is off: a volume fragment REPLACES the pixel, so where two spheres overlap only the
 *     light drawn last survives (the straight seams between two lights). Chapter 06 adds them up.
 * V shows the debug views (common/render/debug_views.c): overdraw, the volumes' fragments per pixel as a
 * heat map, drawn with this pass's faces but counted by additive blending; volumes, the spheres as
 * lines. Read docs/04_light_volumes.md alongside.
 */
#include "app.h"
#include "chapters.h"
#include "debug_views.h"
#include "gbuffer.h"
#include "light_volumes.h"
#include "log.h"

#include <string.h>

static const char *const renderers[] = {"deferred", "forward", NULL};
static const char *const scales[] = {"inradius", "none", NULL};
static const char *const views[] = {"lit", "overdraw", "volumes", NULL};

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "04_light_volumes",
    .summary =
        "Chapter 04: one instanced sphere per light; only the pixels it covers are shaded.",
    .renderers = renderers,
    .views = views,
    .extras =
        {
            {"radius", "R", "radius of every light volume (chapter 05 solves one per light)",
             NULL, "3", CLI_REAL, 1e-6, 1e6},
            {"scale", "MODE", "volume mesh scale: inradius (contains the sphere) or none", scales,
             "inradius"},
        },
};

/* The volumes' fixed-function state: back faces only, no blending, no depth test. */
static const gl_pass_state volume_pass = {.cull = GL_FRONT};

static struct {
    gbuffer g;
    light_volumes lv; /* the programs (compiled FIXED_RADIUS, OVERWRITE) and the icosphere */
    float radius;     /* of every volume */
    bool unscaled;    /* draw the inscribed mesh at radius r: faceted lights */
    debug_views views; /* --view overdraw and volumes */
} state;

static bool init(app *a)
{
    double radius;
    if (!app_extra_number(a, "radius", 1e-6, 1e6, &radius))
        return false;
    state.radius = (float)radius;
    state.unscaled = strcmp(app_extra(a, "scale"), "none") == 0;
    a->pass_state = &volume_pass; /* the overlay shows it */
    return gbuffer_create(&state.g, a->width, a->height) &&
           light_volumes_create(&state.lv, "FIXED_RADIUS 1\nOVERWRITE 1") && debug_views_create(&state.views);
}

static bool resize(app *a) { return gbuffer_resize(&state.g, a->width, a->height); }

/* 2b. one instance of the icosphere per light, all in one draw call, with the state `pass` */
static void draw_volumes(app *a, light_volumes_view view, const gl_pass_state *pass)
{
    const gpu_scene *gs = &a->gs;
    light_volumes_bind(&state.lv, &state.g, gs, view);
    glUniform1f(state.lv.u_fixed_radius, state.radius);
    glUniform1f(state.lv.u_mesh_scale, state.unscaled ? 1.0f : state.lv.mesh_scale);
    gl_pass_state_apply(pass);
    gl_samples_begin(a->query, a->count_pixels);
    glBindVertexArray(state.lv.sphere.vao);
    glDrawElementsInstanced(GL_TRIANGLES, state.lv.sphere.index_count, GL_UNSIGNED_INT, NULL, gs->light_count);
    a->shaded_pixels = gl_samples_end(a->query, a->count_pixels);
    glBindVertexArray(0);
    gl_pass_state_reset();
}

static bool frame(app *a)
{
    if (!app_renderer_is(a, "deferred"))
        return app_render_forward(a);

    /* 1. geometry pass: albedo, normal, material and depth of the visible surface per pixel */
    if (!gbuffer_render(&state.g, &a->gs))
        return false;

    /* the overdraw view: the same volumes, faces and depth state, each fragment counted (+1) */
    if (app_view_is(a, "overdraw")) {
        gl_pass_state count_pass;
        if (!debug_views_begin_overdraw(&state.views, &state.g, &volume_pass, &count_pass))
            return false;
        if (a->gs.light_count > 0)
            draw_volumes(a, LIGHT_VOLUMES_VIEW_OVERDRAW, &count_pass);
        return debug_views_end_overdraw(&state.views, a->target.id);
    }

    /* 2. lighting pass, straight into the target: 2a. ambient at every covered pixel */
    glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
    glViewport(0, 0, a->width, a->height);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    light_volumes_draw_ambient(&state.lv, &state.g, &a->gs);
    if (a->gs.light_count > 0)
        draw_volumes(a, LIGHT_VOLUMES_VIEW_LIT, &volume_pass);
    /* the volumes view: the spheres as drawn (radius, mesh scale), as lines over the picture */
    const debug_views_volumes drawn = {.fixed_radius = state.radius, .unscaled = state.unscaled};
    return gl_check("04 frame") &&
           (!app_view_is(a, "volumes") ||
            debug_views_draw_volumes(&state.views, &state.g, &a->gs, a->target.id, &drawn));
}

static bool key(app *a, int k)
{
    (void)a;
    if (k != 'I')
        return false;
    state.unscaled = !state.unscaled;
    log_info("volume mesh: %s", state.unscaled ? "unscaled (inscribed)" : "scaled by 1 / inradius");
    return true;
}

static void cleanup(app *a)
{
    (void)a;
    debug_views_destroy(&state.views);
    light_volumes_destroy(&state.lv);
    gbuffer_destroy(&state.g);
    memset(&state, 0, sizeof state); /* opened again (the benchmark does), init starts from nothing */
}

const app_desc chapter_04 = {.cli = &cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup, .key = key};

CHAPTER_MAIN(chapter_04)
