/* platform.h - the newest GL core context the driver gives (asked 4.6 down to 3.3) on one of three
 * backends, and the window around it.
 *
 *   platform_create(desc)          returns EXIT_CODE_OK, EXIT_CODE_USAGE (no display: use --headless)
 *                                  or EXIT_CODE_SKIP (no GL context could be made); logs why
 *   platform_destroy()
 *   platform_backend_name()        "glfw", "egl" or "osmesa"
 *   platform_is_windowed()
 *   platform_framebuffer_size(&w, &h)   pixels, not screen units (HiDPI); 0x0 when minimised
 *   platform_should_close()
 *   platform_is_minimised()        the window is iconified or its framebuffer is 0x0
 *   platform_poll()                events; sleeps while the window is minimised
 *   platform_minimise(timeout)     test hook: iconify the window and wait up to timeout seconds
 *                                  until it is; false when it never is (no window manager)
 *   platform_restore_at(when)      test hook: the next platform_poll(), if the window is minimised,
 *                                  asks for it back at platform_time() == when and sleeps at most
 *                                  2 s more
 *   platform_present(fbo, w, h)    copy the app's framebuffer to the window and swap
 *   platform_content_scale()       the window's content scale (2 on a HiDPI screen that doubles
 *                                  its pixels; 1 headless): how much larger text must be to read
 *   platform_set_title(text)
 *   platform_set_window_size(w, h) ask for a new window size in screen units (no-op headless)
 *   platform_time()                monotonic seconds
 *
 * Keys and the mouse go to common/platform/input.c, where the runner reads them.
 * Every chapter renders into its own framebuffer; the window only shows it.
 * That keeps one code path for windowed and headless runs.
 */
#ifndef COMMON_PLATFORM_H
#define COMMON_PLATFORM_H

#include "exit_code.h"
#include "keys.h"

#include <glad/gl.h>
#include <stdbool.h>


typedef struct platform_desc {
    backend_kind backend;
    int width, height;
    const char *title;
    bool gl_debug;
} platform_desc;

int platform_create(const platform_desc *desc);
void platform_destroy(void);
const char *platform_backend_name(void);
bool platform_is_windowed(void);
void platform_framebuffer_size(int *width, int *height);
bool platform_should_close(void);
bool platform_is_minimised(void);
void platform_poll(void);
bool platform_minimise(double timeout);
void platform_restore_at(double when);
void platform_present(GLuint fbo, int width, int height);
float platform_content_scale(void);
void platform_set_title(const char *text);
void platform_set_window_size(int width, int height);
double platform_time(void);

#endif
