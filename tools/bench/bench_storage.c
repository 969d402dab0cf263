/* bench_storage.c - see bench_storage.h. The report is bench_storage_report.c. */
#include "bench_storage.h"
#include "bench_storage_rows.h"

#include "app_embed.h"
#include "chapters.h"
#include "draw_count.h"
#include "frame_stats.h"
#include "frame_timer.h"
#include "gbuffer.h"
#include "gl_util.h"
#include "light.h"
#include "log.h"
#include "scene.h"
#include "shader_layout.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef enum storage_mode { STORAGE_ON, STORAGE_OFF, STORAGE_ONLY } storage_mode;
static storage_mode mode = STORAGE_OFF;
static bool quick_scenes;

bench_storage_results bench_storage_results_now;
#define R bench_storage_results_now

#define ARGS(...) {__VA_ARGS__, NULL}

/* The rows: a chapter and its arguments at 1 sample, and at 4 where the course has a variant
 * (chapter 13 draws forward, Forward+ and the G-buffer multisampled, chapter 16 its ids; the light
 * pre-pass has none). `first` is the pass that stores what the row stores per pixel. */
const storage_renderer bench_storage_renderers[STORAGE_RENDERERS] = {
    {"forward", "depth pre-pass",
     {{&chapter_00, ARGS("--renderer", "forward")}, {&chapter_13, ARGS("--renderer", "forward", "--samples", "4")}}},
    {"forward-plus", "depth pre-pass",
     {{&chapter_00, ARGS("--renderer", "forward-plus")},
      {&chapter_13, ARGS("--renderer", "forward-plus", "--samples", "4")}}},
    {"gbuffer-compact", "geometry",
     {{&chapter_11, ARGS("--renderer", "deferred", "--gbuffer", "compact")},
      {&chapter_13, ARGS("--renderer", "deferred", "--gbuffer", "compact", "--samples", "4")}}},
    {"gbuffer-reference", "geometry",
     {{&chapter_11, ARGS("--renderer", "deferred", "--gbuffer", "reference")},
      {&chapter_13, ARGS("--renderer", "deferred", "--gbuffer", "reference", "--samples", "4")}}},
    {"light-prepass-rgb", "thin pass", {{&chapter_15, ARGS("--renderer", "deferred", "--specular", "rgb")}, {0}}},
    {"light-prepass-mono", "thin pass", {{&chapter_15, ARGS("--renderer", "deferred", "--specular", "mono")}, {0}}},
    {"visibility-buffer", "visibility pass",
     {{&chapter_16, ARGS("--renderer", "deferred")}, {&chapter_16, ARGS("--renderer", "deferred", "--samples", "4")}}},
};

/* What the visibility pass's time is made of: chapter 16's pass cut down (--vis-pass), timed beside
 * the rows gbuffer-compact and visibility-buffer. no-primitive-id writes triangle 0 instead of
 * gl_PrimitiveID, depth-only no id at all: wrong pictures by design, so no bytes and no error. */
const storage_renderer bench_storage_timings[STORAGE_TIMINGS] = {
    {"vis-no-primitive-id", "visibility pass",
     {{&chapter_16, ARGS("--renderer", "deferred", "--vis-pass", "no-primitive-id")},
      {&chapter_16, ARGS("--renderer", "deferred", "--vis-pass", "no-primitive-id", "--samples", "4")}}},
    {"vis-depth-only", "visibility pass",
     {{&chapter_16, ARGS("--renderer", "deferred", "--vis-pass", "depth-only")},
      {&chapter_16, ARGS("--renderer", "deferred", "--vis-pass", "depth-only", "--samples", "4")}}},
};

const char *const bench_storage_scene_names[STORAGE_SCENES] = {"default", "city", "bunnies", "teapots"};
const int bench_storage_samples[STORAGE_SAMPLE_COUNTS] = {1, 4};

/* What visibility_shade.frag fetches from buffers per triangle it shades, besides the ids: the
 * object's SHADER_OBJECT_TEXELS RGBA32F texels (matrices, material), and per corner the object's
 * mesh offsets (RG32I), one index (R32UI) and the vertex's SHADER_MESH_VERTEX_FLOATS floats (R32F).
 * Its "shading" pass shades one triangle per fragment that passes (it discards the background), its
 * "shading edges" pass (MSAA) at most one per sample. */
