/* image.c - see image.h. PNG coding is stb's; this file adds checked, atomic writes and the comparison. */
#include "image.h"

#include "data_dir.h"
#include "log.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include <stb_image.h>
#include <stb_image_write.h>

/* Heat-map ramp: a difference of 1 is already clearly red, HEAT_SATURATE and above is yellow-white. */
#define HEAT_SATURATE 32
/* A difference within the tolerance: there, but not a failure (RGB). */
#define HEAT_WITHIN_TOLERANCE 24, 28, 56

bool image_create(image *img, int width, int height)
{
    *img = (image){0};
    if (width <= 0 || height <= 0 || (size_t)width > SIZE_MAX / 4 / (size_t)height) {
        log_error("image_create: invalid size %dx%d", width, height);
        return false;
    }
    img->pixels = calloc((size_t)width * (size_t)height, 4);
    if (!img->pixels) {
        log_error("image_create: out of memory for %dx%d", width, height);
        return false;
    }
    img->width = width;
    img->height = height;
    return true;
}

void image_destroy(image *img)
{
    if (!img)
        return;
    free(img->pixels);
    *img = (image){0};
}

bool image_load_png(const char *path, image *img)
{
    *img = (image){0};
    int w, h, channels;
    const char *why;
    FILE *f = data_dir_open_input(path, &why); /* a named pipe is refused, not waited on */
    if (!f) {
        log_error("cannot load %s: %s", path, why);
        return false;
    }
    unsigned char *data = stbi_load_from_file(f, &w, &h, &channels, 4);
    fclose(f);
    if (!data) {
        log_error("cannot load %s: %s", path, stbi_failure_reason());
        return false;
    }
    /* Copy into our own allocation so image_destroy() never has to know who allocated the pixels. */
    if (!image_create(img, w, h)) {
        stbi_image_free(data);
        return false;
    }
    memcpy(img->pixels, data, (size_t)w * (size_t)h * 4);
    stbi_image_free(data);
    return true;
}

/* stb hands the encoded PNG over in pieces; remember the first failure instead of ignoring it. */
typedef struct png_sink {
    FILE *file;
    int error; /* errno of the first failed write, 0 while all is well */
} png_sink;

static void png_sink_write(void *context, void *data, int size)
{
    png_sink *sink = context;
    if (sink->error || size <= 0)
        return;
    if (fwrite(data, 1, (size_t)size, sink->file) != (size_t)size)
        sink->error = errno ? errno : EIO;
}

image_format image_format_of(const char *path)
{
    static const struct {
        const char *ext;
        image_format format;
    } known[] = {{".png", IMAGE_PNG}, {".bmp", IMAGE_BMP}, {".tga", IMAGE_TGA}, {".jpg", IMAGE_JPG}, {".jpeg", IMAGE_JPG}};
    const char *dot = strrchr(path, '.');
    for (size_t i = 0; dot && !strchr(dot, '/') && i < sizeof known / sizeof known[0]; i++)
        if (strcasecmp(dot, known[i].ext) == 0)
            return known[i].format;
    return IMAGE_UNKNOWN;
}

/* JPEG quality: high enough that a screenshot's flat colours show no blocks. */
#define JPG_QUALITY 95

/* Writes the image into an already open file and closes it; returns 0 or an errno value. */
static int write_and_close(FILE *file, const image *img, image_format format)
{
    png_sink sink = {.file = file, .error = 0};
    errno = 0;
    int w = img->width, h = img->height, encoded = 0;
    switch (format) {
    case IMAGE_PNG: encoded = stbi_write_png_to_func(png_sink_write, &sink, w, h, 4, img->pixels, w * 4); break;
    case IMAGE_BMP: encoded = stbi_write_bmp_to_func(png_sink_write, &sink, w, h, 4, img->pixels); break;
    case IMAGE_TGA: encoded = stbi_write_tga_to_func(png_sink_write, &sink, w, h, 4, img->pixels); break;
    case IMAGE_JPG:
        encoded = stbi_write_jpg_to_func(png_sink_write, &sink, w, h, 4, img->pixels, JPG_QUALITY);
        break;
    case IMAGE_UNKNOWN: break;
    }
    int error = sink.error;
    if (!error && !encoded)
        error = ENOMEM; /* stb only fails when it cannot allocate its buffers */
    /* Buffered data reaches the disk only at fflush/fsync: a full disk often shows up here, not in fwrite. */
    if (!error && fflush(file) != 0)
        error = errno ? errno : EIO;
    if (!error && fsync(fileno(file)) != 0)
        error = errno;
    if (fclose(file) != 0 && !error)
        error = errno ? errno : EIO;
    return error;
}

bool image_write_png(const char *path, const image *img) { return image_write_as(path, img, IMAGE_PNG); }

bool image_write(const char *path, const image *img)
{
    image_format format = image_format_of(path);
    if (format == IMAGE_UNKNOWN) {
        log_error("cannot write %s: unknown image format (the name must end in .png, .bmp, .tga or .jpg)", path);
        return false;
    }
    return image_write_as(path, img, format);
}

