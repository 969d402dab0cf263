/* frame_timer.c - see frame_timer.h. */
#include "frame_timer.h"

#include "gl_util.h"
#include "log.h"

#include <stdlib.h>
#include <string.h>
#include <time.h>

static frame_timer *active; /* the frame being timed, for frame_timer_mark() */

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

/* Software rasterisers run much of the work outside the query (llvmpipe reported 3.8 ms for 106). */
static bool timers_trusted(void)
{
    const char *forced = getenv("COURSE_FRAME_CLOCK");
    if (forced && strcmp(forced, "cpu") == 0)
        return false;
    if (forced && strcmp(forced, "gpu") == 0)
        return true; /* the tests run the query path on llvmpipe too: its numbers are wrong there */
    const char *renderer = (const char *)glGetString(GL_RENDERER);
    return renderer && !strstr(renderer, "llvmpipe") && !strstr(renderer, "softpipe") &&
           !strstr(renderer, "Software");
}

bool frame_timer_create(frame_timer *t)
{
    memset(t, 0, sizeof *t);
    t->gpu = timers_trusted();
    for (int s = 0; t->gpu && s < 2; s++)
        for (int i = 0; i < FRAME_TIMER_MAX_PASSES; i++)
            t->queries[s][i] = gl_query_create();
    return gl_check("frame_timer_create");
}

void frame_timer_destroy(frame_timer *t)
{
    for (int s = 0; s < 2; s++)
        for (int i = 0; i < FRAME_TIMER_MAX_PASSES; i++)
            gl_query_destroy(&t->queries[s][i]);
    if (active == t)
        active = NULL;
    memset(t, 0, sizeof *t);
}

const char *frame_timer_clock(const frame_timer *t) { return t->gpu ? "gpu-timer" : "glFinish+monotonic"; }

void frame_timer_begin(frame_timer *t)
{
    memset(&t->current, 0, sizeof t->current);
    t->in_pass = t->held = false;
    active = t;
    if (!t->gpu)
        glFinish(); /* nothing earlier is counted in this frame */
    t->t_begin = t->t_pass = now_ms();
}

static void close_pass(frame_timer *t)
{
    if (!t->in_pass)
        return;
    int i = t->current.count - 1;
    if (t->gpu) {
        glEndQuery(GL_TIME_ELAPSED);
    } else {
        glFinish();
        double now = now_ms();
        t->current.ms[i] = now - t->t_pass;
        t->t_pass = now;
    }
    t->in_pass = false;
}

void frame_timer_mark(const char *name)
{
    frame_timer *t = active;
    if (!t || t->held || (t->in_pass && strcmp(t->current.names[t->current.count - 1], name) == 0))
        return; /* not timing, held, or the same pass goes on */
    if (t->current.count == FRAME_TIMER_MAX_PASSES) { /* the pass running goes on: its time takes this one in */
        log_warn("frame_timer: more than %d passes; '%s' is counted in the last", FRAME_TIMER_MAX_PASSES, name);
        return;
    }
    close_pass(t);
    t->current.names[t->current.count++] = name;
    if (t->gpu)
        glBeginQuery(GL_TIME_ELAPSED, t->queries[t->slot][t->current.count - 1]);
    t->in_pass = true;
}

const char *frame_timer_pass(void)
{
    return active && active->in_pass ? active->current.names[active->current.count - 1] : NULL;
}

void frame_timer_hold(bool on)
{
    if (active)
        active->held = on;
}

/* The other slot's frame, recorded one frame ago: its queries are (nearly always) done by now. */
static void collect(frame_timer *t, int slot)
{
    frame_times *f = &t->pending[slot];
    if (!f->valid)
        return;
    f->frame_ms = 0;
    for (int i = 0; i < f->count; i++) {
        GLuint64 ns = 0;
        glGetQueryObjectui64v(t->queries[slot][i], GL_QUERY_RESULT, &ns);
        f->ms[i] = (double)ns * 1e-6;
        f->frame_ms += f->ms[i];
    }
    t->last = *f;
    f->valid = false;
}

void frame_timer_end(frame_timer *t)
{
    close_pass(t);
    active = NULL;
    t->current.valid = true;
    if (!t->gpu) {
        glFinish();
        t->current.frame_ms = now_ms() - t->t_begin; /* close_pass's glFinish: the work is done */
        t->last = t->current;
        return;
    }
    t->pending[t->slot] = t->current;
    t->slot ^= 1;
    collect(t, t->slot);
}
