/* bench_run.c - see bench_run.h. */
#include "frame_stats.h"
#include "bench_run.h"

#include "frame_timer.h"
#include "gbuffer.h"
#include "gl_util.h"
#include "gpu_scene.h"
#include "light.h"
#include "log.h"
#include "progress.h"
#include "scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* What every step of a run works with. */
typedef struct run_ctx {
    bench_state *st;
    bench_renderers *br;
    bench_measure *m;
    frame_timer timers[BENCH_RENDERER_MAX]; /* one per renderer: GPU queries are read a frame late */
    bool chapters_pbr; /* the open chapters were opened on a scene with metallic-roughness materials */
} run_ctx;

/* A chapter picks its G-buffer layout for the scene it opens on (a metallic-roughness scene needs one
 * that holds it): when the next scene needs the other kind, the chapters are closed, to reopen on it. */
static void chapters_follow(run_ctx *x, const scene *s)
{
    bool pbr = false;
    for (int i = 0; i < s->material_count; i++)
        pbr = pbr || s->materials[i].pbr;
    if (pbr != x->chapters_pbr)
        bench_renderers_close_chapters(x->br);
    x->chapters_pbr = pbr;
}

/* ---- prediction of slow cases ------------------------------------------------------------------ */

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
    /* At most 4x past the last count measured: a line through two noisy points far below (1 and 16
     * lights on a busy machine) would predict a flat renderer, Forward+, slow at 256 and skip it. */
    if (lights > 4 * n1)
        lights = 4 * n1;
    if (h->count >= 2 && h->n[1] > h->n[0]) {
        /* cost ~ a + b * lights through the last two points (never a falling line) */
        double b = fmax((h->ms[1] - h->ms[0]) / (h->n[1] - h->n[0]), 0.0);
        return m1 + b * (lights - n1);
    }
    /* One point says what the frame costs, not how it grows: a geometry-bound scene (the bunnies,
     * hundreds of ms at one light) would be skipped at every count if one point were read as
     * cost ~ lights. Two points are needed before a case is predicted slower than it was. */
    return m1;
}

static void history_add(history *h, int lights, double ms)
{
    if (h->count == 2)
        h->n[0] = h->n[1], h->ms[0] = h->ms[1], h->count = 1;
    h->n[h->count] = lights, h->ms[h->count] = ms;
    h->count++;
}

/* ---- one case ---------------------------------------------------------------------------------- */

typedef struct case_desc {
    const char *sweep;
    const char *scene_name;
    bool own_lights;
    int lights; /* the scene's light count */
    double cutoff;
    int renderers[MAX_LIST];
    int renderer_count;
    history *histories;          /* per renderer index, or NULL: no prediction (cut-off sweep) */
    const history *predict_from; /* for the cut-off sweep: the light sweep's histories, may be NULL */
} case_desc;

/* Per renderer of a case, in the case's order. The rows are indices from first_row on, since adding
 * rows moves them. */
typedef struct case_plan {
    int n, first_row;
    int frames[MAX_LIST], warmup[MAX_LIST];
    double *times[MAX_LIST];  /* frames[i] timed frames */
    double *passes[MAX_LIST]; /* BENCH_PASSES per timed frame, NAN where the frame had no such pass */
} case_plan;

/* A case predicted over --max-frame-ms is not drawn: its time is the prediction. One predicted over
 * --case-budget-ms gets fewer frames, so one slow renderer does not hold up the sweep. */
