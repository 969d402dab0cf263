/* test_ssao_reference.c - chapter 17's screen-space ambient occlusion against an exact reference
 * (tools/reference/ao_reference.h, the benchmark's too): for every pixel, the surface behind its
 * centre and G x G cosine-weighted, stratified rays from it, in double precision against every
 * triangle of the scene; the share that leave freely within the radius is the occlusion the chapter
 * estimates (its --view ao, or ao-blurred, in the red channel). The reference's own noise is
 * measured too: a second set of jitters on every 4th pixel.
 *
 *   test_ssao_reference SCENE RADIUS MAX_MEAN BOUND MAX_BEYOND SILHOUETTE BORDER THIN FAR [SAMPLES BLUR]...
 *
 * prints, for each configuration (SAMPLES directions, blur BLUR; the raw view where BLUR is 0), the
 * mean and max error over the pixels that see a surface and the fraction beyond BOUND; fails when the
 * first configuration's mean exceeds MAX_MEAN or its fraction beyond BOUND exceeds MAX_BEYOND. The
 * first configuration is also split into the hard cases, each with its own bound on the fraction
 * beyond BOUND (a pixel may be in several; "open" is the rest):
 *   silhouette  a neighbour (8 around) is background or more than the radius nearer or farther
 *   border      within 8 pixels of the picture's edge
 *   thin        its surface within the radius of a thin object's box (one whose box is thinner than
 *               a fifth of the radius in two directions: the post)
 *   far         its surface more than 8 units from the eye
 */
#include "ao_reference.h"
#include "hard_util.h"
#include "ssao_readback.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define W 160
#define H 120
#define G 64 /* G x G rays per pixel */

static ray_scene rays;
static double reference[W * H]; /* -1: no surface */
static double distance[W * H];  /* from the eye to the surface, for the hard cases */
static bool near_thin[W * H];

enum { CASE_SILHOUETTE, CASE_BORDER, CASE_THIN, CASE_FAR, CASE_OPEN, CASE_COUNT };
static const char *const case_names[CASE_COUNT] = {"silhouette", "border", "thin", "far", "open"};

/* Whether p lies within radius of the box of an object thinner than radius / 5 across two of its
 * extents (the thin case). */
static bool near_thin_object(const double p[3], double radius)
{
    for (int b = 0; b < rays.object_count; b++) {
        const ray_object *t = &rays.objects[b];
        double e[3], outside = 0.0;
        for (int k = 0; k < 3; k++) {
            e[k] = t->hi[k] - t->lo[k];
            double d = fmax(fmax(t->lo[k] - p[k], p[k] - t->hi[k]), 0.0);
            outside += d * d;
        }
        /* thin in two directions (a post; a plane is thin in one only): the middle extent */
        double middle = fmax(fmin(e[0], e[1]), fmin(fmax(e[0], e[1]), e[2]));
        if (middle < radius / 5.0 && sqrt(outside) < radius)
            return true;
    }
    return false;
}

/* Which hard cases pixel (x, y) is in, as bits of 1 << CASE_*. */
static int cases_of(int x, int y, double radius)
{
    int i = y * W + x, bits = 0;
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            int u = x + dx, v = y + dy;
            if (u >= 0 && v >= 0 && u < W && v < H &&
                (reference[v * W + u] < 0.0 || fabs(distance[v * W + u] - distance[i]) > radius))
                bits |= 1 << CASE_SILHOUETTE;
        }
    if (x < 8 || y < 8 || x >= W - 8 || y >= H - 8)
        bits |= 1 << CASE_BORDER;
    if (near_thin[i])
        bits |= 1 << CASE_THIN;
    if (distance[i] > 8.0)
        bits |= 1 << CASE_FAR;
    return bits ? bits : 1 << CASE_OPEN;
}

/* The reference for every pixel (tools/reference/ao_reference.c), and where each surface lies for the
 * hard cases; false when the reference's own noise was not measured. */
static bool build_reference(const gpu_scene *gs, double radius, double *noise_mean, double *noise_max)
{
    ao_reference a;
    ao_reference_begin(&a, &rays, (const float *)gs->view.view_proj, gs->view.eye, W, H, radius, G);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double p[3], *out = &reference[y * W + x];
            *out = ao_reference_pixel(&a, x, y, p);
            distance[y * W + x] = *out < 0.0 ? -1.0
                                             : sqrt((p[0] - a.eye[0]) * (p[0] - a.eye[0]) +
                                                    (p[1] - a.eye[1]) * (p[1] - a.eye[1]) +
                                                    (p[2] - a.eye[2]) * (p[2] - a.eye[2]));
            near_thin[y * W + x] = *out >= 0.0 && near_thin_object(p, radius);
        }
    return ao_reference_noise(&a, noise_mean, noise_max);
}

