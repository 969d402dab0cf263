/* bench_format.c - see bench_format.h. */
#include "bench_format.h"

#include <math.h>
#include <stdio.h>

const char *bench_format_change(double v, int decimals, char *out, size_t size)
{
    if (isnan(v)) {
        snprintf(out, size, "–");
        return out;
    }
    /* what rounds to zero has no sign: "-0.0" and "+0.0" would both read as a change */
    double half_unit = 0.5 * pow(10.0, -decimals);
    if (fabs(v) < half_unit)
        snprintf(out, size, "%.*f", decimals, 0.0);
    else
        snprintf(out, size, "%+.*f", decimals, v);
    return out;
}
