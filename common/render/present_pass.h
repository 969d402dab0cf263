/* present_pass.h - the present pass (chapter 06's): a texture of linear radiance to display values in a
 * framebuffer, once per pixel, with shaders/accum_present.frag. Every frame that adds up or blends
 * light in a float buffer ends with it: the volume chapters' accumulation buffer, the forward frame
 * with glass, chapter 12's glass over the clustered frame, chapter 13's resolved samples, and the
 * overdraw views' counts.
 *
 *   present_pass_create(p)          the program
 *   present_pass_destroy(p)
 *   present_pass_draw(p, texture, target, width, height, options)
 *        the texture (width x height, read texel for texel) into the framebuffer `target` over that
 *        viewport, with the caller's pass state; options NULL: no tone mapping, the lit view.
 *        Leaves texture unit SHADER_UNIT_IMAGE and the vertex array unbound
 */
#ifndef COMMON_PRESENT_PASS_H
#define COMMON_PRESENT_PASS_H

#include <glad/gl.h>
#include <stdbool.h>

typedef struct present_pass_options {
    int tonemap;    /* SHADER_TONEMAP_NONE (0: clamp, forward's transform), _EXPOSURE or _REINHARD */
    float exposure; /* 0 means 1 */
    int view;       /* SHADER_VIEW_LIT (0), or SHADER_VIEW_OVERDRAW: the texture holds counts */
} present_pass_options;

typedef struct present_pass {
    GLuint program;
    GLint u_accum, u_tonemap, u_exposure, u_view;
} present_pass;

bool present_pass_create(present_pass *p);
void present_pass_destroy(present_pass *p);
void present_pass_draw(const present_pass *p, GLuint texture, GLuint target, int width, int height,
                       const present_pass_options *options);

#endif
