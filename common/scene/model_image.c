/* model_image.c - see model_image.h. */
#include "model_image.h"

#include "data_dir.h"
#include "model_file.h"

#include <assimp/scene.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <stb_image.h>

static bool image_kind_ok(const unsigned char *head, size_t size)
{
    static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const unsigned char jpeg[3] = {0xff, 0xd8, 0xff};
    return (size >= sizeof png && memcmp(head, png, sizeof png) == 0) ||
           (size >= sizeof jpeg && memcmp(head, jpeg, sizeof jpeg) == 0);
}

/* Its kind (PNG or JPEG) and size are checked from its header: nothing is decoded here. */
bool model_image_check(const struct aiScene *sc, const char *model, const char *given, long long max_bytes,
                       model_image *out, char *why, size_t n)
{
    char quoted[MODEL_QUOTE_MAX + 8], shown[MODEL_QUOTE_MAX + 32]; /* "texture 'x.png'", "embedded image 0" */
    model_quote(given, quoted, sizeof quoted);
    snprintf(shown, sizeof shown, "texture '%s'", quoted);
    memset(out, 0, sizeof *out);
    int w = 0, h = 0, comp = 0;
    if (given[0] == '*') {
        char *end;
        long k = strtol(given + 1, &end, 10);
        if (*end || end == given + 1 || k < 0 || k >= (long)sc->mNumTextures)
            return model_fail(why, n, "%s: no such embedded image", shown);
        snprintf(shown, sizeof shown, "embedded image %ld", k);
        const struct aiTexture *tex = sc->mTextures[k];
        if (tex->mHeight != 0 || tex->mWidth == 0 || tex->mWidth > INT32_MAX)
            return model_fail(why, n, "%s is not an encoded image", shown);
        out->bytes = (const unsigned char *)tex->pcData, out->size = tex->mWidth;
        if (snprintf(out->path, sizeof out->path, "%s#%ld", model, k) >= (int)sizeof out->path)
            return model_fail(why, n, "%s: its name is too long", shown);
        if (!image_kind_ok(out->bytes, out->size))
            return model_fail(why, n, "%s is not a PNG or JPEG image (the course decodes those two)", shown);
        if (!stbi_info_from_memory(out->bytes, (int)out->size, &w, &h, &comp))
            return model_fail(why, n, "%s: its header cannot be read (%s)", shown, stbi_failure_reason());
    } else {
        char rel[SCENE_PATH_MAX];
        if (given[0] == '/' || strstr(given, "://") || !model_uri_decode(given, rel, sizeof rel))
            return model_fail(why, n, "%s: not a relative path (images are read from beside the model)",
                              shown);
        const char *slash = strrchr(model, '/');
        int dir = slash ? (int)(slash - model) + 1 : 0;
        if (snprintf(out->path, sizeof out->path, "%.*s%s", dir, model, rel) >= (int)sizeof out->path)
            return model_fail(why, n, "%s: its path is too long", shown);
        unsigned char head[8] = {0};
        char reason[160];
        long long bytes;
        FILE *f = NULL;
        /* inside the model's folder once `..` and links are resolved, and a regular file, before it
         * is opened (a named pipe would block the open) */
        char resolved[MODEL_PATH_MAX];
        if (!model_path_inside(model, out->path, resolved, &bytes, reason, sizeof reason))
            return model_fail(why, n, "%s: %s", shown, reason);
        /* named by its resolved path, so that "a.png", "./a.png" and "x/../a.png" are one texture */
        if (strlen(resolved) >= sizeof out->path)
            return model_fail(why, n, "%s: its path is too long", shown);
        memcpy(out->path, resolved, strlen(resolved) + 1);
        const char *refused;
        if (!(f = data_dir_open_input(out->path, &refused)))
            return model_fail(why, n, "%s: %s", shown, refused);
        size_t got = fread(head, 1, sizeof head, f);
        fclose(f);
        if (bytes > max_bytes)
            return model_fail(why, n, "%s: %lld bytes, more than the limit of %lld (COURSE_MODEL_MAX_BYTES)",
                              shown, bytes, max_bytes);
        if (!image_kind_ok(head, got))
            return model_fail(why, n, "%s: not a PNG or JPEG image (the course decodes those two)", shown);
        if (!stbi_info(out->path, &w, &h, &comp))
            return model_fail(why, n, "%s: its header cannot be read (%s)", shown, stbi_failure_reason());
    }
    if (w < 1 || h < 1 || w > MODEL_IMAGE_SIDE_MAX || h > MODEL_IMAGE_SIDE_MAX)
        return model_fail(why, n, "%s: %d x %d texels, more than %d a side", shown, w, h,
                          MODEL_IMAGE_SIDE_MAX);
    out->width = w, out->height = h;
    return true;
}
