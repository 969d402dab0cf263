/* exit_code.h - what every program of the course returns, and the GL backends it can run on: the
 * command line (cli) parses them and the platform layer uses them, and neither includes the other.
 */
#ifndef COMMON_EXIT_CODE_H
#define COMMON_EXIT_CODE_H

enum {
    EXIT_CODE_OK = 0,      /* run */
    EXIT_CODE_RUNTIME = 1, /* a failure while running */
    EXIT_CODE_USAGE = 2,   /* bad option or input */
    EXIT_CODE_SKIP = 77,   /* no GL context (CTest's skip code) */
};

typedef enum backend_kind {
    BACKEND_AUTO,   /* window when a display exists, else EGL, else OSMesa */
    BACKEND_WINDOW, /* GLFW */
    BACKEND_EGL,    /* EGL surfaceless */
    BACKEND_OSMESA, /* Mesa's off-screen library */
} backend_kind;

#endif
