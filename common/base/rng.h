/* rng.h - the course's one random generator: xorshift32 (Marsaglia 2003), tiny, and the same
 * sequence on every machine. The scene recipes (tools/gen_scenes) and the --lights generator
 * (light.c) both draw from it.
 *
 *   rng_seed(seed)            a generator (seed 0, which xorshift cannot leave, is replaced)
 *   rng_next(r)               the next 32 random bits
 *   rng_unit(r)               uniform in [0, 1), 24 random bits
 *   rng_uniform(r, lo, hi)    uniform in [lo, hi)
 *   rng_below(r, n)           an integer in [0, n), n > 0 (a remainder: its bias, under n / 2^32,
 *                             is far below anything a scene shows)
 */
#ifndef COMMON_RNG_H
#define COMMON_RNG_H

#include <stdint.h>

typedef struct rng {
    uint32_t state;
} rng;

rng rng_seed(uint32_t seed);
uint32_t rng_next(rng *r);
double rng_unit(rng *r);
double rng_uniform(rng *r, double lo, double hi);
int rng_below(rng *r, int n);

#endif
