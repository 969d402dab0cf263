/* bench.c - forward against deferred, measured: time per frame, lighting work and error, swept over
 * light counts, scenes, renderers and the cut-off. Writes out/bench.csv, out/bench.md and two plots;
 * a part run alone (--gbuffer-sweep, --storage or --ambient-sweep only) writes only its own files
 * (bench_gbuffer.*, bench_storage.*, bench_ambient*.*), so it never replaces the sweep's.
 *
 * Read docs/compare.md first: it shows a run's tables and explains them. The program is a loop
 * over "cases" (scene, lights, cut-off); in each case every renderer draws the same frame, frame by
 * frame in turn (round robin), so a noisy moment of the machine hits them all alike. After the
 * timed frames one untimed frame per renderer counts the lighting work (GL_SAMPLES_PASSED) and
 * keeps the picture for the error against the exact reference (forward, fp32, cut-off 0).
 *
 *   build/bin/bench                 the course's sweep at 800x800 (3 to 5 minutes on 2 cores)
 *   build/bin/bench --full          the pages' sweep (about 15 minutes, then the storage table):
 *                                   scripts/update-docs.sh
 *   build/bin/bench --quick         a small sweep (seconds): the test suite checks its output's shape
 *
 * This file is the top-level flow; the parts live in tools/bench/:
 *   bench_options    the command line          bench_run      the cases and their timing
 *   bench_renderers  the renderers compared    bench_measure  reference, work, error, read-backs
 *   bench_state      options, machine, rows    bench_error    a picture's error against the exact one
 *   bench_report     bench.csv and bench.md    bench_plots    the gnuplot script and plots
 *   bench_report_pbr the PBR rows' section (metallic-roughness scenes, their own lights)
 *   bench_gbuffer    the G-buffer layouts: bytes, time and precision (--gbuffer-sweep)
 *   bench_storage    what to store per pixel: bytes counted, passes timed, error (--storage)
 *   bench_ambient    SSAO and image-based light against the lighting pass (--ambient-sweep)
 *   bench_ambient_error  their errors against the exact references (tools/reference/)
 *   bench_format     signed differences as the reports print them
 */
#include "bench/bench_ambient.h"
#include "bench/bench_gbuffer.h"
#include "bench/bench_measure.h"
#include "bench/bench_options.h"
#include "bench/bench_plots.h"
#include "bench/bench_renderers.h"
#include "bench/bench_report.h"
#include "bench/bench_run.h"
#include "bench/bench_state.h"
#include "bench/bench_storage.h"

#include "gl_util.h"
#include "log.h"
#include "platform.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

/* Each `only` option runs its part and the others' `only` parts, and nothing else. */
static bool main_sweep_skipped(void)
{
    return bench_gbuffer_only() || bench_storage_only() || bench_ambient_only();
}

static bool gbuffer_sweep_runs(void)
{
    return bench_gbuffer_enabled() && (bench_gbuffer_only() || !main_sweep_skipped());
}

static bool storage_table_runs(void)
{
    return bench_storage_enabled() && (bench_storage_only() || !main_sweep_skipped());
}

static bool ambient_sweep_runs(void)
{
    return bench_ambient_enabled() && (bench_ambient_only() || !main_sweep_skipped());
}

/* The files a run writes. A part run alone (an `only`) writes its own files and never bench.md,
 * bench.csv or the plots: those are the main sweep's, and a part run into the same folder must not
 * replace them with tables of nothing (docs/compare.md, "Outputs"). */
enum { MAX_OUTPUTS = 12 };
typedef struct output_list {
    const char *names[MAX_OUTPUTS];
    int count;
} output_list;

/* Adds name to the list when written is true; returns written, so a chain of writes stops at the
 * first failure. */
static bool output_list_note(output_list *l, bool written, const char *name)
{
    if (written && l->count < MAX_OUTPUTS)
        l->names[l->count++] = name;
    return written;
}

static void output_list_print(FILE *f, const output_list *l)
{
    for (int i = 0; i < l->count; i++)
        fprintf(f, "%s%s", i == 0 ? "" : i + 1 < l->count ? ", " : " and ", l->names[i]);
}

static const char *const ambient_files[] = {"bench_ambient.md", "bench_ambient.csv", "bench_ambient_ssao.csv",
                                            "bench_ambient_ibl.csv"};