static void plan_frames(const bench_options *o, const case_desc *c, bench_row *row, int *frames, int *warmup)
{
    int r = row->renderer;
    const history *h = c->histories ? &c->histories[r] : c->predict_from ? &c->predict_from[r] : NULL;
    double predicted = h ? predict_ms(h, c->lights) : 0.0;
    *frames = o->frames, *warmup = o->warmup;
    if (predicted > o->max_frame_ms) {
        *frames = *warmup = 0;
        row->status = BENCH_STATUS_SKIPPED;
        row->median_ms = row->min_ms = row->max_ms = predicted;
        snprintf(row->note, sizeof row->note, "skipped: predicted %.0f ms/frame > %.0f; time extrapolated",
                 predicted, o->max_frame_ms);
    } else if (predicted * (o->frames + o->warmup) > o->case_budget_ms) {
        int f = (int)(o->case_budget_ms / fmax(predicted, 1.0));
        *frames = f < o->min_frames ? o->min_frames : f > o->frames ? o->frames : f;
        *warmup = 1;
        row->status = *frames < o->frames ? BENCH_STATUS_FEW_FRAMES : BENCH_STATUS_MEASURED;
        if (row->status == BENCH_STATUS_FEW_FRAMES)
            snprintf(row->note, sizeof row->note, "slow: %d frames instead of %d", *frames, o->frames);
    }
    row->frames = *frames, row->warmup = *warmup;
}

/* One row per renderer; p->times is all NULL or allocated, also on failure. */
static bool plan_case(run_ctx *x, const gpu_scene *gs, const case_desc *c, case_plan *p)
{
    memset(p, 0, sizeof *p);
    p->n = c->renderer_count;
    p->first_row = x->st->row_count;
    for (int i = 0; i < p->n; i++) {
        bench_row *row = bench_state_add_row(x->st);
        if (!row)
            return false;
        row->sweep = c->sweep;
        snprintf(row->scene, sizeof row->scene, "%s", c->scene_name);
        row->renderer = c->renderers[i];
        row->own_lights = c->own_lights;
        row->lights = c->lights;
        row->active_lights = gs->light_count;
        row->cutoff = c->cutoff;
        /* A metallic-roughness scene takes a layout that holds it (gbuffer_layout_for_scene). */
        const gbuffer_layout *layout = gbuffer_layout_for_scene(NULL, gs->src);
        row->gbuffer_bytes =
            bench_renderer_is_deferred(row->renderer) && layout ? gbuffer_layout_bytes(layout, false) : 0;
        plan_frames(&x->st->opt, c, row, &p->frames[i], &p->warmup[i]);
        if (p->frames[i] > 0 && (!(p->times[i] = malloc((size_t)p->frames[i] * sizeof(double))) ||
                                 !(p->passes[i] = malloc((size_t)p->frames[i] * BENCH_PASSES * sizeof(double))))) {
            log_error("out of memory for frame times");
            return false;
        }
    }
    return true;
}

/* A frame's passes into the benchmark's columns (NAN: the renderer has no such pass). */
static void record_passes(const frame_times *f, double out[BENCH_PASSES])
{
    for (int k = 0; k < BENCH_PASSES; k++) {
        out[k] = NAN;
        for (int j = 0; f->valid && j < f->count; j++)
            if (strcmp(f->names[j], bench_pass_names[k]) == 0)
                out[k] = f->ms[j];
    }
}

/* The median of one pass over the timed frames that had it. */
static double pass_median(const double *passes, int frames, int k)
{
    double *v = malloc((size_t)frames * sizeof *v), median = NAN;
    int n = 0;
    for (int i = 0; v && i < frames; i++)
        if (!isnan(passes[i * BENCH_PASSES + k]))
            v[n++] = passes[i * BENCH_PASSES + k];
    if (n > 0)
        median = frame_stats_of(v, n).median;
    free(v);
    return median;
}

