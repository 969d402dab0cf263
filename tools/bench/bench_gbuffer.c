/* bench_gbuffer.c - see bench_gbuffer.h. */
#include "bench_gbuffer.h"
#include "bench_gbuffer_rows.h"

#include "bench_report.h"
#include "bench_error.h"

#include "deferred_volumes.h"
#include "frame_stats.h"
#include "frame_timer.h"
#include "gbuffer.h"
#include "gl_program.h"
#include "gl_util.h"
#include "light.h"
#include "log.h"
#include "chapters.h"
#include "scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define RAD_TO_DEG (180.0 / 3.14159265358979323846)

typedef enum sweep_mode { SWEEP_ON, SWEEP_OFF, SWEEP_ONLY } sweep_mode;
static sweep_mode mode = SWEEP_ON;

bench_gbuffer_results bench_gbuffer_results_now;
#define R bench_gbuffer_results_now

/* ---- options ----------------------------------------------------------------------------------- */

void bench_gbuffer_reset(bool quick)
{
    mode = quick ? SWEEP_OFF : SWEEP_ON;
}

int bench_gbuffer_parse_option(const char *arg, const char *value)
{
    if (strcmp(arg, "--gbuffer-sweep") != 0)
        return 0;
    static const char *const names[] = {"on", "off", "only"};
    for (int k = 0; value && k < 3; k++)
        if (strcmp(value, names[k]) == 0) {
            mode = (sweep_mode)k;
            return 1;
        }
    fprintf(stderr, "bench: bad --gbuffer-sweep (on, off or only): '%s' (see --help)\n",
            value ? value : "(missing)");
    return -1;
}

bool bench_gbuffer_enabled(void)
{
    return mode != SWEEP_OFF;
}

bool bench_gbuffer_only(void)
{
    return mode == SWEEP_ONLY;
}

void bench_gbuffer_print_help(FILE *f)
{
    fprintf(f, "  --gbuffer-sweep MODE   on: after the sweeps, every G-buffer layout (common/render/gbuffer.h) on\n"
               "                        the default scene, the city and the PBR teapots (the layouts that\n"
               "                        can hold them): bytes, time, normal, position and picture error\n"
               "                        (DIR/bench_gbuffer.csv, a section of bench.md; only:\n"
               "                        DIR/bench_gbuffer.md, and bench.md is left alone);\n"
               "                        off; only: nothing else (--full: on; otherwise off)\n");
}

/* ---- GL ---------------------------------------------------------------------------------------- */

/* Everything one scene's sweep draws with: one G-buffer and light-volume set per layout, and the
 * reference pass and probe that read positions and normals back as floats. */
typedef struct sweep_gl {
    int width, height;
    bool available[GBUFFER_LAYOUT_COUNT];
    const char *unavailable[GBUFFER_LAYOUT_COUNT]; /* why a layout is not drawn */
    gbuffer g[GBUFFER_LAYOUT_COUNT];
    deferred_volumes dv[GBUFFER_LAYOUT_COUNT];
    frame_timer timers[GBUFFER_LAYOUT_COUNT];
    GLuint exact_program, probe_program;
    fbo exact, probe;
    float *exact_position, *exact_normal, *probe_normal, *probe_position, *hdr, *forward_hdr;
    image reference_picture, forward_picture;
    bool have_reference_picture;
} sweep_gl;

static void sweep_destroy(sweep_gl *s)
{
    for (int l = 0; l < GBUFFER_LAYOUT_COUNT; l++) {
        deferred_volumes_destroy(&s->dv[l]);
        gbuffer_destroy(&s->g[l]);
        frame_timer_destroy(&s->timers[l]);
    }
    gl_program_destroy(&s->exact_program);
    gl_program_destroy(&s->probe_program);
    fbo_destroy(&s->exact);
    fbo_destroy(&s->probe);
    float *const read_backs[] = {s->exact_position, s->exact_normal, s->probe_normal,
                                 s->probe_position, s->hdr,          s->forward_hdr};
    for (size_t i = 0; i < sizeof read_backs / sizeof read_backs[0]; i++)
        free(read_backs[i]);
    image_destroy(&s->reference_picture);
    image_destroy(&s->forward_picture);
    memset(s, 0, sizeof *s);
}

