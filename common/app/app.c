/* app.c - see app.h. The test hooks are in app_hooks.c, the --bench line in app_bench.c. */
#include "app.h"

#include "app_internal.h"
#include "data_dir.h"
#include "gbuffer.h"
#include "gl_program.h"
#include "gl_util.h"
#include "gpu_textures.h"
#include "image.h"
#include "input.h"
#include "light.h"
#include "log.h"
#include "platform.h"
#include "progress.h"

#include <stdio.h>
#include <stdlib.h>
#include <errno.h>
#include <string.h>
#include <sys/stat.h>

bool app_renderer_is(const app *a, const char *name)
{
    return a->cli->renderers && strcmp(a->cli->renderers[a->renderer], name) == 0;
}

bool app_renderer_is_forward(const app *a)
{
    return !a->cli->renderers || app_forward_is(a->cli->renderers[a->renderer]);
}

bool app_view_is(const app *a, const char *name)
{
    return a->cli->views && strcmp(a->cli->views[a->view], name) == 0;
}

const char *app_extra(const app *a, const char *name) { return cli_extra_value(a->cli, a->options, name); }

bool app_extra_number(const app *a, const char *name, double lo, double hi, double *out)
{
    const char *text = app_extra(a, name);
    if (text && cli_parse_double(text, lo, hi, out))
        return true;
    log_error("bad --%s '%s': expected a number in [%g, %g]", name, text ? text : "", lo, hi);
    return false;
}

bool app_extra_compute(const app *a, const char *name, bool *compute)
{
    const char *value = app_extra(a, name);
    *compute = value ? strcmp(value, "cpu") != 0 : gl_have_compute();
    if (!*compute || gl_have_compute())
        return true;
    log_error("--%s %s needs compute shaders (OpenGL 4.3), which this context %s: use --%s cpu", name, value,
              GLAD_GL_VERSION_4_3 ? "has, hidden by COURSE_NO_COMPUTE" : "does not have", name);
    return false;
}

void app_toggle_compute(bool *compute, const char *what)
{
    if (!*compute && !gl_have_compute()) {
        log_info("%s: still the CPU, this context has no compute shaders (OpenGL 4.3)", what);
        return;
    }
    *compute = !*compute;
    log_info("%s: %s", what, *compute ? "compute shaders" : "the CPU");
}

bool app_render_forward(app *a)
{
    /* counted for --bench (and embedded frames) only: with the overlay, counting Forward+ would make
     * its count target mid-run, which the window's leak check sees as a leak */
    const app_forward_options o = {.count_pixels = a->options->bench, .linear_output = a->linear_output};
    app_forward_work work;
    bool ok = app_forward_draw(&a->forward, a->cli->renderers ? a->cli->renderers[a->renderer] : NULL, &a->gs,
                               a->target.id, o, &work);
    a->shaded_pixels = work.shaded;
    a->lights_per_pixel = work.lights_per_pixel;
    a->linear_written = a->linear_output;
    /* forward draws the lit picture whatever view was chosen: it has no G-buffer to show (chapter 02
     * calls that picture its view "final") */
    if (a->view_drawn && strcmp(a->view_drawn, "final") != 0)
        a->view_drawn = "lit";
    return ok;
}

bool app_target_make(app *a)
{
    fbo_destroy(&a->target);
    const fbo_desc desc = {
        .color_formats = {GL_RGBA8}, .color_count = 1, .depth_format = GL_DEPTH_COMPONENT32F, .name = "target"};
    return fbo_create(&a->target, &desc, a->width, a->height);
}

static void next_choice(const char *const *choices, int *index, const char *what)
{
    if (!choices)
        return;
    *index = choices[*index + 1] ? *index + 1 : 0;
    log_info("%s: %s", what, choices[*index]);
}

/* P: the last frame's picture as shown (the comparison too), without the overlay. */
static void save_numbered_screenshot(const app *a, const app_window *w)
{
    char path[64];
    if (mkdir("out", 0755) != 0 && errno != EEXIST) { /* in the current folder, as the page says */
        log_error("P: cannot make the folder out/ in the current folder: %s", strerror(errno));
        return;
    }
    snprintf(path, sizeof path, "out/%s-%ld.png", a->cli->program, a->frame_index);
    app_window_save(w->shown, path);
}