/* Warm-up, then the timed frames, renderer after renderer within each round. */
static bool time_case(run_ctx *x, gpu_scene *gs, const case_desc *c, case_plan *p)
{
    const bench_options *o = &x->st->opt;
    int rounds = 0;
    for (int i = 0; i < p->n; i++)
        rounds = p->frames[i] + p->warmup[i] > rounds ? p->frames[i] + p->warmup[i] : rounds;
    bool ok = true;
    char what[96];
    snprintf(what, sizeof what, "bench: case %d/%d (%s, %d lights)", x->st->case_index + 1, x->st->case_total,
             c->scene_name, c->lights);
    for (int k = 0; k < rounds && ok; k++) {
        progress_frame(what, k, rounds); /* a round: each renderer's frame */
        for (int i = 0; i < p->n && ok; i++) {
            /* Warm-up frames are spread over the first rounds; then timed frames follow. */
            if (k >= p->frames[i] + p->warmup[i])
                continue;
            frame_timer *t = &x->timers[c->renderers[i]];
            double t0 = bench_measure_now_ms();
            frame_timer_begin(t);
            ok = gpu_scene_update(gs, 0.0f, c->cutoff, o->width, o->height) &&
                 bench_render_frame(x->br, c->renderers[i], gs, false, NULL);
            frame_timer_end(t);
            glFinish();
            double ms = bench_measure_now_ms() - t0;
            if (k >= p->warmup[i]) {
                p->times[i][k - p->warmup[i]] = ms;
                record_passes(&t->last, p->passes[i] + (size_t)(k - p->warmup[i]) * BENCH_PASSES);
            }
        }
    }
    progress_end();
    return ok;
}

/* Median, min and max into the rows; the light sweep's medians feed the prediction. */
static void summarise_times(run_ctx *x, const case_desc *c, case_plan *p)
{
    for (int i = 0; i < p->n; i++) {
        bench_row *row = &x->st->rows[p->first_row + i];
        int f = p->frames[i];
        double *t = p->times[i];
        if (f > 0) {
            const frame_stats st = frame_stats_of(t, f);
            row->median_ms = st.median;
            row->min_ms = st.min;
            row->max_ms = st.max;
        }
        for (int k = 0; k < BENCH_PASSES; k++)
            row->pass_ms[k] = f > 0 ? pass_median(p->passes[i], f, k) : NAN;
        if (c->histories)
            history_add(&c->histories[row->renderer], c->lights, row->median_ms);
    }
}

static void free_times(case_plan *p)
{
    for (int i = 0; i < p->n; i++) {
        free(p->times[i]);
        free(p->passes[i]);
        p->times[i] = NULL;
        p->passes[i] = NULL;
    }
}

/* Work and error: one untimed frame per renderer that was not skipped. */
static bool measure_case(run_ctx *x, gpu_scene *gs, const case_desc *c, const case_plan *p)
{
    const bench_options *o = &x->st->opt;
    char key[BENCH_KEY_LEN];
    snprintf(key, sizeof key, "%s/%d/%d", c->scene_name, c->own_lights, c->lights);
    /* The cut-off sweep is about error: it always measures it. */
    bool want_error = c->lights <= o->error_max_lights || strcmp(c->sweep, "cutoff") == 0;
    if (want_error && !bench_measure_make_reference(x->m, x->br, gs, key, c->cutoff))
        return false;
    bench_ideal ideal;
    if (!bench_measure_count_ideal(x->m, x->br, gs, &ideal))
        return false;
    for (int i = 0; i < p->n; i++) {
        bench_row *row = &x->st->rows[p->first_row + i];
        row->covered = ideal.covered;
        row->ideal = ideal.ideal;
        if (row->status == BENCH_STATUS_SKIPPED)
            continue;
        if (!bench_measure_fill_row(x->m, x->br, gs, want_error, row))
            return false;
    }
    return true;
}

static void print_case(const bench_state *st, const case_plan *p)
{
    for (int i = 0; i < p->n; i++) {
        const bench_row *row = &st->rows[p->first_row + i];
        fprintf(stderr, "bench: case %d/%d %-22s %-8s lights %5d%s cut-off %6.3f/256: %9.2f ms%s\n",
                st->case_index, st->case_total, bench_renderer_name(row->renderer), row->scene, row->lights,
                row->own_lights ? " (scene's)" : "", row->cutoff * 256.0, row->median_ms,
                row->status == BENCH_STATUS_SKIPPED      ? " (skipped, extrapolated)"
                : row->status == BENCH_STATUS_FEW_FRAMES ? " (few frames)"
                                                         : "");
    }
}

