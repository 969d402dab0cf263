/* shadow_views.h - chapter 14's window views of its atlas, in one colour scale: each light's tier,
 * the size the plan gave its tiles after fitting the atlas (shaders/shadow_debug.frag; grey: a light
 * without a shadow).
 *
 *   shadow_views_create(v)                       the program, its item table and an empty vertex array
 *   shadow_views_destroy(v)
 *   shadow_views_draw_atlas(v, s, width, height) --view atlas: the whole atlas in the middle square of
 *                                                the bound framebuffer (cleared black), each tile's
 *                                                depth tinted by its light's tier
 *   shadow_views_draw_lights(v, s, gs, width, height)
 *                                                --view importance: over the bound framebuffer's
 *                                                picture, a disc at each light in front of the eye,
 *                                                in the same colours
 *   shadow_views_overlay(s, out, size)           the overlay's line: shadows on or off, the lights
 *                                                shadowed, dropped, off and not chosen, the tiles and
 *                                                how many were drawn this frame
 */
#ifndef CHAPTERS_SHADOW_VIEWS_H
#define CHAPTERS_SHADOW_VIEWS_H

#include "shadow_atlas.h"

#include <stddef.h>

typedef struct shadow_views {
    GLuint program, vertex_array, item_buffer, item_texture;
    float *items;
    int item_cap; /* texels */
} shadow_views;

bool shadow_views_create(shadow_views *v);
void shadow_views_destroy(shadow_views *v);
bool shadow_views_draw_atlas(shadow_views *v, const shadow_atlas *s, int width, int height);
bool shadow_views_draw_lights(shadow_views *v, const shadow_atlas *s, const gpu_scene *gs, int width, int height);
void shadow_views_overlay(const shadow_atlas *s, char *out, size_t size);

#endif
