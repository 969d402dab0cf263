/* app_embed.h - a chapter driven in-process, without its main(): how the benchmark and the tests run
 * the chapters themselves instead of copies of their frames. The caller owns the GL context and the
 * scene; the chapter owns its passes, as when it runs as its own program.
 *
 *   app_embed_open(desc, args, gs, out)  the chapter `desc` (chapters/chapters.h: chapter_NN) with
 *                                        its command-line arguments `args` (NULL-terminated, without
 *                                        the program name: --renderer, --view, --falloff and the
 *                                        chapter's own options), at the size of gs's view; runs its
 *                                        init. A chapter keeps its passes in file-static state, so
 *                                        one chapter is open once at a time (a second open fails).
 *                                        --gbuffer LAYOUT sets the layout of every G-buffer made from
 *                                        then on, as the runner does (gbuffer_set_default_layout: it
 *                                        stays set after the chapter closes)
 *   app_embed_choose(e, args)            other arguments for the next frames: those a learner switches
 *                                        at run time (--renderer, --view, --falloff); the chapter's
 *                                        own options are read by its init and must stay as opened
 *   app_embed_frame(e, gs, count, work)  one frame of gs (already updated by the caller) into the
 *                                        chapter's target; with count, its lighting work into *work
 *                                        (may be NULL): the fragments it counted (-1: none) and the
 *                                        lights each loops over
 *   app_embed_target(e)                  that target: RGBA8 display-encoded colour + 32-bit float
 *                                        depth, the exact depth of the visible surface
 *   app_embed_read_linear(e, gs, rgba)   the linear radiance of the frame (width x height RGBA
 *                                        floats, bottom row first): the chapter's sum before its
 *                                        present pass, or the frame drawn again with linear output;
 *                                        false when it has neither (it display-encodes in its only
 *                                        shader)
 *   app_embed_close(e)                   its cleanup; NULL is fine
 */
#ifndef COMMON_APP_EMBED_H
#define COMMON_APP_EMBED_H

#include "app.h"

typedef struct app_embed app_embed;

typedef struct app_embed_work {
    long shaded;             /* what the chapter counted (--bench's shaded_pixels); -1: not counted */
    double lights_per_pixel; /* lights each of them loops over */
} app_embed_work;

bool app_embed_open(const app_desc *desc, const char *const *args, const gpu_scene *gs, app_embed **out);
bool app_embed_choose(app_embed *e, const char *const *args);
bool app_embed_frame(app_embed *e, const gpu_scene *gs, bool count, app_embed_work *work);
const fbo *app_embed_target(const app_embed *e);
bool app_embed_read_linear(app_embed *e, const gpu_scene *gs, float *rgba);
void app_embed_close(app_embed *e);

#endif
