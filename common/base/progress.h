/* progress.h - a line on stderr while slow frames, or a long run of quick ones, run: which frame, how
 * long so far, about how long is left. Short runs of quick frames print nothing.
 *
 *   progress_set_quiet(quiet)             --quiet: no line at all
 *   progress_frame(what, index, total)    frame `index` (from 0) of `total` (0: no end known, a
 *                                         window) begins, so the one before it has ended; `what`
 *                                         names the run ("07_face_culling", "bench case 3/40")
 *   progress_end()                        the frames are over: no line after this
 *
 * Once a frame, or a run with a known total, has run for PROGRESS_AFTER_S seconds a watcher thread
 * writes a line, so that a single frame of minutes is reported while it runs, and so are minutes of
 * quick frames (a --script of 100,000), and again every PROGRESS_EVERY_S seconds:
 *
 *   07_face_culling: frame 2 of 10 running for 4.1 s; 16.3 s elapsed, about 45 s left
 *
 * The estimate is the mean time of the frames done so far times the frames left, less what the
 * current frame has taken; before the first frame ends there is none ("no estimate yet").
 */
#ifndef COMMON_PROGRESS_H
#define COMMON_PROGRESS_H

#include <stdbool.h>

#define PROGRESS_AFTER_S 2.0
#define PROGRESS_EVERY_S 10.0

void progress_set_quiet(bool quiet);
void progress_frame(const char *what, long index, long total);
void progress_end(void);

#endif
