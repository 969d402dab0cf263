/* test_util.h - what the unit tests share. Header-only: every tests/unit/test_*.c is its own cmocka
 * program (tests/CMakeLists.txt), so there is no extra source to link. Include it after <cmocka.h>.
 *
 *   UNIT_TEST_MAIN(setup, teardown, tests...)   defines main(): runs the cmocka_unit_test()s given
 *                                               as one group, with a group setup and teardown (NULL
 *                                               for none), and returns cmocka's verdict
 *   tmp_dir                                     the group's scratch folder
 *   tmp_dir_create(template)                    mkdtemp(template) into tmp_dir; 0 or -1, as a
 *                                               cmocka group setup returns
 *   tmp_dir_remove(state)                       group teardown: removes tmp_dir and all inside it
 *   tmp_path(name)                              "tmp_dir/name", in a buffer the next call reuses
 *   stderr_capture_begin(&c), stderr_capture_end(&c, out, size)
 *                                               what the code between the two wrote to stderr, into
 *                                               out[size] (c.file is NULL when no file could hold it)
 */
#ifndef TESTS_UNIT_TEST_UTIL_H
#define TESTS_UNIT_TEST_UTIL_H

#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#define UNIT_TEST_MAIN(group_setup, group_teardown, ...)                                                 \
    int main(void)                                                                                       \
    {                                                                                                    \
        const struct CMUnitTest tests[] = {__VA_ARGS__};                                                 \
        return cmocka_run_group_tests(tests, group_setup, group_teardown);                               \
    }

static char tmp_dir[64];

/* template: a path ending in XXXXXX, e.g. "/tmp/test_image_XXXXXX". */
static inline int tmp_dir_create(const char *template)
{
    snprintf(tmp_dir, sizeof tmp_dir, "%s", template);
    return mkdtemp(tmp_dir) ? 0 : -1;
}

static inline int tmp_dir_remove(void **state)
{
    (void)state;
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmp_dir);
    return system(cmd) == 0 ? 0 : -1;
}

static inline const char *tmp_path(const char *name)
{
    static char path[128];
    snprintf(path, sizeof path, "%s/%s", tmp_dir, name);
    return path;
}

typedef struct stderr_capture {
    FILE *file;
    int saved; /* stderr's own descriptor, restored by stderr_capture_end */
} stderr_capture;

static inline void stderr_capture_begin(stderr_capture *c)
{
    fflush(stderr);
    c->file = tmpfile();
    c->saved = dup(2);
    if (c->file)
        dup2(fileno(c->file), 2);
}

static inline void stderr_capture_end(stderr_capture *c, char *out, size_t size)
{
    fflush(stderr);
    dup2(c->saved, 2);
    close(c->saved);
    out[0] = '\0';
    if (!c->file)
        return;
    rewind(c->file);
    size_t n = fread(out, 1, size - 1, c->file);
    out[n] = '\0';
    fclose(c->file);
}

#endif