/* One key, as common/platform/keys.c's table says; returns false to quit. */
static bool handle_key(app *a, const app_desc *desc, app_window *w, int key, bool *paused)
{
    const key_binding *b = keys_find(key, a->cli->program);
    if (b && app_window_key(w, a, b->action))
        return true; /* the window's own keys (app_window.c) */
    switch (b ? b->action : KEY_ACTION_CHAPTER) {
    case KEY_ACTION_CHAPTER:
        if (b && desc->key)
            desc->key(a, key);
        break;
    case KEY_ACTION_QUIT: return false;
    case KEY_ACTION_RENDERER: next_choice(a->cli->renderers, &a->renderer, "renderer"); break;
    case KEY_ACTION_VIEW: next_choice(a->cli->views, &a->view, "view"); break;
    case KEY_ACTION_PAUSE: *paused = !*paused; break;
    case KEY_ACTION_CUTOFF_HALF: a->cutoff = a->cutoff > 0 ? a->cutoff / 2 : LIGHT_DEFAULT_CUTOFF; break;
    case KEY_ACTION_CUTOFF_DOUBLE: a->cutoff = a->cutoff > 0 ? a->cutoff * 2 : LIGHT_DEFAULT_CUTOFF; break;
    case KEY_ACTION_CUTOFF_EXACT: a->cutoff = a->cutoff > 0 ? 0 : LIGHT_DEFAULT_CUTOFF; break;
    case KEY_ACTION_SCREENSHOT: save_numbered_screenshot(a, w); break;
    default: break; /* the window's own (app_window_key), or a mouse gesture */
    }
    return true;
}

/* The loop's state between frames. */
typedef struct loop {
    const app_desc *desc;
    const cli_options *opt;
    app_hooks hooks;
    app_window window;
    double *times;   /* --bench: one per timed frame */
    double *pass_ms; /* --bench: FRAME_TIMER_MAX_PASSES per timed frame */
    long total;      /* frames to draw; 0: until the window closes */
    bool paused;
    double last_clock, title_clock, move_clock;
    frame_times title_sum; /* the timer's frames since the title was last updated */
    int title_n;
    const char *last_note; /* the frame's note last logged */
    bool told_lines_full;
} loop;

/* Size changes (window, or a resize-cycle hook) recreate the targets. */
static bool follow_size(app *a, loop *l)
{
    int w = a->width, h = a->height;
    app_hooks_resize(&l->hooks, a, l->opt, &w, &h);
    if (platform_is_windowed())
        platform_framebuffer_size(&w, &h);
    if (w == a->width && h == a->height)
        return true;
    a->width = w, a->height = h;
    log_debug("resize to %dx%d", w, h);
    return app_check_size_limits(w, h) && app_target_make(a) && (!l->desc->resize || l->desc->resize(a)) &&
           app_window_resize(&l->window, a);
}

/* --bench: the frame's wall time and the timer's passes (one frame late with GPU queries). */
static void record_bench(const app *a, loop *l, double ms)
{
    long i = a->frame_index - l->opt->warmup;
    if (i < 0)
        return;
    l->times[i] = ms;
    for (int k = 0; k < FRAME_TIMER_MAX_PASSES; k++)
        l->pass_ms[i * FRAME_TIMER_MAX_PASSES + k] = k < a->timer.last.count ? a->timer.last.ms[k] : 0.0;
}

/* The window's figure: the timer's frames, averaged over half a second. */
static void record_title(const app *a, loop *l, double now)
{
    const frame_times *f = &a->timer.last;
    if (f->valid) {
        if (l->title_n == 0 || l->title_sum.count != f->count)
            l->title_sum = (frame_times){.count = f->count}, l->title_n = 0;
        for (int k = 0; k < f->count; k++)
            l->title_sum.names[k] = f->names[k], l->title_sum.ms[k] += f->ms[k];
        l->title_sum.frame_ms += f->frame_ms;
        l->title_n++;
    }
    if (now - l->title_clock > 0.5 && l->title_n > 0) {
        app_text_title(a, &l->title_sum, l->title_n, l->paused);
        frame_times *avg = &l->window.times; /* the overlay's figures */
        *avg = l->title_sum;
        for (int k = 0; k < avg->count; k++)
            avg->ms[k] /= l->title_n;
        avg->frame_ms /= l->title_n;
        l->title_sum = (frame_times){0};
        l->title_clock = now, l->title_n = 0;
    }
}

/* What the frame said in words, logged when it changes: its note (the window shows it too), and a
 * chapter's overlay lines that filled their room (cut: the room must grow). */
static void tell_frame_words(const app *a, loop *l)
{
    if (a->note && a->note != l->last_note)
        log_info("note: %s", a->note);
    l->last_note = a->note;
    if (strlen(a->overlay_lines) + 1 >= sizeof a->overlay_lines && !l->told_lines_full) {
        log_error("%s: its overlay lines filled all %zu bytes of app.overlay_lines and were cut: raise "
                  "APP_OVERLAY_LINES",
                  a->cli->program, sizeof a->overlay_lines);
        l->told_lines_full = true;
    }
}

