/* light.h - point-light attenuation and the radius where it falls below the cut-off.
 *
 *   light_attenuation(kc, kl, kq, d)          1 / (kc + kl d + kq d^2)
 *   light_radius(kc, kl, kq, peak, cutoff)    distance r where peak * f(r) == cutoff
 *   light_peak(color, intensity)              intensity * max(color)
 *   light_generate(scene, count, seed)        replace a scene's lights by `count` deterministic ones
 *   light_generate_bounds(scene, lo, hi)      the box light_generate places lights in
 *   light_generate_radius(lo, hi, count)      the radius light_generate gives each light
 *
 * light_radius returns 0 when the light never reaches the cut-off (peak / kc <= cutoff:
 * cull it), INFINITY when it never falls to it (cutoff == 0, or kl == kq == 0 with
 * peak / kc > cutoff); a black light (peak == 0) is 0 even with cutoff == 0. It never
 * overflows or returns NaN for finite, non-negative input, whatever the magnitudes
 * (1e-300 .. 1e300): INFINITY only when r itself exceeds DBL_MAX. Relative error is a few
 * ulps. Negative, NaN or infinite input is a caller error (the scene loader rejects it)
 * and gives NAN.
 *
 * light_generate is the same on every machine for a given seed (common/base/rng.h). It
 * frees the old lights' keys, and returns false only when out of memory (or count < 0),
 * leaving the scene unchanged. Each light:
 *   position   uniform in light_generate_bounds: the objects' extents (position, keys
 *              included, +- |scale| times 0.5 for cubes and planes, times 1 for spheres and
 *              models; a model directive's part: the corners of +-1 through its world matrix,
 *              node matrix included) widened by 10% of the box side on each axis, or a 10 x 10 square around the
 *              camera target when there are no objects; y always from 0.1 to the box top + 1
 *              (at least 1.1)
 *   color      a random hue, saturation 0.7..1, largest component exactly 1; intensity 1
 *   kc, kl, kq 1, 0, and kq chosen so that the radius at LIGHT_DEFAULT_CUTOFF is
 *              R = clamp(extent * 1.5 / sqrt(count), 0.5, extent), extent = the box's largest
 *              side, i.e. kq = (1 / cutoff - 1) / R^2: the lights share the scene evenly
 */
#ifndef COMMON_LIGHT_H
#define COMMON_LIGHT_H

#include <stdbool.h>
#include <stdint.h>

#define LIGHT_DEFAULT_CUTOFF (5.0 / 256.0)

struct scene;

double light_attenuation(double kc, double kl, double kq, double d);
double light_radius(double kc, double kl, double kq, double peak, double cutoff);
double light_peak(const float color[3], double intensity);
bool light_generate(struct scene *s, int count, uint32_t seed);
void light_generate_bounds(const struct scene *s, float lo[3], float hi[3]);
double light_generate_radius(const float lo[3], const float hi[3], int count);

#endif
