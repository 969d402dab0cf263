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
 * fails when the first configuration's error exceeds MAX_ERROR; the others are printed. One light:
 * the view's share is then that light's visibility.
 */
#include "app_embed.h"
#include "chapters.h"
#include "hard_util.h"
#include "mat4d.h"
#include "mesh_data.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 320
#define H 240

typedef struct tri_object {
    double *v; /* 9 doubles per triangle: world space */
    int count;
    double lo[3], hi[3];
    bool casts;
} tri_object;

static tri_object *objects;
static int object_count;

/* Every object's triangles in world space (double), with its box. */
static bool build_triangles(const scene *s)
{
    objects = calloc((size_t)s->object_count, sizeof *objects);
    object_count = s->object_count;
    for (int o = 0; o < s->object_count; o++) {
        mesh_data md;
        if (!objects || !mesh_data_from_scene(&md, s, &s->meshes[s->objects[o].mesh]))
            return false;
        mat4 world;
        scene_object_world_at(s, o, 0.0f, world);
        tri_object *t = &objects[o];
        t->count = md.index_count / 3, t->casts = !s->objects[o].cast_off;
        t->v = malloc((size_t)md.index_count * 3 * sizeof(double));
        for (int k = 0; k < 3; k++)
            t->lo[k] = DBL_MAX, t->hi[k] = -DBL_MAX;
        for (int i = 0; t->v && i < md.index_count; i++) {
            const float *p = &md.vertices[MESH_VERTEX_FLOATS * md.indices[i]];
            for (int r = 0; r < 3; r++) {
                double x = world[3][r];
                for (int c = 0; c < 3; c++)
                    x += (double)world[c][r] * p[c];
                t->v[3 * i + r] = x;
                t->lo[r] = fmin(t->lo[r], x), t->hi[r] = fmax(t->hi[r], x);
            }
        }
        mesh_data_destroy(&md);
        if (!t->v)
            return false;
    }
    return true;
}

/* Whether the segment o + t d, t in [0, tmax], meets the box (slabs). */
static bool ray_box(const double o[3], const double d[3], double tmax, const double lo[3], const double hi[3])
{
    double t0 = 0.0, t1 = tmax;
    for (int k = 0; k < 3; k++) {
        double inv = 1.0 / d[k], a = (lo[k] - o[k]) * inv, b = (hi[k] - o[k]) * inv;
        if (a > b) {
            double x = a;
            a = b, b = x;
        }
        t0 = fmax(t0, a), t1 = fmin(t1, b);
        if (t0 > t1 + 1e-12)
            return false;
    }
    return true;
}

/* Moller-Trumbore in double: the distance along d to triangle v (both sides), or -1. */
static double ray_triangle(const double o[3], const double d[3], const double *v)
{
    double e1[3], e2[3], p[3], q[3], s[3];
    for (int k = 0; k < 3; k++)
        e1[k] = v[3 + k] - v[k], e2[k] = v[6 + k] - v[k], s[k] = o[k] - v[k];
    p[0] = d[1] * e2[2] - d[2] * e2[1], p[1] = d[2] * e2[0] - d[0] * e2[2], p[2] = d[0] * e2[1] - d[1] * e2[0];
    double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    if (fabs(det) < 1e-300)
        return -1.0;
    double u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
    if (u < 0.0 || u > 1.0)
        return -1.0;
    q[0] = s[1] * e1[2] - s[2] * e1[1], q[1] = s[2] * e1[0] - s[0] * e1[2], q[2] = s[0] * e1[1] - s[1] * e1[0];
    double w = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
    if (w < 0.0 || u + w > 1.0)
        return -1.0;
    return (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
}

/* The nearest hit along o + t d with t in (tmin, tmax): its t, or -1; casters_only for shadow rays. */
static double trace(const double o[3], const double d[3], double tmin, double tmax, bool casters_only)
{
    double best = -1.0;
    for (int b = 0; b < object_count; b++) {
        const tri_object *t = &objects[b];
        if ((casters_only && !t->casts) || !ray_box(o, d, tmax, t->lo, t->hi))
            continue;
        for (int i = 0; i < t->count; i++) {
            double h = ray_triangle(o, d, &t->v[9 * i]);
            if (h > tmin && h < tmax && (best < 0.0 || h < best)) {
                best = h;
                if (casters_only)
                    return best; /* any hit shadows */
            }
        }
    }
    return best;
}

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
    double t = trace(eye, d, 1e-9, 1.0, false);
    *hit = t > 0.0;
    if (!*hit)
        return false;
    for (int k = 0; k < 3; k++)
        p[k] = eye[k] + t * d[k], l[k] = light[k] - p[k];
    /* leave the surface by a relative 1e-4 of the way to the light: the primary hit's own triangle */
    return trace(p, l, 1e-4, 1.0, true) < 0.0;
}

/* One configuration: the chapter's visibility view against the exact one; the error over lit pixels. */
static double measure(const gpu_scene *gs, const char *const *args, long *lit_out, long *leak_out)
{
    app_embed *e = NULL;
    static unsigned char rgba[4 * W * H];
    if (!app_embed_open(&chapter_14, args, gs, &e) || !app_embed_frame(e, gs, false, NULL) ||
        !fbo_read_rgba8(app_embed_target(e), 0, rgba)) {
        app_embed_close(e);
        return -1.0;
    }
    app_embed_close(e);
    double vp[16], inv[16], eye[3], light[3];
    mat4d_from_float((const float *)gs->view.view_proj, vp);
    mat4d_invert(vp, inv);
    for (int k = 0; k < 3; k++)
        eye[k] = gs->view.eye[k], light[k] = gs->lights[0].position[k];
    long lit = 0, wrong = 0, leak = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            const unsigned char *px = &rgba[4 * (y * W + x)];
            bool hit;
            if (px[1] < 128)
                continue; /* the light does not reach this pixel: nothing to shadow */
            bool exact = exact_visible(inv, eye, light, x, y, &hit);
            if (!hit)
                continue;
            lit++;
            wrong += (px[0] >= 128) != exact;
            leak += px[0] >= 128 && !exact; /* lit where the exact point is in shadow; the rest is acne */
        }
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
              hard_expect(gpu_scene_update(&gs, 0.0f, 5.0 / 256.0, W, H) && gs.light_count == 1, "one light") &&
              hard_expect(build_triangles(&s), "the scene's triangles in double");
    const double max_error = atof(argv[2]);
    printf("%-8s %-4s %-14s %-11s %-10s %-10s %-6s %s\n", "atlas", "pcf", "normal_offset", "slope_bias", "lit_pixels",
           "wrong", "leak", "acne");
    for (int c = 0; ok && (c == 0 || 3 + 4 * c < argc); c++) {
        const char *atlas = argc > 3 ? argv[3 + 4 * c] : "4096", *pcf = argc > 3 ? argv[4 + 4 * c] : "3";
        const char *offset = argc > 3 ? argv[5 + 4 * c] : "1.5", *slope = argc > 3 ? argv[6 + 4 * c] : "2";
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
