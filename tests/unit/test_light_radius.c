/* test_light_radius.c - light_radius against a long double reference, its edge cases, and why the
 * textbook quadratic formula is not used. */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <time.h>

#include <cmocka.h>

#include "light.h"
#include "rng.h"
#include "test_util.h"

/* A few double roundings (frexp/ldexp are exact, then ~6 operations): 1e-12 is ~4500 ulps. */
#define RADIUS_TOLERANCE 1e-12

/* The same equation solved in long double (64-bit mantissa, 15-bit exponent so nothing here
 * overflows), then polished by Newton on g(r) = kq r^2 + kl r - c. */
static long double radius_reference(double kc, double kl, double kq, double peak, double cutoff)
{
    if (cutoff == 0.0)
        return peak == 0.0 ? 0.0L : (long double)INFINITY;
    /* peak - kc cutoff exactly: the double product fits in 106 bits, its long double rounding
     * error is recovered by fmal. */
    long double p = (long double)kc * cutoff;
    long double e = fmal(kc, cutoff, -p);
    long double c = (((long double)peak - p) - e) / cutoff;
    if (c <= 0.0L)
        return 0.0L;
    if (kq == 0.0) {
        if (kl == 0.0)
            return (long double)INFINITY;
        return c / kl;
    }
    long double r = 2.0L * c / (kl + sqrtl((long double)kl * kl + 4.0L * kq * c));
    for (int i = 0; i < 2; i++) {
        long double g = ((long double)kq * r + kl) * r - c;
        r -= g / (2.0L * kq * r + kl);
    }
    return r;
}

/* Fails the test with the inputs when light_radius and the reference disagree. */
static double check_radius(double kc, double kl, double kq, double peak, double cutoff)
{
    double r = light_radius(kc, kl, kq, peak, cutoff);
    long double ref = radius_reference(kc, kl, kq, peak, cutoff);
    double err = 0.0;
    bool ok;
    if (ref == 0.0L || isinf(ref) || ref > DBL_MAX) {
        ok = ref == 0.0L ? r == 0.0 : isinf(r);
    } else if (ref < DBL_MIN) {
        /* Subnormal: the output itself only has absolute precision. */
        ok = fabsl(r - ref) <= 2.0L * DBL_TRUE_MIN;
    } else {
        err = (double)(fabsl(r - ref) / ref);
        ok = isfinite(r) && err <= RADIUS_TOLERANCE;
    }
    if (!ok)
        fail_msg("light_radius(kc=%.17g, kl=%.17g, kq=%.17g, peak=%.17g, cutoff=%.17g) = %.17g, "
                 "reference %.20Lg, relative error %.3g",
                 kc, kl, kq, peak, cutoff, r, ref, err);
    return err;
}

/* The published table light (kc 1, kl 0.7, kq 1.8, peak 1). The expected radii were computed
 * independently with 50-digit decimal arithmetic from the exact double inputs. */
static void test_published_samples(void **state)
{
    (void)state;
    const struct {
        double cutoff, radius;
    } cases[] = {
        {5.0 / 256.0, 5.0901272062065519818},
        {1.0 / 256.0, 11.709524444486758244},
        {10.0 / 256.0, 3.5075111615349107721},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double r = light_radius(1.0, 0.7, 1.8, 1.0, cases[i].cutoff);
        assert_true(fabs(r - cases[i].radius) <= RADIUS_TOLERANCE * cases[i].radius);
        check_radius(1.0, 0.7, 1.8, 1.0, cases[i].cutoff);
    }
    /* LIGHT_DEFAULT_CUTOFF is the 5/256 row. */
    double r = light_radius(1.0, 0.7, 1.8, 1.0, LIGHT_DEFAULT_CUTOFF);
    assert_true(fabs(r - cases[0].radius) <= RADIUS_TOLERANCE * cases[0].radius);
}

static void test_small_quadratic_term(void **state)
{
    (void)state;
    const double kqs[] = {1e-8, 1e-12, 1e-20, 0.0};
    const double cutoffs[] = {5.0 / 256.0, 1.0 / 256.0, 0.5, 1e-9};
    for (size_t i = 0; i < sizeof kqs / sizeof kqs[0]; i++)
        for (size_t j = 0; j < sizeof cutoffs / sizeof cutoffs[0]; j++) {
            check_radius(1.0, 0.7, kqs[i], 1.0, cutoffs[j]);
            check_radius(1.0, 1e-6, kqs[i], 3.0, cutoffs[j]);
        }
    /* kq = 0 is exactly the linear solution. */
    assert_true(light_radius(1.0, 0.5, 0.0, 1.0, 0.25) == 6.0);
}

/* kq = 1e-12: the textbook root subtracts two nearly equal numbers. It must be visibly wrong
 * (> 1e-6 relative) where the stable form is still within 1e-12, or the test documents nothing. */
