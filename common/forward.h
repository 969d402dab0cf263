/* forward.h - chapter 00's forward renderer, shared so every chapter can switch to it.
 *
 *   forward_create(f)                       compile the shaders
 *   forward_destroy(f)
 *   forward_render(f, gs, options)          draw gs into the bound framebuffer (cleared here)
 *   forward_shaded_pixels(f)                fragments that passed the depth test in the last
 *                                           shading pass (GL_SAMPLES_PASSED), when counting is on
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

/* Uniform locations of one shading program (the display-encoded one or the linear one). */
typedef struct forward_locations {
    gpu_object_uniforms object;
    GLint view_proj, eye, albedo, specular, shininess, use_list, light_list, list_offset, list_count;
} forward_locations;

typedef struct forward {
    GLuint program, depth_program, linear_program;
    GLuint list_buffer, list_texture;
    GLuint query;
    int *list;      /* light indices, object after object */
    int *offsets;   /* per object: first index in list, and count */
    int *counts;
    size_t list_cap;
    int object_cap;
    long list_entries; /* sum of list lengths in the last frame */
    long shaded_pixels;
    struct {
        gpu_object_uniforms object, depth_object;
        GLint view_proj, depth_view_proj, eye, albedo, specular, shininess, use_list, light_list, list_offset,
            list_count;
    } loc;
    forward_locations linear_loc;
} forward;

bool forward_create(forward *f);
void forward_destroy(forward *f);
bool forward_render(forward *f, const gpu_scene *gs, forward_options options);
long forward_shaded_pixels(const forward *f);

#endif