/* What the run will write, for its plan; the plots only where gnuplot works. */
static void plan_outputs(const bench_options *o, output_list *l)
{
    bool sweep = !main_sweep_skipped();
    output_list_note(l, sweep, "bench.csv");
    output_list_note(l, sweep, "bench.md");
    output_list_note(l, gbuffer_sweep_runs(), "bench_gbuffer.csv");
    output_list_note(l, gbuffer_sweep_runs() && !sweep, "bench_gbuffer.md");
    output_list_note(l, storage_table_runs(), "bench_storage.csv");
    output_list_note(l, storage_table_runs() && !sweep, "bench_storage.md");
    for (size_t i = 0; i < sizeof ambient_files / sizeof ambient_files[0]; i++)
        output_list_note(l, ambient_sweep_runs(), ambient_files[i]);
    output_list_note(l, sweep && o->plots, "bench_plots.gp");
    output_list_note(l, sweep && o->plots, "time_vs_lights.png");
    output_list_note(l, sweep && o->plots && o->cutoff_count > 0, "speed_vs_error.png");
}

/* The part run alone writes its section into a page of its own (bench_report_write_part_md). */
static bool write_part(const bench_state *st, output_list *done, const char *csv_name,
                       bool (*write_csv)(const bench_state *), const char *md_name, const char *title,
                       void (*write_md)(FILE *, const bench_state *))
{
    return output_list_note(done, write_csv(st), csv_name) &&
           (!main_sweep_skipped() ||
            output_list_note(done, bench_report_write_part_md(st, md_name, title, write_md), md_name));
}

static bool write_plots(const bench_state *st, output_list *done)
{
    bool drawn = false;
    if (!bench_plots_make(st, &drawn))
        return false;
    output_list_note(done, drawn, "bench_plots.gp");
    output_list_note(done, drawn, "time_vs_lights.png");
    output_list_note(done, drawn && st->opt.cutoff_count > 0, "speed_vs_error.png");
    return true;
}

static bool write_outputs(const bench_state *st, output_list *done)
{
    bool sweep = !main_sweep_skipped();
    return (!sweep || (output_list_note(done, bench_report_write_csv(st), "bench.csv") &&
                       output_list_note(done, bench_report_write_md(st), "bench.md"))) &&
           (!gbuffer_sweep_runs() || write_part(st, done, "bench_gbuffer.csv", bench_gbuffer_write_csv,
                                                "bench_gbuffer.md", "G-buffer layouts", bench_gbuffer_write_md)) &&
           (!storage_table_runs() || write_part(st, done, "bench_storage.csv", bench_storage_write_csv,
                                                "bench_storage.md", "What to store per pixel", bench_storage_write_md)) &&
           (!sweep || !st->opt.plots || write_plots(st, done));
}

/* The main sweep's plan: its cases and about how long they take, measured on the 2-core llvmpipe
 * machine the pages' figures come from (docs/compare.md); a GPU is much faster. */
static void print_sweep_plan(const bench_options *o, int cases)
{
    const char *minutes = strcmp(o->sweep_name, "full") == 0     ? "about 15 minutes (the storage table: more)"
                          : strcmp(o->sweep_name, "course") == 0 ? "3 to 5 minutes"
                                                                 : "under a minute";
    fprintf(stderr,
            "bench: the %s sweep: %d cases (%d scene(s) x %d light counts, %d cut-offs) x %d renderers, "
            "%d PBR scene(s) x %d renderers%s%s%s; %s on 2 cores with llvmpipe%s\n",
            o->sweep_name, cases, o->scene_count, o->light_list_count, o->cutoff_count, o->renderer_count,
            o->pbr_scene_count, o->pbr_renderer_count, gbuffer_sweep_runs() ? ", then the G-buffer layouts" : "",
            storage_table_runs() ? ", then the storage table" : "",
            ambient_sweep_runs() ? ", then the ambient sweep" : "", minutes,
            strcmp(o->sweep_name, "full") == 0 ? "" : " (--full: the pages' sweep)");
}