/* One frame: update, draw, time; false stops the loop with *rc set when it failed. */
static bool draw_frame(app *a, loop *l, int *rc)
{
    double now = platform_time();
    if (platform_is_windowed() && !l->paused && !l->opt->bench)
        a->time += (float)(now - l->last_clock);
    l->last_clock = now;
    app_hooks_after_frame(&l->hooks, platform_is_minimised());
    double t0 = platform_time();
    frame_timer_begin(&a->timer);
    frame_timer_mark("scene update");
    a->count_pixels = l->opt->bench || l->window.overlay_on;
    a->shaded_pixels = -1;
    a->work_name = NULL;
    a->lights_per_pixel = 1.0;
    a->overlay_lines[0] = '\0'; /* a frame that draws no G-buffer leaves no G-buffer line */
    a->note = NULL;
    a->view_drawn = a->cli->views ? a->cli->views[a->view] : NULL;
    bool ok = gpu_scene_update(&a->gs, a->time, a->cutoff, a->width, a->height) && l->desc->frame(a) &&
              app_window_compare(&l->window, a, l->desc->draw_forward);
    frame_timer_end(&a->timer);
    tell_frame_words(a, l);
    if (!ok || (!gl_check("frame") && l->opt->gl_debug)) {
        *rc = EXIT_CODE_RUNTIME;
        return false;
    }
    if (l->opt->bench) {
        glFinish(); /* the frame's wall time, whatever the pass clock; less compare mode's forward */
        const app_frame_split split = app_frame_split_of(&a->timer.last);
        record_bench(a, l, (platform_time() - t0) * 1000.0 - split.forward_ms - split.compose_ms);
    }
    if (platform_is_windowed() || l->window.have_script)
        record_title(a, l, now);
    return true;
}

/* Keys, the script's events and the mouse, before a frame; false to quit. */
static bool take_input(app *a, loop *l)
{
    double now = platform_time();
    input_script_feed(&l->window.script, a->frame_index);
    bool running = true;
    for (int key; (key = input_take_key()) != 0;)
        running = running && handle_key(a, l->desc, &l->window, key, &l->paused);
    app_window_move(&l->window, a, now - l->move_clock);
    l->move_clock = now;
    return running;
}

/* After a frame: --screenshot on the last one, the script's events, the window; false to stop. */
static bool show_frame(app *a, loop *l, bool last, int *rc)
{
    const fbo *display = app_window_display(&l->window, a, l->paused);
    const fbo *picture = display ? display : l->window.shown;
    if (last && l->opt->screenshot && !app_window_save(l->opt->overlay ? picture : l->window.shown, l->opt->screenshot)) {
        *rc = EXIT_CODE_RUNTIME;
        return false;
    }
    bool going = !l->window.have_script || app_window_after_frame(&l->window, a, picture, l->paused, rc);
    platform_present(picture->id, a->width, a->height);
    return going;
}

/* Frames until the count is reached or the window closes; returns the exit code. */
static int run_loop(app *a, loop *l)
{
    int rc = EXIT_CODE_OK;
    for (bool running = true; running;) {
        progress_frame(a->cli->program, a->frame_index, l->total); /* a line on stderr while a frame is slow */
        if (!app_hooks_minimise(&l->hooks, a, l->opt))
            return l->hooks.rc;
        platform_poll();
        if (platform_should_close())
            break;
        if (!follow_size(a, l))
            return EXIT_CODE_RUNTIME;
        if (!take_input(a, l) || !draw_frame(a, l, &rc))
            break;
        bool last = l->total > 0 && a->frame_index + 1 >= l->total;
        running = show_frame(a, l, last, &rc) && !last;
        a->frame_index++;
    }
    return rc;
}