/* Time so far and a guess at the rest: the cases done so far, on average, times those to come. */
static void print_progress(const bench_state *st)
{
    double elapsed = (bench_measure_now_ms() - st->start_ms) / 1000.0;
    double left = elapsed / st->case_index * (st->case_total - st->case_index);
    fprintf(stderr, "bench: %d of %d cases done in %.0f s; about %.0f s to go\n", st->case_index,
            st->case_total, elapsed, left);
}

static bool run_case(run_ctx *x, gpu_scene *gs, const case_desc *c)
{
    const bench_options *o = &x->st->opt;
    if (!gpu_scene_update(gs, 0.0f, c->cutoff, o->width, o->height))
        return false;
    case_plan p;
    bool ok = plan_case(x, gs, c, &p) && time_case(x, gs, c, &p);
    if (ok)
        summarise_times(x, c, &p);
    free_times(&p);
    if (!ok || !measure_case(x, gs, c, &p))
        return false;
    x->st->case_index++;
    print_case(x->st, &p);
    print_progress(x->st);
    return gl_check("run_case");
}

/* ---- scenes ------------------------------------------------------------------------------------ */

/* gs is built from gen; pointing it at own for the scene's own lights is safe because the two are
 * loads of the same file and share every mesh and object. */
static bool run_light_sweep(run_ctx *x, gpu_scene *gs, scene *own, scene *gen, const char *label,
                            history *histories)
{
    const bench_options *o = &x->st->opt;
    bool ok = true;
    for (int k = 0; ok && k < o->light_list_count; k++) {
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
            gs->src = own;
            c.lights = own->light_count;
        } else {
            gs->src = gen;
            ok = light_generate(gen, o->lights[k], o->seed);
            c.lights = o->lights[k];
        }
        ok = ok && run_case(x, gs, &c);
        gs->src = gen;
    }
    return ok;
}

static bool run_cutoff_sweep(run_ctx *x, gpu_scene *gs, scene *gen, const char *label,
                             const history *predict_from)
{
    const bench_options *o = &x->st->opt;
    bool ok = true;
    for (int k = 0; ok && k < o->cutoff_count; k++) {
        case_desc c = {.sweep = "cutoff",
                       .scene_name = label,
                       .lights = o->cutoff_lights,
                       .cutoff = o->cutoffs[k] / 256.0,
                       .predict_from = predict_from};
        for (int i = 0; i < o->renderer_count; i++)
            if (bench_renderer_in_cutoff_sweep(o->renderers[i]))
                c.renderers[c.renderer_count++] = o->renderers[i];
        ok = light_generate(gen, o->cutoff_lights, o->seed) && run_case(x, gs, &c);
    }
    return ok;
}

/* Both sweeps of one scene. `own` keeps the file's lights; `gen` gets light_generate's. */
static bool run_scene(run_ctx *x, const char *name, bool light_sweep, bool cutoff_sweep, history *histories)
{
    char path[SCENE_PATH_MAX], label[NAME_MAX_LEN];
    bench_options_find_scene(&x->st->opt, name, path, sizeof path);
    bench_options_label_scene(name, label, sizeof label);
    scene own, gen;
    if (!scene_load(path, &own))
        return false;
    chapters_follow(x, &own);
    if (!scene_load(path, &gen)) {
        scene_destroy(&own);
        return false;
    }
    gpu_scene gs;
    bool ok = gpu_scene_create(&gen, &gs);
    for (int r = 0; r < bench_renderer_count(); r++)
        histories[r].count = 0;
    if (ok && light_sweep)
        ok = run_light_sweep(x, &gs, &own, &gen, label, histories);
    if (ok && cutoff_sweep)
        ok = run_cutoff_sweep(x, &gs, &gen, label, light_sweep ? histories : NULL);
    gpu_scene_destroy(&gs);
    scene_destroy(&gen);
    scene_destroy(&own);
    bench_measure_forget_reference(x->m);
    return ok;
}

