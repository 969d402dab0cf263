/* forward.h - chapter 00's forward renderer, shared so every chapter can switch to it.
 *
 *   forward_create(f)                       compile the shaders
 *   forward_destroy(f)
 *   forward_render(f, gs, target, options)  draw gs into the framebuffer `target` (cleared here):
 *                                           the three passes below with the state they need;
 *                                           leaves gl_pass_state_reset()'s state
 *   forward_build_light_lists(f, gs)        per object, the lights that reach it, uploaded
 *   forward_draw_depth(f, gs)               every object into the depth buffer only
 *   forward_draw_shaded(f, gs, options)     every object shaded (lists when options.light_lists),
 *                                           with whatever depth state the caller set
 *   forward_shaded_pixels(f)                fragments that passed the depth test in the last
 *                                           shading pass (GL_SAMPLES_PASSED), when counting is on
 *
 * Objects are drawn in batches (gpu_scene_draw): one instanced draw per run of objects sharing a mesh.
 * Depth ties: every pass that draws the scene uses GL_LEQUAL, so where two surfaces have exactly
 * the same depth the one drawn last wins, with or without a pre-pass and in the G-buffer alike.
 *
 * Options are the honest optimisations a forward renderer turns on:
 *   prepass      depth-only pass first, then shade with GL_EQUAL: each pixel shaded once
 *   light_lists  per object, only the lights whose sphere reaches the object's bounding sphere
 * and one that changes the output, not the speed:
 *   linear_output  write linear radiance, unclamped and not display-encoded, for a float target
 *                  (the benchmark's HDR error); a second program built with OUTPUT_LINEAR
 */
#ifndef COMMON_FORWARD_H
#define COMMON_FORWARD_H

#include "gpu_scene.h"

typedef struct forward_options {
    bool prepass;
    bool light_lists;
    bool count_pixels;
    bool linear_output;
} forward_options;

typedef struct forward {
    GLuint program, depth_program, linear_program;
    GLuint list_buffer, list_texture;
    GLuint query;
    int *list;         /* per object (first, count), then the light indices, object after object */
    size_t list_cap;
    long list_entries; /* sum of list lengths in the last frame */
    long shaded_pixels;
} forward;

bool forward_create(forward *f);
void forward_destroy(forward *f);
bool forward_render(forward *f, const gpu_scene *gs, GLuint target, forward_options options);
bool forward_build_light_lists(forward *f, const gpu_scene *gs);
void forward_draw_depth(const forward *f, const gpu_scene *gs);
bool forward_draw_shaded(forward *f, const gpu_scene *gs, forward_options options);
long forward_shaded_pixels(const forward *f);

#endif
