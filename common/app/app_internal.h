/* app_internal.h - the parts of app_run that are not the frame loop (app.c only).
 *
 * The test hooks (app_hooks.c):
 *   app_hooks_init(h, opt)
 *   app_hooks_minimise(h, a, opt)              before a frame's events: one --minimise-cycle round;
 *                                              false: stop the loop (h->rc says why)
 *   app_hooks_resize(h, a, opt, &w, &h)        after them: the --resize-cycle size of this frame
 *   app_hooks_after_frame(h, minimised)        counts frames drawn while minimised
 *   app_hooks_check(h, a, opt)                 the hooks' verdict after the loop: leaked GL
 *                                              objects, frames drawn while minimised; exit code
 * The benchmark line (app_bench.c):
 *   app_bench_print(a, ms, pass_ms, n)         the one `bench: key=value ...` line of --bench: the
 *                                              frames' wall times (glFinish + monotonic) and the
 *                                              median of each pass on the timer's clock
 */
#ifndef COMMON_APP_INTERNAL_H
#define COMMON_APP_INTERNAL_H

#include "app.h"
#include "compare.h"
#include "input_script.h"
#include "overlay.h"

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

/* What app_run and app_embed share (app.c):
 *   app_cli_of(desc, renderers_plus)    the chapter's command line as the runner offers it: the
 *                                       default cut-off, Forward+ beside forward (its list in
 *                                       renderers_plus, APP_RENDERERS_MAX entries, kept by the caller)
 *   app_init(a, cli, opt)               a zeroed app for those options
 *   app_target_make(a)                  a->target at a->width x a->height (RGBA8 + 32-bit float depth)
 *   app_scene_features(a)               a->features from a->scene, and their defines set for every
 *                                       program built from then on (gl_program_set_scene_defines);
 *                                       the list of compiled programs starts again */
#define APP_RENDERERS_MAX 32
cli_desc app_cli_of(const app_desc *desc, const char **renderers_plus);
void app_init(app *a, const cli_desc *cli, const cli_options *opt);
bool app_target_make(app *a);
bool app_scene_features(app *a);

/* The command line's other consequences (app_options.c):
 *   app_print_gl_info(opt, program)     --gl-info: key=value lines about the context; an exit code
 *   app_check_size_limits(w, h)         false (logged) when the context cannot make a w x h target
 *   app_check_size_memory(w, h, shot)   false (logged) when a software rasteriser's memory cannot
 *                                       hold even the runner's own w x h target (and the screenshot)
 *   app_apply_camera(scene, given)      --camera's attributes over the scene's camera (parsed as a
 *                                       scene's camera line); false (logged) when they are wrong
 *   app_with_forward_plus(list, out, capacity)
 *                                       `list` with forward-plus after forward (in out), or list */
int app_print_gl_info(const cli_options *opt, const char *program);
bool app_check_size_limits(int width, int height);
bool app_check_size_memory(int width, int height, bool screenshot);
bool app_apply_camera(scene *s, const char *given);
const char *const *app_with_forward_plus(const char *const *list, const char **out, int capacity);

/* The learner's window (app_window.c):
 *   app_window_create(w, a, opt) / app_window_destroy(w) / app_window_resize(w, a)
 *   app_window_move(w, a, dt)          mouse and held keys to the camera
 *   app_window_key(w, a, action)       the camera, light, overlay and compare keys; false: not one
 *   app_window_compare(w, a, draw_forward)
 *                                      after the chapter's frame: forward (the chapter's own draw_forward
 *                                      when not NULL) and the composed picture
 *   app_window_display(w, a, paused)   the picture with the overlay: what the window shows
 *   app_window_after_frame(w, a, shown, paused, &rc)
 *                                      the script's after-frame events; false: stop (rc says why)
 *   app_text_overlay(w, a, paused)     (app_text.c) the overlay's lines, a string to free (as long
 *                                      as they are: no fixed buffer cuts them); NULL when out of
 *                                      memory (logged)
 *   app_text_key_list(a)               F1's list of the chapter's keys, the same way
 *   app_text_title(a, sum, n, paused)  the window's title from n frames' times (and --verbose's log)
 *   app_window_save(fbo, path)         colour attachment 0 as an image file */
#define APP_COMPARE_PASS "compare forward" /* forward's whole frame in compare mode, as one pass */
#define APP_COMPOSE_PASS "compare compose" /* both pictures into the one shown: neither side's time */
/* A frame's time split into the chapter's own and compare mode's two passes (zero when off);
 * forward_timed: the frame has forward's pass, so forward_ms is its time (a frame drawn without it,
 * or not yet read back, has none: its 0 is no measurement). */
typedef struct app_frame_split {
    double own_ms, forward_ms, compose_ms;
    bool forward_timed;
} app_frame_split;
app_frame_split app_frame_split_of(const frame_times *t);

typedef struct app_window {
    input_script script;
    bool have_script;
    scene_camera home; /* the scene's camera, for Home */
    float extent;      /* the scene's largest side: how fast W A S D fly */
    bool overlay_on, key_list_on;
    compare_mode compare;
    float divider; /* the split's divider, a fraction of the width */
    bool dragging_divider;
    compare cmp;
    bool have_cmp, have_text;
    overlay text;
    fbo display;
    const fbo *shown;  /* the last frame's picture: the target or the composed comparison */
    frame_times times; /* the overlay's figures: the timer's frames averaged over half a second */
    long objects_marked;
    double badge_until; /* platform_time() until which the pause badge shows */
    fbo ideal_target;   /* the scene's depth for the ideal count (forward, drawn when paused) */
    long long ideal;    /* (pixel, light) pairs a perfect volume would shade; -1: not counted */
    unsigned ideal_key; /* what the frame was when it was counted */
    scene start;        /* its lights only: the lights the run started with, for Backspace */
    int new_light;      /* the light G added last, labelled until new_light_until; -1: none */
    double new_light_until;
} app_window;

bool app_window_create(app_window *w, app *a, const cli_options *opt);
void app_window_destroy(app_window *w);
bool app_window_resize(app_window *w, const app *a);
void app_window_move(app_window *w, app *a, double dt);
bool app_window_key(app_window *w, app *a, key_action action);
bool app_window_compare(app_window *w, app *a, bool (*draw_forward)(app *a, GLuint target));
const fbo *app_window_display(app_window *w, app *a, bool paused);
bool app_window_after_frame(app_window *w, app *a, const fbo *shown, bool paused, int *rc);
char *app_text_overlay(const app_window *w, const app *a, bool paused);
char *app_text_key_list(const app *a);
void app_text_title(const app *a, const frame_times *sum, int n, bool paused);
bool app_window_save(const fbo *f, const char *path);

#endif
