/* texture_data.c - see texture_data.h. */
#include "texture_data.h"

#include "log.h"

#include <stb_image.h>
#include <stb_image_resize.h>
#include <stdlib.h>
#include <string.h>

bool texture_data_size(const scene_texture *t, int *width, int *height)
{
    int channels = 0;
    bool ok = t->data ? stbi_info_from_memory(t->data, (int)t->size, width, height, &channels)
                      : stbi_info(t->path, width, height, &channels);
    if (!ok || *width <= 0 || *height <= 0) {
        log_error("cannot read image '%s': %s", t->path, stbi_failure_reason() ? stbi_failure_reason() : "unknown format");
        return false;
    }
    return true;
}

bool texture_data_load(const scene_texture *t, int size, unsigned char *rgba)
{
    int w = 0, h = 0, channels = 0;
    stbi_set_flip_vertically_on_load(1);
    unsigned char *pixels = t->data ? stbi_load_from_memory(t->data, (int)t->size, &w, &h, &channels, 4)
                                    : stbi_load(t->path, &w, &h, &channels, 4);
    stbi_set_flip_vertically_on_load(0);
    if (!pixels) {
        log_error("cannot read image '%s': %s", t->path, stbi_failure_reason() ? stbi_failure_reason() : "unknown format");
        return false;
    }
    bool ok = true;
    if (w == size && h == size)
        memcpy(rgba, pixels, (size_t)size * size * 4);
    else if (t->srgb) /* averaged as light, not as sRGB codes (alpha is linear) */
        ok = stbir_resize_uint8_srgb(pixels, w, h, 0, rgba, size, size, 0, 4, 3, 0) != 0;
    else
        ok = stbir_resize_uint8(pixels, w, h, 0, rgba, size, size, 0, 4) != 0;
    if (!ok)
        log_error("cannot resample image '%s' (%dx%d) to %dx%d", t->path, w, h, size, size);
    stbi_image_free(pixels);
    return ok;
}

int texture_data_layer_size(const scene *s, bool srgb, int cap)
{
    int side = 0;
    for (int i = 0; i < s->texture_count; i++) {
        int w = 0, h = 0;
        if (s->textures[i].srgb == srgb && texture_data_size(&s->textures[i], &w, &h))
            side = w > side ? w : side, side = h > side ? h : side;
    }
    if (side == 0)
        return 0;
    int p = 1;
    while (p < side && p < cap)
        p *= 2;
    return p < cap ? p : cap;
}
