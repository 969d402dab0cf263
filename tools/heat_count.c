/* heat_count.c - read an overdraw screenshot back into counts, so a test can check what the heat
 * map claims (tests/golden/run_overdraw_count.sh): its total against the lighting pass's
 * GL_SAMPLES_PASSED.
 *
 *   heat_count [--expect-sum N] [--expect-each N] [--expect-covered N] IMAGE.png
 *   heat_count --legend OUT.png
 *
 * The colours are not copied here: the tool renders shaders/heat.glsl's heat(0 .. SHADER_HEAT_MAX)
 * in a headless context and maps every pixel of IMAGE to the count whose colour is nearest (within
 * 2/255 per channel; further is "unreadable"). A pixel of heat(SHADER_HEAT_MAX) is "saturated": its
 * count is that or more. Prints the covered pixels (count > 0), the sum, the largest count and how
 * many pixels had each count. With an --expect option: exit 0 when every one holds and no pixel is
 * saturated or unreadable, else 1. --legend writes the scale, one 20x20 swatch per count from 0 to
 * SHADER_HEAT_MAX (docs/03_fullscreen_phong.md shows it). Exit 2: usage or input error; 77: no GL.
 */
#include "cli.h"
#include "fbo.h"
#include "gl_program.h"
#include "gl_util.h"
#include "image.h"
#include "log.h"
#include "platform.h"
#include "shader_layout.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { COUNTS = SHADER_HEAT_MAX + 2, SWATCH = 20, MATCH = 2, DISTINCT = 8 };

static const char *const vert_text = "#version 330 core\n"
                                     "#include \"fullscreen.glsl\"\n"
                                     "void main() { gl_Position = fullscreen_position(gl_VertexID); }\n";
static const char *const frag_text = "#version 330 core\n"
                                     "#include \"heat.glsl\"\n"
                                     "out vec4 o_color;\n"
                                     "void main() { o_color = vec4(heat(int(gl_FragCoord.x)), 1.0); }\n";

typedef struct expectations {
    int sum, each, covered; /* -1: not checked */
} expectations;

static int usage(const char *why)
{
    log_error("heat_count: %s", why);
    fputs("usage: heat_count [--expect-sum N] [--expect-each N] [--expect-covered N] IMAGE.png\n"
          "       heat_count --legend OUT.png\n",
          stderr);
    return 2;
}

/* The largest channel difference between two RGB colours. */
static int distance(const unsigned char *a, const unsigned char *b)
{
    int d = 0;
    for (int k = 0; k < 3; k++)
        d = abs(a[k] - b[k]) > d ? abs(a[k] - b[k]) : d;
    return d;
}

/* heat(0 .. COUNTS - 1) as the driver renders it: one pixel each. */
static bool render_scale(unsigned char palette[COUNTS][4])
{
    GLuint program = gl_program_create("heat_count", vert_text, frag_text, NULL);
    fbo f;
    const fbo_desc desc = {.color_formats = {GL_RGBA8}, .color_count = 1, .name = "heat scale"};
    bool ok = program && fbo_create(&f, &desc, COUNTS, 1);
    if (ok) {
        glBindFramebuffer(GL_FRAMEBUFFER, f.id);
        glViewport(0, 0, COUNTS, 1);
        glUseProgram(program);
        gl_draw_fullscreen();
        ok = fbo_read_rgba8(&f, 0, &palette[0][0]);
        fbo_destroy(&f);
    }
    gl_program_destroy(&program);
    return ok;
}

/* The scale must be readable: distinct steps, black at 0, saturated past the end. */
static bool check_scale(unsigned char palette[COUNTS][4])
{
    const unsigned char black[3] = {0, 0, 0};
    bool ok = distance(palette[0], black) == 0 &&
              distance(palette[SHADER_HEAT_MAX], palette[SHADER_HEAT_MAX + 1]) == 0;
    for (int i = 0; i <= SHADER_HEAT_MAX; i++)
        for (int j = i + 1; j <= SHADER_HEAT_MAX; j++)
            ok = ok && distance(palette[i], palette[j]) >= DISTINCT;
    if (!ok)
        log_error("heat_count: shaders/heat.glsl's colours cannot be read back (0 must be black, each count "
                  "at least %d/255 from every other, %d and more alike)",
                  DISTINCT, SHADER_HEAT_MAX);
    return ok;
}

