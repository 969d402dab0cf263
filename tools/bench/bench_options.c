/* bench_options.c - see bench_options.h. */
#include "data_dir.h"
#include "bench_options.h"

#include "bench_ambient.h"
#include "bench_gbuffer.h"
#include "bench_storage.h"
#include "bench_renderers.h"
#include "progress.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

/* The PBR rows: chapter 00's forward, chapter 11's Forward+ and clustered deferred (the seed's
 * comparison), and in the pages' sweep chapter 10's tiles too. */
static const char *const pbr_renderers_full = "forward,forward-plus,deferred-tiled,deferred-clustered";
static const char *const pbr_renderers_course = "forward,forward-plus,deferred-clustered";

static const char *const default_renderers =
    "forward-naive,forward,forward-plus,deferred-fullscreen,deferred-volumes,deferred-volumes-windowed,"
    "deferred-stencil,deferred-tiled,deferred-clustered";

void bench_options_print_help(FILE *f)
{
    fprintf(
        f,
        "usage: bench [options]\n"
        "Times forward and deferred renderers on the same frames, counts their lighting work and\n"
        "measures their error against an exact reference; writes DIR/bench.csv, DIR/bench.md,\n"
        "DIR/time_vs_lights.png and DIR/speed_vs_error.png (gnuplot).\n\n"
        "The sweep (the last of --full and --quick; the options below change it further):\n"
        "  (default)             the course's sweep, what scripts/run-all.sh runs (3 to 5 minutes on\n"
        "                        2 cores with llvmpipe): scenes default, city, teapots at 1, 16, 256,\n"
        "                        1024 and the scene's own lights, every renderer, the cut-off at\n"
        "                        1, 5, 20; 5 timed frames per case (1 warm-up); no G-buffer sweep\n"
        "  --full                the pages' sweep (scripts/update-docs.sh; about 15 minutes): the five\n"
        "                        scenes at 1,4,16,64,256,1024,4096 and their own lights, the cut-off\n"
        "                        at 0.5,1,2,5,10,20,32, the G-buffer sweep and\n"
        "                        the storage table\n"
        "  --quick               small sweep for tests: 160x160, default scene, 1,16,64 lights,\n"
        "                        3 frames, cut-offs 2,5,16 at 16 lights\n");
    fprintf(
        f,
        "  Every sweep ends with the PBR rows: the metallic-roughness scenes pbr_teapots (the\n"
        "  textured teapots, 80 lights) and gltf_engine (a glTF 2.0 sample of Debian's\n"
        "  assimp-testmodels, 32 lights), each with its own lights at the 5/256 cut-off, drawn by\n"
        "  forward, forward-plus and deferred-clustered (--full: deferred-tiled too)\n\n"
        "  --lights LIST         light counts, comma-separated; 'scene' = the scene's own lights\n"
        "  --scenes LIST         scene names in --scene-dir or .scene paths\n"
        "  --renderers LIST      of: forward-naive forward forward-prepass forward-lists\n"
        "                        deferred-fullscreen deferred-volumes deferred-volumes-windowed\n"
        "                        deferred-stencil deferred-tiled forward-plus deferred-clustered\n"
        "                        (default: forward-naive, forward, forward-plus (chapter 11's Forward+),\n"
        "                        deferred-fullscreen, deferred-volumes,\n"
        "                        deferred-volumes-windowed: chapter 07 with the windowed falloff, whose\n"
        "                        error against the exact hard-falloff picture is the model's price,\n"
        "                        deferred-stencil: chapter 08's stencil light volumes, deferred-tiled:\n"
        "                        chapter 10's per-tile light lists, deferred-clustered: chapter 11's\n"
        "                        clustered deferred; for tiled, clustered and Forward+ shaded_pixels are\n"
        "                        light-loop iterations)\n"
        "  --cutoffs LIST        cut-off sweep in 1/256 units; none: no cut-off sweep\n"
        "  --cutoff-scene NAME   scene of the cut-off sweep (default: the first of --scenes)\n"
        "  --cutoff-lights N     light count of the cut-off sweep (default 256)\n"
        "  --pbr-scenes LIST     the PBR rows' scenes (names or .scene paths), each with its own\n"
        "                        lights; none: no PBR rows. A scene that does not load (the\n"
        "                        glTF sample without its package) is listed as not loaded\n"
        "  --pbr-renderers LIST  the PBR rows' renderers (names as for --renderers)\n"
        "  --size WxH            frame size (default 800x800)\n"
        "  --frames N            timed frames per renderer and case (default 10)\n"
        "  --warmup N            untimed frames first (default 2; llvmpipe compiles shaders at first draw)\n"
        "  --max-frame-ms MS     skip a case predicted slower than this per frame (default 1500);\n"
        "                        its time is extrapolated from the two previous light counts\n"
        "  --case-budget-ms MS   time per renderer and case; slower cases take fewer frames, at least 3\n"
        "                        (default 1500)\n"
        "  --error-max-lights N  measure the error only up to N lights: the exact reference shades\n"
        "                        every pixel with every light (default 256; the cut-off\n"
        "                        sweep always measures it)\n"
        "  --seed N              light_generate seed (default 1)\n"
        "  --scene-dir DIR       where scene names are looked up (default: the data folder's\n"
        "                        assets/scenes)\n"
        "  --out DIR             output folder (default out). A part run alone (--gbuffer-sweep,\n"
        "                        --storage or --ambient-sweep only) writes its own files there and never\n"
        "                        bench.md, bench.csv or the plots, which stay the last sweep's\n"
        "  --backend egl|osmesa  headless GL (default egl)\n"
        "  --no-plots            skip gnuplot\n"
        "  --quiet               no progress lines (written while a frame takes more than 2 s)\n");
    bench_gbuffer_print_help(f);
    bench_storage_print_help(f);
    bench_ambient_print_help(f);
    fprintf(f, "  --help                this text\n\n"
               "exit codes: 0 ok, 1 runtime failure, 2 usage error, 77 no GL context\n");
}

