/* imgdiff.c - compare two PNG renderings and decide whether they agree closely enough.
 *
 * Golden and agreement tests call this with the expected image first. It prints one line of statistics
 * and exits 0 (pass), 1 (the images differ beyond the bound) or 2 (bad usage or unreadable input).
 */
#include "cli.h"
#include "image.h"
#include "log.h"

#include <stdio.h>
#include <string.h>

enum { EXIT_PASS = 0, EXIT_DIFFER = 1, EXIT_USAGE = 2 };

typedef struct options {
    int tolerance;       /* per-channel difference still counted as equal */
    double max_fraction; /* share of pixels allowed over the tolerance */
    const char *mask;
    const char *heatmap;         /* always written */
    const char *heatmap_on_fail; /* written only when the comparison fails */
    bool quiet;
    const char *expected, *actual;
} options;

static void print_usage(FILE *out)
{
    fputs("usage: imgdiff [options] EXPECTED.png ACTUAL.png\n"
          "  --tolerance N          per-channel difference still counted as equal (default 1)\n"
          "  --max-fraction F       fraction of pixels allowed over the tolerance (default 0.0001)\n"
          "  --mask PNG             compare only pixels whose red channel is non-zero in PNG\n"
          "  --heatmap PNG          write a difference heat map\n"
          "  --heatmap-on-fail PNG  write the heat map only when the comparison fails\n"
          "  --quiet                print the result line only on failure\n"
          "  --help                 show this text\n"
          "exit status: 0 pass, 1 images differ beyond the bound, 2 usage or input error\n",
          out);
}

/* Returns -1 when the options are usable, otherwise the exit status. */
static int parse_options(int argc, char **argv, options *opt)
{
    *opt = (options){.tolerance = 1, .max_fraction = 0.0001};
    static const char *const with_value[] = {"--tolerance", "--max-fraction", "--mask", "--heatmap",
                                             "--heatmap-on-fail"};
    int positional = 0;
    for (int i = 1; i < argc; ++i) {
        const char *arg = argv[i];
        const char *value = NULL;
        for (size_t k = 0; k < sizeof with_value / sizeof with_value[0]; ++k) {
            if (strcmp(arg, with_value[k]) != 0)
                continue;
            if (i + 1 == argc) {
                log_error("imgdiff: %s needs a value", arg);
                return EXIT_USAGE;
            }
            value = argv[++i];
        }
        if (strcmp(arg, "--help") == 0) {
            print_usage(stdout);
            return EXIT_PASS;
        } else if (strcmp(arg, "--quiet") == 0) {
            opt->quiet = true;
        } else if (strcmp(arg, "--tolerance") == 0) {
            if (!cli_parse_int(value, 0, 255, &opt->tolerance)) {
                log_error("imgdiff: --tolerance wants an integer 0..255, not '%s'", value);
                return EXIT_USAGE;
            }
        } else if (strcmp(arg, "--max-fraction") == 0) {
            if (!cli_parse_double(value, 0.0, 1.0, &opt->max_fraction)) {
                log_error("imgdiff: --max-fraction wants a number 0..1, not '%s'", value);
                return EXIT_USAGE;
            }
        } else if (strcmp(arg, "--mask") == 0) {
            opt->mask = value;
        } else if (strcmp(arg, "--heatmap") == 0) {
            opt->heatmap = value;
        } else if (strcmp(arg, "--heatmap-on-fail") == 0) {
            opt->heatmap_on_fail = value;
        } else if (arg[0] == '-' && arg[1] != '\0') {
            log_error("imgdiff: unknown option %s (see --help)", arg);
            return EXIT_USAGE;
        } else {
            if (positional == 0)
                opt->expected = arg;
            else if (positional == 1)
                opt->actual = arg;
            positional++;
        }
    }
    if (positional != 2) {
        log_error("imgdiff: expected two images, got %d (see --help)", positional);
        return EXIT_USAGE;
    }
    return -1;
}

int main(int argc, char **argv)
{
    options opt;
    int status = parse_options(argc, argv, &opt);
    if (status >= 0)
        return status;

    image expected = {0}, actual = {0}, mask = {0}, heat = {0};
    image_stats stats;
    bool want_heat = opt.heatmap || opt.heatmap_on_fail;
    status = EXIT_USAGE;
    if (!image_load_png(opt.expected, &expected) || !image_load_png(opt.actual, &actual))
        goto done;
    if (opt.mask && !image_load_png(opt.mask, &mask))
        goto done;
    if (!image_compare(&expected, &actual, opt.mask ? &mask : NULL, opt.tolerance, &stats,
                       want_heat ? &heat : NULL))
        goto done;

    bool pass = stats.frac_over <= opt.max_fraction;
    status = pass ? EXIT_PASS : EXIT_DIFFER;
    if (!pass || !opt.quiet)
        printf("imgdiff: max=%d at (%d,%d) mean=%.4f rmse=%.4f psnr=%.2f dB over_tol=%ld (%.4f %%) -> %s\n",
               stats.max_abs, stats.max_x, stats.max_y, stats.mean_abs, stats.rmse, stats.psnr, stats.over,
               100.0 * stats.frac_over, pass ? "PASS" : "FAIL");
    /* A heat map that was asked for but not written is an error of its own. */
    if (opt.heatmap && !image_write_png(opt.heatmap, &heat))
        status = EXIT_USAGE;
    if (!pass && opt.heatmap_on_fail && !image_write_png(opt.heatmap_on_fail, &heat))
        status = EXIT_USAGE;

done:
    image_destroy(&expected);
    image_destroy(&actual);
    image_destroy(&mask);
    image_destroy(&heat);
    return status;
}
