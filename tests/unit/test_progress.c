/* test_progress.c - the progress line (common/base/progress.c): nothing while a few frames are quick,
 * a line with the frame, the time so far and an estimate once one runs past PROGRESS_AFTER_S, or a
 * long run of quick ones does, and nothing at all with --quiet. stderr goes to a file so that the
 * lines can be read back. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "progress.h"
#include "test_util.h"

#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

static void sleep_s(double s)
{
    struct timespec t = {(time_t)s, (long)((s - (double)(time_t)s) * 1e9)};
    nanosleep(&t, NULL);
}

/* Runs frames of the given lengths through the module and returns what it wrote on stderr. */
static void run_frames(const double *seconds, int n, char *out, size_t size)
{
    char path[] = "/tmp/test_progress_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    fflush(stderr);
    int saved = dup(2);
    dup2(fd, 2);
    for (int i = 0; i < n; i++) {
        progress_frame("test", i, n);
        sleep_s(seconds[i]);
    }
    progress_end();
    sleep_s(0.6); /* the watcher wakes twice a second: a line after the end would show here */
    fflush(stderr);
    dup2(saved, 2);
    close(saved);
    lseek(fd, 0, SEEK_SET);
    ssize_t got = read(fd, out, size - 1);
    out[got > 0 ? got : 0] = '\0';
    close(fd);
    unlink(path);
}

static void test_quick_frames_are_silent(void **state)
{
    (void)state;
    char text[1024];
    const double quick[] = {0.01, 0.01, 0.01};
    run_frames(quick, 3, text, sizeof text);
    assert_string_equal(text, "");
}

static void test_slow_frame_reported_while_it_runs(void **state)
{
    (void)state;
    char text[1024];
    /* Frame 1 takes 0.5 s, frame 2 runs past the 2 s threshold: one line, during frame 2, with an
     * estimate from frame 1's time (0.5 s for each of the 2 frames left, less what frame 2 took). */
    const double frames[] = {0.5, PROGRESS_AFTER_S + 1.2, 0.01};
    run_frames(frames, 3, text, sizeof text);
    assert_non_null(strstr(text, "test: frame 2 of 3 running for "));
    assert_non_null(strstr(text, "s elapsed, about 0 s left"));
    assert_null(strchr(strchr(text, '\n') + 1, '\n')); /* one line: the next is 10 s away */
    progress_set_quiet(true);
    run_frames(frames, 3, text, sizeof text);
    assert_string_equal(text, "");
    progress_set_quiet(false);
}

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Quick frames, many of them: each one restarted the frame clock, so a run of a million 3 ms frames
 * (a --script) went on for most of an hour without a line. Once the run has gone on for
 * PROGRESS_AFTER_S it is reported as a slow frame is. Frames are run until a line shows: the 60 s
 * only stop a run that never prints one. */
static void test_long_run_of_quick_frames_reported(void **state)
{
    (void)state;
    char path[] = "/tmp/test_progress_XXXXXX", text[1024];
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    fflush(stderr);
    int saved = dup(2);
    dup2(fd, 2);
    const double start = now_s();
    const long total = 1000000;
    long frames = 0;
    for (off_t written = 0; written == 0 && frames < total && now_s() - start < 60.0; frames++) {
        progress_frame("quick", frames, total);
        sleep_s(0.002);
        written = lseek(fd, 0, SEEK_END);
    }
    progress_end();
    fflush(stderr);
    dup2(saved, 2);
    close(saved);
    lseek(fd, 0, SEEK_SET);
    ssize_t got = read(fd, text, sizeof text - 1);
    text[got > 0 ? got : 0] = '\0';
    close(fd);
    unlink(path);
    if (!strstr(text, " of 1000000 running for "))
        print_error("after %ld quick frames, stderr held '%s'\n", frames, text);
    assert_non_null(strstr(text, "quick: frame "));
    assert_non_null(strstr(text, " of 1000000 running for "));
    assert_non_null(strstr(text, "s elapsed, about "));
    assert_true(frames > 1);
}

UNIT_TEST_MAIN(NULL, NULL, cmocka_unit_test(test_quick_frames_are_silent),
               cmocka_unit_test(test_slow_frame_reported_while_it_runs),
               cmocka_unit_test(test_long_run_of_quick_frames_reported))