static bool usage_error(const char *what, const char *value)
{
    fprintf(stderr, "bench: %s: '%s' (see --help)\n", what, value ? value : "(missing)");
    return false;
}

/* The whole of s as a number in [lo, hi]; integer: read as strtol reads base 10, so "1e3" is not one. */
static bool parse_number(const char *s, bool integer, double lo, double hi, double *out)
{
    if (!s || !*s)
        return false;
    char *end;
    errno = 0;
    double v = integer ? (double)strtol(s, &end, 10) : strtod(s, &end);
    if (*end || errno || !(v >= lo && v <= hi))
        return false;
    *out = v;
    return true;
}

static bool parse_int(const char *s, int lo, int hi, int *out)
{
    double v;
    if (!parse_number(s, true, lo, hi, &v))
        return false;
    *out = (int)v;
    return true;
}

static bool parse_double(const char *s, double lo, double hi, double *out)
{
    return parse_number(s, false, lo, hi, out);
}

/* Splits a comma-separated list into items; false on an empty item, a too long one, or too many. */
static bool split_list(const char *list, char items[MAX_LIST][NAME_MAX_LEN], int *count)
{
    *count = 0;
    if (!list || !*list)
        return false;
    const char *p = list;
    for (;;) {
        const char *comma = strchr(p, ',');
        size_t len = comma ? (size_t)(comma - p) : strlen(p);
        if (len == 0 || len >= NAME_MAX_LEN || *count == MAX_LIST)
            return false;
        memcpy(items[*count], p, len);
        items[*count][len] = '\0';
        (*count)++;
        if (!comma)
            return true;
        p = comma + 1;
    }
}

/* Reads one item of a list option into slot i of its array; false when the item is bad. */
typedef bool (*item_reader)(bench_options *o, int i, const char *item);

/* Splits list into *count items and reads each with read_item; the usage error names the list
 * (bad_list) or the first item read_item refused (bad_item). */
static bool set_list(bench_options *o, const char *list, int *count, item_reader read_item,
                     const char *bad_list, const char *bad_item)
{
    char items[MAX_LIST][NAME_MAX_LEN];
    if (!split_list(list, items, count))
        return usage_error(bad_list, list);
    for (int i = 0; i < *count; i++)
        if (!read_item(o, i, items[i]))
            return usage_error(bad_item, items[i]);
    return true;
}