bool image_write_as(const char *path, const image *img, image_format format)
{
    if (!img->pixels || img->width <= 0 || img->height <= 0 || img->width > INT_MAX / 4) {
        log_error("cannot write %s: empty or oversized image", path);
        return false;
    }
    /* The temporary file sits beside the target so that rename() stays within one file system. */
    size_t tmp_size = strlen(path) + 32;
    char *tmp = malloc(tmp_size);
    if (!tmp) {
        log_error("cannot write %s: out of memory", path);
        return false;
    }
    snprintf(tmp, tmp_size, "%s.tmp-%ld", path, (long)getpid());

    int error = 0;
    FILE *file = fopen(tmp, "wb");
    if (!file) {
        error = errno;
        free(tmp); /* nothing was created, nothing to remove */
        log_error("cannot write %s: %s", path, strerror(error));
        return false;
    }
    error = write_and_close(file, img, format);
    if (!error && rename(tmp, path) != 0)
        error = errno;
    if (error) {
        remove(tmp);
        log_error("cannot write %s: %s", path, strerror(error));
    }
    free(tmp);
    return error == 0;
}

void image_flip_rows(image *img)
{
    size_t row = (size_t)img->width * 4;
    unsigned char *top = img->pixels;
    unsigned char *bottom = img->pixels + row * (size_t)(img->height - 1);
    for (; top < bottom; top += row, bottom -= row) {
        for (size_t i = 0; i < row; ++i) {
            unsigned char t = top[i];
            top[i] = bottom[i];
            bottom[i] = t;
        }
    }
}

/* Ramp from dark red (difference 1) through red and orange to yellow-white (HEAT_SATURATE and above). */
static void heat_color(int diff, unsigned char *out)
{
    double s = diff >= HEAT_SATURATE ? 1.0 : (double)(diff - 1) / (HEAT_SATURATE - 1);
    double r = 112.0 + 143.0 * fmin(1.0, 2.0 * s);
    double g = 255.0 * fmin(1.0, fmax(0.0, 2.0 * s - 0.5));
    double b = 208.0 * fmax(0.0, 3.0 * s - 2.0);
    out[0] = (unsigned char)lround(r);
    out[1] = (unsigned char)lround(g);
    out[2] = (unsigned char)lround(b);
    out[3] = 255;
}

bool image_compare(const image *a, const image *b, const image *mask, int tolerance, image_stats *stats,
                   image *heat)
{
    *stats = (image_stats){.max_x = -1, .max_y = -1, .psnr = INFINITY};
    if (heat)
        *heat = (image){0};
    if (a->width != b->width || a->height != b->height) {
        log_error("image sizes differ: %dx%d vs %dx%d", a->width, a->height, b->width, b->height);
        return false;
    }
    if (mask && (mask->width != a->width || mask->height != a->height)) {
        log_error("mask size %dx%d differs from image size %dx%d", mask->width, mask->height, a->width,
                  a->height);
        return false;
    }
    if (heat && !image_create(heat, a->width, a->height))
        return false;

    double sum_abs = 0.0, sum_sq = 0.0;
    size_t count = (size_t)a->width * (size_t)a->height;
    for (size_t i = 0; i < count; ++i) {
        const unsigned char *pa = a->pixels + 4 * i;
        const unsigned char *pb = b->pixels + 4 * i;
        unsigned char *ph = heat ? heat->pixels + 4 * i : NULL;
        if (mask && mask->pixels[4 * i] == 0) {
            if (ph)
                memcpy(ph, (unsigned char[4]){0, 0, 96, 255}, 4);
            continue;
        }
        int pixel_max = 0;
        for (int c = 0; c < 3; ++c) {
            int d = abs((int)pa[c] - (int)pb[c]);
            sum_abs += d;
            sum_sq += (double)d * d;
            if (d > pixel_max)
                pixel_max = d;
        }
        /* Strictly greater keeps the first location in row-major order; the first compared pixel seeds it. */
        if (stats->max_x < 0 || pixel_max > stats->max_abs) {
            stats->max_abs = pixel_max;
            stats->max_x = (int)(i % (size_t)a->width);
            stats->max_y = (int)(i / (size_t)a->width);
        }
        if (pixel_max > tolerance)
            stats->over++;
        stats->pixels++;
        if (ph) { /* equal black, within the tolerance a dim slate blue, over it the ramp */
            if (pixel_max == 0)
                memcpy(ph, (unsigned char[4]){0, 0, 0, 255}, 4);
            else if (pixel_max <= tolerance)
                memcpy(ph, (unsigned char[4]){HEAT_WITHIN_TOLERANCE, 255}, 4);
            else
                heat_color(pixel_max, ph);
        }
    }

    if (stats->pixels > 0) {
        double samples = 3.0 * (double)stats->pixels;
        stats->mean_abs = sum_abs / samples;
        stats->rmse = sqrt(sum_sq / samples);
        stats->psnr = stats->rmse > 0.0 ? 20.0 * log10(255.0 / stats->rmse) : INFINITY;
        stats->frac_over = (double)stats->over / (double)stats->pixels;
    }
    return true;
}
