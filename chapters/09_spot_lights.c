/* 09_spot_lights.c - spot lights, each drawn as a CONE volume: a spot lights only the inside of a cone,
 * so the lighting pass draws a mesh around that cone (cut by the light's sphere) instead of the whole
 * sphere. Compare with chapter 07, which draws every light, spots too, as its sphere: the same
 * picture, and more lighting fragments.
 *
 * Taken over: the G-buffer pass (02), the volumes from 04 and 05, the accumulation buffer and the
 * present pass from 06 (common/render/deferred_volumes.c), chapter 07's pass state: back faces, GL_GREATER,
 * depth clamp. New here:
 *   the spot itself: shade_light() multiplies a light by smoothstep(cos(outer), cos(inner), dot(-l, D))
 *     (shaders/shading.glsl). A point light is a spot without a cone (cos(outer) = -1), so every
 *     renderer, forward included, shades both with one code path;
 *   the cone volume (common/render/light_volumes.c, placed by shaders/cone_volume.glsl): an apex at the light,
 *     a 12-sided pyramid whose faces touch the cone, a cap of 3 rings outside the sphere. Like the
 *     icosphere scaled by 1 / inradius it CONTAINS the shape it stands for (--scale none: it does not);
 *   the light list split in two (split_spots): the point lights' spheres in one instanced draw, the
 *     spots' cones in a second, both with volume_pass. A cone volume is convex, as a sphere is, so
 *     its back faces keep working with the camera inside it and across the near and far planes.
 * Options:
 *   --spot-volume sphere   draw the spots as chapter 07 does: the same picture, more shaded pixels
 *   --scale none           the cone without its two scales: its faces cut into the cone, light is lost
 * --view overdraw counts the lighting fragments per pixel; --view volumes draws every light's sphere
 * (as chapter 07 draws them) and each spot's cone inside its sphere. Read docs/09_spot_lights.md.
 */
#include "app.h"
#include "chapters.h"
#include "debug_views.h"
#include "deferred_volumes.h"
#include "gbuffer.h"
#include "gl_program.h"

#include <string.h>

static const char *const renderers[] = {"deferred", "forward", NULL};
static const char *const views[] = {"lit", "overdraw", "volumes", NULL};
static const char *const spot_volumes[] = {"cone", "sphere", NULL};
static const char *const scales[] = {"contain", "none", NULL};

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "09_spot_lights",
    .default_scene = "assets/scenes/spots.scene", /* the spots show the lesson; the others have none */
    .summary = "Chapter 09: spot lights, each drawn as a cone volume instead of its sphere.",
    .renderers = renderers,
    .views = views,
    .extras =
        {
            {"spot-volume", "MESH", "what a spot is drawn as: its cone, or its sphere (chapter 07)", spot_volumes,
             "cone"},
            {"scale", "MODE", "cone mesh scales: contain (the mesh contains the cone) or none (a bug)", scales,
             "contain"},
        },
};

/* Chapter 07's volume state, for the spheres and the cones alike: added up, back faces, kept only
 * where they lie behind the scene's surface, no far-plane clipping. */
static const gl_pass_state volume_pass = {
    .blend = {GL_ONE, GL_ONE},
    .cull = GL_FRONT,
    .depth_func = GL_GREATER,
    .depth_write = false,
    .depth_clamp = true,
};

/* Lights whose sphere holds the whole view: a full-screen triangle, no culling, no depth test. */
static const gl_pass_state fullscreen_pass = {.blend = {GL_ONE, GL_ONE}};

/* The volumes view's lines: both faces, hidden behind the scene, as common/render/debug_views.c draws them. */
static const gl_pass_state line_pass = {.depth_func = GL_LESS};

