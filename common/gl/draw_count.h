/* draw_count.h - the bytes a frame's passes write and read per pixel, counted rather than estimated.
 * While counting is on, every draw the course issues (mesh_draw_instanced, gl_draw_fullscreen) runs
 * inside its own GL_SAMPLES_PASSED query, and what passed is multiplied by what one sample costs in
 * the state of that very draw, read back from GL:
 *   written  the draw framebuffer's colour attachments that are drawn to, their unmasked channels'
 *            bits; the depth attachment's bits when the depth test and depth writes are on; the
 *            stencil's bits when the stencil test is on, with a non-zero write mask and a depth-pass
 *            operation other than GL_KEEP
 *   read     every 2D texture the draw's program samples (sampler2D, sampler2DMS, integer ones),
 *            its texel's bits times its samples, once per fragment the shader ran: a full-screen
 *            draw without a depth or stencil test that can fail runs it on every pixel of the viewport (those that
 *            discard included); any other draw on its samples passed / the target's samples; and
 *            the colour bytes blending reads back, per sample
 * Summed per pass: the pass frame_timer_mark() named last (frame_timer.h), "(no pass)" before any.
 * Not counted: clears, depth-test reads, compute passes (they write per cluster, not per pixel),
 * texture buffers (scene data, not per-pixel storage) and blits; the fetches of fragments that
 * discard in a draw with a depth or stencil test. Texture reads are an upper bound where a
 * shader returns early (a background pixel that reads only its depth counts every texture).
 * Counting syncs on every query: count in frames that are not timed.
 *
 *   draw_count_begin(out)        counting on, into *out (zeroed): installs gl_util's draw hooks
 *                                (gl_draw_hooks_set); false (logged) when already on
 *   draw_count_end()             counting off, the hooks removed; *out holds the frame's passes
 * A draw counted inside another GL_SAMPLES_PASSED query (gl_samples_begin/end; GL allows one at a
 * time) suspends that query, and its samples are added back to the query's result at its end.
 */
#ifndef COMMON_DRAW_COUNT_H
#define COMMON_DRAW_COUNT_H

#include <glad/gl.h>
#include <stdbool.h>

#define DRAW_COUNT_MAX_PASSES 16

typedef struct draw_count_pass {
    const char *name;
    int draws;
    long long samples; /* GL_SAMPLES_PASSED over the pass's draws */
    long long written; /* bytes */
    long long read;    /* bytes: texture fetches and blending's read-back */
} draw_count_pass;

typedef struct draw_counts {
    int count;
    draw_count_pass passes[DRAW_COUNT_MAX_PASSES];
} draw_counts;

bool draw_count_begin(draw_counts *out);
void draw_count_end(void);

#endif
