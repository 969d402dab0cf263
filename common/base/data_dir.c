/* data_dir.c - see data_dir.h. */
#include "data_dir.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#ifndef COURSE_SOURCE_DIR
#define COURSE_SOURCE_DIR "."
#endif
#ifndef COURSE_INSTALL_DATA_REL
#define COURSE_INSTALL_DATA_REL "../share/deferred_course" /* from the executable's folder */
#endif

static struct {
    char dir[4096];
    const char *origin;
} state;

static bool is_data_dir(const char *dir)
{
    char probe[4200];
    struct stat st;
    snprintf(probe, sizeof probe, "%s/shaders/shading.glsl", dir);
    return stat(probe, &st) == 0 && S_ISREG(st.st_mode);
}

/* The installed prefix's data folder, found from /proc/self/exe; false when there is none. */
static bool find_installed(char *out, size_t size)
{
    char exe[4096];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0)
        return false;
    exe[n] = '\0';
    char *slash = strrchr(exe, '/');
    if (!slash)
        return false;
    *slash = '\0';
    int k = snprintf(out, size, "%s/%s", exe, COURSE_INSTALL_DATA_REL);
    return k > 0 && (size_t)k < size && is_data_dir(out);
}

void data_dir_set(const char *dir)
{
    if (dir && *dir) {
        snprintf(state.dir, sizeof state.dir, "%s", dir);
        state.origin = "--data-dir";
    }
}

const char *data_dir(void)
{
    if (state.origin)
        return state.dir;
    const char *env = getenv("COURSE_DATA_DIR");
    if (env && *env) {
        snprintf(state.dir, sizeof state.dir, "%s", env);
        state.origin = "$COURSE_DATA_DIR";
    } else if (find_installed(state.dir, sizeof state.dir)) {
        state.origin = "the installed prefix";
    } else {
        snprintf(state.dir, sizeof state.dir, "%s", COURSE_SOURCE_DIR);
        state.origin = "the source tree";
    }
    return state.dir;
}

bool data_dir_path(const char *relative, char *out, size_t size)
{
    int n = snprintf(out, size, "%s/%s", data_dir(), relative);
    return n > 0 && (size_t)n < size;
}

const char *data_dir_origin(void)
{
    data_dir();
    return state.origin;
}
