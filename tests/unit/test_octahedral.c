/* test_octahedral.c - the G-buffer's normal encoding (shaders/octahedral.glsl) mirrored in C:
 * how many degrees does storing a normal as two half floats cost, or as two fixed-point codes of
 * 8, 12 or 16 bits (the other layouts of common/render/gbuffer.h)? Directions: a dense Fibonacci
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

/* ---- fixed-point codes: octahedral_encode_codes, gbuffer.frag's packing and shininess ------------- */

/* A code q in [0, 2m] stands for (q - m) / m, m = 2^(bits-1) - 1: 0 and +-1 exact. */
static float code_m(int bits) { return (float)((1 << (bits - 1)) - 1); }

/* octahedral_encode_codes: the best of the four code pairs around the exact encoding (best), or
 * each number rounded to its nearest code alone. Returns the codes. */
static void octahedral_encode_codes(const float n[3], float m, bool best, float q[2])
{
    float e[2];
    octahedral_encode(n, e);
    if (!best) {
        q[0] = fminf(fmaxf(floorf(e[0] * m + m + 0.5f), 0.0f), 2.0f * m);
        q[1] = fminf(fmaxf(floorf(e[1] * m + m + 0.5f), 0.0f), 2.0f * m);
        return;
    }
    float lo[2] = {floorf(e[0] * m + m), floorf(e[1] * m + m)}, best_d = 1e30f;
    for (int i = 0; i < 4; i++) {
        float c[2] = {fminf(fmaxf(lo[0] + (float)(i & 1), 0.0f), 2.0f * m),
                      fminf(fmaxf(lo[1] + (float)(i >> 1), 0.0f), 2.0f * m)};
        float r[3], d[2] = {(c[0] - m) / m, (c[1] - m) / m};
        octahedral_decode(d, r);
        float dx = r[0] - n[0], dy = r[1] - n[1], dz = r[2] - n[2], d2 = dx * dx + dy * dy + dz * dz;
        if (d2 < best_d) {
            best_d = d2;
            q[0] = c[0], q[1] = c[1];
        }
    }
}

/* What a unorm channel of `levels` steps stores for a float written to it, and texelFetch returns. */
static float unorm_store(float v, float levels)
{
    return floorf(fminf(fmaxf(v, 0.0f), 1.0f) * levels + 0.5f) / levels;
}

/* gbuffer.frag's pack_12_12 and gbuffer_read.glsl's gbuffer_unpack_12_12, through an RGBA8 store. */
static void pack_12_12(const float q[2], float rgb[3])
{
    float hi[2] = {floorf(q[0] / 16.0f), floorf(q[1] / 256.0f)};
    float lo[2] = {q[0] - hi[0] * 16.0f, q[1] - hi[1] * 256.0f};
    rgb[0] = unorm_store(hi[0] / 255.0f, 255.0f);
    rgb[1] = unorm_store((lo[0] * 16.0f + hi[1]) / 255.0f, 255.0f);
    rgb[2] = unorm_store(lo[1] / 255.0f, 255.0f);
}

static void unpack_12_12(const float rgb[3], float q[2])
{
    float b[3];
    for (int k = 0; k < 3; k++)
        b[k] = floorf(rgb[k] * 255.0f + 0.5f);
    float x_lo = floorf(b[1] / 16.0f);
    q[0] = b[0] * 16.0f + x_lo;
    q[1] = (b[1] - x_lo * 16.0f) * 256.0f + b[2];
}

/* Every pair of 12-bit codes survives the three bytes exactly. */
static void test_pack_12_12(void **unused)
{
    (void)unused;
    long bad = 0;
    for (int x = 0; x <= 4094; x++)
        for (int y = 0; y <= 4094; y++) {
            float q[2] = {(float)x, (float)y}, rgb[3], back[2];
            pack_12_12(q, rgb);
            unpack_12_12(rgb, back);
            bad += back[0] != q[0] || back[1] != q[1];
        }
    assert_int_equal(bad, 0);
}

/* Shininess P = 1 + 255 c (gbuffer.frag's shininess_store): the integers 1..256 come back exactly
 * from 8 bits (the scenes use 8..256), to 1e-3 from 16 bits; others round, 300 clamps to 256.
 * Specular S in an 8-bit alpha: within 1/510. */
