/* test_shadow_reference.c - chapter 14's shadows against an exact reference: for every pixel, a ray
 * from the eye through the pixel's centre finds the surface, and a shadow ray from there to the light
 * says whether it sees the light, both in double precision against every triangle of the scene (the
 * objects that cast: `cast off` ones receive only). The chapter's --view visibility gives, per pixel,
 * whether the light reaches it (green) and the share of its PCF taps that see the light (red; visible
 * from one half). Over the pixels the light reaches, the fraction whose visibility differs is the
 * error, printed for each atlas size, PCF and bias, split into leaks (lit where the exact point is in
 * shadow) and acne (shadowed where it is lit), in pixels (docs/14_shadows.md quotes the table).
 *
 *   test_shadow_reference SCENE MAX_ERROR [ATLAS PCF NORMAL_OFFSET SLOPE_BIAS]...
 *
 * fails when the first configuration's error exceeds MAX_ERROR; the others are printed. Each light is
 * measured alone (the chapter's --view-light K); a scene of more than LIGHT_SAMPLES lights is measured
 * on LIGHT_SAMPLES of them spread over its list (the teapots' 80: every 10th), their lit pixels
 * pooled. The rays go through tests/hard/ray_scene.c's hierarchy: the same hits as testing every
 * triangle, in seconds on the teapots' 293,378.
 */
#include "app_embed.h"
#include "chapters.h"
#include "hard_util.h"
#include "mat4d.h"
#include "ray_scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 320
#define H 240
#define LIGHT_SAMPLES 8 /* lights measured in a scene of many (the teapots' 80: every 10th) */

static ray_scene rays;

/* Whether the exact surface seen through pixel (x, y) sees the light; false with *hit false when the
 * pixel sees no surface. */
static bool exact_visible(const double inv_view_proj[16], const double eye[3], const double light[3], int x, int y,
                          bool *hit)
{
    double ndc[4] = {2.0 * (x + 0.5) / W - 1.0, 2.0 * (y + 0.5) / H - 1.0, 1.0, 1.0}, far_point[4] = {0};
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++)
            far_point[r] += inv_view_proj[4 * c + r] * ndc[c];
    double d[3], p[3], l[3];
    for (int k = 0; k < 3; k++)
        d[k] = far_point[k] / far_point[3] - eye[k];
    double t = ray_scene_trace(&rays, eye, d, 1e-9, 1.0, RAY_NEAREST, NULL);
    *hit = t > 0.0;
    if (!*hit)
        return false;
    for (int k = 0; k < 3; k++)
        p[k] = eye[k] + t * d[k], l[k] = light[k] - p[k];
    /* leave the surface by a relative 1e-4 of the way to the light: the primary hit's own triangle */
    return ray_scene_trace(&rays, p, l, 1e-4, 1.0, RAY_ANY | RAY_CASTERS, NULL) < 0.0;
}

/* One light of one configuration: the chapter's visibility view of light k against the exact one;
 * adds to the lit pixels, the wrong ones and the leaks. */
static bool measure_light(const gpu_scene *gs, const char *const *args, int k, long *lit, long *wrong, long *leak)
{
    app_embed *e = NULL;
    static unsigned char rgba[4 * W * H];
    char light_arg[16];
    snprintf(light_arg, sizeof light_arg, "%d", k);
    const char *with_light[24];
    int n = 0;
    while (args[n] && n < 20)
        with_light[n] = args[n], n++;
    with_light[n++] = "--view-light", with_light[n++] = light_arg, with_light[n] = NULL;
    if (!app_embed_open(&chapter_14, with_light, gs, &e) || !app_embed_frame(e, gs, false, NULL) ||
        !fbo_read_rgba8(app_embed_target(e), 0, rgba)) {
        app_embed_close(e);
        return false;
    }
    app_embed_close(e);
    double vp[16], inv[16], eye[3], light[3];
    mat4d_from_float((const float *)gs->view.view_proj, vp);
    mat4d_invert(vp, inv);
    for (int c = 0; c < 3; c++)
        eye[c] = gs->view.eye[c], light[c] = gs->lights[k].position[c];
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            const unsigned char *px = &rgba[4 * (y * W + x)];
            bool hit;
            if (px[1] < 128)
                continue; /* the light does not reach this pixel: nothing to shadow */
            bool exact = exact_visible(inv, eye, light, x, y, &hit);
            if (!hit)
                continue;
            ++*lit;
            *wrong += (px[0] >= 128) != exact;
            *leak += px[0] >= 128 && !exact; /* lit where the exact point is in shadow; the rest is acne */
        }
    return true;
}

/* One configuration over the sampled lights (every light, or LIGHT_SAMPLES spread over a scene of
 * more): the error over their lit pixels, or -1. */
static double measure(const gpu_scene *gs, const char *const *args, long *lit_out, long *leak_out)
{
    long lit = 0, wrong = 0, leak = 0;
    int step = gs->light_count > LIGHT_SAMPLES ? gs->light_count / LIGHT_SAMPLES : 1;
    for (int k = 0; k < gs->light_count; k += step)
        if (!measure_light(gs, args, k, &lit, &wrong, &leak))
            return -1.0;
    *lit_out = lit, *leak_out = leak;
    return lit ? (double)wrong / (double)lit : 0.0;
}

int main(int argc, char **argv)
{
    if (argc < 3 || (argc - 3) % 4 != 0) {
        fprintf(stderr, "usage: %s SCENE MAX_ERROR [ATLAS PCF NORMAL_OFFSET SLOPE_BIAS]...\n", argv[0]);
        return 2;
    }
    hard_context_create(W, H);
    scene s;
    gpu_scene gs;
    bool ok = hard_expect(scene_load(argv[1], &s) && gpu_scene_create(&s, &gs), "load %s", argv[1]) &&
              hard_expect(gpu_scene_update(&gs, 0.0f, 5.0 / 256.0, W, H) && gs.light_count >= 1, "a light") &&
              hard_expect(ray_scene_build(&rays, &s, 0.0f), "the scene's triangles in double");
    const double max_error = atof(argv[2]);
    printf("%-8s %-4s %-14s %-11s %-10s %-10s %-6s %s\n", "atlas", "pcf", "normal_offset", "slope_bias", "lit_pixels",
           "wrong", "leak", "acne");
    for (int c = 0; ok && (c == 0 || 3 + 4 * c < argc); c++) {
        /* without a configuration: chapter 14's defaults (chapters.h) */
        const char *atlas = argc > 3 ? argv[3 + 4 * c] : "4096", *pcf = argc > 3 ? argv[4 + 4 * c] : CHAPTER_14_PCF;
        const char *offset = argc > 3 ? argv[5 + 4 * c] : CHAPTER_14_NORMAL_OFFSET;
        const char *slope = argc > 3 ? argv[6 + 4 * c] : "2";
        const char *args[] = {"--view", "visibility", "--shadow-atlas", atlas, "--pcf", pcf,
                              "--normal-offset", offset, "--slope-bias", slope, NULL};
        long lit = 0, leak = 0;
        double error = measure(&gs, args, &lit, &leak);
        printf("%-8s %-4s %-14s %-11s %-10ld %.4f %%  %-6ld %ld\n", atlas, pcf, offset, slope, lit, 100.0 * error, leak,
               (long)llround(error * (double)lit) - leak);
        if (c == 0)
            hard_expect(error >= 0.0 && lit > 1000 && error <= max_error,
                        "%s: %.4f %% of %ld lit pixels wrong (at most %.4f %%)", argv[1], 100.0 * error, lit,
                        100.0 * max_error);
    }
    return hard_finish();
}
