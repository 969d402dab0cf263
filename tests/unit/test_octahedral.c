/* test_octahedral.c - the G-buffer's normal encoding (shaders/octahedral.glsl) mirrored in C:
 * how many degrees does storing a normal as two half floats cost? Directions: a dense Fibonacci
 * sphere plus the hard places (poles, axes, the equator where the lower half folds over, the
 * axis lines of the lower half where the fold changes sign). Prints the numbers quoted in
 * docs/02_mrt_gbuffer.md. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include <cmocka.h>

#include "test_util.h"

/* The bound the course promises for the RGBA16F target (lighting must agree to 1/255). */
#define MAX_ERROR_DEG 0.05
/* Without storage the round trip is float arithmetic only. */
#define EXACT_ERROR_DEG 1e-3
#define FIBONACCI_COUNT 200000
#define RAD_TO_DEG (180.0 / 3.14159265358979323846)

/* ---- the mirror of shaders/octahedral.glsl, in float like the GPU ---------------------------- */

static float sign_not_zero(float v) { return v >= 0.0f ? 1.0f : -1.0f; }

static void octahedral_encode(const float n[3], float out[2])
{
    float l1 = fabsf(n[0]) + fabsf(n[1]) + fabsf(n[2]);
    float px = n[0] / l1, py = n[1] / l1;
    if (n[2] >= 0.0f) {
        out[0] = px, out[1] = py;
    } else {
        out[0] = (1.0f - fabsf(py)) * sign_not_zero(px);
        out[1] = (1.0f - fabsf(px)) * sign_not_zero(py);
    }
}

static void octahedral_decode(const float e[2], float out[3])
{
    float x = e[0], y = e[1], z = 1.0f - fabsf(e[0]) - fabsf(e[1]);
    if (z < 0.0f) {
        float fx = (1.0f - fabsf(y)) * sign_not_zero(x);
        float fy = (1.0f - fabsf(x)) * sign_not_zero(y);
        x = fx, y = fy;
    }
    float len = sqrtf(x * x + y * y + z * z);
    out[0] = x / len, out[1] = y / len, out[2] = z / len;
}

/* ---- IEEE half precision: round to nearest, ties to even, subnormals kept ------------------- */

/* Spacing of half floats around x: 2^(e-10) for 2^e <= |x| < 2^(e+1), 2^-24 below 2^-14. */
static float half_spacing(float x)
{
    if (x == 0.0f)
        return ldexpf(1.0f, -24);
    int k;
    frexpf(x, &k); /* |x| = m 2^k, m in [0.5, 1): the leading bit is 2^(k-1) */
    int e = k - 1 < -14 ? -14 : k - 1;
    return ldexpf(1.0f, e - 10); /* 10 stored mantissa bits */
}

/* The half float nearest to x (|x| <= 65504), returned as a float (every half is a float). */
static float half_round(float x)
{
    if (x == 0.0f || !isfinite(x))
        return x;
    float s = half_spacing(x);
    return nearbyintf(x / s) * s; /* exact division by a power of two; default mode: ties even */
}

/* octahedral_encode_half: the best of the four half-float pairs around the exact encoding. */
static void octahedral_encode_half(const float n[3], float out[2])
{
    float e[2], lo[2], s[2], best = 1e30f;
    octahedral_encode(n, e);
    for (int k = 0; k < 2; k++) {
        s[k] = half_spacing(e[k]);
        lo[k] = floorf(e[k] / s[k]) * s[k];
    }
    for (int i = 0; i < 4; i++) {
        float c[2] = {fminf(fmaxf(lo[0] + (float)(i & 1) * s[0], -1.0f), 1.0f),
                      fminf(fmaxf(lo[1] + (float)(i >> 1) * s[1], -1.0f), 1.0f)};
        float r[3];
        octahedral_decode(c, r);
        /* Distance, not dot product: cos of 0.01 degrees is 1 - 1.5e-8, below float's resolution. */
        float dx = r[0] - n[0], dy = r[1] - n[1], dz = r[2] - n[2];
        float d = dx * dx + dy * dy + dz * dz;
        if (d < best) {
            best = d;
            out[0] = c[0], out[1] = c[1];
        }
    }
}

static void test_half_round(void **unused)
{
    (void)unused;
    assert_true(half_round(1.0f) == 1.0f);
    assert_true(half_round(0.1f) == 0.0999755859375f);           /* 0x2E66 */
    assert_true(half_round(65504.0f) == 65504.0f);               /* largest half */
    assert_true(half_round(ldexpf(1.0f, -24)) == ldexpf(1.0f, -24)); /* smallest subnormal */
    assert_true(half_round(ldexpf(1.0f, -26)) == 0.0f);          /* below half of it */
    assert_true(half_round(1.0f + ldexpf(1.0f, -11)) == 1.0f);   /* tie goes to even */
    assert_true(half_round(1.0f + 3.0f * ldexpf(1.0f, -11)) == 1.0f + ldexpf(1.0f, -9));
    assert_true(half_round(-0.333333f) == -0.333251953125f);     /* 0xB555 */
}

/* ---- measuring --------------------------------------------------------------------------- */

typedef struct error_stats {
    double max_deg, sum_deg;
    long count;
    double worst[3];
} error_stats;

/* Angle between unit vectors, accurate near 0 (acos is not). */
static double angle_deg(const double a[3], const float b[3])
{
    double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    double s = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    return atan2(s, d) * RAD_TO_DEG;
}

typedef enum storage { STORE_FLOAT, STORE_HALF_NEAREST, STORE_HALF_BEST } storage;

/* Encode direction d, store it (float, half rounded alone, or best half pair), decode, and
 * accumulate the error. */
