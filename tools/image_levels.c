/* image_levels.c - does a picture clip where it should? For chapter 06's 8-bit exercise: an RGBA8
 * accumulation buffer saturates every channel at 1, so after the tone map the overlaps of several
 * lights form a flat plateau at the tone-mapped value of 1, and nothing is brighter than it.
 *
 *   image_levels --plateau L --min-fraction F IMAGE.png
 *
 * Prints the brightest channel and the share of lit (non-black) pixels whose brightest channel is
 * within 1 of L; exits 0 when no channel exceeds L + 1 and that share is at least F, 1 when not,
 * 2 on a usage or input error. It checks what the exercise teaches, not the bytes of one driver's
 * 8-bit blending (which rounds differently from one GPU to another).
 */
#include "cli.h"
#include "image.h"
#include "log.h"

#include <stdio.h>
#include <string.h>

static int usage(const char *why)
{
    log_error("image_levels: %s", why);
    fputs("usage: image_levels --plateau L --min-fraction F IMAGE.png\n", stderr);
    return 2;
}

/* The brightest channel of pixel i. */
static int peak_of(const unsigned char *p)
{
    int m = p[0] > p[1] ? p[0] : p[1];
    return m > p[2] ? m : p[2];
}

int main(int argc, char **argv)
{
    int plateau = -1;
    double min_fraction = -1.0;
    const char *path = NULL;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--plateau") == 0 && i + 1 < argc)
            cli_parse_int(argv[++i], 0, 255, &plateau);
        else if (strcmp(argv[i], "--min-fraction") == 0 && i + 1 < argc)
            cli_parse_double(argv[++i], 0.0, 1.0, &min_fraction);
        else if (argv[i][0] != '-' && !path)
            path = argv[i];
        else
            return usage("unexpected argument");
    }
    if (plateau < 0 || min_fraction < 0.0 || !path)
        return usage("needs --plateau 0..255, --min-fraction 0..1 and one image");
    image img;
    if (!image_load_png(path, &img))
        return 2;
    long lit = 0, on_plateau = 0;
    int brightest = 0;
    for (long i = 0; i < (long)img.width * img.height; i++) {
        int m = peak_of(img.pixels + 4 * i);
        brightest = m > brightest ? m : brightest;
        lit += m > 0;
        on_plateau += m >= plateau - 1 && m <= plateau + 1;
    }
    image_destroy(&img);
    double fraction = lit ? (double)on_plateau / (double)lit : 0.0;
    bool pass = brightest <= plateau + 1 && fraction >= min_fraction;
    printf("image_levels: brightest=%d plateau=%d on_plateau=%.2f %% of %ld lit pixels (>= %.2f %%) -> %s\n",
           brightest, plateau, 100.0 * fraction, lit, 100.0 * min_fraction, pass ? "PASS" : "FAIL");
    return pass ? 0 : 1;
}
