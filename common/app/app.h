/* app.h - the runner every chapter hands itself to.
 *
 *   app_run(desc, argc, argv)   parse the command line, load the scene, make the context,
 *                               loop frames (window or headless), time them (--bench), write the
 *                               screenshot; returns the process exit code
 *   app_render_forward(a)       the forward renderer selected by --renderer or R (one of
 *                               app_forward.h's; "forward" otherwise) into a->target
 *   app_renderer_is(a, name)    the renderer currently selected (--renderer, or the R key)
 *   app_renderer_is_forward(a)  whether it is one of app_forward.h's forward renderers; every
 *                               chapter that offers `forward` offers chapter 11's `forward-plus` too
 *                               (the runner adds it to the chapter's list)
 *   app_view_is(a, name)        the view currently selected (--view, or the V key)
 *   app_extra(a, name)          the value of a chapter's own option
 *   app_extra_number(a, name, lo, hi, out)
 *                               that value as a number in [lo, hi]; logs and returns false if not
 *   app_extra_compute(a, name, &compute)
 *                               a chapter's choice between compute shaders and its GL 3.3 path
 *                               (--NAME compute|cpu; chapter 10's --path, chapter 11's --assign):
 *                               any value but "cpu" asks for compute; no value: compute where the
 *                               context has it (gl_have_compute). Asked for where it has not:
 *                               false, and one line saying what is missing and what to use instead
 *   app_toggle_compute(&compute, what)
 *                               the same choice switched by a key: to the other path and one log
 *                               line naming it; to compute where the context has none, one line
 *                               saying so, and `compute` stays false
 *
 * A chapter exports an app_desc (its command-line description and six callbacks) named after it,
 * `chapter_NN`, and ends with CHAPTER_MAIN(chapter_NN) (chapters/chapters.h): its main() when built
 * as its own program, nothing when the build compiles it again (CHAPTER_NO_MAIN) for the benchmark
 * and the tests, which drive it in-process (app_embed.h). Its frame callback draws the final, display-encoded picture
 * into a->target (RGBA8 colour + 32-bit float depth), which the runner shows in the window or saves
 * with --screenshot. When a->count_pixels (--bench, or the overlay is on) it counts its lighting
 * pass's fragments with a->query (gl_samples_begin/end) into a->shaded_pixels, and when each of them
 * loops over several lights sets a->lights_per_pixel (their product is the frame's light
 * evaluations); a->pass_state, when it sets it, is shown too, and so are a->overlay_lines and a->note.
 * The overlay and the title name the renderer and the view the frame drew (a->view_drawn). Two
 * requests only an embedding caller makes: a->linear_output asks for linear radiance into a float a->target (a chapter that can sets
 * a->linear_written), and a chapter whose frame sums linear radiance before its present pass points
 * a->linear at that buffer.
 */
#ifndef COMMON_APP_H
#define COMMON_APP_H

#include "app_forward.h"
#include "cli.h"
#include "fbo.h"
#include "frame_timer.h"
#include "gpu_scene.h"
#include "keys.h"
#include "scene.h"
#include "shader_features.h"

/* The chapter's overlay lines' room: more than any chapter writes; one that fills it is told (the
 * runner logs it), never cut silently. */
#define APP_OVERLAY_LINES 512

typedef struct app {
    const cli_options *options;
    const cli_desc *cli;
    scene scene;
    gpu_scene gs;
    shader_features features; /* what the scene uses: every program is built for it (app_scene_features) */
    app_forward forward; /* the forward renderers every chapter can switch to */
    fbo target;
    int width, height;
    int renderer; /* index into cli.renderers */
    int view;     /* index into cli.views */
    float time;
    double cutoff;
    long frame_index;
    GLuint query;       /* a GL_SAMPLES_PASSED query for the chapter's lighting pass */
    frame_timer timer;  /* the frame and its passes, on an honest clock (frame_timer.h) */
    long shaded_pixels; /* what the chapter counted with it in the last frame; -1 if not */
    const char *work_name; /* what that count is, for the overlay; NULL: "lighting fragments" */
    bool count_pixels;  /* whether to count (--bench, or the overlay is on) */
    double lights_per_pixel; /* lights each counted fragment loops over; 1 unless the chapter says */
    bool linear_output;  /* asked by an embedding caller: linear radiance into a float a->target */
    bool linear_written; /* the chapter did so this frame */
    const fbo *linear;   /* the chapter's linear sum of this frame (before present), or NULL */
    const gl_pass_state *pass_state; /* the chapter's lighting pass state, shown by the overlay */
    char overlay_lines[APP_OVERLAY_LINES]; /* the chapter's own overlay lines, set by each frame that
                                            * draws what they describe ("": none; the runner empties
                                            * them before every frame) */
    const char *view_drawn; /* the view the frame drew: the runner sets the chosen one before it;
                             * app_render_forward "lit" (a forward renderer draws no other view) */
    const char *note;       /* set by the frame when its picture needs a word (a view that has
                             * nothing to show on this scene): a string that outlives the frame,
                             * shown even with the overlay off; the runner clears it before every frame */
    char default_scene[4200]; /* the data folder's default scene, when no --scene was given */
    bool input_error; /* set by init when what failed was an option's value (beyond the context's
                       * limit): the run exits 2, not 1 */
} app;

typedef struct app_desc {
    const cli_desc *cli;            /* its command line (--help prints it) */
    bool (*accepts_scene)(const app *a); /* optional: the scene (a->gs) fits the chapter's limits;
                                          * false (the chapter logs why): exit 2, before init */
    bool (*init)(app *a);           /* GL resources; target exists */
    bool (*resize)(app *a);         /* after the target was recreated at a->width x a->height */
    bool (*frame)(app *a);          /* draw into a->target */
    void (*cleanup)(app *a);
    bool (*key)(app *a, int key);   /* a chapter's own keys; return true when handled */
    /* compare mode's forward picture (key M), display-encoded into `target`; NULL: the renderer
     * table's forward (chapter 13: forward MSAA at its own sample count) */
    bool (*draw_forward)(app *a, GLuint target);
    bool draws_glass; /* its own renderers draw transparent objects (00, 12); if not, the runner says
                       * once, on stderr, that a scene's glass is left out */
    bool takes_reversed_z; /* its lighting passes read the G-buffer's depth through gbuffer_read.glsl only,
                            * never depth-tested (11, 17, 19): --gbuffer reversed-z is accepted though it
                            * sets a pass state (gbuffer_layout_fits_pass) */
    bool prefers_reversed_z; /* with no --gbuffer, the compact layout with its depth reversed on scenes
                              * without metallic-roughness materials (17, 19: gbuffer_layout_for_chapter) */
} app_desc;

int app_run(const app_desc *desc, int argc, char **argv);
bool app_render_forward(app *a);
bool app_renderer_is(const app *a, const char *name);
bool app_renderer_is_forward(const app *a);
bool app_view_is(const app *a, const char *name);
const char *app_extra(const app *a, const char *name);
bool app_extra_number(const app *a, const char *name, double lo, double hi, double *out);
bool app_extra_compute(const app *a, const char *name, bool *compute);
void app_toggle_compute(bool *compute, const char *what);

#endif
