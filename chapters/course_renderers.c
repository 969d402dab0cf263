/* course_renderers.c - see course_renderers.h. */
#include "course_renderers.h"

#include "chapters.h"

#include <string.h>

#define ARGS(...) ((const char *const[]){__VA_ARGS__, NULL})

const course_renderer course_renderers[COURSE_RENDERER_COUNT] = {
    {"forward", &chapter_00, ARGS("--renderer", "forward"), false}, /* depth pre-pass + light lists */
    {"forward-naive", &chapter_00, ARGS("--renderer", "forward-naive"), false}, /* every light everywhere */
    {"forward-prepass", &chapter_00, ARGS("--renderer", "forward-prepass"), false},
    {"forward-lists", &chapter_00, ARGS("--renderer", "forward-lists"), false},
    {"deferred-fullscreen", &chapter_03, ARGS("--renderer", "deferred"), true}, /* all lights per pixel */
    {"deferred-volumes", &chapter_07, ARGS("--renderer", "deferred"), true},    /* depth-tested back faces */
    /* the same with the windowed falloff: no cut-off step (its error is the model's price) */
    {"deferred-volumes-windowed", &chapter_07, ARGS("--renderer", "deferred", "--falloff", "windowed"), true},
    {"deferred-stencil", &chapter_08, ARGS("--renderer", "deferred"), true}, /* stencil light volumes */
    {"deferred-tiled", &chapter_10, ARGS("--renderer", "deferred"), true},   /* per-tile light lists */
    /* Forward+ as every chapter offers it: chapter 11's passes, with chapter 12's glass */
    {"forward-plus", &chapter_00, ARGS("--renderer", "forward-plus"), false},
    {"deferred-clustered", &chapter_11, ARGS("--renderer", "deferred"), true}, /* per-cluster lists */
};

int course_renderer_find(const char *name)
{
    for (int i = 0; name && i < COURSE_RENDERER_COUNT; i++)
        if (strcmp(course_renderers[i].name, name) == 0)
            return i;
    return -1;
}

app_embed *course_set_embed(course_set *set, int r, const gpu_scene *gs)
{
    int first = 0;
    while (course_renderers[first].chapter != course_renderers[r].chapter)
        first++;
    app_embed **e = &set->open[first];
    if (!*e) {
        app_forward_set_plus(&chapter_11_forward_plus); /* as CHAPTER_MAIN does */
        if (!app_embed_open(course_renderers[r].chapter, course_renderers[r].args, gs, e))
            return NULL;
    } else if (set->chosen[first] != r && !app_embed_choose(*e, course_renderers[r].args)) {
        return NULL;
    }
    set->chosen[first] = r;
    return *e;
}

void course_set_destroy(course_set *set)
{
    for (int i = 0; i < COURSE_RENDERER_COUNT; i++)
        app_embed_close(set->open[i]);
    memset(set, 0, sizeof *set);
}
