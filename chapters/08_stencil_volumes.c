/* 08_stencil_volumes.c - a light shades only the pixels whose surface lies INSIDE its volume: a
 * stencil pass counts, per pixel, how the volume's faces lie around the surface, and the lighting
 * pass runs only where the count says "inside". Compare with chapter 07, whose back faces with
 * GL_GREATER keep every surface in front of the sphere's far side, also those in front of the
 * whole sphere (1.8 times the fragments the lights need, at 1,024 lights on the default scene).
 *
 * Taken over: the G-buffer pass (02), now with a depth-stencil target (gbuffer_create_with; the
 * shaders read a copy of its depth, since the passes below write its stencil); the volumes from 04
 * and 05; the accumulation buffer and the present pass from 06 (common/render/deferred_volumes.c); back
 * faces and depth clamp from 07. New here, per batch of lights:
 *   a. stencil_pass: both faces, colour writes off, depth test GL_LEQUAL against the scene's depth,
 *      depth writes off. Where a face lies BEHIND the visible surface (the test fails) a back face
 *      adds 1 and a front face takes 1 away (GL_INCR_WRAP, GL_DECR_WRAP: one operation per face,
 *      glStencilOpSeparate). A surface inside the sphere has its back face behind it and its front
 *      face in front: 1. In front of the sphere both faces are behind it: 1 - 1 = 0; behind the
 *      sphere neither is: 0. With the camera inside, no front face is on screen, and the surfaces
 *      inside still count 1. Wrapping makes the count independent of the order the faces come in.
 *   b. light_pass: back faces, no depth test (the stencil holds its answer), stencil test
 *      GL_NOTEQUAL 0; each fragment also sets its pixel back to 0 (GL_ZERO where it passes), so the
 *      next batch starts from a clean stencil without a clear.
 * Batches: two lights whose rectangles on screen do not overlap touch different pixels, so their
 * counts cannot mix, and one instanced draw per pass serves all the lights of a batch
 * (common/render/light_batches.c). Lights whose sphere holds the whole view are drawn as in 07: full-screen.
 * The options show why each choice is made:
 *   --batch off          one light per batch: two draws per light instead of two per batch
 *   --count depth-pass   count the faces IN FRONT of the surface instead: right from outside,
 *                        but with the camera inside a sphere the light vanishes
 *   --depth-clamp off    the far plane clips back faces: lights vanish near it
 *   --reset off          the lighting pass leaves its counts: later batches shade stale pixels
 *                        (the picture is the same; --bench's shaded_pixels and the overdraw are not)
 * Read docs/08_stencil_volumes.md alongside.
 */
#include "app.h"
#include "chapters.h"
#include "debug_views.h"
#include "deferred_volumes.h"
#include "gbuffer.h"
#include "gl_program.h"
#include "light_batches.h"
#include "log.h"

#include <stdlib.h>
#include <string.h>

static const char *const renderers[] = {"deferred", "forward", NULL};
static const char *const views[] = {"lit", "overdraw", "volumes", NULL};
static const char *const on_off[] = {"on", "off", NULL};
static const char *const counts[] = {"depth-fail", "depth-pass", NULL};

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "08_stencil_volumes",
    .summary = "Chapter 08: stencil light volumes: each light shades only the surfaces inside it.",
    .renderers = renderers,
    .views = views,
    .extras =
        {
            {"batch", "ON", "one stencil pass for all lights whose screen rectangles do not overlap", on_off,
             "on"},
            {"count", "WHERE", "faces counted where the depth test fails (right) or passes (a bug)", counts,
             "depth-fail"},
            {"depth-clamp", "ON", "keep volumes that cross the far plane", on_off, "on"},
            {"reset", "ON", "the lighting pass sets the stencil back to 0 for the next batch", on_off, "on"},
        },
};

/* a. Count in the stencil, per face (glStencilOpSeparate(face, sfail, dpfail, dppass)): +1 for a
 * back face behind the surface, -1 for a front face behind it. Nothing else is written. */
static const gl_pass_state stencil_pass = {
    .depth_func = GL_LEQUAL,
    .depth_write = false,
    .depth_clamp = true,
    .stencil_func = GL_ALWAYS,
    .stencil_front = {GL_KEEP, GL_DECR_WRAP, GL_KEEP},
    .stencil_back = {GL_KEEP, GL_INCR_WRAP, GL_KEEP},
    .stencil_only = true,
};

/* The wrong count, for --count depth-pass: +1 for a front face in front of the surface, -1 for a
 * back face in front of it. Needs the front face: wrong when it is behind the eye. */
static const gl_pass_state stencil_pass_depth_pass = {
    .depth_func = GL_LEQUAL,
    .depth_clamp = true,
    .stencil_func = GL_ALWAYS,
    .stencil_front = {GL_KEEP, GL_KEEP, GL_INCR_WRAP},
    .stencil_back = {GL_KEEP, GL_KEEP, GL_DECR_WRAP},
    .stencil_only = true,
};

