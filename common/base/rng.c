/* rng.c - see rng.h. */
#include "rng.h"

rng rng_seed(uint32_t seed) { return (rng){.state = seed ? seed : 0x9e3779b9u}; }

uint32_t rng_next(rng *r)
{
    uint32_t x = r->state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    r->state = x;
    return x;
}

/* 24 bits: exact in a float, and the scene files print fewer digits than that. */
double rng_unit(rng *r) { return (double)(rng_next(r) >> 8) / 16777216.0; }

double rng_uniform(rng *r, double lo, double hi) { return lo + (hi - lo) * rng_unit(r); }

int rng_below(rng *r, int n) { return (int)(rng_next(r) % (uint32_t)n); }
