/* test_shader_log.c - shader info logs as Mesa, NVIDIA and AMD write them map to source string,
 * line and column; anything else is left alone. The lines are captured from real drivers (Mesa
 * 22.3 llvmpipe, NVIDIA 580 on an H200) or written in AMD's documented format. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "shader_log.h"
#include "test_util.h"

/* Parses a whole line and checks the place and the message it keeps. */
static void expect_place(const char *line, int source, int ln, int column, const char *severity,
                         const char *message)
{
    shader_log_line p;
    assert_true(shader_log_parse(line, (int)strlen(line), &p));
    assert_int_equal(p.source, source);
    assert_int_equal(p.line, ln);
    assert_int_equal(p.column, column);
    assert_string_equal(p.severity, severity);
    assert_int_equal(p.message_len, (int)strlen(message));
    assert_memory_equal(p.message, message, strlen(message));
}

static void test_mesa(void **state)
{
    (void)state;
    expect_place("0:12(3): error: syntax error, unexpected '@'", 0, 12, 3, "",
                 "error: syntax error, unexpected '@'");
    /* an included file has its own source string */
    expect_place("2:31(14): error: `x' undeclared", 2, 31, 14, "", "error: `x' undeclared");
}

static void test_nvidia(void **state)
{
    (void)state;
    expect_place("0(12) : error C0502: syntax error at token \"@\"", 0, 12, 0, "",
                 "error C0502: syntax error at token \"@\"");
    expect_place("2(31) : error C1008: undefined variable \"x\"", 2, 31, 0, "",
                 "error C1008: undefined variable \"x\"");
}

static void test_amd(void **state)
{
    (void)state;
    expect_place("ERROR: 0:12: '@' : syntax error", 0, 12, 0, "error", "'@' : syntax error");
    expect_place("WARNING: 1:4: 'x' : unused", 1, 4, 0, "warning", "'x' : unused");
}

static void test_not_a_place(void **state)
{
    (void)state;
    shader_log_line p;
    const char *lines[] = {"", "error: 2 compilation errors", "ERROR: 2 compilation errors.",
                           "0:12 something", "(12) : error", "-1:3(1): error: negative"};
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++)
        assert_false(shader_log_parse(lines[i], (int)strlen(lines[i]), &p));
}

/* Only the first n characters count: a log is one buffer, not one string per line. */
static void test_length_bounds_the_line(void **state)
{
    (void)state;
    const char *log = "0(7) : error C0000: first\n0(8) : error C0000: second\n";
    const char *end = strchr(log, '\n');
    shader_log_line p;
    assert_true(shader_log_parse(log, (int)(end - log), &p));
    assert_int_equal(p.line, 7);
    assert_int_equal(p.message_len, (int)strlen("error C0000: first"));
    assert_false(shader_log_parse(log, 3, &p)); /* "0(7" alone is no place */
}

UNIT_TEST_MAIN(NULL, NULL, cmocka_unit_test(test_mesa), cmocka_unit_test(test_nvidia), cmocka_unit_test(test_amd),
               cmocka_unit_test(test_not_a_place), cmocka_unit_test(test_length_bounds_the_line))
