/* bench_renderers.c - see bench_renderers.h. */
#include "bench_renderers.h"

#include "course_renderers.h"
#include "gbuffer.h"
#include "gl_util.h"
#include "log.h"

#include <stdlib.h>
#include <string.h>

_Static_assert(COURSE_RENDERER_COUNT <= BENCH_RENDERER_MAX, "raise BENCH_RENDERER_MAX");

/* The chapters, embedded, and the benchmark's own target (until a chapter draws). */
struct bench_renderers {
    course_set chapters;
    const fbo *last; /* the target of the last frame drawn */
    fbo target;
};

int bench_renderer_count(void) { return COURSE_RENDERER_COUNT; }

const char *bench_renderer_name(int r) { return course_renderers[r].name; }

int bench_renderer_find(const char *name) { return course_renderer_find(name); }

bool bench_renderer_is_deferred(int r) { return course_renderers[r].deferred; }

static bool is(int r, const char *name) { return strcmp(course_renderers[r].name, name) == 0; }

bool bench_renderer_uses_volumes(int r) { return is(r, "deferred-volumes"); }

bool bench_renderer_uses_stencil(int r) { return is(r, "deferred-stencil"); }

bool bench_renderer_uses_tiles(int r) { return is(r, "deferred-tiled"); }

/* The naive forward loop ignores the cut-off's main effect (it loops over every light anyway). */
bool bench_renderer_in_cutoff_sweep(int r) { return !is(r, "forward-naive"); }

/* Forward-naive: the plain GL_LEQUAL pass, not the pre-pass, so where two surfaces tie in depth it
 * keeps the same one as the G-buffer pass does, and those few pixels do not count as error. */
int bench_renderer_reference(void) { return course_renderer_find("forward-naive"); }

/* Forward (pre-pass + lists): its depth pre-pass writes the exact visible depth at little cost. */
int bench_renderer_depth_source(void) { return course_renderer_find("forward"); }

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
    *out = NULL;
    /* Zeroed, so that destroy undoes a create that stopped half way. */
    bench_renderers *br = calloc(1, sizeof *br);
    if (!br) {
        log_error("out of memory for the renderers");
        return false;
    }
    if (!fbo_create(&br->target, &target, width, height)) {
        bench_renderers_destroy(br);
        return false;
    }
    br->last = &br->target;
    *out = br;
    return true;
}

void bench_renderers_destroy(bench_renderers *br)
{
    if (!br)
        return;
    course_set_destroy(&br->chapters);
    fbo_destroy(&br->target);
    free(br);
}

void bench_renderers_close_chapters(bench_renderers *br)
{
    course_set_destroy(&br->chapters);
    br->last = &br->target;
}

const fbo *bench_renderers_target(const bench_renderers *br) { return br->last; }

bool bench_renderers_read_target(const bench_renderers *br, image *out)
{
    if (!image_create(out, br->last->width, br->last->height))
        return false;
    bool ok = fbo_read_rgba8(br->last, 0, out->pixels);
    image_flip_rows(out); /* images are top row first */
    return ok;
}

bool bench_render_frame(bench_renderers *br, int r, const gpu_scene *gs, bool count, bench_frame_work *work)
{
    app_embed *e = course_set_embed(&br->chapters, r, gs);
    app_embed_work w = {-1, 1.0};
    bool ok = e && app_embed_frame(e, gs, count, &w);
    if (e)
        br->last = app_embed_target(e);
    if (work)
        *work = (bench_frame_work){w.shaded, w.lights_per_pixel};
    return ok;
}

bool bench_read_linear(bench_renderers *br, int r, const gpu_scene *gs, float *rgba)
{
    app_embed *e = course_set_embed(&br->chapters, r, gs);
    return e && app_embed_read_linear(e, gs, rgba);
}
