/* test_input_script.c - --script files: frames and ranges, file order within a frame, every action,
 * errors at file:line, and the events reaching common/platform/input.c as the window's would. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "input.h"
#include "input_script.h"
#include "keys.h"
#include "test_util.h"

#include <string.h>

static void test_parses_and_orders(void **state)
{
    (void)state;
    input_script s;
    assert_true(input_script_parse("# a walk\n3 screenshot a.png\n1-2 key W  # comment\n3 key Space\n\n"
                                   "0 move 10.5 20\n0 press left\n5 objects check\n4 objects mark\n6 quit\n",
                                   "walk", &s));
    assert_int_equal(s.count, 9);
    int first, count;
    input_script_range(&s, 3, &first, &count);
    assert_int_equal(count, 2);
    assert_int_equal(s.events[first].kind, SCRIPT_SCREENSHOT); /* file order within a frame */
    assert_string_equal(s.events[first].path, "a.png");
    assert_int_equal(s.events[first + 1].code, KEY_SPACE);
    input_script_range(&s, 2, &first, &count);
    assert_int_equal(count, 1);
    assert_int_equal(s.events[first].code, 'W');
    input_script_range(&s, 4, &first, &count);
    assert_int_equal(s.events[first].kind, SCRIPT_OBJECTS_MARK);
    input_script_range(&s, 5, &first, &count);
    assert_int_equal(s.events[first].kind, SCRIPT_OBJECTS_CHECK);
    input_script_range(&s, 7, &first, &count);
    assert_int_equal(count, 0);
    assert_int_equal(input_script_last_frame(&s), 6);
    input_script_destroy(&s);
}

static void test_keys_by_label(void **state)
{
    (void)state;
    assert_int_equal(keys_code("Home"), KEY_HOME);
    assert_int_equal(keys_code("F1"), KEY_F1);
    assert_int_equal(keys_code("+"), '=');
    assert_int_equal(keys_code("PgUp"), KEY_PAGE_UP);
    assert_int_equal(keys_code("g"), 'G');
    assert_int_equal(keys_code("left drag"), 0); /* a mouse gesture is no key */
    assert_int_equal(keys_code("Nope"), 0);
}

static void test_rejects_bad_lines(void **state)
{
    (void)state;
    const char *bad[] = {
        "x key W\n",          /* no frame */
        "5-2 key W\n",        /* range backwards */
        "1 jump\n",           /* unknown action */
        "1 key Nope\n",       /* unknown key */
        "1 move 3\n",         /* one coordinate */
        "1 press middle\n",   /* unknown button */
        "1 objects count\n",  /* mark or check */
        "1 quit now\n",       /* nothing after quit */
        "1 screenshot\n",     /* no file */
        "-1 key W\n",         /* negative frame */
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        input_script s;
        assert_false(input_script_parse(bad[i], "bad", &s));
        assert_null(s.events);
    }
}

/* The feed takes the path the window's callbacks take: a key press is queued, held keys stay
 * down until their `up`, the mouse's motion is summed until taken. */
static void test_feed_reaches_input(void **state)
{
    (void)state;
    input_script s;
    assert_true(input_script_parse("0 key G\n0 down W\n0 move 10 10\n1 move 30 15\n1 press right\n1 scroll -2\n"
                                   "2 up W\n2 release right\n", "feed", &s));
    input_reset();
    input_script_feed(&s, 0);
    assert_int_equal(input_take_key(), 'G');
    assert_int_equal(input_take_key(), 'W');
    assert_int_equal(input_take_key(), 0);
    assert_true(input_key_held('W'));
    assert_false(input_key_held('G'));
    input_take_mouse();
    input_script_feed(&s, 1);
    input_mouse m = input_take_mouse();
    assert_float_equal(m.dx, 20.0, 0.0);
    assert_float_equal(m.dy, 5.0, 0.0);
    assert_float_equal(m.scroll, -2.0, 0.0);
    assert_true(m.held[INPUT_BUTTON_RIGHT] && m.pressed[INPUT_BUTTON_RIGHT]);
    input_script_feed(&s, 2);
    m = input_take_mouse();
    assert_false(input_key_held('W'));
    assert_false(m.held[INPUT_BUTTON_RIGHT] || m.pressed[INPUT_BUTTON_RIGHT]);
    input_script_destroy(&s);
}

/* The limits are what input_script.h says: frames 0..99,999, and 1,000,000 events load, one more
 * does not. */
static void test_event_limit_as_stated(void **state)
{
    (void)state;
    input_script s;
    char text[200];
    text[0] = '\0';
    for (int i = 0; i < 10; i++) /* ten ranges over every frame a script may name */
        strcat(text, "0-99999 key W\n");
    assert_true(input_script_parse(text, "limit", &s));
    assert_int_equal(s.count, 1000000);
    assert_int_equal(SCRIPT_EVENTS_MAX, 1000000);
    assert_int_equal(input_script_last_frame(&s), 99999);
    input_script_destroy(&s);
    strcat(text, "0 quit\n");
    assert_false(input_script_parse(text, "limit", &s));
    assert_null(s.events);
}

/* A 14-byte line asked for a million frames (47 minutes of a headless run, no output): the last
 * frame a script may name is 99,999, so a script runs at most 100,000 frames. */
static void test_frame_limit_as_stated(void **state)
{
    (void)state;
    input_script s;
    assert_true(input_script_parse("99999 quit\n", "frames", &s));
    assert_int_equal(input_script_last_frame(&s), 99999);
    input_script_destroy(&s);
    assert_true(input_script_parse("0-99999 down W\n", "frames", &s));
    assert_int_equal(s.count, 100000);
    input_script_destroy(&s);
    static const char *const refused[] = {"100000 quit\n", "0-100000 key W\n", "0-999999 key W\n",
                                          "99999-100000 up W\n"};
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        assert_false(input_script_parse(refused[i], "frames", &s));
        assert_null(s.events);
    }
}

/* A check compares with a mark made before it: an earlier frame, or an earlier line of its frame. */
static void test_check_needs_a_mark(void **state)
{
    (void)state;
    input_script s;
    assert_false(input_script_parse("5 objects check\n", "check", &s));
    assert_false(input_script_parse("4 objects check\n4 objects mark\n", "check", &s));
    assert_false(input_script_parse("4 objects check\n5 objects mark\n", "check", &s));
    assert_true(input_script_parse("4 objects mark\n4 objects check\n", "check", &s));
    input_script_destroy(&s);
    assert_true(input_script_parse("5 objects check\n4 objects mark\n", "check", &s));
    input_script_destroy(&s);
}

/* A range of screenshots shares one copy of its file name; a folder is not a script. */
static void test_paths_and_files(void **state)
{
    (void)state;
    input_script s;
    assert_true(input_script_parse("0-2 screenshot shot.png\n", "paths", &s));
    assert_int_equal(s.count, 3);
    assert_ptr_equal(s.events[0].path, s.events[2].path);
    assert_string_equal(s.events[1].path, "shot.png");
    input_script_destroy(&s);
    assert_false(input_script_load("/tmp", &s));
    assert_null(s.events);
}

UNIT_TEST_MAIN(NULL, NULL, cmocka_unit_test(test_event_limit_as_stated), cmocka_unit_test(test_frame_limit_as_stated),
               cmocka_unit_test(test_check_needs_a_mark),
               cmocka_unit_test(test_paths_and_files), cmocka_unit_test(test_parses_and_orders), cmocka_unit_test(test_keys_by_label),
               cmocka_unit_test(test_rejects_bad_lines), cmocka_unit_test(test_feed_reaches_input))