static bool write_legend(const char *path, unsigned char palette[COUNTS][4])
{
    image img;
    if (!image_create(&img, SWATCH * (SHADER_HEAT_MAX + 1), SWATCH))
        return false;
    for (int y = 0; y < img.height; y++)
        for (int x = 0; x < img.width; x++)
            memcpy(img.pixels + 4 * ((size_t)y * img.width + x), palette[x / SWATCH], 4);
    bool ok = image_write_png(path, &img);
    image_destroy(&img);
    return ok;
}

static int count_image(const char *path, unsigned char palette[COUNTS][4], expectations e)
{
    image img;
    if (!image_load_png(path, &img))
        return 2;
    long histogram[SHADER_HEAT_MAX + 1] = {0}, unreadable = 0, sum = 0, covered = 0, not_each = 0;
    int max = 0;
    for (long i = 0; i < (long)img.width * img.height; i++) {
        int best = 0;
        for (int c = 1; c <= SHADER_HEAT_MAX; c++)
            best = distance(img.pixels + 4 * i, palette[c]) < distance(img.pixels + 4 * i, palette[best])
                       ? c
                       : best;
        if (distance(img.pixels + 4 * i, palette[best]) > MATCH) {
            unreadable++;
            continue;
        }
        histogram[best]++;
        sum += best;
        covered += best > 0;
        not_each += best > 0 && best != e.each;
        max = best > max ? best : max;
    }
    image_destroy(&img);
    long saturated = histogram[SHADER_HEAT_MAX];
    printf("heat_count: %s: covered=%ld sum=%ld max=%d saturated=%ld unreadable=%ld counts", path, covered,
           sum, max, saturated, unreadable);
    for (int c = 0; c <= SHADER_HEAT_MAX; c++)
        if (histogram[c])
            printf(" %d:%ld", c, histogram[c]);
    bool expecting = e.sum >= 0 || e.each >= 0 || e.covered >= 0;
    bool pass = unreadable == 0 && (!expecting || saturated == 0);
    if (e.sum >= 0 && sum != e.sum)
        printf(" (expected sum %d)", e.sum), pass = false;
    if (e.each >= 0 && not_each > 0)
        printf(" (%ld covered pixels differ from the expected %d)", not_each, e.each), pass = false;
    if (e.covered >= 0 && covered != e.covered)
        printf(" (expected covered %d)", e.covered), pass = false;
    printf(" -> %s\n", pass ? "PASS" : "FAIL");
    return pass ? 0 : 1;
}

static int make_context(void)
{
    platform_desc pd = {.backend = BACKEND_EGL, .width = 16, .height = 16, .title = "heat_count"};
    int rc = platform_create(&pd);
    if (rc != EXIT_CODE_OK) {
        pd.backend = BACKEND_OSMESA;
        rc = platform_create(&pd);
    }
    return rc;
}

int main(int argc, char **argv)
{
    expectations e = {-1, -1, -1};
    const char *path = NULL, *legend = NULL;
    for (int i = 1; i < argc; i++) {
        int *target = strcmp(argv[i], "--expect-sum") == 0       ? &e.sum
                      : strcmp(argv[i], "--expect-each") == 0    ? &e.each
                      : strcmp(argv[i], "--expect-covered") == 0 ? &e.covered
                                                                 : NULL;
        if (target && i + 1 < argc && cli_parse_int(argv[i + 1], 0, INT_MAX, target))
            i++;
        else if (strcmp(argv[i], "--legend") == 0 && i + 1 < argc)
            legend = argv[++i];
        else if (argv[i][0] != '-' && !path)
            path = argv[i];
        else
            return usage("unexpected or bad argument");
    }
    if (!path == !legend)
        return usage("needs one IMAGE.png, or --legend OUT.png");
    int rc = make_context();
    if (rc != EXIT_CODE_OK)
        return rc == EXIT_CODE_SKIP ? 77 : 2;
    unsigned char palette[COUNTS][4];
    if (!render_scale(palette) || !check_scale(palette))
        rc = 2;
    else if (legend)
        rc = write_legend(legend, palette) ? 0 : 2;
    else
        rc = count_image(path, palette, e);
    gl_util_shutdown();
    platform_destroy();
    return rc;
}
