/* app_window.c - what a learner does in the window: move the camera, add lights, read the overlay,
 * compare with forward; and what a --script asks for after a frame. (app.c only: app_internal.h) */
#include "app_internal.h"

#include "camera.h"
#include "gl_util.h"
#include "image.h"
#include "input.h"
#include "light.h"
#include "light_work.h"
#include "log.h"
#include "platform.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define ORBIT_RADIANS_PER_PIXEL 0.006f
#define LOOK_RADIANS_PER_PIXEL 0.003f
#define FLY_EXTENTS_PER_SECOND 0.4f /* the scene's largest side crossed in 2.5 s */
#define DIVIDER_STEP 0.05f
#define DIVIDER_GRAB_PIXELS 8.0
#define LIGHTS_MAX 65536
#define PAUSE_BADGE_SECONDS 2.0
#define NEW_LIGHT_SECONDS 3.0 /* how long a light added with G is labelled (or until the next key) */

bool app_window_create(app_window *w, app *a, const cli_options *opt)
{
    memset(w, 0, sizeof *w);
    w->home = a->scene.camera;
    w->overlay_on = opt->overlay;
    w->divider = 0.5f;
    w->compare = opt->compare ? (compare_mode)cli_choice_index((const char *const[]){"off", "split", "difference", NULL}, opt->compare) : COMPARE_OFF;
    float lo[3], hi[3];
    light_generate_bounds(&a->scene, lo, hi);
    w->extent = fmaxf(fmaxf(hi[0] - lo[0], hi[1] - lo[1]), hi[2] - lo[2]);
    if (opt->script && !input_script_load(opt->script, &w->script))
        return false;
    w->have_script = opt->script != NULL;
    w->shown = &a->target;
    w->ideal = -1;
    w->new_light = -1;
    for (int i = 0; i < a->scene.light_count; i++)
        if (!scene_add_light(&w->start, &a->scene.lights[i]))
            return false;
    return true;
}

void app_window_destroy(app_window *w)
{
    fbo_destroy(&w->ideal_target);
    if (w->have_cmp)
        compare_destroy(&w->cmp);
    if (w->have_text)
        overlay_destroy(&w->text);
    fbo_destroy(&w->display);
    input_script_destroy(&w->script);
    scene_destroy(&w->start);
}

bool app_window_resize(app_window *w, const app *a)
{
    fbo_destroy(&w->display);
    fbo_destroy(&w->ideal_target);
    return !w->have_cmp || compare_resize(&w->cmp, a->width, a->height);
}

/* ---- camera -------------------------------------------------------------------------------- */

static int divider_pixel(const app_window *w, const app *a) { return (int)lroundf(w->divider * (float)a->width); }

/* Mouse and held keys since the last frame, applied to the scene's camera (gpu_scene reads it). */
void app_window_move(app_window *w, app *a, double dt)
{
    scene_camera *c = &a->scene.camera;
    input_mouse m = input_take_mouse();
    bool on_divider = w->compare == COMPARE_SPLIT &&
                      fabs(m.press_x[INPUT_BUTTON_LEFT] - divider_pixel(w, a)) <= DIVIDER_GRAB_PIXELS;
    if (m.pressed[INPUT_BUTTON_LEFT])
        w->dragging_divider = on_divider;
    if (m.held[INPUT_BUTTON_LEFT] && w->dragging_divider)
        w->divider = fminf(fmaxf((float)(m.x / a->width), 0.0f), 1.0f);
    else if (m.held[INPUT_BUTTON_LEFT] && !m.pressed[INPUT_BUTTON_LEFT])
        camera_orbit(c, -(float)m.dx * ORBIT_RADIANS_PER_PIXEL, (float)m.dy * ORBIT_RADIANS_PER_PIXEL); /* grab the world */
    if (m.held[INPUT_BUTTON_RIGHT] && !m.pressed[INPUT_BUTTON_RIGHT])
        camera_look(c, -(float)m.dx * LOOK_RADIANS_PER_PIXEL, -(float)m.dy * LOOK_RADIANS_PER_PIXEL);
    if (m.scroll != 0.0)
        camera_zoom(c, (float)m.scroll);
    float step = FLY_EXTENTS_PER_SECOND * w->extent * (float)dt;
    float ahead = (float)(input_key_held('W') - input_key_held('S')) * step;
    float right = (float)(input_key_held('D') - input_key_held('A')) * step;
    if (ahead != 0.0f || right != 0.0f)
        camera_fly(c, ahead, right);
}

