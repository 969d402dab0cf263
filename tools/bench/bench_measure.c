/* bench_measure.c - see bench_measure.h. */
#include "bench_measure.h"

#include "bench_error.h"

#include "gl_util.h"
#include "light_work.h"
#include "log.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

bool bench_measure_create(int width, int height, bench_measure *m)
{
    memset(m, 0, sizeof *m);
    m->width = width, m->height = height;
    size_t n = (size_t)width * (size_t)height;
    m->depth = malloc(n * sizeof *m->depth);
    m->hdr = malloc(4 * n * sizeof *m->hdr);
    m->ref_hdr = malloc(4 * n * sizeof *m->ref_hdr);
    m->positions = malloc(4 * n * sizeof *m->positions);
    if (!m->depth || !m->hdr || !m->ref_hdr || !m->positions) {
        log_error("out of memory for %dx%d read-back buffers", width, height);
        return false;
    }
    return true;
}

void bench_measure_destroy(bench_measure *m)
{
    image_destroy(&m->ref8);
    free(m->depth);
    free(m->hdr);
    free(m->ref_hdr);
    free(m->positions);
    memset(m, 0, sizeof *m);
}

double bench_measure_now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

/* Forward, fp32, cut-off 0 (every light reaches every pixel): the same shading model with nothing
 * truncated. Kept while the (scene, lights) stay: it is the slowest frame of a case. */
bool bench_measure_make_reference(bench_measure *m, bench_renderers *br, gpu_scene *gs, const char *key,
                                  double cutoff)
{
    if (m->have_ref && strcmp(m->ref_key, key) == 0)
        return true;
    m->have_ref = false;
    double t0 = bench_measure_now_ms();
    const int r = bench_renderer_reference();
    bool ok =
        gpu_scene_update(gs, 0.0f, 0.0, m->width, m->height) && bench_render_frame(br, r, gs, false, NULL);
    image_destroy(&m->ref8);
    ok = ok && bench_renderers_read_target(br, &m->ref8) &&
         bench_read_linear(br, r, gs, m->ref_hdr);
    ok = gpu_scene_update(gs, 0.0f, cutoff, m->width, m->height) && ok;
    if (!ok)
        return false;
    snprintf(m->ref_key, sizeof m->ref_key, "%s", key);
    m->have_ref = true;
    fprintf(stderr, "bench:   reference (forward fp32, cut-off 0, %d lights): %.0f ms\n", gs->light_count,
            bench_measure_now_ms() - t0);
    return true;
}

void bench_measure_forget_reference(bench_measure *m)
{
    m->have_ref = false;
}

bool bench_measure_count_ideal(bench_measure *m, bench_renderers *br, const gpu_scene *gs, bench_ideal *out)
{
    if (!bench_render_frame(br, bench_renderer_depth_source(), gs, false, NULL) ||
        !fbo_read_depth(bench_renderers_target(br), m->depth))
        return false;
    const float *view_proj = (const float *)gs->view.view_proj;
    light_work_positions(m->depth, m->width, m->height, view_proj, m->positions);
    out->covered = 0;
    for (size_t p = 0; p < (size_t)m->width * (size_t)m->height; p++)
        out->covered += m->positions[4 * p + 3] != 0.0;
    out->ideal =
        light_work_ideal_pairs(m->positions, m->width, m->height, view_proj, gs->lights, gs->light_count);
    return true;
}

/* The 8-bit error always; the linear one where the renderer has a linear output. */
static bool measure_error(bench_measure *m, bench_renderers *br, const gpu_scene *gs, bench_row *row)
{
    image img;
    if (!bench_renderers_read_target(br, &img))
        return false;
    row->have_error8 = image_compare(&img, &m->ref8, NULL, 1, &row->error8, NULL);
    image_destroy(&img);
    if (!isfinite(row->error8.psnr) || row->error8.psnr > BENCH_PSNR_CAP)
        row->error8.psnr = BENCH_PSNR_CAP;
    if (bench_read_linear(br, row->renderer, gs, m->hdr)) {
        bench_error_measure_hdr(m->hdr, m->ref_hdr, m->width, m->height, &row->error_hdr);
        row->have_error_hdr = true;
    }
    return true;
}

bool bench_measure_fill_row(bench_measure *m, bench_renderers *br, const gpu_scene *gs, bool want_error,
                            bench_row *row)
{
    bench_frame_work work;
    if (!bench_render_frame(br, row->renderer, gs, true, &work))
        return false;
    row->have_work = work.shaded >= 0;
    row->shaded = work.shaded;
    row->light_evals = (double)work.shaded * work.lights_per_px;
    row->work_ratio = row->ideal > 0 ? row->light_evals / (double)row->ideal : 0.0;
    return !want_error || measure_error(m, br, gs, row);
}
