/* bench_ambient.c - see bench_ambient.h. */
#include "bench_ambient.h"

#include "app_embed.h"
#include "bench_ambient_error.h"
#include "bench_format.h"
#include "bench_measure.h"
#include "chapters.h"
#include "frame_stats.h"
#include "frame_timer.h"
#include "gl_util.h"
#include "light.h"
#include "log.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef enum ambient_mode { AMBIENT_ON, AMBIENT_OFF, AMBIENT_ONLY } ambient_mode;
static ambient_mode mode = AMBIENT_OFF;

enum { SCENES = 2, CHAPTERS = 3, COLUMNS = BENCH_AMBIENT_COLUMNS };
static const char *const scene_names[SCENES] = {"default", "teapots_probes"};
static const app_desc *const chapter_descs[CHAPTERS] = {&chapter_11, &chapter_17, &chapter_19};
static const char *const chapter_names[CHAPTERS] = {"11_clustered", "17_ssao", "19_image_based_light"};
/* The passes a row reports, by frame_timer_mark's names; the frame is column 0. */
static const char *const pass_names[COLUMNS] = {"frame", "geometry", "light assignment", "ssao", "ssao blur", "lighting"};

typedef bench_ambient_row ambient_row;

void bench_ambient_reset(bool full) { mode = full ? AMBIENT_ON : AMBIENT_OFF; }

int bench_ambient_parse_option(const char *arg, const char *value)
{
    if (strcmp(arg, "--ambient-sweep") != 0)
        return 0;
    static const char *const names[] = {"on", "off", "only"};
    for (int k = 0; value && k < 3; k++)
        if (strcmp(value, names[k]) == 0) {
            mode = (ambient_mode)k;
            return 1;
        }
    fprintf(stderr, "bench: bad --ambient-sweep (on, off or only): '%s' (see --help)\n", value ? value : "(missing)");
    return -1;
}

bool bench_ambient_enabled(void) { return mode != AMBIENT_OFF; }
bool bench_ambient_only(void) { return mode == AMBIENT_ONLY; }

void bench_ambient_print_help(FILE *f)
{
    fprintf(f, "  --ambient-sweep MODE   on: after the sweeps, chapter 17's SSAO and chapter 19's probes beside\n"
               "                        chapter 11 on the default scene and teapots_probes: their passes' time\n"
               "                        and memory; then SSAO's directions x blur timed and compared with\n"
               "                        traced occlusion (160x120), and the split sum's error by roughness\n"
               "                        against Monte Carlo (DIR/bench_ambient.md, bench_ambient*.csv);\n"
               "                        off; only: nothing else (--full: on; otherwise off)\n");
}

static double pass_ms(const frame_times *t, const char *name)
{
    for (int j = 0; t->valid && j < t->count; j++)
        if (strcmp(t->names[j], name) == 0)
            return t->ms[j];
    return NAN;
}

/* Chapter 17's targets at w x h (chapters/17_ssao.c, targets_follow): two RGBA16F occlusion targets
 * and the depth-normal pre-pass's RGBA8 + D32F, made for either renderer. */
static double ssao_bytes(int w, int h) { return (8.0 + 8.0 + 4.0 + 4.0) * w * h; }

/* What chapter `desc` adds on the GPU over chapter 11's frame (its own targets or probes). */
static double added_bytes(const app_desc *desc, const bench_options *o)
{
    if (desc == &chapter_17)
        return ssao_bytes(o->width, o->height);
    return desc == &chapter_19 ? (double)chapter_19_probe_bytes() : 0.0;
}

bool bench_ambient_time(const bench_options *o, const gpu_scene *gs, int count, const app_desc *const descs[],
                        const char *const *const args[], bench_ambient_row rows[])
{
    app_embed *e[CHAPTERS] = {0};
    frame_timer timers[CHAPTERS] = {0};
    /* at least 2 untimed frames: with 1, the first timed frame of a chapter drawn after the others
     * still took hundreds of milliseconds more than the next (measured on llvmpipe) */
    const int warmup = o->warmup > 2 ? o->warmup : 2, frames = o->frames > 0 ? o->frames : 1;
    double *t = calloc((size_t)CHAPTERS * COLUMNS * (size_t)frames, sizeof *t);
    double first[CHAPTERS] = {0};
    bool ok = t && count <= CHAPTERS;
    for (int c = 0; ok && c < count; c++)
        ok = frame_timer_create(&timers[c]) && app_embed_open(descs[c], args ? args[c] : NULL, gs, &e[c]);
    for (int k = 0; ok && k < warmup + frames; k++)
        for (int c = 0; ok && c < count; c++) {
            double t0 = bench_measure_now_ms();
            frame_timer_begin(&timers[c]);
            ok = app_embed_frame(e[c], gs, false, NULL);
            frame_timer_end(&timers[c]);
            glFinish();
            double ms = bench_measure_now_ms() - t0;
            if (k == 0)
                first[c] = ms;
            if (k < warmup)
                continue;
            double *slot = t + ((size_t)c * COLUMNS) * (size_t)frames;
            slot[k - warmup] = ms;
            for (int j = 1; j < COLUMNS; j++)
                slot[(size_t)j * (size_t)frames + (size_t)(k - warmup)] = pass_ms(&timers[c].last, pass_names[j]);
        }
    for (int c = 0; ok && c < count; c++) {
        for (int j = 0; j < COLUMNS; j++) {
            double *col = t + ((size_t)c * COLUMNS + (size_t)j) * (size_t)frames;
            int n = 0;
            for (int i = 0; i < frames; i++)
                if (!isnan(col[i]))
                    col[n++] = col[i];
            rows[c].ms[j] = n > 0 ? frame_stats_of(col, n).median : NAN;
        }
        rows[c].first_extra_ms = first[c] - rows[c].ms[0];
        rows[c].frames = frames;
        rows[c].bytes = added_bytes(descs[c], o); /* while the chapter is open: its probes are */
    }
    for (int c = 0; c < count; c++) {
        app_embed_close(e[c]);
        frame_timer_destroy(&timers[c]);
    }
    free(t);
    return ok;
}

