/* bench.c - forward against deferred, measured: time per frame, lighting work and error, swept over
 * light counts, scenes, renderers and the cut-off. Writes out/bench.csv, out/bench.md and two plots.
 *
 * Read docs/08_compare.md first: it shows a run's tables and explains them. The program is a loop
 * over "cases" (scene, lights, cut-off); in each case every renderer draws the same frame, frame by
 * frame in turn (round robin), so a noisy moment of the machine hits them all alike. After the
 * timed frames one untimed frame per renderer counts the lighting work (GL_SAMPLES_PASSED) and
 * keeps the picture for the error against the exact reference (forward, fp32, cut-off 0).
 *
 *   build/bin/bench                 the default sweep at 800x800 (a few minutes on 2 cores)
 *   build/bin/bench --quick         a small sweep (seconds): the test suite checks its output's shape
 */
#include "bench/bench_work.h"

#include "deferred_fullscreen.h"
#include "fbo.h"
#include "forward.h"
#include "gbuffer.h"
#include "gl_util.h"
#include "gpu_scene.h"
#include "image.h"
#include "light.h"
#include "light_volumes.h"
#include "log.h"
#include "platform.h"
#include "scene.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#define MAX_LIST 32
#define NAME_MAX_LEN 64
#define LIGHTS_OWN (-1) /* the scene's own lights, as the scene file has them */

/* ---- renderers ------------------------------------------------------------------------------- */

typedef enum renderer_kind { KIND_FORWARD, KIND_DEFERRED_FULLSCREEN, KIND_DEFERRED_VOLUMES } renderer_kind;

typedef struct renderer_def {
    const char *name;
    renderer_kind kind;
    bool prepass, light_lists; /* forward only */
    bool in_cutoff_sweep;      /* the naive forward loop ignores the cut-off's main effect: left out */
} renderer_def;

/* A faster variant plugs in here: a name, a kind, and a case in render_frame(). */
static const renderer_def renderer_defs[] = {
    {"forward-naive", KIND_FORWARD, false, false, false},
    {"forward-prepass-lists", KIND_FORWARD, true, true, true},
    {"forward-prepass", KIND_FORWARD, true, false, true},
    {"forward-lists", KIND_FORWARD, false, true, true},
    {"deferred-fullscreen", KIND_DEFERRED_FULLSCREEN, false, false, true},
    {"deferred-volumes", KIND_DEFERRED_VOLUMES, false, false, true},
};
#define RENDERER_COUNT ((int)(sizeof renderer_defs / sizeof renderer_defs[0]))
static const char *const default_renderers =
    "forward-naive,forward-prepass-lists,deferred-fullscreen,deferred-volumes";

/* ---- options ------------------------------------------------------------------------------ */

typedef struct bench_options {
    int lights[MAX_LIST];
    int light_list_count;
    char scenes[MAX_LIST][NAME_MAX_LEN];
    int scene_count;
    int renderers[MAX_LIST];
    int renderer_count;
    double cutoffs[MAX_LIST]; /* in 1/256 units */
    int cutoff_count;
    char cutoff_scene[NAME_MAX_LEN];
    int cutoff_lights;
    int width, height;
    int frames, warmup, min_frames;
    double max_frame_ms, case_budget_ms;
    int error_max_lights;
    uint32_t seed;
    const char *scene_dir;
    const char *out_dir;
    bool quick, plots;
    cli_backend backend;
} bench_options;

/* ---- results ------------------------------------------------------------------------------ */

typedef enum row_status { STATUS_MEASURED, STATUS_FEW_FRAMES, STATUS_SKIPPED } row_status;
static const char *const status_names[] = {"measured", "few_frames", "skipped"};

typedef struct bench_row {
    const char *sweep; /* "lights" or "cutoff" */
    char scene[NAME_MAX_LEN];
    int renderer;    /* index into renderer_defs */
    bool own_lights; /* the scene file's lights, not generated ones */
    int lights, active_lights;
    double cutoff;
    int frames, warmup;
    double median_ms, min_ms, max_ms;
    row_status status;
    char note[160];
    bool have_work;
    long long shaded, covered, ideal;
    double light_evals, work_ratio;
    bool have_error8, have_error_hdr;
    image_stats error8;
    bench_error error_hdr;
} bench_row;

static struct {
    bench_options opt;
    forward fwd;
    gbuffer gbuf;
    deferred_fullscreen fullscreen;
    light_volumes volumes;
    fbo target, linear_target;
    /* the exact reference of the current (scene, lights): 8-bit and linear */
    image ref8;
    float *ref_hdr;
    char ref_key[NAME_MAX_LEN + 32];
    bool have_ref;
    float *depth, *hdr;
    double *positions;
    bench_row *rows;
    int row_count, row_cap;
    int case_index, case_total;
    char cpu[256];
    int cores;
    char gl_renderer[256], gl_version[256];
} state;

/* ---- command line ------------------------------------------------------------------------------ */

static void print_help(FILE *f)
{
    fprintf(
        f,
        "usage: bench [options]\n"
        "Times forward and deferred renderers on the same frames, counts their lighting work and\n"
        "measures their error against an exact reference; writes DIR/bench.csv, DIR/bench.md,\n"
        "DIR/time_vs_lights.png and DIR/speed_vs_error.png (gnuplot).\n\n"
        "  --lights LIST         light counts, comma-separated; 'scene' = the scene's own lights\n"
        "                        (default 1,4,16,64,256,1024,4096,scene)\n"
        "  --scenes LIST         scene names in --scene-dir or .scene paths\n"
        "                        (default default,city,bunnies,sphere,teapots)\n"
        "  --renderers LIST      of: forward-naive forward-prepass-lists forward-prepass forward-lists\n"
        "                        deferred-fullscreen deferred-volumes (default: naive, prepass-lists,\n"
        "                        fullscreen, volumes)\n"
        "  --cutoffs LIST        cut-off sweep in 1/256 units (default 0.5,1,2,5,10,20,32)\n"
        "  --cutoff-scene NAME   scene of the cut-off sweep (default: the first of --scenes)\n"
        "  --cutoff-lights N     light count of the cut-off sweep (default 256)\n"
        "  --size WxH            frame size (default 800x800)\n"
        "  --frames N            timed frames per renderer and case (default 10)\n"
        "  --warmup N            untimed frames first (default 2; llvmpipe compiles shaders at first draw)\n"
        "  --max-frame-ms MS     skip a case predicted slower than this per frame (default 1500);\n"
        "                        its time is extrapolated from the two previous light counts\n"
        "  --case-budget-ms MS   time per renderer and case; slower cases take fewer frames, at least 3\n"
        "                        (default 1500)\n"
        "  --error-max-lights N  measure the error only up to N lights: the exact reference shades\n"
        "                        every pixel with every light (default 256; the cut-off\n"
        "                        sweep always measures it)\n"
        "  --seed N              light_generate seed (default 1)\n"
        "  --scene-dir DIR       where scene names are looked up (default assets/scenes)\n"
        "  --out DIR             output folder (default out)\n"
        "  --backend egl|osmesa  headless GL (default egl)\n"
        "  --no-plots            skip gnuplot\n"
        "  --quick               small sweep for tests: 160x160, default scene, 1,16,64 lights,\n"
        "                        3 frames, cut-offs 2,5,16 at 16 lights\n"
        "  --help                this text\n\n"
        "exit codes: 0 ok, 1 runtime failure, 2 usage error, 77 no GL context\n");
}

static bool usage_error(const char *what, const char *value)
{
    fprintf(stderr, "bench: %s: '%s' (see --help)\n", what, value ? value : "(missing)");
    return false;
}

static bool parse_int(const char *s, int lo, int hi, int *out)
{
    if (!s || !*s)
        return false;
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (*end || errno || v < lo || v > hi)
        return false;
    *out = (int)v;
    return true;
}