static void test_textbook_formula_cancels(void **state)
{
    (void)state;
    volatile double kc = 1.0, kl = 1.0, kq = 1e-12, peak = 1.0, cutoff = 0.5;
    double c = peak / cutoff - kc;
    double naive = (-kl + sqrt(kl * kl + 4.0 * kq * c)) / (2.0 * kq);
    long double ref = radius_reference(kc, kl, kq, peak, cutoff);
    double naive_err = (double)(fabsl(naive - ref) / ref);
    print_message("textbook formula at kq = 1e-12: relative error %.3g\n", naive_err);
    assert_true(naive_err > 1e-6);
    assert_true(check_radius(kc, kl, kq, peak, cutoff) <= RADIUS_TOLERANCE);
}

static void test_culled_and_unbounded(void **state)
{
    (void)state;
    /* peak / kc == cutoff exactly, and below it: the light never reaches the cut-off. */
    assert_true(light_radius(2.0, 0.7, 1.8, 1.0, 0.5) == 0.0);
    assert_true(light_radius(1.0, 0.7, 1.8, 5.0 / 256.0, 5.0 / 256.0) == 0.0);
    assert_true(light_radius(1.0, 0.0, 0.0, 5.0 / 256.0, 5.0 / 256.0) == 0.0);
    assert_true(light_radius(1.0, 0.7, 1.8, 0.01, 5.0 / 256.0) == 0.0);
    assert_true(light_radius(1e300, 1.0, 1.0, 1e-300, 1e-300) == 0.0);
    /* Barely brighter than the cut-off: tiny but positive. */
    check_radius(1.0, 0.7, 1.8, 1.0 + 0x1.0p-52, 1.0);
    check_radius(1.0, 0.7, 1.8, 0.1000000001, 0.1); /* peak / cutoff rounds; c keeps its digits */
    check_radius(3.0, 0.0, 1e-3, 0.3 * (1.0 + 1e-12), 0.1);
    assert_true(light_radius(1.0, 0.7, 1.8, 1.0 + 0x1.0p-52, 1.0) > 0.0);
    /* Constant light above the cut-off never falls to it. */
    assert_true(isinf(light_radius(1.0, 0.0, 0.0, 1.0, 5.0 / 256.0)));
    /* No cut-off: exact mode, unless the light is black. */
    assert_true(isinf(light_radius(1.0, 0.7, 1.8, 1.0, 0.0)));
    assert_true(light_radius(1.0, 0.7, 1.8, 0.0, 0.0) == 0.0);
    assert_true(light_radius(1.0, 0.7, 1.8, 0.0, 5.0 / 256.0) == 0.0);
    /* kc = 0: f is infinite at the light, the radius still finite. */
    check_radius(0.0, 0.7, 1.8, 1.0, 5.0 / 256.0);
}

static void test_extreme_magnitudes(void **state)
{
    (void)state;
    check_radius(1.0, 0.7, 1.8, 1e30, 5.0 / 256.0);
    check_radius(1.0, 0.7, 1.8, 1e-30, 1e-33);
    check_radius(1e-300, 1e-300, 1e-300, 1e300, 1e-300);
    check_radius(0.0, 0.0, 1.0, 1e300, 1e-300); /* c = 1e600 overflows, r = 1e300 does not */
    assert_true(isfinite(light_radius(0.0, 0.0, 1.0, 1e300, 1e-300)));
    check_radius(0.0, 1e300, 0.0, 1e300, 1e-300);
    check_radius(1e300, 1e300, 1e300, 1e300, 1e-300);
    check_radius(0.0, 1e-300, 1e300, 1e-300, 1e300);
    check_radius(0.0, 1e300, 1e-300, 1e-300, 1e-300);
    /* Truly beyond DBL_MAX: INFINITY, not NaN. */
    assert_true(isinf(light_radius(0.0, 0.0, 1e-300, 1e300, 1e-300)));
    assert_true(isinf(light_radius(0.0, 1e-300, 0.0, 1e300, 1.0)));
    check_radius(0.0, DBL_TRUE_MIN, DBL_TRUE_MIN, DBL_MAX, DBL_TRUE_MIN);
    check_radius(DBL_TRUE_MIN, DBL_MAX, DBL_MAX, DBL_MAX, DBL_TRUE_MIN);
}

static void test_invalid_input_is_nan(void **state)
{
    (void)state;
    const double bad[] = {-1.0, -0x1.0p-1074, NAN, INFINITY, -INFINITY};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        assert_true(isnan(light_radius(bad[i], 0.7, 1.8, 1.0, 0.1)));
        assert_true(isnan(light_radius(1.0, bad[i], 1.8, 1.0, 0.1)));
        assert_true(isnan(light_radius(1.0, 0.7, bad[i], 1.0, 0.1)));
        assert_true(isnan(light_radius(1.0, 0.7, 1.8, bad[i], 0.1)));
        assert_true(isnan(light_radius(1.0, 0.7, 1.8, 1.0, bad[i])));
    }
}

