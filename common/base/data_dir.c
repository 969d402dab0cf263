/* data_dir.c - see data_dir.h. */
#include "data_dir.h"

#include <errno.h>
#include <fcntl.h>
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

bool data_dir_find(const char *given, const char *first, char *out, size_t size, char *tried, size_t tried_size)
{
    struct stat st;
    size_t base = first ? strlen(first) : 0;
    const char *sep = base > 0 && first[base - 1] != '/' ? "/" : "";
    int n = given[0] == '/' || base == 0 ? snprintf(out, size, "%s", given)
                                         : snprintf(out, size, "%s%s%s", first, sep, given);
    bool fits = n > 0 && (size_t)n < size;
    if (fits && stat(out, &st) == 0)
        return true;
    char cwd[4096];
    if (base == 0 && given[0] != '/' && getcwd(cwd, sizeof cwd))
        snprintf(tried, tried_size, "%s/%s", cwd, given);
    else
        snprintf(tried, tried_size, "%s", fits ? out : given);
    if (given[0] == '/')
        return false;
    /* Then the data folder: `--scene assets/scenes/city.scene` from any folder. */
    char second[4200];
    int m = snprintf(second, sizeof second, "%s/%s", data_dir(), given);
    if (m <= 0 || (size_t)m >= sizeof second)
        return false;
    size_t used = strlen(tried);
    snprintf(tried + used, tried_size - used, " and %s (the data folder, from %s)", second, data_dir_origin());
    if (stat(second, &st) != 0 || (size_t)m >= size)
        return false;
    memcpy(out, second, (size_t)m + 1);
    return true;
}

bool data_dir_find_output(const char *given, char *out, size_t size, char *why, size_t why_size)
{
    const char *slash = strrchr(given, '/');
    char dir[4200], tried[9000], where[4200];
    struct stat st;
    if (!slash) { /* the current folder */
        int n = snprintf(out, size, "%s", given);
        if (n > 0 && (size_t)n < size && !(stat(out, &st) == 0 && S_ISDIR(st.st_mode)))
            return true;
        snprintf(why, why_size, "%s", n > 0 && (size_t)n < size ? "it is a folder" : "path too long");
        return false;
    }
    snprintf(dir, sizeof dir, "%.*s", slash == given ? 1 : (int)(slash - given), given);
    if (!data_dir_find(dir, NULL, where, sizeof where, tried, sizeof tried) || stat(where, &st) != 0 ||
        !S_ISDIR(st.st_mode)) {
        snprintf(why, why_size, "No such file or directory (no folder %s: looked for %s)", dir, tried);
        return false;
    }
    int n = snprintf(out, size, "%s%s", where, slash);
    if (n < 0 || (size_t)n >= size || (stat(out, &st) == 0 && S_ISDIR(st.st_mode))) {
        snprintf(why, why_size, "%s", n >= 0 && (size_t)n < size ? "it is a folder" : "path too long");
        return false;
    }
    return true;
}

/* An open() without O_NONBLOCK waits for a writer on a named pipe (forever, for a FIFO nobody opens):
 * so the file is opened non-blocking and its kind read from the open descriptor, not from the path. */
FILE *data_dir_open_input(const char *path, const char **why)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) {
        *why = strerror(errno);
        return NULL;
    }
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        *why = "not a regular file";
        close(fd);
        return NULL;
    }
    int flags = fcntl(fd, F_GETFL);
    FILE *f = flags >= 0 && fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) == 0 ? fdopen(fd, "rb") : NULL;
    if (!f) {
        *why = strerror(errno);
        close(fd);
    }
    return f;
}
