/* renderers.c - see renderers.h. */
#include "renderers.h"

#include "renderer_tiled.h"

#include "frame_timer.h"
#include "light_batches.h"
#include "log.h"
#include "shader_layout.h"
#include "shader_log.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const renderer_info renderer_table[RENDERER_COUNT] = {
    [RENDERER_FORWARD] = {"forward", "00", "depth pre-pass + per-object light lists", true, {true, true}},
    [RENDERER_FORWARD_NAIVE] = {"forward-naive", "00", "every object with every light", true, {false, false}},
    [RENDERER_FORWARD_PREPASS] = {"forward-prepass", "00", "depth pre-pass only", true, {true, false}},
    [RENDERER_FORWARD_LISTS] = {"forward-lists", "00", "per-object light lists only", true, {false, true}},
    [RENDERER_DEFERRED_FULLSCREEN] = {"deferred-fullscreen", "03", "one full-screen pass, all lights per pixel"},
    [RENDERER_DEFERRED_VOLUMES] = {"deferred-volumes", "07", "depth-tested back faces of one sphere per light"},
    [RENDERER_DEFERRED_VOLUMES_WINDOWED] = {"deferred-volumes-windowed", "07",
                                            "deferred-volumes with the windowed falloff: no cut-off step"},
    [RENDERER_DEFERRED_STENCIL] = {"deferred-stencil", "08",
                                   "per batch of lights, a stencil pass, then light where it is set"},
    [RENDERER_DEFERRED_TILED] = {"deferred-tiled", "10",
                                 "per-tile light lists, one pass reading the G-buffer once per pixel"},
    [RENDERER_FORWARD_PLUS] = {"forward-plus", "11",
                               "clustered forward: depth pre-pass, each fragment loops over its "
                               "cluster's lights", true, {true, false}},
    [RENDERER_DEFERRED_CLUSTERED] = {"deferred-clustered", "11",
                                     "per-cluster light lists, one pass reading the G-buffer once per pixel"},
};

/* chapters/07_face_culling.c's volume state: added up, back faces behind the surface. */
const gl_pass_state renderer_volume_pass = {
    .blend = {GL_ONE, GL_ONE},
    .cull = GL_FRONT,
    .depth_func = GL_GREATER,
    .depth_clamp = true,
};

/* chapters/08_stencil_volumes.c's two passes: count where the faces lie behind the surface, then
 * light where the count is not 0 and reset it. */
const gl_pass_state renderer_stencil_pass = {
    .depth_func = GL_LEQUAL,
    .depth_clamp = true,
    .stencil_func = GL_ALWAYS,
    .stencil_front = {GL_KEEP, GL_DECR_WRAP, GL_KEEP},
    .stencil_back = {GL_KEEP, GL_INCR_WRAP, GL_KEEP},
    .stencil_only = true,
};
const gl_pass_state renderer_stencil_light_pass = {
    .blend = {GL_ONE, GL_ONE},
    .cull = GL_FRONT,
    .depth_clamp = true,
    .stencil_func = GL_NOTEQUAL,
    .stencil_back = {GL_KEEP, GL_KEEP, GL_ZERO},
};

int renderer_find(const char *name)
{
    for (int i = 0; name && i < RENDERER_COUNT; i++)
        if (strcmp(renderer_table[i].name, name) == 0)
            return i;
    return -1;
}

void renderers_create(renderer_set *r) { memset(r, 0, sizeof *r); }

static void stencil_destroy(renderer_stencil *st)
{
    for (int i = 0; i < st->query_count; i++)
        gl_query_destroy(&st->queries[i]);
    free(st->queries);
    light_batches_destroy(&st->lb);
    gl_program_destroy(&st->program);
    deferred_volumes_destroy(&st->dv);
    gbuffer_destroy(&st->g);
}


void renderers_destroy(renderer_set *r)
{
    if (r->have_clusters)
        clusters_destroy(&r->clusters);
    if (r->have_tiled)
        tiled_destroy(&r->tiled);
    if (r->have_stencil)
        stencil_destroy(&r->stencil);
    if (r->have_volumes)
        deferred_volumes_destroy(&r->volumes);
    if (r->have_fullscreen)
        deferred_fullscreen_destroy(&r->fullscreen);
    if (r->have_gbuffer)
        gbuffer_destroy(&r->g);
    if (r->have_forward)
        forward_destroy(&r->fwd);
    memset(r, 0, sizeof *r);
}

