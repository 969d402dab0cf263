/* gen_color.h - the colours the scene recipes draw.
 *
 *   gen_color_random(r, saturation_lo, saturation_hi, out)
 *        a random hue with a saturation in [lo, hi) and its brightest channel at 1, so that a
 *        light's intensity alone sets its peak (drawn from common/base/rng.h)
 */
#ifndef TOOLS_GEN_SCENES_GEN_COLOR_H
#define TOOLS_GEN_SCENES_GEN_COLOR_H

#include "rng.h"

void gen_color_random(rng *r, double saturation_lo, double saturation_hi, double out[3]);

#endif