/* The course's generator, for reproducible samples. */
static rng sample_rng = {0x5eed};

static double sample_unit(void) { return rng_unit(&sample_rng); }

/* 10^u, u uniform in [lo, hi]; `zero` of the time exactly 0. */
static double sample_log(double lo, double hi, double zero)
{
    if (sample_unit() < zero)
        return 0.0;
    return pow(10.0, lo + (hi - lo) * sample_unit());
}

static double sample_kq(void)
{
    double u = sample_unit();
    if (u < 0.05)
        return 1e-8;
    if (u < 0.10)
        return 1e-12;
    return sample_log(-16.0, 2.0, 0.1);
}

#define SAMPLE_COUNT 1000000

static void test_million_random_inputs(void **state)
{
    (void)state;
    if (LDBL_MANT_DIG < 64 || LDBL_MAX_EXP <= DBL_MAX_EXP) {
        print_message("long double is no wider than double here: no reference\n");
        skip();
    }
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    double worst = 0.0;
    int culled = 0;
    for (int i = 0; i < SAMPLE_COUNT; i++) {
        double kc, kl, kq, peak, cutoff;
        if (i % 10 != 0) { /* scenes: many decades around the usual values */
            kc = sample_log(-4.0, 2.0, 0.05);
            kl = sample_log(-12.0, 2.0, 0.1);
            kq = sample_kq();
            peak = sample_log(-3.0, 4.0, 0.0);
            cutoff = sample_log(-6.0, 0.0, 0.0);
        } else { /* anything a double holds */
            kc = sample_log(-300.0, 300.0, 0.1);
            kl = sample_log(-300.0, 300.0, 0.1);
            kq = sample_log(-300.0, 300.0, 0.1);
            peak = sample_log(-300.0, 300.0, 0.0);
            cutoff = sample_log(-300.0, 300.0, 0.0);
        }
        double err = check_radius(kc, kl, kq, peak, cutoff);
        worst = fmax(worst, err);
        culled += light_radius(kc, kl, kq, peak, cutoff) == 0.0;
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double seconds = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    print_message("%d samples: worst relative error %.3g (%.1f ulp), %d culled, %.2f s\n", SAMPLE_COUNT,
                  worst, worst / DBL_EPSILON, culled, seconds);
    /* Both kinds of outcome must have been exercised for the sweep to mean anything. */
    assert_true(culled > SAMPLE_COUNT / 100 && culled < SAMPLE_COUNT / 2);
}

/* The radius is where the attenuated light meets the cut-off. */
static void test_radius_meets_cutoff(void **state)
{
    (void)state;
    int checked = 0;
    for (int i = 0; i < 100000; i++) {
        double kc = sample_log(-4.0, 2.0, 0.05);
        double kl = sample_log(-12.0, 2.0, 0.1);
        double kq = sample_kq();
        double peak = sample_log(-3.0, 4.0, 0.0);
        double cutoff = sample_log(-6.0, 0.0, 0.0);
        double r = light_radius(kc, kl, kq, peak, cutoff);
        if (r == 0.0 || isinf(r))
            continue;
        double at_r = peak * light_attenuation(kc, kl, kq, r);
        if (fabs(at_r - cutoff) > 1e-12 * cutoff)
            fail_msg("kc=%.17g kl=%.17g kq=%.17g peak=%.17g cutoff=%.17g: r=%.17g gives %.17g", kc, kl, kq,
                     peak, cutoff, r, at_r);
        checked++;
    }
    assert_true(checked > 50000);
}

static void test_attenuation_and_peak(void **state)
{
    (void)state;
    assert_true(light_attenuation(1.0, 0.7, 1.8, 0.0) == 1.0);
    assert_true(fabs(light_attenuation(1.0, 0.7, 1.8, 2.0) - 1.0 / 9.6) <= 1e-15);
    const float color[3] = {0.25f, 0.75f, 0.5f};
    assert_true(light_peak(color, 2.0) == 1.5);
    const float blue[3] = {0.0f, 0.0f, 3.0f};
    assert_true(light_peak(blue, 0.5) == 1.5);
}

UNIT_TEST_MAIN(NULL, NULL, cmocka_unit_test(test_attenuation_and_peak),
               cmocka_unit_test(test_published_samples), cmocka_unit_test(test_small_quadratic_term),
               cmocka_unit_test(test_textbook_formula_cancels), cmocka_unit_test(test_culled_and_unbounded),
               cmocka_unit_test(test_extreme_magnitudes), cmocka_unit_test(test_invalid_input_is_nan),
               cmocka_unit_test(test_million_random_inputs), cmocka_unit_test(test_radius_meets_cutoff))