static bool sweep_create(sweep_gl *s, int width, int height)
{
    memset(s, 0, sizeof *s);
    s->width = width, s->height = height;
    size_t n = 4 * (size_t)width * (size_t)height;
    s->exact_position = malloc(n * sizeof(float));
    s->exact_normal = malloc(n * sizeof(float));
    s->probe_normal = malloc(n * sizeof(float));
    s->probe_position = malloc(n * sizeof(float));
    s->hdr = malloc(n * sizeof(float));
    s->forward_hdr = malloc(n * sizeof(float));
    if (!s->exact_position || !s->exact_normal || !s->probe_normal || !s->probe_position || !s->hdr ||
        !s->forward_hdr) {
        log_error("out of memory for the G-buffer sweep's read-backs");
        return false;
    }
    /* The geometry pass's own floats (gbuffer.frag with GBUFFER_EXACT), and a probe that decodes a
     * layout's normal or position into a float target (gbuffer_view.frag's RAW views). */
    const fbo_desc exact = {.color_formats = {GL_RGBA32F, GL_RGBA32F},
                            .color_count = 2,
                            .depth_format = GL_DEPTH_COMPONENT32F,
                            .name = "exact normal and position"};
    const fbo_desc probe = {.color_formats = {GL_RGBA32F}, .color_count = 1, .name = "G-buffer probe"};
    s->exact_program = gl_program_load("forward.vert", "gbuffer.frag", "GBUFFER_EXACT 1");
    s->probe_program = gl_program_load("fullscreen.vert", "gbuffer_view.frag", NULL);
    if (!s->exact_program || !s->probe_program || !fbo_create(&s->exact, &exact, width, height) ||
        !fbo_create(&s->probe, &probe, width, height))
        return false;
    for (int l = 0; l < GBUFFER_LAYOUT_COUNT; l++) {
        const gbuffer_layout *layout = &gbuffer_layouts[l];
        if (!frame_timer_create(&s->timers[l]))
            return false;
        s->available[l] = gbuffer_layout_available(layout); /* reversed-z without clip control: no */
        s->unavailable[l] = "not available: no glClipControl";
        if (s->available[l] &&
            (!gbuffer_create_with(&s->g[l], width, height, &(gbuffer_desc){.layout = layout}) ||
             !deferred_volumes_create(&s->dv[l], &s->g[l], GL_RGBA16F)))
            return false;
    }
    return gl_check("bench_gbuffer create");
}

/* Chapter 07's frame with layout l (chapters/07_face_culling.c, chapter_07_draw_with). */
static bool draw_frame(sweep_gl *s, int l, const gpu_scene *gs, GLuint target)
{
    return chapter_07_draw_with(&s->g[l], &s->dv[l], gs, target, (deferred_volumes_frame){.accum_format = GL_RGBA16F});
}

/* The float position and normal of every covered pixel, as the geometry pass computes them. */
static bool draw_exact(sweep_gl *s, const gpu_scene *gs)
{
    gpu_scene_draw_into(gs, s->exact.id, s->width, s->height, s->exact_program,
                        &(gl_pass_state){.cull = GL_BACK, .depth_func = GL_LEQUAL, .depth_write = true});
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return fbo_read_float(&s->exact, 0, s->exact_position) && fbo_read_float(&s->exact, 1, s->exact_normal);
}

/* What layout l's G-buffer decodes at every pixel: the normal, or the position (SHADER_GBUFFER_VIEW_*). */
static bool probe(sweep_gl *s, int l, const gpu_scene *gs, int view, float *out)
{
    glBindFramebuffer(GL_FRAMEBUFFER, s->probe.id);
    glViewport(0, 0, s->width, s->height);
    gl_pass_state_reset();
    gbuffer_bind_textures(&s->g[l], gs, s->probe_program, SHADER_UNIT_GBUFFER);
    glUniform1i(glGetUniformLocation(s->probe_program, "u_view"), view);
    glUniform2f(glGetUniformLocation(s->probe_program, "u_near_far"), gs->view.near_plane,
                gs->view.far_plane);
    gl_draw_fullscreen();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return fbo_read_float(&s->probe, 0, out);
}

