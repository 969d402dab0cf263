/* frame_timer.h - how long a frame and each of its passes take, on a clock that tells the truth.
 *
 *   frame_timer_create(t)       picks the clock: GL_TIME_ELAPSED queries where the driver's timers
 *                               can be trusted; on a software rasteriser (llvmpipe, whose timer
 *                               queries measure a fraction of the work) the CPU's monotonic clock
 *                               with glFinish() at every pass boundary. $COURSE_FRAME_CLOCK=cpu
 *                               forces the second, =gpu the first (the tests exercise the query
 *                               path that way; llvmpipe's figures from it mean nothing).
 *   frame_timer_destroy(t)
 *   frame_timer_begin(t)        a frame starts; it becomes the timer frame_timer_mark() reports to
 *   frame_timer_mark(name)      the pass `name` starts and the one before it ends (no-op when no
 *                               frame is being timed, or when `name` is the pass already running):
 *                               the passes in common/ call it themselves (work before the first
 *                               mark counts in the CPU clock's frame time only)
 *   frame_timer_pass()          the name of the pass running in the frame being timed; NULL when
 *                               none is (draw_count.h sums its counts under it)
 *   frame_timer_hold(on)        while on, frame_timer_mark() changes nothing: the pass running
 *                               takes in all the work inside, marks and all (compare mode times a
 *                               whole forward frame, with its own passes, as one pass that way)
 *   frame_timer_end(t)          the frame ends; t->last holds the latest finished frame (with GPU
 *                               queries that is the previous frame: they are read one frame late
 *                               so that the CPU never waits for them)
 *   frame_timer_clock(t)        "gpu-timer" or "glFinish+monotonic", for every label that shows one
 *
 * Without a submission wait a frame's CPU time is only how long the driver took to queue the work:
 * that is why the runner never shows CPU time without glFinish.
 */
#ifndef COMMON_FRAME_TIMER_H
#define COMMON_FRAME_TIMER_H

#include <glad/gl.h>
#include <stdbool.h>

/* A chapter's passes and compare mode's two; a frame with more counts the rest in its last pass. */
#define FRAME_TIMER_MAX_PASSES 16

typedef struct frame_times {
    int count;                            /* passes */
    const char *names[FRAME_TIMER_MAX_PASSES];
    double ms[FRAME_TIMER_MAX_PASSES];
    double frame_ms; /* the whole frame: sum of the passes (GPU) or begin to end (CPU) */
    bool valid;
} frame_times;

typedef struct frame_timer {
    bool gpu;
    GLuint queries[2][FRAME_TIMER_MAX_PASSES]; /* two frames in flight */
    frame_times pending[2];
    int slot;     /* the frame being recorded */
    bool in_pass;
    bool held; /* frame_timer_hold(true) */
    double t_begin, t_pass;
    frame_times current, last;
} frame_timer;

bool frame_timer_create(frame_timer *t);
void frame_timer_destroy(frame_timer *t);
void frame_timer_begin(frame_timer *t);
void frame_timer_mark(const char *name);
const char *frame_timer_pass(void);
void frame_timer_hold(bool on);
void frame_timer_end(frame_timer *t);
const char *frame_timer_clock(const frame_timer *t);

#endif
