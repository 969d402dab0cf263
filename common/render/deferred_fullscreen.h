/* deferred_fullscreen.h - chapter 03's lighting pass: a full-screen triangle that shades every
 * covered pixel of a G-buffer with every light (shaders/deferred_fullscreen.frag).
 *
 *   deferred_fullscreen_create(d, defines)         compile the lighting program (`defines`:
 *                                                  VIEW_REACH for chapter 03's reach view,
 *                                                  VIEW_OVERDRAW for its overdraw view, or NULL)
 *   deferred_fullscreen_destroy(d)
 *   deferred_fullscreen_render(d, g, gs, target, options)
 *                                                  clear the framebuffer `target`'s colour to black
 *                                                  and light g's pixels into it (no depth test, no
 *                                                  blending); leaves gl_pass_state_reset()'s state
 *   deferred_fullscreen_shaded_pixels(d)           pixels the last pass shaded (GL_SAMPLES_PASSED),
 *                                                  when options.count_pixels; background is not counted
 */
#ifndef COMMON_DEFERRED_FULLSCREEN_H
#define COMMON_DEFERRED_FULLSCREEN_H

#include "gbuffer.h"
#include "gpu_scene.h"

typedef struct deferred_fullscreen_options {
    bool count_pixels; /* a GL_SAMPLES_PASSED query around the lighting pass */
} deferred_fullscreen_options;

typedef struct deferred_fullscreen {
    GLuint program;
    GLuint query;
    long shaded_pixels; /* -1 until counted */
} deferred_fullscreen;

bool deferred_fullscreen_create(deferred_fullscreen *d, const char *defines);
void deferred_fullscreen_destroy(deferred_fullscreen *d);
bool deferred_fullscreen_render(deferred_fullscreen *d, const gbuffer *g, const gpu_scene *gs, GLuint target,
                                deferred_fullscreen_options options);
long deferred_fullscreen_shaded_pixels(const deferred_fullscreen *d);

#endif
