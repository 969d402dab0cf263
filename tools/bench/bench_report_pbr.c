/* bench_report_pbr.c - the PBR rows' section of bench.md (bench_report.h): the metallic-roughness
 * scenes with their own lights, forward against deferred, beside the seed's figure. */
#include "bench_report.h"

#include "bench_renderers.h"

#include <math.h>
#include <string.h>

/* The seed's one figure for this experiment (8 textured teapots and a box, 80 lights): deferred about
 * 23 % faster than forward, that is forward's time about 1.23 times deferred's. */
#define SEED_SPEEDUP 1.23

static bool has_time(const bench_row *r)
{
    return r && r->status != BENCH_STATUS_NOT_LOADED && r->median_ms > 0;
}

/* The first row of each PBR scene, in the order they ran: the rows of one scene follow it. */
static bool first_of_scene(const bench_state *st, int i)
{
    const bench_row *r = &st->rows[i];
    if (strcmp(r->sweep, "pbr") != 0)
        return false;
    for (int k = 0; k < i; k++)
        if (strcmp(st->rows[k].sweep, "pbr") == 0 && strcmp(st->rows[k].scene, r->scene) == 0)
            return false;
    return true;
}

/* Forward's time over the fastest deferred renderer's: above 1, deferred is faster. */
static void write_speedup_cell(FILE *f, const bench_state *st, const char *scene_name)
{
    const bench_options *o = &st->opt;
    const bench_row *fwd = bench_state_find_row(st, "pbr", scene_name, bench_renderer_find("forward"), true, 0, -1);
    const bench_row *def = NULL;
    for (int i = 0; i < o->pbr_renderer_count; i++) {
        const bench_row *r = bench_state_find_row(st, "pbr", scene_name, o->pbr_renderers[i], true, 0, -1);
        if (bench_renderer_is_deferred(o->pbr_renderers[i]) && has_time(r) && (!def || r->median_ms < def->median_ms))
            def = r;
    }
    if (!has_time(fwd) || !def) {
        fprintf(f, " – |");
        return;
    }
    double ratio = fwd->median_ms / def->median_ms;
    fprintf(f, " %.2f (%s: %s %.0f %%) |", ratio, bench_renderer_name(def->renderer),
            ratio >= 1.0 ? "faster by" : "slower by", fabs(ratio - 1.0) * 100.0);
}

static void write_times(FILE *f, const bench_state *st)
{
    const bench_options *o = &st->opt;
    fprintf(f, "| scene | lights | G-buffer bytes |");
    for (int i = 0; i < o->pbr_renderer_count; i++)
        fprintf(f, " %s |", bench_renderer_name(o->pbr_renderers[i]));
    fprintf(f, " forward / fastest deferred |\n|---|---|---|");
    for (int i = 0; i < o->pbr_renderer_count; i++)
        fprintf(f, "---|");
    fprintf(f, "---|\n");
    for (int i = 0; i < st->row_count; i++) {
        if (!first_of_scene(st, i))
            continue;
        const bench_row *first = &st->rows[i];
        int bytes = 0;
        for (int k = 0; k < o->pbr_renderer_count; k++) {
            const bench_row *r = bench_state_find_row(st, "pbr", first->scene, o->pbr_renderers[k], true, 0, -1);
            bytes = r && r->gbuffer_bytes > bytes ? r->gbuffer_bytes : bytes;
        }
        if (first->status == BENCH_STATUS_NOT_LOADED)
            fprintf(f, "| %s | – | – |", first->scene);
        else if (bytes > 0)
            fprintf(f, "| %s | %d | %d |", first->scene, first->lights, bytes);
        else
            fprintf(f, "| %s | %d | – |", first->scene, first->lights);
        for (int k = 0; k < o->pbr_renderer_count; k++)
            bench_report_time_cell(f, bench_state_find_row(st, "pbr", first->scene, o->pbr_renderers[k], true, 0, -1));
        write_speedup_cell(f, st, first->scene);
        fprintf(f, "\n");
    }
}

static void write_work_and_error(FILE *f, const bench_state *st)
{
    fprintf(f, "\n| scene | renderer | shaded | evaluations / ideal | max 8-bit | mean 8-bit | PSNR 8-bit dB |\n"
               "|---|---|---|---|---|---|---|\n");
    for (int i = 0; i < st->row_count; i++) {
        const bench_row *r = &st->rows[i];
        if (strcmp(r->sweep, "pbr") != 0 || r->status == BENCH_STATUS_NOT_LOADED)
            continue;
        fprintf(f, "| %s | %s |", r->scene, bench_renderer_name(r->renderer));
        if (r->have_work && r->ideal > 0)
            fprintf(f, " %lld | %.2f |", r->shaded, r->work_ratio);
        else if (r->have_work)
            fprintf(f, " %lld | – |", r->shaded);
        else
            fprintf(f, " NA | NA |");
        if (r->have_error8)
            fprintf(f, " %d | %.4f | %.1f |\n", r->error8.max_abs, r->error8.mean_abs, r->error8.psnr);
        else
            fprintf(f, " NA | NA | NA |\n");
    }
}

void bench_report_write_pbr(FILE *f, const bench_state *st)
{
    bool any = false, missing = false;
    for (int i = 0; i < st->row_count; i++)
        if (strcmp(st->rows[i].sweep, "pbr") == 0) {
            any = true;
            missing = missing || st->rows[i].status == BENCH_STATUS_NOT_LOADED;
        }
    if (!any)
        return;
    fprintf(f,
            "\n## Metallic-roughness scenes (chapter 18)\n\n"
            "Each scene with its own lights at the 5/256 cut-off (docs/18_pbr_materials.md, \"What it costs\"); "
            "median ms per frame. The deferred renderers draw these scenes with a G-buffer layout that holds "
            "metallic-roughness materials (its bytes per pixel, with depth, in the third column; the "
            "G-buffer sweep measures every layout). The last column is forward's time over the fastest "
            "deferred renderer's: the seed reported deferred about 23 %% faster than forward on its textured "
            "teapots with 80 lights, a ratio of about %.2f. Error: against the exact reference "
            "(forward, fp32, cut-off 0), as in the tables above.\n\n",
            SEED_SPEEDUP);
    write_times(f, st);
    if (missing)
        fprintf(f, "\nNot loaded: the scene file or a model it names is missing (gltf_engine imports a sample "
                   "of Debian's assimp-testmodels, which scripts/install-deps.sh installs); bench.csv's note "
                   "names the file.\n");
    write_work_and_error(f, st);
}
