/* bench_report.c - see bench_report.h. */
#include "bench_report.h"

#include "bench_gbuffer.h"
#include "bench_storage.h"
#include "bench_renderers.h"

#include "gbuffer.h"

#include "log.h"

#include <errno.h>
#include <math.h>
#include <string.h>

static const char *const status_names[] = {"measured", "few_frames", "skipped", "not_loaded"};

FILE *bench_report_open_tmp(const char *dir, const char *name, char *tmp, size_t size)
{
    snprintf(tmp, size, "%s/%s.tmp", dir, name);
    FILE *f = fopen(tmp, "w");
    if (!f)
        log_error("cannot write %s: %s", tmp, strerror(errno));
    return f;
}

bool bench_report_close_tmp(FILE *f, const char *tmp, const char *dir, const char *name)
{
    char final[1024];
    snprintf(final, sizeof final, "%s/%s", dir, name);
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
    "psnr_hdr,light_lists_ms,depth_prepass_ms,shading_ms,geometry_ms,lighting_ms,present_ms,pass_clock,note";

bool bench_report_write_csv(const bench_state *st)
{
    char tmp[1024];
    FILE *f = bench_report_open_tmp(st->opt.out_dir, "bench.csv", tmp, sizeof tmp);
    if (!f)
        return false;
    fprintf(f, "%s\n", csv_columns);
    for (int i = 0; i < st->row_count; i++) {
        const bench_row *r = &st->rows[i];
        bool measured = r->status == BENCH_STATUS_MEASURED || r->status == BENCH_STATUS_FEW_FRAMES;
        fprintf(f, "%s,%s,%s,%s,%d,%d,%.4g,%d,%d,%d,%d", r->sweep, r->scene, bench_renderer_name(r->renderer),
                r->own_lights ? "scene" : "generated", r->lights, r->active_lights, r->cutoff * 256.0,
                st->opt.width, st->opt.height, r->frames, r->warmup);
        put_num(f, r->status != BENCH_STATUS_NOT_LOADED, "%.3f", r->median_ms);
        put_num(f, measured, "%.3f", r->min_ms);
        put_num(f, measured, "%.3f", r->max_ms);
        put_num(f, r->median_ms > 0, "%.2f", 1000.0 / r->median_ms);
        fprintf(f, ",%s", status_names[r->status]);
        put_num(f, r->have_work, "%.0f", (double)r->shaded);
        put_num(f, true, "%.0f", (double)r->covered);
        put_num(f, true, "%.0f", (double)r->ideal);
        put_num(f, r->have_work, "%.0f", r->light_evals);
        put_num(f, r->have_work && r->ideal > 0, "%.4f", r->work_ratio);
        bool deferred = bench_renderer_is_deferred(r->renderer);
        put_num(f, deferred && r->gbuffer_bytes > 0, "%.0f", r->gbuffer_bytes);
        put_num(f, deferred, "%.0f", bench_renderer_gbuffer_naive_bytes());
        put_num(f, r->have_error8, "%.0f", r->error8.max_abs);
        put_num(f, r->have_error8, "%.5f", r->error8.mean_abs);
        put_num(f, r->have_error8, "%.2f", r->error8.psnr);
        put_num(f, r->have_error_hdr, "%.6g", r->error_hdr.max_abs);
        put_num(f, r->have_error_hdr, "%.6g", r->error_hdr.mean_abs);
        put_num(f, r->have_error_hdr, "%.2f", r->error_hdr.psnr);
        for (int k = 0; k < BENCH_PASSES; k++)
            put_num(f, measured && !isnan(r->pass_ms[k]), "%.3f", r->pass_ms[k]);
        fprintf(f, ",%s", st->pass_clock ? st->pass_clock : "NA");
        fprintf(f, ",%s\n", r->note); /* notes never hold commas */
    }
    return bench_report_close_tmp(f, tmp, st->opt.out_dir, "bench.csv");
}

/* The fastest forward and deferred rows of one light-sweep case. */
static void best_of_case(const bench_state *st, const char *scene_name, bool own, int lights,
                         const bench_row **fwd, const bench_row **def)
{
    *fwd = *def = NULL;
    for (int i = 0; i < st->opt.renderer_count; i++) {
        int r = st->opt.renderers[i];
        const bench_row *row = bench_state_find_row(st, "lights", scene_name, r, own, lights, -1);
        if (!row)
            continue;
        const bench_row **best = bench_renderer_is_deferred(r) ? def : fwd;
        if (!*best || row->median_ms < (*best)->median_ms)
            *best = row;
    }
}

void bench_report_time_cell(FILE *f, const bench_row *r)
{
    if (!r)
        fprintf(f, " – |");
    else if (r->status == BENCH_STATUS_NOT_LOADED)
        fprintf(f, " not loaded |");
    else
        fprintf(f, " %.1f%s |", r->median_ms,
                r->status == BENCH_STATUS_SKIPPED      ? "*"
                : r->status == BENCH_STATUS_FEW_FRAMES ? "†"
                                                       : "");
}

static int volumes_renderer_selected(const bench_state *st)
{
    for (int i = 0; i < st->opt.renderer_count; i++)
        if (bench_renderer_uses_volumes(st->opt.renderers[i]))
            return st->opt.renderers[i];
    return -1;
}

static int stencil_renderer_selected(const bench_state *st)
{
    for (int i = 0; i < st->opt.renderer_count; i++)
        if (bench_renderer_uses_stencil(st->opt.renderers[i]))
            return st->opt.renderers[i];
    return -1;
}

static int tiled_renderer_selected(const bench_state *st)
{
    for (int i = 0; i < st->opt.renderer_count; i++)
        if (bench_renderer_uses_tiles(st->opt.renderers[i]))
            return st->opt.renderers[i];
    return -1;
}

/* Shaded pixels / ideal pairs of renderer `r` on the default scene and the city, at 1024 generated
 * lights and at the city's own: one row each, met when at most `bound`. */
static void write_work_targets(FILE *f, const bench_state *st, int renderer, double bound, const char *what,
                               int *rows)
{
    const char *work_scenes[] = {"default", "city"};
    for (int s = 0; s < 2 && renderer >= 0; s++) {
        for (int i = 0; i < st->row_count; i++) {
            const bench_row *r = &st->rows[i];
            if (strcmp(r->sweep, "lights") || strcmp(r->scene, work_scenes[s]) || r->renderer != renderer ||
                !r->have_work)
                continue;
            bool at_target =
                (r->own_lights && strcmp(r->scene, "city") == 0) || (!r->own_lights && r->lights == 1024);
            if (!at_target)
                continue;
            if ((*rows)++ == 0)
                fprintf(f, "| target | measured | result |\n|---|---|---|\n");
            fprintf(f, "| %s, %d lights%s: %s shade ≤ %.1f× the ideal pairs | %.2f× (%lld of %lld) | %s |\n",
                    r->scene, r->lights, r->own_lights ? " (scene's)" : "", what, bound, r->work_ratio,
                    r->shaded, r->ideal, r->work_ratio <= bound ? "met" : "missed");
        }
    }
}

/* What the speed-up rows say, in one sentence a learner can take away. */
typedef struct speedups {
    int rows, met;
    double lo, hi;
} speedups;

static void write_conclusion(FILE *f, const speedups *sp, int rows)
{
    if (rows == 0) {
        fprintf(f, "This run's sweep holds none of the targets' cases (1,024 generated lights, or the city "
                   "with its own lights), so there is nothing to check; the default sweep has them.\n\n");
        return;
    }
    fprintf(f, "\n");
    if (sp->rows > 0)
        fprintf(f, "**In one sentence:** at 1,024 lights the light volumes drew a frame %.1f× to %.1f× faster "
                   "than the best forward renderer on %d scene(s), and reached the 20× target on %d of them.\n\n",
                sp->lo, sp->hi, sp->rows, sp->met);
}

static void write_targets(FILE *f, const bench_state *st)
{
    const bench_options *o = &st->opt;
    int vol = volumes_renderer_selected(st), rows = 0;
    speedups sp = {0, 0, 1e300, 0};
    fprintf(f, "## Targets\n\n");
    /* 1. light volumes >= 20x the best forward at 1024 lights (800x800) */
    for (int s = 0; s < o->scene_count; s++) {
        char label[NAME_MAX_LEN];
        bench_options_label_scene(o->scenes[s], label, sizeof label);
        const bench_row *fwd, *def;
        best_of_case(st, label, false, 1024, &fwd, &def);
        const bench_row *v =
            vol >= 0 ? bench_state_find_row(st, "lights", label, vol, false, 1024, -1) : NULL;
        if (!fwd || !v)
            continue;
        double speedup = fwd->median_ms / v->median_ms;
        if (rows++ == 0)
            fprintf(f, "| target | measured | result |\n|---|---|---|\n");
        sp.rows++, sp.met += speedup >= 20;
        sp.lo = fmin(sp.lo, speedup), sp.hi = fmax(sp.hi, speedup);
        fprintf(f,
                "| %s, 1024 lights: light volumes ≥ 20× the best forward (%s) | %.1f× (%.1f vs %.1f ms%s) | "
                "%s |\n",
                label, bench_renderer_name(fwd->renderer), speedup, v->median_ms, fwd->median_ms,
                fwd->status == BENCH_STATUS_SKIPPED ? ", forward extrapolated" : "",
                speedup >= 20 ? "met" : "missed");
    }
    /* 2. work ratio <= 1.5 on default and city (chapter 07); <= 1.1 with the stencil (chapter 08) */
    write_work_targets(f, st, vol, 1.5, "light volumes", &rows);
    write_work_targets(f, st, stencil_renderer_selected(st), 1.1, "stencil light volumes", &rows);
    /* chapter 10: light-loop iterations <= 3x the ideal pairs */
    write_work_targets(f, st, tiled_renderer_selected(st), 3.0, "tiled light lists", &rows);
    /* 3. city at its own 757 lights >= 10 fps */
    const bench_row *city = vol >= 0 ? bench_state_find_row(st, "lights", "city", vol, true, 0, -1) : NULL;
    if (city && rows++ == 0)
        fprintf(f, "| target | measured | result |\n|---|---|---|\n");
    if (city)
        fprintf(f, "| city, its %d lights, %dx%d: light volumes ≥ 10 fps | %.1f fps (%.1f ms) | %s |\n",
                city->lights, o->width, o->height, 1000.0 / city->median_ms, city->median_ms,
                1000.0 / city->median_ms >= 10 ? "met" : "missed");
    write_conclusion(f, &sp, rows);
}

/* Whether --renderers holds a forward and a deferred renderer, the two sides a crossover needs. */
static bool both_sides_selected(const bench_options *o)
{
    bool fwd = false, def = false;
    for (int i = 0; i < o->renderer_count; i++)
        *(bench_renderer_is_deferred(o->renderers[i]) ? &def : &fwd) = true;
    return fwd && def;
}

static void write_crossover(FILE *f, const bench_state *st)
{
    const bench_options *o = &st->opt;
    if (!both_sides_selected(o)) {
        fprintf(f, "## Crossover\n\nNone to find: --renderers holds only %s renderers; the crossover "
                   "needs a forward and a deferred one.\n\n",
                o->renderer_count > 0 && bench_renderer_is_deferred(o->renderers[0]) ? "deferred" : "forward");
        return;
    }
    fprintf(
        f, "## Crossover\n\nSmallest generated light count at which the fastest deferred renderer beats the "
           "fastest forward one, and the speed-up (best forward ms / best deferred ms) at 1024 lights and "
           "at the scene's own lights.\n\n"
           "| scene | crossover (lights) | speed-up at 1024 | speed-up at own lights |\n|---|---|---|---|\n");
    for (int s = 0; s < o->scene_count; s++) {
        char label[NAME_MAX_LEN];
        bench_options_label_scene(o->scenes[s], label, sizeof label);
        int crossover = -1;
        for (int k = 0; k < o->light_list_count && crossover < 0; k++) {
            const bench_row *fwd, *def;
            if (o->lights[k] == LIGHTS_OWN)
                continue;
            best_of_case(st, label, false, o->lights[k], &fwd, &def);
            if (fwd && def && def->median_ms < fwd->median_ms)
                crossover = o->lights[k];
        }
        fprintf(f, "| %s | %s", label, crossover >= 0 ? "" : "none in the sweep");
        if (crossover >= 0)
            fprintf(f, "%d", crossover);
        fprintf(f, " |");
        const bench_row *fwd, *def;
        best_of_case(st, label, false, 1024, &fwd, &def);
        if (fwd && def)
            fprintf(f, " %.1f× |", fwd->median_ms / def->median_ms);
        else
            fprintf(f, " – |");
        best_of_case(st, label, true, 0, &fwd, &def);
        if (fwd && def)
            fprintf(f, " %.1f× (%d lights) |\n", fwd->median_ms / def->median_ms, fwd->lights);
        else
            fprintf(f, " – |\n");
    }
    fprintf(f, "\n");
}

static void write_intro(FILE *f, const bench_state *st)
{
    const bench_options *o = &st->opt;
    fprintf(f, "# Forward against deferred: benchmark results\n\n");
    fprintf(f, "- machine: %s, %d logical cores\n- GL: %s, %s\n", st->cpu, st->cores, st->gl_renderer,
            st->gl_version);
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
            "- G-buffer: %d bytes per pixel, layout %s (naive layout with world position: %d)%s\n\n",
            bench_renderer_gbuffer_bytes(), gbuffer_layout_name(gbuffer_default_layout()),
            bench_renderer_gbuffer_naive_bytes(),
            bench_gbuffer_enabled() ? "; the other layouts: \"G-buffer layouts\" below" : "");
}

