/* bench.c - forward against deferred, measured: time per frame, lighting work and error, swept over
 * light counts, scenes, renderers and the cut-off. Writes out/bench.csv, out/bench.md and two plots.
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

/* --gbuffer-sweep only or --storage only: the main sweep does not run, nor the other of the two
 * unless it says `only` too. */
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

static bool write_outputs(const bench_state *st)
{
    return bench_report_write_csv(st) && bench_report_write_md(st) &&
           (!gbuffer_sweep_runs() || bench_gbuffer_write_csv(st)) &&
           (!storage_table_runs() || bench_storage_write_csv(st)) &&
           (!st->opt.plots || main_sweep_skipped() || bench_plots_make(st));
}

/* What the run will do and about how long it takes, measured on the 2-core llvmpipe machine the
 * pages' figures come from (docs/compare.md); a GPU is much faster. */
static void print_plan(const bench_options *o, int cases)
{
    const char *minutes = strcmp(o->sweep_name, "full") == 0     ? "about 15 minutes (the storage table: more)"
                          : strcmp(o->sweep_name, "course") == 0 ? "3 to 5 minutes"
                                                                 : "under a minute";
    fprintf(stderr,
            "bench: the %s sweep: %d cases (%d scene(s) x %d light counts, %d cut-offs) x %d renderers, "
            "%d PBR scene(s) x %d renderers%s%s; %s on 2 cores with llvmpipe%s\n",
            o->sweep_name, cases, o->scene_count, o->light_list_count, o->cutoff_count, o->renderer_count,
            o->pbr_scene_count, o->pbr_renderer_count,
            gbuffer_sweep_runs() ? ", then the G-buffer layouts" : "",
            storage_table_runs() ? ", then the storage table" : "", minutes,
            strcmp(o->sweep_name, "full") == 0 ? "" : " (--full: the pages' sweep)");
    fprintf(stderr, "bench: results will be in %s/ (bench.md, bench.csv%s)\n", o->out_dir,
            o->plots ? ", time_vs_lights.png, speed_vs_error.png" : "");
}

/* The ambient sweep opens chapters 11, 17 and 19 itself: the sweeps before it leave theirs open. */
static bool run_ambient(bench_renderers *br, const bench_options *o)
{
    bench_renderers_close_chapters(br);
    return bench_ambient_run(o);
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
    bool ok = bench_measure_create(o->width, o->height, &m) &&
              bench_renderers_create(o->width, o->height, &br) &&
              (main_sweep_skipped() || bench_run_all(&st, br, &m)) &&
              (!gbuffer_sweep_runs() || bench_gbuffer_run(&st, br, &m)) &&
              (!storage_table_runs() || bench_storage_run(&st, br, &m)) &&
              (!ambient_sweep_runs() || run_ambient(br, o));
    rc = ok ? EXIT_CODE_OK : EXIT_CODE_RUNTIME;
    if (ok)
        fprintf(stderr, "bench: %d cases in %.1f s\n", st.case_index, (bench_measure_now_ms() - t0) / 1000.0);
    if (ok && !write_outputs(&st))
        rc = EXIT_CODE_RUNTIME;
    if (rc == EXIT_CODE_OK)
        printf("bench: wrote %s/bench.csv %s/bench.md%s\n", o->out_dir, o->out_dir,
               o->plots ? " and the plots" : "");
    bench_renderers_destroy(br);
    bench_measure_destroy(&m);
    gl_util_shutdown();
    platform_destroy();
    bench_state_destroy(&st);
    return rc;
}
