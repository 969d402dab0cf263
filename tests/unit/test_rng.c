/* test_rng.c - the course's one random generator: Marsaglia's xorshift32 sequence, draws in range,
 * and no stuck state. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "rng.h"
#include "test_util.h"

/* The first outputs from state 1 (Marsaglia 2003, shifts 13, 17, 5), computed independently. */
static void test_known_sequence(void **state)
{
    (void)state;
    rng r = rng_seed(1);
    assert_int_equal(rng_next(&r), 270369u);
    assert_int_equal(rng_next(&r), 67634689u);
    assert_int_equal(rng_next(&r), 2647435461u);
}

static void test_draws_in_range(void **state)
{
    (void)state;
    rng r = rng_seed(12345);
    int seen[7] = {0};
    for (int i = 0; i < 100000; i++) {
        double u = rng_unit(&r);
        assert_true(u >= 0.0 && u < 1.0);
        double v = rng_uniform(&r, -2.5, 4.0);
        assert_true(v >= -2.5 && v < 4.0);
        int k = rng_below(&r, 7);
        assert_true(k >= 0 && k < 7);
        seen[k]++;
    }
    for (int k = 0; k < 7; k++) /* 100,000 / 7 = 14,286 expected; 5 sigma is about 560 */
        assert_true(seen[k] > 13500 && seen[k] < 15100);
}

/* State 0 is a fixed point of xorshift: the seed must never leave the generator there. */
static void test_zero_seed_moves(void **state)
{
    (void)state;
    rng r = rng_seed(0);
    assert_true(rng_next(&r) != 0u);
}

UNIT_TEST_MAIN(NULL, NULL, cmocka_unit_test(test_known_sequence), cmocka_unit_test(test_draws_in_range),
               cmocka_unit_test(test_zero_seed_moves))
