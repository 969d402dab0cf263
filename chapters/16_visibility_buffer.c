/* 16_visibility_buffer.c - the visibility buffer (Burns and Hunt 2013): the geometry pass writes no
 * surface at all, only WHICH triangle each pixel sees, one 32-bit id, and depth. The shading pass
 * reads the id, fetches that triangle's three vertices, rebuilds where the pixel's ray meets it and
 * shades. Compare with chapter 11, whose G-buffer pass this chapter replaces (12 bytes + depth a
 * pixel for chapter 02's compact layout, here 4 + depth) and whose cluster lists it shades with.
 *
 * Taken over: chapter 11's cluster lists and clustered shading (chapter_11_assign, clusters.glsl's
 * cluster_shade: shade_light() for every light of the pixel's cluster), forward.vert's instanced
 * draws and its invariant position (00), the full-screen pass (03).
 * New here, three passes:
 *   1. visibility pass (visibility.frag): every opaque object once into ONE R32UI target and the
 *      picture's own depth (a->target's texture, shared): id = (object + 1) << 20 | triangle, the
 *      triangle's index in its mesh (gl_PrimitiveID); 0 is the background. 8 bytes a pixel.
 *      Limits, checked when the scene is loaded (exit 2 beyond them): 4,095 objects, 2^20 =
 *      1,048,576 triangles per mesh (SHADER_VIS_TRIANGLE_BITS, common/base/shader_layout.h)
 *   2. light assignment: chapter 11's, unchanged
 *   3. shading (visibility_shade.frag): one full-screen pass; each pixel fetches its triangle's
 *      vertices (vis_meshes.c: every mesh's buffers copied into texture buffers), intersects its ray
 *      with the triangle for the barycentrics, interpolates position and normal, and loops over its
 *      cluster's lights
 * --samples N (MSAA; compare with chapter 13, whose forward MSAA it matches): the ids and their own
 * depth hold N samples a pixel (4 + 4 bytes a sample, the picture's depth is not written); the
 * shading pass runs twice, "shading" for the pixels whose samples hold one id (once, as above),
 * "shading edges" for the others (each sample's triangle shaded where forward MSAA shades it, the
 * samples averaged in linear radiance before the display encoding).
 * Views: lit; ids, a colour per id (hashed). Glass (chapter 12) is not drawn: the ids hold one
 * surface a sample.
 * --vis-pass MODE times what the visibility pass is made of, with pictures that are not the chapter's:
 * no-primitive-id writes triangle 0 instead of gl_PrimitiveID (visibility.frag built with
 * VIS_NO_PRIMITIVE_ID), depth-only the same program with no colour drawn (the ids stay the background).
 * --shadows N (chapter 14's atlas, chapters.h; off by default): the shading pass, built with SHADOWS,
 * multiplies each light by how much of it reaches the rebuilt surface; forward and Forward+ read the
 * same atlas. Key K turns them off and on.
 * Read docs/16_visibility_buffer.md alongside.
 */
#include "app.h"
#include "chapters.h"
#include "clusters.h"
#include "frame_timer.h"
#include "gl_program.h"
#include "gl_util.h"
#include "log.h"
#include "vis_meshes.h"

#include <stdio.h>
#include <string.h>

#define VIS_MAX_SAMPLES 32

static const char *const renderers[] = {"deferred", "forward", NULL};
static const char *const views[] = {"lit", "ids", NULL};
static const char *const vis_passes[] = {"full", "no-primitive-id", "depth-only", NULL};
enum { VIS_FULL, VIS_NO_PRIMITIVE_ID, VIS_DEPTH_ONLY }; /* --vis-pass, in vis_passes' order */

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "16_visibility_buffer",
    .summary = "Chapter 16: the visibility buffer: a triangle id per pixel, then one full-screen pass that "
               "fetches the triangle, rebuilds the surface and shades with chapter 11's cluster lists.",
    .renderers = renderers,
    .views = views,
    .extras = {{"samples", "N", "ids per sample: N samples per pixel, edge pixels shaded per sample (1: no MSAA)",
                NULL, "1", CLI_POWER_OF_TWO, 1, VIS_MAX_SAMPLES},
               {"vis-pass", "MODE", "the visibility pass: full (the chapter's); timing only, wrong pictures: "
                "no-primitive-id (triangle 0, gl_PrimitiveID not read), depth-only (no id written either: "
                "the background)", vis_passes, "full"},
               CHAPTER_14_SHADOW_OPTIONS("K")},
};

