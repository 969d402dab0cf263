/* platform.c - see platform.h. */
#include <glad/gl.h>

#include "platform.h"

#include "gl_util.h"
#include "input.h"
#include "log.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/osmesa.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <stdlib.h>
#include <string.h>
#include <time.h>

#define RESTORE_WAIT 30.0 /* seconds platform_poll waits for a window it asked back (test hook; polled) */

static struct {
    backend_kind backend;
    GLFWwindow *window;
    EGLDisplay egl_display;
    EGLContext egl_context;
    OSMesaContext osmesa;
    unsigned char osmesa_pixel[4]; /* OSMesa wants a colour buffer; we never draw to it */
    double restore_at; /* > 0: platform_restore_at() was called */
} state;

double platform_time(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* ---- GLFW ------------------------------------------------------------------------------ */

static void glfw_error(int code, const char *message)
{
    log_debug("GLFW error 0x%x: %s", code, message);
}

/* GLFW's key codes are keys.h's (letters are ASCII, the others GLFW's numbers); the keypad's
 * plus and minus are the main keyboard's. */
static void glfw_key(GLFWwindow *w, int key, int scancode, int action, int mods)
{
    (void)w;
    (void)scancode;
    (void)mods;
    if (action == GLFW_REPEAT)
        return;
    key = key == GLFW_KEY_KP_ADD ? '=' : key == GLFW_KEY_KP_SUBTRACT ? '-' : key;
    input_key(key, action == GLFW_PRESS);
}

/* Screen units to framebuffer pixels: on a HiDPI screen they differ by the content scale. */
static void glfw_cursor(GLFWwindow *w, double x, double y)
{
    int ww = 0, wh = 0, fw = 0, fh = 0;
    glfwGetWindowSize(w, &ww, &wh);
    glfwGetFramebufferSize(w, &fw, &fh);
    input_mouse_move(ww > 0 ? x * fw / ww : x, wh > 0 ? y * fh / wh : y);
}

static void glfw_button(GLFWwindow *w, int button, int action, int mods)
{
    (void)w;
    (void)mods;
    int b = button == GLFW_MOUSE_BUTTON_LEFT ? INPUT_BUTTON_LEFT : button == GLFW_MOUSE_BUTTON_RIGHT ? INPUT_BUTTON_RIGHT : -1;
    input_mouse_button(b, action == GLFW_PRESS);
}

static void glfw_scroll(GLFWwindow *w, double dx, double dy)
{
    (void)w;
    (void)dx;
    input_scroll(dy);
}

/* Core versions asked for, newest first, and the first the driver gives is kept: asked for 3.3 a
 * driver may return exactly 3.3 (NVIDIA does), while a feature of a later chapter can need more.
 * 3.3 is the floor every chapter runs on. */
static const int gl_versions[][2] = {{4, 6}, {4, 5}, {4, 3}, {4, 1}, {3, 3}};
#define GL_VERSION_COUNT ((int)(sizeof gl_versions / sizeof gl_versions[0]))

static GLFWwindow *glfw_window_newest(const platform_desc *desc)
{
    for (int v = 0; v < GL_VERSION_COUNT; v++) {
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, gl_versions[v][0]);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, gl_versions[v][1]);
        GLFWwindow *w = glfwCreateWindow(desc->width, desc->height, desc->title, NULL, NULL);
        if (w)
            return w;
    }
    return NULL;
}

static int create_glfw(const platform_desc *desc)
{
    glfwSetErrorCallback(glfw_error);
    if (!glfwInit()) {
        log_error("cannot open a window: no display (DISPLAY is not set or the X server is unreachable); "
                  "run with --headless");
        return EXIT_CODE_USAGE;
    }
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, desc->gl_debug ? GLFW_TRUE : GLFW_FALSE);
    state.window = glfw_window_newest(desc);
    if (!state.window) {
        const char *why = NULL;
        glfwGetError(&why);
        log_error("cannot create a GL core window (3.3 or newer): %s", why ? why : "unknown reason");
        glfwTerminate();
        return EXIT_CODE_SKIP;
    }
    glfwMakeContextCurrent(state.window);
    glfwSwapInterval(0); /* measure the renderer, not the display's refresh */
    glfwSetKeyCallback(state.window, glfw_key);
    glfwSetCursorPosCallback(state.window, glfw_cursor);
    glfwSetMouseButtonCallback(state.window, glfw_button);
    glfwSetScrollCallback(state.window, glfw_scroll);
    if (!gladLoadGL(glfwGetProcAddress)) {
        log_error("cannot load GL functions through GLFW");
        return EXIT_CODE_SKIP;
    }
    return EXIT_CODE_OK;
}

