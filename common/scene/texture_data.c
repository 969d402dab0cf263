/* texture_data.c - see texture_data.h. */
#include "texture_data.h"

#include "data_dir.h"
#include "log.h"
#include "model_image.h"

#include <stb_image.h>
#include <stb_image_resize.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Where texture i comes from, the start of each of its messages: "SCENE:LINE: material 'brick'
 * base_map 'PATH'", as the parser names a map; "image 'PATH'" for one no scene line named. */
static void texture_origin(const scene *s, int i, char *out, size_t n)
{
    const scene_texture *t = &s->textures[i];
    if (t->line > 0)
        snprintf(out, n, "%s:%d: material '%s' %s '%s'", s->path, t->line, t->material,
                 scene_map_attribute(t->map), t->path);
    else
        snprintf(out, n, "image '%s'", t->path);
}

static const char *stbi_reason(void)
{
    return stbi_failure_reason() ? stbi_failure_reason() : "unknown format";
}

/* The image's header from `f` (a file's) or its embedded bytes: false, logged, when it cannot be read
 * or is larger than a scene's maps may be (the file may have changed since the scene was read). */
static bool read_header(const scene *s, int i, FILE *f, int *w, int *h)
{
    const scene_texture *t = &s->textures[i];
    char origin[2 * SCENE_PATH_MAX + 2 * SCENE_NAME_MAX];
    int channels = 0;
    bool known = t->data ? stbi_info_from_memory(t->data, (int)t->size, w, h, &channels)
                         : stbi_info_from_file(f, w, h, &channels);
    if (!known || *w <= 0 || *h <= 0) {
        texture_origin(s, i, origin, sizeof origin);
        log_error("%s: cannot read image: %s", origin, stbi_reason());
        return false;
    }
    if (*w > MODEL_IMAGE_SIDE_MAX || *h > MODEL_IMAGE_SIDE_MAX) {
        texture_origin(s, i, origin, sizeof origin);
        log_error("%s: %d x %d texels, more than %d a side", origin, *w, *h, MODEL_IMAGE_SIDE_MAX);
        return false;
    }
    return true;
}

/* A file texture opened as a regular file (a named pipe is refused, not waited on); NULL, logged. */
static FILE *open_texture(const scene *s, int i)
{
    const char *why;
    FILE *f = data_dir_open_input(s->textures[i].path, &why);
    if (!f) {
        char origin[2 * SCENE_PATH_MAX + 2 * SCENE_NAME_MAX];
        texture_origin(s, i, origin, sizeof origin);
        log_error("%s: cannot open image: %s", origin, why);
    }
    return f;
}

bool texture_data_size(const scene *s, int i, int *width, int *height)
{
    FILE *f = s->textures[i].data ? NULL : open_texture(s, i);
    if (!s->textures[i].data && !f)
        return false;
    bool ok = read_header(s, i, f, width, height);
    if (f)
        fclose(f);
    return ok;
}

/* Decoded only once its header has passed: the header bounds what stb_image allocates. */
static unsigned char *decode(const scene *s, int i, int *w, int *h)
{
    const scene_texture *t = &s->textures[i];
    FILE *f = t->data ? NULL : open_texture(s, i);
    if (!t->data && !f)
        return NULL;
    int channels = 0;
    unsigned char *pixels = NULL;
    if (read_header(s, i, f, w, h)) {
        stbi_set_flip_vertically_on_load(1);
        pixels = t->data ? stbi_load_from_memory(t->data, (int)t->size, w, h, &channels, 4)
                         : stbi_load_from_file(f, w, h, &channels, 4);
        stbi_set_flip_vertically_on_load(0);
        if (!pixels) {
            char origin[2 * SCENE_PATH_MAX + 2 * SCENE_NAME_MAX];
            texture_origin(s, i, origin, sizeof origin);
            log_error("%s: cannot read image: %s", origin, stbi_reason());
        }
    }
    if (f)
        fclose(f);
    return pixels;
}

bool texture_data_load(const scene *s, int i, int size, unsigned char *rgba)
{
    int w = 0, h = 0;
    unsigned char *pixels = decode(s, i, &w, &h);
    if (!pixels)
        return false;
    bool ok = true;
    if (w == size && h == size)
        memcpy(rgba, pixels, (size_t)size * size * 4);
    else if (s->textures[i].srgb) /* averaged as light, not as sRGB codes (alpha is linear) */
        ok = stbir_resize_uint8_srgb(pixels, w, h, 0, rgba, size, size, 0, 4, 3, 0) != 0;
    else
        ok = stbir_resize_uint8(pixels, w, h, 0, rgba, size, size, 0, 4) != 0;
    if (!ok) {
        char origin[2 * SCENE_PATH_MAX + 2 * SCENE_NAME_MAX];
        texture_origin(s, i, origin, sizeof origin);
        log_error("%s: cannot resample image (%dx%d) to %dx%d", origin, w, h, size, size);
    }
    stbi_image_free(pixels);
    return ok;
}

int texture_data_layer_size(const scene *s, bool srgb, int cap)
{
    int side = 0;
    for (int i = 0; i < s->texture_count; i++) {
        int w = 0, h = 0;
        if (s->textures[i].srgb == srgb && texture_data_size(s, i, &w, &h))
            side = w > side ? w : side, side = h > side ? h : side;
    }
    if (side == 0)
        return 0;
    int p = 1;
    while (p < side && p < cap)
        p *= 2;
    return p < cap ? p : cap;
}