static struct {
    gbuffer g;
    deferred_volumes dv;     /* the spheres' program, the accumulation buffer, the present pass */
    debug_views views;       /* --view overdraw's heat map colours, --view volumes' spheres */
    light_volumes_cone cone; /* the cone template and the two scales that make it contain the cone */
    GLuint cone_program;     /* light_volume.vert + .frag with CONE_VOLUME */
    GLuint cone_line_program; /* volume_wire.vert + .frag with CONE_VOLUME, for --view volumes */
    int points, spots;       /* finite lights in the light list: the point lights, then the spots */
    bool spots_as_spheres;   /* --spot-volume sphere */
    bool unscaled;           /* --scale none */
} state;

static bool init(app *a)
{
    state.spots_as_spheres = strcmp(app_extra(a, "spot-volume"), "sphere") == 0;
    state.unscaled = strcmp(app_extra(a, "scale"), "none") == 0;
    a->pass_state = &volume_pass; /* the overlay shows it */
    state.cone_program = gl_program_load("light_volume.vert", "light_volume.frag", "CONE_VOLUME 1");
    state.cone_line_program = gl_program_load("volume_wire.vert", "volume_wire.frag", "CONE_VOLUME 1");
    return state.cone_program && state.cone_line_program && light_volumes_cone_create(&state.cone) &&
           gbuffer_create(&state.g, a->width, a->height) &&
           deferred_volumes_create(&state.dv, &state.g, GL_RGBA16F) && debug_views_create(&state.views);
}

static bool resize(app *a)
{
    return gbuffer_resize(&state.g, a->width, a->height) && deferred_volumes_resize(&state.dv, &state.g);
}

/* The finite lights (light_volumes_sort put them first) reordered: point lights, then spots, so
 * that each mesh is one instanced draw. The lights that hold the whole view stay at the end. */
static void split_spots(light_volumes *lv, const gpu_scene *gs)
{
    int points = 0;
    for (int i = 0; i < lv->finite_count; i++) {
        if (!state.spots_as_spheres && gpu_light_is_spot(&gs->lights[lv->indices[i]]))
            continue;
        int swap = lv->indices[points];
        lv->indices[points++] = lv->indices[i];
        lv->indices[i] = swap;
    }
    state.points = points;
    state.spots = lv->finite_count - points;
    int n = gs->light_count > 0 ? gs->light_count : 1; /* a texture buffer may not be empty */
    gl_texture_buffer_upload(lv->index_buffer, lv->index_texture, GL_R32I, lv->indices, (size_t)n * sizeof(int));
}

/* The cone programs read what light_volumes_bind gives the sphere program: the lights, the light
 * list from instance state.points on, the camera; and the cone's scales (1 with --scale none). */
static void bind_cone_program(GLuint p, const gpu_scene *gs)
{
    glUseProgram(p);
    gpu_scene_bind_lights(gs, p, SHADER_UNIT_LIGHTS);
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_LIGHT_INDEX);
    glBindTexture(GL_TEXTURE_BUFFER, state.dv.lv.index_texture);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(glGetUniformLocation(p, "u_light_index"), SHADER_UNIT_LIGHT_INDEX);
    glUniform1i(glGetUniformLocation(p, "u_first_instance"), state.points);
    glUniform1i(glGetUniformLocation(p, "u_fullscreen"), 0);
    glUniformMatrix4fv(glGetUniformLocation(p, "u_view_proj"), 1, GL_FALSE, (const float *)gs->view.view_proj);
    glUniform1f(glGetUniformLocation(p, "u_cone_side_scale"), state.unscaled ? 1.0f : state.cone.side_scale);
    glUniform1f(glGetUniformLocation(p, "u_cone_cap_scale"), state.unscaled ? 1.0f : state.cone.cap_scale);
}

/* 2. lighting: ambient, then a. the point lights' spheres, b. the spots' cones, c. the full-screen
 * lights, all added up in the accumulation buffer */
