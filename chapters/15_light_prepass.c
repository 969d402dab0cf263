/* 15_light_prepass.c - deferred lighting, the light pre-pass (Engel 2008): the lights meet the
 * surface BEFORE its material. A thin first geometry pass writes only what the lights need (normal,
 * shininess, depth); the lights are added up per pixel into a light buffer; a second geometry pass
 * draws every object again and combines that buffer with the object's own albedo and specular
 * strength, straight from its material. Compare with chapter 11, whose clustered deferred pass this
 * chapter splits in two around the material, and with chapter 02's G-buffer, which the thin pass
 * replaces.
 *
 * Taken over: chapter 11's cluster lists (chapter_11_assign: the same grid, the same lists), the
 * compact G-buffer's RT1 encoding (octahedral normal in 2 x 12 bits, shininess in 8: its packing is
 * shaders/gbuffer_encode.glsl), the depth pre-pass's GL_EQUAL and its shared vertex shader (00).
 * New here, four passes:
 *   1. thin pass (light_prepass_thin.frag): normal + shininess into ONE RGBA8 target, depth into the
 *      picture's own depth buffer (a->target's texture, shared): 8 bytes a pixel, no albedo
 *   2. light assignment: chapter 11's, unchanged
 *   3. light accumulation (light_prepass_accum.frag): one full-screen pass; each pixel loops over its
 *      cluster's lights and sums shade_light()'s two terms apart, before the material
 *      (shade_light_terms in shaders/shading.glsl): diffuse D = sum f E (n.l), specular
 *      S = sum f E (n.h)^s, written once into RGBA16F (no blending)
 *   4. second geometry pass (light_prepass_combine.frag): every object again, GL_EQUAL against the
 *      thin pass's depth, so one fragment per pixel: ambient + albedo * D + specular * S
 * --specular mono|rgb: how the light buffer holds S.
 *   rgb   two RGBA16F targets (D and S): 16 bytes a pixel, chapter 00's picture
 *   mono  Engel's layout, one target: D in RGB, S's luminance in A (8 bytes); the combine pass
 *         rebuilds S as D's colour scaled to that luminance. Exact for one light (its S and D have
 *         the same colour); where lights of different colours overlap, a highlight takes the colour
 *         of the mixed diffuse light instead of its own light's.
 * Metallic-roughness materials (LIGHT_PREPASS_PBR, for a scene that has any): Schlick's Fresnel is
 *   linear in F0, so three sums that know no material make pbr_brdf exact in the second pass: the thin
 *   target becomes RGBA16F (half-float octahedral normal after the normal map, -1 - roughness after the
 *   metal-rough map; Blinn-Phong's shininess stays positive), the light buffer three RGBA16F targets
 *   (C, A, B); rgb only. 12 + 24 bytes a pixel.
 * Views: lit; light, the diffuse light buffer D (pbr: C); specular, S as the combine pass reads it
 *   back (pbr: A + B).
 * --shadows N (chapter 14's atlas, chapters.h; off by default): the accumulation pass, built with
 *   SHADOWS, multiplies each light's two terms by how much of it reaches the pixel; forward and
 *   Forward+ read the same atlas. Key K turns them off and on.
 * --bench's shaded_pixels: the second geometry pass's fragments (GL_SAMPLES_PASSED).
 * Read docs/15_light_prepass.md alongside.
 */
#include "app.h"
#include "chapters.h"
#include "clusters.h"
#include "frame_timer.h"
#include "gl_program.h"
#include "gl_util.h"
#include "log.h"

#include <string.h>

static const char *const renderers[] = {"deferred", "forward", NULL};
static const char *const views[] = {"lit", "light", "specular", NULL};
static const char *const speculars[] = {"rgb", "mono", NULL};

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "15_light_prepass",
    .summary = "Chapter 15: deferred lighting (light pre-pass): a thin pass, the lights summed into a light "
               "buffer, a second geometry pass with each object's material.",
    .renderers = renderers,
    .views = views,
    .extras =
        {
            {"specular", "CHANNELS",
             "the light buffer's specular: rgb (two targets, forward's picture) or mono (one channel: "
             "highlights take the diffuse light's colour)",
             speculars, "rgb"},
            CHAPTER_14_SHADOW_OPTIONS("K"),
        },
};