/* One scene: the three chapters open together, drawn in turn, frame by frame. */
static bool run_scene(const bench_options *o, const char *name, ambient_row rows[CHAPTERS])
{
    char path[SCENE_PATH_MAX];
    bench_options_find_scene(o, name, path, sizeof path);
    scene sc;
    gpu_scene gs;
    if (!scene_load(path, &sc))
        return false;
    bool made = gpu_scene_create(&sc, &gs);
    bool ok = made && gpu_scene_update(&gs, 0.0f, LIGHT_DEFAULT_CUTOFF, o->width, o->height) &&
              bench_ambient_time(o, &gs, CHAPTERS, chapter_descs, NULL, rows);
    if (made)
        gpu_scene_destroy(&gs);
    scene_destroy(&sc);
    return ok;
}

static void put_ms(FILE *f, double ms, const char *sep)
{
    if (isnan(ms))
        fprintf(f, "–%s", sep);
    else
        fprintf(f, "%.1f%s", ms, sep);
}

/* A difference (the lighting over chapter 11's, the first frame's extra) with its sign. */
static void put_change(FILE *f, double ms, const char *sep)
{
    char text[32];
    fprintf(f, "%s%s", bench_format_change(ms, 1, text, sizeof text), sep);
}

static bool write_results(const bench_options *o, ambient_row rows[SCENES][CHAPTERS])
{
    char path[1100];
    snprintf(path, sizeof path, "%s/bench_ambient.csv", o->out_dir);
    FILE *csv = fopen(path, "w");
    snprintf(path, sizeof path, "%s/bench_ambient.md", o->out_dir);
    FILE *md = fopen(path, "w");
    if (!csv || !md) {
        log_error("cannot write %s/bench_ambient.*", o->out_dir);
        if (csv)
            fclose(csv);
        if (md)
            fclose(md);
        return false;
    }
    fprintf(csv, "scene,chapter,width,height,frames,frame_ms,geometry_ms,light_assignment_ms,ssao_ms,ssao_blur_ms,"
                 "lighting_ms,lighting_over_11_ms,first_frame_extra_ms,added_bytes\n");
    fprintf(md, "## SSAO and image-based light against the lighting pass (%dx%d, median of %d frames, ms)\n\n"
                "| scene | chapter | frame | geometry | light assignment | SSAO | blur | lighting | lighting − "
                "chapter 11's | first frame's extra | memory added |\n|---|---|---|---|---|---|---|---|---|---|---|\n",
            o->width, o->height, rows[0][0].frames);
    for (int s = 0; s < SCENES; s++)
        for (int c = 0; c < CHAPTERS; c++) {
            const ambient_row *r = &rows[s][c];
            double over = r->ms[5] - rows[s][0].ms[5];
            fprintf(csv, "%s,%s,%d,%d,%d", scene_names[s], chapter_names[c], o->width, o->height, r->frames);
            fprintf(md, "| %s | %s | ", scene_names[s], chapter_names[c]);
            for (int j = 0; j < COLUMNS; j++) {
                fprintf(csv, isnan(r->ms[j]) ? "," : ",%.3f", r->ms[j]);
                put_ms(md, r->ms[j], " | ");
            }
            fprintf(csv, ",%.3f,%.3f,%.0f\n", c ? over : 0.0, r->first_extra_ms, r->bytes);
            put_change(md, c ? over : NAN, " | ");
            put_change(md, r->first_extra_ms, " | ");
            fprintf(md, "%.1f MiB |\n", r->bytes / 1048576.0);
        }
    fclose(csv);
    fclose(md);
    return true;
}

bool bench_ambient_run(const bench_options *o)
{
    static ambient_row rows[SCENES][CHAPTERS];
    bool ok = true;
    char extra[32];
    for (int s = 0; ok && s < SCENES; s++) {
        ok = run_scene(o, scene_names[s], rows[s]);
        for (int c = 0; ok && c < CHAPTERS; c++)
            fprintf(stderr, "bench: ambient %-15s %-21s frame %8.1f ms, lighting %8.1f ms, ssao %6.1f + %6.1f ms, "
                            "first frame %s ms, %.1f MiB\n",
                    scene_names[s], chapter_names[c], rows[s][c].ms[0], rows[s][c].ms[5], rows[s][c].ms[3],
                    rows[s][c].ms[4], bench_format_change(rows[s][c].first_extra_ms, 0, extra, sizeof extra),
                    rows[s][c].bytes / 1048576.0);
    }
    return ok && write_results(o, rows) && bench_ambient_error_run(o);
}