/* Scene and context; on failure everything made so far is released. */
static int app_open(app *a, const app_desc *desc, const cli_options *opt)
{
    /* Input first: a bad scene is reported the same with or without a GL context. */
    if (!scene_load(opt->scene_path, &a->scene)) {
        if (opt->scene_path == a->default_scene)
            log_error("the default scene is looked for in the data folder %s (from %s): give --scene, "
                      "--data-dir or COURSE_DATA_DIR",
                      data_dir(), data_dir_origin());
        return EXIT_CODE_USAGE;
    }
    if (opt->camera && !app_apply_camera(&a->scene, opt->camera)) {
        scene_destroy(&a->scene);
        return EXIT_CODE_USAGE;
    }
    if (opt->falloff)
        a->scene.falloff = strcmp(opt->falloff, "windowed") == 0 ? SHADER_FALLOFF_WINDOWED : SHADER_FALLOFF_HARD;
    if (opt->lights >= 0 && !light_generate(&a->scene, opt->lights, opt->seed)) {
        scene_destroy(&a->scene);
        return EXIT_CODE_RUNTIME;
    }
    log_debug("data folder %s (from %s)", data_dir(), data_dir_origin());
    const platform_desc pd = {
        .backend = opt->backend, .width = opt->width, .height = opt->height, .title = desc->cli->program,
        .gl_debug = opt->gl_debug};
    int rc = platform_create(&pd);
    if (rc != EXIT_CODE_OK)
        scene_destroy(&a->scene);
    else if (platform_is_windowed())
        platform_framebuffer_size(&a->width, &a->height);
    return rc;
}

bool app_scene_features(app *a)
{
    char defines[256];
    a->features = shader_features_of(&a->scene);
    gl_program_compiled_reset();
    return shader_features_defines(&a->features, defines, sizeof defines) && gl_program_set_scene_defines(defines);
}

/* GL resources of the runner and the chapter. */
static int app_setup(app *a, const app_desc *desc)
{
    if (!app_check_size_limits(a->width, a->height) ||
        !app_check_size_memory(a->width, a->height, a->options->screenshot != NULL))
        return EXIT_CODE_USAGE;
    gpu_textures_set_anisotropy(a->options->anisotropy > 0 ? (float)a->options->anisotropy : GPU_TEXTURES_ANISOTROPY);
    if (!gpu_scene_create(&a->scene, &a->gs))
        return EXIT_CODE_USAGE; /* a model file that cannot be loaded is an input error */
    if (!app_scene_features(a))
        return EXIT_CODE_RUNTIME;
    if (desc->accepts_scene && !desc->accepts_scene(a))
        return EXIT_CODE_USAGE; /* a scene beyond the chapter's limits is an input error too */
    a->query = gl_query_create();
    if (!frame_timer_create(&a->timer))
        return EXIT_CODE_RUNTIME;
    /* --gbuffer: the layout of every G-buffer made from here on, the chapter's included; a reversed-Z
     * layout only where the chapter's lighting pass (its pass state, set by init) can take it. */
    const gbuffer_layout *asked = a->options->gbuffer ? gbuffer_layout_find(a->options->gbuffer) : NULL;
    /* A scene with metallic-roughness materials needs a layout that holds them; 17 and 19 prefer
     * reversed-Z (gbuffer_layout_for_chapter). */
    const gbuffer_layout *layout = gbuffer_layout_for_chapter(asked, &a->scene, desc->prefers_reversed_z);
    if (!layout || !gbuffer_set_default_layout(layout))
        return EXIT_CODE_USAGE;
    /* A scene with emissive materials: every G-buffer gets RT2 for it (common/render/gbuffer.h). */
    gbuffer_set_default_emissive(gbuffer_scene_emits(&a->scene));
    if (!app_target_make(a) || (desc->init && !desc->init(a)))
        return a->input_error ? EXIT_CODE_USAGE : EXIT_CODE_RUNTIME;
    if (a->gs.transparent_count > 0 && !desc->draws_glass && !app_renderer_is_forward(a))
        log_warn("%s: the scene's %d glass object(s) are not drawn by this chapter's %s renderer (chapter 12 adds "
                 "glass; --renderer forward draws it)",
                 desc->cli->program, a->gs.transparent_count, a->cli->renderers[a->renderer]);
    return !asked || desc->takes_reversed_z || gbuffer_layout_fits_pass(layout, a->pass_state) ? EXIT_CODE_OK
                                                                                               : EXIT_CODE_USAGE;
}

static void app_close(app *a, const app_desc *desc)
{
    if (desc->cleanup)
        desc->cleanup(a);
    fbo_destroy(&a->target);
    gl_query_destroy(&a->query);
    frame_timer_destroy(&a->timer);
    app_forward_destroy(&a->forward);
    gpu_scene_destroy(&a->gs);
    gl_util_shutdown();
    if (gl_live_objects() != 0)
        log_warn("%ld GL object(s) still alive at exit", gl_live_objects());
    platform_destroy();
    scene_destroy(&a->scene);
}

