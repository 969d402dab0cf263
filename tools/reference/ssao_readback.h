/* ssao_readback.h - what ao_reference.h is compared with: chapter 17's occlusion for one setting,
 * drawn in-process (app_embed.h) at the size of gs's view and read back.
 *
 *   ssao_readback(gs, radius, samples, blur, rgba)
 *        --view ao (blur "0") or ao-blurred, with --ao-radius, --ao-samples and --ao-blur as given
 *        (command-line text): width x height RGBA bytes, bottom row first, A in the red channel
 */
#ifndef TOOLS_SSAO_READBACK_H
#define TOOLS_SSAO_READBACK_H

#include "gpu_scene.h"

#include <stdbool.h>

bool ssao_readback(const gpu_scene *gs, const char *radius, const char *samples, const char *blur,
                   unsigned char *rgba);

#endif