/* The G-buffer at the view's size, made or remade as needed. */
static bool ensure_gbuffer(renderer_set *r, const gpu_scene *gs)
{
    int w = gs->view.width, h = gs->view.height;
    if (!r->have_gbuffer)
        return (r->have_gbuffer = gbuffer_create(&r->g, w, h));
    return (r->g.fbo.width == w && r->g.fbo.height == h) || gbuffer_resize(&r->g, w, h);
}

/* The stencil renderer at the view's size; its accumulation buffer also borrows g's stencil. */
static bool ensure_stencil(renderer_set *r, const gpu_scene *gs)
{
    renderer_stencil *st = &r->stencil;
    int w = gs->view.width, h = gs->view.height;
    if (r->have_stencil && st->g.fbo.width == w && st->g.fbo.height == h)
        return true;
    bool ok;
    if (!r->have_stencil) {
        memset(st, 0, sizeof *st);
        st->program = gl_program_load("light_volume.vert", "depth_only.frag", NULL);
        st->u_first = glGetUniformLocation(st->program, "u_first_instance");
        st->u_fullscreen = glGetUniformLocation(st->program, "u_fullscreen");
        ok = st->program && gbuffer_create_with(&st->g, w, h, &(gbuffer_desc){.stencil = true}) &&
             deferred_volumes_create(&st->dv, &st->g, GL_RGBA16F);
    } else {
        ok = gbuffer_resize(&st->g, w, h) && deferred_volumes_resize(&st->dv, &st->g);
    }
    if (ok)
        gbuffer_attach_stencil(&st->g, st->dv.accum.id);
    r->have_stencil = ok && gl_check("renderers: stencil");
    if (!r->have_stencil)
        stencil_destroy(st);
    return r->have_stencil;
}


static bool ensure(renderer_set *r, renderer_id id, const gpu_scene *gs)
{
    if (id == RENDERER_DEFERRED_STENCIL)
        return ensure_stencil(r, gs);
    if (id == RENDERER_DEFERRED_TILED)
        return ensure_tiled(r, gs);
    if (id == RENDERER_FORWARD_PLUS || id == RENDERER_DEFERRED_CLUSTERED) {
        /* Light assignment as chapter 11 makes it by default: by compute shaders where the context
         * has them (the same lists as the CPU's, chapters.11_assign_same_*), else on the CPU. */
        const clusters_desc lists = {.compute = renderer_have_compute()};
        if (!r->have_clusters && !(r->have_clusters = clusters_create(&r->clusters, &lists)))
            return false;
        if (id == RENDERER_FORWARD_PLUS) /* a scene with glass goes through forward's linear frame */
            return gs->transparent_count == 0 || r->have_forward || (r->have_forward = forward_create(&r->fwd));
        return ensure_gbuffer(r, gs);
    }
    if (renderer_table[id].forward)
        return r->have_forward || (r->have_forward = forward_create(&r->fwd));
    if (!ensure_gbuffer(r, gs))
        return false;
    if (id == RENDERER_DEFERRED_FULLSCREEN)
        return r->have_fullscreen || (r->have_fullscreen = deferred_fullscreen_create(&r->fullscreen, NULL));
    return r->have_volumes || (r->have_volumes = deferred_volumes_create(&r->volumes, &r->g, GL_RGBA16F));
}

static bool draw_forward(renderer_set *r, renderer_id id, const gpu_scene *gs, GLuint target,
                         renderer_draw_options o, renderer_result *res)
{
    forward_options fo = renderer_table[id].forward_options;
    fo.count_pixels = o.count_pixels;
    fo.linear_output = o.linear_output;
    bool ok = forward_render(&r->fwd, gs, target, fo);
    res->shaded = o.count_pixels ? forward_shaded_pixels(&r->fwd) : -1;
    res->lights_per_pixel = fo.light_lists && gs->src->object_count > 0
                                ? (double)r->fwd.list_entries / gs->src->object_count
                                : gs->light_count;
    return ok;
}

/* Instances [first, first + count) of the light list with the program in use. */
static void draw_lights(const renderer_stencil *st, GLint u_first, GLint u_fullscreen, int first, int count,
                        bool fullscreen)
{
    glUniform1i(u_first, first);
    glUniform1i(u_fullscreen, fullscreen);
    if (fullscreen) {
        glBindVertexArray(st->dv.lv.sphere.vao);
        glDrawArraysInstanced(GL_TRIANGLES, 0, 3, count);
    } else {
        mesh_draw_instanced(&st->dv.lv.sphere, count);
    }
}

