/* 11_clustered.c - clustered shading: the view cut into clusters, screen tiles times exponential
 * view-depth slices, a list per cluster of the lights that can reach it, and two renderers that read
 * the SAME lists: clustered deferred (one full-screen pass over the G-buffer) and clustered forward,
 * Forward+ (a depth pre-pass, then every object shaded once, each fragment looping over its cluster's
 * lights). Compare with chapter 10, whose tiles span every depth their pixels hold: a tile over an
 * edge (a near box in front of a far wall) collects the lights of both; a cluster only those of its
 * slice.
 *
 * Taken over: the G-buffer pass (02), shade_light() with its spots (00, 09), the depth pre-pass and
 * GL_EQUAL from chapter 00, the heat map (03). New here, the passes below (their math and buffers in
 * common/clusters/, the shaders in shaders/clusters.glsl and cluster_assign.comp):
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
#include "frame_timer.h"
#include "gbuffer.h"
#include "gl_util.h"

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
            {"tile", "PIXELS", "cluster tile size in pixels (default 32)", NULL, NULL, CLI_WHOLE, 1, 4096},
            {"slices", "N",
             "view-depth slices between the near and far planes (default: as many as make the "
             "clusters about as deep as they are tall)",
             NULL, NULL, CLI_WHOLE, 1, CLUSTER_MAX_SLICES},
            {"cluster-lights", "N",
             "most lights a cluster's list holds; a cluster with more loops over all "
             "of them (default: no limit)",
             NULL, NULL, CLI_WHOLE, 1, 1 << 30},
            {"assign", "WHERE",
             "light lists made by compute shaders (GL 4.3) or on the CPU (GL 3.3); check: compute, "
             "compared with the CPU's every frame (exit 1 at the first difference); default: compute "
             "where the context has it",
             assigns, NULL},
        },
};

/* Clustered deferred: every pixel written once; no blending, no depth test, nothing culled. */
static const gl_pass_state deferred_pass = {.depth_write = false};

/* Forward+: chapter 00's two passes. The pre-pass writes the nearest depth (GL_LEQUAL: on a tie the
 * object drawn last wins, as in the G-buffer); then only the fragment that wrote it is shaded. */
static const gl_pass_state prepass = {.cull = GL_BACK, .depth_func = GL_LEQUAL, .depth_write = true};
static const gl_pass_state shade_after_prepass = {.cull = GL_BACK, .depth_func = GL_EQUAL};

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

/* The most entries a list holds: the texture buffer must address every cluster's (and --cluster-lights). */
static int list_limit(const clusters *c)
{
    GLint max_texels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &max_texels);
    int limit = max_texels / cluster_grid_count(&c->grid);
    if (c->desc.cluster_limit > 0 && c->desc.cluster_limit < limit)
        limit = c->desc.cluster_limit;
    return limit > 0 ? limit : 1;
}

/* The compute path: the CPU's candidates (per slice and tile row, the lights that may reach it), then
 * three passes over the rows, each reading what the one before wrote to its storage buffers. */
