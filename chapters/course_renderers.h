/* course_renderers.h - the renderers the benchmark compares and the tests name, each a chapter with
 * arguments (a row: chapter_NN and what --renderer, --falloff choose in it), so that what is
 * measured is what the chapter draws. The benchmark's CSV rows and the docs use these names.
 *
 *   course_renderer_find(name)    its index in course_renderers, or -1
 *   course_set_embed(set, r, gs)  renderer r's chapter, embedded (app_embed.h) on first use at gs's
 *                                 size and set to r's arguments; the rows of one chapter share one
 *                                 (a chapter is open once at a time); NULL on failure (logged)
 *   course_set_destroy(set)       every chapter the set opened
 */
#ifndef CHAPTERS_COURSE_RENDERERS_H
#define CHAPTERS_COURSE_RENDERERS_H

#include "app_embed.h"

typedef struct course_renderer {
    const char *name;
    const app_desc *chapter;
    const char *const *args; /* NULL-terminated, without the program name */
    bool deferred;           /* lights from a G-buffer */
} course_renderer;

enum { COURSE_RENDERER_COUNT = 11 };
extern const course_renderer course_renderers[COURSE_RENDERER_COUNT];

/* The chapters a caller has open, zero-initialised. */
typedef struct course_set {
    app_embed *open[COURSE_RENDERER_COUNT]; /* at the index of the first row of each chapter */
    int chosen[COURSE_RENDERER_COUNT];      /* the row each is set to */
} course_set;

int course_renderer_find(const char *name);
app_embed *course_set_embed(course_set *set, int r, const gpu_scene *gs);
void course_set_destroy(course_set *set);

#endif