static void test_material_channels(void **unused)
{
    (void)unused;
    for (int p = 1; p <= 256; p++) {
        float c8 = unorm_store(((float)p - 1.0f) / 255.0f, 255.0f);
        float c16 = unorm_store(((float)p - 1.0f) / 255.0f, 65535.0f);
        assert_true(fabsf(1.0f + 255.0f * c8 - (float)p) < 1e-4f);
        assert_true(fabsf(1.0f + 255.0f * c16 - (float)p) < 1e-3f);
    }
    assert_true(fabsf(1.0f + 255.0f * unorm_store((24.3f - 1.0f) / 255.0f, 255.0f) - 24.0f) < 1e-4f);
    assert_true(fabsf(1.0f + 255.0f * unorm_store((300.0f - 1.0f) / 255.0f, 255.0f) - 256.0f) < 1e-4f);
    for (int i = 0; i <= 1000; i++) {
        float s = (float)i / 1000.0f;
        assert_true(fabsf(unorm_store(s, 255.0f) - s) <= 0.5f / 255.0f + 1e-7f);
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

typedef enum storage {
    STORE_FLOAT,
    STORE_HALF_NEAREST,
    STORE_HALF_BEST,
    STORE_CODES_NEAREST,
    STORE_CODES_BEST
} storage;

static int code_bits = 8; /* for STORE_CODES_*: the bits per number */

/* Encode direction d, store it (float, half rounded alone, or best half pair), decode, and
 * accumulate the error. */
static void measure(double x, double y, double z, storage store, error_stats *st)
{
    double len = sqrt(x * x + y * y + z * z);
    double d[3] = {x / len, y / len, z / len};
    float n[3] = {(float)d[0], (float)d[1], (float)d[2]}, e[2], r[3];
    if (store == STORE_HALF_BEST) {
        octahedral_encode_half(n, e);
    } else if (store == STORE_CODES_NEAREST || store == STORE_CODES_BEST) {
        float m = code_m(code_bits), q[2];
        octahedral_encode_codes(n, m, store == STORE_CODES_BEST, q);
        assert_true(q[0] >= 0.0f && q[0] <= 2.0f * m && q[1] >= 0.0f && q[1] <= 2.0f * m);
        e[0] = (q[0] - m) / m, e[1] = (q[1] - m) / m; /* what octahedral_decode_codes decodes */
    } else {
        octahedral_encode(n, e);
    }
    assert_true(fabsf(e[0]) <= 1.0f && fabsf(e[1]) <= 1.0f);
    if (store == STORE_HALF_NEAREST || store == STORE_HALF_BEST) {
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

/* Fixed-point codes, the layouts other than `reference` (common/render/gbuffer.h): bounds a little above
 * what was measured here (printed: max 0.638, 0.0396, 0.00247 degrees; mean 0.294, 0.0184,
 * 0.00114), so a change to the encoder that costs precision fails. Four more bits are 16 times
 * finer; 2 x 12 bits reach the half floats' maximum (their mean is 0.0131). */
static void test_round_trip_codes(void **unused)
{
    (void)unused;
    static const struct {
        int bits;
        double max_deg, mean_deg; /* bounds for the best-of-four codes */
    } cases[] = {{8, 0.66, 0.30}, {12, 0.041, 0.019}, {16, 0.0026, 0.0012}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        error_stats nearest = {0}, best = {0};
        code_bits = cases[k].bits;
        measure_all(STORE_CODES_NEAREST, &nearest);
        measure_all(STORE_CODES_BEST, &best);
        printf("octahedral, 2 x %2d bits, rounded:   mean %.6f deg, max %.6f deg\n", cases[k].bits,
               nearest.sum_deg / nearest.count, nearest.max_deg);
        printf("octahedral, 2 x %2d bits, best pair: mean %.6f deg, max %.6f deg at (%.4f, %.4f, %.4f)\n",
               cases[k].bits, best.sum_deg / best.count, best.max_deg, best.worst[0], best.worst[1],
               best.worst[2]);
        assert_true(best.max_deg < cases[k].max_deg);
        assert_true(best.sum_deg / best.count < cases[k].mean_deg);
        assert_true(best.max_deg < nearest.max_deg && best.sum_deg < nearest.sum_deg);
    }
}

/* The axes are codes exactly (the reason for the unused code): the floor's normal and a wall's
 * come back without error at every width. */
static void test_codes_axes_exact(void **unused)
{
    (void)unused;
    static const float axes[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int bits = 8; bits <= 16; bits += 4)
        for (int a = 0; a < 6; a++) {
            float m = code_m(bits), q[2] = {0, 0}, e[2], r[3];
            octahedral_encode_codes(axes[a], m, true, q);
            e[0] = (q[0] - m) / m, e[1] = (q[1] - m) / m;
            octahedral_decode(e, r);
            assert_true(r[0] == axes[a][0] && r[1] == axes[a][1] && r[2] == axes[a][2]);
        }
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
               cmocka_unit_test(test_pack_12_12), cmocka_unit_test(test_material_channels),
               cmocka_unit_test(test_round_trip_codes), cmocka_unit_test(test_codes_axes_exact),
               cmocka_unit_test(test_round_trip_exact), cmocka_unit_test(test_round_trip_half))