/* 1. thin pass: chapter 00's pre-pass state (GL_LEQUAL: on a tie the object drawn last wins). */
static const gl_pass_state thin_pass = {.cull = GL_BACK, .depth_func = GL_LEQUAL, .depth_write = true};
/* 3. light accumulation: every pixel written once; no blending, no depth test. */
static const gl_pass_state accumulation_pass = {.depth_write = false};
/* 4. second geometry pass: only the fragment the thin pass kept; depth read, never written. */
static const gl_pass_state combine_pass = {.cull = GL_BACK, .depth_func = GL_EQUAL};

static struct {
    fbo thin;  /* RGBA8 normal + shininess (pbr: RGBA16F); depth: a->target's */
    fbo light; /* RGBA16F diffuse (+ specular luminance); rgb: and RGBA16F specular; pbr: and B */
    clusters c;
    shadow_atlas atlas; /* --shadows N: chapter 14's; nothing made without it */
    GLuint thin_program, combine_program;
    gl_program_variants accumulation; /* with chapter 14's SHADOWS while a light is shadowed, and without */
    const char *defines;              /* the light buffer's: LIGHT_PREPASS_PBR on a metallic-roughness scene */
    gl_program_extra shadows;         /* --shadows N: the atlas's define and inputs (none without) */
    const gl_program_extra *extra;    /* this frame's: shadows, or none (shadow_atlas_programs) */
    bool rgb; /* --specular rgb */
    bool pbr; /* the scene has metallic-roughness materials: LIGHT_PREPASS_PBR's buffers and shaders */
} state;

static bool scene_has_pbr(const app *a)
{
    for (int m = 0; m < a->gs.src->material_count; m++)
        if (a->gs.src->materials[m].pbr)
            return true;
    return false;
}

/* The accumulation program for this frame's shadows (each variant built once, on first use). */
static GLuint accumulation_program(void)
{
    return gl_program_variant(&state.accumulation, "fullscreen.vert", "light_prepass_accum.frag", state.defines,
                              state.extra);
}

static bool init(app *a)
{
    state.pbr = scene_has_pbr(a);
    state.rgb = state.pbr || strcmp(app_extra(a, "specular"), "rgb") == 0; /* mono: refused for deferred */
    const char *defines = state.defines = state.pbr ? "LIGHT_PREPASS_PBR 1" : NULL;
    if (state.pbr)
        log_info("metallic-roughness scene: thin pass RGBA16F + depth, 12 bytes a pixel; light buffer "
                 "C, A, B in three RGBA16F, 24 bytes a pixel");
    a->pass_state = &combine_pass; /* the overlay shows it */
    a->work_name = "second geometry pass fragments";
    /* --shadows N: the accumulation pass and forward read chapter 14's atlas (none: no define, no input) */
    if (!chapter_14_shadows_create(a, &state.atlas, &state.shadows))
        return false;
    app_forward_set_extra(&a->forward, &state.shadows);
    /* chapter 11's lists, made where it makes them by default; clusters_use binds the atlas */
    const clusters_desc lists = {.compute = gl_have_compute(), .extra = state.shadows};
    state.extra = &state.shadows;
    state.thin_program = gl_program_load("forward.vert", "light_prepass_thin.frag", defines);
    state.combine_program = gl_program_load("forward.vert", "light_prepass_combine.frag", defines);
    return state.thin_program && accumulation_program() && state.combine_program && clusters_create(&state.c, &lists);
}

/* The thin target on the picture's depth texture, and the light buffer, at the picture's size: made
 * when missing, remade when the picture's depth, its size or --specular changed. */