static bool parse_double(const char *s, double lo, double hi, double *out)
{
    if (!s || !*s)
        return false;
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (*end || errno || !(v >= lo && v <= hi))
        return false;
    *out = v;
    return true;
}

/* Splits a comma-separated list into items; false on an empty item, a too long one, or too many. */
static bool split_list(const char *list, char items[MAX_LIST][NAME_MAX_LEN], int *count)
{
    *count = 0;
    if (!list || !*list)
        return false;
    const char *p = list;
    for (;;) {
        const char *comma = strchr(p, ',');
        size_t len = comma ? (size_t)(comma - p) : strlen(p);
        if (len == 0 || len >= NAME_MAX_LEN || *count == MAX_LIST)
            return false;
        memcpy(items[*count], p, len);
        items[*count][len] = '\0';
        (*count)++;
        if (!comma)
            return true;
        p = comma + 1;
    }
}

static bool set_lights(bench_options *o, const char *list)
{
    char items[MAX_LIST][NAME_MAX_LEN];
    if (!split_list(list, items, &o->light_list_count))
        return usage_error("bad --lights list", list);
    for (int i = 0; i < o->light_list_count; i++)
        if (strcmp(items[i], "scene") == 0)
            o->lights[i] = LIGHTS_OWN;
        else if (!parse_int(items[i], 0, 1 << 20, &o->lights[i]))
            return usage_error("bad light count in --lights", items[i]);
    return true;
}

static bool set_renderers(bench_options *o, const char *list)
{
    char items[MAX_LIST][NAME_MAX_LEN];
    if (!split_list(list, items, &o->renderer_count))
        return usage_error("bad --renderers list", list);
    for (int i = 0; i < o->renderer_count; i++) {
        o->renderers[i] = -1;
        for (int r = 0; r < RENDERER_COUNT; r++)
            if (strcmp(items[i], renderer_defs[r].name) == 0)
                o->renderers[i] = r;
        if (o->renderers[i] < 0)
            return usage_error("unknown renderer in --renderers", items[i]);
    }
    return true;
}

static bool set_cutoffs(bench_options *o, const char *list)
{
    char items[MAX_LIST][NAME_MAX_LEN];
    if (!split_list(list, items, &o->cutoff_count))
        return usage_error("bad --cutoffs list", list);
    for (int i = 0; i < o->cutoff_count; i++)
        if (!parse_double(items[i], 1e-6, 255.0, &o->cutoffs[i]))
            return usage_error("bad cut-off in --cutoffs (1/256 units, > 0)", items[i]);
    return true;
}

static bool set_scenes(bench_options *o, const char *list)
{
    if (!split_list(list, o->scenes, &o->scene_count))
        return usage_error("bad --scenes list", list);
    return true;
}

/* Returns CLI_EXIT_OK, CLI_EXIT_USAGE or CLI_EXIT_DONE (after --help). */
static int parse_options(int argc, char **argv, bench_options *o)
{
    memset(o, 0, sizeof *o);
    /* The defaults go through the same parsers as the options (they cannot fail). */
    set_lights(o, "1,4,16,64,256,1024,4096,scene");
    set_scenes(o, "default,city,bunnies,sphere,teapots");
    set_renderers(o, default_renderers);
    set_cutoffs(o, "0.5,1,2,5,10,20,32");
    o->cutoff_lights = 256;
    o->width = o->height = 800;
    o->frames = 10, o->warmup = 2, o->min_frames = 3;
    o->max_frame_ms = 1500, o->case_budget_ms = 1500;
    o->error_max_lights = 256;
    o->seed = 1;
    o->scene_dir = "assets/scenes";
    o->out_dir = "out";
    o->plots = true;
    o->backend = CLI_BACKEND_EGL;
    /* --quick first, so the options after it can still change what it set. */
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--quick") == 0) {
            o->quick = true;
            set_lights(o, "1,16,64");
            set_scenes(o, "default");
            set_cutoffs(o, "2,5,16");
            o->cutoff_lights = 16;
            o->width = o->height = 160;
            o->frames = 3, o->warmup = 1;
            o->case_budget_ms = 1000;
        }
    }
    bool have_cutoff_scene = false;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        bool takes_value = true;
        bool good = true;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            print_help(stdout);
            return CLI_EXIT_DONE;
        } else if (strcmp(a, "--quick") == 0) {
            takes_value = false;
        } else if (strcmp(a, "--no-plots") == 0) {
            o->plots = false, takes_value = false;
        } else if (strcmp(a, "--lights") == 0) {
            good = set_lights(o, v);
        } else if (strcmp(a, "--scenes") == 0) {
            good = set_scenes(o, v);
        } else if (strcmp(a, "--renderers") == 0) {
            good = set_renderers(o, v);
        } else if (strcmp(a, "--cutoffs") == 0) {
            good = set_cutoffs(o, v);
        } else if (strcmp(a, "--cutoff-scene") == 0) {
            good = v && *v && strlen(v) < NAME_MAX_LEN
                       ? (snprintf(o->cutoff_scene, NAME_MAX_LEN, "%s", v), true)
                       : usage_error("bad --cutoff-scene", v);
            have_cutoff_scene = true;
        } else if (strcmp(a, "--cutoff-lights") == 0) {
            good = parse_int(v, 1, 1 << 20, &o->cutoff_lights) || usage_error("bad --cutoff-lights", v);
        } else if (strcmp(a, "--size") == 0) {
            int w = 0, h = 0;
            char extra;
            good = (v && sscanf(v, "%dx%d%c", &w, &h, &extra) == 2 && w >= 16 && h >= 16 && w <= 8192 &&
                    h <= 8192) ||
                   usage_error("bad --size (WxH, 16..8192)", v);
            o->width = w, o->height = h;
        } else if (strcmp(a, "--frames") == 0) {
            good = parse_int(v, 1, 100000, &o->frames) || usage_error("bad --frames", v);
        } else if (strcmp(a, "--warmup") == 0) {
            good = parse_int(v, 0, 100000, &o->warmup) || usage_error("bad --warmup", v);
        } else if (strcmp(a, "--max-frame-ms") == 0) {
            good = parse_double(v, 1, 1e9, &o->max_frame_ms) || usage_error("bad --max-frame-ms", v);
        } else if (strcmp(a, "--case-budget-ms") == 0) {
            good = parse_double(v, 1, 1e9, &o->case_budget_ms) || usage_error("bad --case-budget-ms", v);
        } else if (strcmp(a, "--error-max-lights") == 0) {
            good = parse_int(v, 0, 1 << 20, &o->error_max_lights) || usage_error("bad --error-max-lights", v);
        } else if (strcmp(a, "--seed") == 0) {
            int seed = 0;
            good = parse_int(v, 0, 2147483647, &seed) || usage_error("bad --seed", v);
            o->seed = (uint32_t)seed;
        } else if (strcmp(a, "--scene-dir") == 0) {
            good = (v && *v) || usage_error("bad --scene-dir", v);
            o->scene_dir = v;
        } else if (strcmp(a, "--out") == 0) {
            good = (v && *v) || usage_error("bad --out", v);
            o->out_dir = v;
        } else if (strcmp(a, "--backend") == 0) {
            if (v && strcmp(v, "egl") == 0)
                o->backend = CLI_BACKEND_EGL;
            else if (v && strcmp(v, "osmesa") == 0)
                o->backend = CLI_BACKEND_OSMESA;
            else
                good = usage_error("bad --backend (egl or osmesa)", v);
        } else {
            usage_error("unknown option", a);
            return CLI_EXIT_USAGE;
        }
        if (!good)
            return CLI_EXIT_USAGE;
        if (takes_value)
            i++;
    }
    if (o->min_frames > o->frames)
        o->min_frames = o->frames;
    if (!have_cutoff_scene)
        snprintf(o->cutoff_scene, NAME_MAX_LEN, "%s", o->scenes[0]);
    return CLI_EXIT_OK;
}

