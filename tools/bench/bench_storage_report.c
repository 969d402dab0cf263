/* bench_storage_report.c - the storage table's CSV, its section of bench.md and its targets
 * (bench_storage.h). */
#include "bench_storage.h"
#include "bench_storage_rows.h"

#include "bench_report.h"

#include <math.h>
#include <string.h>

#define R bench_storage_results_now

/* The targets of docs/16_visibility_buffer.md. */
#define TARGET_VIS_BYTES_PER_SAMPLE 8.0
#define TARGET_FIRST_PASS_SPEEDUP 1.5

static void put(FILE *f, bool have, const char *fmt, double v)
{
    fputc(',', f);
    if (have && isfinite(v))
        fprintf(f, fmt, v);
    else
        fputs("NA", f);
}

static int scene_index(const char *name)
{
    for (int si = 0; si < STORAGE_SCENES; si++)
        if (strcmp(bench_storage_scene_names[si], name) == 0)
            return si;
    return -1;
}

static int renderer_index(const char *name)
{
    for (int ri = 0; ri < STORAGE_RENDERERS; ri++)
        if (strcmp(bench_storage_renderers[ri].name, name) == 0)
            return ri;
    return -1;
}

/* The first pass's bytes per sample that passed: what one visible sample stores, from the formats
 * the pass drew into (counted bytes over counted samples). */
static double stored_per_sample(const storage_row *r, int ri)
{
    const storage_pass *p = bench_storage_find_pass(r, bench_storage_renderers[ri].first);
    return p && p->samples_per_px > 0 ? p->written_per_px / p->samples_per_px : NAN;
}

static double pass_ms(const storage_row *r, const char *pass)
{
    const storage_pass *p = r->measured ? bench_storage_find_pass(r, pass) : NULL;
    return p ? p->ms : NAN;
}

static double first_pass_ms(const storage_row *r, int ri)
{
    return pass_ms(r, bench_storage_renderers[ri].first);
}

/* A timing-only row (bench_storage_timings): its passes' times and its frame's, bytes and error NA. */
static void write_timing_csv(FILE *f, const bench_state *st, int si, const storage_row *r)
{
    const char *scene_name = bench_storage_scene_names[si];
    for (int i = 0; r->measured && i < r->pass_count; i++) {
        fprintf(f, "%s,%d,%s,%d,%s,%d,%d,%d,NA,NA,NA,NA,NA,NA", scene_name, R.scene_lights[si], r->renderer,
                r->samples, r->passes[i].name, st->opt.width, st->opt.height, r->frames);
        put(f, true, "%.3f", r->passes[i].ms);
        fprintf(f, ",NA,NA,NA,NA,%s,%s\n", R.pass_clock, r->note);
    }
    fprintf(f, "%s,%d,%s,%d,total,%d,%d,%d,NA,NA,NA,NA,NA,NA", scene_name, R.scene_lights[si], r->renderer,
            r->samples, st->opt.width, st->opt.height, r->frames);
    put(f, r->measured, "%.3f", r->frame_ms);
    fprintf(f, ",NA,NA,NA,NA,%s,%s\n", R.pass_clock, r->note);
}

