/* 13_msaa.c - deferred shading with multisampling: a multisampled G-buffer, the pixels whose samples
 * hold more than one surface found from those samples and shaded per sample, all others once, and
 * the samples averaged in linear radiance before the display encoding. Compare with chapter 11, whose
 * clustered deferred pass this chapter keeps (the same cluster lists, the same shading function), and
 * with forward MSAA at the same sample count, which this chapter draws too (--renderer forward).
 * The cost: every G-buffer target holds N samples per pixel, N times the memory and the bandwidth
 * (--bench prints the bytes). Opaque objects only: chapter 12's glass is left out. Deferred:
 *   1. geometry pass into the multisampled G-buffer (gbuffer_desc.samples): without sample shading
 *      gbuffer.frag runs once per pixel per primitive, at the pixel centre, and writes its values to
 *      the samples that primitive covers; each sample gets its own depth
 *   2. light assignment: chapter 11's clusters
 *   3. edges: a full-screen pass that keeps the pixels whose samples differ (albedo, normal/material,
 *      background or not; compared exactly) and marks them in the stencil
 *   4. lighting, stencil 0: each pixel shaded once, at its centre (the mean of its sample depths)
 *   5. lighting edges, stencil 1: each sample shaded at its own position, the mean written: the
 *      resolve, in linear radiance, into a float target
 *   6. present: that picture display-encoded once (accum_present.frag)
 * Forward (and Forward+) draw into a multisampled float target of the same sample count, which the
 * resolve pass averages the same way; the same present pass follows. --view edges: edge pixels in
 * magenta; --bench adds an 'msaa:' line (the multisampled targets' bytes, the edge pixels).
 * Read docs/13_msaa.md alongside.
 */
#include "app.h"
#include "chapters.h"
#include "clusters.h"
#include "forward.h"
#include "gbuffer.h"
#include "gl_program.h"
#include "log.h"

#include <stdio.h>
#include <string.h>

#define MSAA_MAX_SAMPLES 32

static const char *const renderers[] = {"deferred", "forward", "forward-plus", NULL};
static const char *const views[] = {"lit", "edges", NULL};

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "13_msaa",
    .summary = "Chapter 13: deferred shading with MSAA: per-sample shading on edges, against forward MSAA.",
    .renderers = renderers,
    .views = views,
    .extras = {{"samples", "N",
                "samples per pixel, every renderer (1: no multisampling; at most what the context offers)",
                NULL, "4", CLI_POWER_OF_TWO, 1, MSAA_MAX_SAMPLES}},
};

enum { PASS_EDGES, PASS_PIXEL, PASS_SAMPLES }; /* msaa_deferred.frag's u_pass */

/* The stencil sorts the pixels: the edge pass writes 1 where it keeps a fragment, then the pixel pass
 * runs where the stencil is 0 and the sample pass where it is not. No depth test, no blending. */
#define STENCIL_INCR {GL_KEEP, GL_KEEP, GL_INCR}
static const gl_pass_state edge_pass = {
    .stencil_func = GL_ALWAYS, .stencil_front = STENCIL_INCR, .stencil_back = STENCIL_INCR, .stencil_only = true};
static const gl_pass_state pixel_pass = {.stencil_func = GL_EQUAL};
static const gl_pass_state sample_pass = {.stencil_func = GL_NOTEQUAL};
/* Forward+: chapter 11's pre-pass and GL_EQUAL shading, per sample. */
static const gl_pass_state prepass = {.cull = GL_BACK, .depth_func = GL_LEQUAL, .depth_write = true};
static const gl_pass_state shade_after_prepass = {.cull = GL_BACK, .depth_func = GL_EQUAL};

static struct {
    int samples;
    float offsets[2 * MSAA_MAX_SAMPLES], mean[2]; /* sample positions in the pixel, and their mean */
    gbuffer g;
    clusters c;
    forward fwd;
    fbo msaa; /* forward's frame: RGBA16F + depth, multisampled */
    fbo lit;  /* the resolved linear picture (RGBA16F) + the edge stencil */
    GLuint edge_program, shade_program, resolve_program, edge_query;
    present_pass present; /* chapter 06's present pass */
    long edge_pixels;
} state;

static bool make_targets(app *a)
{
    fbo_destroy(&state.msaa);
    fbo_destroy(&state.lit);
    const fbo_desc msaa = {.color_formats = {GL_RGBA16F}, .color_count = 1, .depth_format = GL_DEPTH_COMPONENT32F,
                           .samples = state.samples, .name = "forward msaa"};
    const fbo_desc lit = {.color_formats = {GL_RGBA16F}, .color_count = 1, .depth_format = GL_DEPTH24_STENCIL8,
                          .name = "resolved"};
    return fbo_create(&state.msaa, &msaa, a->width, a->height) && fbo_create(&state.lit, &lit, a->width, a->height);
}

