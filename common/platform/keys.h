/* keys.h - every window key of the course in one table: what the runner does with a key, and what
 * --help and the README's key table say about it (tools/key_table prints the README's table, and
 * a test fails when the README differs).
 *
 *   keys_find(code, program)                 the binding of a key in that chapter, or NULL
 *   keys_print_help(stream, program, views)  the --help "window keys" section of that chapter
 *                                            (views: whether it has views for V to cycle)
 *   keys_print_markdown(stream)              the README's key table
 *   keys_code(label)                         the code of a key by its label ("W", "Space", "F1",
 *                                            "+"), any single printable character, or 0
 *
 * A chapter's own keys are in the table too, tagged with its number; the runner hands them to the
 * chapter's key callback, which is where their lesson is.
 */
#ifndef COMMON_KEYS_H
#define COMMON_KEYS_H

#include <stdbool.h>
#include <stdio.h>

/* Letters and digits are their ASCII upper-case codes ('F', '1'); the platform maps the others.
 * KEY_MOUSE marks the table's mouse gestures, which no key code matches. */
enum {
    KEY_MOUSE = -1,
    KEY_ESCAPE = 256,
    KEY_SPACE = ' ',
    KEY_UP = 265,
    KEY_DOWN = 264,
    KEY_LEFT = 263,
    KEY_RIGHT = 262,
    KEY_PAGE_UP = 266,
    KEY_PAGE_DOWN = 267,
    KEY_HOME = 268,
    KEY_BACKSPACE = 259,
    KEY_F1 = 290,
};

typedef enum key_action {
    KEY_ACTION_CHAPTER, /* the chapter's key callback */
    KEY_ACTION_QUIT,
    KEY_ACTION_RENDERER,
    KEY_ACTION_VIEW,
    KEY_ACTION_CUTOFF_HALF,
    KEY_ACTION_CUTOFF_DOUBLE,
    KEY_ACTION_CUTOFF_EXACT,
    KEY_ACTION_PAUSE,
    KEY_ACTION_SCREENSHOT,
    KEY_ACTION_FLY, /* held: W A S D move the camera (common/app/camera.c) */
    KEY_ACTION_FRAME_SCENE,
    KEY_ACTION_HOME_CAMERA,
    KEY_ACTION_PRINT_POSE,
    KEY_ACTION_ADD_LIGHT,
    KEY_ACTION_LIGHTS_DOUBLE,
    KEY_ACTION_LIGHTS_HALF,
    KEY_ACTION_LIGHTS_RESTORE,
    KEY_ACTION_OVERLAY,
    KEY_ACTION_KEY_LIST,
    KEY_ACTION_COMPARE,
    KEY_ACTION_DIVIDER_LEFT,
    KEY_ACTION_DIVIDER_RIGHT,
    KEY_ACTION_MOUSE, /* a mouse gesture, listed with the keys; the runner reads the mouse itself */
} key_action;

typedef struct key_binding {
    int code;
    const char *label;    /* as a learner presses it: "R", "Space", "Esc" */
    const char *chapters; /* "04" or "06": only there; NULL: every chapter */
    key_action action;
    const char *does;
} key_binding;

const key_binding *keys_find(int code, const char *program);
void keys_print_help(FILE *stream, const char *program, bool views);
void keys_print_markdown(FILE *stream);
int keys_code(const char *label);

#endif
