/* input.c - see input.h. */
#include "input.h"

#include <string.h>

#define KEY_QUEUE 64
#define KEY_CODES 512 /* every KEY_* code and ASCII letter is below this */

static struct {
    int queue[KEY_QUEUE];
    int queued;
    bool held[KEY_CODES];
    input_mouse mouse;
    bool moved; /* a first position is known: motion is measured from it */
} state;

void input_reset(void) { memset(&state, 0, sizeof state); }

void input_key(int code, bool down)
{
    if (code <= 0 || code >= KEY_CODES)
        return;
    if (down && state.queued < KEY_QUEUE)
        state.queue[state.queued++] = code;
    state.held[code] = down;
}

int input_take_key(void)
{
    if (state.queued == 0)
        return 0;
    int code = state.queue[0];
    memmove(state.queue, state.queue + 1, (size_t)(--state.queued) * sizeof state.queue[0]);
    return code;
}

bool input_key_held(int code) { return code > 0 && code < KEY_CODES && state.held[code]; }

void input_mouse_move(double x, double y)
{
    if (state.moved) {
        state.mouse.dx += x - state.mouse.x;
        state.mouse.dy += y - state.mouse.y;
    }
    state.mouse.x = x, state.mouse.y = y;
    state.moved = true;
}

void input_mouse_button(int button, bool down)
{
    if (button < 0 || button >= INPUT_BUTTON_COUNT)
        return;
    if (down && !state.mouse.held[button]) {
        state.mouse.pressed[button] = true;
        state.mouse.press_x[button] = state.mouse.x, state.mouse.press_y[button] = state.mouse.y;
    }
    state.mouse.held[button] = down;
}

void input_scroll(double dy) { state.mouse.scroll += dy; }

input_mouse input_take_mouse(void)
{
    input_mouse m = state.mouse;
    state.mouse.dx = state.mouse.dy = state.mouse.scroll = 0.0;
    memset(state.mouse.pressed, 0, sizeof state.mouse.pressed);
    return m;
}