/* ---- machine ------------------------------------------------------------------------------ */

static void read_cpu_info(void)
{
    snprintf(state.cpu, sizeof state.cpu, "unknown CPU");
    state.cores = 0;
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (!f)
        return;
    char line[512];
    bool have_name = false;
    while (fgets(line, sizeof line, f)) {
        if (strncmp(line, "processor", 9) == 0)
            state.cores++;
        if (!have_name && strncmp(line, "model name", 10) == 0) {
            const char *colon = strchr(line, ':');
            if (colon) {
                snprintf(state.cpu, sizeof state.cpu, "%s", colon + 1 + (colon[1] == ' '));
                state.cpu[strcspn(state.cpu, "\n")] = '\0';
                have_name = true;
            }
        }
    }
    fclose(f);
}

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

/* ---- GL resources ------------------------------------------------------------------------------ */

static bool gl_resources_create(void)
{
    int w = state.opt.width, h = state.opt.height;
    const fbo_desc target = {.color_formats = {GL_RGBA8},
                             .color_count = 1,
                             .depth_format = GL_DEPTH_COMPONENT32F,
                             .name = "target"};
    const fbo_desc linear = {.color_formats = {GL_RGBA32F},
                             .color_count = 1,
                             .depth_format = GL_DEPTH_COMPONENT32F,
                             .name = "linear target"};
    size_t n = (size_t)w * (size_t)h;
    state.depth = malloc(n * sizeof *state.depth);
    state.hdr = malloc(4 * n * sizeof *state.hdr);
    state.ref_hdr = malloc(4 * n * sizeof *state.ref_hdr);
    state.positions = malloc(4 * n * sizeof *state.positions);
    if (!state.depth || !state.hdr || !state.ref_hdr || !state.positions) {
        log_error("out of memory for %dx%d read-back buffers", w, h);
        return false;
    }
    return forward_create(&state.fwd) && gbuffer_create(&state.gbuf, w, h) &&
           deferred_fullscreen_create(&state.fullscreen) &&
           light_volumes_create(&state.volumes, &state.gbuf) && fbo_create(&state.target, &target, w, h) &&
           fbo_create(&state.linear_target, &linear, w, h);
}

static void gl_resources_destroy(void)
{
    fbo_destroy(&state.linear_target);
    fbo_destroy(&state.target);
    light_volumes_destroy(&state.volumes);
    deferred_fullscreen_destroy(&state.fullscreen);
    gbuffer_destroy(&state.gbuf);
    forward_destroy(&state.fwd);
    image_destroy(&state.ref8);
    free(state.depth);
    free(state.hdr);
    free(state.ref_hdr);
    free(state.positions);
}

/* ---- one frame ------------------------------------------------------------------------------ */

typedef struct frame_result {
    long shaded;          /* GL_SAMPLES_PASSED of the lighting pass, when counted */
    double lights_per_px; /* lights each shaded fragment loops over (forward lists: the mean list) */
} frame_result;

/* Draws one frame of renderer r; the picture ends in state.target (or the linear target). */
static bool render_frame(int r, const gpu_scene *gs, bool count, bool linear, frame_result *out)
{
    const renderer_def *d = &renderer_defs[r];
    frame_result res = {-1, 1.0};
    bool ok = true;
    switch (d->kind) {
    case KIND_FORWARD: {
        const forward_options o = {.prepass = d->prepass,
                                   .light_lists = d->light_lists,
                                   .count_pixels = count,
                                   .linear_output = linear};
        glBindFramebuffer(GL_FRAMEBUFFER, linear ? state.linear_target.id : state.target.id);
        ok = forward_render(&state.fwd, gs, o);
        res.shaded = count ? forward_shaded_pixels(&state.fwd) : -1;
        res.lights_per_px = d->light_lists && gs->src->object_count > 0
                                ? (double)state.fwd.list_entries / gs->src->object_count
                                : gs->light_count;
        break;
    }
    case KIND_DEFERRED_FULLSCREEN: {
        ok = gbuffer_render(&state.gbuf, gs);
        glBindFramebuffer(GL_FRAMEBUFFER, state.target.id);
        const deferred_fullscreen_options o = {.count_pixels = count};
        ok = ok && deferred_fullscreen_render(&state.fullscreen, &state.gbuf, gs, o);
        res.shaded = count ? deferred_fullscreen_shaded_pixels(&state.fullscreen) : -1;
        res.lights_per_px = gs->light_count;
        break;
    }
    case KIND_DEFERRED_VOLUMES: {
        ok = gbuffer_render(&state.gbuf, gs);
        glBindFramebuffer(GL_FRAMEBUFFER, state.target.id);
        const light_volumes_options o = {.count_pixels = count};
        ok = ok && light_volumes_render(&state.volumes, &state.gbuf, gs, o);
        res.shaded = count ? light_volumes_shaded_pixels(&state.volumes) : -1;
        res.lights_per_px = 1.0; /* one fragment per (pixel, light) */
        break;
    }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (out)
        *out = res;
    return ok;
}

/* Linear radiance of renderer r's frame into state.hdr; false when it has none to give. */
static bool read_linear(int r, const gpu_scene *gs)
{
    const fbo *src = NULL;
    switch (renderer_defs[r].kind) {
    case KIND_FORWARD:
        if (!render_frame(r, gs, false, true, NULL))
            return false;
        src = &state.linear_target;
        break;
    case KIND_DEFERRED_VOLUMES: src = &state.volumes.accum; break; /* RGBA16F sum, before present */
    case KIND_DEFERRED_FULLSCREEN: return false;                   /* display-encodes in its only shader */
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, src->id);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, src->width, src->height, GL_RGBA, GL_FLOAT, state.hdr);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return gl_check("read_linear");
}

static bool read_depth(const fbo *f)
{
    glBindFramebuffer(GL_READ_FRAMEBUFFER, f->id);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, f->width, f->height, GL_DEPTH_COMPONENT, GL_FLOAT, state.depth);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return gl_check("read_depth");
}

/* ---- the exact reference ------------------------------------------------------------------------------ */

/* Forward, fp32, cut-off 0 (every light reaches every pixel): the same shading model with nothing
 * truncated. The plain GL_LESS forward pass, not the pre-pass: where two surfaces tie in depth it keeps
 * the same one as the G-buffer pass does, so those few pixels do not count as error. Kept while the
 * (scene, lights) stay. */
static bool make_reference(gpu_scene *gs, const char *key, double cutoff)
{
    if (state.have_ref && strcmp(state.ref_key, key) == 0)
        return true;
    state.have_ref = false;
    double t0 = now_ms();
    const int r = 0; /* forward-naive */
    bool ok = gpu_scene_update(gs, 0.0f, 0.0, state.opt.width, state.opt.height) &&
              render_frame(r, gs, false, false, NULL);
    image_destroy(&state.ref8);
    ok = ok && fbo_read_rgba8(&state.target, 0, &state.ref8) && read_linear(r, gs);
    if (ok)
        memcpy(state.ref_hdr, state.hdr,
               (size_t)state.opt.width * (size_t)state.opt.height * 4 * sizeof(float));
    ok = gpu_scene_update(gs, 0.0f, cutoff, state.opt.width, state.opt.height) && ok;
    if (!ok)
        return false;
    snprintf(state.ref_key, sizeof state.ref_key, "%s", key);
    state.have_ref = true;
    fprintf(stderr, "bench:   reference (forward fp32, cut-off 0, %d lights): %.0f ms\n", gs->light_count,
            now_ms() - t0);
    return true;
}

/* ---- prediction of slow cases
 * ------------------------------------------------------------------------------ */

