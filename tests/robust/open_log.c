/* open_log.c - an LD_PRELOAD interposer that writes every path the process opens, one a line, to
 * the file named by OPEN_LOG (tests/robust/hostile_gltf.py: nothing outside a model's folder is
 * opened). It wraps the C library's open calls (open, openat, their 64-bit and fortified forms,
 * fopen) and passes each call on unchanged. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef int (*open_fn)(const char *, int, ...);
typedef int (*openat_fn)(int, const char *, int, ...);
typedef int (*open2_fn)(const char *, int);
typedef int (*openat2_fn)(int, const char *, int);
typedef FILE *(*fopen_fn)(const char *, const char *);
/* dlsym's object pointer as a function pointer, the way POSIX allows (ISO C has no cast for it) */
#define REAL(name, type)                                                                                      \
    type real;                                                                                                \
    do {                                                                                                      \
        void *next = dlsym(RTLD_NEXT, name);                                                                  \
        memcpy(&real, &next, sizeof next);                                                                    \
    } while (0)

static void log_path(const char *path)
{
    static int fd = -2;
    if (fd == -2) {
        const char *name = getenv("OPEN_LOG");
        REAL("open", open_fn);
        fd = name && real ? real(name, O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644) : -1;
    }
    if (fd < 0 || !path)
        return;
    char line[4200];
    size_t n = strlen(path);
    if (n > sizeof line - 2)
        n = sizeof line - 2;
    memcpy(line, path, n);
    line[n++] = '\n';
    if (write(fd, line, n) < 0)
        return;
}

static mode_t mode_of(int flags, va_list ap)
{
    return (flags & O_CREAT) || (flags & __O_TMPFILE) == __O_TMPFILE ? (mode_t)va_arg(ap, int) : 0;
}



int open(const char *path, int flags, ...)
{
    va_list ap;
    va_start(ap, flags);
    mode_t mode = mode_of(flags, ap);
    va_end(ap);
    REAL("open", open_fn);
    log_path(path);
    return real(path, flags, mode);
}

int open64(const char *path, int flags, ...)
{
    va_list ap;
    va_start(ap, flags);
    mode_t mode = mode_of(flags, ap);
    va_end(ap);
    REAL("open64", open_fn);
    log_path(path);
    return real(path, flags, mode);
}

int openat(int dir, const char *path, int flags, ...)
{
    va_list ap;
    va_start(ap, flags);
    mode_t mode = mode_of(flags, ap);
    va_end(ap);
    REAL("openat", openat_fn);
    log_path(path);
    return real(dir, path, flags, mode);
}

int openat64(int dir, const char *path, int flags, ...)
{
    va_list ap;
    va_start(ap, flags);
    mode_t mode = mode_of(flags, ap);
    va_end(ap);
    REAL("openat64", openat_fn);
    log_path(path);
    return real(dir, path, flags, mode);
}

int __open_2(const char *path, int flags)
{
    REAL("__open_2", open2_fn);
    log_path(path);
    return real(path, flags);
}

int __open64_2(const char *path, int flags)
{
    REAL("__open64_2", open2_fn);
    log_path(path);
    return real(path, flags);
}

int __openat_2(int dir, const char *path, int flags)
{
    REAL("__openat_2", openat2_fn);
    log_path(path);
    return real(dir, path, flags);
}

FILE *fopen(const char *path, const char *mode)
{
    REAL("fopen", fopen_fn);
    log_path(path);
    return real(path, mode);
}

FILE *fopen64(const char *path, const char *mode)
{
    REAL("fopen64", fopen_fn);
    log_path(path);
    return real(path, mode);
}
