/* test_bench_format.c - the benchmark's signed differences (tools/bench/bench_format.c): a negative
 * first-frame cost once printed "+-157 ms" (a "+" before "%.0f"); each sign is written once. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "bench_format.h"
#include "test_util.h"

#include <math.h>

typedef struct change_case {
    double v;
    int decimals;
    const char *want;
} change_case;

static void test_change_signs(void **state)
{
    (void)state;
    static const change_case cases[] = {
        {-157.2, 0, "-157"}, {57.0, 0, "+57"},     {-157.04, 1, "-157.0"}, {2.94, 1, "+2.9"},
        {-0.04, 1, "0.0"},   {0.04, 1, "0.0"},     {0.0, 0, "0"},          {-0.6, 0, "-1"},
        {NAN, 1, "–"},       {1e6, 0, "+1000000"},
    };
    char out[32];
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const char *got = bench_format_change(cases[i].v, cases[i].decimals, out, sizeof out);
        assert_ptr_equal(got, out);
        assert_string_equal(got, cases[i].want);
    }
}

/* A buffer too small for the number is cut, never overrun, and stays a string. */
static void test_change_small_buffer(void **state)
{
    (void)state;
    char out[4] = "xxx";
    bench_format_change(-157.0, 0, out, sizeof out);
    assert_string_equal(out, "-15");
}

UNIT_TEST_MAIN(NULL, NULL, cmocka_unit_test(test_change_signs), cmocka_unit_test(test_change_small_buffer))