/* Per renderer, the last two (lights, ms) of the current scene's light sweep. */
typedef struct history {
    int n[2];
    double ms[2];
    int count;
} history;

static double predict_ms(const history *h, int lights)
{
    if (h->count == 0)
        return 0.0;
    int n1 = h->n[h->count - 1];
    double m1 = h->ms[h->count - 1];
    if (h->count >= 2 && h->n[1] > h->n[0]) {
        /* cost ~ a + b * lights through the last two points (never a falling line) */
        double b = fmax((h->ms[1] - h->ms[0]) / (h->n[1] - h->n[0]), 0.0);
        return m1 + b * (lights - n1);
    }
    return lights > n1 && n1 > 0 ? m1 * lights / n1 : m1;
}

static void history_add(history *h, int lights, double ms)
{
    if (h->count == 2)
        h->n[0] = h->n[1], h->ms[0] = h->ms[1], h->count = 1;
    h->n[h->count] = lights, h->ms[h->count] = ms;
    h->count++;
}

/* ---- one case ------------------------------------------------------------------------------ */

static bench_row *row_add(void)
{
    if (state.row_count == state.row_cap) {
        int cap = state.row_cap ? 2 * state.row_cap : 64;
        bench_row *rows = realloc(state.rows, (size_t)cap * sizeof *rows);
        if (!rows) {
            log_error("out of memory for %d result rows", cap);
            return NULL;
        }
        state.rows = rows, state.row_cap = cap;
    }
    bench_row *row = &state.rows[state.row_count++];
    memset(row, 0, sizeof *row);
    return row;
}

static int compare_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

typedef struct case_desc {
    const char *sweep;
    const char *scene_name;
    bool own_lights;
    int lights; /* the scene's light count */
    double cutoff;
    int renderers[MAX_LIST];
    int renderer_count;
    history *histories;          /* per renderer_defs entry, or NULL: no prediction (cut-off sweep) */
    const history *predict_from; /* for the cut-off sweep: the light sweep's histories, may be NULL */
} case_desc;

static bool run_case(gpu_scene *gs, const case_desc *c)
{
    const bench_options *o = &state.opt;
    int n = c->renderer_count;
    int frames[MAX_LIST], warmup[MAX_LIST];
    double predicted[MAX_LIST];
    double *times[MAX_LIST] = {0};
    bench_row *rows[MAX_LIST];
    if (!gpu_scene_update(gs, 0.0f, c->cutoff, o->width, o->height))
        return false;
    int first_row = state.row_count;
    for (int i = 0; i < n; i++) {
        bench_row *row = row_add();
        if (!row)
            return false;
        int r = c->renderers[i];
        row->sweep = c->sweep;
        snprintf(row->scene, sizeof row->scene, "%s", c->scene_name);
        row->renderer = r;
        row->own_lights = c->own_lights;
        row->lights = c->lights;
        row->active_lights = gs->light_count;
        row->cutoff = c->cutoff;
        const history *h = c->histories ? &c->histories[r] : c->predict_from ? &c->predict_from[r] : NULL;
        predicted[i] = h ? predict_ms(h, c->lights) : 0.0;
        frames[i] = o->frames, warmup[i] = o->warmup;
        if (predicted[i] > o->max_frame_ms) {
            frames[i] = warmup[i] = 0;
            row->status = STATUS_SKIPPED;
            row->median_ms = row->min_ms = row->max_ms = predicted[i];
            snprintf(row->note, sizeof row->note,
                     "skipped: predicted %.0f ms/frame > %.0f; time extrapolated", predicted[i],
                     o->max_frame_ms);
        } else if (predicted[i] * (o->frames + o->warmup) > o->case_budget_ms) {
            int f = (int)(o->case_budget_ms / fmax(predicted[i], 1.0));
            frames[i] = f < o->min_frames ? o->min_frames : f > o->frames ? o->frames : f;
            warmup[i] = 1;
            row->status = frames[i] < o->frames ? STATUS_FEW_FRAMES : STATUS_MEASURED;
            if (row->status == STATUS_FEW_FRAMES)
                snprintf(row->note, sizeof row->note, "slow: %d frames instead of %d", frames[i], o->frames);
        }
        row->frames = frames[i], row->warmup = warmup[i];
        if (frames[i] > 0 && !(times[i] = malloc((size_t)frames[i] * sizeof(double)))) {
            log_error("out of memory for frame times");
            return false;
        }
    }
    for (int i = 0; i < n; i++)
        rows[i] = &state.rows[first_row + i];

    /* Warm-up, then the timed frames, renderer after renderer within each round. */
    int rounds = 0;
    for (int i = 0; i < n; i++)
        rounds = frames[i] + warmup[i] > rounds ? frames[i] + warmup[i] : rounds;
    bool ok = true;
    for (int k = 0; k < rounds && ok; k++) {
        for (int i = 0; i < n && ok; i++) {
            /* Warm-up frames are spread over the first rounds; then timed frames follow. */
            if (k >= frames[i] + warmup[i])
                continue;
            double t0 = now_ms();
            ok = gpu_scene_update(gs, 0.0f, c->cutoff, o->width, o->height) &&
                 render_frame(c->renderers[i], gs, false, false, NULL);
            glFinish();
            double ms = now_ms() - t0;
            if (k >= warmup[i])
                times[i][k - warmup[i]] = ms;
        }
    }
    for (int i = 0; i < n && ok; i++) {
        bench_row *row = rows[i];
        if (frames[i] > 0) {
            qsort(times[i], (size_t)frames[i], sizeof(double), compare_double);
            int f = frames[i];
            row->median_ms = f % 2 ? times[i][f / 2] : 0.5 * (times[i][f / 2 - 1] + times[i][f / 2]);
            row->min_ms = times[i][0];
            row->max_ms = times[i][f - 1];
        }
        if (c->histories)
            history_add(&c->histories[row->renderer], c->lights, row->median_ms);
    }
    for (int i = 0; i < n; i++)
        free(times[i]);
    if (!ok)
        return false;

    /* Work and error: one untimed frame per measured renderer. */
    char key[NAME_MAX_LEN + 32];
    snprintf(key, sizeof key, "%s/%d/%d", c->scene_name, c->own_lights, c->lights);
    /* The cut-off sweep is about error: it always measures it. */
    bool want_error = c->lights <= o->error_max_lights || strcmp(c->sweep, "cutoff") == 0;
    if (want_error && !make_reference(gs, key, c->cutoff))
        return false;
    /* Depth of the visible surface, from the cheapest exact-depth renderer. */
    ok = render_frame(1, gs, false, false, NULL) && read_depth(&state.target);
    if (!ok)
        return false;
    bench_work_positions(state.depth, o->width, o->height, (const float *)gs->view.view_proj,
                         state.positions);
    long long covered = 0;
    for (size_t p = 0; p < (size_t)o->width * (size_t)o->height; p++)
        covered += state.positions[4 * p + 3] != 0.0;
    long long ideal = bench_work_ideal_pairs(state.positions, o->width, o->height,
                                             (const float *)gs->view.view_proj, gs->lights, gs->light_count);
    for (int i = 0; i < n; i++) {
        bench_row *row = rows[i];
        row->covered = covered;
        row->ideal = ideal;
        if (row->status == STATUS_SKIPPED)
            continue;
        frame_result res;
        if (!render_frame(row->renderer, gs, true, false, &res))
            return false;
        row->have_work = res.shaded >= 0;
        row->shaded = res.shaded;
        row->light_evals = (double)res.shaded * res.lights_per_px;
        row->work_ratio = ideal > 0 ? row->light_evals / (double)ideal : 0.0;
        if (want_error) {
            image img;
            if (!fbo_read_rgba8(&state.target, 0, &img))
                return false;
            row->have_error8 = image_compare(&img, &state.ref8, NULL, 1, &row->error8, NULL);
            image_destroy(&img);
            if (!isfinite(row->error8.psnr) || row->error8.psnr > BENCH_PSNR_CAP)
                row->error8.psnr = BENCH_PSNR_CAP;
            if (read_linear(row->renderer, gs)) {
                bench_work_hdr_error(state.hdr, state.ref_hdr, o->width, o->height, &row->error_hdr);
                row->have_error_hdr = true;
            }
        }
    }
    state.case_index++;
    for (int i = 0; i < n; i++) {
        const bench_row *row = rows[i];
        fprintf(stderr, "bench: case %d/%d %-22s %-8s lights %5d%s cut-off %6.3f/256: %9.2f ms%s\n",
                state.case_index, state.case_total, renderer_defs[row->renderer].name, row->scene,
                row->lights, row->own_lights ? " (scene's)" : "", row->cutoff * 256.0, row->median_ms,
                row->status == STATUS_SKIPPED      ? " (skipped, extrapolated)"
                : row->status == STATUS_FEW_FRAMES ? " (few frames)"
                                                   : "");
    }
    return gl_check("run_case");
}

