/* ao_reference.h - ambient occlusion, exactly: the answer chapter 17's SSAO estimates, traced in
 * double precision through ray_scene.h. For a pixel, a ray from the eye through its centre finds the
 * surface; G x G rays leave it over the hemisphere about its normal, cosine-weighted and stratified
 * (one jittered ray per cell of the unit square, mapped to the disc and lifted), each asking whether
 * anything lies within the radius. The share that leave freely is the occlusion A (1: open, 0: shut),
 * what the chapter's --view ao shows in its red channel. Its own noise is measured as it goes: a
 * second set of jitters on every 4th pixel (in raster order) that sees a surface.
 * hard.ssao_reference (tests/ssao/) and the benchmark's --ambient-sweep both measure against it.
 *
 *   ao_reference_begin(a, rays, view_proj, eye, width, height, radius, side)
 *                                 a reference for the view (view_proj and eye as gpu_scene's view
 *                                 holds them) at width x height, side x side rays per pixel
 *   ao_reference_pixel(a, x, y, p) A at pixel (x, y) (0, 0 the bottom left, as GL reads back), and
 *                                 the surface point into p (may be NULL); -1 where no surface is.
 *                                 The jitters come from one sequence: call the pixels in the same
 *                                 order for the same figures
 *   ao_reference_noise(a, &mean, &max)
 *                                 the largest and the mean difference between the two sets of
 *                                 jitters so far; false when no pixel was checked
 */
#ifndef TOOLS_AO_REFERENCE_H
#define TOOLS_AO_REFERENCE_H

#include "ray_scene.h"
#include "rng.h"

#include <stdbool.h>

typedef struct ao_reference {
    const ray_scene *rays;
    double inv_view_proj[16], eye[3], radius;
    int width, height, side;
    rng jitter, again;
    double noise_sum, noise_max;
    long noise_count;
} ao_reference;

void ao_reference_begin(ao_reference *a, const ray_scene *rays, const float view_proj[16], const float eye[3],
                        int width, int height, double radius, int side);
double ao_reference_pixel(ao_reference *a, int x, int y, double p[3]);
bool ao_reference_noise(const ao_reference *a, double *mean, double *max);

#endif
