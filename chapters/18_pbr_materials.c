/* 18_pbr_materials.c - metallic-roughness materials with textures (after Karis 2013, "Real Shading in
 * Unreal Engine 4"): the same lights, now reflected by GGX microfacets with Smith's visibility and
 * Schlick's Fresnel, the surfaces' colour, roughness, metalness, small-scale normal and ambient
 * occlusion read from images. Compare with chapter 11, whose clustered deferred frame this is.
 *
 * Taken over: chapter 11's light lists and shading pass (chapter_11_assign, chapter_11_shade_deferred),
 * chapter 06's present pass. Everything a material needs is in common/, because every renderer shades
 * it: the BRDF in shaders/shading.glsl (chosen per material: a negative shininess marks a
 * metallic-roughness one), the images in shaders/material_maps.glsl (read where the surface is first
 * known: forward.frag, forward_plus.frag, gbuffer.frag) from two texture arrays (common/gl/gpu_textures.c),
 * the tangents in common/scene/mesh_tangents.c.
 * New here:
 *   1. the G-buffer for PBR: the `reference` layout, 16 bytes a pixel with its depth (the runner picks
 *      it for a scene with metallic-roughness materials): RT0 base colour (sRGB) + occlusion, RT1 the
 *      octahedral normal in two half floats, metallic, and -1 - roughness, whose sign marks the material
 *   2. the lighting summed in linear radiance, then presented with an exposure (keys - and +), the
 *      forward renderers' too (R, and compare mode's left side)
 *   3. the channel views: what the geometry pass stored, one channel at a time (keys 1 to 8, --view);
 *      the emissive is RT2, a third target the G-buffer has only for a scene with emissive materials
 *   4. keys that change the light: the ambient (T, Y), and every light moved together (I J K L,
 *      Up, Down), so a highlight can be walked across a surface
 * --shadows N (chapter 14's atlas, chapters.h; off by default): chapter 11's shading pass and the
 * forward renderers built with SHADOWS, each light's GGX term times how much of it reaches the
 * point; key N turns them off and on (K is taken: it moves the lights nearer).
 * Read docs/18_pbr_materials.md alongside.
 */
#include "app.h"
#include "chapters.h"
#include "clusters.h"
#include "gbuffer.h"
#include "gl_program.h"
#include "gl_util.h"
#include "log.h"
#include "present_pass.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const char *const renderers[] = {"deferred", "forward", NULL};
/* lit, then the G-buffer's channels: their index is pbr_channels.frag's u_channel. */
static const char *const views[] = {"lit",    "albedo", "metallic", "roughness", "normal",
                                    "occlusion", "depth", "emissive", NULL};

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "18_pbr_materials",
    .summary = "Chapter 18: textured metallic-roughness materials (GGX, Smith, Schlick) through chapter 11's "
               "clustered deferred frame, with the G-buffer's channels on keys 1 to 8.",
    .renderers = renderers,
    .views = views,
    .default_scene = "assets/scenes/pbr_teapots.scene", /* textured: the lesson needs images */
    .extras =
        {
            {"exposure", "E", "multiply the linear picture by E before display (keys - and +)", NULL, "1", CLI_REAL,
             1.0 / 64.0, 64.0},
            {"ambient", "K", "multiply the scene's ambient light by K (keys T and Y)", NULL, "1", CLI_REAL, 0.0, 64.0},
            CHAPTER_14_SHADOW_OPTIONS("N"),
        },
};

/* The lighting pass writes every pixel once (chapter 11's); the present pass too. */
static const gl_pass_state deferred_pass = {.depth_write = false};
static const float LIGHT_STEP = 0.25f; /* scene units per press of I J K L, Up, Down */

static struct {
    gbuffer g;
    clusters c;
    shadow_atlas atlas; /* --shadows N: chapter 14's; nothing made without it */
    gl_program_extra shadows; /* its SHADOWS define and inputs (none without it) */
    fbo linear;      /* RGBA32F: the lighting pass's linear radiance, before the exposure */
    fbo forward_linear; /* RGBA32F + depth: the forward renderers' linear radiance, the same way */
    present_pass present;
    GLuint channels_program;
    float exposure;
    float ambient_scale;
    vec3 ambient;    /* the scene's own, which ambient_scale multiplies */
    vec3 moved;      /* how far the lights have been moved, for the log line */
} state;

static void apply_ambient(app *a)
{
    glm_vec3_scale(state.ambient, state.ambient_scale, a->scene.ambient);
}

