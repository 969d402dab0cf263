/* model_image.h - an image a model file names, checked from its header before anything decodes it.
 *
 *   model_image_check(sc, model, given, max_bytes, out, why, n)
 *        `given` as a material of Assimp's scene `sc` names it: "*N", an image embedded in the file
 *        (a .glb's, or a data URI's), or a path relative to the model file `model` ("%20" escapes
 *        decoded; an absolute path or a URL is refused). The image must be PNG or JPEG (its first
 *        bytes say so), a file of at most max_bytes, and its header must give a size of 1 to
 *        MODEL_IMAGE_SIDE_MAX texels a side. On success *out holds its path (a file's, or
 *        "MODEL#N" for an embedded one, whose encoded bytes out->bytes point into `sc`) and size;
 *        false with *why (one line) otherwise.
 */
#ifndef COMMON_MODEL_IMAGE_H
#define COMMON_MODEL_IMAGE_H

#include "scene.h"

#include <stdbool.h>
#include <stddef.h>

#define MODEL_IMAGE_SIDE_MAX 16384 /* the largest texture llvmpipe makes */

typedef struct model_image {
    char path[SCENE_PATH_MAX];
    const unsigned char *bytes; /* embedded: the encoded image, inside the Assimp scene; else NULL */
    size_t size;
    int width, height;
} model_image;

struct aiScene;

bool model_image_check(const struct aiScene *sc, const char *model, const char *given, long long max_bytes,
                       model_image *out, char *why, size_t n);

#endif