/* ---- scenes ------------------------------------------------------------------------------ */

static void scene_path(const char *name, char *out, size_t size)
{
    size_t len = strlen(name);
    if (strchr(name, '/') || (len > 6 && strcmp(name + len - 6, ".scene") == 0))
        snprintf(out, size, "%s", name);
    else
        snprintf(out, size, "%s/%s.scene", state.opt.scene_dir, name);
}

static void scene_label(const char *name, char *out, size_t size)
{
    const char *slash = strrchr(name, '/');
    snprintf(out, size, "%s", slash ? slash + 1 : name);
    char *dot = strrchr(out, '.');
    if (dot && strcmp(dot, ".scene") == 0)
        *dot = '\0';
}

/* Both sweeps of one scene. `own` keeps the file's lights; `gen` gets light_generate's. The GPU
 * scene is built from `gen`; the two share every mesh and object, so pointing it at `own` for
 * the scene's own lights is safe. */
static bool run_scene(const char *name, bool light_sweep, bool cutoff_sweep, history *histories)
{
    const bench_options *o = &state.opt;
    char path[SCENE_PATH_MAX], label[NAME_MAX_LEN];
    scene_path(name, path, sizeof path);
    scene_label(name, label, sizeof label);
    scene own, gen;
    if (!scene_load(path, &own))
        return false;
    if (!scene_load(path, &gen)) {
        scene_destroy(&own);
        return false;
    }
    gpu_scene gs;
    bool ok = gpu_scene_create(&gen, &gs);
    for (int r = 0; r < RENDERER_COUNT; r++)
        histories[r].count = 0;
    for (int k = 0; ok && light_sweep && k < o->light_list_count; k++) {
        bool use_own = o->lights[k] == LIGHTS_OWN;
        case_desc c = {.sweep = "lights",
                       .scene_name = label,
                       .own_lights = use_own,
                       .cutoff = LIGHT_DEFAULT_CUTOFF,
                       .renderer_count = o->renderer_count,
                       .histories = use_own ? NULL : histories,
                       .predict_from = histories};
        memcpy(c.renderers, o->renderers, sizeof c.renderers);
        if (use_own) {
            gs.src = &own;
            c.lights = own.light_count;
        } else {
            gs.src = &gen;
            ok = light_generate(&gen, o->lights[k], o->seed);
            c.lights = o->lights[k];
        }
        ok = ok && run_case(&gs, &c);
        gs.src = &gen;
    }
    for (int k = 0; ok && cutoff_sweep && k < o->cutoff_count; k++) {
        case_desc c = {.sweep = "cutoff",
                       .scene_name = label,
                       .lights = o->cutoff_lights,
                       .cutoff = o->cutoffs[k] / 256.0,
                       .predict_from = light_sweep ? histories : NULL};
        for (int i = 0; i < o->renderer_count; i++)
            if (renderer_defs[o->renderers[i]].in_cutoff_sweep)
                c.renderers[c.renderer_count++] = o->renderers[i];
        ok = light_generate(&gen, o->cutoff_lights, o->seed) && run_case(&gs, &c);
    }
    gpu_scene_destroy(&gs);
    scene_destroy(&gen);
    scene_destroy(&own);
    state.have_ref = false;
    return ok;
}

/* ---- output files ------------------------------------------------------------------------------ */

/* Every output goes to NAME.tmp first and is renamed into place: a reader never sees half a file. */
static FILE *open_tmp(const char *name, char *tmp, size_t size)
{
    snprintf(tmp, size, "%s/%s.tmp", state.opt.out_dir, name);
    FILE *f = fopen(tmp, "w");
    if (!f)
        log_error("cannot write %s: %s", tmp, strerror(errno));
    return f;
}

static bool close_and_rename(FILE *f, const char *tmp, const char *name)
{
    char final[1024];
    snprintf(final, sizeof final, "%s/%s", state.opt.out_dir, name);
    bool ok = !ferror(f);
    ok = fclose(f) == 0 && ok;
    if (ok && rename(tmp, final) != 0) {
        log_error("cannot rename %s to %s: %s", tmp, final, strerror(errno));
        ok = false;
    }
    if (!ok)
        remove(tmp);
    return ok;
}

/* "NA" where a value was not measured: gnuplot and spreadsheets read it as missing. */
static void put_num(FILE *f, bool have, const char *fmt, double v)
{
    fputc(',', f);
    if (have && isfinite(v))
        fprintf(f, fmt, v);
    else
        fputs("NA", f);
}

static const char *const csv_columns =
    "sweep,scene,renderer,light_set,lights,active_lights,cutoff_256,width,height,frames,warmup,median_ms,"
    "min_ms,max_ms,fps,status,shaded_pixels,covered_pixels,ideal_pairs,light_evals,work_ratio,"
    "gbuffer_bytes,gbuffer_naive_bytes,max_abs_8bit,mean_abs_8bit,psnr_8bit,max_abs_hdr,mean_abs_hdr,"
    "psnr_hdr,note";

static bool write_csv(void)
{
    char tmp[1024];
    FILE *f = open_tmp("bench.csv", tmp, sizeof tmp);
    if (!f)
        return false;
    fprintf(f, "%s\n", csv_columns);
    for (int i = 0; i < state.row_count; i++) {
        const bench_row *r = &state.rows[i];
        bool measured = r->status != STATUS_SKIPPED;
        fprintf(f, "%s,%s,%s,%s,%d,%d,%.4g,%d,%d,%d,%d", r->sweep, r->scene, renderer_defs[r->renderer].name,
                r->own_lights ? "scene" : "generated", r->lights, r->active_lights, r->cutoff * 256.0,
                state.opt.width, state.opt.height, r->frames, r->warmup);
        put_num(f, true, "%.3f", r->median_ms);
        put_num(f, measured, "%.3f", r->min_ms);
        put_num(f, measured, "%.3f", r->max_ms);
        put_num(f, r->median_ms > 0, "%.2f", 1000.0 / r->median_ms);
        fprintf(f, ",%s", status_names[r->status]);
        put_num(f, r->have_work, "%.0f", (double)r->shaded);
        put_num(f, true, "%.0f", (double)r->covered);
        put_num(f, true, "%.0f", (double)r->ideal);
        put_num(f, r->have_work, "%.0f", r->light_evals);
        put_num(f, r->have_work && r->ideal > 0, "%.4f", r->work_ratio);
        bool deferred = renderer_defs[r->renderer].kind != KIND_FORWARD;
        put_num(f, deferred, "%.0f", gbuffer_bytes_per_pixel());
        put_num(f, deferred, "%.0f", GBUFFER_NAIVE_BYTES);
        put_num(f, r->have_error8, "%.0f", r->error8.max_abs);
        put_num(f, r->have_error8, "%.5f", r->error8.mean_abs);
        put_num(f, r->have_error8, "%.2f", r->error8.psnr);
        put_num(f, r->have_error_hdr, "%.6g", r->error_hdr.max_abs);
        put_num(f, r->have_error_hdr, "%.6g", r->error_hdr.mean_abs);
        put_num(f, r->have_error_hdr, "%.2f", r->error_hdr.psnr);
        fprintf(f, ",%s\n", r->note); /* notes never hold commas */
    }
    return close_and_rename(f, tmp, "bench.csv");
}