static void print_pose(const app *a)
{
    char line[512];
    camera_format(&a->scene.camera, line, sizeof line);
    printf("%s\n", line); /* stdout: ready to paste into a scene file, or after --camera */
    fflush(stdout);
}

/* ---- lights -------------------------------------------------------------------------------- */

/* A warm white light half-way to the target, bright (intensity 3) and reaching as far as the target
 * at the default cut-off, so that it shows; the window labels it for NEW_LIGHT_SECONDS. */
static void add_light(app_window *w, app *a)
{
    const scene_camera *c = &a->scene.camera;
    vec3 dir;
    glm_vec3_sub((float *)c->target, (float *)c->eye, dir);
    float distance = glm_vec3_norm(dir);
    float reach = fmaxf(distance, 1.0f);
    const float intensity = 3.0f; /* kc = 1, kl = 0: the radius is sqrt((peak / cutoff - 1) / kq) */
    scene_light l = {.color = {1.0f, 0.95f, 0.85f}, .intensity = intensity, .kc = 1.0f, .kl = 0.0f,
                     .kq = (float)((intensity / LIGHT_DEFAULT_CUTOFF - 1.0) / ((double)reach * reach))};
    glm_vec3_scale(dir, 0.5f, dir);
    glm_vec3_add((float *)c->eye, dir, l.position);
    if (!scene_add_light(&a->scene, &l))
        return;
    log_info("lights: %d (added one at %.2f %.2f %.2f)", a->scene.light_count, (double)l.position[0],
             (double)l.position[1], (double)l.position[2]);
    w->new_light = a->scene.light_count - 1;
    w->new_light_until = platform_time() + NEW_LIGHT_SECONDS;
}

/* Backspace: the lights the run started with (the scene's, or --lights'), kept in w->start. */
static void restore_lights(app_window *w, app *a)
{
    if (!light_generate(&a->scene, 0, 0))
        return;
    for (int i = 0; i < w->start.light_count; i++)
        if (!scene_add_light(&a->scene, &w->start.lights[i]))
            return;
    w->new_light = -1;
    log_info("lights: %d, as at the start", a->scene.light_count);
}

/* For NEW_LIGHT_SECONDS after G: a label at the new light, where the camera sees it. */
static void mark_new_light(const app_window *w, app *a, overlay *text, GLuint target)
{
    if (w->new_light < 0 || w->new_light >= a->scene.light_count || platform_time() > w->new_light_until)
        return;
    vec4 p = {0.0f, 0.0f, 0.0f, 1.0f};
    scene_light_position_at(&a->scene, w->new_light, a->time, p);
    glm_mat4_mulv(a->gs.view.view_proj, p, p);
    if (p[3] <= 0.0f)
        return; /* behind the camera */
    float x = (p[0] / p[3] * 0.5f + 0.5f) * (float)a->width, y = (0.5f - p[1] / p[3] * 0.5f) * (float)a->height;
    char label[64];
    snprintf(label, sizeof label, "+ new light %d", w->new_light + 1);
    overlay_draw_label(text, target, a->width, a->height, label, x, y, platform_content_scale());
}

static void scale_lights(app *a, bool twice)
{
    int n = a->scene.light_count;
    n = twice ? (n > 0 ? n * 2 : 1) : n / 2;
    if (n > LIGHTS_MAX) {
        log_info("lights: at most %d here (--lights takes more)", LIGHTS_MAX);
        return;
    }
    if (light_generate(&a->scene, n, a->options->seed))
        log_info("lights: %d generated", n);
}

/* ---- keys ---------------------------------------------------------------------------------- */

bool app_window_key(app_window *w, app *a, key_action action)
{
    if (action != KEY_ACTION_ADD_LIGHT)
        w->new_light_until = 0.0; /* the new light's label goes at the next key */
    switch (action) {
    case KEY_ACTION_FRAME_SCENE: {
        float lo[3], hi[3];
        light_generate_bounds(&a->scene, lo, hi);
        camera_frame(&a->scene.camera, lo, hi, (float)a->width / (float)a->height);
        return true;
    }
    case KEY_ACTION_HOME_CAMERA: a->scene.camera = w->home; return true;
    case KEY_ACTION_PRINT_POSE: print_pose(a); return true;
    case KEY_ACTION_ADD_LIGHT: add_light(w, a); return true;
    case KEY_ACTION_LIGHTS_RESTORE: restore_lights(w, a); return true;
    case KEY_ACTION_LIGHTS_DOUBLE: scale_lights(a, true); return true;
    case KEY_ACTION_LIGHTS_HALF: scale_lights(a, false); return true;
    case KEY_ACTION_OVERLAY: w->overlay_on = !w->overlay_on; return true;
    case KEY_ACTION_KEY_LIST: w->key_list_on = !w->key_list_on; return true;
    case KEY_ACTION_PAUSE: w->badge_until = platform_time() + PAUSE_BADGE_SECONDS; return false; /* the loop pauses */
    case KEY_ACTION_COMPARE:
        w->compare = (compare_mode)((w->compare + 1) % COMPARE_MODE_COUNT);
        log_info("compare: %s", compare_mode_name(w->compare));
        return true;
    case KEY_ACTION_DIVIDER_LEFT: w->divider = fmaxf(w->divider - DIVIDER_STEP, 0.0f); return true;
    case KEY_ACTION_DIVIDER_RIGHT: w->divider = fminf(w->divider + DIVIDER_STEP, 1.0f); return true;
    default: return false;
    }
}

