/* app_internal.h - the parts of app_run that are not the frame loop (app.c only).
 *
 *   app_hooks_init(h, opt)
 *   app_hooks_minimise(h, a, opt)              before a frame's events: one --minimise-cycle round;
 *                                              false: stop the loop (h->rc says why)
 *   app_hooks_resize(h, a, opt, &w, &h)        after them: the --resize-cycle size of this frame
 *   app_hooks_after_frame(h, minimised)        counts frames drawn while minimised
 *   app_hooks_check(h, a, opt)                 the hooks' verdict after the loop: leaked GL
 *                                              objects, frames drawn while minimised; exit code
 *   app_bench_print(a, ms, pass_ms, n)         the one `bench: key=value ...` line of --bench: the
 *                                              frames' wall times (glFinish + monotonic) and the
 *                                              median of each pass on the timer's clock
 */
#ifndef COMMON_APP_INTERNAL_H
#define COMMON_APP_INTERNAL_H

#include "app.h"

typedef struct app_hooks {
    long cycle_end;          /* last frame of --resize-cycle, 0 when off */
    long live_before_resize; /* GL objects alive before the resizes */
    long live_before_minimise;
    long minimised_frames;
    int base_width, base_height;
    int rc; /* why the hooks stopped the loop */
} app_hooks;

void app_hooks_init(app_hooks *h, const cli_options *opt);
bool app_hooks_minimise(app_hooks *h, const app *a, const cli_options *opt);
void app_hooks_resize(app_hooks *h, const app *a, const cli_options *opt, int *width, int *height);
void app_hooks_after_frame(app_hooks *h, bool minimised);
int app_hooks_check(const app_hooks *h, const app *a, const cli_options *opt);
void app_bench_print(const app *a, double *ms, double *pass_ms, int n);

#endif