static bool draw_volumes(app *a, light_volumes_view view)
{
    light_volumes *lv = &state.dv.lv;
    const gpu_scene *gs = &a->gs;
    if (!deferred_volumes_resize(&state.dv, &state.g) || !light_volumes_sort(lv, gs))
        return false;
    split_spots(lv, gs);
    frame_timer_mark("lighting");
    glBindFramebuffer(GL_FRAMEBUFFER, state.dv.accum.id);
    glViewport(0, 0, state.dv.accum.width, state.dv.accum.height);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    if (view != LIGHT_VOLUMES_VIEW_OVERDRAW)
        light_volumes_draw_ambient(lv, &state.g, gs);
    gl_samples_begin(a->query, a->count_pixels);

    light_volumes_bind(lv, &state.g, gs, view);
    gl_pass_state_apply(&volume_pass);
    glUniform1i(lv->u_fullscreen, 0);
    glUniform1i(lv->u_first_instance, 0);
    if (state.points > 0)
        mesh_draw_instanced(&lv->sphere, state.points);

    bind_cone_program(state.cone_program, gs);
    gbuffer_bind_textures(&state.g, gs, state.cone_program, SHADER_UNIT_GBUFFER);
    glUniform1i(glGetUniformLocation(state.cone_program, "u_view"), (int)view);
    if (state.spots > 0)
        mesh_draw_instanced(&state.cone.mesh, state.spots);

    int fullscreen = gs->light_count - lv->finite_count;
    if (fullscreen > 0) {
        glUseProgram(lv->program);
        gl_pass_state_apply(&fullscreen_pass);
        glUniform1i(lv->u_fullscreen, 1);
        glUniform1i(lv->u_first_instance, lv->finite_count);
        glBindVertexArray(lv->sphere.vao);
        glDrawArraysInstanced(GL_TRIANGLES, 0, 3, fullscreen);
    }
    a->shaded_pixels = gl_samples_end(a->query, a->count_pixels);
    gl_pass_state_reset();
    return gl_check("09 lighting");
}

/* The volumes view's cones, as lines over the spheres debug_views_draw_volumes left in `target`. */
static bool draw_cone_lines(const gpu_scene *gs)
{
    if (state.spots == 0)
        return true;
    bind_cone_program(state.cone_line_program, gs);
    glUniform1f(glGetUniformLocation(state.cone_line_program, "u_fixed_radius"), 0.0f);
    gl_pass_state_apply(&line_pass);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    mesh_draw_instanced(&state.cone.mesh, state.spots);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    gl_pass_state_reset();
    return gl_check("09 cone lines");
}

static bool frame(app *a)
{
    if (!app_renderer_is(a, "deferred"))
        return app_render_forward(a);

    /* 1. geometry pass: also the depth the volumes are tested against */
    if (!gbuffer_render(&state.g, &a->gs))
        return false;

    /* 2. lighting pass, spheres and cones; 3. present */
    const deferred_volumes_frame f = {
        .view = app_view_is(a, "overdraw") ? LIGHT_VOLUMES_VIEW_OVERDRAW : LIGHT_VOLUMES_VIEW_LIT,
    };
    if (!draw_volumes(a, f.view))
        return false;
    deferred_volumes_present(&state.dv, a->target.id, &f);
    /* the volumes view: every light's sphere (what chapter 07 draws), and each spot's cone inside it */
    return !app_view_is(a, "volumes") ||
           (debug_views_draw_volumes(&state.views, &state.g, &a->gs, a->target.id, NULL) &&
            draw_cone_lines(&a->gs));
}

static void cleanup(app *a)
{
    (void)a;
    gl_program_destroy(&state.cone_program);
    gl_program_destroy(&state.cone_line_program);
    light_volumes_cone_destroy(&state.cone);
    debug_views_destroy(&state.views);
    deferred_volumes_destroy(&state.dv);
    gbuffer_destroy(&state.g);
    memset(&state, 0, sizeof state); /* opened again (the benchmark does), init starts from nothing */
}

const app_desc chapter_09 = {.cli = &cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup};

CHAPTER_MAIN(chapter_09)