/* ---- compare ------------------------------------------------------------------------------- */

/* After the chapter's frame, inside the frame timer: forward under its own pass name, then both
 * into one picture. */
bool app_window_compare(app_window *w, app *a, bool (*draw_forward)(app *a, GLuint target))
{
    w->shown = &a->target;
    if (w->compare == COMPARE_OFF)
        return true;
    if (!w->have_cmp && !(w->have_cmp = compare_create(&w->cmp, a->width, a->height)))
        return false;
    /* forward's own passes (light lists, pre-pass, shading) go into this one pass, on the same clock */
    frame_timer_mark(APP_COMPARE_PASS);
    frame_timer_hold(true);
    const app_forward_options o = {0};
    bool drawn = draw_forward ? draw_forward(a, w->cmp.forward.id)
                              : app_forward_draw(&a->forward, "forward", &a->gs, w->cmp.forward.id, o, NULL);
    frame_timer_hold(false);
    frame_timer_mark(APP_COMPOSE_PASS);
    if (!drawn ||
        !compare_compose(&w->cmp, &a->target, w->compare, divider_pixel(w, a)))
        return false;
    w->shown = &w->cmp.shown;
    return true;
}

app_frame_split app_frame_split_of(const frame_times *t)
{
    app_frame_split s = {.own_ms = t->frame_ms};
    for (int k = 0; k < t->count; k++) {
        if (strcmp(t->names[k], APP_COMPARE_PASS) == 0)
            s.forward_ms += t->ms[k], s.forward_timed = true;
        else if (strcmp(t->names[k], APP_COMPOSE_PASS) == 0)
            s.compose_ms += t->ms[k];
    }
    s.own_ms -= s.forward_ms + s.compose_ms;
    return s;
}

/* ---- the ideal work ------------------------------------------------------------------------ */

/* FNV-1a over what decides the ideal count: camera, lights, cut-off, time, size. */
static unsigned frame_key(const app *a)
{
    unsigned h = 2166136261u;
    const unsigned char *parts[] = {(const void *)&a->scene.camera, (const void *)&a->cutoff, (const void *)&a->time,
                                    (const void *)&a->width, (const void *)&a->height, (const void *)&a->gs.light_count};
    const size_t sizes[] = {sizeof a->scene.camera, sizeof a->cutoff, sizeof a->time, sizeof a->width, sizeof a->height,
                            sizeof a->gs.light_count};
    for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++)
        for (size_t i = 0; i < sizes[k]; i++)
            h = (h ^ parts[k][i]) * 16777619u;
    return h;
}

/* The pairs a perfect light volume would shade (common/render/light_work.h), from the depth of a forward
 * frame read back: a CPU count, so only while paused and only when the frame changed. */
static void count_ideal(app_window *w, app *a)
{
    unsigned key = frame_key(a);
    if (w->ideal >= 0 && key == w->ideal_key)
        return;
    w->ideal = -1;
    const fbo_desc d = {.color_formats = {GL_RGBA8}, .color_count = 1, .depth_format = GL_DEPTH_COMPONENT32F,
                        .name = "ideal count"};
    size_t n = (size_t)a->width * (size_t)a->height;
    float *depth = malloc(n * sizeof *depth);
    double *positions = malloc(4 * n * sizeof *positions);
    if (depth && positions && (w->ideal_target.id || fbo_create(&w->ideal_target, &d, a->width, a->height)) &&
        app_forward_draw(&a->forward, "forward", &a->gs, w->ideal_target.id, (app_forward_options){0}, NULL)) {
        fbo_read_depth(&w->ideal_target, depth);
        const float *vp = (const float *)a->gs.view.view_proj;
        light_work_positions(depth, a->width, a->height, vp, positions);
        w->ideal = light_work_ideal_pairs(positions, a->width, a->height, vp, a->gs.lights, a->gs.light_count);
        w->ideal_key = key;
    }
    free(depth);
    free(positions);
}