/* b. Light where the count is not 0, added up as in 06; back faces as in 07, and each fragment
 * resets its pixel's count (--reset off: GL_KEEP instead of GL_ZERO). */
static const gl_pass_state light_pass = {
    .blend = {GL_ONE, GL_ONE},
    .cull = GL_FRONT,
    .depth_clamp = true,
    .stencil_func = GL_NOTEQUAL,
    .stencil_back = {GL_KEEP, GL_KEEP, GL_ZERO},
};

/* Lights whose sphere holds the whole view: every visible surface is inside, no stencil needed. */
static const gl_pass_state fullscreen_pass = {.blend = {GL_ONE, GL_ONE}};

static struct {
    gbuffer g;           /* with a stencil */
    deferred_volumes dv; /* the volumes, the accumulation buffer (sharing g's depth-stencil), present */
    light_batches lb;
    GLuint stencil_program;      /* light_volume.vert + an empty fragment shader */
    GLint u_first, u_fullscreen; /* its uniforms (the lighting program's are in dv.lv) */
    gl_pass_state count, light;
    bool one_per_light;
    GLuint *queries; /* GL_SAMPLES_PASSED of each lighting draw, read once the frame is drawn */
    int queries_made, queries_used;
    debug_views views; /* --view volumes */
} state;

/* Instances [first, first + count) of the light list, with the program in use (both programs share
 * light_volume.vert, so they rasterise the same pixels). */
static void draw_volume_instances(GLint u_first, GLint u_fullscreen, int first, int count, bool fullscreen)
{
    glUniform1i(u_first, first);
    glUniform1i(u_fullscreen, fullscreen);
    if (fullscreen) {
        glBindVertexArray(state.dv.lv.sphere.vao);
        glDrawArraysInstanced(GL_TRIANGLES, 0, 3, count);
    } else {
        mesh_draw_instanced(&state.dv.lv.sphere, count);
    }
}

/* A lighting draw, counted in a query of its own: the stencil passes between them must not be. */
static void draw_lighting(bool counted, const gl_pass_state *pass, int first, int count, bool fullscreen)
{
    const light_volumes *lv = &state.dv.lv;
    glUseProgram(lv->program);
    gl_pass_state_apply(pass);
    if (counted)
        glBeginQuery(GL_SAMPLES_PASSED, state.queries[state.queries_used++]);
    draw_volume_instances(lv->u_first_instance, lv->u_fullscreen, first, count, fullscreen);
    if (counted)
        glEndQuery(GL_SAMPLES_PASSED);
}

/* --bench: one query per lighting draw (one per batch, and the full-screen lights). */
static bool make_queries(int n)
{
    GLuint *q = n > state.queries_made ? realloc(state.queries, (size_t)n * sizeof *q) : state.queries;
    if (!q)
        return false;
    for (state.queries = q; state.queries_made < n; state.queries_made++)
        q[state.queries_made] = gl_query_create();
    state.queries_used = 0;
    return true;
}

static long counted_pixels(void)
{
    long sum = 0;
    for (int i = 0; i < state.queries_used; i++) {
        GLuint samples = 0;
        glGetQueryObjectuiv(state.queries[i], GL_QUERY_RESULT, &samples);
        sum += (long)samples;
    }
    return sum;
}

/* The stencil program sees the same lights, light list and camera as the lighting program. */
static void bind_stencil_program(const gpu_scene *gs, float mesh_scale)
{
    GLuint p = state.stencil_program;
    glUseProgram(p);
    gpu_scene_bind_lights(gs, p, SHADER_UNIT_LIGHTS);
    glUniform1i(glGetUniformLocation(p, "u_light_index"), SHADER_UNIT_LIGHT_INDEX);
    glUniformMatrix4fv(glGetUniformLocation(p, "u_view_proj"), 1, GL_FALSE,
                       (const float *)gs->view.view_proj);
    glUniform1f(glGetUniformLocation(p, "u_mesh_scale"), mesh_scale);
}

/* 2. lighting: ambient, then per batch a. count in the stencil, b. light where the count is not 0 */
static bool draw_volumes(app *a, light_volumes_view view)
{
    light_volumes *lv = &state.dv.lv;
    const gpu_scene *gs = &a->gs;
    bool counted = a->count_pixels;
    if (!deferred_volumes_resize(&state.dv, &state.g) || !light_volumes_sort(lv, gs) ||
        !light_batches_make(&state.lb, lv, gs, state.one_per_light) ||
        (counted && !make_queries(state.lb.count + 1)))
        return false;
    frame_timer_mark("lighting");
    glBindFramebuffer(GL_FRAMEBUFFER, state.dv.accum.id);
    glViewport(0, 0, state.dv.accum.width, state.dv.accum.height);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    if (view != LIGHT_VOLUMES_VIEW_OVERDRAW)
        light_volumes_draw_ambient(lv, &state.g, gs);
    light_volumes_bind(lv, &state.g, gs, view);
    bind_stencil_program(gs, lv->mesh_scale);

    for (int b = 0; b < state.lb.count; b++) {
        const light_batch *batch = &state.lb.batches[b];
        glUseProgram(state.stencil_program);
        gl_pass_state_apply(&state.count);
        draw_volume_instances(state.u_first, state.u_fullscreen, batch->first, batch->count, false);
        draw_lighting(counted, &state.light, batch->first, batch->count, false);
    }
    if (gs->light_count > lv->finite_count)
        draw_lighting(counted, &fullscreen_pass, lv->finite_count, gs->light_count - lv->finite_count, true);
    gl_pass_state_reset();
    a->shaded_pixels = counted ? counted_pixels() : -1;
    a->linear = &state.dv.accum; /* the sum in linear radiance, before the present pass */
    return true;
}

