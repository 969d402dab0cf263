/* gen_rng.h - gen_scenes's own small PRNG (xorshift32): the same numbers on every platform.
 *
 *   gen_rng_next_u32(r)                        the next 32-bit state
 *   gen_rng_uniform(r, lo, hi)                 uniform in [lo, hi), 24 bits of resolution
 *   gen_rng_below(r, n)                        an integer in [0, n), n > 0
 *   gen_rng_color(r, saturation_lo, saturation_hi, out)
 *                                              a random hue with its brightest channel at 1
 *
 * Seed it by setting .state (never 0). It is deliberately not common/light.c's splitmix64: the
 * committed scenes were drawn from this one, and any other sequence would change them.
 */
#ifndef TOOLS_GEN_SCENES_GEN_RNG_H
#define TOOLS_GEN_SCENES_GEN_RNG_H

#include <stdint.h>

typedef struct gen_rng {
    uint32_t state;
} gen_rng;

uint32_t gen_rng_next_u32(gen_rng *r);
double gen_rng_uniform(gen_rng *r, double lo, double hi);
int gen_rng_below(gen_rng *r, int n);
void gen_rng_color(gen_rng *r, double saturation_lo, double saturation_hi, double out[3]);

#endif