static const bench_row *find_row(const char *sweep, const char *scene_name, int renderer, bool own,
                                 int lights, double cutoff)
{
    for (int i = 0; i < state.row_count; i++) {
        const bench_row *r = &state.rows[i];
        if (strcmp(r->sweep, sweep) == 0 && strcmp(r->scene, scene_name) == 0 && r->renderer == renderer &&
            r->own_lights == own && (own || r->lights == lights) && (cutoff < 0 || r->cutoff == cutoff))
            return r;
    }
    return NULL;
}

/* The fastest forward and deferred rows of one light-sweep case. */
static void best_of_case(const char *scene_name, bool own, int lights, const bench_row **fwd,
                         const bench_row **def)
{
    *fwd = *def = NULL;
    for (int i = 0; i < state.opt.renderer_count; i++) {
        int r = state.opt.renderers[i];
        const bench_row *row = find_row("lights", scene_name, r, own, lights, -1);
        if (!row)
            continue;
        const bench_row **best = renderer_defs[r].kind == KIND_FORWARD ? fwd : def;
        if (!*best || row->median_ms < (*best)->median_ms)
            *best = row;
    }
}

static void time_cell(FILE *f, const bench_row *r)
{
    if (!r)
        fprintf(f, " – |");
    else
        fprintf(f, " %.1f%s |", r->median_ms,
                r->status == STATUS_SKIPPED      ? "*"
                : r->status == STATUS_FEW_FRAMES ? "†"
                                                 : "");
}

static int volumes_renderer_selected(void)
{
    for (int i = 0; i < state.opt.renderer_count; i++)
        if (renderer_defs[state.opt.renderers[i]].kind == KIND_DEFERRED_VOLUMES)
            return state.opt.renderers[i];
    return -1;
}

static void write_targets(FILE *f)
{
    const bench_options *o = &state.opt;
    int vol = volumes_renderer_selected();
    fprintf(f, "## Targets\n\n| target | measured | result |\n|---|---|---|\n");
    /* 1. light volumes >= 20x the best forward at 1024 lights (800x800) */
    for (int s = 0; s < o->scene_count; s++) {
        char label[NAME_MAX_LEN];
        scene_label(o->scenes[s], label, sizeof label);
        const bench_row *fwd, *def;
        best_of_case(label, false, 1024, &fwd, &def);
        const bench_row *v = vol >= 0 ? find_row("lights", label, vol, false, 1024, -1) : NULL;
        if (!fwd || !v)
            continue;
        double speedup = fwd->median_ms / v->median_ms;
        fprintf(f,
                "| %s, 1024 lights: light volumes ≥ 20× the best forward (%s) | %.1f× (%.1f vs %.1f ms%s) | "
                "%s |\n",
                label, renderer_defs[fwd->renderer].name, speedup, v->median_ms, fwd->median_ms,
                fwd->status == STATUS_SKIPPED ? ", forward extrapolated" : "",
                speedup >= 20 ? "met" : "missed");
    }
    /* 2. work ratio <= 1.5 on default and city */
    const char *work_scenes[] = {"default", "city"};
    for (int s = 0; s < 2 && vol >= 0; s++) {
        for (int i = 0; i < state.row_count; i++) {
            const bench_row *r = &state.rows[i];
            if (strcmp(r->sweep, "lights") || strcmp(r->scene, work_scenes[s]) || r->renderer != vol ||
                !r->have_work)
                continue;
            bool at_target =
                (r->own_lights && strcmp(r->scene, "city") == 0) || (!r->own_lights && r->lights == 1024);
            if (!at_target)
                continue;
            fprintf(f,
                    "| %s, %d lights%s: light volumes shade ≤ 1.5× the ideal pairs | %.2f× (%lld of %lld) | "
                    "%s |\n",
                    r->scene, r->lights, r->own_lights ? " (scene's)" : "", r->work_ratio, r->shaded,
                    r->ideal, r->work_ratio <= 1.5 ? "met" : "missed");
        }
    }
    /* 3. city at its own 757 lights >= 10 fps */
    const bench_row *city = vol >= 0 ? find_row("lights", "city", vol, true, 0, -1) : NULL;
    if (city)
        fprintf(f, "| city, its %d lights, %dx%d: light volumes ≥ 10 fps | %.1f fps (%.1f ms) | %s |\n",
                city->lights, o->width, o->height, 1000.0 / city->median_ms, city->median_ms,
                1000.0 / city->median_ms >= 10 ? "met" : "missed");
    fprintf(f, "\n");
}

static void write_crossover(FILE *f)
{
    const bench_options *o = &state.opt;
    fprintf(
        f, "## Crossover\n\nSmallest generated light count at which the fastest deferred renderer beats the "
           "fastest forward one, and the speed-up (best forward ms / best deferred ms) at 1024 lights and "
           "at the scene's own lights.\n\n"
           "| scene | crossover (lights) | speed-up at 1024 | speed-up at own lights |\n|---|---|---|---|\n");
    for (int s = 0; s < o->scene_count; s++) {
        char label[NAME_MAX_LEN];
        scene_label(o->scenes[s], label, sizeof label);
        int crossover = -1;
        for (int k = 0; k < o->light_list_count && crossover < 0; k++) {
            const bench_row *fwd, *def;
            if (o->lights[k] == LIGHTS_OWN)
                continue;
            best_of_case(label, false, o->lights[k], &fwd, &def);
            if (fwd && def && def->median_ms < fwd->median_ms)
                crossover = o->lights[k];
        }
        fprintf(f, "| %s | %s", label, crossover >= 0 ? "" : "none in the sweep");
        if (crossover >= 0)
            fprintf(f, "%d", crossover);
        fprintf(f, " |");
        const bench_row *fwd, *def;
        best_of_case(label, false, 1024, &fwd, &def);
        if (fwd && def)
            fprintf(f, " %.1f× |", fwd->median_ms / def->median_ms);
        else
            fprintf(f, " – |");
        best_of_case(label, true, 0, &fwd, &def);
        if (fwd && def)
            fprintf(f, " %.1f× (%d lights) |\n", fwd->median_ms / def->median_ms, fwd->lights);
        else
            fprintf(f, " – |\n");
    }
    fprintf(f, "\n");
}

