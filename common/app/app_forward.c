/* app_forward.c - see app_forward.h. */
#include "app_forward.h"

#include "log.h"

#include <string.h>

static const app_forward_plus *forward_plus; /* chapter 11's, set by CHAPTER_MAIN */

void app_forward_set_plus(const app_forward_plus *plus) { forward_plus = plus; }

void app_forward_set_extra(app_forward *f, const gl_program_extra *extra)
{
    f->extra = extra ? *extra : (gl_program_extra){0};
    if (f->have_fwd) /* made already: from the next draw on (each variant's programs built once) */
        forward_set_extra(&f->fwd, &f->extra);
    if (f->have_clusters)
        clusters_set_extra(&f->c, &f->extra);
}

bool app_forward_is(const char *name)
{
    return name && (forward_variant_find(name) || strcmp(name, "forward-plus") == 0);
}

static bool need_forward(app_forward *f)
{
    return f->have_fwd || (f->have_fwd = forward_create_with(&f->fwd, &f->extra));
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
    out->lights_per_pixel = forward_lights_per_pixel(&f->fwd, gs, fo.light_lists);
    return true;
}

/* The opaque frame in linear radiance, then chapter 12's glass over it with the same lists. */
static bool shade_forward_plus_glass(void *user, const gpu_scene *gs)
{
    app_forward *f = user;
    return forward_plus->shade(&f->c, gs, CLUSTERS_VIEW_LINEAR) &&
           clusters_shade_glass(&f->c, gs, forward_glass_passes, 2, GPU_SCENE_BACK_TO_FRONT, CLUSTERS_VIEW_LINEAR);
}

/* Chapter 11's Forward+, its lists made as the chapter makes them by default; a scene with glass
 * blends it in linear radiance: straight into a float target, else through forward's linear frame. */
static bool draw_forward_plus(app_forward *f, const gpu_scene *gs, GLuint target, app_forward_options o,
                              app_forward_work *out)
{
    if (!forward_plus) {
        log_error("Forward+ is chapter 11's: this program did not link it (chapters/chapters.h)");
        return false;
    }
    const clusters_desc lists = {.compute = gl_have_compute(), .extra = f->extra};
    bool glass = gs->transparent_count > 0;
    if ((!f->have_clusters && !(f->have_clusters = clusters_create(&f->c, &lists))) || (glass && !need_forward(f)))
        return false;
    bool ok = forward_plus->prepass(&f->c, gs, target) &&
              (!glass                ? forward_plus->shade(&f->c, gs, o.linear_output ? CLUSTERS_VIEW_LINEAR
                                                                                  : CLUSTERS_VIEW_LIT)
               : o.linear_output ? shade_forward_plus_glass(f, gs)
                                 : forward_draw_linear(&f->fwd, gs, shade_forward_plus_glass, f));
    gl_pass_state_reset();
    if (!ok || (o.count_pixels && !forward_plus->count(&f->c, gs)))
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
