/* gbuffer.c - see gbuffer.h. */
#include "gbuffer.h"

#include "frame_timer.h"
#include "gl_program.h"
#include "gl_util.h"
#include "log.h"
#include "mat4d.h"

#include <stdio.h>
#include <string.h>

/* What each loses is measured by tests/unit/test_octahedral.c (normals) and the benchmark's
 * G-buffer sweep (positions, pictures); docs/02_mrt_gbuffer.md has the numbers. The names are
 * gbuffer_layout_names[] (GL-free, for the command line). */
const gbuffer_layout gbuffer_layouts[GBUFFER_LAYOUT_COUNT] = {
    [GBUFFER_LAYOUT_REFERENCE] = {GL_SRGB8_ALPHA8, GL_RGBA16F, SHADER_GBUFFER_NORMAL_HALF, GBUFFER_DEPTH_D32F,
                                  "normal <= 0.040 deg (half floats); S, P half floats"},
    [GBUFFER_LAYOUT_COMPACT] = {GL_SRGB8_ALPHA8, GL_RGBA8, SHADER_GBUFFER_NORMAL_PACKED, GBUFFER_DEPTH_D32F,
                                "normal <= 0.040 deg (2x12 bits); S to 1/255; P integer"},
    [GBUFFER_LAYOUT_COMPACT_D24S8] = {GL_SRGB8_ALPHA8, GL_RGBA8, SHADER_GBUFFER_NORMAL_PACKED,
                                      GBUFFER_DEPTH_D24S8, "as compact, depth in 24-bit fixed point"},
    [GBUFFER_LAYOUT_REVERSED_Z] = {GL_SRGB8_ALPHA8, GL_RGBA8, SHADER_GBUFFER_NORMAL_PACKED,
                                   GBUFFER_DEPTH_D32F_REVERSED,
                                   "as compact; relative depth error even over distance"},
    [GBUFFER_LAYOUT_LINEAR_ALBEDO] = {GL_RGBA8, GL_RGBA8, SHADER_GBUFFER_NORMAL_PACKED, GBUFFER_DEPTH_D32F,
                                      "as compact, albedo in linear 1/255 steps (coarse in the dark)"},
    [GBUFFER_LAYOUT_OCT8] = {GL_SRGB8_ALPHA8, GL_RGBA8, SHADER_GBUFFER_NORMAL_BYTES, GBUFFER_DEPTH_D32F,
                             "as compact, normal <= 0.64 deg (2x8 bits)"},
    [GBUFFER_LAYOUT_OCT16] = {GL_SRGB8_ALPHA8, GL_RGBA16, SHADER_GBUFFER_NORMAL_SHORTS, GBUFFER_DEPTH_D32F,
                              "as compact, normal <= 0.0025 deg (2x16 bits)"},
};

static const gbuffer_layout *default_layout = &gbuffer_layouts[GBUFFER_LAYOUT_DEFAULT];
static bool default_emissive;

/* ---- layouts ----------------------------------------------------------------------------------- */

const char *gbuffer_layout_name(const gbuffer_layout *layout) { return gbuffer_layout_names[layout - gbuffer_layouts]; }

const gbuffer_layout *gbuffer_layout_find(const char *name)
{
    for (int i = 0; name && i < GBUFFER_LAYOUT_COUNT; i++)
        if (strcmp(gbuffer_layout_names[i], name) == 0)
            return &gbuffer_layouts[i];
    return NULL;
}

GLenum gbuffer_layout_depth_format(const gbuffer_layout *layout, bool stencil)
{
    if (layout->depth == GBUFFER_DEPTH_D24S8)
        return GL_DEPTH24_STENCIL8;
    return stencil ? GL_DEPTH32F_STENCIL8 : GL_DEPTH_COMPONENT32F;
}

/* Bits of the formats the layouts use, as the format names state them (tests/gbuffer/ checks them
 * against what GL reports). D32F_S8 holds 40 bits; most hardware pads it to 64. */
static int format_bits(GLenum format)
{
    switch (format) {
    case GL_SRGB8_ALPHA8:
    case GL_RGBA8:
    case GL_DEPTH24_STENCIL8:
    case GL_DEPTH_COMPONENT32F: return 32;
    case GL_RGBA16F:
    case GL_RGBA16: return 64;
    case GL_DEPTH32F_STENCIL8: return 40;
    default: return 0;
    }
}

