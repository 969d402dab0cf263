/* 10_tiled_deferred.c - tiled deferred shading: the screen in 16x16-pixel tiles, a list per tile of
 * the lights that can reach it, and ONE full-screen pass that reads each pixel's G-buffer once and
 * adds up its tile's lights in registers, writing the pixel once. Compare with chapter 07, whose
 * volumes read the G-buffer again and blend into an accumulation buffer for every light on a pixel.
 *
 * Taken over: the G-buffer pass (02), shade_light() with its spots (00, 09), the heat map (03). New:
 *   2. tile depth bounds: the nearest and farthest surface of each tile, in view depth; background
 *      pixels do not count (a tile of background only gets no lights at all)
 *   3. light culling: a light joins a tile's list when its bounding sphere (a spot's: the sphere
 *      around its cone) reaches the tile's frustum between those depths (shaders/tiled_cull.glsl)
 *   4. shading: shaders/tiled_shade.frag loops over the tile's list; no blending, no sum buffer
 * Two paths make the lists; the shading pass is the same for both:
 *   --path compute (GL 4.3): shaders/tiled_cull.comp, one 16x16 workgroup per tile, finds the depth
 *     bounds with shared-memory atomics and tests the lights, each invocation a run of them
 *     (glDispatchCompute); the shading pass reads what it wrote after a glMemoryBarrier
 *   --path cpu (GL 3.3): a reduction pass draws one fragment per tile into an RGBA32F target
 *     (tile_depth_bounds.frag reads the tile's pixels), read back; the CPU puts each light into the
 *     tiles of its screen rectangle that it reaches and uploads the lists as texture buffers
 * Both lists are in light order and never leave out a light that reaches a pixel of the tile; a
 * light that reaches none adds exactly 0, so both paths draw the same picture, byte for byte (the L
 * key switches between them). --tile-lights N: a tile with more lights loops over every light
 * (slower, never wrong). --view overdraw: the light-loop iterations per pixel; --view tiles: each
 * tile's list length. Read docs/10_tiled_deferred.md alongside.
 */
#include "app.h"
#include "chapters.h"
#include "gbuffer.h"
#include "gl_program.h"
#include "light_batches.h"
#include "tile_cull.h"

#include <stdlib.h>
#include <string.h>

enum { TILE_SIZE = 16, VIEW_TILES = 3 }; /* VIEW_TILES: a u_view_mode beside SHADER_VIEW_* */
#define TILED_DEFINES "TILE_SIZE 16\nVIEW_TILES 3"

static const char *const renderers[] = {"deferred", "forward", NULL};
static const char *const views[] = {"lit", "overdraw", "tiles", NULL};
static const char *const paths[] = {"compute", "cpu", NULL};

/* What this chapter adds to the shared command line (--help prints it). */
static const cli_desc cli = {
    .program = "10_tiled_deferred",
    .summary = "Chapter 10: tiled deferred shading: per-tile light lists, one shading pass.",
    .renderers = renderers,
    .views = views,
    .extras =
        {
            {"path", "PATH", "light lists made by a compute shader (GL 4.3) or on the CPU (GL 3.3); default: "
                             "compute where the context has it", paths, NULL},
            {"tile-lights", "N", "most lights a tile's list holds; a tile with more loops over all of them "
                                 "(default: no limit)", NULL, NULL, CLI_WHOLE, 1, 1 << 30},
        },
};

/* The shading pass writes every pixel once: no blending, no depth test, nothing culled. */
static const gl_pass_state shading_pass = {.depth_write = false};

static struct {
    gbuffer g;
    bool compute;                   /* --path compute */
    int tile_limit;                 /* --tile-lights; 0: none */
    int tiles_x, tiles_y, capacity; /* capacity: list entries per tile */
    GLuint cull_program;            /* compute: tiled_cull.comp */
    GLuint bounds_program;          /* cpu: tile_depth_bounds.frag, drawn into `bounds` */
    fbo bounds;                     /* cpu: per tile, RGBA32F: nearest, farthest, covered pixels */
    GLuint shade_program;           /* tiled_shade.frag */
    GLuint list_buffer, list_texture;     /* the light indices (R32I) */
    GLuint range_buffer, range_texture;   /* per tile: first, count or -1, covered pixels (RGBA32I) */
    GLuint sphere_buffer, sphere_texture; /* each light's bounding sphere, view space (RGBA32F) */
    vec4 *spheres;
    float *tile_bounds;     /* cpu: the bounds read back */
    tile_frustum *frustums; /* cpu: per tile */
    int *ranges, *list;     /* cpu: what goes into range_buffer and list_buffer */
} state;
static GLuint *const buffers[] = {&state.list_buffer, &state.range_buffer, &state.sphere_buffer};
static GLuint *const textures[] = {&state.list_texture, &state.range_texture, &state.sphere_texture};