bool bench_storage_write_csv(const bench_state *st)
{
    char tmp[1024];
    FILE *f = bench_report_open_tmp(st->opt.out_dir, "bench_storage.csv", tmp, sizeof tmp);
    if (!f)
        return false;
    fprintf(f, "scene,lights,renderer,samples,pass,width,height,frames,draws,samples_passed_per_px,"
               "written_bytes_per_px,read_bytes_per_px,scene_data_bytes_per_px,stored_bytes_per_sample,ms,"
               "max_abs_8bit,mean_abs_8bit,psnr_8bit,pixels_over_1,pass_clock,note\n");
    for (int si = 0; si < bench_storage_scene_count(); si++)
        for (int ri = 0; R.scene_done[si] && ri < STORAGE_RENDERERS; ri++)
            for (int k = 0; k < STORAGE_SAMPLE_COUNTS; k++) {
                const storage_row *r = &R.rows[si][ri][k];
                const char *scene_name = bench_storage_scene_names[si];
                for (int i = 0; r->measured && i < r->pass_count; i++) {
                    const storage_pass *p = &r->passes[i];
                    fprintf(f, "%s,%d,%s,%d,%s,%d,%d,%d,%d", scene_name, R.scene_lights[si], r->renderer, r->samples,
                            p->name, st->opt.width, st->opt.height, r->frames, p->draws);
                    put(f, true, "%.4f", p->samples_per_px);
                    put(f, true, "%.4f", p->written_per_px);
                    put(f, true, "%.4f", p->read_per_px);
                    put(f, false, "%f", 0);
                    put(f, p->samples_per_px > 0, "%.4f", p->written_per_px / p->samples_per_px);
                    put(f, true, "%.3f", p->ms);
                    fprintf(f, ",NA,NA,NA,NA,%s,\n", R.pass_clock);
                }
                bool m = r->measured;
                fprintf(f, "%s,%d,%s,%d,total,%d,%d,%d,NA,NA", scene_name, R.scene_lights[si],
                        bench_storage_renderers[ri].name, bench_storage_samples[k], st->opt.width, st->opt.height,
                        r->frames);
                put(f, m, "%.4f", r->written_per_px);
                put(f, m, "%.4f", r->read_per_px);
                put(f, m, "%.4f", r->scene_read_per_px);
                put(f, m, "%.4f", stored_per_sample(r, ri));
                put(f, m, "%.3f", r->frame_ms);
                bool e = m && r->have_error;
                put(f, e, "%.0f", r->error8.max_abs);
                put(f, e, "%.5f", r->error8.mean_abs);
                put(f, e, "%.2f", r->error8.psnr);
                put(f, e, "%.0f", (double)r->error8.over);
                fprintf(f, ",%s,%s\n", R.pass_clock, r->note);
            }
    for (int si = 0; si < bench_storage_scene_count(); si++)
        for (int ti = 0; R.scene_done[si] && ti < STORAGE_TIMINGS; ti++)
            for (int k = 0; k < STORAGE_SAMPLE_COUNTS; k++)
                write_timing_csv(f, st, si, &R.timings[si][ti][k]);
    return bench_report_close_tmp(f, tmp, st->opt.out_dir, "bench_storage.csv");
}

/* "thin pass 1.2, light assignment 0.3, ..." in the order the passes ran. */
static void write_passes(FILE *f, const storage_row *r)
{
    for (int i = 0; i < r->pass_count; i++)
        fprintf(f, "%s%s %.1f", i ? ", " : "", r->passes[i].name, r->passes[i].ms);
}

static void write_scene_table(FILE *f, int si)
{
    fprintf(f, "\n### %s (%d lights)\n\n"
               "| renderer | samples | stores B/sample | writes B/px | reads B/px | scene data B/px | passes, ms | "
               "frame ms | 8-bit error: max, mean, px > 1 |\n|---|---|---|---|---|---|---|---|---|\n",
            bench_storage_scene_names[si], R.scene_lights[si]);
    for (int ri = 0; ri < STORAGE_RENDERERS; ri++)
        for (int k = 0; k < STORAGE_SAMPLE_COUNTS; k++) {
            const storage_row *r = &R.rows[si][ri][k];
            fprintf(f, "| %s | %d |", bench_storage_renderers[ri].name, bench_storage_samples[k]);
            if (!r->measured) {
                fprintf(f, " %s | | | | | | |\n", r->note);
                continue;
            }
            fprintf(f, " %.1f | %.1f | %.1f |", stored_per_sample(r, ri), r->written_per_px, r->read_per_px);
            if (r->scene_read_per_px > 0)
                fprintf(f, " %.0f |", r->scene_read_per_px);
            else
                fprintf(f, " – |");
            fputc(' ', f);
            write_passes(f, r);
            fprintf(f, " | %.1f |", r->frame_ms);
            if (r->have_error)
                fprintf(f, " %d, %.3f, %.2f %% |\n", r->error8.max_abs, r->error8.mean_abs, 100.0 * r->error8.frac_over);
            else
                fprintf(f, " NA |\n");
        }
}

