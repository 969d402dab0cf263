/* bench_ambient_error.c - see bench_ambient_error.h. */
#include "bench_ambient_error.h"

#include "ao_reference.h"
#include "bench_ambient.h"
#include "chapters.h"
#include "ibl_probes.h"
#include "light.h"
#include "log.h"
#include "probe_readback.h"
#include "progress.h"
#include "ssao_readback.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

enum { AO_W = 160, AO_H = 120, AO_RAYS = 64, MAX_CONFIGS = 10, MAX_RADII = 3, IBL_SCENES = 2, IBL_LEVELS = 5 };
enum { MC_SAMPLES = 65536 };
static const int sample_counts[] = {4, 8, 16, 32, 64}, quick_sample_counts[] = {4, 16, 64};
static const int blurs[] = {0, 2};
static const double radii[MAX_RADII] = {0.25, 0.5, 1.0}, quick_radius = 0.5;
static const double BOUND = 0.1; /* hard.ssao_reference's: an error in A a reader sees */
static const double F0 = 0.5;    /* hard.ibl_reference's */
static const char *const ibl_scene_names[IBL_SCENES] = {"default", "teapots_probes"};

typedef struct ao_error {
    long count, over;
    double sum, max;
} ao_error;

typedef struct ssao_config {
    int samples, blur;
    bench_ambient_row time;
    ao_error error[MAX_RADII];
} ssao_config;

typedef struct ssao_table {
    ssao_config rows[MAX_CONFIGS];
    int count;
    double radii[MAX_RADII];
    int radius_count, stride;
    double noise_mean[MAX_RADII], noise_max[MAX_RADII];
} ssao_table;

static double reference[AO_W * AO_H]; /* A traced; -1: no surface, or a pixel the subsample skips */

/* Traced occlusion at every stride-th pixel of gs's view (already at AO_W x AO_H). */
static void trace_reference(const ray_scene *rays, const gpu_scene *gs, double radius, int stride, double *noise_mean,
                            double *noise_max)
{
    ao_reference a;
    char what[64];
    snprintf(what, sizeof what, "bench: traced occlusion, radius %g, row", radius);
    ao_reference_begin(&a, rays, (const float *)gs->view.view_proj, gs->view.eye, AO_W, AO_H, radius, AO_RAYS);
    for (int y = 0; y < AO_H; y++) {
        progress_frame(what, y, AO_H);
        for (int x = 0; x < AO_W; x++)
            reference[y * AO_W + x] = x % stride || y % stride ? -1.0 : ao_reference_pixel(&a, x, y, NULL);
    }
    progress_end();
    ao_reference_noise(&a, noise_mean, noise_max);
}

/* Chapter 17's occlusion for one configuration at AO_W x AO_H against the reference. */
static bool compare_config(const gpu_scene *gs, const ssao_config *c, double radius, ao_error *out)
{
    char samples[16], blur[16], r[32];
    snprintf(samples, sizeof samples, "%d", c->samples);
    snprintf(blur, sizeof blur, "%d", c->blur);
    snprintf(r, sizeof r, "%g", radius);
    static unsigned char rgba[4 * AO_W * AO_H];
    bool ok = ssao_readback(gs, r, samples, blur, rgba);
    *out = (ao_error){0};
    for (int i = 0; ok && i < AO_W * AO_H; i++) {
        if (reference[i] < 0.0)
            continue;
        double err = fabs(rgba[4 * i] / 255.0 - reference[i]);
        out->sum += err, out->max = fmax(out->max, err), out->over += err > BOUND, out->count++;
    }
    return ok && out->count > 0;
}

/* Each configuration timed at the run's size, one after the other (each chapter 17 alone). */
static bool time_configs(const bench_options *o, gpu_scene *gs, ssao_table *t)
{
    bool ok = gpu_scene_update(gs, 0.0f, LIGHT_DEFAULT_CUTOFF, o->width, o->height);
    for (int i = 0; ok && i < t->count; i++) {
        ssao_config *c = &t->rows[i];
        char samples[16], blur[16];
        snprintf(samples, sizeof samples, "%d", c->samples);
        snprintf(blur, sizeof blur, "%d", c->blur);
        const char *args[] = {"--ao-samples", samples, "--ao-blur", blur, NULL};
        const char *const *const all_args[] = {args};
        const app_desc *const descs[] = {&chapter_17};
        progress_frame("bench: SSAO settings timed, setting", i, t->count);
        ok = bench_ambient_time(o, gs, 1, descs, all_args, &c->time);
    }
    progress_end();
    return ok;
}