/* Tiles for the target's size, and room for `lights` lights in every tile's list (unless
 * --tile-lights, or the largest texture buffer, says fewer: such a tile loops over every light). */
static bool size_tiles(const app *a, int lights)
{
    int tiles_x = (a->width + TILE_SIZE - 1) / TILE_SIZE, tiles_y = (a->height + TILE_SIZE - 1) / TILE_SIZE;
    int tiles = tiles_x * tiles_y, capacity = lights > 0 ? lights : 1;
    GLint max_texels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &max_texels);
    if (state.tile_limit > 0 && state.tile_limit < capacity)
        capacity = state.tile_limit;
    capacity = capacity < max_texels / tiles ? capacity : max_texels / tiles;
    if (tiles_x == state.tiles_x && tiles_y == state.tiles_y && capacity == state.capacity)
        return true;
    state.tiles_x = tiles_x, state.tiles_y = tiles_y, state.capacity = capacity;
    state.tile_bounds = realloc(state.tile_bounds, (size_t)tiles * 4 * sizeof(float));
    state.ranges = realloc(state.ranges, (size_t)tiles * 4 * sizeof(int));
    state.frustums = realloc(state.frustums, (size_t)tiles * sizeof *state.frustums);
    fbo_destroy(&state.bounds);
    const fbo_desc bounds = {.color_formats = {GL_RGBA32F}, .color_count = 1, .name = "tile bounds"};
    if (!state.tile_bounds || !state.ranges || !state.frustums || !fbo_create(&state.bounds, &bounds, tiles_x, tiles_y))
        return false;
    if (state.compute) { /* room for what the compute shader writes: every tile's whole list */
        gl_texture_buffer_upload(state.list_buffer, state.list_texture, GL_R32I, NULL,
                                 (size_t)tiles * (size_t)capacity * sizeof(int));
        gl_texture_buffer_upload(state.range_buffer, state.range_texture, GL_RGBA32I, NULL,
                                 (size_t)tiles * 4 * sizeof(int));
    }
    return gl_check("10 size_tiles");
}

/* Each light's bounding sphere in view space, once per frame: a point light's own; a spot's, the
 * smallest around its cone (tile_sphere, the C twin of shaders/tiled_cull.glsl). */
static bool light_spheres(const gpu_scene *gs)
{
    int n = gs->light_count > 0 ? gs->light_count : 1;
    if (!(state.spheres = realloc(state.spheres, (size_t)n * sizeof(vec4))))
        return false;
    for (int i = 0; i < gs->light_count; i++)
        tile_sphere(&gs->lights[i], &gs->view, state.spheres[i]);
    if (state.compute) /* the compute shader reads them as a texture buffer */
        gl_texture_buffer_upload(state.sphere_buffer, state.sphere_texture, GL_RGBA32F, state.spheres,
                                 (size_t)n * sizeof(vec4));
    return true;
}

/* 2 + 3 on the GPU, one dispatch: each workgroup finds its tile's depth bounds and lights. */
static bool cull_compute(app *a)
{
    frame_timer_mark("tile culling");
    if (!state.cull_program && !(state.cull_program = gl_compute_program_load("tiled_cull.comp", TILED_DEFINES)))
        return false;
    GLuint p = state.cull_program;
    glUseProgram(p);
    gbuffer_bind_textures(&state.g, &a->gs, p, SHADER_UNIT_GBUFFER);
    tile_bind_view(p, &a->gs.view);
    gl_texture_buffer_bind(p, "u_light_spheres", SHADER_UNIT_LIGHTS, state.sphere_texture);
    glUniform1i(glGetUniformLocation(p, "u_light_count"), a->gs.light_count);
    glUniform1i(glGetUniformLocation(p, "u_tile_capacity"), state.capacity);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, state.list_buffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, state.range_buffer);
    glDispatchCompute((GLuint)state.tiles_x, (GLuint)state.tiles_y, 1);
    /* The shading pass fetches the lists as texture buffers; --bench reads the ranges back. */
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    return gl_check("10 tile culling");
}

