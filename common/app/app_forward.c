/* app_forward.c - see app_forward.h. */
#include "app_forward.h"

#include <string.h>

bool app_forward_is(const char *name)
{
    return name && (forward_variant_find(name) || strcmp(name, "forward-plus") == 0);
}

static bool need_forward(app_forward *f)
{
    return f->have_fwd || (f->have_fwd = forward_create(&f->fwd));
}

/* Chapter 00's frame with the variant's optimisations. */
static bool draw_variant(app_forward *f, const forward_options *variant, const gpu_scene *gs, GLuint target,
                         app_forward_options o, app_forward_work *out)
{
    forward_options fo = *variant;
    fo.count_pixels = o.count_pixels;
    fo.linear_output = o.linear_output;
    if (!need_forward(f) || !forward_render(&f->fwd, gs, target, fo))
        return false;
    out->shaded = o.count_pixels ? forward_shaded_pixels(&f->fwd) : -1;
    out->lights_per_pixel = fo.light_lists && gs->src->object_count > 0
                                ? (double)f->fwd.list_entries / gs->src->object_count
                                : gs->light_count;
    return true;
}

/* Chapter 11's Forward+, its lists made as the chapter makes them by default. */
static bool draw_forward_plus(app_forward *f, const gpu_scene *gs, GLuint target, app_forward_options o,
                              app_forward_work *out)
{
    const clusters_desc lists = {.compute = gl_have_compute()};
    if (!f->have_clusters && !(f->have_clusters = clusters_create(&f->c, &lists)))
        return false;
    if (gs->transparent_count > 0 && !need_forward(f)) /* glass goes through forward's linear frame */
        return false;
    clusters_view view = o.linear_output ? CLUSTERS_VIEW_LINEAR : CLUSTERS_VIEW_LIT;
    if (!clusters_render_forward_plus(&f->c, f->have_fwd ? &f->fwd : NULL, gs, target, view) ||
        (o.count_pixels && !clusters_count(&f->c, NULL, gs)))
        return false;
    out->shaded = o.count_pixels ? f->c.evaluations : -1;
    out->lights_per_pixel = 1.0; /* shaded counts the light-loop iterations */
    return true;
}

bool app_forward_draw(app_forward *f, const char *name, const gpu_scene *gs, GLuint target,
                      app_forward_options options, app_forward_work *out)
{
    app_forward_work work = {-1, 1.0};
    const forward_options *variant = forward_variant_find(name);
    bool ok = name && strcmp(name, "forward-plus") == 0
                  ? draw_forward_plus(f, gs, target, options, &work)
                  : draw_variant(f, variant ? variant : &forward_variants[0].options, gs, target, options, &work);
    if (out)
        *out = work;
    return ok;
}

void app_forward_destroy(app_forward *f)
{
    if (f->have_clusters)
        clusters_destroy(&f->c);
    if (f->have_fwd)
        forward_destroy(&f->fwd);
    memset(f, 0, sizeof *f);
}
