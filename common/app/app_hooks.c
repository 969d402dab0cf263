/* app_hooks.c - the runner's test hooks (--resize-cycle, --minimise-cycle); see app_internal.h. */
#include "app_internal.h"

#include "gl_util.h"
#include "log.h"
#include "platform.h"

#include <string.h>

#define MINIMISE_WAIT 30.0 /* seconds --minimise-cycle waits for the window manager to iconify (polled:
                            * a loaded machine may take seconds, an idle one returns at once) */
#define MINIMISED_FOR 0.1 /* seconds it stays minimised before the loop asks for it back */

void app_hooks_init(app_hooks *h, const cli_options *opt)
{
    memset(h, 0, sizeof *h);
    h->cycle_end = opt->resize_cycle > 0 ? opt->resize_cycle + 1 : 0;
}

/* --resize-cycle N: frame 0 at the base size, frames 1..N each at another size, frame N+1 back at
 * the base size. Consecutive sizes differ, so every one of those frames recreates the targets. */
static void resize_cycle_size(const app_hooks *h, long frame, long cycle, int *w, int *ht)
{
    static const int scale[3][2] = {{2, 2}, {3, 4}, {4, 3}}; /* quarters of the base size */
    if (frame > cycle) {
        *w = h->base_width, *ht = h->base_height;
        return;
    }
    const int *s = scale[(frame - 1) % 3];
    *w = h->base_width * s[0] / 4 > 0 ? h->base_width * s[0] / 4 : 1;
    *ht = h->base_height * s[1] / 4 > 0 ? h->base_height * s[1] / 4 : 1;
}

/* --minimise-cycle: one round per frame boundary; the platform_poll() that follows must sleep
 * through it, so any frame drawn while minimised is counted as a failure. */
static bool minimise_round(app_hooks *h, long frame, int rounds)
{
    if (frame == 1)
        h->live_before_minimise = gl_live_objects();
    if (!platform_minimise(MINIMISE_WAIT)) {
        log_error("no window manager: cannot minimise");
        h->rc = EXIT_CODE_SKIP;
        return false;
    }
    log_debug("minimised (round %ld of %d)", frame, rounds);
    platform_restore_at(platform_time() + MINIMISED_FOR);
    return true;
}

bool app_hooks_minimise(app_hooks *h, const app *a, const cli_options *opt)
{
    long frame = a->frame_index;
    return !(frame >= 1 && frame <= opt->minimise_cycle) || minimise_round(h, frame, opt->minimise_cycle);
}

void app_hooks_resize(app_hooks *h, const app *a, const cli_options *opt, int *width, int *height)
{
    long frame = a->frame_index;
    if (frame < 1 || frame > h->cycle_end)
        return;
    if (frame == 1) /* after one frame: lazily made objects exist by now */
        h->live_before_resize = gl_live_objects(), h->base_width = a->width, h->base_height = a->height;
    resize_cycle_size(h, frame, opt->resize_cycle, width, height);
    platform_set_window_size(*width, *height);
}

void app_hooks_after_frame(app_hooks *h, bool minimised)
{
    if (minimised)
        h->minimised_frames++;
}

int app_hooks_check(const app_hooks *h, const app *a, const cli_options *opt)
{
    if (h->cycle_end > 0 && a->frame_index > h->cycle_end && gl_live_objects() != h->live_before_resize) {
        log_error("--resize-cycle: %ld live GL objects before %d resizes, %ld after", h->live_before_resize,
                  opt->resize_cycle, gl_live_objects());
        return EXIT_CODE_RUNTIME;
    }
    if (h->minimised_frames > 0) {
        log_error("--minimise-cycle: %ld frame(s) drawn while the window was minimised", h->minimised_frames);
        return EXIT_CODE_RUNTIME;
    }
    if (opt->minimise_cycle > 0 && a->frame_index > opt->minimise_cycle &&
        gl_live_objects() != h->live_before_minimise) {
        log_error("--minimise-cycle: %ld live GL objects before %d minimise cycles, %ld after",
                  h->live_before_minimise, opt->minimise_cycle, gl_live_objects());
        return EXIT_CODE_RUNTIME;
    }
    return EXIT_CODE_OK;
}
