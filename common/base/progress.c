/* progress.c - see progress.h. */
#include "progress.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static struct {
    pthread_mutex_t lock;
    pthread_cond_t wake;
    pthread_t thread;
    bool started, stop, quiet, active;
    char what[96];
    long index, total, done; /* done: frames ended since the run began */
    double run_start, frame_start, last_line;
} state = {.lock = PTHREAD_MUTEX_INITIALIZER};

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void write_line(double now)
{
    double running = now - state.frame_start, elapsed = now - state.run_start;
    char of[32] = "", left[64] = "no estimate yet";
    if (state.total > 0)
        snprintf(of, sizeof of, " of %ld", state.total);
    if (state.total > 0 && state.done > 0) {
        double mean = (state.frame_start - state.run_start) / (double)state.done;
        double rest = mean * (double)(state.total - state.index) - running;
        snprintf(left, sizeof left, "about %.0f s left", rest > 0.0 ? rest : 0.0);
    } else if (state.total == 0) {
        snprintf(left, sizeof left, "until the window closes");
    }
    fprintf(stderr, "%s: frame %ld%s running for %.1f s; %.1f s elapsed, %s\n", state.what, state.index + 1, of,
            running, elapsed, left);
    fflush(stderr);
    state.last_line = now;
}

/* Worth a line: the current frame is slow, or a run of known length has gone on for as long (quick
 * frames, many of them: every frame starts the frame clock again, so they alone never looked slow). */
static bool overdue(double now)
{
    bool slow_frame = now - state.frame_start >= PROGRESS_AFTER_S;
    bool long_run = state.total > 0 && now - state.run_start >= PROGRESS_AFTER_S;
    return state.active && !state.quiet && (slow_frame || long_run) &&
           now - state.last_line >= PROGRESS_EVERY_S;
}

/* Wakes twice a second; writes a line when the run is overdue and none was written lately. */
static void *watch(void *unused)
{
    (void)unused;
    pthread_mutex_lock(&state.lock);
    while (!state.stop) {
        struct timespec until;
        clock_gettime(CLOCK_REALTIME, &until);
        until.tv_nsec += 500000000L;
        if (until.tv_nsec >= 1000000000L)
            until.tv_sec++, until.tv_nsec -= 1000000000L;
        pthread_cond_timedwait(&state.wake, &state.lock, &until);
        double now = now_s();
        if (overdue(now))
            write_line(now);
    }
    pthread_mutex_unlock(&state.lock);
    return NULL;
}

static void stop_watching(void)
{
    pthread_mutex_lock(&state.lock);
    state.stop = true;
    pthread_cond_signal(&state.wake);
    pthread_mutex_unlock(&state.lock);
    pthread_join(state.thread, NULL);
}

void progress_set_quiet(bool quiet)
{
    pthread_mutex_lock(&state.lock);
    state.quiet = quiet;
    pthread_mutex_unlock(&state.lock);
}

void progress_frame(const char *what, long index, long total)
{
    pthread_mutex_lock(&state.lock);
    double now = now_s();
    if (!state.active || index == 0) { /* a new run */
        state.run_start = now;
        state.done = 0;
        state.last_line = now - PROGRESS_EVERY_S; /* the first slow frame is reported at once */
    } else {
        state.done++;
    }
    snprintf(state.what, sizeof state.what, "%s", what);
    state.index = index, state.total = total, state.frame_start = now, state.active = true;
    if (!state.started && !state.quiet) {
        pthread_cond_init(&state.wake, NULL);
        state.started = pthread_create(&state.thread, NULL, watch, NULL) == 0;
        if (state.started)
            atexit(stop_watching);
    }
    pthread_mutex_unlock(&state.lock);
}

void progress_end(void)
{
    pthread_mutex_lock(&state.lock);
    state.active = false;
    pthread_mutex_unlock(&state.lock);
}
