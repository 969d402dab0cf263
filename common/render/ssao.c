/* ssao.c - screen-space ambient occlusion (ssao.h; chapter 17 introduces it, docs/17_ssao.md). */
#include "ssao.h"

#include "frame_timer.h"
#include "gl_program.h"
#include "gl_util.h"
#include "log.h"
#include "rng.h"
#include "shader_layout.h"

#include <cglm/cglm.h>
#include <math.h>
#include <stdio.h>

/* Forward's depth-normal pre-pass: chapter 00's pre-pass state (on a tie the object drawn last wins,
 * as in the G-buffer). */
static const gl_pass_state prepass = {.cull = GL_BACK, .depth_func = GL_LEQUAL, .depth_write = true};
/* SSAO and blur: every pixel written once; no blending, no depth test. */
static const gl_pass_state fullscreen_pass = {.depth_write = false};

/* `samples` unit directions about z (the normal in the shader's frame), cosine-weighted and
 * stratified in the cosine, so that even 4 span the hemisphere. */
static void make_kernel(rng *r, int samples, float kernel[][3])
{
    for (int i = 0; i < samples; i++) {
        /* u = sin^2 of the angle from the normal, uniform per stratum: cos-weighted directions */
        double u = (i + rng_unit(r)) / samples, phi = 2.0 * GLM_PI * rng_unit(r);
        double s = sqrt(u);
        kernel[i][0] = (float)(s * cos(phi)), kernel[i][1] = (float)(s * sin(phi));
        kernel[i][2] = (float)sqrt(1.0 - u);
    }
}

/* The SHADER_AO_NOISE_SIZE^2 noise tile, RG32F: per pixel the (cos, sin) of its turn about the
 * normal, the circle's SHADER_AO_NOISE_SIZE^2 angles in a random order; 0 on failure. */
static GLuint make_noise(rng *r)
{
    enum { N = SHADER_AO_NOISE_SIZE * SHADER_AO_NOISE_SIZE };
    int order[N];
    float turns[N][2];
    for (int i = 0; i < N; i++)
        order[i] = i;
    for (int i = N - 1; i > 0; i--) { /* Fisher-Yates */
        int j = rng_below(r, i + 1), t = order[i];
        order[i] = order[j], order[j] = t;
    }
    for (int i = 0; i < N; i++) {
        double angle = 2.0 * GLM_PI * (order[i] + 0.5) / N;
        turns[i][0] = (float)cos(angle), turns[i][1] = (float)sin(angle);
    }
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, SHADER_AO_NOISE_SIZE, SHADER_AO_NOISE_SIZE, 0, GL_RG, GL_FLOAT,
                 turns);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    return gl_check("ssao noise tile") ? t : 0;
}

/* The radius, the directions or the blur changed while running (the keys): the kernel and the noise
 * tile are made again from the same seed, so a count reached by keys draws what --ao-samples would. */
bool ssao_set(ssao *s, const ssao_desc *desc)
{
    rng r = rng_seed(17);
    make_kernel(&r, desc->samples, s->kernel);
    GLuint noise = make_noise(&r);
    if (!noise)
        return false;
    glDeleteTextures(1, &s->noise);
    s->noise = noise;
    s->desc = *desc;
    return true;
}

/* T / Y: the radius halved or doubled; J / L: the directions halved or doubled; B / N: the blur
 * window one step smaller or larger. Each within --ao-radius's, --ao-samples' and --ao-blur's ranges. */
bool ssao_key(ssao *s, int key)
{
    ssao_desc d = s->desc;
    switch (key) {
    case 'T': d.radius = fmaxf(d.radius * 0.5f, 1e-3f); break;
    case 'Y': d.radius = fminf(d.radius * 2.0f, 1e3f); break;
    case 'J': d.samples = d.samples > 1 ? d.samples / 2 : 1; break;
    case 'L': d.samples = d.samples * 2 < SHADER_AO_MAX_SAMPLES ? d.samples * 2 : SHADER_AO_MAX_SAMPLES; break;
    case 'B': d.blur = d.blur > 0 ? d.blur - 1 : 0; break;
    case 'N': d.blur = d.blur < 16 ? d.blur + 1 : 16; break;
    default: return false;
    }
    if (ssao_set(s, &d))
        log_info("ambient occlusion: radius %g, %d directions, blur %d", d.radius, d.samples, d.blur);
    return true;
}

