/* app_forward.h - the forward renderers every chapter can switch to (--renderer, the R key, compare
 * mode): chapter 00's four (forward.h's forward_variants) and chapter 11's Forward+ (clusters.h).
 * The runner owns one; its GL objects are made the first time a renderer draws. Forward+'s passes are
 * chapter 11's, written there once: the runner reaches them through app_forward_set_plus, which
 * chapters/chapters.h's CHAPTER_MAIN (and the embedding library) call before anything draws.
 *
 *   app_forward_set_plus(plus)          Forward+'s frame and count (chapter_11_forward_plus)
 *   app_forward_set_extra(f, extra)     a chapter's additions to every forward renderer's shading
 *                                       programs (chapter 14's shadows in chapters 15, 16 and 18),
 *                                       from the next draw on (NULL: none): their defines, and the
 *                                       bind called on each program before it draws
 *   app_forward_is(name)                whether name is one of them ("forward", "forward-naive",
 *                                       "forward-prepass", "forward-lists", "forward-plus")
 *   app_forward_draw(f, name, gs, target, options, out)
 *                                       one frame of renderer `name` ("forward" when it is none of
 *                                       them) into the framebuffer `target`; out (may be NULL): its
 *                                       shading work
 *   app_forward_destroy(f)
 */
#ifndef COMMON_APP_FORWARD_H
#define COMMON_APP_FORWARD_H

#include "clusters.h"
#include "forward.h"

typedef struct app_forward {
    forward fwd;
    clusters c; /* Forward+'s lists, chapter 11's defaults (compute where the context has it) */
    bool have_fwd, have_clusters;
    gl_program_extra extra; /* app_forward_set_extra's; none by default */
} app_forward;

typedef struct app_forward_options {
    bool count_pixels;  /* the shading pass's work into out */
    bool linear_output; /* linear radiance, for a float target */
} app_forward_options;

/* Forward+'s passes, as chapter 11 draws them: the depth pre-pass into `target` (cleared) and the
 * light assignment; the shading of the opaque objects after it (into the framebuffer bound); the
 * light-loop iterations of the last frame into c->evaluations. */
typedef struct app_forward_plus {
    bool (*prepass)(clusters *c, const gpu_scene *gs, GLuint target);
    bool (*shade)(clusters *c, const gpu_scene *gs, clusters_view view);
    bool (*count)(clusters *c, const gpu_scene *gs);
} app_forward_plus;

typedef struct app_forward_work {
    long shaded;             /* fragments shaded (Forward+: light-loop iterations); -1: not counted */
    double lights_per_pixel; /* lights each of them loops over (lists: the mean length) */
} app_forward_work;

void app_forward_set_plus(const app_forward_plus *plus);
void app_forward_set_extra(app_forward *f, const gl_program_extra *extra);
bool app_forward_is(const char *name);
bool app_forward_draw(app_forward *f, const char *name, const gpu_scene *gs, GLuint target,
                      app_forward_options options, app_forward_work *out);
void app_forward_destroy(app_forward *f);

#endif