static void light_draw(renderer_stencil *st, int *query, const gl_pass_state *pass, int first, int count,
                       bool fullscreen)
{
    glUseProgram(st->dv.lv.program);
    gl_pass_state_apply(pass);
    if (query)
        glBeginQuery(GL_SAMPLES_PASSED, st->queries[(*query)++]);
    draw_lights(st, st->dv.lv.u_first_instance, st->dv.lv.u_fullscreen, first, count, fullscreen);
    if (query)
        glEndQuery(GL_SAMPLES_PASSED);
}

static bool make_queries(renderer_stencil *st, int n)
{
    GLuint *q = n > st->query_count ? realloc(st->queries, (size_t)n * sizeof *q) : st->queries;
    if (!q)
        return false;
    for (st->queries = q; st->query_count < n; st->query_count++)
        q[st->query_count] = gl_query_create();
    return true;
}

/* Chapter 08's frame (chapters/08_stencil_volumes.c, draw_volumes): ambient, then per batch the
 * stencil pass and the lighting pass, the full-screen lights, present. */
static bool draw_stencil(renderer_stencil *st, const gpu_scene *gs, GLuint target, bool count, long *shaded)
{
    light_volumes *lv = &st->dv.lv;
    if (!gbuffer_render(&st->g, gs) || !light_volumes_sort(lv, gs) ||
        !light_batches_make(&st->lb, lv, gs, false) || (count && !make_queries(st, st->lb.count + 1)))
        return false;
    frame_timer_mark("lighting");
    glBindFramebuffer(GL_FRAMEBUFFER, st->dv.accum.id);
    glViewport(0, 0, st->dv.accum.width, st->dv.accum.height);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    light_volumes_draw_ambient(lv, &st->g, gs);
    light_volumes_bind(lv, &st->g, gs, LIGHT_VOLUMES_VIEW_LIT);
    glUseProgram(st->program);
    gpu_scene_bind_lights(gs, st->program, SHADER_UNIT_LIGHTS);
    glUniform1i(glGetUniformLocation(st->program, "u_light_index"), SHADER_UNIT_LIGHT_INDEX);
    glUniformMatrix4fv(glGetUniformLocation(st->program, "u_view_proj"), 1, GL_FALSE,
                       (const float *)gs->view.view_proj);
    glUniform1f(glGetUniformLocation(st->program, "u_mesh_scale"), lv->mesh_scale);
    int used = 0, *query = count ? &used : NULL;
    for (int b = 0; b < st->lb.count; b++) {
        const light_batch *batch = &st->lb.batches[b];
        glUseProgram(st->program);
        gl_pass_state_apply(&renderer_stencil_pass);
        draw_lights(st, st->u_first, st->u_fullscreen, batch->first, batch->count, false);
        light_draw(st, query, &renderer_stencil_light_pass, batch->first, batch->count, false);
    }
    if (gs->light_count > lv->finite_count)
        light_draw(st, query, &(gl_pass_state){.blend = {GL_ONE, GL_ONE}}, lv->finite_count,
                   gs->light_count - lv->finite_count, true);
    gl_pass_state_reset();
    *shaded = count ? 0 : -1;
    for (int i = 0; i < used; i++) {
        GLuint samples = 0;
        glGetQueryObjectuiv(st->queries[i], GL_QUERY_RESULT, &samples);
        *shaded += (long)samples;
    }
    deferred_volumes_present(&st->dv, target, &(deferred_volumes_frame){0});
    return gl_check("renderers: deferred-stencil");
}

static const gl_pass_state forward_plus_equal = {.cull = GL_BACK, .depth_func = GL_EQUAL};

/* Forward+ in linear radiance, then the glass over it with the same lists (chapter 12). */
static bool forward_plus_linear(void *user, const gpu_scene *gs)
{
    clusters *c = user;
    return clusters_shade_forward(c, gs, &forward_plus_equal, CLUSTERS_VIEW_LINEAR) &&
           clusters_shade_glass(c, gs, forward_glass_passes, 2, GPU_SCENE_BACK_TO_FRONT, CLUSTERS_VIEW_LINEAR);
}

/* Forward+'s shading after its pre-pass; a scene with glass blends it in linear radiance: straight
 * into a float target, else through forward's linear frame, as forward does. */
static bool shade_forward_plus(renderer_set *r, const gpu_scene *gs, clusters_view view)
{
    if (gs->transparent_count == 0)
        return clusters_shade_forward(&r->clusters, gs, &forward_plus_equal, view);
    if (view == CLUSTERS_VIEW_LINEAR)
        return forward_plus_linear(&r->clusters, gs);
    return forward_draw_linear(&r->fwd, gs, forward_plus_linear, &r->clusters);
}