bool ssao_create(ssao *s, const ssao_desc *desc)
{
    *s = (ssao){.desc = *desc, .on = true, .layout = gbuffer_default_layout()};
    rng r = rng_seed(17);
    make_kernel(&r, desc->samples, s->kernel);
    s->noise = make_noise(&r);
    /* the pre-pass is the geometry pass's own shader, its RT1 only (ssao_resize maps it to the one
     * target): the normal in the G-buffer's encoding, normal maps applied, so the passes read the
     * same bits whichever renderer drew them */
    char defines[64];
    snprintf(defines, sizeof defines, "GBUFFER_NORMAL %d", s->layout->normal_encoding);
    s->ssao_program = gl_program_load("fullscreen.vert", "ssao.frag", NULL);
    s->blur_program = gl_program_load("fullscreen.vert", "ssao_blur.frag", NULL);
    s->prepass_program = gl_program_load("forward.vert", "gbuffer.frag", defines);
    return s->noise && s->ssao_program && s->blur_program && s->prepass_program;
}

bool ssao_resize(ssao *s, int width, int height)
{
    if (s->ao.id && s->ao.width == width && s->ao.height == height)
        return true;
    fbo_destroy(&s->normals), fbo_destroy(&s->ao), fbo_destroy(&s->ao_blurred);
    const fbo_desc normals = {.color_formats = {s->layout->normal_format},
                              .color_count = 1,
                              .depth_format = gbuffer_layout_depth_format(s->layout, false),
                              .name = "depth-normal pre-pass"};
    const fbo_desc ao = {.color_formats = {GL_RGBA16F}, .color_count = 1, .name = "ambient occlusion"};
    if (!fbo_create(&s->normals, &normals, width, height) || !fbo_create(&s->ao, &ao, width, height) ||
        !fbo_create(&s->ao_blurred, &ao, width, height))
        return false;
    /* gbuffer.frag's location 1 (the normal and material) into the one target; location 0 dropped */
    const GLenum draw[2] = {GL_NONE, GL_COLOR_ATTACHMENT0};
    glBindFramebuffer(GL_FRAMEBUFFER, s->normals.id);
    glDrawBuffers(2, draw);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return gl_check("ssao targets");
}

bool ssao_draw_prepass(ssao *s, const gpu_scene *gs)
{
    frame_timer_mark("depth-normal pre-pass");
    /* its depth as the G-buffer's (reversed with a reversed-Z layout), so the passes read the same bits */
    gl_pass_state state = prepass;
    gpu_scene view;
    gbuffer_layout_depth_begin(s->layout, gs, &view, &state);
    gpu_scene_draw_into(&view, s->normals.id, s->normals.width, s->normals.height, s->prepass_program, &state);
    gbuffer_layout_depth_end(s->layout);
    return gl_check("ssao depth-normal pre-pass");
}

/* Forward's surface for the two passes, in the uniforms gbuffer_read.glsl reads: the pre-pass's
 * normal (encoded as the G-buffer's) and depth. */
static void bind_prepass(const ssao *s, GLuint p, const gpu_scene *gs)
{
    const GLuint textures[2] = {s->normals.color[0], s->normals.depth};
    const char *const names[2] = {"u_gbuffer_normal", "u_gbuffer_depth"};
    for (int i = 0; i < 2; i++) {
        glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_GBUFFER + 1 + i);
        glBindTexture(GL_TEXTURE_2D, textures[i]);
        glUniform1i(glGetUniformLocation(p, names[i]), SHADER_UNIT_GBUFFER + 1 + i);
    }
    glActiveTexture(GL_TEXTURE0);
    gbuffer_layout_bind_depth(s->layout, gs, p);
    glUniform1i(glGetUniformLocation(p, "u_gbuffer_normal_encoding"), s->layout->normal_encoding);
    glUniform2f(glGetUniformLocation(p, "u_viewport_size"), (float)s->normals.width,
                (float)s->normals.height);
}