/* A time in a table cell, or a dash where the row was not measured. */
static void put_ms_cell(FILE *f, double ms)
{
    if (isfinite(ms))
        fprintf(f, " %.1f |", ms);
    else
        fprintf(f, " – |");
}

/* The first passes side by side, per scene and sample count: the compact G-buffer's geometry pass,
 * the visibility pass, and the visibility pass cut down (timing-only rows, --vis-pass). */
static void write_vis_timings(FILE *f)
{
    const int vis = renderer_index("visibility-buffer"), compact = renderer_index("gbuffer-compact");
    fprintf(f, "\n### What the visibility pass's time is made of\n\n"
               "The first pass's median ms, from the rows above (the compact G-buffer's geometry pass: chapter 11, "
               "at 4 samples chapter 13; the visibility pass: chapter 16), beside chapter 16's visibility pass cut "
               "down, timing only (its pictures are wrong by design: no bytes, no error): *without "
               "gl_PrimitiveID* (`--vis-pass no-primitive-id`) writes the object's triangle 0 instead of "
               "`gl_PrimitiveID`, *depth only* (`--vis-pass depth-only`) writes no id, depth alone. Each "
               "is one more run of the chapter, after the table's rows.\n\n"
               "| scene | samples | compact G-buffer: geometry | visibility pass | without gl_PrimitiveID | "
               "depth only |\n|---|---|---|---|---|---|\n");
    for (int si = 0; si < bench_storage_scene_count(); si++)
        for (int k = 0; R.scene_done[si] && k < STORAGE_SAMPLE_COUNTS; k++) {
            fprintf(f, "| %s | %d |", bench_storage_scene_names[si], bench_storage_samples[k]);
            put_ms_cell(f, first_pass_ms(&R.rows[si][compact][k], compact));
            put_ms_cell(f, first_pass_ms(&R.rows[si][vis][k], vis));
            for (int ti = 0; ti < STORAGE_TIMINGS; ti++)
                put_ms_cell(f, pass_ms(&R.timings[si][ti][k], bench_storage_timings[ti].first));
            fputc('\n', f);
        }
}

/* The bunnies' time target again without gl_PrimitiveID (the timing-only rows), and depth only. */
static void write_timings_target(FILE *f, int bunnies, int k, const storage_row *g, int compact)
{
    const storage_row *no_id = &R.timings[bunnies][STORAGE_TIMING_NO_PRIMITIVE_ID][k],
                      *depth = &R.timings[bunnies][STORAGE_TIMING_DEPTH_ONLY][k];
    const char *first = bench_storage_timings[STORAGE_TIMING_NO_PRIMITIVE_ID].first;
    const double ms = pass_ms(no_id, first), ratio = first_pass_ms(g, compact) / ms;
    if (isfinite(ms))
        fprintf(f, "; without gl_PrimitiveID (`--vis-pass no-primitive-id`, timing only) the pass takes %.1f ms, "
                   "%.2fx faster than the compact geometry pass: %s",
                ms, ratio, ratio >= TARGET_FIRST_PASS_SPEEDUP ? "met" : "NOT met");
    else
        fprintf(f, "; without gl_PrimitiveID: not measured (%s)", no_id->note);
    const double depth_ms = pass_ms(depth, bench_storage_timings[STORAGE_TIMING_DEPTH_ONLY].first);
    if (isfinite(depth_ms))
        fprintf(f, "; depth only %.1f ms", depth_ms);
    fputc('\n', f);
}

