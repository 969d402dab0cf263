/* tile_cull.h - chapter 10's light culling on the CPU, GL-free except for tile_bind_view: the C twin
 * of shaders/tiled_cull.glsl, for the chapter's GL 3.3 path (chapters/10_tiled_deferred.c, which
 * shows how the frame uses it). Kept beside the chapter, not in common/: no other chapter culls tiles.
 *
 *   tile_sphere(light, view, out)             a light's bounding sphere in view space (a spot's
 *                                             around its cone), grown by 1e-4 of the distances so
 *                                             that float rounding never cuts a light
 *   tile_frustum_make(view, x, y, size, depth, f)
 *                                             the piece of the view behind the size x size pixel
 *                                             tile whose bottom-left pixel is (x, y) (cut at the
 *                                             view's edge), its surfaces at view depths depth[0..1]
 *   tile_sphere_visible(f, sphere)            whether the sphere can reach that piece (conservative)
 *   tile_bind_view(program, view)             the view uniforms of the chapter's two culling
 *                                             programs (tiled_cull.comp, tile_depth_bounds.frag), in use
 */
#ifndef CHAPTERS_TILE_CULL_H
#define CHAPTERS_TILE_CULL_H

#include "gpu_scene.h"

/* A tile's piece of the view: four side planes (unit normals, inside >= 0), the depths of its
 * surfaces (distances in front of the eye), the box around it; all in view space. */
typedef struct tile_frustum {
    vec4 side[4];
    float depth[2];
    vec3 lo, hi;
} tile_frustum;

void tile_sphere(const gpu_light *light, const frame_view *view, vec4 out);
void tile_frustum_make(const frame_view *view, int x, int y, int size, const float depth[2], tile_frustum *f);
bool tile_sphere_visible(const tile_frustum *f, const vec4 sphere);
void tile_bind_view(GLuint program, const frame_view *view);

#endif
