/* image.h - 8-bit RGBA images: PNG in and out, and comparison of two renderings.
 *
 *   image_create(img, w, h)                 zeroed RGBA8 pixels, rows top to bottom
 *   image_destroy(img)
 *   image_load_png(path, img)               any PNG, converted to RGBA8
 *   image_write_png(path, img)              atomic: PATH.tmp-PID then rename(); the old file stays on failure
 *   image_write(path, img)                  the same, in the format the name's extension says (.png,
 *                                           .bmp, .tga, .jpg/.jpeg); an unknown extension is an error
 *   image_write_as(path, img, format)       the same in a given format
 *   image_format_of(path)                   the format an extension names, or IMAGE_UNKNOWN
 *   image_flip_rows(img)                    GL reads bottom-up; PNG is top-down
 *   image_compare(a, b, mask, tol, stats, heat)
 *                                           per-channel RGB stats; mask (may be NULL) selects pixels
 *                                           whose mask red channel is non-zero; heat (may be NULL)
 *                                           receives a diff heat-map: black where equal, dim slate
 *                                           blue within tol, and over it a
 *                                           ramp from dark red to yellow-white, so a real
 *                                           difference stands out of 1-level rounding
 */
#ifndef COMMON_IMAGE_H
#define COMMON_IMAGE_H

#include <stdbool.h>

typedef enum image_format { IMAGE_UNKNOWN, IMAGE_PNG, IMAGE_BMP, IMAGE_TGA, IMAGE_JPG } image_format;

typedef struct image {
    int width, height;
    unsigned char *pixels; /* width * height * 4 bytes, RGBA, top row first */
} image;

typedef struct image_stats {
    long pixels;       /* pixels compared (inside the mask) */
    int max_abs;       /* largest channel difference, 0..255 */
    int max_x, max_y;  /* where it is */
    double mean_abs;   /* mean channel difference over R, G, B of compared pixels, in 0..255 units */
    double rmse;       /* root mean square channel difference, 0..255 units */
    double psnr;       /* dB; INFINITY when identical */
    long over;         /* pixels with any channel difference > tolerance */
    double frac_over;  /* over / pixels */
} image_stats;

bool image_create(image *img, int width, int height);
void image_destroy(image *img);
bool image_load_png(const char *path, image *img);
bool image_write_png(const char *path, const image *img);
bool image_write(const char *path, const image *img);
bool image_write_as(const char *path, const image *img, image_format format);
image_format image_format_of(const char *path);
void image_flip_rows(image *img);
bool image_compare(const image *a, const image *b, const image *mask, int tolerance, image_stats *stats,
                   image *heat);

#endif