/* ---- EGL surfaceless ---------------------------------------------------------------------- */

static bool create_egl(void)
{
    state.egl_display = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    EGLint major, minor;
    if (state.egl_display == EGL_NO_DISPLAY || !eglInitialize(state.egl_display, &major, &minor)) {
        log_debug("EGL: no surfaceless display (0x%x)", eglGetError());
        return false;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        log_debug("EGL: OpenGL API unavailable (0x%x)", eglGetError());
        return false;
    }
    for (int v = 0; v < GL_VERSION_COUNT && state.egl_context == EGL_NO_CONTEXT; v++) {
        const EGLint attrs[] = {EGL_CONTEXT_MAJOR_VERSION,        gl_versions[v][0],
                                EGL_CONTEXT_MINOR_VERSION,        gl_versions[v][1],
                                EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                EGL_NONE};
        state.egl_context = eglCreateContext(state.egl_display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attrs);
    }
    if (state.egl_context == EGL_NO_CONTEXT ||
        !eglMakeCurrent(state.egl_display, EGL_NO_SURFACE, EGL_NO_SURFACE, state.egl_context)) {
        log_debug("EGL: cannot create a core context, 3.3 or newer (0x%x)", eglGetError());
        return false;
    }
    if (!gladLoadGL((GLADloadfunc)eglGetProcAddress)) {
        log_debug("EGL: cannot load GL functions");
        return false;
    }
    return true;
}

static void destroy_egl(void)
{
    if (state.egl_display == EGL_NO_DISPLAY)
        return;
    eglMakeCurrent(state.egl_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (state.egl_context != EGL_NO_CONTEXT)
        eglDestroyContext(state.egl_display, state.egl_context);
#if !defined(__SANITIZE_ADDRESS__)
    /* Under AddressSanitizer, eglTerminate unloads the driver before LeakSanitizer can name its frames. */
    eglTerminate(state.egl_display);
#endif
    state.egl_context = EGL_NO_CONTEXT;
    state.egl_display = EGL_NO_DISPLAY;
}

/* ---- OSMesa ------------------------------------------------------------------------------- */

static bool create_osmesa(void)
{
    for (int v = 0; v < GL_VERSION_COUNT && !state.osmesa; v++) {
        const int attrs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                             OSMESA_CONTEXT_MAJOR_VERSION, gl_versions[v][0], OSMESA_CONTEXT_MINOR_VERSION,
                             gl_versions[v][1], 0};
        state.osmesa = OSMesaCreateContextAttribs(attrs, NULL);
    }
    if (!state.osmesa) {
        log_debug("OSMesa: cannot create a core context, 3.3 or newer");
        return false;
    }
    if (!OSMesaMakeCurrent(state.osmesa, state.osmesa_pixel, GL_UNSIGNED_BYTE, 1, 1)) {
        log_debug("OSMesa: cannot make the context current");
        return false;
    }
    if (!gladLoadGL((GLADloadfunc)OSMesaGetProcAddress)) {
        log_debug("OSMesa: cannot load GL functions");
        return false;
    }
    return true;
}

/* ---- public ------------------------------------------------------------------------------- */

static bool display_available(void)
{
    const char *x = getenv("DISPLAY");
    const char *wl = getenv("WAYLAND_DISPLAY");
    return (x && *x) || (wl && *wl);
}

