/* app.h - the runner every chapter hands itself to.
 *
 *   app_run(desc, argc, argv)   parse the command line, load the scene, make the context,
 *                               loop frames (window or headless), time them (--bench), write the
 *                               screenshot; returns the process exit code
 *   app_render_forward(a)       chapter 00's renderer with the best forward options, into a->target
 *   app_forward_options(name)   options for "forward", "forward-naive", "forward-prepass", "forward-lists"
 *   app_renderer_is(a, name)    the renderer currently selected (--renderer, or the R key)
 *   app_view_is(a, name)        the view currently selected (--view, or the V key)
 *   app_extra(a, name)          the value of a chapter's own option
 *
 * A chapter fills an app_desc: its command-line description and four callbacks. Its frame
 * callback draws the final, display-encoded picture into a->target (RGBA8 colour + 32-bit float
 * depth), which the runner shows in the window or saves with --screenshot.
 */
#ifndef COMMON_APP_H
#define COMMON_APP_H

#include "cli.h"
#include "fbo.h"
#include "forward.h"
#include "gpu_scene.h"
#include "scene.h"

typedef struct app {
    const cli_options *options;
    const cli_desc *cli;
    scene scene;
    gpu_scene gs;
    forward fwd;
    fbo target;
    int width, height;
    int renderer; /* index into cli.renderers */
    int view;     /* index into cli.views */
    float time;
    double cutoff;
    long frame_index;
    double frame_ms;    /* last frame, CPU + glFinish when timing */
    long shaded_pixels; /* a chapter may report its lighting pass's GL_SAMPLES_PASSED here; -1 if not */
    void *user;
} app;

typedef struct app_desc {
    cli_desc cli;
    bool (*init)(app *a);           /* GL resources; target exists */
    bool (*resize)(app *a);         /* after the target was recreated at a->width x a->height */
    bool (*frame)(app *a);          /* draw into a->target */
    void (*cleanup)(app *a);
    bool (*key)(app *a, int key);   /* a chapter's own keys; return true when handled */
} app_desc;

int app_run(const app_desc *desc, int argc, char **argv);
bool app_render_forward(app *a);
forward_options app_forward_options(const char *name);
bool app_renderer_is(const app *a, const char *name);
bool app_view_is(const app *a, const char *name);
const char *app_extra(const app *a, const char *name);

#endif