static bool read_light_count(bench_options *o, int i, const char *item)
{
    if (strcmp(item, "scene") == 0) {
        o->lights[i] = LIGHTS_OWN;
        return true;
    }
    return parse_int(item, 0, 1 << 20, &o->lights[i]);
}

static bool read_renderer(bench_options *o, int i, const char *item)
{
    o->renderers[i] = bench_renderer_find(item);
    return o->renderers[i] >= 0;
}

static bool read_cutoff(bench_options *o, int i, const char *item)
{
    return parse_double(item, 1e-6, 255.0, &o->cutoffs[i]);
}

static bool set_lights(bench_options *o, const char *list)
{
    return set_list(o, list, &o->light_list_count, read_light_count, "bad --lights list",
                    "bad light count in --lights");
}

static bool set_renderers(bench_options *o, const char *list)
{
    /* The message lists the valid names (chapters/course_renderers.c). */
    char bad[512];
    int n = snprintf(bad, sizeof bad, "unknown renderer in --renderers (one of:");
    for (int r = 0; r < bench_renderer_count() && n > 0 && n < (int)sizeof bad - 32; r++)
        n += snprintf(bad + n, sizeof bad - (size_t)n, " %s", bench_renderer_name(r));
    snprintf(bad + n, sizeof bad - (size_t)n, ")");
    return set_list(o, list, &o->renderer_count, read_renderer, "bad --renderers list", bad);
}

static bool set_cutoffs(bench_options *o, const char *list)
{
    if (list && strcmp(list, "none") == 0) {
        o->cutoff_count = 0;
        return true;
    }
    return set_list(o, list, &o->cutoff_count, read_cutoff, "bad --cutoffs list",
                    "bad cut-off in --cutoffs (1/256 units, > 0)");
}

static bool set_scenes(bench_options *o, const char *list)
{
    if (!split_list(list, o->scenes, &o->scene_count))
        return usage_error("bad --scenes list", list);
    return true;
}

static bool set_pbr_scenes(bench_options *o, const char *list)
{
    if (list && strcmp(list, "none") == 0) {
        o->pbr_scene_count = 0;
        return true;
    }
    if (!split_list(list, o->pbr_scenes, &o->pbr_scene_count))
        return usage_error("bad --pbr-scenes list", list);
    return true;
}

static bool read_pbr_renderer(bench_options *o, int i, const char *item)
{
    o->pbr_renderers[i] = bench_renderer_find(item);
    return o->pbr_renderers[i] >= 0;
}

static bool set_pbr_renderers(bench_options *o, const char *list)
{
    return set_list(o, list, &o->pbr_renderer_count, read_pbr_renderer, "bad --pbr-renderers list",
                    "unknown renderer in --pbr-renderers (see --renderers)");
}

/* The defaults go through the same parsers as the options (they cannot fail). */
static void set_defaults(bench_options *o)
{
    memset(o, 0, sizeof *o);
    set_lights(o, "1,4,16,64,256,1024,4096,scene");
    set_scenes(o, "default,city,bunnies,sphere,teapots");
    set_renderers(o, default_renderers);
    set_cutoffs(o, "0.5,1,2,5,10,20,32");
    set_pbr_scenes(o, "pbr_teapots,gltf_engine");
    set_pbr_renderers(o, pbr_renderers_full);
    o->cutoff_lights = 256;
    o->width = o->height = 800;
    o->frames = 10, o->warmup = 2, o->min_frames = 3;
    o->max_frame_ms = 1500, o->case_budget_ms = 1500;
    o->error_max_lights = 256;
    o->seed = 1;
    /* The course's scenes wherever the benchmark runs from (common/base/data_dir.h). */
    static char scene_dir[4200];
    o->scene_dir = data_dir_path("assets/scenes", scene_dir, sizeof scene_dir) ? scene_dir : "assets/scenes";
    o->out_dir = "out";
    o->plots = true;
    o->backend = BACKEND_EGL;
    o->sweep_name = "full";
    bench_gbuffer_reset(false);
    bench_storage_reset(true, false);
    bench_ambient_reset(true);
}