int platform_create(const platform_desc *desc)
{
    memset(&state, 0, sizeof state);
    state.egl_display = EGL_NO_DISPLAY;
    state.egl_context = EGL_NO_CONTEXT;
    backend_kind b = desc->backend;
    if (b == BACKEND_AUTO || b == BACKEND_WINDOW) {
        if (!display_available()) {
            log_error("no display to open a window on (DISPLAY is not set): run with --headless");
            return EXIT_CODE_USAGE;
        }
        int rc = create_glfw(desc);
        if (rc != EXIT_CODE_OK)
            return rc;
        state.backend = BACKEND_WINDOW;
    } else {
        bool ok = false;
        if (b == BACKEND_EGL) {
            ok = create_egl();
            if (!ok) {
                destroy_egl();
                log_info("EGL could not make a GL 3.3 core context; falling back to OSMesa");
                b = BACKEND_OSMESA;
            }
        }
        if (b == BACKEND_OSMESA)
            ok = create_osmesa();
        if (!ok) {
            log_error("no GL 3.3 core context could be created (tried %s); is Mesa (libgl1-mesa-dri, "
                      "libegl-mesa0, libosmesa6) installed?",
                      desc->backend == BACKEND_EGL ? "EGL and OSMesa" : "OSMesa");
            platform_destroy();
            return EXIT_CODE_SKIP;
        }
        state.backend = b;
    }
    if (desc->gl_debug)
        gl_debug_enable();
    log_debug("GL %s, %s, backend %s", (const char *)glGetString(GL_VERSION),
              (const char *)glGetString(GL_RENDERER), platform_backend_name());
    return EXIT_CODE_OK;
}

void platform_destroy(void)
{
    if (state.window) {
        glfwDestroyWindow(state.window);
        glfwTerminate();
        state.window = NULL;
    }
    destroy_egl();
    if (state.osmesa) {
        OSMesaDestroyContext(state.osmesa);
        state.osmesa = NULL;
    }
}

const char *platform_backend_name(void)
{
    switch (state.backend) {
    case BACKEND_WINDOW: return "glfw";
    case BACKEND_EGL: return "egl";
    case BACKEND_OSMESA: return "osmesa";
    default: return "none";
    }
}

bool platform_is_windowed(void) { return state.window != NULL; }

void platform_framebuffer_size(int *width, int *height)
{
    if (state.window)
        glfwGetFramebufferSize(state.window, width, height);
}

float platform_content_scale(void)
{
    float x = 1.0f, y = 1.0f;
    if (state.window)
        glfwGetWindowContentScale(state.window, &x, &y);
    return x > 0.0f ? x : 1.0f;
}

bool platform_should_close(void) { return state.window && glfwWindowShouldClose(state.window); }

bool platform_is_minimised(void)
{
    if (!state.window)
        return false;
    /* Windows reports a 0x0 framebuffer; X11 keeps the size and only sets the iconified state. */
    int w = 0, h = 0;
    glfwGetFramebufferSize(state.window, &w, &h);
    return w == 0 || h == 0 || glfwGetWindowAttrib(state.window, GLFW_ICONIFIED);
}

/* Sleeps until an event arrives; with a restore scheduled, wakes up to ask for the window back and
 * gives up RESTORE_WAIT seconds later, so a test hook can never hang the run. */
static void wait_minimised(void)
{
    double give_up = 0.0;
    while (platform_is_minimised() && !glfwWindowShouldClose(state.window)) {
        double now = platform_time();
        if (state.restore_at <= 0.0) {
            glfwWaitEvents();
        } else if (now < state.restore_at) {
            glfwWaitEventsTimeout(state.restore_at - now);
        } else if (give_up == 0.0) {
            glfwRestoreWindow(state.window);
            give_up = now + RESTORE_WAIT;
        } else if (now < give_up) {
            glfwWaitEventsTimeout(give_up - now);
        } else {
            log_warn("the window is still minimised %.0f s after asking for it back", RESTORE_WAIT);
            break;
        }
    }
    state.restore_at = 0.0;
}

void platform_poll(void)
{
    if (!state.window)
        return;
    glfwPollEvents();
    /* Minimised: nothing to draw until the window comes back. */
    wait_minimised();
}

bool platform_minimise(double timeout)
{
    if (!state.window)
        return false;
    glfwIconifyWindow(state.window);
    /* Iconifying is a request to the window manager; without one it silently does nothing. */
    double end = platform_time() + timeout;
    while (!glfwGetWindowAttrib(state.window, GLFW_ICONIFIED)) {
        double left = end - platform_time();
        if (left <= 0.0)
            return false;
        glfwWaitEventsTimeout(left < 0.01 ? left : 0.01);
    }
    return true;
}

void platform_restore_at(double when) { state.restore_at = when; }

void platform_present(GLuint fbo, int width, int height)
{
    if (!state.window)
        return;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glfwSwapBuffers(state.window);
}

void platform_set_title(const char *text)
{
    if (state.window)
        glfwSetWindowTitle(state.window, text);
}

void platform_set_window_size(int width, int height)
{
    if (state.window)
        glfwSetWindowSize(state.window, width, height);
}

