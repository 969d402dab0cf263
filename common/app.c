/* app.c - see app.h. */
#include "app.h"

#include "gl_util.h"
#include "light.h"
#include "log.h"
#include "platform.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define MINIMISE_WAIT 2.0  /* seconds --minimise-cycle waits for the window manager to iconify */
#define MINIMISED_FOR 0.1  /* seconds it stays minimised before the loop asks for it back */

forward_options app_forward_options(const char *name)
{
    forward_options o = {.prepass = true, .light_lists = true};
    if (name && strcmp(name, "forward-naive") == 0)
        o.prepass = false, o.light_lists = false;
    else if (name && strcmp(name, "forward-prepass") == 0)
        o.light_lists = false;
    else if (name && strcmp(name, "forward-lists") == 0)
        o.prepass = false;
    return o;
}

bool app_renderer_is(const app *a, const char *name)
{
    return a->cli->renderers && strcmp(a->cli->renderers[a->renderer], name) == 0;
}

bool app_view_is(const app *a, const char *name)
{
    return a->cli->views && strcmp(a->cli->views[a->view], name) == 0;
}

const char *app_extra(const app *a, const char *name) { return cli_extra_value(a->cli, a->options, name); }

bool app_render_forward(app *a)
{
    const char *name = a->cli->renderers ? a->cli->renderers[a->renderer] : "forward";
    forward_options o = app_forward_options(strncmp(name, "forward", 7) == 0 ? name : "forward");
    o.count_pixels = a->options->bench;
    glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
    bool ok = forward_render(&a->fwd, &a->gs, o);
    if (o.count_pixels)
        a->shaded_pixels = forward_shaded_pixels(&a->fwd);
    return ok;
}

static bool make_target(app *a)
{
    fbo_destroy(&a->target);
    const fbo_desc desc = {
        .color_formats = {GL_RGBA8}, .color_count = 1, .depth_format = GL_DEPTH_COMPONENT32F, .name = "target"};
    return fbo_create(&a->target, &desc, a->width, a->height);
}

static bool check_size_limits(int width, int height)
{
    GLint max_tex = 0, max_rb = 0, max_vp[2] = {0, 0};
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_tex);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_rb);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, max_vp);
    int limit_w = max_tex, limit_h = max_tex;
    limit_w = limit_w < max_rb ? limit_w : max_rb;
    limit_h = limit_h < max_rb ? limit_h : max_rb;
    limit_w = limit_w < max_vp[0] ? limit_w : max_vp[0];
    limit_h = limit_h < max_vp[1] ? limit_h : max_vp[1];
    if (width > limit_w || height > limit_h) {
        log_error("--size %dx%d is larger than this GL allows (%dx%d: GL_MAX_TEXTURE_SIZE %d, "
                  "GL_MAX_RENDERBUFFER_SIZE %d, GL_MAX_VIEWPORT_DIMS %dx%d)",
                  width, height, limit_w, limit_h, max_tex, max_rb, max_vp[0], max_vp[1]);
        return false;
    }
    return true;
}

static int compare_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

/* key=value output keeps values free of spaces. */
static void print_token(const char *s)
{
    for (; s && *s; s++)
        putchar(*s == ' ' || *s == '\t' || *s == '=' ? '_' : *s);
}

static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

static void print_bench(const app *a, double *ms, int n)
{
    qsort(ms, (size_t)n, sizeof *ms, compare_double);
    double sum = 0;
    for (int i = 0; i < n; i++)
        sum += ms[i];
    double median = n % 2 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
    char scene_name[256];
    snprintf(scene_name, sizeof scene_name, "%s", base_name(a->options->scene_path));
    char *dot = strrchr(scene_name, '.');
    if (dot)
        *dot = '\0';
    printf("bench: chapter=%s renderer=%s scene=", a->cli->program,
           a->cli->renderers ? a->cli->renderers[a->renderer] : "forward");
    print_token(scene_name);
    printf(" lights=%d active_lights=%d culled_lights=%d size=%dx%d frames=%d warmup=%d median_ms=%.3f "
           "min_ms=%.3f max_ms=%.3f mean_ms=%.3f fps=%.2f cutoff=%.6g shaded_pixels=%ld clock=glFinish+monotonic "
           "backend=%s gl_renderer=",
           a->scene.light_count, a->gs.light_count, a->gs.culled_count, a->width, a->height, n,
           a->options->warmup, median, ms[0], ms[n - 1], sum / n, median > 0 ? 1000.0 / median : 0.0, a->cutoff,
           a->shaded_pixels, platform_backend_name());
    print_token((const char *)glGetString(GL_RENDERER));
    printf("\n");
    fflush(stdout);
}