/* The learner's sweep: the scenes and light counts where the renderers' order changes (one light,
 * where forward wins; 16, where clustered and tiled overtake it on the city and the teapots; 256
 * and 1,024, where only the light lists stay flat), each scene's own lights, every renderer, and
 * the cut-off at three points. A few minutes on 2 cores; --full is the pages' sweep. */
static void set_course(bench_options *o)
{
    o->sweep_name = "course";
    set_lights(o, "1,16,256,1024,scene");
    set_scenes(o, "default,city,teapots");
    set_cutoffs(o, "1,5,20");
    set_pbr_renderers(o, pbr_renderers_course);
    o->frames = 5, o->warmup = 1; /* a first look: medians of 5 frames, the pages' run takes 10 */
    o->case_budget_ms = 800;
    bench_gbuffer_reset(true);
    bench_storage_reset(false, false);
    bench_ambient_reset(false);
}

static void set_quick(bench_options *o)
{
    o->sweep_name = "quick";
    o->quick = true;
    set_lights(o, "1,16,64");
    set_scenes(o, "default");
    set_cutoffs(o, "2,5,16");
    set_pbr_renderers(o, pbr_renderers_course);
    o->cutoff_lights = 16;
    o->width = o->height = 160;
    o->frames = 3, o->warmup = 1;
    o->case_budget_ms = 1000;
    bench_gbuffer_reset(true);
    bench_storage_reset(false, true);
    bench_ambient_reset(false);
}

/* What one option with a value made of its value; OPTION_UNKNOWN lets the next group try it. */
typedef enum option_result { OPTION_UNKNOWN, OPTION_GOOD, OPTION_BAD } option_result;

static option_result option_result_of(bool good)
{
    return good ? OPTION_GOOD : OPTION_BAD;
}

/* The options that pick the cases. */
static option_result parse_sweep_option(bench_options *o, const char *a, const char *v,
                                        bool *have_cutoff_scene)
{
    bool good;
    if (strcmp(a, "--lights") == 0) {
        good = set_lights(o, v);
    } else if (strcmp(a, "--scenes") == 0) {
        good = set_scenes(o, v);
    } else if (strcmp(a, "--renderers") == 0) {
        good = set_renderers(o, v);
    } else if (strcmp(a, "--cutoffs") == 0) {
        good = set_cutoffs(o, v);
    } else if (strcmp(a, "--cutoff-scene") == 0) {
        good = v && *v && strlen(v) < NAME_MAX_LEN ? (snprintf(o->cutoff_scene, NAME_MAX_LEN, "%s", v), true)
                                                   : usage_error("bad --cutoff-scene", v);
        *have_cutoff_scene = true;
    } else if (strcmp(a, "--pbr-scenes") == 0) {
        good = set_pbr_scenes(o, v);
    } else if (strcmp(a, "--pbr-renderers") == 0) {
        good = set_pbr_renderers(o, v);
    } else if (strcmp(a, "--cutoff-lights") == 0) {
        good = parse_int(v, 1, 1 << 20, &o->cutoff_lights) || usage_error("bad --cutoff-lights", v);
    } else if (strcmp(a, "--seed") == 0) {
        int seed = 0;
        good = parse_int(v, 0, 2147483647, &seed) || usage_error("bad --seed", v);
        o->seed = (uint32_t)seed;
    } else {
        return OPTION_UNKNOWN;
    }
    return option_result_of(good);
}

/* The options that decide how each case is drawn and timed. */
static option_result parse_timing_option(bench_options *o, const char *a, const char *v)
{
    bool good;
    if (strcmp(a, "--size") == 0) {
        int w = 0, h = 0;
        char extra;
        good = (v && sscanf(v, "%dx%d%c", &w, &h, &extra) == 2 && w >= 16 && h >= 16 && w <= 8192 &&
                h <= 8192) ||
               usage_error("bad --size (WxH, 16..8192)", v);
        o->width = w, o->height = h;
    } else if (strcmp(a, "--frames") == 0) {
        good = parse_int(v, 1, 100000, &o->frames) || usage_error("bad --frames", v);
    } else if (strcmp(a, "--warmup") == 0) {
        good = parse_int(v, 0, 100000, &o->warmup) || usage_error("bad --warmup", v);
    } else if (strcmp(a, "--max-frame-ms") == 0) {
        good = parse_double(v, 1, 1e9, &o->max_frame_ms) || usage_error("bad --max-frame-ms", v);
    } else if (strcmp(a, "--case-budget-ms") == 0) {
        good = parse_double(v, 1, 1e9, &o->case_budget_ms) || usage_error("bad --case-budget-ms", v);
    } else if (strcmp(a, "--error-max-lights") == 0) {
        good = parse_int(v, 0, 1 << 20, &o->error_max_lights) || usage_error("bad --error-max-lights", v);
    } else {
        return OPTION_UNKNOWN;
    }
    return option_result_of(good);
}

