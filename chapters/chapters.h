/* chapters.h - every chapter's descriptor (common/app/app.h): each chapters/NN_name.c defines its
 * chapter_NN and ends with CHAPTER_MAIN(chapter_NN). The build compiles each chapter twice: as its
 * own program, and without its main() into the library the benchmark and the tests link, which run
 * the chapters in-process through common/app/app_embed.h. The renderers the benchmark compares are
 * chapters with arguments: chapters/course_renderers.h.
 *
 * A chapter whose stage a later one builds on exports it here, so that it is written once, in the
 * chapter that teaches it: chapter 07's frame with any G-buffer layout, and chapter 11's clustered
 * passes (chapters 12 and 13 call them, and every chapter's Forward+ through the runner).
 */
#ifndef CHAPTERS_CHAPTERS_H
#define CHAPTERS_CHAPTERS_H

#include "app.h"
#include "clusters.h"
#include "deferred_volumes.h"
#include "gbuffer.h"

extern const app_desc chapter_00, chapter_01, chapter_02, chapter_03, chapter_04, chapter_05, chapter_06,
    chapter_07, chapter_08, chapter_09, chapter_10, chapter_11, chapter_12, chapter_13, chapter_14, chapter_15,
    chapter_16, chapter_17, chapter_18, chapter_19;

/* Chapter 19's probes and split-sum table: their GPU memory, in bytes, while the chapter is open (the
 * benchmark's ambient rows, tools/bench/bench_ambient.c). */
long chapter_19_probe_bytes(void);

/* Chapter 07's frame with a G-buffer of any layout, reversed-Z included (the G-buffer sweep and the
 * tests): geometry pass into g, the volumes summed in dv with how's accumulation format and view (its
 * volume state is the chapter's), presented into target. */
bool chapter_07_draw_with(gbuffer *g, deferred_volumes *dv, const gpu_scene *gs, GLuint target,
                          deferred_volumes_frame how);

/* Chapter 11's passes (chapters/11_clustered.c explains them):
 *   chapter_11_assign(c, gs)            the grid for gs's view and every cluster's light list, on the
 *                                       CPU or by compute shaders (c->desc)
 *   chapter_11_shade_deferred(c, g, gs, pass, view)
 *                                       one full-screen pass reading g, into the framebuffer bound
 *   chapter_11_shade_forward(c, gs, pass, view)
 *                                       every opaque object shaded once, after the depth pre-pass
 *   chapter_11_forward_plus             Forward+'s passes and count, as the runner draws them */
bool chapter_11_assign(clusters *c, const gpu_scene *gs);
bool chapter_11_shade_deferred(clusters *c, const gbuffer *g, const gpu_scene *gs, const gl_pass_state *pass,
                               clusters_view view);
bool chapter_11_shade_forward(clusters *c, const gpu_scene *gs, const gl_pass_state *pass, clusters_view view);
extern const app_forward_plus chapter_11_forward_plus;

/* The last line of a chapter: its main(), which hands the runner chapter 11's Forward+ (every chapter
 * offers it) and the chapter; nothing when compiled for the embedding library. */
#ifdef CHAPTER_NO_MAIN
#define CHAPTER_MAIN(desc)
#else
#define CHAPTER_MAIN(desc)                                                                                    \
    int main(int argc, char **argv)                                                                           \
    {                                                                                                         \
        app_forward_set_plus(&chapter_11_forward_plus);                                                       \
        return app_run(&(desc), argc, argv);                                                                  \
    }
#endif

#endif