int gbuffer_layout_bytes(const gbuffer_layout *layout, bool stencil)
{
    return (format_bits(layout->albedo_format) + format_bits(layout->normal_format) +
            format_bits(gbuffer_layout_depth_format(layout, stencil))) / 8;
}

int gbuffer_bytes_per_pixel(void)
{
    return gbuffer_layout_bytes(default_layout, false) + (default_emissive ? format_bits(GBUFFER_EMISSIVE_FORMAT) / 8 : 0);
}

int gbuffer_pixel_bytes(const gbuffer *g)
{
    return gbuffer_layout_bytes(g->desc.layout, g->desc.stencil) +
           (g->desc.emissive ? format_bits(GBUFFER_EMISSIVE_FORMAT) / 8 : 0);
}

double gbuffer_memory_bytes(const gbuffer *g)
{
    const int samples = g->desc.samples > 1 ? g->desc.samples : 1;
    return (double)gbuffer_pixel_bytes(g) * samples * g->fbo.width * g->fbo.height;
}

/* ---- emissive (RT2) -------------------------------------------------------------------------- */

/* Only a metallic-roughness material emits (gpu_scene.c writes 0 for Blinn-Phong ones). */
bool gbuffer_scene_emits(const scene *s)
{
    for (int i = 0; i < s->material_count; i++) {
        const scene_material *m = &s->materials[i];
        if (m->pbr && (m->emissive[0] > 0.0f || m->emissive[1] > 0.0f || m->emissive[2] > 0.0f ||
                       m->maps[SCENE_MAP_EMISSIVE] >= 0))
            return true;
    }
    return false;
}

void gbuffer_set_default_emissive(bool on) { default_emissive = on; }

bool gbuffer_default_emissive(void) { return default_emissive; }

static bool is_reversed(const gbuffer_layout *layout) { return layout->depth == GBUFFER_DEPTH_D32F_REVERSED; }

/* glClipControl is core in 4.5; the loader is generated for 4.6, so the flags say what is there. */
static bool have_clip_control(void)
{
    return (GLAD_GL_VERSION_4_5 || GLAD_GL_ARB_clip_control) && glClipControl != NULL;
}

bool gbuffer_layout_available(const gbuffer_layout *layout)
{
    if (is_reversed(layout) && !have_clip_control()) {
        log_error("G-buffer layout %s needs glClipControl (GL 4.5 or GL_ARB_clip_control), which this "
                  "context (GL %s) lacks",
                  gbuffer_layout_name(layout), (const char *)glGetString(GL_VERSION));
        return false;
    }
    return true;
}

bool gbuffer_set_default_layout(const gbuffer_layout *layout)
{
    if (!layout || !gbuffer_layout_available(layout))
        return false;
    default_layout = layout;
    log_debug("G-buffer layout %s: %d bytes per pixel", gbuffer_layout_name(layout), gbuffer_layout_bytes(layout, false));
    return true;
}

const gbuffer_layout *gbuffer_default_layout(void) { return default_layout; }

/* A metallic-roughness material is marked by a negative shininess (shaders/shading.glsl): a
 * half-float RT1 keeps the sign; 8-bit ones clamp it to 0, a Blinn-Phong shininess of 1; oct16's
 * RGBA16 marks it in its spare channel (gbuffer.frag). */
bool gbuffer_layout_holds_pbr(const gbuffer_layout *layout)
{
    return layout->normal_encoding == SHADER_GBUFFER_NORMAL_HALF ||
           layout->normal_encoding == SHADER_GBUFFER_NORMAL_SHORTS;
}

static bool scene_has_pbr(const scene *s)
{
    bool pbr = false;
    for (int i = 0; i < s->material_count; i++)
        pbr = pbr || s->materials[i].pbr;
    return pbr;
}

const gbuffer_layout *gbuffer_layout_for_scene(const gbuffer_layout *layout, const scene *s)
{
    const bool pbr = scene_has_pbr(s);
    if (!pbr)
        return layout ? layout : default_layout;
    if (!layout)
        return gbuffer_layout_holds_pbr(default_layout) ? default_layout : &gbuffer_layouts[GBUFFER_LAYOUT_OCT16];
    if (gbuffer_layout_holds_pbr(layout))
        return layout;
    char holds[128] = "";
    for (int i = 0; i < GBUFFER_LAYOUT_COUNT; i++)
        if (gbuffer_layout_holds_pbr(&gbuffer_layouts[i]))
            snprintf(holds + strlen(holds), sizeof holds - strlen(holds), "%s%s", holds[0] ? ", " : "",
                     gbuffer_layout_names[i]);
    log_error("G-buffer layout %s cannot hold the scene's metallic-roughness materials (its RT1 is 8-bit: "
              "docs/18_pbr_materials.md); layouts that can: %s",
              gbuffer_layout_name(layout), holds);
    return NULL;
}

