/* gen_color.c - see gen_color.h. */
#include "gen_color.h"

#include <string.h>

/* HSV with value 1: a saturated but not garish colour. */
void gen_color_random(rng *r, double saturation_lo, double saturation_hi, double out[3])
{
    double h = rng_uniform(r, 0.0, 6.0);
    double s = rng_uniform(r, saturation_lo, saturation_hi);
    int sector = (int)h;
    double f = h - sector;
    double p = 1.0 - s, q = 1.0 - s * f, t = 1.0 - s * (1.0 - f);
    double rgb[6][3] = {{1, t, p}, {q, 1, p}, {p, 1, t}, {p, q, 1}, {t, p, 1}, {1, p, q}};
    memcpy(out, rgb[sector % 6], sizeof rgb[0]);
}
