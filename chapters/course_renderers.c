/* course_renderers.c - see course_renderers.h. */
#include "course_renderers.h"

#include "chapters.h"

#include <string.h>

#define ARGS(...) ((const char *const[]){__VA_ARGS__, NULL})

const course_renderer course_renderers[COURSE_RENDERER_COUNT] = {
    {"forward", &chapter_00, ARGS("--renderer", "forward"), "depth pre-pass + per-object light lists", false},
    {"forward-naive", &chapter_00, ARGS("--renderer", "forward-naive"), "every object with every light", false},
    {"forward-prepass", &chapter_00, ARGS("--renderer", "forward-prepass"), "depth pre-pass only", false},
    {"forward-lists", &chapter_00, ARGS("--renderer", "forward-lists"), "per-object light lists only", false},
    {"deferred-fullscreen", &chapter_03, ARGS("--renderer", "deferred"),
     "one full-screen pass, all lights per pixel", true},
    {"deferred-volumes", &chapter_07, ARGS("--renderer", "deferred"),
     "depth-tested back faces of one sphere per light", true},
    {"deferred-volumes-windowed", &chapter_07, ARGS("--renderer", "deferred", "--falloff", "windowed"),
     "deferred-volumes with the windowed falloff: no cut-off step", true},
    {"deferred-stencil", &chapter_08, ARGS("--renderer", "deferred"),
     "per batch of lights, a stencil pass, then light where it is set", true},
    {"deferred-tiled", &chapter_10, ARGS("--renderer", "deferred"),
     "per-tile light lists, one pass reading the G-buffer once per pixel", true},
    /* Forward+ as every chapter offers it (chapter 11's passes, glass included, chapter 12) */
    {"forward-plus", &chapter_00, ARGS("--renderer", "forward-plus"),
     "clustered forward: depth pre-pass, each fragment loops over its cluster's lights", false},
    {"deferred-clustered", &chapter_11, ARGS("--renderer", "deferred"),
     "per-cluster light lists, one pass reading the G-buffer once per pixel", true},
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
    app_forward_set_plus(&chapter_11_forward_plus); /* as CHAPTER_MAIN does */
    if (!*e && !app_embed_open(course_renderers[r].chapter, course_renderers[r].args, gs, e))
        return NULL;
    if (set->chosen[first] != r && !app_embed_choose(*e, course_renderers[r].args))
        return NULL;
    set->chosen[first] = r;
    return *e;
}

void course_set_destroy(course_set *set)
{
    for (int i = 0; i < COURSE_RENDERER_COUNT; i++)
        app_embed_close(set->open[i]);
    memset(set, 0, sizeof *set);
}