static bool ssao_run(const bench_options *o, ssao_table *t)
{
    const int *counts = o->quick ? quick_sample_counts : sample_counts;
    const int n = o->quick ? 3 : 5;
    t->count = 0;
    for (int s = 0; s < n; s++)
        for (int b = 0; b < 2; b++)
            t->rows[t->count++] = (ssao_config){.samples = counts[s], .blur = blurs[b]};
    t->radius_count = o->quick ? 1 : MAX_RADII, t->stride = o->quick ? 4 : 1;
    for (int r = 0; r < t->radius_count; r++)
        t->radii[r] = o->quick ? quick_radius : radii[r];
    char path[SCENE_PATH_MAX];
    bench_options_find_scene(o, "default", path, sizeof path);
    scene sc;
    gpu_scene gs;
    ray_scene rays = {0};
    if (!scene_load(path, &sc))
        return false;
    bool made = gpu_scene_create(&sc, &gs);
    bool ok = made && ray_scene_build(&rays, &sc, 0.0f) &&
              gpu_scene_update(&gs, 0.0f, LIGHT_DEFAULT_CUTOFF, AO_W, AO_H);
    for (int r = 0; ok && r < t->radius_count; r++) {
        trace_reference(&rays, &gs, t->radii[r], t->stride, &t->noise_mean[r], &t->noise_max[r]);
        for (int i = 0; ok && i < t->count; i++)
            ok = compare_config(&gs, &t->rows[i], t->radii[r], &t->rows[i].error[r]);
        fprintf(stderr, "bench: ambient SSAO against traced occlusion at radius %g: %d settings compared\n",
                t->radii[r], t->count);
    }
    ok = ok && time_configs(o, &gs, t);
    ray_scene_destroy(&rays);
    if (made)
        gpu_scene_destroy(&gs);
    scene_destroy(&sc);
    return ok;
}

/* Probe 0 of a scene, as chapter 19 makes it at its defaults, against Monte Carlo by roughness. */
static bool ibl_run(const bench_options *o, const char *name, split_sum_errors out[IBL_LEVELS])
{
    static ibl probes;
    const ibl_desc desc = {.size = 128, .levels = IBL_LEVELS, .samples = 256, .brdf_size = 64, .brdf_samples = 512};
    char path[SCENE_PATH_MAX];
    bench_options_find_scene(o, name, path, sizeof path);
    scene sc;
    gpu_scene gs;
    split_sum_probe read = {0};
    if (!scene_load(path, &sc))
        return false;
    bool made = gpu_scene_create(&sc, &gs), created = made && ibl_probes_create(&probes, &desc);
    bool ok = created && gpu_scene_update(&gs, 0.0f, LIGHT_DEFAULT_CUTOFF, 64, 64) && /* hard.ibl_reference's view */
              ibl_probes_capture(&probes, &gs) && probes.count > 0 && probe_readback(&probes, 0, &read);
    if (made && !ok)
        log_error("%s: no probe to compare with Monte Carlo", path);
    for (int l = 0; ok && l < IBL_LEVELS; l++) {
        char what[96];
        snprintf(what, sizeof what, "bench: split sum against Monte Carlo on %s, roughness", name);
        progress_frame(what, l, IBL_LEVELS);
        split_sum_error(&read, l, F0, MC_SAMPLES, &out[l]);
    }
    progress_end();
    probe_readback_free(&read);
    if (created)
        ibl_probes_destroy(&probes);
    if (made)
        gpu_scene_destroy(&gs);
    scene_destroy(&sc);
    return ok;
}

static double mean_of(const ao_error *e) { return e->count ? e->sum / (double)e->count : NAN; }
static double beyond_of(const ao_error *e) { return e->count ? 100.0 * (double)e->over / (double)e->count : NAN; }

static void put_ms(FILE *f, double ms)
{
    if (isnan(ms))
        fprintf(f, " – |");
    else
        fprintf(f, " %.1f |", ms);
}

static void write_ssao(const bench_options *o, const ssao_table *t, FILE *md, FILE *csv)
{
    fprintf(md, "\n## SSAO against traced occlusion\n\n"
                "Chapter 17 on the default scene. Time: each setting alone at %dx%d (radius 0.5), median of %d "
                "frames, ms. Error: its occlusion (`--view ao`, `ao-blurred` with a blur) at %dx%d against "
                "occlusion traced in double precision (%d x %d cosine-weighted rays per pixel, %s), over the "
                "%ld pixels that see a surface: the mean error in A (0 shut, 1 open) and the share of pixels "
                "off by more than %.1f. The reference's own noise (a second set of rays on every 4th pixel traced): "
                "mean",
            o->width, o->height, t->rows[0].time.frames, AO_W, AO_H, AO_RAYS, AO_RAYS,
            t->stride > 1 ? "every 4th pixel in x and y" : "every pixel", t->rows[0].error[0].count, BOUND);
    for (int r = 0; r < t->radius_count; r++)
        fprintf(md, "%s %.5f (max %.4f) at radius %g", r ? "," : "", t->noise_mean[r], t->noise_max[r], t->radii[r]);
    fprintf(md, ".\n\n| directions | blur | frame | SSAO | blur pass |");
    for (int r = 0; r < t->radius_count; r++)
        fprintf(md, " radius %g: mean | beyond %.1f |", t->radii[r], BOUND);
    fprintf(md, "\n|---|---|---|---|---|");
    for (int r = 0; r < t->radius_count; r++)
        fprintf(md, "---|---|");
    fprintf(md, "\n");
    fprintf(csv, "scene,samples,blur,width,height,frames,frame_ms,ssao_ms,ssao_blur_ms,radius,reference_width,"
                 "reference_height,reference_stride,pixels,mean_error,max_error,beyond_0_1_percent\n");
    for (int i = 0; i < t->count; i++) {
        const ssao_config *c = &t->rows[i];
        const double *ms = c->time.ms;
        fprintf(md, "| %d | %d |", c->samples, c->blur);
        put_ms(md, ms[BENCH_AMBIENT_FRAME]);
        put_ms(md, ms[BENCH_AMBIENT_SSAO]);
        put_ms(md, ms[BENCH_AMBIENT_BLUR]);
        for (int r = 0; r < t->radius_count; r++) {
            const ao_error *e = &c->error[r];
            fprintf(md, " %.4f | %.2f %% |", mean_of(e), beyond_of(e));
            fprintf(csv, "default,%d,%d,%d,%d,%d,%.3f,%.3f,", c->samples, c->blur, o->width, o->height, c->time.frames,
                    ms[BENCH_AMBIENT_FRAME], ms[BENCH_AMBIENT_SSAO]);
            if (!isnan(ms[BENCH_AMBIENT_BLUR]))
                fprintf(csv, "%.3f", ms[BENCH_AMBIENT_BLUR]);
            fprintf(csv, ",%g,%d,%d,%d,%ld,%.5f,%.5f,%.3f\n", t->radii[r], AO_W, AO_H, t->stride, e->count, mean_of(e),
                    e->max, beyond_of(e));
        }
        fprintf(md, "\n");
    }
}