/* ---- error measures ---------------------------------------------------------------------------- */

/* Angle between two directions in degrees, accurate near 0 (acos is not). */
static double angle_deg(const float *a, const float *b)
{
    double c[3] = {(double)a[1] * b[2] - (double)a[2] * b[1], (double)a[2] * b[0] - (double)a[0] * b[2],
                   (double)a[0] * b[1] - (double)a[1] * b[0]};
    double d = (double)a[0] * b[0] + (double)a[1] * b[1] + (double)a[2] * b[2];
    return atan2(sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), d) * RAD_TO_DEG;
}

typedef struct sample {
    double distance, error;
} sample;

static int by_distance(const void *a, const void *b)
{
    double x = ((const sample *)a)->distance, y = ((const sample *)b)->distance;
    return (x > y) - (x < y);
}

/* Normal and position error of the probed layout against the exact floats. */
static bool measure_precision(const sweep_gl *s, const gpu_scene *gs, layout_row *row)
{
    size_t n = (size_t)s->width * (size_t)s->height, used = 0;
    sample *samples = malloc(n * sizeof *samples);
    if (!samples) {
        log_error("out of memory for the position errors");
        return false;
    }
    double sum_deg = 0.0;
    row->normal_max = 0.0, row->covered = 0, row->other_surface = 0;
    for (size_t p = 0; p < n; p++) {
        const float *xp = s->exact_position + 4 * p, *xn = s->exact_normal + 4 * p;
        const float *pn = s->probe_normal + 4 * p, *pp = s->probe_position + 4 * p;
        bool exact_covered = xp[3] > 0.5f, layout_covered = pn[3] > 0.5f;
        if (!exact_covered && !layout_covered)
            continue;
        row->covered++;
        double deg = exact_covered && layout_covered ? angle_deg(xn, pn) : 180.0;
        if (deg > OTHER_SURFACE_DEG) {
            row->other_surface++;
            continue;
        }
        sum_deg += deg;
        row->normal_max = fmax(row->normal_max, deg);
        double dx = (double)pp[0] - xp[0], dy = (double)pp[1] - xp[1], dz = (double)pp[2] - xp[2];
        double ex = (double)xp[0] - gs->view.eye[0], ey = (double)xp[1] - gs->view.eye[1],
               ez = (double)xp[2] - gs->view.eye[2];
        samples[used++] = (sample){sqrt(ex * ex + ey * ey + ez * ez), sqrt(dx * dx + dy * dy + dz * dz)};
    }
    row->normal_mean = used ? sum_deg / (double)used : 0.0;
    qsort(samples, used, sizeof *samples, by_distance);
    for (int b = 0; b < 3; b++) {
        size_t lo = used * (size_t)b / 3, hi = used * (size_t)(b + 1) / 3;
        band *out = &row->bands[b];
        *out = (band){0};
        for (size_t i = lo; i < hi; i++) {
            out->mean += samples[i].error;
            out->max = fmax(out->max, samples[i].error);
        }
        if (hi > lo) {
            out->mean /= (double)(hi - lo);
            out->distance = samples[(lo + hi) / 2].distance;
        }
    }
    free(samples);
    return true;
}

/* Chapter 00's forward renderer at the sweep's cut-off, 8-bit and linear: the same frame with every
 * shading input a float, so the difference is what the layout's storage costs (as the agreement
 * tests measure it). */
static bool draw_forward(sweep_gl *s, bench_renderers *br, const gpu_scene *gs)
{
    const int r = bench_renderer_find("forward");
    image_destroy(&s->forward_picture);
    return bench_render_frame(br, r, gs, false, NULL) &&
           bench_renderers_read_target(br, &s->forward_picture) &&
           bench_read_linear(br, r, gs, s->forward_hdr);
}

static void compare8(const image *a, const image *b, image_stats *out)
{
    image_compare(a, b, NULL, 1, out, NULL);
    if (!isfinite(out->psnr) || out->psnr > BENCH_PSNR_CAP)
        out->psnr = BENCH_PSNR_CAP;
}