const int bench_storage_vis_scene_bytes =
    SHADER_OBJECT_TEXELS * 16 + 3 * (8 + 4 + SHADER_MESH_VERTEX_FLOATS * 4);

/* ---- options ----------------------------------------------------------------------------------- */

void bench_storage_reset(bool on, bool quick)
{
    mode = on ? STORAGE_ON : STORAGE_OFF;
    quick_scenes = quick;
}

int bench_storage_parse_option(const char *arg, const char *value)
{
    if (strcmp(arg, "--storage") != 0)
        return 0;
    static const char *const names[] = {"on", "off", "only"};
    for (int k = 0; value && k < 3; k++)
        if (strcmp(value, names[k]) == 0) {
            mode = (storage_mode)k;
            return 1;
        }
    fprintf(stderr, "bench: bad --storage (on, off or only): '%s' (see --help)\n", value ? value : "(missing)");
    return -1;
}

bool bench_storage_enabled(void) { return mode != STORAGE_OFF; }

bool bench_storage_only(void) { return mode == STORAGE_ONLY; }

int bench_storage_scene_count(void) { return quick_scenes ? 1 : STORAGE_SCENES; }

void bench_storage_print_help(FILE *f)
{
    fprintf(f, "  --storage MODE         on: after the sweeps, what to store per pixel: forward, Forward+, the compact\n"
               "                        and reference G-buffer, the light pre-pass and the visibility buffer at 1\n"
               "                        and 4 samples on the default, city, bunnies and teapots scenes (--quick:\n"
               "                        the default scene): bytes written and read per pixel (counted), each\n"
               "                        pass's time, 8-bit error (DIR/bench_storage.csv, a section of bench.md;\n"
               "                        only: DIR/bench_storage.md, and bench.md is left alone),\n"
               "                        and chapter 16's visibility pass timed without gl_PrimitiveID and with\n"
               "                        depth only (--vis-pass, timing only);\n"
               "                        off; only: nothing else (--full: on; otherwise off). About 7 minutes at\n"
               "                        320x240 with 3 frames on 2 cores with llvmpipe: the bunnies' frames take\n"
               "                        seconds\n");
}

/* ---- one row ----------------------------------------------------------------------------------- */

static storage_pass *pass_named(storage_row *row, const char *name)
{
    for (int i = 0; i < row->pass_count; i++)
        if (strcmp(row->passes[i].name, name) == 0)
            return &row->passes[i];
    if (row->pass_count == STORAGE_MAX_PASSES)
        return NULL;
    storage_pass *p = &row->passes[row->pass_count++];
    snprintf(p->name, sizeof p->name, "%s", name);
    return p;
}

static double median_of(double *v, int n)
{
    int k = 0;
    for (int i = 0; i < n; i++)
        if (!isnan(v[i]))
            v[k++] = v[i];
    return k > 0 ? frame_stats_of(v, k).median : NAN;
}

/* Warm-up, then timed frames: the frame and each pass on frame_timer's clock. */
static bool time_row(app_embed *e, const bench_options *o, const gpu_scene *gs, storage_row *row)
{
    frame_timer t;
    const int frames = o->frames, warmup = o->warmup > 0 ? o->warmup : 1;
    double *ms = calloc((size_t)frames * (STORAGE_MAX_PASSES + 1), sizeof *ms);
    if (!ms || !frame_timer_create(&t)) {
        free(ms);
        log_error("out of memory for frame times");
        return false;
    }
    bool ok = true;
    for (int k = 0; ok && k < warmup + frames; k++) {
        frame_timer_begin(&t);
        ok = app_embed_frame(e, gs, false, NULL);
        frame_timer_end(&t);
        if (k < warmup)
            continue;
        double *slot = ms + (size_t)(k - warmup) * (STORAGE_MAX_PASSES + 1);
        for (int i = 0; i < STORAGE_MAX_PASSES; i++)
            slot[i] = NAN;
        slot[STORAGE_MAX_PASSES] = t.last.frame_ms;
        for (int i = 0; t.last.valid && i < t.last.count; i++) {
            storage_pass *p = pass_named(row, t.last.names[i]);
            if (p)
                slot[p - row->passes] = t.last.ms[i];
        }
    }
    double *column = malloc((size_t)frames * sizeof *column);
    for (int i = 0; ok && column && i <= STORAGE_MAX_PASSES; i++) {
        for (int k = 0; k < frames; k++)
            column[k] = ms[(size_t)k * (STORAGE_MAX_PASSES + 1) + (size_t)i];
        if (i < row->pass_count)
            row->passes[i].ms = median_of(column, frames);
        else if (i == STORAGE_MAX_PASSES)
            row->frame_ms = median_of(column, frames);
    }
    ok = ok && column;
    row->frames = frames;
    free(column);
    free(ms);
    frame_timer_destroy(&t);
    return ok;
}