/* ---- what the window shows ----------------------------------------------------------------- */

bool app_window_save(const fbo *f, const char *path)
{
    image img;
    if (!image_create(&img, f->width, f->height))
        return false;
    bool ok = fbo_read_rgba8(f, 0, img.pixels);
    image_flip_rows(&img); /* image files store the top row first */
    ok = ok && image_write(path, &img);
    image_destroy(&img);
    if (ok)
        log_info("wrote %s (%dx%d)", path, f->width, f->height);
    return ok;
}

/* The picture, then the overlay, the key list or, for PAUSE_BADGE_SECONDS after Space, a badge: what the window shows
 * (and what a script's screenshot reads). NULL when nothing shows it (headless, no script). */
const fbo *app_window_display(app_window *w, app *a, bool paused)
{
    if (!platform_is_windowed() && !w->have_script && !a->options->overlay)
        return NULL;
    const fbo_desc d = {.color_formats = {GL_RGBA8}, .color_count = 1, .name = "display"};
    if ((!w->display.id && !fbo_create(&w->display, &d, a->width, a->height)) ||
        (!w->have_text && !(w->have_text = overlay_create(&w->text))))
        return NULL;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, w->shown->id);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, w->display.id);
    glBlitFramebuffer(0, 0, a->width, a->height, 0, 0, a->width, a->height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    const float content = platform_content_scale();
    if (w->key_list_on) { /* F1's list replaces the overlay while it shows: one box, readable */
        char *keys = app_text_key_list(a);
        if (keys)
            overlay_draw(&w->text, w->display.id, a->width, a->height, keys, OVERLAY_TOP_LEFT, content);
        free(keys);
        return &w->display;
    }
    if (w->overlay_on && paused)
        count_ideal(w, a);
    if (w->overlay_on) {
        char *text = app_text_overlay(w, a, paused);
        if (text)
            overlay_draw(&w->text, w->display.id, a->width, a->height, text, OVERLAY_TOP_LEFT, content);
        free(text);
    } else if (platform_time() < w->badge_until) {
        overlay_draw(&w->text, w->display.id, a->width, a->height, paused ? "PAUSED (Space resumes)" : "RESUMED",
                     OVERLAY_TOP_LEFT, content);
    } else if (a->note) { /* the overlay, when on, has it as a line */
        overlay_draw(&w->text, w->display.id, a->width, a->height, a->note, OVERLAY_TOP_LEFT, content);
    }
    mark_new_light(w, a, &w->text, w->display.id);
    return &w->display;
}

/* ---- the script's after-frame events ------------------------------------------------------- */

static bool script_objects(app_window *w, const script_event *e, int *rc)
{
    long live = gl_live_objects();
    if (e->kind == SCRIPT_OBJECTS_MARK) {
        w->objects_marked = live;
        return true;
    }
    if (live == w->objects_marked)
        return true;
    log_error("%s:%d: %ld GL objects alive, %ld at the mark: %ld leaked", w->script.name, e->line, live,
              w->objects_marked, live - w->objects_marked);
    *rc = EXIT_CODE_RUNTIME;
    return false;
}

bool app_window_after_frame(app_window *w, app *a, const fbo *shown, bool paused, int *rc)
{
    int first, count;
    input_script_range(&w->script, a->frame_index, &first, &count);
    for (int i = first; i < first + count; i++) {
        const script_event *e = &w->script.events[i];
        char *text = NULL;
        switch (e->kind) {
        case SCRIPT_SCREENSHOT:
            if (!app_window_save(shown, e->path)) {
                *rc = EXIT_CODE_RUNTIME;
                return false;
            }
            break;
        case SCRIPT_OVERLAY: /* what the window shows: F1's list while it shows, else the overlay */
            if (paused)
                count_ideal(w, a);
            text = w->key_list_on ? app_text_key_list(a) : app_text_overlay(w, a, paused);
            for (char *line = text ? strtok(text, "\n") : NULL; line; line = strtok(NULL, "\n"))
                printf("%s: %s\n", w->key_list_on ? "keys" : "overlay", line);
            fflush(stdout);
            free(text);
            break;
        case SCRIPT_OBJECTS_MARK:
        case SCRIPT_OBJECTS_CHECK:
            if (!script_objects(w, e, rc))
                return false;
            break;
        case SCRIPT_QUIT: return false;
        default: break;
        }
    }
    return true;
}
