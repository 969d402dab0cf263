/* input.h - what the learner does with the keys and the mouse. The window's callbacks
 * (common/platform/platform.c) and a --script file (common/platform/input_script.c) both write here, and the runner
 * reads only from here, so a scripted run takes exactly the path a person's hands take.
 *
 *   input_reset()                       forget everything (a new run)
 *   input_key(code, down)               a key (KEY_* of keys.h) went down or up; a press is queued
 *   input_take_key()                    next key pressed since the last call, or 0
 *   input_key_held(code)                whether the key is down now (the fly keys)
 *   input_mouse_move(x, y)              the cursor, in framebuffer pixels from the top-left corner
 *   input_mouse_button(button, down)    INPUT_BUTTON_LEFT or INPUT_BUTTON_RIGHT
 *   input_scroll(dy)                    wheel steps, positive away from the user
 *   input_take_mouse()                  the cursor, its buttons, and the motion and scroll since
 *                                       the last call
 */
#ifndef COMMON_INPUT_H
#define COMMON_INPUT_H

#include <stdbool.h>

enum { INPUT_BUTTON_LEFT, INPUT_BUTTON_RIGHT, INPUT_BUTTON_COUNT };

typedef struct input_mouse {
    double x, y;         /* framebuffer pixels, top-left origin */
    double dx, dy;       /* motion since the last input_take_mouse */
    double scroll;       /* wheel steps since then */
    bool held[INPUT_BUTTON_COUNT];
    bool pressed[INPUT_BUTTON_COUNT]; /* went down since then */
    double press_x[INPUT_BUTTON_COUNT], press_y[INPUT_BUTTON_COUNT]; /* where */
} input_mouse;

void input_reset(void);
void input_key(int code, bool down);
int input_take_key(void);
bool input_key_held(int code);
void input_mouse_move(double x, double y);
void input_mouse_button(int button, bool down);
void input_scroll(double dy);
input_mouse input_take_mouse(void);

#endif
