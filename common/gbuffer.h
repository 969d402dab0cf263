/* gbuffer.h - the G-buffer: what the lighting passes need to know about each visible pixel.
 *
 *   gbuffer_create(g, width, height)     textures + framebuffer + the geometry-pass program
 *   gbuffer_resize(g, width, height)     recreate the textures (window resize)
 *   gbuffer_destroy(g)
 *   gbuffer_render(g, gs)                geometry pass into g's own framebuffer: every object once,
 *                                        depth test on; leaves framebuffer 0 bound and
 *                                        gl_pass_state_reset()'s state
 *   gbuffer_bind_textures(g, gs, program, first_unit)
 *                                        u_gbuffer_albedo, u_gbuffer_normal, u_gbuffer_depth on units
 *                                        first_unit..first_unit+2, plus u_inv_view_proj and u_eye
 *   gbuffer_bytes_per_pixel()            this layout's size (a naive layout is GBUFFER_NAIVE_BYTES)
 *
 * Layout (nothing the shading model does not read):
 *   RT0  GL_SRGB8_ALPHA8  albedo.rgb (sRGB-encoded: 8 bits spent where the eye sees them), a unused
 *   RT1  GL_RGBA16F       octahedral normal (x, y), specular, shininess
 *   depth GL_DEPTH_COMPONENT32F  position is rebuilt from it with the inverse view-projection
 * shaders/gbuffer_read.glsl decodes a pixel: gbuffer_read(ivec2 pixel) -> surface.
 */
#ifndef COMMON_GBUFFER_H
#define COMMON_GBUFFER_H

#include "fbo.h"
#include "gpu_scene.h"

/* position RGBA16F (8) + normal RGBA16F (8) + albedo RGBA8 (4) + depth 32 bit (4) */
#define GBUFFER_NAIVE_BYTES 24

typedef struct gbuffer {
    fbo fbo;         /* color[0] albedo, color[1] normal/material, depth */
    GLuint program;  /* geometry pass */
} gbuffer;

bool gbuffer_create(gbuffer *g, int width, int height);
bool gbuffer_resize(gbuffer *g, int width, int height);
void gbuffer_destroy(gbuffer *g);
bool gbuffer_render(gbuffer *g, const gpu_scene *gs);
void gbuffer_bind_textures(const gbuffer *g, const gpu_scene *gs, GLuint program, int first_unit);
int gbuffer_bytes_per_pixel(void);

#endif