/* 2. tile depth bounds, GL 3.3: one fragment per tile reads its pixels; the CPU reads the result. */
static bool depth_bounds_reduce(app *a)
{
    frame_timer_mark("tile depth bounds");
    glBindFramebuffer(GL_FRAMEBUFFER, state.bounds.id);
    glViewport(0, 0, state.tiles_x, state.tiles_y);
    gl_pass_state_apply(&shading_pass);
    glUseProgram(state.bounds_program);
    gbuffer_bind_textures(&state.g, &a->gs, state.bounds_program, SHADER_UNIT_GBUFFER);
    tile_bind_view(state.bounds_program, &a->gs.view);
    gl_draw_fullscreen();
    gl_read_rgba_float(state.bounds.id, 0, state.tiles_x, state.tiles_y, state.tile_bounds); /* the read-back */
    gl_pass_state_reset();
    return gl_check("10 tile depth bounds");
}

/* 3. light culling on the CPU, with the C twin of shaders/tiled_cull.glsl (tile_cull.h): two
 * sweeps over the lights, each over the tiles of its screen rectangle (light_batches_rect, chapter
 * 08): count every tile's lights; then, each tile's first entry known (w: where its next one goes),
 * write them, in light order. */
static bool cull_cpu(app *a)
{
    frame_timer_mark("light culling");
    const frame_view *v = &a->gs.view;
    int tiles = state.tiles_x * state.tiles_y, entries = 0;
    for (int t = 0; t < tiles; t++) {
        int x = t % state.tiles_x * TILE_SIZE, y = t / state.tiles_x * TILE_SIZE;
        tile_frustum_make(v, x, y, TILE_SIZE, &state.tile_bounds[4 * t], &state.frustums[t]);
        int *range = &state.ranges[4 * t];
        range[0] = range[1] = range[3] = 0, range[2] = (int)state.tile_bounds[4 * t + 2];
    }
    for (int sweep = 0; sweep < 2; sweep++) {
        for (int i = 0; i < a->gs.light_count; i++) {
            const gpu_light *l = &a->gs.lights[i];
            int px[4] = {0, 0, v->width - 1, v->height - 1};
            if (l->radius < 1e30f)
                light_batches_rect(v, l->position, l->radius, px);
            for (int ty = px[1] / TILE_SIZE; ty <= px[3] / TILE_SIZE; ty++) {
                for (int tx = px[0] / TILE_SIZE; tx <= px[2] / TILE_SIZE; tx++) {
                    int t = ty * state.tiles_x + tx, *range = &state.ranges[4 * t];
                    if (range[2] == 0 || !tile_sphere_visible(&state.frustums[t], state.spheres[i]))
                        continue; /* background only, or out of reach */
                    if (sweep == 0)
                        range[1]++;
                    else if (range[1] >= 0)
                        state.list[range[3]++] = i;
                }
            }
        }
        for (int t = 0; sweep == 0 && t < tiles; t++) { /* over capacity: no entries, every light */
            int *range = &state.ranges[4 * t];
            range[0] = range[3] = entries;
            range[1] = range[1] <= state.capacity ? range[1] : -1;
            entries += range[1] > 0 ? range[1] : 0;
        }
        if (sweep == 0 && !(state.list = realloc(state.list, (size_t)(entries + 1) * sizeof(int))))
            return false;
    }
    gl_texture_buffer_upload(state.range_buffer, state.range_texture, GL_RGBA32I, state.ranges,
                             (size_t)tiles * 4 * sizeof(int));
    gl_texture_buffer_upload(state.list_buffer, state.list_texture, GL_R32I, state.list,
                             (size_t)(entries + 1) * sizeof(int));
    return gl_check("10 light culling");
}