static bool attach_stencil(void)
{
    gbuffer_attach_stencil(&state.g, state.dv.accum.id); /* the lighting pass tests g's stencil */
    return gl_check("attach_stencil");
}

static bool init(app *a)
{
    state.one_per_light = strcmp(app_extra(a, "batch"), "off") == 0;
    bool depth_fail = strcmp(app_extra(a, "count"), "depth-fail") == 0;
    state.count = depth_fail ? stencil_pass : stencil_pass_depth_pass;
    state.light = light_pass;
    state.count.depth_clamp = state.light.depth_clamp = strcmp(app_extra(a, "depth-clamp"), "on") == 0;
    if (strcmp(app_extra(a, "reset"), "off") == 0)
        state.light.stencil_back[2] = GL_KEEP;
    a->pass_state = &state.light; /* the overlay shows the lighting pass's state */
    state.stencil_program = gl_program_load("light_volume.vert", "depth_only.frag", NULL);
    state.u_first = glGetUniformLocation(state.stencil_program, "u_first_instance");
    state.u_fullscreen = glGetUniformLocation(state.stencil_program, "u_fullscreen");
    return state.stencil_program &&
           gbuffer_create_with(&state.g, a->width, a->height, &(gbuffer_desc){.stencil = true}) &&
           deferred_volumes_create(&state.dv, &state.g, GL_RGBA16F) && attach_stencil() &&
           debug_views_create(&state.views);
}

static bool resize(app *a)
{
    return gbuffer_resize(&state.g, a->width, a->height) && deferred_volumes_resize(&state.dv, &state.g) &&
           attach_stencil();
}

static bool frame(app *a)
{
    if (!app_renderer_is(a, "deferred"))
        return app_render_forward(a);

    /* 1. geometry pass: also the depth the volumes are tested against, and a cleared stencil */
    if (!gbuffer_render(&state.g, &a->gs))
        return false;

    /* 2. lighting pass, batch by batch; 3. present */
    const deferred_volumes_frame f = {
        .view = app_view_is(a, "overdraw") ? LIGHT_VOLUMES_VIEW_OVERDRAW : LIGHT_VOLUMES_VIEW_LIT,
    };
    if (!draw_volumes(a, f.view))
        return false;
    deferred_volumes_present(&state.dv, a->target.id, &f);
    return gl_check("08 frame") && (!app_view_is(a, "volumes") ||
                                    debug_views_draw_volumes(&state.views, &state.g, &a->gs, a->target.id, NULL));
}

static bool key(app *a, int k)
{
    (void)a;
    if (k == 'B') {
        state.one_per_light = !state.one_per_light;
        log_info("batches %s", state.one_per_light ? "off (one light per stencil pass)" : "on");
    } else if (k == 'X') {
        bool was_fail = state.count.stencil_back[1] == GL_INCR_WRAP;
        bool clamp = state.count.depth_clamp;
        state.count = was_fail ? stencil_pass_depth_pass : stencil_pass;
        state.count.depth_clamp = clamp;
        log_info("count where the depth test %s", was_fail ? "passes (wrong inside a volume)" : "fails");
    } else if (k == 'Z') {
        state.count.depth_clamp = state.light.depth_clamp = !state.light.depth_clamp;
        log_info("depth clamp %s", state.light.depth_clamp ? "on" : "off");
    } else {
        return false;
    }
    return true;
}

static void cleanup(app *a)
{
    /* --verbose: the last frame's batches, and its draws: the ambient, two per batch, one full-screen */
    int fullscreen = a->gs.light_count - state.dv.lv.finite_count;
    if (app_renderer_is(a, "deferred"))
        log_debug("stencil: %d batches for %d lights (%d full-screen): %d draws", state.lb.count,
                  a->gs.light_count, fullscreen, 1 + 2 * state.lb.count + (fullscreen > 0));
    for (int i = 0; i < state.queries_made; i++)
        gl_query_destroy(&state.queries[i]);
    free(state.queries);
    debug_views_destroy(&state.views);
    light_batches_destroy(&state.lb);
    gl_program_destroy(&state.stencil_program);
    deferred_volumes_destroy(&state.dv), gbuffer_destroy(&state.g);
    memset(&state, 0, sizeof state); /* opened again (the benchmark does), init starts from nothing */
}

const app_desc chapter_08 = {.cli = &cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup, .key = key};

CHAPTER_MAIN(chapter_08)