/* One untimed frame with every draw counted, its passes named by a frame timer. */
static bool count_row(app_embed *e, const gpu_scene *gs, storage_row *row)
{
    frame_timer t;
    draw_counts c;
    if (!frame_timer_create(&t) || !draw_count_begin(&c))
        return false;
    frame_timer_begin(&t);
    bool ok = app_embed_frame(e, gs, false, NULL);
    frame_timer_end(&t);
    draw_count_end();
    frame_timer_destroy(&t);
    const double pixels = (double)gs->view.width * gs->view.height;
    for (int i = 0; ok && i < c.count; i++) {
        storage_pass *p = pass_named(row, c.passes[i].name);
        if (!p)
            continue;
        p->draws = c.passes[i].draws;
        p->samples_per_px = (double)c.passes[i].samples / pixels;
        p->written_per_px = (double)c.passes[i].written / pixels;
        p->read_per_px = (double)c.passes[i].read / pixels;
        row->written_per_px += p->written_per_px;
        row->read_per_px += p->read_per_px;
    }
    if (ok && strcmp(row->renderer, "visibility-buffer") == 0) {
        const storage_pass *once = bench_storage_find_pass(row, "shading"),
                           *edges = bench_storage_find_pass(row, "shading edges");
        row->scene_read_per_px = bench_storage_vis_scene_bytes *
                                 ((once ? once->samples_per_px : 0.0) + (edges ? edges->samples_per_px * row->samples : 0.0));
    }
    return ok && gl_check("bench_storage count");
}

/* The chapter's last picture, top row first. */
static bool read_picture(app_embed *e, image *out)
{
    const fbo *t = app_embed_target(e);
    if (!image_create(out, t->width, t->height))
        return false;
    bool ok = fbo_read_rgba8(t, 0, out->pixels);
    image_flip_rows(out);
    return ok;
}

/* The exact picture at 4 samples: chapter 13's forward MSAA at cut-off 0 (every light in every
 * list), its samples resolved in linear radiance as every 4-sample row's are; at 1 sample the
 * benchmark's own (bench_measure.h). An antialiased picture is compared with an antialiased one. */
static image reference4;

static bool make_reference4(gpu_scene *gs, int width, int height)
{
    static const char *const args[] = {"--renderer", "forward", "--samples", "4", NULL};
    app_embed *e = NULL;
    image_destroy(&reference4);
    bool ok = gpu_scene_update(gs, 0.0f, 0.0, width, height) && app_embed_open(&chapter_13, args, gs, &e) &&
              app_embed_frame(e, gs, false, NULL) && read_picture(e, &reference4);
    app_embed_close(e);
    return gpu_scene_update(gs, 0.0f, LIGHT_DEFAULT_CUTOFF, width, height) && ok;
}

static bool error_row(app_embed *e, const bench_measure *m, storage_row *row)
{
    image img;
    const image *reference = row->samples == 1 ? &m->ref8 : &reference4;
    bool ok = read_picture(e, &img);
    row->have_error = ok && image_compare(&img, reference, NULL, 1, &row->error8, NULL);
    image_destroy(&img);
    if (row->have_error && (!isfinite(row->error8.psnr) || row->error8.psnr > BENCH_PSNR_CAP))
        row->error8.psnr = BENCH_PSNR_CAP;
    return ok;
}

const storage_pass *bench_storage_find_pass(const storage_row *row, const char *name)
{
    for (int i = 0; i < row->pass_count; i++)
        if (strcmp(row->passes[i].name, name) == 0)
            return &row->passes[i];
    return NULL;
}

/* Row sr at bench_storage_samples[k] into *row: its chapter opened, timed, counted, compared, closed;
 * without m (a timing-only row) timed only. A chapter that refuses the scene (its limits) leaves a
 * note; a GL failure stops the table. */