/* The options about files and the GL context. */
static option_result parse_io_option(bench_options *o, const char *a, const char *v)
{
    bool good = true;
    if (strcmp(a, "--scene-dir") == 0) {
        good = (v && *v) || usage_error("bad --scene-dir", v);
        o->scene_dir = v;
    } else if (strcmp(a, "--out") == 0) {
        good = (v && *v) || usage_error("bad --out", v);
        o->out_dir = v;
    } else if (strcmp(a, "--backend") == 0) {
        if (v && strcmp(v, "egl") == 0)
            o->backend = BACKEND_EGL;
        else if (v && strcmp(v, "osmesa") == 0)
            o->backend = BACKEND_OSMESA;
        else
            good = usage_error("bad --backend (egl or osmesa)", v);
    } else {
        return OPTION_UNKNOWN;
    }
    return option_result_of(good);
}

int bench_options_parse(int argc, char **argv, bench_options *out)
{
    bench_options *o = out;
    set_defaults(o);
    /* The sweep first (the course's unless --full or --quick; the last of those two given), so the
     * options after it can still change what it set. */
    bool quick = false, full = false;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--quick") == 0)
            quick = true, full = false;
        else if (strcmp(argv[i], "--full") == 0)
            full = true, quick = false;
    }
    if (quick)
        set_quick(o);
    else if (!full)
        set_course(o);
    bool have_cutoff_scene = false;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            bench_options_print_help(stdout);
            return CLI_PARSE_DONE;
        }
        if (strcmp(a, "--quick") == 0 || strcmp(a, "--full") == 0)
            continue;
        if (strcmp(a, "--no-plots") == 0) {
            o->plots = false;
            continue;
        }
        if (strcmp(a, "--quiet") == 0) {
            progress_set_quiet(true);
            continue;
        }
        int gbuffer = bench_gbuffer_parse_option(a, v);
        if (gbuffer == 0)
            gbuffer = bench_storage_parse_option(a, v);
        if (gbuffer == 0)
            gbuffer = bench_ambient_parse_option(a, v);
        if (gbuffer != 0) {
            if (gbuffer < 0)
                return EXIT_CODE_USAGE;
            i++; /* the value */
            continue;
        }
        option_result res = parse_sweep_option(o, a, v, &have_cutoff_scene);
        if (res == OPTION_UNKNOWN)
            res = parse_timing_option(o, a, v);
        if (res == OPTION_UNKNOWN)
            res = parse_io_option(o, a, v);
        if (res == OPTION_UNKNOWN)
            usage_error("unknown option", a);
        if (res != OPTION_GOOD)
            return EXIT_CODE_USAGE;
        i++; /* the value */
    }
    if (o->min_frames > o->frames)
        o->min_frames = o->frames;
    if (!have_cutoff_scene)
        snprintf(o->cutoff_scene, NAME_MAX_LEN, "%s", o->scenes[0]);
    return EXIT_CODE_OK;
}

void bench_options_find_scene(const bench_options *options, const char *name, char *out, size_t size)
{
    size_t len = strlen(name);
    if (strchr(name, '/') || (len > 6 && strcmp(name + len - 6, ".scene") == 0))
        snprintf(out, size, "%s", name);
    else
        snprintf(out, size, "%s/%s.scene", options->scene_dir, name);
}

void bench_options_label_scene(const char *name, char *out, size_t size)
{
    const char *slash = strrchr(name, '/');
    snprintf(out, size, "%s", slash ? slash + 1 : name);
    char *dot = strrchr(out, '.');
    if (dot && strcmp(dot, ".scene") == 0)
        *dot = '\0';
}