static bool write_md(void)
{
    const bench_options *o = &state.opt;
    char tmp[1024];
    FILE *f = open_tmp("bench.md", tmp, sizeof tmp);
    if (!f)
        return false;
    fprintf(f, "# Forward against deferred: benchmark results\n\n");
    fprintf(f, "- machine: %s, %d logical cores\n- GL: %s, %s\n", state.cpu, state.cores, state.gl_renderer,
            state.gl_version);
    fprintf(f,
            "- frame %dx%d; per case %d warm-up + %d timed frames per renderer, renderers interleaved "
            "frame by frame; median ms with glFinish + CLOCK_MONOTONIC%s\n",
            o->width, o->height, o->warmup, o->frames, o->quick ? " (--quick)" : "");
    fprintf(
        f,
        "- `*` time extrapolated (case skipped: predicted > %.0f ms/frame); `†` fewer frames (at least %d: "
        "case predicted over %.0f ms)\n",
        o->max_frame_ms, o->min_frames, o->case_budget_ms);
    fprintf(f,
            "- error reference: forward renderer, fp32, cut-off 0 (every light reaches every pixel), the "
            "same shading model; errors only up to %d lights\n",
            o->error_max_lights);
    fprintf(f,
            "- G-buffer: %d bytes per pixel (naive layout with world position: %d); the G-buffer has one "
            "layout, so there is no precision option to sweep\n\n",
            gbuffer_bytes_per_pixel(), GBUFFER_NAIVE_BYTES);
    write_targets(f);
    write_crossover(f);

    fprintf(f, "## Median ms per frame\n\n");
    for (int s = 0; s < o->scene_count; s++) {
        char label[NAME_MAX_LEN];
        scene_label(o->scenes[s], label, sizeof label);
        fprintf(f, "### %s\n\n| lights |", label);
        for (int i = 0; i < o->renderer_count; i++)
            fprintf(f, " %s |", renderer_defs[o->renderers[i]].name);
        fprintf(f, "\n|---|");
        for (int i = 0; i < o->renderer_count; i++)
            fprintf(f, "---|");
        fprintf(f, "\n");
        for (int k = 0; k < o->light_list_count; k++) {
            bool own = o->lights[k] == LIGHTS_OWN;
            const bench_row *any = find_row("lights", label, o->renderers[0], own, o->lights[k], -1);
            if (!any)
                continue;
            fprintf(f, "| %d%s |", any->lights, own ? " (scene's)" : "");
            for (int i = 0; i < o->renderer_count; i++)
                time_cell(f, find_row("lights", label, o->renderers[i], own, o->lights[k], -1));
            fprintf(f, "\n");
        }
        fprintf(f, "\n");
    }

    fprintf(f,
            "## Lighting work\n\nshaded = GL_SAMPLES_PASSED of the lighting pass; evaluations = shaded × "
            "lights looped per fragment (forward with lists: the mean list length, an estimate); ideal = "
            "(pixel, light) pairs whose visible surface lies inside the light's radius, counted on the CPU "
            "from the depth buffer.\n\n"
            "| scene | lights | renderer | shaded | evaluations | ideal | evaluations / ideal |\n"
            "|---|---|---|---|---|---|---|\n");
    for (int i = 0; i < state.row_count; i++) {
        const bench_row *r = &state.rows[i];
        if (strcmp(r->sweep, "lights") || !r->have_work)
            continue;
        fprintf(f, "| %s | %d%s | %s | %lld | %.4g | %lld |", r->scene, r->lights,
                r->own_lights ? " (scene's)" : "", renderer_defs[r->renderer].name, r->shaded, r->light_evals,
                r->ideal);
        /* no ideal work (no light reaches a visible surface): no ratio */
        if (r->ideal > 0)
            fprintf(f, " %.2f |\n", r->work_ratio);
        else
            fprintf(f, " – |\n");
    }

    fprintf(
        f,
        "\n## Error against the exact reference (cut-off 5/256)\n\n8-bit: display-encoded output, 0..255 "
        "per channel. HDR: linear radiance, PSNR with peak 1.0 (NA: the renderer has no linear output).\n\n"
        "| scene | lights | renderer | max 8-bit | mean 8-bit | PSNR 8-bit dB | max HDR | mean HDR | PSNR "
        "HDR dB |\n"
        "|---|---|---|---|---|---|---|---|---|\n");
    for (int i = 0; i < state.row_count; i++) {
        const bench_row *r = &state.rows[i];
        if (strcmp(r->sweep, "lights") || !r->have_error8)
            continue;
        fprintf(f, "| %s | %d%s | %s | %d | %.4f | %.1f |", r->scene, r->lights,
                r->own_lights ? " (scene's)" : "", renderer_defs[r->renderer].name, r->error8.max_abs,
                r->error8.mean_abs, r->error8.psnr);
        if (r->have_error_hdr)
            fprintf(f, " %.4g | %.3g | %.1f |\n", r->error_hdr.max_abs, r->error_hdr.mean_abs,
                    r->error_hdr.psnr);
        else
            fprintf(f, " NA | NA | NA |\n");
    }

    fprintf(f,
            "\n## Speed against error: the cut-off (%s, %d lights)\n\n"
            "| cut-off (/256) | renderer | active lights | ms | evaluations / ideal | mean 8-bit | PSNR "
            "8-bit dB | "
            "mean HDR | PSNR HDR dB |\n|---|---|---|---|---|---|---|---|---|\n",
            o->cutoff_scene, o->cutoff_lights);
    for (int i = 0; i < state.row_count; i++) {
        const bench_row *r = &state.rows[i];
        if (strcmp(r->sweep, "cutoff"))
            continue;
        fprintf(f, "| %.3g | %s | %d | ", r->cutoff * 256.0, renderer_defs[r->renderer].name,
                r->active_lights);
        time_cell(f, r);
        if (r->have_work && r->ideal > 0)
            fprintf(f, " %.2f |", r->work_ratio);
        else
            fprintf(f, " – |");
        if (r->have_error8)
            fprintf(f, " %.4f | %.1f |", r->error8.mean_abs, r->error8.psnr);
        else
            fprintf(f, " NA | NA |");
        if (r->have_error_hdr)
            fprintf(f, " %.3g | %.1f |\n", r->error_hdr.mean_abs, r->error_hdr.psnr);
        else
            fprintf(f, " NA | NA |\n");
    }
    return close_and_rename(f, tmp, "bench.md");
}

/* ---- plots ------------------------------------------------------------------------------ */

/* A self-contained gnuplot script (the data inline) is written next to the plots, so a reader can
 * restyle them with `gnuplot DIR/bench_plots.gp` without running the benchmark again. */
