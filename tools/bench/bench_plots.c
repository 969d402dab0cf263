/* bench_plots.c - see bench_plots.h. */
#include "bench_plots.h"

#include "bench_renderers.h"
#include "bench_report.h"

#include "log.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Each renderer its own colour and mark, the same in both plots and whichever renderers a run
 * selects (indexed by the renderer, not by its place in --renderers): eleven colours a reader tells
 * apart (no pale yellow), and filled shapes and crosses, so no two renderers share both. An
 * extrapolated time gets a large ring around its mark instead. */
static const char *const renderer_colours[] = {"#e41a1c", "#377eb8", "#4daf4a", "#984ea3", "#ff7f00", "#a65628",
                                               "#f781bf", "#000000", "#17becf", "#808080", "#1a237e"};
static const int renderer_points[] = {5, 7, 9, 11, 13, 15, 1, 2, 3, 5, 7};
#define STYLES ((int)(sizeof renderer_points / sizeof renderer_points[0]))

/* "lc rgb '#e41a1c' pt 5" for renderer r; `ring`: the mark of an extrapolated time. */
static const char *style_of(int r, bool ring)
{
    static char out[64];
    int k = r % STYLES;
    if (ring)
        snprintf(out, sizeof out, "lc rgb '%s' pt 6 ps 2.5", renderer_colours[k]);
    else
        snprintf(out, sizeof out, "lc rgb '%s' pt %d", renderer_colours[k], renderer_points[k]);
    return out;
}

/* One block per (scene, renderer): lights, ms, measured (1) or extrapolated (0). The scene's own
 * lights are another light set, not a point of the generated sweep: left out. */
static void write_time_data(FILE *f, const bench_state *st)
{
    const bench_options *o = &st->opt;
    for (int s = 0; s < o->scene_count; s++) {
        char label[NAME_MAX_LEN];
        bench_options_label_scene(o->scenes[s], label, sizeof label);
        for (int i = 0; i < o->renderer_count; i++) {
            fprintf(f, "$t_%d_%d << EOD\n", s, i);
            for (int k = 0; k < o->light_list_count; k++) {
                if (o->lights[k] == LIGHTS_OWN)
                    continue;
                const bench_row *r =
                    bench_state_find_row(st, "lights", label, o->renderers[i], false, o->lights[k], -1);
                if (r && r->median_ms > 0)
                    fprintf(f, "%d %.4f %d\n", r->lights, r->median_ms, r->status != BENCH_STATUS_SKIPPED);
            }
            fprintf(f, "EOD\n");
        }
    }
}

static void write_time_plots(FILE *f, const bench_state *st)
{
    const bench_options *o = &st->opt;
    fprintf(f, "set output '%s/time_vs_lights.png.tmp'\n", o->out_dir);
    int cols = o->scene_count <= 1 ? 1 : o->scene_count <= 4 ? 2 : 3;
    int rows_n = (o->scene_count + cols - 1) / cols;
    fprintf(f,
            "set multiplot layout %d,%d title 'Median ms per frame against light count, %dx%d, %s (log-log; "
            "ringed marks: extrapolated)'\n",
            rows_n, cols, o->width, o->height, st->gl_renderer);
    fprintf(f,
            "set logscale xy\nset grid\nset key top left\nset xlabel 'lights'\nset ylabel 'ms per frame'\n");
    for (int s = 0; s < o->scene_count; s++) {
        char label[NAME_MAX_LEN];
        bench_options_label_scene(o->scenes[s], label, sizeof label);
        fprintf(f, "set title '%s'\nplot ", label);
        for (int i = 0; i < o->renderer_count; i++) {
            int r = o->renderers[i];
            fprintf(f, "%s$t_%d_%d using 1:(($3)>0?$2:NaN) with linespoints %s title '%s', ",
                    i ? ", \\\n     " : "", s, i, style_of(r, false), bench_renderer_name(r));
            /* a line takes a colour, no point type (gnuplot warns) */
            fprintf(f, "$t_%d_%d using 1:2 with lines lc rgb '%s' notitle, ", s, i, renderer_colours[r % STYLES]);
            fprintf(f, "$t_%d_%d using 1:(($3)>0?NaN:$2) with points %s notitle, ", s, i, style_of(r, true));
            fprintf(f, "$t_%d_%d using 1:(($3)>0?NaN:$2) with points %s notitle", s, i, style_of(r, false));
        }
        fprintf(f, "\n");
    }
    fprintf(f, "unset multiplot\n");
}

