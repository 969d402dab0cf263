/* gen_path.c - folders, relative paths and checked output files for gen_scenes. */
/* realpath() is an X/Open extension in glibc's headers. */
#define _XOPEN_SOURCE 700

#include "gen_path.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "log.h"

bool gen_path_make_dir(const char *dir)
{
    if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
        log_error("%s: cannot create: %s", dir, strerror(errno));
        return false;
    }
    return true;
}

/* Scenes name their models relative to the scene file, so the tree can move as a whole. */
bool gen_path_relative(const char *from, const char *to, size_t size, char *out)
{
    char a[GEN_PATH_MAX], b[GEN_PATH_MAX];
    if (!realpath(from, a) || !realpath(to, b)) {
        log_error("%s or %s: %s", from, to, strerror(errno));
        return false;
    }
    /* The longest common prefix that ends on a whole path component in both. */
    size_t common = 0;
    for (size_t i = 0;; i++) {
        bool end_a = a[i] == '\0' || a[i] == '/', end_b = b[i] == '\0' || b[i] == '/';
        if (end_a && end_b) {
            common = i;
        }
        if (a[i] != b[i] || a[i] == '\0') {
            break;
        }
    }
    out[0] = '\0';
    size_t used = 0;
    for (const char *p = a + common; *p; p++) {
        if (*p == '/') {
            used += (size_t)snprintf(out + used, size - used, "%s..", used ? "/" : "");
        }
    }
    const char *rest = b + common;
    if (*rest == '/') {
        rest++;
    }
    if (*rest) {
        used += (size_t)snprintf(out + used, size - used, "%s%s", used ? "/" : "", rest);
    }
    if (used == 0) {
        snprintf(out, size, ".");
    }
    return used < size;
}

bool gen_path_join(const char *dir, const char *name, char out[GEN_PATH_MAX])
{
    int n = snprintf(out, GEN_PATH_MAX, "%s/%s", dir, name);
    if (n < 0 || n >= GEN_PATH_MAX) {
        log_error("%s/%s: path too long", dir, name);
        return false;
    }
    return true;
}

FILE *gen_path_open_file(const char *path)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        log_error("%s: cannot write: %s", path, strerror(errno));
    }
    return f;
}

/* The writers print without checking each call: the stream's error flag and fclose (which
 * flushes) catch a full disk or a failed write once, here. */
bool gen_path_close_file(FILE *f, const char *path)
{
    bool ok = !ferror(f);
    if (fclose(f) != 0) {
        ok = false;
    }
    if (!ok) {
        log_error("%s: write failed", path);
    }
    return ok;
}