static bool write_plot_script(const char *term)
{
    const bench_options *o = &state.opt;
    char tmp[1024];
    FILE *f = open_tmp("bench_plots.gp", tmp, sizeof tmp);
    if (!f)
        return false;
    fprintf(f, "# Generated by bench: plots of bench.csv. Run from the output folder's parent.\n");
    fprintf(f, "set terminal %s size 1500,900 font ',10'\nset datafile missing 'NA'\n", term);
    /* one block per (scene, renderer): lights, ms, measured (1) or extrapolated (0) */
    for (int s = 0; s < o->scene_count; s++) {
        char label[NAME_MAX_LEN];
        scene_label(o->scenes[s], label, sizeof label);
        for (int i = 0; i < o->renderer_count; i++) {
            fprintf(f, "$t_%d_%d << EOD\n", s, i);
            for (int k = 0; k < o->light_list_count; k++) {
                if (o->lights[k] == LIGHTS_OWN)
                    continue;
                const bench_row *r = find_row("lights", label, o->renderers[i], false, o->lights[k], -1);
                if (r && r->median_ms > 0)
                    fprintf(f, "%d %.4f %d\n", r->lights, r->median_ms, r->status != STATUS_SKIPPED);
            }
            fprintf(f, "EOD\n");
        }
    }
    fprintf(f, "set output '%s/time_vs_lights.png.tmp'\n", o->out_dir);
    int cols = o->scene_count <= 1 ? 1 : o->scene_count <= 4 ? 2 : 3;
    int rows_n = (o->scene_count + cols - 1) / cols;
    fprintf(f,
            "set multiplot layout %d,%d title 'Median ms per frame against light count, %dx%d, %s (log-log; "
            "open marks: extrapolated)'\n",
            rows_n, cols, o->width, o->height, state.gl_renderer);
    fprintf(f,
            "set logscale xy\nset grid\nset key top left\nset xlabel 'lights'\nset ylabel 'ms per frame'\n");
    for (int s = 0; s < o->scene_count; s++) {
        char label[NAME_MAX_LEN];
        scene_label(o->scenes[s], label, sizeof label);
        fprintf(f, "set title '%s'\nplot ", label);
        for (int i = 0; i < o->renderer_count; i++) {
            fprintf(f,
                    "%s$t_%d_%d using 1:2 with lines lc %d title '%s', "
                    "$t_%d_%d using 1:(($3)>0?$2:NaN) with points lc %d pt 7 notitle, "
                    "$t_%d_%d using 1:(($3)>0?NaN:$2) with points lc %d pt 6 notitle",
                    i ? ", \\\n     " : "", s, i, i + 1, renderer_defs[o->renderers[i]].name, s, i, i + 1, s,
                    i, i + 1);
        }
        fprintf(f, "\n");
    }
    fprintf(f, "unset multiplot\n");

    /* speed against error: x = mean 8-bit error (and HDR), y = ms, one line per renderer */
    for (int i = 0; i < o->renderer_count; i++) {
        fprintf(f, "$e_%d << EOD\n", i);
        for (int k = 0; k < state.row_count; k++) {
            const bench_row *r = &state.rows[k];
            if (strcmp(r->sweep, "cutoff") || r->renderer != o->renderers[i] || !r->have_error8)
                continue;
            fprintf(f, "%.6g %.4f %.6g %.4g\n", fmax(r->error8.mean_abs, 1e-4), r->median_ms,
                    r->have_error_hdr ? fmax(r->error_hdr.mean_abs, 1e-7) : NAN, r->cutoff * 256.0);
        }
        fprintf(f, "EOD\n");
    }
    fprintf(f, "set output '%s/speed_vs_error.png.tmp'\nunset logscale\n", o->out_dir);
    fprintf(f,
            "set multiplot layout 1,2 title 'Speed against error over the cut-off, %s, %d lights, %dx%d "
            "(labels: cut-off in 1/256)'\n",
            o->cutoff_scene, o->cutoff_lights, o->width, o->height);
    fprintf(f, "set logscale xy\nset grid\nset key top right\nset ylabel 'ms per frame'\n");
    for (int pass = 0; pass < 2; pass++) {
        fprintf(f, "set title '%s'\nset xlabel '%s'\nplot ",
                pass ? "linear HDR error (renderers with a linear output)" : "8-bit display error",
                pass ? "mean |error| of linear radiance" : "mean |error| in 8-bit levels");
        int x = pass ? 3 : 1;
        bool first = true;
        for (int i = 0; i < o->renderer_count; i++) {
            if (!renderer_defs[o->renderers[i]].in_cutoff_sweep)
                continue;
            fprintf(
                f,
                "%s$e_%d using %d:2 with linespoints lc %d pt 7 title '%s', "
                "$e_%d using %d:2:(sprintf('%%g', $4)) with labels offset 0.8,0.6 textcolor lt %d notitle",
                first ? "" : ", \\\n     ", i, x, i + 1, renderer_defs[o->renderers[i]].name, i, x, i + 1);
            first = false;
        }
        fprintf(f, "\n");
    }
    fprintf(f, "unset multiplot\n");
    return close_and_rename(f, tmp, "bench_plots.gp");
}

static bool make_plots(void)
{
    /* pngcairo draws smoother lines; plain png (libgd) is the fallback. */
    FILE *probe = popen("gnuplot -e \"set terminal pngcairo\" 2>&1", "r");
    if (!probe) {
        log_warn("gnuplot not found: no plots");
        return true;
    }
    char buf[256];
    bool cairo = true, any = false;
    while (fgets(buf, sizeof buf, probe))
        any = true, cairo = cairo && !strstr(buf, "unknown") && !strstr(buf, "not found");
    int probe_rc = pclose(probe);
    if (probe_rc != 0 && !any) {
        log_warn("gnuplot not usable (exit %d): no plots", probe_rc);
        return true;
    }
    if (!write_plot_script(cairo ? "pngcairo" : "png"))
        return false;
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "gnuplot '%s/bench_plots.gp'", state.opt.out_dir);
    bool plotted = system(cmd) == 0;
    if (!plotted)
        log_error("gnuplot failed on %s/bench_plots.gp", state.opt.out_dir);
    const char *plots[] = {"time_vs_lights.png", "speed_vs_error.png"};
    for (int i = 0; i < 2; i++) {
        char tmp[1024], final[1024];
        snprintf(tmp, sizeof tmp, "%s/%s.tmp", state.opt.out_dir, plots[i]);
        snprintf(final, sizeof final, "%s/%s", state.opt.out_dir, plots[i]);
        if (!plotted) {
            remove(tmp);
            continue;
        }
        if (rename(tmp, final) != 0) {
            log_error("cannot rename %s to %s: %s", tmp, final, strerror(errno));
            return false;
        }
    }
    return plotted;
}

/* ---- main ------------------------------------------------------------------------------ */

static int count_cases(void)
{
    const bench_options *o = &state.opt;
    return o->scene_count * o->light_list_count + o->cutoff_count;
}

static bool run_all(void)
{
    const bench_options *o = &state.opt;
    history histories[RENDERER_COUNT];
    memset(histories, 0, sizeof histories);
    char want[NAME_MAX_LEN];
    scene_label(o->cutoff_scene, want, sizeof want);
    bool cutoff_done = false;
    for (int s = 0; s < o->scene_count; s++) {
        char label[NAME_MAX_LEN];
        scene_label(o->scenes[s], label, sizeof label);
        bool cutoff_here = !cutoff_done && strcmp(label, want) == 0;
        if (!run_scene(o->scenes[s], true, cutoff_here, histories))
            return false;
        cutoff_done = cutoff_done || cutoff_here;
    }
    if (!cutoff_done && !run_scene(o->cutoff_scene, false, true, histories))
        return false;
    return true;
}

int main(int argc, char **argv)
{
    int rc = parse_options(argc, argv, &state.opt);
    if (rc == CLI_EXIT_DONE)
        return 0;
    if (rc != CLI_EXIT_OK)
        return rc;
    const bench_options *o = &state.opt;
    if (mkdir(o->out_dir, 0755) != 0 && errno != EEXIST) {
        log_error("cannot create %s: %s", o->out_dir, strerror(errno));
        return CLI_EXIT_RUNTIME;
    }
    const platform_desc pd = {
        .backend = o->backend, .width = o->width, .height = o->height, .title = "bench"};
    rc = platform_create(&pd);
    if (rc != CLI_EXIT_OK)
        return rc;
    read_cpu_info();
    snprintf(state.gl_renderer, sizeof state.gl_renderer, "%s", (const char *)glGetString(GL_RENDERER));
    snprintf(state.gl_version, sizeof state.gl_version, "%s", (const char *)glGetString(GL_VERSION));
    printf("bench: cpu=\"%s\" cores=%d gl_renderer=\"%s\" gl_version=\"%s\" size=%dx%d frames=%d warmup=%d\n",
           state.cpu, state.cores, state.gl_renderer, state.gl_version, o->width, o->height, o->frames,
           o->warmup);
    fflush(stdout);

    state.case_total = count_cases();
    double t0 = now_ms();
    bool ok = gl_resources_create() && run_all();
    rc = ok ? CLI_EXIT_OK : CLI_EXIT_RUNTIME;
    if (ok)
        fprintf(stderr, "bench: %d cases in %.1f s\n", state.case_index, (now_ms() - t0) / 1000.0);
    if (ok && !(write_csv() && write_md() && (!o->plots || make_plots())))
        rc = CLI_EXIT_RUNTIME;
    if (rc == CLI_EXIT_OK)
        printf("bench: wrote %s/bench.csv %s/bench.md%s\n", o->out_dir, o->out_dir,
               o->plots ? " and the plots" : "");
    gl_resources_destroy();
    gl_util_shutdown();
    platform_destroy();
    free(state.rows);
    return rc;
}
