/* renderers.c - see renderers.h. */
#include "renderers.h"

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
};

/* chapters/07_face_culling.c's volume state: added up, back faces behind the surface. */
const gl_pass_state renderer_volume_pass = {
    .blend = {GL_ONE, GL_ONE},
    .cull = GL_FRONT,
    .depth_func = GL_GREATER,
    .depth_clamp = true,
};

int renderer_find(const char *name)
{
    for (int i = 0; name && i < RENDERER_COUNT; i++)
        if (strcmp(renderer_table[i].name, name) == 0)
            return i;
    return -1;
}

void renderers_create(renderer_set *r) { memset(r, 0, sizeof *r); }

void renderers_destroy(renderer_set *r)
{
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

static bool ensure(renderer_set *r, renderer_id id, const gpu_scene *gs)
{
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

bool renderers_draw(renderer_set *r, renderer_id id, const gpu_scene *gs, GLuint target,
                    renderer_draw_options o, renderer_result *result)
{
    renderer_result res = {-1, 1.0};
    bool ok = ensure(r, id, gs);
    if (ok && renderer_table[id].forward) {
        ok = draw_forward(r, id, gs, target, o, &res);
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
        res.shaded = deferred_volumes_shaded_pixels(&r->volumes);
        res.lights_per_pixel = 1.0; /* one fragment per (pixel, light) */
    }
    if (result)
        *result = res;
    return ok;
}

const fbo *renderers_accum(const renderer_set *r) { return &r->volumes.accum; }