static bool init(app *a)
{
    double exposure, ambient;
    if (!app_extra_number(a, "exposure", 1.0 / 64.0, 64.0, &exposure) ||
        !app_extra_number(a, "ambient", 0.0, 64.0, &ambient))
        return false;
    state.exposure = (float)exposure, state.ambient_scale = (float)ambient;
    glm_vec3_copy(a->scene.ambient, state.ambient);
    apply_ambient(a);
    /* --shadows N: chapter 11's shading pass and forward read chapter 14's atlas (none: no define) */
    if (!chapter_14_shadows_create(a, &state.atlas, &state.shadows))
        return false;
    app_forward_set_extra(&a->forward, &state.shadows);
    const clusters_desc lists = {.compute = gl_have_compute(), .extra = state.shadows};
    a->pass_state = &deferred_pass; /* the overlay shows it */
    state.channels_program = gl_program_load("fullscreen.vert", "pbr_channels.frag", NULL);
    return state.channels_program && gbuffer_create(&state.g, a->width, a->height) &&
           clusters_create(&state.c, &lists) && present_pass_create(&state.present);
}

static bool resize(app *a) { return gbuffer_resize(&state.g, a->width, a->height); }

/* f made, or made again, as d at the picture's size. */
static bool fit_target(fbo *f, const fbo_desc *d, const app *a)
{
    if (f->id && f->width == a->width && f->height == a->height)
        return true;
    fbo_destroy(f);
    return fbo_create(f, d, a->width, a->height);
}

/* 4. present: linear radiance times the exposure (1: the picture chapter 11 and forward draw),
 * display-encoded into `target` */
static bool present(app *a, GLuint linear, GLuint target)
{
    frame_timer_mark("present");
    gl_pass_state_apply(&deferred_pass);
    const present_pass_options options = {.tonemap = SHADER_TONEMAP_EXPOSURE, .exposure = state.exposure};
    present_pass_draw(&state.present, linear, target, a->width, a->height, &options);
    gl_pass_state_reset();
    return gl_check("18 present");
}

/* The forward renderers (R, and compare mode's left side) at the same exposure: their linear
 * radiance, then the same present pass, so that every picture of the chapter answers - and +. */
static bool draw_forward_exposed(app *a, const char *renderer, GLuint target, app_forward_work *work)
{
    const fbo_desc d = {.color_formats = {GL_RGBA32F}, .color_count = 1, .depth_format = GL_DEPTH_COMPONENT32F,
                        .name = "forward linear radiance"};
    const app_forward_options o = {.count_pixels = a->options->bench && work, .linear_output = true};
    return fit_target(&state.forward_linear, &d, a) &&
           app_forward_draw(&a->forward, renderer, &a->gs, state.forward_linear.id, o, work) &&
           present(a, state.forward_linear.color[0], target);
}

static bool draw_forward_compared(app *a, GLuint target) { return draw_forward_exposed(a, "forward", target, NULL); }

/* R: forward or Forward+, at the exposure; an embedding caller's linear radiance has none, and at
 * exposure 1 the present pass would change nothing: forward draws the picture itself, as in chapter 11. */
static bool frame_forward(app *a)
{
    if (a->linear_output || state.exposure == 1.0f)
        return app_render_forward(a);
    app_forward_work work = {.shaded = -1, .lights_per_pixel = 1.0};
    bool ok = draw_forward_exposed(a, a->cli->renderers[a->renderer], a->target.id, &work);
    a->shaded_pixels = work.shaded, a->lights_per_pixel = work.lights_per_pixel;
    a->view_drawn = "lit"; /* forward has no G-buffer channel to show */
    return ok;
}

/* The overlay's lines: the G-buffer (when this frame drew one), then the exposure and the ambient. */
static void write_overlay(app *a, bool drew_gbuffer)
{
    int n = 0;
    if (drew_gbuffer)
        n = snprintf(a->overlay_lines, sizeof a->overlay_lines, "G-buffer %s: %d bytes a pixel%s\n",
                     gbuffer_layout_name(state.g.desc.layout), gbuffer_pixel_bytes(&state.g),
                     state.g.desc.emissive ? ", with RT2 (emissive)" : "");
    snprintf(a->overlay_lines + n, sizeof a->overlay_lines - (size_t)n,
             "exposure %g (keys - and +), ambient x %g (keys T and Y)", state.exposure, state.ambient_scale);
}

/* 2. the views other than lit: one channel of the G-buffer, straight into the picture. */
static bool draw_channel(app *a)
{
    glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
    glViewport(0, 0, a->width, a->height);
    gl_pass_state_apply(&deferred_pass);
    GLuint p = state.channels_program;
    glUseProgram(p);
    gbuffer_bind_textures(&state.g, &a->gs, p, SHADER_UNIT_GBUFFER);
    glUniform1i(glGetUniformLocation(p, "u_channel"), a->view);
    glUniform2f(glGetUniformLocation(p, "u_near_far"), a->gs.view.near_plane, a->gs.view.far_plane);
    gl_draw_fullscreen();
    gl_pass_state_reset();
    return gl_check("18 channel view");
}