/* The picture against forward at the same cut-off, the exact reference (when drawn) and the
 * `reference` layout's picture. */
static bool measure_picture(sweep_gl *s, int l, bench_renderers *br, const bench_measure *m, bool exact,
                            layout_row *row)
{
    image img;
    if (!bench_renderers_read_target(br, &img) || !fbo_read_float(&s->dv[l].accum, 0, s->hdr)) {
        image_destroy(&img);
        return false;
    }
    compare8(&img, &s->forward_picture, &row->vs_forward8);
    bench_error_measure_hdr(s->hdr, s->forward_hdr, s->width, s->height, &row->vs_forward_hdr);
    row->have_exact = exact;
    if (exact) {
        compare8(&img, &m->ref8, &row->error8);
        bench_error_measure_hdr(s->hdr, m->ref_hdr, s->width, s->height, &row->error_hdr);
    }
    if (l == GBUFFER_LAYOUT_REFERENCE) {
        image_destroy(&s->reference_picture);
        s->reference_picture = img;
        s->have_reference_picture = true;
    }
    if (s->have_reference_picture)
        compare8(&img, &s->reference_picture, &row->vs_reference);
    if (l != GBUFFER_LAYOUT_REFERENCE)
        image_destroy(&img);
    return true;
}

/* ---- the sweep --------------------------------------------------------------------------------- */

static double pass_ms(const frame_times *t, const char *name)
{
    for (int j = 0; t->valid && j < t->count; j++)
        if (strcmp(t->names[j], name) == 0)
            return t->ms[j];
    return NAN;
}

static double median_of(double *v, int n)
{
    int k = 0;
    for (int i = 0; i < n; i++)
        if (!isnan(v[i]))
            v[k++] = v[i];
    return k > 0 ? frame_stats_of(v, k).median : NAN;
}

/* Warm-up, then timed frames, every layout in turn within a round. */
static bool time_layouts(sweep_gl *s, const bench_options *o, bench_renderers *br, const gpu_scene *gs,
                         layout_row *out)
{
    const int warmup = o->warmup > 0 ? o->warmup : 1, frames = o->frames;
    double *t = malloc(3 * (size_t)frames * GBUFFER_LAYOUT_COUNT * sizeof *t);
    if (!t) {
        log_error("out of memory for frame times");
        return false;
    }
    bool ok = true;
    GLuint target = bench_renderers_target(br)->id;
    for (int k = 0; ok && k < warmup + frames; k++)
        for (int l = 0; ok && l < GBUFFER_LAYOUT_COUNT; l++) {
            if (!s->available[l])
                continue;
            double t0 = bench_measure_now_ms();
            frame_timer_begin(&s->timers[l]);
            ok = draw_frame(s, l, gs, target);
            frame_timer_end(&s->timers[l]);
            glFinish();
            double ms = bench_measure_now_ms() - t0;
            if (k < warmup)
                continue;
            double *slot = t + 3 * ((size_t)l * (size_t)frames + (size_t)(k - warmup));
            slot[0] = ms;
            slot[1] = pass_ms(&s->timers[l].last, "geometry");
            slot[2] = pass_ms(&s->timers[l].last, "lighting");
        }
    double *column = malloc((size_t)frames * sizeof *column);
    for (int l = 0; ok && column && l < GBUFFER_LAYOUT_COUNT; l++) {
        double *medians[3] = {&out[l].frame_ms, &out[l].geometry_ms, &out[l].lighting_ms};
        for (int j = 0; j < 3; j++) {
            for (int i = 0; i < frames; i++)
                column[i] = t[3 * ((size_t)l * (size_t)frames + (size_t)i) + (size_t)j];
            *medians[j] = s->available[l] ? median_of(column, frames) : NAN;
        }
        out[l].frames = s->available[l] ? frames : 0;
    }
    if (!column)
        log_error("out of memory for frame times");
    ok = ok && column;
    free(column);
    free(t);
    return ok;
}