static bool save_screenshot(const app *a, const char *path)
{
    image img;
    if (!fbo_read_rgba8(&a->target, 0, &img))
        return false;
    bool ok = image_write_png(path, &img);
    image_destroy(&img);
    if (ok)
        log_info("wrote %s (%dx%d)", path, a->width, a->height);
    return ok;
}

static void update_title(const app *a, double ms)
{
    char title[512];
    snprintf(title, sizeof title, "%s | %s%s%s | %d lights (%d culled) | %dx%d | %.2f ms (%.0f fps) | cut-off %.4g%s",
             a->cli->program, a->cli->renderers ? a->cli->renderers[a->renderer] : "forward",
             a->cli->views ? " | view " : "", a->cli->views ? a->cli->views[a->view] : "", a->scene.light_count,
             a->gs.culled_count, a->width, a->height, ms, ms > 0 ? 1000.0 / ms : 0.0, a->cutoff,
             a->cutoff == 0 ? " (exact)" : "");
    platform_set_title(title);
}

/* --resize-cycle N: frame 0 at the base size, frames 1..N each at another size, frame N+1 back at
 * the base size. Consecutive sizes differ, so every one of those frames recreates the targets. */
static void resize_cycle_size(int base_w, int base_h, long frame, long cycle, int *w, int *h)
{
    static const int scale[3][2] = {{2, 2}, {3, 4}, {4, 3}}; /* quarters of the base size */
    if (frame > cycle) {
        *w = base_w, *h = base_h;
        return;
    }
    const int *s = scale[(frame - 1) % 3];
    *w = base_w * s[0] / 4 > 0 ? base_w * s[0] / 4 : 1;
    *h = base_h * s[1] / 4 > 0 ? base_h * s[1] / 4 : 1;
}

/* Keys every chapter shares; returns false to quit. */
static bool handle_key(app *a, const app_desc *desc, int key, bool *paused)
{
    if (desc->key && desc->key(a, key))
        return true;
    switch (key) {
    case PLATFORM_KEY_ESCAPE:
    case 'Q': return false;
    case 'R':
        if (a->cli->renderers) {
            a->renderer = a->cli->renderers[a->renderer + 1] ? a->renderer + 1 : 0;
            log_info("renderer: %s", a->cli->renderers[a->renderer]);
        }
        break;
    case 'V':
        if (a->cli->views) {
            a->view = a->cli->views[a->view + 1] ? a->view + 1 : 0;
            log_info("view: %s", a->cli->views[a->view]);
        }
        break;
    case PLATFORM_KEY_SPACE: *paused = !*paused; break;
    case '[': a->cutoff = a->cutoff > 0 ? a->cutoff / 2 : LIGHT_DEFAULT_CUTOFF; break;
    case ']': a->cutoff = a->cutoff > 0 ? a->cutoff * 2 : LIGHT_DEFAULT_CUTOFF; break;
    case '0': a->cutoff = a->cutoff > 0 ? 0 : LIGHT_DEFAULT_CUTOFF; break;
    case 'P': {
        char path[64];
        mkdir("out", 0755);
        snprintf(path, sizeof path, "out/%s-%ld.png", a->cli->program, a->frame_index);
        save_screenshot(a, path);
        break;
    }
    default: break;
    }
    return true;
}

