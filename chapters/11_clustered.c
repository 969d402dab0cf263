/* 11_clustered.c - clustered shading: the view cut into clusters, screen tiles times exponential
 * view-depth slices, a list per cluster of the lights that can reach it, and two renderers that read
 * the SAME lists: clustered deferred (one full-screen pass over the G-buffer) and clustered forward,
 * Forward+ (a depth pre-pass, then every object shaded once, each fragment looping over its cluster's
 * lights). Compare with chapter 10, whose tiles span every depth their pixels hold: a tile over an
 * edge (a near box in front of a far wall) collects the lights of both; a cluster only those of its
 * slice.
 *
 * Taken over: the G-buffer pass (02), shade_light() with its spots (00, 09), the depth pre-pass and
 * GL_EQUAL from chapter 00, the heat map (03). New here (common/clusters/cluster_grid.c, common/clusters/clusters.c,
 * shaders/clusters.glsl):
 *   the grid: 32 x 32-pixel tiles times S slices; slice k holds view depths
 *     near * (far / near)^(k / S) .. near * (far / near)^((k + 1) / S), S chosen so that a cluster is
 *     about as deep as it is tall (175 on the default scene at 800 x 800)
 *   2. light assignment: each light's bounding sphere (a spot's: the sphere around its cone) in view
 *      space, into every cluster whose box it reaches; per cluster (first, count) and the light
 *      indices, in two texture buffers. --assign cpu (GL 3.3): made on the CPU and uploaded;
 *      --assign compute (GL 4.3, common/clusters/cluster_assign_gpu.c): the CPU finds each light's slices
 *      and tiles, compute passes test the clusters and write the lists, the same bit for bit
 *      (--assign check compares them every frame); the L key switches
 *   3. shading: the fragment finds its cluster from gl_FragCoord and its view depth, and loops over
 *      that list calling shade_light(); written once, no blending
 * --cluster-lights N: the most entries a cluster's list holds; a cluster with more loops over every
 * light (slower, never wrong). --view overdraw: the light-loop iterations per pixel (--bench: their
 * total is shaded_pixels); --view clusters: each pixel's cluster list length, odd slices darker.
 * Read docs/11_clustered.md alongside.
 */
#include "app.h"
#include "chapters.h"
#include "clusters.h"
#include "gbuffer.h"

#include <string.h>

static const char *const renderers[] = {"deferred", "forward-plus", "forward", NULL};
static const char *const views[] = {"lit", "overdraw", "clusters", NULL};
static const char *const assigns[] = {"compute", "cpu", "check", NULL};

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "11_clustered",
    .summary = "Chapter 11: clustered shading: per-cluster light lists, for deferred and for Forward+.",
    .renderers = renderers,
    .views = views,
    .extras =
        {
            {"tile", "PIXELS", "cluster tile size in pixels (default 32)", NULL, NULL},
            {"slices", "N",
             "view-depth slices between the near and far planes (default: as many as make the "
             "clusters about as deep as they are tall)",
             NULL, NULL},
            {"cluster-lights", "N",
             "most lights a cluster's list holds; a cluster with more loops over all "
             "of them (default: no limit)",
             NULL, NULL},
            {"assign", "WHERE",
             "light lists made by compute shaders (GL 4.3) or on the CPU (GL 3.3); check: compute, "
             "compared with the CPU's every frame (exit 1 at the first difference); default: compute "
             "where the context has it",
             assigns, NULL},
        },
};

/* Clustered deferred: every pixel written once; no blending, no depth test, nothing culled. */
static const gl_pass_state deferred_pass = {.depth_write = false};


static struct {
    gbuffer g;
    clusters c;
} state;

/* An optional whole-number option; false (logged) when out of range. */
static bool option_int(const app *a, const char *name, int lo, int hi, int *out)
{
    double n = 0;
    if (!app_extra(a, name))
        return true;
    if (!app_extra_number(a, name, lo, hi, &n))
        return false;
    *out = (int)n;
    return true;
}

static bool init(app *a)
{
    clusters_desc desc = {0};
    if (!option_int(a, "tile", 1, 4096, &desc.tile_size) ||
        !option_int(a, "slices", 1, CLUSTER_MAX_SLICES, &desc.slices) ||
        !option_int(a, "cluster-lights", 1, 1 << 30, &desc.cluster_limit))
        return false;
    const char *assign = app_extra(a, "assign");
    desc.check = assign && strcmp(assign, "check") == 0;
    if (!app_extra_compute(a, "assign", &desc.compute))
        return false;
    a->pass_state = &deferred_pass; /* the overlay shows it */
    return gbuffer_create(&state.g, a->width, a->height) && clusters_create(&state.c, &desc);
}

static bool resize(app *a)
{
    return gbuffer_resize(&state.g, a->width, a->height);
}

static clusters_view view_of(const app *a)
{
    return a->linear_output             ? CLUSTERS_VIEW_LINEAR /* asked by the benchmark: float target */
           : app_view_is(a, "overdraw") ? CLUSTERS_VIEW_OVERDRAW
           : app_view_is(a, "clusters") ? CLUSTERS_VIEW_CLUSTERS
                                        : CLUSTERS_VIEW_LIT;
}

/* Clustered deferred: 1. geometry pass; 2. light assignment; 3. one full-screen shading pass. */
static bool frame_deferred(app *a)
{
    if (!gbuffer_render(&state.g, &a->gs) || !clusters_assign(&state.c, &a->gs))
        return false;
    glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
    glViewport(0, 0, a->width, a->height);
    bool ok = clusters_shade_deferred(&state.c, &state.g, &a->gs, &deferred_pass, view_of(a));
    gl_pass_state_reset();
    return ok && (!a->count_pixels || clusters_count(&state.c, &state.g, &a->gs));
}

/* Forward+: 1. depth pre-pass; 2. light assignment; 3. every object shaded once, GL_EQUAL. Written
 * in common/clusters/clusters.c (clusters_render_forward_plus), since every chapter offers Forward+. */
static bool frame_forward_plus(app *a)
{
    return clusters_render_forward_plus(&state.c, NULL, &a->gs, a->target.id, view_of(a)) &&
           (!a->count_pixels || clusters_count(&state.c, NULL, &a->gs));
}

static bool frame(app *a)
{
    if (app_renderer_is(a, "forward"))
        return app_render_forward(a);
    bool deferred = app_renderer_is(a, "deferred");
    a->pass_state = deferred ? &deferred_pass : &clusters_shade_after_prepass;
    if (!(deferred ? frame_deferred(a) : frame_forward_plus(a)))
        return false;
    a->linear_written = a->linear_output;
    /* --bench and the overlay: the light-loop iterations, counted by the same shader */
    a->shaded_pixels = a->count_pixels ? state.c.evaluations : -1;
    return true;
}

/* L: the lists made by compute shaders or on the CPU; the picture stays the same. */
static bool key(app *a, int k)
{
    (void)a;
    if (k != 'L')
        return false;
    app_toggle_compute(&state.c.desc.compute, "light assignment");
    return true;
}

static void cleanup(app *a)
{
    (void)a;
    clusters_destroy(&state.c);
    gbuffer_destroy(&state.g);
}

const app_desc chapter_11 = {.cli = &cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup, .key = key};

CHAPTER_MAIN(chapter_11)