/* After the loop: the hooks' verdict, the bench line, a closed window's screenshot, GL errors. */
static int app_finish(app *a, loop *l, int rc)
{
    const cli_options *opt = l->opt;
    progress_end();
    if (rc == EXIT_CODE_OK)
        rc = app_hooks_check(&l->hooks, a, opt);
    if (rc == EXIT_CODE_OK && opt->bench && a->frame_index == l->total)
        app_bench_print(a, l->times, l->pass_ms, opt->frames);
    if (rc == EXIT_CODE_OK && opt->screenshot && l->total == 0 && !app_window_save(l->window.shown, opt->screenshot))
        rc = EXIT_CODE_RUNTIME; /* window closed by the user: keep the last frame */
    if (opt->gl_debug && gl_debug_error_count() > 0) {
        log_error("%ld GL error(s) during the run", gl_debug_error_count());
        if (rc == EXIT_CODE_OK)
            rc = EXIT_CODE_RUNTIME;
    }
    return rc;
}

void app_init(app *a, const cli_desc *cli, const cli_options *opt)
{
    memset(a, 0, sizeof *a);
    a->options = opt;
    a->cli = cli;
    a->width = opt->width;
    a->height = opt->height;
    a->renderer = cli->renderers ? cli_choice_index(cli->renderers, opt->renderer) : 0;
    a->view = cli->views ? cli_choice_index(cli->views, opt->view) : 0;
    a->time = opt->time;
    a->cutoff = opt->cutoff;
    a->shaded_pixels = -1;
}

cli_desc app_cli_of(const app_desc *desc, const char **renderers_plus)
{
    cli_desc cli = *desc->cli;
    cli.default_cutoff = LIGHT_DEFAULT_CUTOFF;
    cli.renderers = app_with_forward_plus(cli.renderers, renderers_plus, APP_RENDERERS_MAX);
    return cli;
}

int app_run(const app_desc *desc, int argc, char **argv)
{
    static const char *renderers_plus[APP_RENDERERS_MAX];
    cli_desc cli = app_cli_of(desc, renderers_plus);
    cli_options opt;
    int rc = cli_parse(argc, argv, &cli, &opt);
    if (rc != EXIT_CODE_OK)
        return rc == CLI_PARSE_DONE ? 0 : rc;
    log_set_verbose(opt.verbose);
    log_set_quiet(opt.bench);
    if (opt.screenshot && image_format_of(opt.screenshot) == IMAGE_UNKNOWN) {
        log_error("%s: --screenshot '%s': unknown image format (end the name in .png, .bmp, .tga or .jpg)",
                  desc->cli->program, opt.screenshot);
        return EXIT_CODE_USAGE;
    }
    data_dir_set(opt.data_dir);
    app a;
    app_init(&a, &cli, &opt);
    const char *lesson_scene = cli.default_scene ? cli.default_scene : CLI_DEFAULT_SCENE;
    if (!opt.scene_path)
        opt.scene_path =
            data_dir_path(lesson_scene, a.default_scene, sizeof a.default_scene) ? a.default_scene : lesson_scene;
    if (opt.gl_info)
        return app_print_gl_info(&opt, desc->cli->program);
    if ((rc = app_open(&a, desc, &opt)) != EXIT_CODE_OK)
        return rc;

    loop l = {.desc = desc, .opt = &opt, .paused = opt.paused, .last_clock = platform_time()};
    l.move_clock = l.last_clock;
    app_hooks_init(&l.hooks, &opt);
    input_reset();
    rc = app_setup(&a, desc);
    if (rc == EXIT_CODE_OK && !app_window_create(&l.window, &a, &opt))
        rc = EXIT_CODE_USAGE; /* a bad script is an input error */
    if (rc == EXIT_CODE_OK && opt.bench &&
        (!(l.times = malloc((size_t)opt.frames * sizeof *l.times)) ||
         !(l.pass_ms = calloc((size_t)opt.frames * FRAME_TIMER_MAX_PASSES, sizeof *l.pass_ms)))) {
        log_error("out of memory for %d frame times", opt.frames);
        rc = EXIT_CODE_RUNTIME;
    }
    l.total = (long)opt.frames + (opt.bench ? opt.warmup : 0);
    if (l.total > 0)
        l.total += l.hooks.cycle_end + opt.minimise_cycle;
    if (l.total > 0 && input_script_last_frame(&l.window.script) >= l.total)
        l.total = input_script_last_frame(&l.window.script) + 1; /* a script runs to its end */
    if (rc == EXIT_CODE_OK)
        rc = app_finish(&a, &l, run_loop(&a, &l));
    app_window_destroy(&l.window);
    app_close(&a, desc);
    free(l.times);
    free(l.pass_ms);
    return rc;
}