static bool targets_follow(const app *a)
{
    const fbo *t = &a->target;
    if (!state.thin.id || state.thin.depth != t->depth || state.thin.width != t->width ||
        state.thin.height != t->height) {
        fbo_destroy(&state.thin);
        const fbo_desc thin = {.color_formats = {state.pbr ? GL_RGBA16F : GL_RGBA8}, .color_count = 1,
                               .depth_format = GL_DEPTH_COMPONENT32F, .shared_depth = t->depth,
                               .name = "thin pass"};
        if (!fbo_create(&state.thin, &thin, t->width, t->height))
            return false;
    }
    const int targets = state.pbr ? 3 : state.rgb ? 2 : 1;
    if (state.light.id && state.light.color_count == targets && state.light.width == t->width &&
        state.light.height == t->height)
        return true;
    fbo_destroy(&state.light);
    const fbo_desc light = {.color_formats = {GL_RGBA16F, GL_RGBA16F, GL_RGBA16F}, .color_count = targets,
                            .name = "light buffer"};
    return fbo_create(&state.light, &light, t->width, t->height);
}

static bool resize(app *a) { return targets_follow(a); }

static void bind_texture(GLuint program, const char *name, int unit, GLuint texture)
{
    glActiveTexture(GL_TEXTURE0 + (GLenum)unit);
    glBindTexture(GL_TEXTURE_2D, texture);
    glUniform1i(glGetUniformLocation(program, name), unit);
    glActiveTexture(GL_TEXTURE0);
}

/* 1. thin pass: every opaque object once, normal + shininess and depth; nothing else. */
static bool draw_thin(const gpu_scene *gs)
{
    frame_timer_mark("thin pass");
    glBindFramebuffer(GL_FRAMEBUFFER, state.thin.id);
    glViewport(0, 0, state.thin.width, state.thin.height);
    gl_pass_state_apply(&thin_pass);
    glClearColor(0, 0, 0, 0); /* zero normal, depth 1: the background */
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(state.thin_program);
    gpu_scene_bind_objects(gs, state.thin_program, SHADER_UNIT_OBJECTS);
    gpu_scene_draw(gs, state.thin_program);
    gl_pass_state_reset();
    return gl_check("15 thin pass");
}

/* 3. light accumulation: per pixel, its cluster's lights' diffuse and specular sums, once. */
static bool accumulate_lights(const gpu_scene *gs)
{
    const GLuint p = accumulation_program();
    if (!p)
        return false;
    frame_timer_mark("light accumulation");
    glBindFramebuffer(GL_FRAMEBUFFER, state.light.id);
    glViewport(0, 0, state.light.width, state.light.height);
    gl_pass_state_apply(&accumulation_pass);
    clusters_use(&state.c, gs, p, CLUSTERS_VIEW_LIT); /* lights, lists, eye */
    bind_texture(p, "u_thin_normal", SHADER_UNIT_GBUFFER, state.thin.color[0]);
    bind_texture(p, "u_thin_depth", SHADER_UNIT_GBUFFER + 1, state.thin.depth);
    glUniformMatrix4fv(glGetUniformLocation(p, "u_inv_view_proj"), 1, GL_FALSE, (const float *)gs->view.inv_view_proj);
    glUniform2f(glGetUniformLocation(p, "u_viewport_size"), (float)state.light.width, (float)state.light.height);
    gl_draw_fullscreen();
    gl_pass_state_reset();
    return gl_check("15 light accumulation");
}

static int view_of(const app *a)
{
    return app_view_is(a, "light") ? 1 : app_view_is(a, "specular") ? 2 : 0; /* the combine shader's VIEW_* */
}

/* 4. second geometry pass: every object again into the picture, on the thin pass's depth; each
 * visible fragment meets the light buffer with its own material. */