static bool assign_compute(clusters *c, int lights, int limit)
{
    const cluster_assign_buffers out = {c->range_buffer, c->range_texture, c->list_buffer, c->list_texture};
    cluster_assign_gpu *gpu = &c->gpu;
    if (!cluster_assign_gpu_prepare(gpu, &c->grid, (const float(*)[4])c->spheres, lights, limit, &out))
        return false;
    cluster_assign_gpu_use(gpu, CLUSTER_ASSIGN_COUNT); /* each row counts its clusters' lights */
    glDispatchCompute(gpu->groups, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    cluster_assign_gpu_use(gpu, CLUSTER_ASSIGN_SCAN); /* one workgroup: where each row's entries begin */
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    cluster_assign_gpu_use(gpu, CLUSTER_ASSIGN_FILL); /* each row writes its (first, count) and lists */
    glDispatchCompute(gpu->groups, 1, 1);
    /* the shading passes fetch both as texture buffers (and --assign check reads them back) */
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    cluster_assign_gpu_finish();
    return gl_check("11 light assignment");
}

/* 2. light assignment: the grid for this view, each light's bounding sphere in view space, the lists. */
bool chapter_11_assign(clusters *c, const gpu_scene *gs)
{
    frame_timer_mark("light assignment");
    const frame_view *v = &gs->view;
    /* tile_size-pixel tiles times the slices (cubic clusters unless --slices), near to far */
    cluster_grid_init(&c->grid, v->width, v->height, c->desc.tile_size, c->desc.slices, (const float *)v->proj,
                      v->near_plane, v->far_plane);
    int limit = list_limit(c);
    if (!clusters_light_spheres(c, gs))
        return false;
    if (c->desc.compute)
        return assign_compute(c, gs->light_count, limit) &&
               (!c->desc.check || clusters_check(c, gs->light_count, limit));
    if (!cluster_lists_assign(&c->lists, &c->grid, (const float(*)[4])c->spheres, gs->light_count, limit))
        return false;
    clusters_upload_lists(c); /* the CPU's lists, into the same two buffers */
    return gl_check("11 light assignment");
}

/* 3. clustered deferred: one full-screen triangle; each pixel reads the G-buffer once and loops over
 * its cluster's list (clustered_deferred.frag). */
bool chapter_11_shade_deferred(clusters *c, const gbuffer *g, const gpu_scene *gs, const gl_pass_state *pass,
                               clusters_view view)
{
    GLuint p = clusters_program(c, CLUSTERS_PROGRAM_DEFERRED);
    if (!p)
        return false;
    if (view != CLUSTERS_VIEW_COUNT) /* the count names its own pass */
        frame_timer_mark("lighting");
    gl_pass_state_apply(pass);
    clusters_use(c, gs, p, view);
    gbuffer_bind_textures(g, gs, p, SHADER_UNIT_GBUFFER);
    gl_draw_fullscreen();
    return gl_check("11 clustered deferred shading");
}

/* 3. Forward+: every opaque object once; after the pre-pass only the visible fragment passes
 * (forward_plus.frag finds its cluster from gl_FragCoord and its view depth). */
bool chapter_11_shade_forward(clusters *c, const gpu_scene *gs, const gl_pass_state *pass, clusters_view view)
{
    GLuint p = clusters_program(c, CLUSTERS_PROGRAM_FORWARD);
    if (!p)
        return false;
    if (view != CLUSTERS_VIEW_COUNT)
        frame_timer_mark("shading");
    gl_pass_state_apply(pass);
    clusters_use(c, gs, p, view);
    gpu_scene_bind_objects(gs, p, SHADER_UNIT_OBJECTS);
    gpu_scene_draw(gs, p);
    return gl_check("11 Forward+ shading");
}

/* The light-loop iterations, exactly as the shading pass ran them: the same shader in its count view
 * (g NULL: Forward+, which draws its own pre-pass there). */
static bool count_evaluations(clusters *c, const gbuffer *g, const gpu_scene *gs)
{
    if (!clusters_count_begin(c, gs))
        return false;
    bool drawn = g ? chapter_11_shade_deferred(c, g, gs, &(gl_pass_state){0}, CLUSTERS_VIEW_COUNT)
                   : clusters_draw_depth(c, gs) &&
                         chapter_11_shade_forward(c, gs, &shade_after_prepass, CLUSTERS_VIEW_COUNT);
    return clusters_count_end(c, drawn);
}

static bool count_forward_plus(clusters *c, const gpu_scene *gs) { return count_evaluations(c, NULL, gs); }

/* Forward+: 1. depth pre-pass into target (cleared); 2. light assignment. */
static bool forward_plus_prepass(clusters *c, const gpu_scene *gs, GLuint target)
{
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, gs->view.width, gs->view.height);
    gl_pass_state_apply(&prepass);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    frame_timer_mark("depth pre-pass");
    return clusters_draw_depth(c, gs) && chapter_11_assign(c, gs);
}

/* 3. every object shaded once, GL_EQUAL: only the fragment the pre-pass kept. */
static bool forward_plus_shade(clusters *c, const gpu_scene *gs, clusters_view view)
{
    return chapter_11_shade_forward(c, gs, &shade_after_prepass, view);
}

const app_forward_plus chapter_11_forward_plus = {
    .prepass = forward_plus_prepass, .shade = forward_plus_shade, .count = count_forward_plus};

/* Clustered deferred: 1. geometry pass; 2. light assignment; 3. one full-screen shading pass. */
static bool frame_deferred(app *a)
{
    if (!gbuffer_render(&state.g, &a->gs) || !chapter_11_assign(&state.c, &a->gs))
        return false;
    glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
    glViewport(0, 0, a->width, a->height);
    bool ok = chapter_11_shade_deferred(&state.c, &state.g, &a->gs, &deferred_pass, view_of(a));
    gl_pass_state_reset();
    return ok && (!a->count_pixels || count_evaluations(&state.c, &state.g, &a->gs));
}

/* Forward+: 1. depth pre-pass; 2. light assignment; 3. every object shaded once, GL_EQUAL. */
static bool frame_forward_plus(app *a)
{
    bool ok = forward_plus_prepass(&state.c, &a->gs, a->target.id) && forward_plus_shade(&state.c, &a->gs, view_of(a));
    gl_pass_state_reset();
    return ok && (!a->count_pixels || count_evaluations(&state.c, NULL, &a->gs));
}

static bool frame(app *a)
{
    if (app_renderer_is(a, "forward"))
        return app_render_forward(a);
    bool deferred = app_renderer_is(a, "deferred");
    a->pass_state = deferred ? &deferred_pass : &shade_after_prepass;
    if (!(deferred ? frame_deferred(a) : frame_forward_plus(a)))
        return false;
    a->linear_written = a->linear_output;
    /* --bench and the overlay: the light-loop iterations, counted by the same shader */
    a->shaded_pixels = a->count_pixels ? state.c.evaluations : -1;
    a->work_name = "light-loop iterations";
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
    memset(&state, 0, sizeof state); /* opened again (the benchmark does), init starts from nothing */
}

const app_desc chapter_11 = {.cli = &cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup, .key = key,
                             .takes_reversed_z = true};

CHAPTER_MAIN(chapter_11)