/* The driver may round a sample count up: read what it made, and where its samples lie. */
static bool read_samples(app *a)
{
    GLint made = 1;
    if (state.samples > 1) {
        glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, state.g.fbo.color[0]);
        glGetTexLevelParameteriv(GL_TEXTURE_2D_MULTISAMPLE, 0, GL_TEXTURE_SAMPLES, &made);
        glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
    }
    if (made != state.samples) {
        log_error("13_msaa: bad --samples '%d': the driver made %d samples per pixel; ask for %d", state.samples, made,
                  made);
        return !(a->input_error = true);
    }
    state.mean[0] = state.mean[1] = 0.5f, state.offsets[0] = state.offsets[1] = 0.5f;
    if (state.samples > 1) {
        state.mean[0] = state.mean[1] = 0.0f;
        glBindFramebuffer(GL_FRAMEBUFFER, state.g.fbo.id);
        for (int s = 0; s < state.samples; s++) {
            glGetMultisamplefv(GL_SAMPLE_POSITION, (GLuint)s, &state.offsets[2 * s]);
            state.mean[0] += state.offsets[2 * s] / (float)state.samples;
            state.mean[1] += state.offsets[2 * s + 1] / (float)state.samples;
        }
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    /* They, and the edges view's colour, are the same every frame: set once, in both programs. */
    const GLuint programs[] = {state.shade_program, state.edge_program};
    for (int i = 0; i < 2 && programs[i]; i++) {
        glUseProgram(programs[i]);
        glUniform2fv(glGetUniformLocation(programs[i], "u_sample_offsets"), state.samples, state.offsets);
        glUniform2fv(glGetUniformLocation(programs[i], "u_mean_offset"), 1, state.mean);
        glUniform4f(glGetUniformLocation(programs[i], "u_edge_colour"), 1.0f, 0.0f, 1.0f, 1.0f);
    }
    return gl_check("13 sample positions");
}

static bool init(app *a)
{
    double n = 4;
    /* The parser took a power of two up to MSAA_MAX_SAMPLES; the context's own limit is known now. */
    if (!app_extra_number(a, "samples", 1, MSAA_MAX_SAMPLES, &n) ||
        !fbo_samples_supported((int)n, MSAA_MAX_SAMPLES, "13_msaa: bad --samples"))
        return !(a->input_error = true);
    state.samples = (int)n;
    char defines[96];
    snprintf(defines, sizeof defines, "MSAA_SAMPLES %d%s", state.samples,
             state.samples > 1 ? "\nGBUFFER_MULTISAMPLE 1\nMSAA_MULTISAMPLE 1" : "");
    state.shade_program = gl_program_load("fullscreen.vert", "msaa_deferred.frag", defines);
    if (state.samples > 1) { /* the edge pass's own program: a shader that may discard runs before the
                                stencil test, so the lighting passes' program must not hold it */
        char edge_defines[128];
        snprintf(edge_defines, sizeof edge_defines, "%s\nMSAA_EDGES 1", defines);
        state.edge_program = gl_program_load("fullscreen.vert", "msaa_deferred.frag", edge_defines);
    }
    state.resolve_program = gl_program_load("fullscreen.vert", "msaa_resolve.frag", defines);
    state.edge_query = gl_query_create();
    a->pass_state = &pixel_pass; /* the overlay shows it */
    const clusters_desc lists = {.compute = gl_have_compute()}; /* chapter 11's default */
    return state.shade_program && (state.samples == 1 || state.edge_program) && state.resolve_program &&
           present_pass_create(&state.present) &&
           gbuffer_create_with(&state.g, a->width, a->height, &(gbuffer_desc){.samples = state.samples}) &&
           read_samples(a) && clusters_create(&state.c, &lists) && forward_create(&state.fwd) && make_targets(a);
}

static bool resize(app *a)
{
    return gbuffer_resize(&state.g, a->width, a->height) && make_targets(a);
}

/* One of msaa_deferred.frag's passes over the whole screen, with the G-buffer and the cluster lists. */
static void draw_shade_pass(const app *a, int pass, const gl_pass_state *s)
{
    const GLuint p = pass == PASS_EDGES ? state.edge_program : state.shade_program;
    gl_pass_state_apply(s);
    glUseProgram(p);
    gpu_scene_bind_lights(&a->gs, p, SHADER_UNIT_LIGHTS);
    gbuffer_bind_textures(&state.g, &a->gs, p, SHADER_UNIT_GBUFFER);
    clusters_bind(&state.c, p, SHADER_UNIT_LIGHT_INDEX); /* and the unit after it */
    glUniform1i(glGetUniformLocation(p, "u_pass"), pass);
    glUniform1i(glGetUniformLocation(p, "u_show_edges"), app_view_is(a, "edges"));
    gl_draw_fullscreen();
}

