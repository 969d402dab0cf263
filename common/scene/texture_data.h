/* texture_data.h - a material's image, decoded for the GPU's texture arrays (GL-free).
 *
 *   texture_data_size(scene, i, &w, &h)     texture i's size from its header (no decoding); false, with
 *                                           one line logged, when it cannot be read
 *   texture_data_load(scene, i, size, rgba) decode it (PNG, JPEG, TGA, BMP through stb_image) from its
 *                                           file or its embedded bytes to RGBA8, resampled to
 *                                           size x size into rgba (size * size * 4 bytes): in linear
 *                                           light for an sRGB image, as numbers for the others
 *
 * A file is opened only as a regular file, and decoded only once its header gives at most
 * MODEL_IMAGE_SIDE_MAX texels a side (the scene's check, made again: the file may have changed).
 * Every message starts where the scene names the image: "SCENE:LINE: material 'brick' base_map
 * 'PATH': cannot read image: REASON".
 *   texture_data_layer_size(scene, kind_srgb, cap)
 *                                           the side every layer of one array gets: the largest side
 *                                           of the scene's images of that colour space, rounded up to
 *                                           a power of two, at most cap; 0 when there is none
 *
 * Rows are stored bottom row first, as GL's texture coordinates count t upwards from the bottom
 * (a glTF or OBJ file's v = 0 is the image's bottom once flipped this way).
 */
#ifndef COMMON_TEXTURE_DATA_H
#define COMMON_TEXTURE_DATA_H

#include "scene.h"

#include <stdbool.h>

bool texture_data_size(const scene *s, int i, int *width, int *height);
bool texture_data_load(const scene *s, int i, int size, unsigned char *rgba);
int texture_data_layer_size(const scene *s, bool srgb, int cap);

#endif