static void write_ibl(int scenes, const split_sum_errors rows[IBL_SCENES][IBL_LEVELS], FILE *md, FILE *csv)
{
    fprintf(md, "\n## Split sum against Monte Carlo\n\n"
                "Probe 0 of each scene, made as chapter 19 makes it (128 x 128 per face, 256 samples per "
                "prefiltered texel), read back and compared with the full GGX BRDF integrated by Monte Carlo "
                "(%d samples, F0 %.1f) for %d normals x n·v = 1, 0.75, 0.5, 0.25: the split sum's relative "
                "error in luminance, looked up along the mirror direction and along the chapter's dominant "
                "direction.\n\n"
                "| scene | roughness | mirror: mean | max | dominant (the chapter's): mean | max | n·v = 1: mean |\n"
                "|---|---|---|---|---|---|---|\n",
            MC_SAMPLES, F0, SPLIT_SUM_NORMALS);
    fprintf(csv, "scene,roughness,mirror_mean,mirror_max,dominant_mean,dominant_max,head_on_mean\n");
    for (int s = 0; s < scenes; s++)
        for (int l = 0; l < IBL_LEVELS; l++) {
            const split_sum_errors *e = &rows[s][l];
            fprintf(md, "| %s | %.2f | %.4f | %.4f | %.4f | %.4f | %.4f |\n", ibl_scene_names[s], e->roughness,
                    e->mirror_mean, e->mirror_max, e->dominant_mean, e->dominant_max, e->head_on_mean);
            fprintf(csv, "%s,%.2f,%.5f,%.5f,%.5f,%.5f,%.5f\n", ibl_scene_names[s], e->roughness, e->mirror_mean,
                    e->mirror_max, e->dominant_mean, e->dominant_max, e->head_on_mean);
        }
}

static FILE *open_out(const bench_options *o, const char *name, const char *mode)
{
    char path[1100];
    snprintf(path, sizeof path, "%s/%s", o->out_dir, name);
    FILE *f = fopen(path, mode);
    if (!f)
        log_error("cannot write %s", path);
    return f;
}

bool bench_ambient_error_run(const bench_options *o)
{
    static ssao_table ssao;
    static split_sum_errors ibl_rows[IBL_SCENES][IBL_LEVELS];
    const int ibl_scenes = o->quick ? 1 : IBL_SCENES;
    bool ok = ssao_run(o, &ssao);
    for (int s = 0; ok && s < ibl_scenes; s++) {
        ok = ibl_run(o, ibl_scene_names[s], ibl_rows[s]);
        for (int l = 0; ok && l < IBL_LEVELS; l++)
            fprintf(stderr, "bench: ambient split sum on %-15s roughness %.2f: mean relative error %.4f\n",
                    ibl_scene_names[s], ibl_rows[s][l].roughness, ibl_rows[s][l].dominant_mean);
    }
    if (!ok)
        return false;
    FILE *md = open_out(o, "bench_ambient.md", "a"), *ssao_csv = open_out(o, "bench_ambient_ssao.csv", "w"),
         *ibl_csv = open_out(o, "bench_ambient_ibl.csv", "w");
    if (md && ssao_csv && ibl_csv) {
        write_ssao(o, &ssao, md, ssao_csv);
        write_ibl(ibl_scenes, (const split_sum_errors(*)[IBL_LEVELS])ibl_rows, md, ibl_csv);
    }
    ok = md && ssao_csv && ibl_csv;
    if (md)
        fclose(md);
    if (ssao_csv)
        fclose(ssao_csv);
    if (ibl_csv)
        fclose(ibl_csv);
    return ok;
}