/* The two targets, from the rows measured; "not measured" with the reason otherwise. */
static void write_targets(FILE *f)
{
    const int vis = renderer_index("visibility-buffer"), compact = renderer_index("gbuffer-compact");
    fprintf(f, "\nTargets:\n\n");
    for (int k = 0; k < STORAGE_SAMPLE_COUNTS; k++) {
        double worst = -1.0;
        const char *note = "";
        for (int si = 0; si < bench_storage_scene_count(); si++) {
            const storage_row *r = &R.rows[si][vis][k];
            if (r->measured && isfinite(stored_per_sample(r, vis)))
                worst = fmax(worst, stored_per_sample(r, vis));
            else if (R.scene_done[si])
                note = r->note;
        }
        if (worst >= 0.0)
            fprintf(f, "- the visibility buffer stores at most %.0f bytes per sample, depth included, at %d sample(s): "
                       "measured %.1f (the most of the scenes measured): %s\n",
                    TARGET_VIS_BYTES_PER_SAMPLE, bench_storage_samples[k], worst,
                    worst <= TARGET_VIS_BYTES_PER_SAMPLE ? "met" : "NOT met");
        else
            fprintf(f, "- the visibility buffer stores at most %.0f bytes per sample at %d sample(s): not measured (%s)\n",
                    TARGET_VIS_BYTES_PER_SAMPLE, bench_storage_samples[k], *note ? note : "no scene measured");
    }
    const int bunnies = scene_index("bunnies"), k4 = 1;
    const storage_row *v = &R.rows[bunnies][vis][k4], *g = &R.rows[bunnies][compact][k4];
    if (bunnies < bench_storage_scene_count() && R.scene_done[bunnies] && v->measured && g->measured) {
        double ratio = first_pass_ms(g, compact) / first_pass_ms(v, vis);
        fprintf(f, "- on the bunnies at 4 samples, the visibility pass at least %.1fx faster than the compact "
                   "G-buffer's geometry pass: %.1f ms against %.1f ms, %.2fx: %s",
                TARGET_FIRST_PASS_SPEEDUP, first_pass_ms(v, vis), first_pass_ms(g, compact), ratio,
                ratio >= TARGET_FIRST_PASS_SPEEDUP ? "met" : "NOT met");
        write_timings_target(f, bunnies, k4, g, compact);
    } else {
        fprintf(f, "- on the bunnies at 4 samples, the visibility pass at least %.1fx faster than the compact "
                   "G-buffer's geometry pass: not measured (%s)\n",
                TARGET_FIRST_PASS_SPEEDUP,
                bunnies >= bench_storage_scene_count() ? "the bunnies are not in this sweep"
                : !v->measured                          ? v->note
                                                        : g->note);
    }
}

void bench_storage_write_md(FILE *f, const bench_state *st)
{
    const bench_options *o = &st->opt;
    if (!R.ran)
        return; /* --gbuffer-sweep only */
    fprintf(f,
            "\n## What to store per pixel\n\n"
            "Each renderer is its chapter, opened with its arguments (chapters 00, 11, 13, 15, 16), on each "
            "scene with its own lights at cut-off 5/256, %dx%d; %d warm-up + %d timed frames per row, one row "
            "after another; passes on the %s clock (medians). Bytes are counted in one more frame "
            "(common/gl/draw_count.h): every draw's GL_SAMPLES_PASSED times what one sample writes in that "
            "draw's state (the formats of the attachments drawn, depth when depth writes are on, stencil when "
            "it is written), and the bytes of every 2D texture its shaders sample, once per fragment (an "
            "upper bound where a shader stops early), plus what blending reads back; divided by the "
            "pixels. Depth-test reads, compute passes and blits are not counted. *Stores B/sample*: the "
            "first pass's bytes over its samples (what one visible sample keeps, depth included). *Writes* "
            "and *reads*: every pass, overdraw included. *Scene data*: the visibility buffer's shading pass "
            "fetches, per triangle it shades, the triangle's indices and vertices and its object's matrices "
            "(%d bytes, from visibility_shade.frag), from buffers that the caches share between pixels: one "
            "triangle per covered pixel, and at 4 samples at most one per sample of an edge pixel. "
            "8-bit error: against the exact reference (forward, fp32, cut-off 0); at 4 samples against the "
            "exact 4-sample picture (chapter 13's forward MSAA at cut-off 0), so that antialiasing is not "
            "counted as error.\n",
            o->width, o->height, o->warmup > 0 ? o->warmup : 1, o->frames, R.pass_clock ? R.pass_clock : "frame",
            bench_storage_vis_scene_bytes);
    write_targets(f);
    for (int si = 0; si < bench_storage_scene_count(); si++)
        if (R.scene_done[si])
            write_scene_table(f, si);
    write_vis_timings(f);
    fprintf(f, "\n");
}
