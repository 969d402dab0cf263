/* chapters.h - every chapter's descriptor (common/app/app.h): each chapters/NN_name.c defines its
 * chapter_NN and ends with CHAPTER_MAIN(chapter_NN). The build compiles each chapter twice: as its
 * own program, and without its main() into the library the benchmark and the tests link, which run
 * the chapters in-process through common/app/app_embed.h. The renderers the benchmark compares are
 * chapters with arguments: chapters/course_renderers.h.
 *
 * A chapter whose stage a later one builds on exports it here, so that it is written once, in the
 * chapter that teaches it: chapter 07's frame with any G-buffer layout, chapter 11's clustered
 * passes (chapters 12 and 13 call them, and every chapter's Forward+ through the runner), and
 * chapter 14's shadows as chapters 15 to 19 take them (--shadows N).
 */
#ifndef CHAPTERS_CHAPTERS_H
#define CHAPTERS_CHAPTERS_H

#include "app.h"
#include "clusters.h"
#include "deferred_volumes.h"
#include "gbuffer.h"
#include "shadow_atlas.h"

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

/* Chapter 14's shadows in a later chapter (15 to 19), off unless asked for:
 *   CHAPTER_14_SHADOW_OPTIONS(key)    the options it names, as chapter 14 does: --shadows N (the N
 *                                     most important lights; 0, the default: none), --pcf and
 *                                     --shadow-atlas; `key` toggles them
 *   chapter_14_shadows_create(a, s, extra)
 *                                     with N > 0, the atlas (chapter 14's normal offset, slope bias,
 *                                     format and culling) and *extra its SHADOWS define and inputs
 *                                     (shadow_atlas_extra); with N = 0 nothing made and *extra empty,
 *                                     so the chapter's picture is what it was. False (logged) on a
 *                                     bad value or a context that cannot make the atlas
 *   chapter_14_shadows_update(s, gs)  each frame, before anything shades: the tiles and tables
 *                                     (nothing without an atlas); then shadow_atlas_programs picks
 *                                     the frame's program additions (nothing shadowed: the ones
 *                                     without SHADOWS)
 *   chapter_14_shadows_key(s)         shadows on / off; without an atlas, one line saying how to
 *                                     start with one
 *   shadow_atlas_destroy(s) at cleanup (nothing made: nothing to do). */
extern const char *const chapter_14_pcfs[];
/* Chapter 14's default filter and normal offset, chosen by measurement (docs/14_shadows.md, "Choosing
 * the defaults"): against exact shadow rays on the teapots PCF 3 is no more right than PCF 1 (one
 * bilinear 2 x 2 comparison) and costs 1.5x its shading pass on llvmpipe; 0.25 texels of normal offset
 * leaks less than 1.5 while the slope-scaled bias still keeps the acne away. */
#define CHAPTER_14_PCF "1"
#define CHAPTER_14_NORMAL_OFFSET "0.25"
#define CHAPTER_14_SHADOW_OPTIONS(key)                                                                     \
    {"shadows", "N", "chapter 14's shadows for the N most important lights (0: none; key " key ")", NULL, "0", \
     CLI_WHOLE, 0, 1 << 20},                                                                               \
        {"pcf", "N", "with --shadows: comparisons a side averaged per lookup", chapter_14_pcfs,         \
         CHAPTER_14_PCF},                                                                                  \
        {"shadow-atlas", "SIZE", "with --shadows: the atlas's side in texels, a power of two from 256", NULL, \
         "4096", CLI_POWER_OF_TWO, 256, 32768}
bool chapter_14_shadows_create(app *a, shadow_atlas *s, gl_program_extra *extra);
bool chapter_14_shadows_update(shadow_atlas *s, const gpu_scene *gs);
bool chapter_14_shadows_key(shadow_atlas *s);

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
