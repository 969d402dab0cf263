/* window_check.c - what the learner's window shows, checked against the pictures it is made of.
 *
 *   window_check split FORWARD PICTURE SHOWN DIVIDER
 *       SHOWN is FORWARD left of column DIVIDER - COMPARE_DIVIDER_WIDTH, white up to DIVIDER, and
 *       PICTURE from DIVIDER on, pixel for pixel
 *   window_check difference FORWARD PICTURE SHOWN
 *       SHOWN is black exactly where FORWARD and PICTURE agree (at most COMPARE_TOLERANCE_LEVELS
 *       apart in every channel), and not black where they do not
 *   window_check overlay PLAIN WITH
 *       WITH differs from PLAIN only inside one box from the top-left corner (its first changed pixel
 *       in the top-left quarter: black stays black under the box), darkened, with text:
 *       at least 200 white pixels that are not white in PLAIN
 *
 * Exit 0 when the claim holds, 1 when it does not (with where and by how much), 2 on bad input.
 */
#include "compare.h"
#include "cli.h"
#include "image.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define OVERLAY_MIN_TEXT_PIXELS 200

static int usage(const char *why)
{
    fprintf(stderr, "window_check: %s\nusage: window_check split FORWARD PICTURE SHOWN DIVIDER\n"
                    "       window_check difference FORWARD PICTURE SHOWN\n"
                    "       window_check overlay PLAIN WITH\n", why);
    return 2;
}

static const unsigned char *px(const image *img, int x, int y) { return img->pixels + 4 * ((size_t)y * img->width + x); }
static bool same_rgb(const unsigned char *a, const unsigned char *b) { return memcmp(a, b, 3) == 0; }
static bool is_white(const unsigned char *a) { return a[0] == 255 && a[1] == 255 && a[2] == 255; }
static bool is_black(const unsigned char *a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }

static int max_level_diff(const unsigned char *a, const unsigned char *b)
{
    int m = 0;
    for (int c = 0; c < 3; c++)
        m = abs(a[c] - b[c]) > m ? abs(a[c] - b[c]) : m;
    return m;
}

static int check_split(const image *f, const image *p, const image *s, int divider)
{
    long wrong = 0;
    int first_x = -1, first_y = -1;
    for (int y = 0; y < s->height; y++)
        for (int x = 0; x < s->width; x++) {
            const unsigned char *want = x < divider - COMPARE_DIVIDER_WIDTH ? px(f, x, y) : x < divider ? NULL : px(p, x, y);
            bool ok = want ? same_rgb(px(s, x, y), want) : is_white(px(s, x, y));
            if (!ok && wrong++ == 0)
                first_x = x, first_y = y;
        }
    if (wrong) {
        printf("FAIL split: %ld pixels are not forward | divider | picture (first at %d,%d)\n", wrong, first_x, first_y);
        return 1;
    }
    printf("ok   split: forward left of column %d, the picture right of it, pixel for pixel\n", divider);
    return 0;
}

static int check_difference(const image *f, const image *p, const image *s)
{
    long agree = 0, differ = 0, wrong = 0;
    for (int y = 0; y < s->height; y++)
        for (int x = 0; x < s->width; x++) {
            bool same = max_level_diff(px(f, x, y), px(p, x, y)) <= COMPARE_TOLERANCE_LEVELS;
            agree += same, differ += !same;
            wrong += same != is_black(px(s, x, y));
        }
    if (wrong) {
        printf("FAIL difference: %ld pixels are black where the pictures differ or lit where they agree\n", wrong);
        return 1;
    }
    printf("ok   difference: black on the %ld pixels that agree, lit on the %ld that differ\n", agree, differ);
    return 0;
}

/* Every pixel of the box is text (white) or the picture darkened by the box's translucent black. */
static bool darkened_or_text(const unsigned char *plain, const unsigned char *with)
{
    return is_white(with) || (with[0] <= plain[0] && with[1] <= plain[1] && with[2] <= plain[2]);
}

static int check_overlay(const image *plain, const image *with)
{
    int x0 = with->width, y0 = with->height, x1 = -1, y1 = -1;
    long text = 0, not_box = 0;
    for (int y = 0; y < with->height; y++)
        for (int x = 0; x < with->width; x++)
            if (!same_rgb(px(plain, x, y), px(with, x, y))) {
                x0 = x < x0 ? x : x0, y0 = y < y0 ? y : y0, x1 = x > x1 ? x : x1, y1 = y > y1 ? y : y1;
                text += is_white(px(with, x, y)) && !is_white(px(plain, x, y));
                not_box += !darkened_or_text(px(plain, x, y), px(with, x, y));
            }
    if (x1 < 0) {
        printf("FAIL overlay: the two pictures are the same: no overlay drawn\n");
        return 1;
    }
    bool corner = x0 < with->width / 4 && y0 < with->height / 4, small = (long)(x1 + 1) * (y1 + 1) <= (long)with->width * with->height * 9 / 10;
    if (!corner || !small || not_box > 0 || text < OVERLAY_MIN_TEXT_PIXELS) {
        printf("FAIL overlay: changes from %d,%d to %d,%d (want a box from the top-left quarter, under 90 %% of the "
               "picture), %ld pixels neither text nor darkened, %ld text pixels (at least %d)\n",
               x0, y0, x1, y1, not_box, text, OVERLAY_MIN_TEXT_PIXELS);
        return 1;
    }
    printf("ok   overlay: only a %dx%d box at the top-left corner changed (darkened), with %ld text pixels\n", x1 + 1,
           y1 + 1, text);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2 || strcmp(argv[1], "--help") == 0)
        return usage("a check and its images");
    int n = strcmp(argv[1], "overlay") == 0 ? 2 : 3, divider = 0;
    if (argc != 2 + n + (strcmp(argv[1], "split") == 0))
        return usage("wrong number of arguments");
    image img[3];
    for (int k = 0; k < n; k++)
        if (!image_load_png(argv[2 + k], &img[k]))
            return 2;
    for (int k = 1; k < n; k++)
        if (img[k].width != img[0].width || img[k].height != img[0].height)
            return usage("the images differ in size");
    int rc;
    if (strcmp(argv[1], "split") == 0)
        rc = cli_parse_int(argv[5], 0, img[0].width, &divider) ? check_split(&img[0], &img[1], &img[2], divider) : usage("bad divider");
    else if (strcmp(argv[1], "difference") == 0)
        rc = check_difference(&img[0], &img[1], &img[2]);
    else if (strcmp(argv[1], "overlay") == 0)
        rc = check_overlay(&img[0], &img[1]);
    else
        rc = usage("unknown check");
    for (int k = 0; k < n; k++)
        image_destroy(&img[k]);
    return rc;
}