/* The surface the passes read: the G-buffer's, or forward's pre-pass (g NULL). */
static void bind_surface(const ssao *s, GLuint p, const gbuffer *g, const gpu_scene *gs)
{
    glUseProgram(p);
    if (g)
        gbuffer_bind_textures(g, gs, p, SHADER_UNIT_GBUFFER);
    else
        bind_prepass(s, p, gs);
    glUniformMatrix4fv(glGetUniformLocation(p, "u_view_proj"), 1, GL_FALSE,
                       (const float *)gs->view.view_proj);
    glUniform1f(glGetUniformLocation(p, "u_radius"), s->desc.radius);
}

bool ssao_draw(ssao *s, const gbuffer *g, const gpu_scene *gs)
{
    frame_timer_mark("ssao");
    gl_pass_state_apply(&fullscreen_pass);
    glBindFramebuffer(GL_FRAMEBUFFER, s->ao.id);
    glViewport(0, 0, s->ao.width, s->ao.height);
    bind_surface(s, s->ssao_program, g, gs);
    glUniform3fv(glGetUniformLocation(s->ssao_program, "u_kernel"), s->desc.samples, &s->kernel[0][0]);
    glUniform1i(glGetUniformLocation(s->ssao_program, "u_samples"), s->desc.samples);
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_IMAGE);
    glBindTexture(GL_TEXTURE_2D, s->noise);
    glUniform1i(glGetUniformLocation(s->ssao_program, "u_noise"), SHADER_UNIT_IMAGE);
    gl_draw_fullscreen();
    if (s->desc.blur > 0) {
        frame_timer_mark("ssao blur");
        glBindFramebuffer(GL_FRAMEBUFFER, s->ao_blurred.id);
        bind_surface(s, s->blur_program, g, gs);
        glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_IMAGE);
        glBindTexture(GL_TEXTURE_2D, s->ao.color[0]);
        glUniform1i(glGetUniformLocation(s->blur_program, "u_ao_raw"), SHADER_UNIT_IMAGE);
        glUniform1i(glGetUniformLocation(s->blur_program, "u_blur"), s->desc.blur);
        gl_draw_fullscreen();
    }
    glActiveTexture(GL_TEXTURE0);
    gl_pass_state_reset();
    return gl_check("ssao");
}

GLuint ssao_occlusion(const ssao *s)
{
    return s->desc.blur > 0 ? s->ao_blurred.color[0] : s->ao.color[0];
}

void ssao_bind(GLuint program, const void *ssao_state)
{
    const ssao *s = ssao_state;
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_AO);
    glBindTexture(GL_TEXTURE_2D, ssao_occlusion(s));
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(glGetUniformLocation(program, "u_ao"), SHADER_UNIT_AO);
    glUniform1i(glGetUniformLocation(program, "u_ao_on"), s->on);
}

void ssao_show(const ssao *s, bool raw, GLuint target, int width, int height)
{
    const fbo *f = raw || s->desc.blur == 0 ? &s->ao : &s->ao_blurred;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, f->id);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
    glBlitFramebuffer(0, 0, f->width, f->height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void ssao_destroy(ssao *s)
{
    fbo_destroy(&s->ao_blurred), fbo_destroy(&s->ao), fbo_destroy(&s->normals);
    glDeleteTextures(1, &s->noise);
    s->noise = 0;
    gl_program_destroy(&s->prepass_program);
    gl_program_destroy(&s->blur_program);
    gl_program_destroy(&s->ssao_program);
}
