/* light_batches.h - chapter 08's batches of lights: two lights whose rectangles on screen do not
 * overlap touch different pixels, so their stencil counts cannot mix, and one stencil pass and one
 * lighting pass (one instanced draw each) serve every light of a batch.
 *
 *   light_batches_make(lb, lv, gs, one_per_light)
 *        after light_volumes_sort(lv, gs): each finite light's rectangle (light_batches_rect), then
 *        first fit, largest rectangle first (as in bin packing): a light joins the first batch none
 *        of whose rectangles it overlaps (one_per_light: a batch of its own). Rewrites lv's light
 *        list batch by batch and uploads it; lb->batches[0 .. lb->count) are ranges of that list.
 *        false when out of memory (logged). Up to n^2 / 2 rectangle tests: measured on 2 cores,
 *        0.9 ms for 1,024 lights (120 batches), 11 ms for 4,096, 0.2 s for 16,384
 *   light_batches_destroy(lb)
 *   light_batches_rect(view, position, radius, rect)
 *        the pixels {x0, y0, x1, y1} (inclusive) that can hold a sphere: its bounding box in view
 *        space, projected, one pixel wider for rounding; the whole view when the box reaches behind
 *        the eye
 */
#ifndef COMMON_LIGHT_BATCHES_H
#define COMMON_LIGHT_BATCHES_H

#include "light_volumes.h"

typedef struct light_batch {
    int first, count; /* instances [first, first + count) of the light list */
} light_batch;

typedef struct light_batches {
    light_batch *batches;
    int count;
    /* Work space, per finite light (in light_volumes_sort's order) or per batch: */
    int (*rects)[4]; /* each light's rectangle */
    int *order;      /* the lights by decreasing area, then the new light list */
    int *next;       /* per light, the next light of its batch (-1: none) */
    int *head;       /* per batch, its latest light */
    int capacity;
} light_batches;

bool light_batches_make(light_batches *lb, light_volumes *lv, const gpu_scene *gs, bool one_per_light);
void light_batches_destroy(light_batches *lb);
void light_batches_rect(const frame_view *view, const float position[3], float radius, int rect[4]);

#endif