/* The compact layout with its depth reversed: the same 12 bytes, and the precision a position rebuilt
 * from depth needs where a light's hard cut-off crosses a surface (docs/17_ssao.md). */
const gbuffer_layout *gbuffer_layout_for_chapter(const gbuffer_layout *layout, const scene *s, bool prefers_reversed_z)
{
    if (!layout && prefers_reversed_z && default_layout == &gbuffer_layouts[GBUFFER_LAYOUT_COMPACT] &&
        !scene_has_pbr(s) && have_clip_control())
        return &gbuffer_layouts[GBUFFER_LAYOUT_REVERSED_Z];
    return gbuffer_layout_for_scene(layout, s);
}

bool gbuffer_layout_fits_pass(const gbuffer_layout *layout, const gl_pass_state *pass)
{
    if (!is_reversed(layout) || !pass)
        return true;
    log_error("G-buffer layout %s: this chapter's lighting pass reads the G-buffer's depth as standard depth "
              "(near 0, far 1); reversed-Z needs its tests mirrored (common/render/gbuffer.h); chapters 02, 03, 11, "
              "17 and 19 take it",
              gbuffer_layout_name(layout));
    return false;
}

/* ---- reversed-Z ------------------------------------------------------------------------------ */

/* The matrix that draws reversed-Z: the projection's depth row replaced by z' = (w - z) / 2, which
 * maps clip z/w = -1 (near) to 1 and +1 (far) to 0: window depth d' = 1 - d in exact arithmetic,
 * with glClipControl's [0,1] range. Rows x, y and w are view_proj's own floats, so the rasteriser
 * covers exactly the pixels forward.vert covers with the standard matrix; the new row is computed in
 * double from proj and view (its two terms nearly cancel for a distant far plane) and rounded once.
 * view_proj's row is never read, so a copy of the view that already holds this matrix gives it again. */
static void reversed_view_proj(const frame_view *v, mat4 out)
{
    glm_mat4_copy((vec4 *)v->view_proj, out);
    for (int c = 0; c < 4; c++) {
        double z = 0.0;
        for (int k = 0; k < 4; k++)
            z += 0.5 * ((double)v->proj[k][3] - (double)v->proj[k][2]) * (double)v->view[c][k];
        out[c][2] = (float)z;
    }
}

/* Inverse in double (common/base/mat4d.h), rounded to float once at the end: the reconstruction matrix
 * of reversed-Z should not throw away the precision its depth keeps. */
static void invert_to_float(const float *m, mat4 out)
{
    double a[16], inv[16];
    mat4d_from_float(m, a);
    mat4d_invert(a, inv);
    for (int i = 0; i < 16; i++)
        out[i / 4][i % 4] = (float)inv[i];
}

/* The comparison that means the same with depth mirrored (d' = 1 - d). */
static GLenum mirror_depth_func(GLenum func)
{
    switch (func) {
    case GL_LESS: return GL_GREATER;
    case GL_GREATER: return GL_LESS;
    case GL_LEQUAL: return GL_GEQUAL;
    case GL_GEQUAL: return GL_LEQUAL;
    default: return func; /* EQUAL, NOTEQUAL, ALWAYS, NEVER, 0 */
    }
}