static bool run_row(const bench_options *o, const storage_renderer *sr, int si, int k, const gpu_scene *gs,
                    bench_measure *m, storage_row *row)
{
    const storage_variant *v = &sr->at[k];
    memset(row, 0, sizeof *row);
    row->renderer = sr->name;
    row->samples = bench_storage_samples[k];
    if (!m)
        snprintf(row->note, sizeof row->note, "timing only: a wrong picture by design; no bytes and no error");
    if (!v->chapter) {
        snprintf(row->note, sizeof row->note, "no %d-sample variant in the course", row->samples);
        return true;
    }
    const gbuffer_layout *layout = gbuffer_default_layout(); /* --gbuffer changes it for good */
    app_embed *e = NULL;
    if (!app_embed_open(v->chapter, v->args, gs, &e)) {
        snprintf(row->note, sizeof row->note, "the chapter refused the scene (see the log)");
        gbuffer_set_default_layout(layout);
        return gl_check("bench_storage open");
    }
    bool ok = time_row(e, o, gs, row) && (!m || (count_row(e, gs, row) && error_row(e, m, row)));
    app_embed_close(e);
    gbuffer_set_default_layout(layout);
    row->measured = ok;
    const storage_pass *first = bench_storage_find_pass(row, sr->first);
    if (ok && !m)
        fprintf(stderr, "bench: storage %-8s %-19s x%d timing only: %s %9.2f ms, frame %9.2f ms\n",
                bench_storage_scene_names[si], sr->name, row->samples, sr->first, first ? first->ms : NAN,
                row->frame_ms);
    else if (ok)
        fprintf(stderr, "bench: storage %-8s %-19s x%d %6.1f B/px written %7.1f B/px read %9.2f ms\n",
                bench_storage_scene_names[si], sr->name, row->samples, row->written_per_px, row->read_per_px,
                row->frame_ms);
    return ok;
}

static bool run_scene(const bench_options *o, int si, bench_renderers *br, bench_measure *m)
{
    char path[SCENE_PATH_MAX], key[BENCH_KEY_LEN];
    bench_options_find_scene(o, bench_storage_scene_names[si], path, sizeof path);
    scene sc;
    if (!scene_load(path, &sc))
        return false;
    gpu_scene gs;
    bool ok = gpu_scene_create(&sc, &gs);
    if (ok) {
        R.scene_lights[si] = sc.light_count;
        snprintf(key, sizeof key, "storage/%s", bench_storage_scene_names[si]);
        /* The reference is drawn by the benchmark's own chapter 00, closed again so that the rows
         * can open it with their arguments (a chapter is open once at a time). */
        ok = bench_measure_make_reference(m, br, &gs, key, LIGHT_DEFAULT_CUTOFF) &&
             gpu_scene_update(&gs, 0.0f, LIGHT_DEFAULT_CUTOFF, o->width, o->height);
        bench_renderers_close_chapters(br);
        ok = ok && make_reference4(&gs, o->width, o->height);
        for (int ri = 0; ok && ri < STORAGE_RENDERERS; ri++)
            for (int k = 0; ok && k < STORAGE_SAMPLE_COUNTS; k++)
                ok = run_row(o, &bench_storage_renderers[ri], si, k, &gs, m, &R.rows[si][ri][k]);
        for (int ti = 0; ok && ti < STORAGE_TIMINGS; ti++)
            for (int k = 0; ok && k < STORAGE_SAMPLE_COUNTS; k++)
                ok = run_row(o, &bench_storage_timings[ti], si, k, &gs, NULL, &R.timings[si][ti][k]);
        gpu_scene_destroy(&gs);
    }
    scene_destroy(&sc);
    bench_measure_forget_reference(m);
    R.scene_done[si] = ok;
    return ok;
}

bool bench_storage_run(const bench_state *st, bench_renderers *br, bench_measure *m)
{
    double t0 = bench_measure_now_ms();
    memset(&R, 0, sizeof R);
    R.ran = true;
    frame_timer t;
    if (!frame_timer_create(&t))
        return false;
    R.pass_clock = frame_timer_clock(&t);
    frame_timer_destroy(&t);
    app_forward_set_plus(&chapter_11_forward_plus); /* as CHAPTER_MAIN does */
    for (int si = 0; si < bench_storage_scene_count(); si++)
        if (!run_scene(&st->opt, si, br, m))
            return false;
    image_destroy(&reference4);
    fprintf(stderr, "bench: storage table in %.1f s\n", (bench_measure_now_ms() - t0) / 1000.0);
    return gl_check("bench_storage_run");
}