static bool combine(app *a)
{
    const GLuint p = state.combine_program;
    frame_timer_mark("second geometry pass");
    glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
    glViewport(0, 0, a->width, a->height);
    gl_pass_state_apply(&combine_pass);
    glClearColor(0, 0, 0, 1); /* forward's background; the depth is the thin pass's */
    glClear(GL_COLOR_BUFFER_BIT);
    glUseProgram(p);
    gpu_scene_bind_lights(&a->gs, p, SHADER_UNIT_LIGHTS); /* the ambient term */
    gpu_scene_bind_objects(&a->gs, p, SHADER_UNIT_OBJECTS);
    bind_texture(p, "u_light_diffuse", SHADER_UNIT_GBUFFER, state.light.color[0]);
    bind_texture(p, "u_light_specular", SHADER_UNIT_GBUFFER + 1, state.rgb ? state.light.color[1] : 0);
    if (state.pbr)
        bind_texture(p, "u_light_fresnel", SHADER_UNIT_GBUFFER + 2, state.light.color[2]);
    glUniform1i(glGetUniformLocation(p, "u_specular_rgb"), state.rgb);
    glUniform1i(glGetUniformLocation(p, "u_view"), view_of(a));
    glUniform1i(glGetUniformLocation(p, "u_output_linear"), a->linear_output);
    gl_samples_begin(a->query, a->count_pixels);
    gpu_scene_draw(&a->gs, p);
    a->shaded_pixels = gl_samples_end(a->query, a->count_pixels);
    gl_pass_state_reset();
    return gl_check("15 second geometry pass");
}

static bool frame(app *a)
{
    if (!chapter_14_shadows_update(&state.atlas, &a->gs)) /* --shadows N: before anything shades */
        return false;
    /* shadows that are off cost nothing: the programs without them */
    state.extra = shadow_atlas_programs(&state.atlas, &state.shadows, NULL);
    clusters_set_extra(&state.c, state.extra);
    app_forward_set_extra(&a->forward, state.extra);
    if (!app_renderer_is(a, "deferred"))
        return app_render_forward(a);
    a->pass_state = &combine_pass;
    if (!targets_follow(a) || !draw_thin(&a->gs) || !chapter_11_assign(&state.c, &a->gs) ||
        !accumulate_lights(&a->gs) || !combine(a))
        return false;
    a->linear_written = a->linear_output;
    return true;
}

/* B: the light buffer's specular in one channel or three; the targets follow on the next frame.
 * K: shadows on / off (with --shadows N). */
static bool key(app *a, int k)
{
    (void)a;
    if (k == 'K')
        return chapter_14_shadows_key(&state.atlas);
    if (k != 'B')
        return false;
    if (state.pbr) {
        log_info("light buffer specular: rgb (a metallic-roughness scene needs all three sums)");
        return true;
    }
    state.rgb = !state.rgb;
    log_info("light buffer specular: %s", state.rgb ? "rgb (two targets)" : "mono (one channel)");
    return true;
}

static void cleanup(app *a)
{
    (void)a;
    clusters_destroy(&state.c);
    shadow_atlas_destroy(&state.atlas);
    fbo_destroy(&state.light);
    fbo_destroy(&state.thin);
    gl_program_destroy(&state.combine_program);
    gl_program_variants_destroy(&state.accumulation);
    gl_program_destroy(&state.thin_program);
    memset(&state, 0, sizeof state); /* opened again (the benchmark does), init starts from nothing */
}

/* A metallic-roughness highlight needs its specular sums A and B in colour (docs/15_light_prepass.md):
 * the one-channel light buffer has no room for them, so --specular mono refuses such a scene. */
static bool accepts_scene(const app *a)
{
    if (!app_renderer_is(a, "deferred") || strcmp(app_extra(a, "specular"), "mono") != 0 || !scene_has_pbr(a))
        return true;
    log_error("%s: --specular mono cannot hold a metallic-roughness highlight (its two specular sums are "
              "colours): use --specular rgb",
              a->gs.src->path);
    return false;
}

const app_desc chapter_15 = {.cli = &cli, .accepts_scene = accepts_scene, .init = init, .resize = resize,
                             .frame = frame, .cleanup = cleanup, .key = key};

CHAPTER_MAIN(chapter_15)