static void set_clip_control(bool reversed)
{
    glClipControl(GL_LOWER_LEFT, reversed ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
}

void gbuffer_layout_depth_begin(const gbuffer_layout *layout, const gpu_scene *gs, gpu_scene *view,
                                gl_pass_state *state)
{
    *view = *gs;
    if (!is_reversed(layout))
        return;
    reversed_view_proj(&gs->view, view->view.view_proj);
    state->depth_func = mirror_depth_func(state->depth_func);
    set_clip_control(true);
    glClearDepth(0.0); /* far, for a pass that clears */
}

void gbuffer_layout_depth_end(const gbuffer_layout *layout)
{
    if (!is_reversed(layout))
        return;
    set_clip_control(false);
    glClearDepth(1.0);
}

void gbuffer_layout_bind_depth(const gbuffer_layout *layout, const gpu_scene *gs, GLuint program)
{
    const bool reversed = is_reversed(layout);
    mat4 inv;
    if (reversed) {
        mat4 vp;
        reversed_view_proj(&gs->view, vp);
        invert_to_float((const float *)vp, inv);
    }
    glUniformMatrix4fv(glGetUniformLocation(program, "u_inv_view_proj"), 1, GL_FALSE,
                       reversed ? (const float *)inv : (const float *)gs->view.inv_view_proj);
    glUniform1i(glGetUniformLocation(program, "u_gbuffer_reversed_z"), reversed);
}

void gbuffer_depth_test_begin(const gbuffer *g, const gpu_scene *gs, gpu_scene *view, gl_pass_state *state)
{
    gbuffer_layout_depth_begin(g->desc.layout, gs, view, state);
}

void gbuffer_depth_test_end(const gbuffer *g) { gbuffer_layout_depth_end(g->desc.layout); }

/* ---- the G-buffer ------------------------------------------------------------------------------ */

static bool has_stencil(GLenum depth_format)
{
    return depth_format == GL_DEPTH24_STENCIL8 || depth_format == GL_DEPTH32F_STENCIL8;
}

static bool make_targets(gbuffer *g, int width, int height)
{
    const gbuffer_layout *l = g->desc.layout;
    const GLenum depth_format = gbuffer_layout_depth_format(l, g->desc.stencil);
    const fbo_desc desc = {
        .color_formats = {l->albedo_format, l->normal_format, GBUFFER_EMISSIVE_FORMAT},
        .color_count = g->desc.emissive ? 3 : 2,
        .depth_format = depth_format,
        .name = "gbuffer",
        .samples = g->desc.samples,
    };
    /* The copy has the same format and samples: a depth blit needs them. */
    const fbo_desc copy = {.depth_format = depth_format, .name = "gbuffer depth copy", .samples = g->desc.samples};
    return fbo_create(&g->fbo, &desc, width, height) &&
           (!g->desc.stencil || fbo_create(&g->depth_copy, &copy, width, height));
}

bool gbuffer_create(gbuffer *g, int width, int height) { return gbuffer_create_with(g, width, height, NULL); }

bool gbuffer_create_with(gbuffer *g, int width, int height, const gbuffer_desc *desc)
{
    if (!gbuffer_create_pass(g, desc) || !make_targets(g, width, height)) {
        gbuffer_destroy(g);
        return false;
    }
    return gl_check("gbuffer_create");
}

bool gbuffer_create_pass(gbuffer *g, const gbuffer_desc *desc)
{
    memset(g, 0, sizeof *g);
    if (desc)
        g->desc = *desc;
    if (!g->desc.layout)
        g->desc.layout = default_layout;
    g->desc.emissive = g->desc.emissive || default_emissive;
    if (!gbuffer_layout_available(g->desc.layout))
        return false;
    /* forward.vert: the same vertex path as the forward renderer, so both rasterise identically. */
    char defines[96];
    snprintf(defines, sizeof defines, "GBUFFER_NORMAL %d%s", g->desc.layout->normal_encoding,
             g->desc.emissive ? "\nGBUFFER_EMISSIVE 1" : "");
    g->program = gl_program_load("forward.vert", "gbuffer.frag", defines);
    return g->program != 0;
}

bool gbuffer_resize(gbuffer *g, int width, int height)
{
    fbo_destroy(&g->fbo);
    fbo_destroy(&g->depth_copy);
    return make_targets(g, width, height);
}

void gbuffer_attach_stencil(const gbuffer *g, GLuint framebuffer)
{
    if (!g->desc.stencil) {
        log_error("gbuffer_attach_stencil: this G-buffer has no stencil (gbuffer_desc.stencil)");
        return;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_TEXTURE_2D, g->fbo.depth, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

bool gbuffer_follow_target(const gbuffer *g, fbo *target, GLenum format, const char *name)
{
    if (target->id && target->depth == g->fbo.depth && target->width == g->fbo.width &&
        target->height == g->fbo.height)
        return true;
    fbo_destroy(target);
    const fbo_desc desc = {.color_formats = {format},
                           .color_count = 1,
                           .depth_format = GL_DEPTH_COMPONENT32F,
                           .shared_depth = g->fbo.depth,
                           .name = name};
    return fbo_create(target, &desc, g->fbo.width, g->fbo.height);
}

void gbuffer_destroy(gbuffer *g)
{
    fbo_destroy(&g->fbo);
    fbo_destroy(&g->depth_copy);
    gl_program_destroy(&g->program);
    memset(g, 0, sizeof *g);
}

bool gbuffer_render(gbuffer *g, const gpu_scene *gs)
{
    if (g->fbo.width != gs->view.width || g->fbo.height != gs->view.height) {
        log_error("gbuffer is %dx%d but the view is %dx%d (call gbuffer_resize)", g->fbo.width, g->fbo.height,
                  gs->view.width, gs->view.height);
        return false;
    }
    frame_timer_mark("geometry");
    glBindFramebuffer(GL_FRAMEBUFFER, g->fbo.id);
    glViewport(0, 0, g->fbo.width, g->fbo.height);
    /* Zero normal/material and depth 1 (reversed: 0, the depth test's begin sets it) mark the
     * background; the lighting pass tests
     * depth. Same state as forward_render (GL_LEQUAL: on an exact depth tie the object drawn last
     * wins): an object hides another exactly where it does there. Reversed, GL_GEQUAL keeps that. */
    gl_pass_state geometry = {.cull = GL_BACK, .depth_func = GL_LEQUAL, .depth_write = true};
    gpu_scene view;
    gbuffer_depth_test_begin(g, gs, &view, &geometry);
    gl_pass_state_apply(&geometry);
    glClearColor(0, 0, 0, 0);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    bool stencil = has_stencil(gbuffer_layout_depth_format(g->desc.layout, g->desc.stencil));
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | (stencil ? GL_STENCIL_BUFFER_BIT : 0));
    /* Without this an SRGB8 attachment stores the linear value unconverted (and reads decode it). */
    glEnable(GL_FRAMEBUFFER_SRGB);

    glUseProgram(g->program);
    gpu_scene_bind_objects(&view, g->program, SHADER_UNIT_OBJECTS);
    gpu_scene_draw(&view, g->program);

    glDisable(GL_FRAMEBUFFER_SRGB);
    gbuffer_depth_test_end(g);
    gl_pass_state_reset();
    if (g->desc.stencil) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, g->fbo.id);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, g->depth_copy.id);
        glBlitFramebuffer(0, 0, g->fbo.width, g->fbo.height, 0, 0, g->fbo.width, g->fbo.height,
                          GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return true;
}

void gbuffer_bind_textures(const gbuffer *g, const gpu_scene *gs, GLuint program, int first_unit)
{
    static const char *const names[3] = {"u_gbuffer_albedo", "u_gbuffer_normal", "u_gbuffer_depth"};
    const GLuint textures[3] = {g->fbo.color[0], g->fbo.color[1],
                                g->desc.stencil ? g->depth_copy.depth : g->fbo.depth};
    /* A multisampled G-buffer is read by shaders built with GBUFFER_MULTISAMPLE (sampler2DMS). */
    const GLenum target = g->fbo.samples > 1 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D;
    glUseProgram(program);
    for (int i = 0; i < 3; i++) {
        glActiveTexture(GL_TEXTURE0 + (GLenum)(first_unit + i));
        glBindTexture(target, textures[i]);
        glUniform1i(glGetUniformLocation(program, names[i]), first_unit + i);
    }
    glActiveTexture(GL_TEXTURE0);
    gbuffer_layout_bind_depth(g->desc.layout, gs, program);
    /* RT2 on its own unit, bound or not: a sampler left on unit 0 would meet the lights' buffer there. */
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_GBUFFER_EMISSIVE);
    glBindTexture(target, g->desc.emissive ? g->fbo.color[2] : 0);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(glGetUniformLocation(program, "u_gbuffer_emissive"), SHADER_UNIT_GBUFFER_EMISSIVE);
    glUniform1i(glGetUniformLocation(program, "u_gbuffer_has_emissive"), g->desc.emissive);
    glUniform1i(glGetUniformLocation(program, "u_gbuffer_normal_encoding"), g->desc.layout->normal_encoding);
    glUniform3fv(glGetUniformLocation(program, "u_eye"), 1, gs->view.eye);
    glUniform2f(glGetUniformLocation(program, "u_viewport_size"), (float)g->fbo.width, (float)g->fbo.height);
}