typedef struct error_stats {
    long count, over;
    double sum, max;
} error_stats;

/* One configuration: the chapter's occlusion view against the reference, over every pixel with a
 * surface (all) and per hard case. */
static bool measure(const gpu_scene *gs, const char *radius, const char *samples, const char *blur, double bound,
                    error_stats *all, error_stats cases[CASE_COUNT])
{
    static unsigned char rgba[4 * W * H];
    bool ok = ssao_readback(gs, radius, samples, blur, rgba);
    *all = (error_stats){0};
    for (int c = 0; c < CASE_COUNT; c++)
        cases[c] = (error_stats){0};
    for (int i = 0; ok && i < W * H; i++) {
        if (reference[i] < 0.0)
            continue;
        double err = fabs(rgba[4 * i] / 255.0 - reference[i]);
        int bits = cases_of(i % W, i / W, atof(radius));
        for (int c = 0; c <= CASE_COUNT; c++) {
            error_stats *st = c == CASE_COUNT ? all : &cases[c];
            if (c < CASE_COUNT && !(bits & 1 << c))
                continue;
            st->sum += err, st->max = fmax(st->max, err), st->over += err > bound, st->count++;
        }
    }
    return ok && all->count > 1000;
}

static double mean_of(const error_stats *e) { return e->count ? e->sum / (double)e->count : 0.0; }
static double beyond_of(const error_stats *e) { return e->count ? (double)e->over / (double)e->count : 0.0; }

int main(int argc, char **argv)
{
    if (argc < 10 || (argc - 10) % 2 != 0) {
        fprintf(stderr, "usage: %s SCENE RADIUS MAX_MEAN BOUND MAX_BEYOND SILHOUETTE BORDER THIN FAR [SAMPLES BLUR]...\n",
                argv[0]);
        return 2;
    }
    hard_context_create(W, H);
    scene s;
    gpu_scene gs;
    double noise_mean = 0.0, noise = 0.0;
    bool ok = hard_expect(scene_load(argv[1], &s) && gpu_scene_create(&s, &gs), "load %s", argv[1]) &&
              hard_expect(gpu_scene_update(&gs, 0.0f, 5.0 / 256.0, W, H), "the view at %dx%d", W, H) &&
              hard_expect(ray_scene_build(&rays, &s, 0.0f), "the scene's triangles in double");
    bool traced = ok && build_reference(&gs, atof(argv[2]), &noise_mean, &noise);
    ok = ok && hard_expect(traced && noise_mean < 1.0 / 255.0,
                           "the reference's own noise (%d rays): mean %.5f, max %.5f (1/255 = %.5f)", G * G,
                           noise_mean, noise, 1.0 / 255.0);
    const double max_mean = atof(argv[3]), bound = atof(argv[4]), max_beyond = atof(argv[5]);
    printf("%-8s %-5s %-10s %-10s beyond %.3f\n", "samples", "blur", "mean", "max", bound);
    for (int c = 0; ok && (c == 0 || 10 + 2 * c < argc); c++) {
        const char *samples = argc > 10 ? argv[10 + 2 * c] : "16", *blur = argc > 10 ? argv[11 + 2 * c] : "2";
        error_stats all, cases[CASE_COUNT];
        bool measured = measure(&gs, argv[2], samples, blur, bound, &all, cases);
        printf("%-8s %-5s %-10.4f %-10.4f %.4f %%\n", samples, blur, mean_of(&all), all.max, 100.0 * beyond_of(&all));
        if (c > 0)
            continue;
        hard_expect(measured && mean_of(&all) <= max_mean && beyond_of(&all) <= max_beyond,
                    "%s: mean error %.4f (at most %.4f), %.4f %% of pixels beyond %.3f (at most %.4f %%)", argv[1],
                    mean_of(&all), max_mean, 100.0 * beyond_of(&all), bound, 100.0 * max_beyond);
        for (int k = 0; k < CASE_COUNT; k++) {
            const error_stats *e = &cases[k];
            if (k == CASE_OPEN) { /* the rest: printed, bounded by the whole */
                printf("  %-10s %6ld pixels: mean %.4f, max %.4f, %.4f %% beyond %.3f\n", case_names[k], e->count,
                       mean_of(e), e->max, 100.0 * beyond_of(e), bound);
                continue;
            }
            double limit = atof(argv[6 + k]);
            hard_expect(e->count > 0 && beyond_of(e) <= limit,
                        "  %-10s %6ld pixels: mean %.4f, max %.4f, %.4f %% beyond %.3f (at most %.4f %%)", case_names[k],
                        e->count, mean_of(e), e->max, 100.0 * beyond_of(e), bound, 100.0 * limit);
        }
    }
    return hard_finish();
}