/* 1. visibility pass: chapter 00's pre-pass state (GL_LEQUAL: on a tie the object drawn last wins). */
static const gl_pass_state visibility_pass = {.cull = GL_BACK, .depth_func = GL_LEQUAL, .depth_write = true};
/* 3. shading: every pixel written once; no blending, no depth test. */
static const gl_pass_state shading_pass = {.depth_write = false};

/* The id's two fields: the object + 1 above, the triangle below (0 stays the background). */
#define VIS_MAX_TRIANGLES (1L << SHADER_VIS_TRIANGLE_BITS)
#define VIS_MAX_OBJECTS ((1L << (32 - SHADER_VIS_TRIANGLE_BITS)) - 1)

enum { VIS_PASS_PIXELS, VIS_PASS_EDGES }; /* visibility_shade.frag's u_pass (MSAA only) */

static struct {
    int samples, vis_pass;
    fbo ids; /* R32UI ids; depth: a->target's (MSAA: its own, multisampled) */
    vis_meshes meshes;
    clusters c;
    shadow_atlas atlas; /* --shadows N: chapter 14's; nothing made without it */
    GLuint visibility_program;
    gl_program_variants shading; /* with chapter 14's SHADOWS while a light is shadowed, and without */
    char defines[32];            /* the shading pass's: VIS_SAMPLES with MSAA */
    gl_program_extra shadows;    /* --shadows N: the atlas's define and inputs (none without) */
    const gl_program_extra *extra; /* this frame's: shadows, or none (shadow_atlas_programs) */
    GLuint map_samplers[2]; /* the material images read trilinear, without anisotropy (see make_samplers) */
} state;

/* Before init: a scene whose ids would not fit the 32 bits is refused, with the limit it breaks (the
 * forward renderers have no ids). */
static bool accepts_scene(const app *a)
{
    const gpu_scene *gs = &a->gs;
    if (!app_renderer_is(a, "deferred"))
        return true;
    if (gs->src->object_count > VIS_MAX_OBJECTS) {
        log_error("%s: %d objects; the visibility buffer's ids hold at most %ld (%d bits of object)", gs->src->path,
                  gs->src->object_count, VIS_MAX_OBJECTS, 32 - SHADER_VIS_TRIANGLE_BITS);
        return false;
    }
    for (int m = 0; m < gs->src->mesh_count; m++)
        if (gs->meshes[m].index_count / 3 > VIS_MAX_TRIANGLES) {
            log_error("%s: mesh '%s' has %d triangles; the visibility buffer's ids hold at most %ld a mesh "
                      "(%d bits of triangle)",
                      gs->src->path, gs->src->meshes[m].name, gs->meshes[m].index_count / 3, VIS_MAX_TRIANGLES,
                      SHADER_VIS_TRIANGLE_BITS);
            return false;
        }
    return true;
}

/* The shading pass reads the material images with textureGrad, the derivatives rebuilt from the
 * triangle. llvmpipe (Mesa 22.3) ignores those derivatives on a texture filtered anisotropically, so
 * the pass reads through sampler objects of its own: the arrays' trilinear filtering without the
 * anisotropy (docs/16_visibility_buffer.md, "Textures"). Forward matches it with --anisotropy 1. */
/* The shading program for this frame's shadows (each variant built once, on first use). */
static GLuint shading_program(void)
{
    return gl_program_variant(&state.shading, "fullscreen.vert", "visibility_shade.frag",
                              state.samples > 1 ? state.defines : NULL, state.extra);
}

