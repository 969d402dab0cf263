/* input_script.h - a --script file: timed keys and mouse events, fed to common/platform/input.c exactly as
 * the window's callbacks feed it, plus a few things for the runner to do after a frame (take a
 * screenshot of what the window shows, print the overlay, count GL objects, quit). Tests drive the
 * window with it; a learner can record a walk through a scene with it.
 *
 *   input_script_load(path, s)         parse a file; errors name file:line
 *   input_script_parse(text, name, s)  the same from a string
 *   input_script_destroy(s)
 *   input_script_feed(s, frame)        frame's input events into common/platform/input.c (before the frame)
 *   input_script_range(s, frame, &first, &count)
 *                                      frame's events, in file order (the runner does the
 *                                      after-frame ones: kind >= SCRIPT_SCREENSHOT)
 *   input_script_last_frame(s)         the last frame with an event, -1 for an empty script
 *
 * Format, one event per line, '#' starts a comment:
 *   FRAME[-LAST] ACTION [ARGS]        on frame FRAME (0 is the first), or on each of FRAME..LAST
 *   key K        press and release K, a label of the key table (W, Space, Home, F1, PgUp, +, ...)
 *   down K | up K                     hold K down / let it go (the fly keys W A S D)
 *   move X Y     the cursor to framebuffer pixel (X, Y), from the top-left corner
 *   press B | release B               mouse button B: left or right
 *   scroll DY    wheel steps (positive: zoom in)
 *   screenshot PATH                   after the frame: what the window shows (overlay included);
 *                                     PATH's folder found at load, current folder then data folder
 *   overlay      after the frame: print the overlay's text to stdout, each line "overlay: ..." (while
 *                F1's list shows, which replaces it in the window: that list, each line "keys: ...")
 *   objects mark | objects check      after the frame: remember the number of live GL objects /
 *                                     fail the run unless it is the remembered number (leaks)
 *   quit         after the frame: stop
 *
 * Limits, checked while parsing: frames 0..99,999, so that a script runs at most 100,000 frames
 * (a run goes on to a script's last frame: 28 minutes at 60 frames a second, and a 14-byte line
 * `0-9999999 key W` no longer asks for hours of frames); at most 1,000,000 events after ranges
 * are expanded (a range FRAME-LAST is one event per frame); 1023 characters a line; a regular file
 * of at most 64 MiB. `objects check` needs an `objects mark` before it.
 */
#ifndef COMMON_INPUT_SCRIPT_H
#define COMMON_INPUT_SCRIPT_H

#include <stdbool.h>

#define SCRIPT_FRAME_MAX 99999L /* the last frame a script may name */
#define SCRIPT_EVENTS_MAX 1000000

typedef enum script_kind {
    SCRIPT_KEY,
    SCRIPT_DOWN,
    SCRIPT_UP,
    SCRIPT_MOVE,
    SCRIPT_PRESS,
    SCRIPT_RELEASE,
    SCRIPT_SCROLL,
    SCRIPT_SCREENSHOT, /* from here on: after the frame, for the runner */
    SCRIPT_OVERLAY,
    SCRIPT_OBJECTS_MARK,
    SCRIPT_OBJECTS_CHECK,
    SCRIPT_QUIT,
} script_kind;

typedef struct script_event {
    long frame;
    script_kind kind;
    int code;    /* key code, or mouse button */
    double x, y; /* move: the cursor; scroll: y */
    const char *path; /* screenshot: the file, owned by the script (one copy a line, shared by its range) */
    int line;
} script_event;

typedef struct input_script {
    script_event *events; /* sorted by frame, file order kept within a frame */
    int count;
    char **paths; /* the screenshot lines' files */
    int path_count;
    char name[256];
} input_script;

bool input_script_load(const char *path, input_script *s);
bool input_script_parse(const char *text, const char *name, input_script *s);
void input_script_destroy(input_script *s);
void input_script_feed(const input_script *s, long frame);
void input_script_range(const input_script *s, long frame, int *first, int *count);
long input_script_last_frame(const input_script *s);

#endif