/* One metallic-roughness scene with its own lights, by the PBR renderers. A scene that does not load
 * (its error logged) gets rows that say so, and the run goes on: the glTF sample needs a package. */
static bool run_pbr_scene(run_ctx *x, const char *name)
{
    const bench_options *o = &x->st->opt;
    char path[SCENE_PATH_MAX], label[NAME_MAX_LEN];
    bench_options_find_scene(o, name, path, sizeof path);
    bench_options_label_scene(name, label, sizeof label);
    scene own;
    if (!scene_load(path, &own)) {
        for (int i = 0; i < o->pbr_renderer_count; i++) {
            bench_row *row = bench_state_add_row(x->st);
            if (!row)
                return false;
            *row = (bench_row){.sweep = "pbr", .renderer = o->pbr_renderers[i], .own_lights = true,
                               .status = BENCH_STATUS_NOT_LOADED, .median_ms = NAN};
            snprintf(row->scene, sizeof row->scene, "%s", label);
            snprintf(row->note, sizeof row->note, "not loaded: %.100s (the log says why)", path);
        }
        x->st->case_index++;
        return true;
    }
    chapters_follow(x, &own);
    gpu_scene gs;
    case_desc c = {.sweep = "pbr",
                   .scene_name = label,
                   .own_lights = true,
                   .lights = own.light_count,
                   .cutoff = LIGHT_DEFAULT_CUTOFF,
                   .renderer_count = o->pbr_renderer_count};
    memcpy(c.renderers, o->pbr_renderers, sizeof c.renderers);
    bool ok = gpu_scene_create(&own, &gs) && run_case(x, &gs, &c);
    gpu_scene_destroy(&gs);
    scene_destroy(&own);
    bench_measure_forget_reference(x->m);
    return ok;
}

/* ---- all cases --------------------------------------------------------------------------------- */

int bench_run_count_cases(const bench_options *options)
{
    return options->scene_count * options->light_list_count + options->cutoff_count + options->pbr_scene_count;
}

static bool run_sweeps(run_ctx *x);

/* Every sweep, with one frame timer per renderer for the pass columns. */
bool bench_run_all(bench_state *st, bench_renderers *br, bench_measure *m)
{
    run_ctx x = {st, br, m, {{0}}, false};
    for (int r = 0; r < BENCH_RENDERER_MAX; r++)
        if (!frame_timer_create(&x.timers[r]))
            return false;
    st->pass_clock = frame_timer_clock(&x.timers[0]);
    bool ok = run_sweeps(&x);
    for (int r = 0; r < BENCH_RENDERER_MAX; r++)
        frame_timer_destroy(&x.timers[r]);
    return ok;
}

/* The cut-off sweep runs with the light sweep of its scene, whose times predict its slow cases. */
static bool run_sweeps(run_ctx *x)
{
    bench_state *st = x->st;
    const bench_options *o = &st->opt;
    history histories[BENCH_RENDERER_MAX];
    memset(histories, 0, sizeof histories);
    char want[NAME_MAX_LEN];
    bench_options_label_scene(o->cutoff_scene, want, sizeof want);
    bool cutoff_done = false;
    for (int s = 0; s < o->scene_count; s++) {
        char label[NAME_MAX_LEN];
        bench_options_label_scene(o->scenes[s], label, sizeof label);
        bool cutoff_here = !cutoff_done && strcmp(label, want) == 0;
        if (!run_scene(x, o->scenes[s], true, cutoff_here, histories))
            return false;
        cutoff_done = cutoff_done || cutoff_here;
    }
    if (!cutoff_done && !run_scene(x, o->cutoff_scene, false, true, histories))
        return false;
    for (int s = 0; s < o->pbr_scene_count; s++)
        if (!run_pbr_scene(x, o->pbr_scenes[s]))
            return false;
    return true;
}