static void measure(double x, double y, double z, storage store, error_stats *st)
{
    double len = sqrt(x * x + y * y + z * z);
    double d[3] = {x / len, y / len, z / len};
    float n[3] = {(float)d[0], (float)d[1], (float)d[2]}, e[2], r[3];
    if (store == STORE_HALF_BEST)
        octahedral_encode_half(n, e);
    else
        octahedral_encode(n, e);
    assert_true(fabsf(e[0]) <= 1.0f && fabsf(e[1]) <= 1.0f);
    if (store != STORE_FLOAT) {
        /* What the RGBA16F store does; a no-op for STORE_HALF_BEST's exact half floats. */
        float h[2] = {half_round(e[0]), half_round(e[1])};
        if (store == STORE_HALF_BEST)
            assert_true(h[0] == e[0] && h[1] == e[1]);
        e[0] = h[0], e[1] = h[1];
    }
    octahedral_decode(e, r);
    double err = angle_deg(d, r);
    if (err > st->max_deg) {
        st->max_deg = err;
        st->worst[0] = d[0], st->worst[1] = d[1], st->worst[2] = d[2];
    }
    st->sum_deg += err;
    st->count++;
}

/* Fibonacci sphere (even coverage, both poles approached) plus the special directions. */
static void measure_all(storage store, error_stats *st)
{
    const double golden_angle = 3.14159265358979323846 * (3.0 - sqrt(5.0));
    for (int i = 0; i < FIBONACCI_COUNT; i++) {
        double z = 1.0 - (2.0 * i + 1.0) / FIBONACCI_COUNT;
        double r = sqrt(1.0 - z * z), phi = golden_angle * i;
        measure(r * cos(phi), r * sin(phi), z, store, st);
    }
    static const double axes[][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0},
                                     {1, 1, -1}, {-1, 1, -1}, {1, -1, -1}, {-1, -1, -1}, {1, 1, 0}};
    for (size_t i = 0; i < sizeof axes / sizeof axes[0]; i++)
        measure(axes[i][0], axes[i][1], axes[i][2], store, st);
    /* The fold (equator, just above and below) and the lower half's axis planes x = 0, y = 0. */
    static const double heights[] = {0.0, 1e-7, -1e-7, 1e-3, -1e-3};
    for (int i = 0; i < 4096; i++) {
        double a = 2.0 * 3.14159265358979323846 * i / 4096;
        for (size_t h = 0; h < sizeof heights / sizeof heights[0]; h++)
            measure(cos(a), sin(a), heights[h], store, st);
        double t = -fabs(sin(a)); /* lower half only */
        measure(0.0, cos(a), t, store, st);
        measure(cos(a), 0.0, t, store, st);
        measure(1e-6 * cos(a), 1e-6 * sin(a), -1.0, store, st); /* around the lower pole */
    }
}

static void test_round_trip_exact(void **unused)
{
    (void)unused;
    error_stats st = {0};
    measure_all(STORE_FLOAT, &st);
    printf("octahedral, float only:      %ld directions, mean %.6f deg, max %.6f deg\n", st.count,
           st.sum_deg / st.count, st.max_deg);
    assert_true(st.max_deg < EXACT_ERROR_DEG);
}

static void test_round_trip_half(void **unused)
{
    (void)unused;
    error_stats nearest = {0}, best = {0};
    measure_all(STORE_HALF_NEAREST, &nearest);
    measure_all(STORE_HALF_BEST, &best);
    printf("octahedral, half, rounded:   %ld directions, mean %.6f deg, max %.6f deg at (%.4f, %.4f, %.4f)\n",
           nearest.count, nearest.sum_deg / nearest.count, nearest.max_deg, nearest.worst[0],
           nearest.worst[1], nearest.worst[2]);
    printf("octahedral, half, best pair: %ld directions, mean %.6f deg, max %.6f deg at (%.4f, %.4f, %.4f)\n",
           best.count, best.sum_deg / best.count, best.max_deg, best.worst[0], best.worst[1], best.worst[2]);
    /* The G-buffer's encoder (octahedral_encode_half) keeps the promise. */
    assert_true(best.max_deg < MAX_ERROR_DEG);
    /* It beats rounding each number alone, which it exists for... */
    assert_true(best.max_deg < nearest.max_deg && best.sum_deg < nearest.sum_deg);
    /* ...and storage costs something: a mean of zero would mean half_round did nothing. */
    assert_true(nearest.sum_deg / nearest.count > 1e-5);
}

/* The poles and the fold land where the mapping says: lower pole on a corner, equator on the
 * diamond's edge, and the decoded directions are those points exactly. */
static void test_special_points(void **unused)
{
    (void)unused;
    float e[2], r[3];
    const float down[3] = {0, 0, -1}, up[3] = {0, 0, 1}, east[3] = {1, 0, 0}, south[3] = {0, -1, 0};
    octahedral_encode(down, e);
    assert_true(fabsf(e[0]) == 1.0f && fabsf(e[1]) == 1.0f);
    octahedral_decode(e, r);
    assert_true(r[2] == -1.0f);
    octahedral_encode(up, e);
    assert_true(e[0] == 0.0f && e[1] == 0.0f);
    octahedral_encode(east, e);
    assert_true(e[0] == 1.0f && e[1] == 0.0f);
    octahedral_encode(south, e);
    assert_true(e[0] == 0.0f && e[1] == -1.0f);
    octahedral_decode(e, r);
    assert_true(r[1] == -1.0f && fabsf(r[0]) < 1e-7f && fabsf(r[2]) < 1e-7f);
}

UNIT_TEST_MAIN(NULL, NULL, cmocka_unit_test(test_half_round), cmocka_unit_test(test_special_points),
               cmocka_unit_test(test_round_trip_exact), cmocka_unit_test(test_round_trip_half))
