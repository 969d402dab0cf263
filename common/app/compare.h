/* compare.h - forward and the chapter's renderer in one picture, so "the same picture" can be seen:
 * a split screen (forward left of a movable divider, the chapter's renderer right of it) or their
 * difference: black where the two agree, i.e. differ by at most COMPARE_TOLERANCE_LEVELS 8-bit
 * levels in every channel (the course's "same picture"), elsewhere the largest channel's difference
 * in levels through the overdraw views' heat map (shaders/heat.glsl: 1 level dark purple, 16 and
 * more pale yellow, i.e. the difference magnified 16 times).
 *
 *   compare_create(c, width, height)     the forward picture's and the composed picture's targets
 *   compare_resize(c, width, height)
 *   compare_destroy(c)
 *   compare_compose(c, picture, mode, divider)
 *                                        c->forward (drawn by the caller) and `picture` into c->shown;
 *                                        divider: the first column of the right-hand side, pixels
 *   compare_mode_name(mode)              "off", "split", "difference"
 *
 * The runner draws forward into c->forward after the chapter's frame, under its own pass name in
 * the frame timer, so the overlay can show both sides' times.
 */
#ifndef COMMON_COMPARE_H
#define COMMON_COMPARE_H

#include "fbo.h"

#define COMPARE_TOLERANCE_LEVELS 1
#define COMPARE_DIVIDER_WIDTH 2 /* pixels left of the divider column drawn white */

typedef enum compare_mode { COMPARE_OFF, COMPARE_SPLIT, COMPARE_DIFFERENCE, COMPARE_MODE_COUNT } compare_mode;

typedef struct compare {
    fbo forward; /* RGBA8 + depth, like the app's target */
    fbo shown;   /* RGBA8 */
    GLuint program;
} compare;

bool compare_create(compare *c, int width, int height);
bool compare_resize(compare *c, int width, int height);
void compare_destroy(compare *c);
bool compare_compose(compare *c, const fbo *picture, compare_mode mode, int divider);
const char *compare_mode_name(compare_mode mode);

#endif