static void make_samplers(void)
{
    glGenSamplers(2, state.map_samplers);
    gl_live_objects_add(2);
    for (int i = 0; i < 2; i++) {
        glSamplerParameteri(state.map_samplers[i], GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glSamplerParameteri(state.map_samplers[i], GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glSamplerParameteri(state.map_samplers[i], GL_TEXTURE_WRAP_S, GL_REPEAT);
        glSamplerParameteri(state.map_samplers[i], GL_TEXTURE_WRAP_T, GL_REPEAT);
    }
}

static void bind_samplers(bool on)
{
    glBindSampler(SHADER_UNIT_MAPS_SRGB, on ? state.map_samplers[0] : 0);
    glBindSampler(SHADER_UNIT_MAPS_LINEAR, on ? state.map_samplers[1] : 0);
}

static bool init(app *a)
{
    a->pass_state = &shading_pass; /* the overlay shows it */
    double n = 1;
    if (!app_extra_number(a, "samples", 1, VIS_MAX_SAMPLES, &n) ||
        !fbo_samples_supported((int)n, VIS_MAX_SAMPLES, "16_visibility_buffer: bad --samples"))
        return !(a->input_error = true);
    state.samples = (int)n;
    snprintf(state.defines, sizeof state.defines, "VIS_SAMPLES %d", state.samples);
    /* --shadows N: the shading pass and forward read chapter 14's atlas (none: no define, no input) */
    if (!chapter_14_shadows_create(a, &state.atlas, &state.shadows))
        return false;
    state.extra = &state.shadows;
    app_forward_set_extra(&a->forward, &state.shadows);
    const clusters_desc lists = {.compute = gl_have_compute(), .extra = state.shadows}; /* chapter 11's default */
    state.vis_pass = cli_choice_index(vis_passes, app_extra(a, "vis-pass"));
    if (state.vis_pass != VIS_FULL)
        log_warn("16_visibility_buffer: --vis-pass %s: the picture is not the chapter's, timing only",
                 vis_passes[state.vis_pass]);
    state.visibility_program = gl_program_load("forward.vert", "visibility.frag",
                                               state.vis_pass != VIS_FULL ? "VIS_NO_PRIMITIVE_ID 1" : NULL);
    make_samplers();
    return state.visibility_program && shading_program() && vis_meshes_create(&state.meshes, &a->gs) &&
           clusters_create(&state.c, &lists);
}

/* The id target on the picture's depth texture (MSAA: on its own): made when missing, remade when
 * either changed. */
static bool targets_follow(const app *a)
{
    const fbo *t = &a->target;
    const bool msaa = state.samples > 1;
    if (state.ids.id && (msaa || state.ids.depth == t->depth) && state.ids.width == t->width &&
        state.ids.height == t->height)
        return true;
    fbo_destroy(&state.ids);
    const fbo_desc ids = {.color_formats = {GL_R32UI}, .color_count = 1, .depth_format = GL_DEPTH_COMPONENT32F,
                          .shared_depth = msaa ? 0 : t->depth, .samples = state.samples, .name = "visibility buffer"};
    return fbo_create(&state.ids, &ids, t->width, t->height);
}

static bool resize(app *a) { return targets_follow(a); }

/* 1. visibility pass: every opaque object once; an id and a depth per pixel, nothing else. */
static bool draw_visibility(const gpu_scene *gs)
{
    static const GLuint background[4] = {0, 0, 0, 0};
    frame_timer_mark("visibility pass");
    glBindFramebuffer(GL_FRAMEBUFFER, state.ids.id);
    glViewport(0, 0, state.ids.width, state.ids.height);
    gl_pass_state_apply(&visibility_pass);
    glClearBufferuiv(GL_COLOR, 0, background); /* an integer target: glClearColor does not apply */
    glClear(GL_DEPTH_BUFFER_BIT);
    if (state.vis_pass == VIS_DEPTH_ONLY)
        glDrawBuffer(GL_NONE); /* after the clear: the ids stay the background */
    glUseProgram(state.visibility_program);
    gpu_scene_bind_objects(gs, state.visibility_program, SHADER_UNIT_OBJECTS);
    gpu_scene_draw(gs, state.visibility_program);
    if (state.vis_pass == VIS_DEPTH_ONLY)
        glDrawBuffer(GL_COLOR_ATTACHMENT0);
    gl_pass_state_reset();
    return gl_check("16 visibility pass");
}

/* 3. shading: per pixel, its triangle rebuilt from the id and its cluster's lights; the background
 * is the clear colour (the shader discards it). MSAA: the pixels of one id, then the edges. */
static bool shade(app *a)
{
    const GLuint p = shading_program();
    const gpu_scene *gs = &a->gs;
    if (!p)
        return false;
    frame_timer_mark("shading");
    glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
    glViewport(0, 0, a->width, a->height);
    gl_pass_state_apply(&shading_pass);
    glClearColor(0, 0, 0, 1); /* forward's background */
    glClear(GL_COLOR_BUFFER_BIT);
    clusters_use(&state.c, gs, p, a->linear_output ? CLUSTERS_VIEW_LINEAR : CLUSTERS_VIEW_LIT);
    gpu_scene_bind_objects(gs, p, SHADER_UNIT_OBJECTS);
    vis_meshes_bind(&state.meshes, p, SHADER_UNIT_VIS_MESHES);
    bind_samplers(true);
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_GBUFFER);
    glBindTexture(state.samples > 1 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D, state.ids.color[0]);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(glGetUniformLocation(p, "u_ids"), SHADER_UNIT_GBUFFER);
    glUniformMatrix4fv(glGetUniformLocation(p, "u_inv_view_proj"), 1, GL_FALSE, (const float *)gs->view.inv_view_proj);
    glUniform2f(glGetUniformLocation(p, "u_viewport_size"), (float)a->width, (float)a->height);
    glUniform1i(glGetUniformLocation(p, "u_show_ids"), app_view_is(a, "ids"));
    glUniform1i(glGetUniformLocation(p, "u_pass"), VIS_PASS_PIXELS);
    gl_samples_begin(a->query, a->count_pixels);
    gl_draw_fullscreen();
    if (state.samples > 1) {
        frame_timer_mark("shading edges");
        glUniform1i(glGetUniformLocation(p, "u_pass"), VIS_PASS_EDGES);
        gl_draw_fullscreen();
    }
    a->shaded_pixels = gl_samples_end(a->query, a->count_pixels);
    bind_samplers(false);
    gl_pass_state_reset();
    return gl_check("16 shading");
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
    a->pass_state = &shading_pass;
    a->work_name = "shading pass pixels";
    if (!targets_follow(a) || !draw_visibility(&a->gs) || !chapter_11_assign(&state.c, &a->gs) || !shade(a))
        return false;
    a->linear_written = a->linear_output;
    return true;
}

/* K: shadows on / off (with --shadows N). */
static bool key(app *a, int k)
{
    (void)a;
    return k == 'K' && chapter_14_shadows_key(&state.atlas);
}

static void cleanup(app *a)
{
    (void)a;
    clusters_destroy(&state.c);
    shadow_atlas_destroy(&state.atlas);
    if (state.map_samplers[0]) {
        glDeleteSamplers(2, state.map_samplers);
        gl_live_objects_add(-2);
        memset(state.map_samplers, 0, sizeof state.map_samplers);
    }
    vis_meshes_destroy(&state.meshes);
    fbo_destroy(&state.ids);
    gl_program_variants_destroy(&state.shading);
    gl_program_destroy(&state.visibility_program);
    memset(&state, 0, sizeof state); /* opened again (the benchmark does), init starts from nothing */
}

const app_desc chapter_16 = {.cli = &cli, .accepts_scene = accepts_scene, .init = init, .resize = resize,
                             .frame = frame, .cleanup = cleanup, .key = key};

CHAPTER_MAIN(chapter_16)