bool bench_report_write_part_md(const bench_state *st, const char *name, const char *title,
                                void (*write_section)(FILE *f, const bench_state *st))
{
    char tmp[1024];
    FILE *f = bench_report_open_tmp(st->opt.out_dir, name, tmp, sizeof tmp);
    if (!f)
        return false;
    fprintf(f, "# %s: benchmark results\n\n- machine: %s, %d logical cores\n- GL: %s, %s\n", title, st->cpu,
            st->cores, st->gl_renderer, st->gl_version);
    write_section(f, st);
    return bench_report_close_tmp(f, tmp, st->opt.out_dir, name);
}

static void write_times(FILE *f, const bench_state *st)
{
    const bench_options *o = &st->opt;
    fprintf(f, "## Median ms per frame\n\n");
    for (int s = 0; s < o->scene_count; s++) {
        char label[NAME_MAX_LEN];
        bench_options_label_scene(o->scenes[s], label, sizeof label);
        fprintf(f, "### %s\n\n| lights |", label);
        for (int i = 0; i < o->renderer_count; i++)
            fprintf(f, " %s |", bench_renderer_name(o->renderers[i]));
        fprintf(f, "\n|---|");
        for (int i = 0; i < o->renderer_count; i++)
            fprintf(f, "---|");
        fprintf(f, "\n");
        for (int k = 0; k < o->light_list_count; k++) {
            bool own = o->lights[k] == LIGHTS_OWN;
            const bench_row *any =
                bench_state_find_row(st, "lights", label, o->renderers[0], own, o->lights[k], -1);
            if (!any)
                continue;
            fprintf(f, "| %d%s |", any->lights, own ? " (scene's)" : "");
            for (int i = 0; i < o->renderer_count; i++)
                bench_report_time_cell(f,
                          bench_state_find_row(st, "lights", label, o->renderers[i], own, o->lights[k], -1));
            fprintf(f, "\n");
        }
        fprintf(f, "\n");
    }
}