int app_run(const app_desc *desc, int argc, char **argv)
{
    cli_options opt;
    int rc = cli_parse(argc, argv, &desc->cli, &opt);
    if (rc == CLI_EXIT_DONE)
        return 0;
    if (rc != CLI_EXIT_OK)
        return rc;
    log_set_verbose(opt.verbose);
    log_set_quiet(opt.bench);

    app a;
    memset(&a, 0, sizeof a);
    a.options = &opt;
    a.cli = &desc->cli;
    a.width = opt.width;
    a.height = opt.height;
    a.renderer = desc->cli.renderers ? cli_choice_index(desc->cli.renderers, opt.renderer) : 0;
    a.view = desc->cli.views ? cli_choice_index(desc->cli.views, opt.view) : 0;
    a.time = opt.time;
    a.cutoff = opt.cutoff;
    a.shaded_pixels = -1;

    /* Input first: a bad scene is reported the same with or without a GL context. */
    if (!scene_load(opt.scene_path, &a.scene))
        return CLI_EXIT_USAGE;
    if (opt.lights >= 0 && !light_generate(&a.scene, opt.lights, opt.seed)) {
        scene_destroy(&a.scene);
        return CLI_EXIT_RUNTIME;
    }

    const platform_desc pd = {
        .backend = opt.backend, .width = opt.width, .height = opt.height, .title = desc->cli.program,
        .gl_debug = opt.gl_debug};
    rc = platform_create(&pd);
    if (rc != CLI_EXIT_OK) {
        scene_destroy(&a.scene);
        return rc;
    }
    if (platform_is_windowed())
        platform_framebuffer_size(&a.width, &a.height);

    double *times = NULL;
    bool ok = check_size_limits(a.width, a.height);
    if (!ok)
        rc = CLI_EXIT_USAGE;
    if (ok && !gpu_scene_create(&a.scene, &a.gs)) {
        ok = false;
        rc = CLI_EXIT_USAGE; /* a model file that cannot be loaded is an input error */
    }
    ok = ok && forward_create(&a.fwd) && make_target(&a) && (!desc->init || desc->init(&a));
    if (ok && opt.bench && !(times = malloc((size_t)opt.frames * sizeof *times))) {
        log_error("out of memory for %d frame times", opt.frames);
        ok = false;
    }
    if (!ok && rc == CLI_EXIT_OK)
        rc = CLI_EXIT_RUNTIME;

    bool paused = opt.paused, running = ok;
    double last_clock = platform_time(), title_clock = 0.0, ms_sum = 0.0;
    int ms_n = 0;
    long total = (long)opt.frames + (opt.bench ? opt.warmup : 0);
    long cycle_end = opt.resize_cycle > 0 ? opt.resize_cycle + 1 : 0, live_before = 0;
    int base_w = a.width, base_h = a.height;
    long live_before_minimise = 0, minimised_frames = 0;
    if (total > 0)
        total += cycle_end + opt.minimise_cycle;
    while (running) {
        /* --minimise-cycle: one round per frame boundary; the platform_poll() below must sleep
         * through it, so any frame drawn while minimised is counted as a failure. */
        if (a.frame_index >= 1 && a.frame_index <= opt.minimise_cycle) {
            if (a.frame_index == 1)
                live_before_minimise = gl_live_objects();
            if (!platform_minimise(MINIMISE_WAIT)) {
                log_error("no window manager: cannot minimise");
                rc = CLI_EXIT_SKIP;
                break;
            }
            log_debug("minimised (round %ld of %d)", a.frame_index, opt.minimise_cycle);
            platform_restore_at(platform_time() + MINIMISED_FOR);
        }
        platform_poll();
        if (platform_should_close())
            break;
        int w = a.width, h = a.height;
        if (a.frame_index >= 1 && a.frame_index <= cycle_end) {
            if (a.frame_index == 1) /* after one frame: lazily made objects exist by now */
                live_before = gl_live_objects(), base_w = a.width, base_h = a.height;
            resize_cycle_size(base_w, base_h, a.frame_index, opt.resize_cycle, &w, &h);
            platform_set_window_size(w, h);
        }
        if (platform_is_windowed())
            platform_framebuffer_size(&w, &h);
        if (w != a.width || h != a.height) {
            a.width = w, a.height = h;
            log_debug("resize to %dx%d", w, h);
            if (!check_size_limits(w, h) || !make_target(&a) || (desc->resize && !desc->resize(&a))) {
                rc = CLI_EXIT_RUNTIME;
                break;
            }
        }
        for (int key; (key = platform_take_key()) != 0;)
            if (!handle_key(&a, desc, key, &paused))
                running = false;
        if (!running)
            break;

        double now = platform_time();
        if (platform_is_windowed() && !paused && !opt.bench)
            a.time += (float)(now - last_clock);
        last_clock = now;

        if (platform_is_minimised())
            minimised_frames++;
        double t0 = platform_time();
        if (!gpu_scene_update(&a.gs, a.time, a.cutoff, a.width, a.height) || !desc->frame(&a)) {
            rc = CLI_EXIT_RUNTIME;
            break;
        }
        if (opt.bench)
            glFinish();
        double ms = (platform_time() - t0) * 1000.0;
        a.frame_ms = ms;
        if (opt.bench && a.frame_index >= opt.warmup)
            times[a.frame_index - opt.warmup] = ms;
        if (!gl_check("frame") && opt.gl_debug) {
            rc = CLI_EXIT_RUNTIME;
            break;
        }
        a.frame_index++;
        bool last = total > 0 && a.frame_index >= total;
        if (last && opt.screenshot && !save_screenshot(&a, opt.screenshot)) {
            rc = CLI_EXIT_RUNTIME;
            break;
        }
        platform_present(a.target.id, a.width, a.height);
        if (platform_is_windowed()) {
            ms_sum += ms, ms_n++;
            if (now - title_clock > 0.5) {
                update_title(&a, ms_sum / ms_n);
                title_clock = now, ms_sum = 0.0, ms_n = 0;
            }
        }
        if (last)
            break;
    }
    if (rc == CLI_EXIT_OK && cycle_end > 0 && a.frame_index > cycle_end && gl_live_objects() != live_before) {
        log_error("--resize-cycle: %ld live GL objects before %d resizes, %ld after", live_before,
                  opt.resize_cycle, gl_live_objects());
        rc = CLI_EXIT_RUNTIME;
    }
    if (rc == CLI_EXIT_OK && minimised_frames > 0) {
        log_error("--minimise-cycle: %ld frame(s) drawn while the window was minimised", minimised_frames);
        rc = CLI_EXIT_RUNTIME;
    } else if (rc == CLI_EXIT_OK && opt.minimise_cycle > 0 && a.frame_index > opt.minimise_cycle &&
               gl_live_objects() != live_before_minimise) {
        log_error("--minimise-cycle: %ld live GL objects before %d minimise cycles, %ld after",
                  live_before_minimise, opt.minimise_cycle, gl_live_objects());
        rc = CLI_EXIT_RUNTIME;
    }
    if (rc == CLI_EXIT_OK && opt.bench && a.frame_index == total)
        print_bench(&a, times, opt.frames);
    if (rc == CLI_EXIT_OK && opt.screenshot && total == 0 && !save_screenshot(&a, opt.screenshot))
        rc = CLI_EXIT_RUNTIME; /* window closed by the user: keep the last frame */
    if (opt.gl_debug && gl_debug_error_count() > 0) {
        log_error("%ld GL error(s) during the run", gl_debug_error_count());
        if (rc == CLI_EXIT_OK)
            rc = CLI_EXIT_RUNTIME;
    }

    if (desc->cleanup)
        desc->cleanup(&a);
    fbo_destroy(&a.target);
    forward_destroy(&a.fwd);
    gpu_scene_destroy(&a.gs);
    gl_util_shutdown();
    if (gl_live_objects() != 0)
        log_warn("%ld GL object(s) still alive at exit", gl_live_objects());
    platform_destroy();
    scene_destroy(&a.scene);
    free(times);
    return rc;
}
