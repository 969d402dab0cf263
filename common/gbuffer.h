/* gbuffer.h - the G-buffer: what the lighting passes need to know about each visible pixel.
 *
 *   gbuffer_create(g, width, height)     textures + framebuffer + the geometry-pass program
 *   gbuffer_create_with(g, width, height, desc)
 *                                        the same with options (desc may be NULL: the defaults)
 *   gbuffer_attach_stencil(g, framebuffer)
 *                                        attach g's stencil to `framebuffer` (one that borrows g's
 *                                        depth texture, like the light accumulation buffer), so a
 *                                        pass drawing there tests the stencil; g made with .stencil
 *   gbuffer_resize(g, width, height)     recreate the textures (window resize)
 *   gbuffer_destroy(g)
 *   gbuffer_render(g, gs)                geometry pass into g's own framebuffer: every object once,
 *                                        depth test on; leaves framebuffer 0 bound and
 *                                        gl_pass_state_reset()'s state
 *   gbuffer_bind_textures(g, gs, program, first_unit)
 *                                        u_gbuffer_albedo, u_gbuffer_normal, u_gbuffer_depth on units
 *                                        first_unit..first_unit+2, plus u_inv_view_proj and u_eye
 *                                        (with a stencil: the depth's copy, see below)
 *   gbuffer_bytes_per_pixel()            this layout's size (a naive layout is GBUFFER_NAIVE_BYTES)
 *
 * Layout (nothing the shading model does not read):
 *   RT0  GL_SRGB8_ALPHA8  albedo.rgb (sRGB-encoded: 8 bits spent where the eye sees them), a unused
 *   RT1  GL_RGBA16F       octahedral normal (x, y), specular, shininess
 *   depth GL_DEPTH_COMPONENT32F  position is rebuilt from it with the inverse view-projection;
 *         GL_DEPTH32F_STENCIL8 with desc.stencil (chapter 08): the same 32-bit float depth, plus 8
 *         stencil bits that gbuffer_render clears to 0 (the depth is the same values to the bit).
 *         gbuffer_render then copies the depth (glBlitFramebuffer), and the shaders read the copy:
 *         a pass that writes the stencil must not sample the texture it writes (a feedback loop,
 *         undefined in GL; llvmpipe finishes all queued drawing before each such draw)
 * shaders/gbuffer_read.glsl decodes a pixel: gbuffer_read(ivec2 pixel) -> surface.
 */
#ifndef COMMON_GBUFFER_H
#define COMMON_GBUFFER_H

#include "fbo.h"
#include "gpu_scene.h"

/* position RGBA16F (8) + normal RGBA16F (8) + albedo RGBA8 (4) + depth 32 bit (4) */
#define GBUFFER_NAIVE_BYTES 24

/* Options; zero is the default. */
typedef struct gbuffer_desc {
    bool stencil; /* a depth-stencil target (GL_DEPTH32F_STENCIL8) instead of depth only */
} gbuffer_desc;

typedef struct gbuffer {
    fbo fbo;        /* color[0] albedo, color[1] normal/material, depth (and stencil) */
    GLuint program; /* geometry pass */
    gbuffer_desc desc;
    fbo depth_copy; /* with desc.stencil: the depth, copied after the geometry pass, for the shaders */
} gbuffer;

bool gbuffer_create(gbuffer *g, int width, int height);
bool gbuffer_create_with(gbuffer *g, int width, int height, const gbuffer_desc *desc);
void gbuffer_attach_stencil(const gbuffer *g, GLuint framebuffer);
bool gbuffer_resize(gbuffer *g, int width, int height);
void gbuffer_destroy(gbuffer *g);
bool gbuffer_render(gbuffer *g, const gpu_scene *gs);
void gbuffer_bind_textures(const gbuffer *g, const gpu_scene *gs, GLuint program, int first_unit);
int gbuffer_bytes_per_pixel(void);

#endif