/* Speed against error: x = mean 8-bit error (and HDR), y = ms, one line per renderer. The floors
 * keep an exact renderer's zero error on the log axis. */
static void write_error_data(FILE *f, const bench_state *st)
{
    const bench_options *o = &st->opt;
    for (int i = 0; i < o->renderer_count; i++) {
        fprintf(f, "$e_%d << EOD\n", i);
        for (int k = 0; k < st->row_count; k++) {
            const bench_row *r = &st->rows[k];
            if (strcmp(r->sweep, "cutoff") || r->renderer != o->renderers[i] || !r->have_error8)
                continue;
            fprintf(f, "%.6g %.4f %.6g %.4g\n", fmax(r->error8.mean_abs, 1e-4), r->median_ms,
                    r->have_error_hdr ? fmax(r->error_hdr.mean_abs, 1e-7) : NAN, r->cutoff * 256.0);
        }
        fprintf(f, "EOD\n");
    }
}

static void write_error_plots(FILE *f, const bench_state *st)
{
    const bench_options *o = &st->opt;
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
            if (!bench_renderer_in_cutoff_sweep(o->renderers[i]))
                continue;
            int r = o->renderers[i];
            fprintf(f, "%s$e_%d using %d:2 with linespoints %s title '%s', ", first ? "" : ", \\\n     ", i, x,
                    style_of(r, false), bench_renderer_name(r));
            fprintf(f, "$e_%d using %d:2:(sprintf('%%g', $4)) with labels offset 0.8,0.6 textcolor rgb '%s' notitle",
                    i, x, renderer_colours[r % STYLES]);
            first = false;
        }
        fprintf(f, "\n");
    }
    fprintf(f, "unset multiplot\n");
}

static bool write_plot_script(const bench_state *st, const char *term)
{
    char tmp[1024];
    FILE *f = bench_report_open_tmp(st->opt.out_dir, "bench_plots.gp", tmp, sizeof tmp);
    if (!f)
        return false;
    fprintf(f, "# Generated by bench: plots of bench.csv. Run from the output folder's parent.\n");
    fprintf(f, "set terminal %s size 1500,900 font ',10'\nset datafile missing 'NA'\n", term);
    write_time_data(f, st);
    write_time_plots(f, st);
    if (st->opt.cutoff_count > 0) { /* --cutoffs none: no error plot */
        write_error_data(f, st);
        write_error_plots(f, st);
    }
    return bench_report_close_tmp(f, tmp, st->opt.out_dir, "bench_plots.gp");
}

bool bench_plots_make(const bench_state *st, bool *drawn)
{
    *drawn = false;
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
    if (!write_plot_script(st, cairo ? "pngcairo" : "png"))
        return false;
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "gnuplot '%s/bench_plots.gp'", st->opt.out_dir);
    bool plotted = system(cmd) == 0;
    if (!plotted)
        log_error("gnuplot failed on %s/bench_plots.gp", st->opt.out_dir);
    const char *plots[] = {"time_vs_lights.png", "speed_vs_error.png"};
    for (int i = 0; i < (st->opt.cutoff_count > 0 ? 2 : 1); i++) {
        char tmp[1024], final[1024];
        snprintf(tmp, sizeof tmp, "%s/%s.tmp", st->opt.out_dir, plots[i]);
        snprintf(final, sizeof final, "%s/%s", st->opt.out_dir, plots[i]);
        if (!plotted) {
            remove(tmp);
            continue;
        }
        if (rename(tmp, final) != 0) {
            log_error("cannot rename %s to %s: %s", tmp, final, strerror(errno));
            return false;
        }
    }
    *drawn = plotted;
    return plotted;
}
