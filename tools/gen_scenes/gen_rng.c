/* gen_rng.c - xorshift32 and the draws the scene recipes make from it. */
#include "gen_rng.h"

#include <string.h>

uint32_t gen_rng_next_u32(gen_rng *r)
{
    uint32_t x = r->state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    r->state = x;
    return x;
}

/* 24 bits are exact in a float and plenty here. */
double gen_rng_uniform(gen_rng *r, double lo, double hi)
{
    return lo + (hi - lo) * (double)(gen_rng_next_u32(r) >> 8) / 16777216.0;
}

int gen_rng_below(gen_rng *r, int n)
{
    return (int)(gen_rng_next_u32(r) % (uint32_t)n);
}

/* A saturated but not garish colour with its brightest channel at 1, so a light's intensity
 * alone sets its peak. */
void gen_rng_color(gen_rng *r, double saturation_lo, double saturation_hi, double out[3])
{
    double h = gen_rng_uniform(r, 0.0, 6.0);
    double s = gen_rng_uniform(r, saturation_lo, saturation_hi);
    int sector = (int)h;
    double f = h - sector;
    double p = 1.0 - s, q = 1.0 - s * f, t = 1.0 - s * (1.0 - f);
    double rgb[6][3] = {{1, t, p}, {q, 1, p}, {p, 1, t}, {p, q, 1}, {t, p, 1}, {1, p, q}};
    memcpy(out, rgb[sector % 6], sizeof rgb[0]);
}
