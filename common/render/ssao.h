/* ssao.h - screen-space ambient occlusion (chapter 17's stage, docs/17_ssao.md), moved here when
 * chapter 19 put it under its image-based light: two full-screen passes over a surface's depth and
 * normal (the G-buffer's, or forward's depth-normal pre-pass in the same encoding), and what the
 * shading programs built with AMBIENT_OCCLUSION read.
 *
 *   ssao_create(s, desc)                 the kernel and noise tile (the course's rng, seed 17), the
 *                                        programs; forward's pre-pass in the default G-buffer
 *                                        layout's normal encoding (gbuffer_default_layout(): set it
 *                                        for the scene first, as the runner does)
 *   ssao_resize(s, width, height)        the occlusion targets and the pre-pass target at that size
 *   ssao_draw_prepass(s, gs)             forward's depth-normal pre-pass: every opaque object's
 *                                        normal, as the G-buffer's geometry pass writes it, and depth
 *   ssao_draw(s, g, gs)                  1. SSAO, 2. the blur (desc.blur > 0), from g's surface, or
 *                                        from the pre-pass's when g is NULL
 *   ssao_set(s, desc)                    another radius, direction count or blur while running (the
 *                                        kernel and noise made again, as ssao_create would)
 *   ssao_key(s, key)                     chapter 17's keys (19's too): T / Y radius halved / doubled,
 *                                        J / L directions halved / doubled, B / N blur -1 / +1;
 *                                        false for any other key
 *   ssao_bind(program, s)                u_ao and u_ao_on on a program built with AMBIENT_OCCLUSION
 *                                        (a gl_program_extra's bind)
 *   ssao_occlusion(s)                    the texture the ambient term reads (blurred, or raw without
 *                                        a blur)
 *   ssao_show(s, raw, target, w, h)      the raw or the read occlusion, grey, blitted into target
 *   ssao_destroy(s)
 */
#ifndef COMMON_SSAO_H
#define COMMON_SSAO_H

#include "fbo.h"
#include "gbuffer.h"
#include "gpu_scene.h"

typedef struct ssao_desc {
    float radius; /* how far a surface may be and still hide the sky (scene units) */
    int samples;  /* directions per pixel, 1 to SHADER_AO_MAX_SAMPLES */
    int blur;     /* blur window 2N x 2N pixels; 0: none */
} ssao_desc;

typedef struct ssao {
    ssao_desc desc;
    bool on;
    fbo normals;        /* forward only: the layout's RT1 format + its depth */
    fbo ao, ao_blurred; /* RGBA16F, the occlusion in r */
    GLuint ssao_program, blur_program, prepass_program, noise;
    const gbuffer_layout *layout; /* the pre-pass's encoding */
    float kernel[SHADER_AO_MAX_SAMPLES][3];
} ssao;

bool ssao_create(ssao *s, const ssao_desc *desc);
bool ssao_resize(ssao *s, int width, int height);
bool ssao_draw_prepass(ssao *s, const gpu_scene *gs);
bool ssao_draw(ssao *s, const gbuffer *g, const gpu_scene *gs);
bool ssao_set(ssao *s, const ssao_desc *desc);
bool ssao_key(ssao *s, int key);
void ssao_bind(GLuint program, const void *ssao_state);
GLuint ssao_occlusion(const ssao *s);
void ssao_show(const ssao *s, bool raw, GLuint target, int width, int height);
void ssao_destroy(ssao *s);

#endif