/* chapters/11_clustered.c's two frames, with its pass states: Forward+ (pre-pass, then GL_EQUAL) or
 * clustered deferred (G-buffer, then one full-screen pass). */
static bool draw_clustered(renderer_set *r, renderer_id id, const gpu_scene *gs, GLuint target,
                           renderer_draw_options o, renderer_result *res)
{
    static const gl_pass_state prepass = {.cull = GL_BACK, .depth_func = GL_LEQUAL, .depth_write = true};
    static const gl_pass_state fullscreen = {0};
    clusters *c = &r->clusters;
    bool deferred = id == RENDERER_DEFERRED_CLUSTERED;
    clusters_view view = o.linear_output ? CLUSTERS_VIEW_LINEAR : CLUSTERS_VIEW_LIT;
    bool ok;
    if (deferred) {
        ok = gbuffer_render(&r->g, gs) && clusters_assign(c, gs);
        glBindFramebuffer(GL_FRAMEBUFFER, target);
        glViewport(0, 0, gs->view.width, gs->view.height);
        ok = ok && clusters_shade_deferred(c, &r->g, gs, &fullscreen, view);
    } else {
        glBindFramebuffer(GL_FRAMEBUFFER, target);
        glViewport(0, 0, gs->view.width, gs->view.height);
        gl_pass_state_apply(&prepass);
        glClearColor(0, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        frame_timer_mark("depth pre-pass");
        ok = clusters_draw_depth(c, gs) && clusters_assign(c, gs) && shade_forward_plus(r, gs, view);
    }
    gl_pass_state_reset();
    ok = ok && (!o.count_pixels || clusters_count(c, deferred ? &r->g : NULL, gs));
    res->shaded = o.count_pixels && ok ? c->covered : -1;
    res->lights_per_pixel = o.count_pixels && ok && c->covered > 0 ? (double)c->evaluations / (double)c->covered : 0.0;
    return ok;
}

bool renderers_draw(renderer_set *r, renderer_id id, const gpu_scene *gs, GLuint target,
                    renderer_draw_options o, renderer_result *result)
{
    renderer_result res = {-1, 1.0};
    bool ok = ensure(r, id, gs);
    if (ok && (id == RENDERER_FORWARD_PLUS || id == RENDERER_DEFERRED_CLUSTERED)) {
        ok = draw_clustered(r, id, gs, target, o, &res);
    } else if (ok && renderer_table[id].forward) {
        ok = draw_forward(r, id, gs, target, o, &res);
    } else if (ok && id == RENDERER_DEFERRED_STENCIL) {
        ok = draw_stencil(&r->stencil, gs, target, o.count_pixels, &res.shaded);
        r->accum = &r->stencil.dv.accum;
    } else if (ok && id == RENDERER_DEFERRED_TILED) {
        ok = draw_tiled(&r->tiled, gs, target, o.count_pixels, &res.shaded);
    } else if (ok && id == RENDERER_DEFERRED_FULLSCREEN) {
        const deferred_fullscreen_options fo = {.count_pixels = o.count_pixels};
        ok = gbuffer_render(&r->g, gs) && deferred_fullscreen_render(&r->fullscreen, &r->g, gs, target, fo);
        res.shaded = o.count_pixels ? deferred_fullscreen_shaded_pixels(&r->fullscreen) : -1;
        res.lights_per_pixel = gs->light_count;
    } else if (ok) {
        const deferred_volumes_frame f = {
            .volume_state = &renderer_volume_pass, .accum_format = GL_RGBA16F, .count_pixels = o.count_pixels};
        /* The windowed row draws the same frame with the other falloff: a copy of the view, the
         * lights and the buffers, shaded with that model (gpu_scene_bind_lights reads it). */
        gpu_scene shaded = *gs;
        if (id == RENDERER_DEFERRED_VOLUMES_WINDOWED)
            shaded.falloff = SHADER_FALLOFF_WINDOWED;
        ok = gbuffer_render(&r->g, &shaded) && deferred_volumes_render(&r->volumes, &r->g, &shaded, target, &f);
        r->accum = &r->volumes.accum;
        res.shaded = deferred_volumes_shaded_pixels(&r->volumes);
        res.lights_per_pixel = 1.0; /* one fragment per (pixel, light) */
    }
    if (result)
        *result = res;
    return ok;
}

const fbo *renderers_accum(const renderer_set *r) { return r->accum ? r->accum : &r->volumes.accum; }

bool renderer_have_compute(void)
{
    const char *hide = getenv("COURSE_NO_COMPUTE");
    return GLAD_GL_VERSION_4_3 && !(hide && *hide && strcmp(hide, "0") != 0);
}