/* A part run alone: what each part draws (their --help says more), never the sweep it skips. */
static void print_parts_plan(const bench_options *o)
{
    fprintf(stderr, "bench: no sweep, only the part(s) asked for, at %dx%d, %d timed frame(s) per row:\n",
            o->width, o->height, o->frames);
    if (gbuffer_sweep_runs())
        fprintf(stderr, "bench:   the G-buffer layouts: chapter 07's frame with every layout on the default scene, "
                        "the city and pbr_teapots\n");
    if (storage_table_runs())
        fprintf(stderr, "bench:   the storage table: 7 renderers at 1 and 4 samples on %s (about 7 minutes at "
                        "320x240 with 3 frames on 2 cores with llvmpipe; --quick: under a minute)\n",
                o->quick ? "the default scene" : "the default, city, bunnies and teapots scenes");
    if (ambient_sweep_runs())
        fprintf(stderr, "bench:   the ambient sweep: chapters 11, 17 and 19 on the default scene and teapots_probes, "
                        "then SSAO's settings against traced occlusion and the split sum against Monte Carlo "
                        "(--full at 800x800: about 7 minutes on 2 cores with llvmpipe; --quick: under a minute)\n");
}

static void print_plan(const bench_options *o, int cases)
{
    if (main_sweep_skipped())
        print_parts_plan(o);
    else
        print_sweep_plan(o, cases);
    output_list planned = {0};
    plan_outputs(o, &planned);
    fprintf(stderr, "bench: results will be in %s/ (", o->out_dir);
    output_list_print(stderr, &planned);
    fprintf(stderr, "%s)\n", main_sweep_skipped() ? "; no other file there is touched" : "");
}

/* The ambient sweep opens chapters 11, 17 and 19 itself: the sweeps before it leave theirs open. */
static bool run_ambient(bench_renderers *br, const bench_options *o, output_list *done)
{
    bench_renderers_close_chapters(br);
    bool ok = bench_ambient_run(o);
    for (size_t i = 0; ok && i < sizeof ambient_files / sizeof ambient_files[0]; i++)
        output_list_note(done, true, ambient_files[i]);
    return ok;
}

int main(int argc, char **argv)
{
    static bench_state st; /* large; zeroed */
    int rc = bench_options_parse(argc, argv, &st.opt);
    if (rc == CLI_PARSE_DONE)
        return 0;
    if (rc != EXIT_CODE_OK)
        return rc;
    const bench_options *o = &st.opt;
    if (mkdir(o->out_dir, 0755) != 0 && errno != EEXIST) {
        log_error("cannot create %s: %s", o->out_dir, strerror(errno));
        return EXIT_CODE_RUNTIME;
    }
    const platform_desc pd = {
        .backend = o->backend, .width = o->width, .height = o->height, .title = "bench"};
    rc = platform_create(&pd);
    if (rc != EXIT_CODE_OK)
        return rc;
    bench_state_read_machine(&st);
    printf("bench: cpu=\"%s\" cores=%d gl_renderer=\"%s\" gl_version=\"%s\" size=%dx%d frames=%d warmup=%d\n",
           st.cpu, st.cores, st.gl_renderer, st.gl_version, o->width, o->height, o->frames, o->warmup);
    fflush(stdout);

    st.case_total = bench_run_count_cases(o);
    print_plan(o, st.case_total);
    double t0 = st.start_ms = bench_measure_now_ms();
    bench_measure m;
    bench_renderers *br = NULL;
    output_list done = {0};
    bool ok = bench_measure_create(o->width, o->height, &m) &&
              bench_renderers_create(o->width, o->height, &br) &&
              (main_sweep_skipped() || bench_run_all(&st, br, &m)) &&
              (!gbuffer_sweep_runs() || bench_gbuffer_run(&st, br, &m)) &&
              (!storage_table_runs() || bench_storage_run(&st, br, &m)) &&
              (!ambient_sweep_runs() || run_ambient(br, o, &done));
    rc = ok ? EXIT_CODE_OK : EXIT_CODE_RUNTIME;
    if (ok && main_sweep_skipped()) /* a part alone counts no cases */
        fprintf(stderr, "bench: done in %.1f s\n", (bench_measure_now_ms() - t0) / 1000.0);
    else if (ok)
        fprintf(stderr, "bench: %d cases in %.1f s\n", st.case_index, (bench_measure_now_ms() - t0) / 1000.0);
    if (ok && !write_outputs(&st, &done))
        rc = EXIT_CODE_RUNTIME;
    if (rc == EXIT_CODE_OK) {
        printf("bench: wrote into %s/: ", o->out_dir); /* only what this run wrote */
        output_list_print(stdout, &done);
        printf("\n");
    }
    bench_renderers_destroy(br);
    bench_measure_destroy(&m);
    gl_util_shutdown();
    platform_destroy();
    bench_state_destroy(&st);
    return rc;
}