static bool frame(app *a)
{
    bool deferred = app_renderer_is(a, "deferred");
    write_overlay(a, deferred);
    if (!chapter_14_shadows_update(&state.atlas, &a->gs)) /* --shadows N: before anything shades */
        return false;
    /* shadows that are off cost nothing: the programs without them */
    const gl_program_extra *extra = shadow_atlas_programs(&state.atlas, &state.shadows, NULL);
    clusters_set_extra(&state.c, extra);
    app_forward_set_extra(&a->forward, extra);
    if (!deferred)
        return frame_forward(a);

    /* 1. geometry pass: the materials' images applied, the surface stored (the reference layout) */
    if (!gbuffer_render(&state.g, &a->gs))
        return false;
    if (app_view_is(a, "emissive") && !state.g.desc.emissive)
        a->note = "this scene has no emissive material, so the G-buffer has no RT2: the emissive view is black";
    if (!app_view_is(a, "lit"))
        return draw_channel(a);

    /* 2. light assignment and 3. the lighting pass (chapter 11's, unchanged); at exposure 1 straight
     * into the picture, display-encoded, as chapter 11 draws it (the present pass would only copy it) */
    if (state.exposure == 1.0f && !a->linear_output) {
        glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
        glViewport(0, 0, a->width, a->height);
        bool ok = chapter_11_assign(&state.c, &a->gs) &&
                  chapter_11_shade_deferred(&state.c, &state.g, &a->gs, &deferred_pass, CLUSTERS_VIEW_LIT);
        gl_pass_state_reset();
        return ok;
    }
    const fbo_desc linear = {.color_formats = {GL_RGBA32F}, .color_count = 1, .name = "linear radiance"};
    if (!fit_target(&state.linear, &linear, a) || !chapter_11_assign(&state.c, &a->gs))
        return false;
    glBindFramebuffer(GL_FRAMEBUFFER, state.linear.id);
    glViewport(0, 0, a->width, a->height);
    if (!chapter_11_shade_deferred(&state.c, &state.g, &a->gs, &deferred_pass, CLUSTERS_VIEW_LINEAR))
        return false;
    gl_pass_state_reset();
    a->linear = &state.linear;
    return present(a, state.linear.color[0], a->target.id);
}

/* Every light, and each of its keys, moved by d: the whole rig at once. */
static void move_lights(app *a, float dx, float dy, float dz)
{
    vec3 d = {dx, dy, dz};
    for (int i = 0; i < a->scene.light_count; i++) {
        scene_light *l = &a->scene.lights[i];
        glm_vec3_add(l->position, d, l->position);
        for (int k = 0; k < l->key_count; k++)
            glm_vec3_add(l->keys[k].position, d, l->keys[k].position);
    }
    glm_vec3_add(state.moved, d, state.moved);
    log_info("lights moved by %.2f %.2f %.2f from where the scene put them", state.moved[0], state.moved[1],
             state.moved[2]);
}

static bool key(app *a, int k)
{
    if (k >= '1' && k <= '8') { /* the views by number: 1 lit, 2 albedo ... 7 depth, 8 emissive */
        a->view = k - '1';
        log_info("view: %s", views[a->view]);
        return true;
    }
    switch (k) {
    case '-':
    case '=':
        state.exposure = glm_clamp(k == '=' ? state.exposure * 2.0f : state.exposure * 0.5f, 1.0f / 64.0f, 64.0f);
        log_info("exposure %g", state.exposure);
        return true;
    case 'T':
    case 'Y':
        state.ambient_scale = fminf(k == 'Y' ? fmaxf(state.ambient_scale * 2.0f, 0.125f) : state.ambient_scale * 0.5f,
                                    64.0f);
        apply_ambient(a);
        log_info("ambient x %g: %.3f %.3f %.3f", state.ambient_scale, a->scene.ambient[0], a->scene.ambient[1],
                 a->scene.ambient[2]);
        return true;
    case 'I': move_lights(a, 0, 0, -LIGHT_STEP); return true;
    case 'K': move_lights(a, 0, 0, LIGHT_STEP); return true;
    case 'J': move_lights(a, -LIGHT_STEP, 0, 0); return true;
    case 'L': move_lights(a, LIGHT_STEP, 0, 0); return true;
    case KEY_UP: move_lights(a, 0, LIGHT_STEP, 0); return true;
    case KEY_DOWN: move_lights(a, 0, -LIGHT_STEP, 0); return true;
    case 'N': return chapter_14_shadows_key(&state.atlas); /* chapter 14's K, which moves lights here */
    default: return false;
    }
}

static void cleanup(app *a)
{
    (void)a;
    present_pass_destroy(&state.present);
    fbo_destroy(&state.linear);
    fbo_destroy(&state.forward_linear);
    clusters_destroy(&state.c);
    gbuffer_destroy(&state.g);
    shadow_atlas_destroy(&state.atlas);
    gl_program_destroy(&state.channels_program);
    memset(&state, 0, sizeof state); /* opened again (the benchmark does), init starts from nothing */
}

const app_desc chapter_18 = {.cli = &cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup,
                             .key = key, .draw_forward = draw_forward_compared};

CHAPTER_MAIN(chapter_18)