/* The cells that name a light-sweep row: scene, lights, renderer. */
static void write_row_head(FILE *f, const bench_row *r)
{
    fprintf(f, "| %s | %d%s | %s |", r->scene, r->lights, r->own_lights ? " (scene's)" : "",
            bench_renderer_name(r->renderer));
}

/* No ideal work (no light reaches a visible surface): no ratio. */
static void write_ratio_cell(FILE *f, const bench_row *r)
{
    if (r->have_work && r->ideal > 0)
        fprintf(f, " %.2f |", r->work_ratio);
    else
        fprintf(f, " – |");
}

static void write_work_row(FILE *f, const bench_row *r)
{
    write_row_head(f, r);
    fprintf(f, " %lld | %.4g | %lld |", r->shaded, r->light_evals, r->ideal);
    write_ratio_cell(f, r);
    fputc('\n', f);
}

static void write_error_row(FILE *f, const bench_row *r)
{
    write_row_head(f, r);
    fprintf(f, " %d | %.4f | %.1f |", r->error8.max_abs, r->error8.mean_abs, r->error8.psnr);
    if (r->have_error_hdr)
        fprintf(f, " %.4g | %.3g | %.1f |\n", r->error_hdr.max_abs, r->error_hdr.mean_abs, r->error_hdr.psnr);
    else
        fprintf(f, " NA | NA | NA |\n");
}

