/* chapters.h - every chapter's descriptor (common/app/app.h): each chapters/NN_name.c defines its
 * chapter_NN and ends with CHAPTER_MAIN(chapter_NN). The build compiles each chapter twice: as its
 * own program, and without its main() into the library the benchmark and the tests link, which run
 * the chapters in-process through common/app/app_embed.h. The renderers the benchmark compares are
 * chapters with arguments: chapters/course_renderers.h.
 */
#ifndef CHAPTERS_CHAPTERS_H
#define CHAPTERS_CHAPTERS_H

#include "app.h"
#include "deferred_volumes.h"
#include "gbuffer.h"

extern const app_desc chapter_00, chapter_01, chapter_02, chapter_03, chapter_04, chapter_05, chapter_06,
    chapter_07, chapter_08, chapter_09, chapter_10, chapter_11, chapter_12, chapter_13;

/* Chapter 07's frame with a G-buffer of any layout, reversed-Z included (the G-buffer sweep and the
 * tests): geometry pass into g, the volumes summed in dv with how's accumulation format and view (its
 * volume state is the chapter's), presented into target. */
bool chapter_07_draw_with(gbuffer *g, deferred_volumes *dv, const gpu_scene *gs, GLuint target,
                          deferred_volumes_frame how);

#endif