/* Deferred: 1. geometry; 2. clusters; 3. edges; 4. pixels; 5. edge samples, averaged (the resolve). */
static bool frame_deferred(app *a)
{
    if (!gbuffer_render(&state.g, &a->gs) || !chapter_11_assign(&state.c, &a->gs))
        return false;
    glBindFramebuffer(GL_FRAMEBUFFER, state.lit.id);
    glViewport(0, 0, a->width, a->height);
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    state.edge_pixels = 0;
    if (state.samples > 1) {
        frame_timer_mark("edges");
        draw_shade_pass(a, PASS_EDGES, &edge_pass);
    }
    frame_timer_mark("lighting");
    draw_shade_pass(a, PASS_PIXEL, &pixel_pass);
    if (state.samples > 1) {
        frame_timer_mark("lighting edges");
        gl_samples_begin(state.edge_query, true);
        draw_shade_pass(a, PASS_SAMPLES, &sample_pass);
        state.edge_pixels = gl_samples_end(state.edge_query, true);
    }
    gl_pass_state_reset();
    return gl_check("13 deferred lighting");
}

/* Forward (plus: Forward+) into the multisampled target, in linear radiance; then the resolve. Its
 * passes are timed under their own names, except as compare mode's left side (`timed` false). */
static bool frame_forward(app *a, bool plus, bool timed)
{
    bool ok;
    if (!plus) {
        const bool count = a->count_pixels && timed;
        const forward_options o = {.prepass = true, .light_lists = true, .count_pixels = count, .linear_output = true};
        ok = forward_render(&state.fwd, &a->gs, state.msaa.id, o);
        if (timed)
            a->shaded_pixels = count ? forward_shaded_pixels(&state.fwd) : -1;
    } else {
        glBindFramebuffer(GL_FRAMEBUFFER, state.msaa.id);
        glViewport(0, 0, a->width, a->height);
        gl_pass_state_apply(&prepass);
        glClearColor(0, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        frame_timer_mark("depth pre-pass");
        ok = clusters_draw_depth(&state.c, &a->gs) && chapter_11_assign(&state.c, &a->gs) &&
             chapter_11_shade_forward(&state.c, &a->gs, &shade_after_prepass, CLUSTERS_VIEW_LINEAR);
        gl_pass_state_reset();
    }
    if (!ok)
        return false;
    if (timed)
        frame_timer_mark("resolve");
    glBindFramebuffer(GL_FRAMEBUFFER, state.lit.id);
    glViewport(0, 0, a->width, a->height);
    glUseProgram(state.resolve_program);
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_IMAGE);
    glBindTexture(state.samples > 1 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D, state.msaa.color[0]);
    glUniform1i(glGetUniformLocation(state.resolve_program, "u_image"), SHADER_UNIT_IMAGE);
    gl_draw_fullscreen();
    return gl_check("13 resolve");
}

/* 6. present: the resolved linear picture display-encoded once, into `target`. */
static bool present(app *a, GLuint target, bool timed)
{
    if (timed)
        frame_timer_mark("present");
    present_pass_draw(&state.present, state.lit.color[0], target, a->width, a->height, NULL);
    return gl_check("13 present");
}

static bool frame(app *a)
{
    bool deferred = app_renderer_is(a, "deferred");
    a->pass_state = deferred ? &pixel_pass : &shade_after_prepass;
    a->shaded_pixels = -1;
    return (deferred ? frame_deferred(a) : frame_forward(a, app_renderer_is(a, "forward-plus"), true)) &&
           present(a, a->target.id, true);
}

/* Compare mode's left side (key M): forward MSAA at the same sample count, as --renderer forward draws
 * it, so that the split and the difference set like against like. */
static bool draw_forward(app *a, GLuint target)
{
    return frame_forward(a, false, false) && present(a, target, false);
}

/* --bench: what multisampling costs in memory, and how much of the picture is edges. */
static void print_report(const app *a)
{
    const bool deferred = app_renderer_is(a, "deferred");
    const int per_sample = deferred ? gbuffer_pixel_bytes(&state.g) : 12; /* RGBA16F + D32F; RT2 counted */
    const double bytes = deferred ? gbuffer_memory_bytes(&state.g) : (double)per_sample * state.samples * a->width * a->height;
    printf("msaa: renderer=%s samples=%d bytes_per_sample=%d bytes_per_pixel=%d msaa_mib=%.2f edge_pixels=%ld "
           "edge_fraction=%.5f\n",
           deferred ? "deferred" : renderers[a->renderer], state.samples, per_sample, per_sample * state.samples,
           bytes / (1024.0 * 1024.0), deferred ? state.edge_pixels : -1L,
           deferred ? (double)state.edge_pixels / ((double)a->width * a->height) : -1.0);
    fflush(stdout);
}

static void cleanup(app *a)
{
    if (a->options->bench && state.shade_program)
        print_report(a);
    gl_query_destroy(&state.edge_query);
    gl_program_destroy(&state.edge_program);
    gl_program_destroy(&state.shade_program);
    gl_program_destroy(&state.resolve_program);
    present_pass_destroy(&state.present);
    fbo_destroy(&state.msaa);
    fbo_destroy(&state.lit);
    forward_destroy(&state.fwd);
    clusters_destroy(&state.c);
    gbuffer_destroy(&state.g);
    memset(&state, 0, sizeof state); /* opened again (the benchmark does), init starts from nothing */
}

const app_desc chapter_13 = {.cli = &cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup, .draw_forward = draw_forward};

CHAPTER_MAIN(chapter_13)