static const char *const work_heading =
    "## Lighting work\n\nshaded = GL_SAMPLES_PASSED of the lighting pass; evaluations = shaded × "
    "lights looped per fragment (forward with lists: the mean list length, an estimate); ideal = "
    "(pixel, light) pairs whose visible surface lies inside the light's radius, counted on the CPU "
    "from the depth buffer.\n\n"
    "| scene | lights | renderer | shaded | evaluations | ideal | evaluations / ideal |\n"
    "|---|---|---|---|---|---|---|\n";

static const char *const error_heading =
    "\n## Error against the exact reference (cut-off 5/256)\n\n8-bit: display-encoded output, 0..255 "
    "per channel. HDR: linear radiance, PSNR with peak 1.0 (NA: the renderer has no linear output).\n\n"
    "| scene | lights | renderer | max 8-bit | mean 8-bit | PSNR 8-bit dB | max HDR | mean HDR | PSNR "
    "HDR dB |\n"
    "|---|---|---|---|---|---|---|---|---|\n";

/* The work table, or the error table: each lists the light-sweep rows that have its values. */
static void write_light_table(FILE *f, const bench_state *st, bool errors)
{
    fputs(errors ? error_heading : work_heading, f);
    for (int i = 0; i < st->row_count; i++) {
        const bench_row *r = &st->rows[i];
        if (strcmp(r->sweep, "lights") != 0)
            continue;
        if (errors && r->have_error8)
            write_error_row(f, r);
        else if (!errors && r->have_work)
            write_work_row(f, r);
    }
}