/* 4. shading: every pixel once, its tile's lights added up in the shader. */
static bool shade(app *a)
{
    frame_timer_mark("lighting");
    GLuint p = state.shade_program;
    glBindFramebuffer(GL_FRAMEBUFFER, a->target.id);
    glViewport(0, 0, a->width, a->height);
    gl_pass_state_apply(&shading_pass);
    glUseProgram(p);
    gpu_scene_bind_lights(&a->gs, p, SHADER_UNIT_LIGHTS);
    gbuffer_bind_textures(&state.g, &a->gs, p, SHADER_UNIT_GBUFFER);
    gl_texture_buffer_bind(p, "u_tile_lights", SHADER_UNIT_LIGHT_LIST, state.list_texture);
    gl_texture_buffer_bind(p, "u_tile_ranges", SHADER_UNIT_LIGHT_INDEX, state.range_texture);
    glUniform1i(glGetUniformLocation(p, "u_tiles_x"), state.tiles_x);
    int mode = app_view_is(a, "overdraw") ? SHADER_VIEW_OVERDRAW : app_view_is(a, "tiles") ? VIEW_TILES : SHADER_VIEW_LIT;
    glUniform1i(glGetUniformLocation(p, "u_view_mode"), mode);
    gl_draw_fullscreen();
    gl_pass_state_reset();
    return gl_check("10 shading");
}

/* The light-loop iterations of the frame: every covered pixel loops over its tile's whole list. */
static long light_evaluations(const app *a)
{
    int tiles = state.tiles_x * state.tiles_y;
    if (state.compute) /* the compute shader's ranges, read back */
        gl_buffer_read(state.range_buffer, (size_t)tiles * 4 * sizeof(int), state.ranges);
    long sum = 0;
    for (const int *r = state.ranges; r < state.ranges + 4 * tiles; r += 4)
        sum += (long)r[2] * (r[1] < 0 ? a->gs.light_count : r[1]);
    return sum;
}

static bool init(app *a)
{
    double limit = 0;
    if ((app_extra(a, "tile-lights") && !app_extra_number(a, "tile-lights", 1, 1 << 30, &limit)) ||
        !app_extra_compute(a, "path", &state.compute))
        return false;
    state.tile_limit = (int)limit;
    a->pass_state = &shading_pass; /* the overlay shows it */
    state.shade_program = gl_program_load("fullscreen.vert", "tiled_shade.frag", TILED_DEFINES);
    state.bounds_program = gl_program_load("fullscreen.vert", "tile_depth_bounds.frag", TILED_DEFINES);
    for (int i = 0; i < 3; i++)
        *buffers[i] = gl_buffer_create(), *textures[i] = gl_texture_create();
    return state.shade_program && state.bounds_program && gbuffer_create(&state.g, a->width, a->height);
}

static bool resize(app *a) { return gbuffer_resize(&state.g, a->width, a->height); }

static bool frame(app *a)
{
    if (!app_renderer_is(a, "deferred"))
        return app_render_forward(a);
    /* 1. geometry pass */
    if (!gbuffer_render(&state.g, &a->gs) || !size_tiles(a, a->gs.light_count) || !light_spheres(&a->gs))
        return false;
    /* 2. tile depth bounds and 3. light culling: one dispatch, or a reduction pass and the CPU */
    bool ok = state.compute ? cull_compute(a) : depth_bounds_reduce(a) && cull_cpu(a);
    /* 4. shading */
    if (!ok || !shade(a))
        return false;
    a->shaded_pixels = a->count_pixels ? light_evaluations(a) : -1;
    a->work_name = "light-loop iterations";
    return true;
}

/* L: the lists made by the compute shader or on the CPU; the picture stays the same. */
static bool key(app *a, int k)
{
    (void)a;
    if (k == 'L') /* then size_tiles again: the compute path's buffers hold every tile's whole list */
        app_toggle_compute(&state.compute, "tile lists"), state.capacity = 0;
    return k == 'L';
}

static void cleanup(app *a)
{
    (void)a;
    GLuint *programs[] = {&state.cull_program, &state.shade_program, &state.bounds_program};
    for (int i = 0; i < 3; i++)
        gl_program_destroy(programs[i]), gl_buffer_destroy(buffers[i]), gl_texture_destroy(textures[i]);
    fbo_destroy(&state.bounds), gbuffer_destroy(&state.g);
    free(state.spheres), free(state.tile_bounds), free(state.frustums), free(state.ranges), free(state.list);
    memset(&state, 0, sizeof state); /* opened again (the benchmark does), init starts from nothing */
}

const app_desc chapter_10 = {.cli = &cli, .init = init, .resize = resize, .frame = frame, .cleanup = cleanup, .key = key};

CHAPTER_MAIN(chapter_10)
