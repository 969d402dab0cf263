/* ssao_kernel.h - chapter 17's two random inputs to the SSAO pass, made once at start-up with the
 * course's rng (common/base/rng.h) instead of shipped as data. Kept beside the chapter, not in
 * common/: no other chapter uses them.
 *
 *   ssao_kernel_make(r, samples, kernel)  `samples` unit directions about z (the normal in the
 *                                         shader's frame), cosine-weighted and stratified in the
 *                                         cosine, so that even 4 span the hemisphere
 *   ssao_noise_create(r)                  the SHADER_AO_NOISE_SIZE^2 noise tile, RG32F: per pixel the
 *                                         (cos, sin) of its turn about the normal, the circle's
 *                                         SHADER_AO_NOISE_SIZE^2 angles in a random order; 0 on failure
 */
#ifndef CHAPTERS_SSAO_KERNEL_H
#define CHAPTERS_SSAO_KERNEL_H

#include "rng.h"

#include <glad/gl.h>

void ssao_kernel_make(rng *r, int samples, float kernel[][3]);
GLuint ssao_noise_create(rng *r);

#endif