static void write_cutoff(FILE *f, const bench_state *st)
{
    const bench_options *o = &st->opt;
    if (o->cutoff_count == 0)
        return; /* --cutoffs none */
    fprintf(f,
            "\n## Speed against error: the cut-off (%s, %d lights)\n\n"
            "| cut-off (/256) | renderer | active lights | ms | evaluations / ideal | mean 8-bit | PSNR "
            "8-bit dB | "
            "mean HDR | PSNR HDR dB |\n|---|---|---|---|---|---|---|---|---|\n",
            o->cutoff_scene, o->cutoff_lights);
    for (int i = 0; i < st->row_count; i++) {
        const bench_row *r = &st->rows[i];
        if (strcmp(r->sweep, "cutoff"))
            continue;
        fprintf(f, "| %.3g | %s | %d | ", r->cutoff * 256.0, bench_renderer_name(r->renderer),
                r->active_lights);
        bench_report_time_cell(f, r);
        write_ratio_cell(f, r);
        if (r->have_error8)
            fprintf(f, " %.4f | %.1f |", r->error8.mean_abs, r->error8.psnr);
        else
            fprintf(f, " NA | NA |");
        if (r->have_error_hdr)
            fprintf(f, " %.3g | %.1f |\n", r->error_hdr.mean_abs, r->error_hdr.psnr);
        else
            fprintf(f, " NA | NA |\n");
    }
}

bool bench_report_write_md(const bench_state *st)
{
    char tmp[1024];
    FILE *f = bench_report_open_tmp(st->opt.out_dir, "bench.md", tmp, sizeof tmp);
    if (!f)
        return false;
    write_intro(f, st);
    write_targets(f, st);
    write_crossover(f, st);
    write_times(f, st);
    write_light_table(f, st, false);
    write_light_table(f, st, true);
    write_cutoff(f, st);
    bench_report_write_pbr(f, st);
    if (bench_gbuffer_enabled())
        bench_gbuffer_write_md(f, st);
    if (bench_storage_enabled())
        bench_storage_write_md(f, st);
    return bench_report_close_tmp(f, tmp, st->opt.out_dir, "bench.md");
}
