/* bench_renderers.c - see bench_renderers.h. */
#include "bench_renderers.h"

#include "gbuffer.h"
#include "gl_util.h"
#include "log.h"
#include "renderers.h"

#include <stdlib.h>
#include <string.h>

_Static_assert(RENDERER_COUNT <= BENCH_RENDERER_MAX, "raise BENCH_RENDERER_MAX");

/* The course's renderer table (common/renderers.c) and the benchmark's two targets. */
struct bench_renderers {
    renderer_set set;
    fbo target, linear_target;
};

int bench_renderer_count(void) { return RENDERER_COUNT; }

const char *bench_renderer_name(int r) { return renderer_table[r].name; }

int bench_renderer_find(const char *name) { return renderer_find(name); }

bool bench_renderer_is_deferred(int r) { return !renderer_table[r].forward; }

bool bench_renderer_uses_volumes(int r) { return r == RENDERER_DEFERRED_VOLUMES; }

bool bench_renderer_uses_stencil(int r) { return r == RENDERER_DEFERRED_STENCIL; }

bool bench_renderer_uses_tiles(int r) { return r == RENDERER_DEFERRED_TILED; }

/* The naive forward loop ignores the cut-off's main effect (it loops over every light anyway). */
bool bench_renderer_in_cutoff_sweep(int r) { return r != RENDERER_FORWARD_NAIVE; }

/* Forward-naive: the plain GL_LEQUAL pass, not the pre-pass, so where two surfaces tie in depth it
 * keeps the same one as the G-buffer pass does, and those few pixels do not count as error. */
int bench_renderer_reference(void) { return RENDERER_FORWARD_NAIVE; }

/* Forward (pre-pass + lists): its depth pre-pass writes the exact visible depth at little cost. */
int bench_renderer_depth_source(void) { return RENDERER_FORWARD; }

int bench_renderer_gbuffer_bytes(void)
{
    return gbuffer_bytes_per_pixel();
}

int bench_renderer_gbuffer_naive_bytes(void)
{
    return GBUFFER_NAIVE_BYTES;
}

/* A float depth buffer, so that the depth read back for the ideal work is the exact one. */
static fbo_desc target_desc(GLenum color_format, const char *name)
{
    return (fbo_desc){.color_formats = {color_format},
                      .color_count = 1,
                      .depth_format = GL_DEPTH_COMPONENT32F,
                      .name = name};
}

bool bench_renderers_create(int width, int height, bench_renderers **out)
{
    const fbo_desc target = target_desc(GL_RGBA8, "target");
    const fbo_desc linear = target_desc(GL_RGBA32F, "linear target");
    *out = NULL;
    /* Zeroed, so that destroy undoes a create that stopped half way. */
    bench_renderers *br = calloc(1, sizeof *br);
    if (!br) {
        log_error("out of memory for the renderers");
        return false;
    }
    renderers_create(&br->set);
    if (!fbo_create(&br->target, &target, width, height) || !fbo_create(&br->linear_target, &linear, width, height)) {
        bench_renderers_destroy(br);
        return false;
    }
    *out = br;
    return true;
}

void bench_renderers_destroy(bench_renderers *br)
{
    if (!br)
        return;
    fbo_destroy(&br->linear_target);
    fbo_destroy(&br->target);
    renderers_destroy(&br->set);
    free(br);
}

const fbo *bench_renderers_target(const bench_renderers *br) { return &br->target; }

bool bench_renderers_read_target(const bench_renderers *br, image *out)
{
    if (!image_create(out, br->target.width, br->target.height))
        return false;
    bool ok = fbo_read_rgba8(&br->target, 0, out->pixels);
    image_flip_rows(out); /* images are top row first */
    return ok;
}

bool bench_render_frame(bench_renderers *br, int r, const gpu_scene *gs, bool count, bench_frame_work *work)
{
    renderer_result res;
    bool ok = renderers_draw(&br->set, (renderer_id)r, gs, br->target.id, (renderer_draw_options){.count_pixels = count},
                             &res);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (work)
        *work = (bench_frame_work){res.shaded, res.lights_per_pixel};
    return ok;
}

bool bench_read_linear(bench_renderers *br, int r, const gpu_scene *gs, float *rgba)
{
    const fbo *src = &br->linear_target;
    if (r == RENDERER_DEFERRED_FULLSCREEN || r == RENDERER_DEFERRED_TILED)
        return false; /* display-encodes in its only shader */
    if (r == RENDERER_DEFERRED_VOLUMES || r == RENDERER_DEFERRED_VOLUMES_WINDOWED ||
        r == RENDERER_DEFERRED_STENCIL)
        src = renderers_accum(&br->set); /* the RGBA16F sum of the last frame, before present */
    else if (!renderers_draw(&br->set, (renderer_id)r, gs, src->id, (renderer_draw_options){.linear_output = true},
                             NULL))
        return false;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, src->id);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, src->width, src->height, GL_RGBA, GL_FLOAT, rgba);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return gl_check("read_linear");
}