static bool measure_layouts(sweep_gl *s, bench_renderers *br, const bench_measure *m, bool exact,
                            const gpu_scene *gs, layout_row *out)
{
    if (!draw_exact(s, gs) || !draw_forward(s, br, gs))
        return false;
    for (int l = 0; l < GBUFFER_LAYOUT_COUNT; l++) {
        layout_row *row = &out[l];
        if (!s->available[l]) {
            snprintf(row->note, sizeof row->note, "%s", s->unavailable[l]);
            continue;
        }
        if (!draw_frame(s, l, gs, bench_renderers_target(br)->id) ||
            !measure_picture(s, l, br, m, exact, row) ||
            !probe(s, l, gs, SHADER_GBUFFER_VIEW_NORMAL_RAW, s->probe_normal) ||
            !probe(s, l, gs, SHADER_GBUFFER_VIEW_POSITION_RAW, s->probe_position) ||
            !measure_precision(s, gs, row))
            return false;
        row->measured = true;
    }
    return true;
}

static bool run_scene(const bench_options *o, int si, bench_renderers *br, bench_measure *m)
{
    char path[SCENE_PATH_MAX], key[BENCH_KEY_LEN];
    bench_options_find_scene(o, bench_gbuffer_scene_names[si], path, sizeof path);
    scene sc;
    if (!scene_load(path, &sc))
        return false;
    gpu_scene gs;
    sweep_gl s;
    bool ok = gpu_scene_create(&sc, &gs);
    /* As in the main sweep, the exact reference (every light on every pixel) only up to
     * --error-max-lights: beyond, it is the slowest frame of all. */
    const bool exact = sc.light_count <= o->error_max_lights;
    if (ok) {
        snprintf(key, sizeof key, "gbuffer/%s", bench_gbuffer_scene_names[si]);
        ok = sweep_create(&s, o->width, o->height);
        /* A metallic-roughness scene: the layouts that cannot hold it are listed, not drawn. */
        bool pbr = false;
        for (int i = 0; i < sc.material_count; i++)
            pbr = pbr || sc.materials[i].pbr;
        for (int l = 0; ok && pbr && l < GBUFFER_LAYOUT_COUNT; l++)
            if (s.available[l] && !gbuffer_layout_holds_pbr(&gbuffer_layouts[l])) {
                s.available[l] = false;
                s.unavailable[l] = "cannot hold metallic-roughness materials (fixed-point RT1): not drawn";
            }
        ok = ok &&
             (!exact || bench_measure_make_reference(m, br, &gs, key, LIGHT_DEFAULT_CUTOFF)) &&
             gpu_scene_update(&gs, 0.0f, LIGHT_DEFAULT_CUTOFF, o->width, o->height) &&
             time_layouts(&s, o, br, &gs, R.rows[si]) && measure_layouts(&s, br, m, exact, &gs, R.rows[si]);
        R.pass_clock = frame_timer_clock(&s.timers[0]);
        for (int l = 0; l < GBUFFER_LAYOUT_COUNT; l++) {
            R.rows[si][l].lights = sc.light_count;
            if (ok && R.rows[si][l].measured)
                fprintf(stderr, "bench: gbuffer %-8s %-14s %2d bytes %9.2f ms, normal max %.4f deg\n",
                        bench_gbuffer_scene_names[si], gbuffer_layout_names[l],
                        gbuffer_layout_bytes(&gbuffer_layouts[l], false), R.rows[si][l].frame_ms,
                        R.rows[si][l].normal_max);
        }
        sweep_destroy(&s);
        gpu_scene_destroy(&gs);
    }
    scene_destroy(&sc);
    bench_measure_forget_reference(m);
    R.scene_done[si] = ok;
    return ok;
}

bool bench_gbuffer_run(const bench_state *st, bench_renderers *br, bench_measure *m)
{
    double t0 = bench_measure_now_ms();
    memset(&R, 0, sizeof R);
    for (int si = 0; si < SCENES; si++)
        if (!run_scene(&st->opt, si, br, m))
            return false;
    fprintf(stderr, "bench: G-buffer sweep in %.1f s\n", (bench_measure_now_ms() - t0) / 1000.0);
    return gl_check("bench_gbuffer_run");
}
