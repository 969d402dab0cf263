/* test_clusters.c - chapter 11's clusters without GL (common/clusters/cluster_grid.c and cluster_lists.c,
 * compiled in by tests/chapters/chapter_11.cmake and tests/CMakeLists.txt): the slice of a depth, and the
 * conservative assignment: a sphere is listed in every cluster that a point of it falls in, and in no
 * cluster whose box it cannot reach. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "test_util.h"

#include "cluster_grid.h"
#include "cluster_lists.h"
#include "rng.h"

#include <cglm/cglm.h>
#include <math.h>

enum { W = 320, H = 240, TILE = 32 };
static const float NEAR = 0.1f, FAR = 60.0f;

static void make_grid(cluster_grid *g, int slices, int width, int height)
{
    mat4 proj;
    glm_perspective(glm_rad(50.0f), (float)width / (float)height, NEAR, FAR, proj);
    cluster_grid_init(g, width, height, TILE, slices, (const float *)proj, NEAR, FAR);
}

static void test_slice_of_depth(void **s)
{
    (void)s;
    cluster_grid g;
    make_grid(&g, 24, W, H);
    /* the formula's two ends: near is slice 0 (ln 1 = 0), far the last; outside them, clamped */
    assert_int_equal(cluster_grid_slice(&g, NEAR), 0);
    assert_int_equal(cluster_grid_slice(&g, NEAR * 0.5f), 0);
    assert_int_equal(cluster_grid_slice(&g, 0.0f), 0);
    assert_int_equal(cluster_grid_slice(&g, -3.0f), 0);
    assert_int_equal(cluster_grid_slice(&g, NAN), 0);
    assert_int_equal(cluster_grid_slice(&g, FAR), 23);
    assert_int_equal(cluster_grid_slice(&g, FAR * 4.0f), 23);
    assert_float_equal(cluster_grid_slice_depth(&g, 0), NEAR, 1e-7);
    assert_float_equal(cluster_grid_slice_depth(&g, 24), FAR, 1e-4);
    /* slice k holds near (far / near)^(k / S) .. near (far / near)^((k + 1) / S) */
    for (int k = 0; k < 24; k++) {
        float a = cluster_grid_slice_depth(&g, k), b = cluster_grid_slice_depth(&g, k + 1);
        assert_true(b > a);
        assert_float_equal(b / a, powf(FAR / NEAR, 1.0f / 24.0f), 1e-4);
        assert_int_equal(cluster_grid_slice(&g, a * 1.0001f), k);
        assert_int_equal(cluster_grid_slice(&g, b * 0.9999f), k);
        assert_int_equal(cluster_grid_slice(&g, sqrtf(a * b)), k);
    }
}

static void test_cubic_slices(void **s)
{
    (void)s;
    cluster_grid g;
    make_grid(&g, 0, 800, 800);
    /* 25 tile rows at fovy 50: each slice 1 + 2 tan(25 deg) / 25 deeper than the one before */
    double step = log(1.0 + 2.0 * tan(glm_rad(25.0)) / 25.0);
    assert_int_equal(g.slices, (int)ceil(log(FAR / NEAR) / step));
    assert_true(g.slices > 100 && g.slices <= CLUSTER_MAX_SLICES);
    make_grid(&g, 0, 1, 1);
    assert_true(g.slices >= 1 && g.slices < 20);
    assert_int_equal(g.tiles_x, 1);
    assert_int_equal(g.tiles_y, 1);
    make_grid(&g, 0, 17, 17);
    assert_int_equal(g.tiles_x, 1);
}

/* Whether cluster c's list holds sphere i. */
static bool listed(const cluster_lists *l, int c, int i)
{
    int first = l->ranges[2 * c], count = l->ranges[2 * c + 1];
    if (count < 0)
        return true; /* every light */
    for (int k = 0; k < count; k++)
        if (l->indices[first + k] == i)
            return true;
    return false;
}

/* A point of view space to its pixel and depth; false when it is outside the view. */
static bool project(const cluster_grid *g, mat4 proj, const vec3 p, int *x, int *y, float *depth)
{
    vec4 clip;
    glm_mat4_mulv(proj, (vec4){p[0], p[1], p[2], 1.0f}, clip);
    *depth = -p[2];
    if (*depth < NEAR || *depth > FAR)
        return false;
    float px = (clip[0] / clip[3] + 1.0f) * 0.5f * (float)g->width,
          py = (clip[1] / clip[3] + 1.0f) * 0.5f * (float)g->height;
    if (px < 0.0f || py < 0.0f || px >= (float)g->width || py >= (float)g->height)
        return false;
    *x = (int)px, *y = (int)py;
    return true;
}

/* The hard cases: one around the eye, one across the near plane, one across the far plane, one
 * wholly beyond it, one behind the eye, one off to the side of the view, small and large ones. */
static const float cases[][4] = {
    {0.0f, 0.0f, 0.0f, 2.0f},   {0.02f, -0.01f, -0.15f, 0.2f}, {1.0f, 0.5f, -58.0f, 5.0f},
    {0.0f, 0.0f, -70.0f, 5.0f}, {0.0f, 0.0f, 6.0f, 3.0f},      {-40.0f, 0.0f, -10.0f, 2.0f},
    {-2.0f, 1.0f, -8.0f, 0.3f}, {2.5f, -1.5f, -12.0f, 4.0f},   {0.0f, 0.0f, -30.0f, 0.05f},
};
enum { CASES = sizeof cases / sizeof cases[0], RANDOM = 40 };

static void test_sphere_in_every_cluster_it_touches(void **s)
{
    (void)s;
    mat4 proj;
    glm_perspective(glm_rad(50.0f), (float)W / (float)H, NEAR, FAR, proj);
    cluster_grid g;
    cluster_grid_init(&g, W, H, TILE, 24, (const float *)proj, NEAR, FAR);
    float spheres[CASES + RANDOM][4];
    rng r = rng_seed(11);
    for (int i = 0; i < CASES; i++)
        glm_vec4_copy((float *)cases[i], spheres[i]);
    for (int i = CASES; i < CASES + RANDOM; i++) {
        spheres[i][0] = (float)rng_uniform(&r, -15.0f, 15.0f);
        spheres[i][1] = (float)rng_uniform(&r, -10.0f, 10.0f);
        spheres[i][2] = -(float)rng_uniform(&r, -1.0f, 50.0f);
        spheres[i][3] = (float)rng_uniform(&r, 0.05f, 4.0f);
    }
    cluster_lists l = {0};
    assert_true(cluster_lists_assign(&l, &g, (const float(*)[4])spheres, CASES + RANDOM, 0));
    assert_int_equal(l.overflowed, 0);
    long checked = 0, per_sphere[CASES + RANDOM] = {0};
    for (int i = 0; i < CASES + RANDOM; i++) {
        for (int n = 0; n < 20000; n++) {
            /* a point of the ball; one in four on its surface, where the test is tightest */
            vec3 d = {(float)rng_uniform(&r, -1, 1), (float)rng_uniform(&r, -1, 1),
                      (float)rng_uniform(&r, -1, 1)};
            float len = glm_vec3_norm(d);
            if (len > 1.0f || len < 1e-3f)
                continue;
            glm_vec3_scale(d, (n % 4 == 0 ? 1.0f / len : 1.0f) * spheres[i][3], d);
            vec3 p;
            glm_vec3_add(spheres[i], d, p);
            int x, y;
            float depth;
            if (!project(&g, proj, p, &x, &y, &depth))
                continue;
            int c = cluster_grid_index(&g, x, y, depth);
            if (!listed(&l, c, i))
                fail_msg(
                    "sphere %d (%g %g %g r %g): point at pixel (%d, %d) depth %g, cluster %d, not listed", i,
                    spheres[i][0], spheres[i][1], spheres[i][2], spheres[i][3], x, y, depth, c);
            checked++, per_sphere[i]++;
        }
    }
    printf("%ld points checked; around the eye %ld, across near %ld, across far %ld\n", checked,
           per_sphere[0], per_sphere[1], per_sphere[2]);
    assert_true(checked > 100000);
    /* the in-view hard cases really were checked: around the eye, across near, across far */
    assert_true(per_sphere[0] > 100 && per_sphere[1] > 100 && per_sphere[2] > 100);
    /* not listed where it cannot reach: beyond the far plane, behind the eye, off to the side */
    for (int c = 0; c < l.clusters; c++) {
        assert_false(listed(&l, c, 3));
        assert_false(listed(&l, c, 4));
        assert_false(listed(&l, c, 5));
    }
    /* and every entry is a cluster whose box the (grown) sphere reaches: nothing listed far away */
    long entries = 0;
    for (int c = 0; c < l.clusters; c++) {
        int tx = c % g.tiles_x, ty = (c / g.tiles_x) % g.tiles_y, k = c / (g.tiles_x * g.tiles_y);
        for (int e = 0; e < l.ranges[2 * c + 1]; e++) {
            int i = l.indices[l.ranges[2 * c] + e];
            float lo[3], hi[3], d2 = 0.0f;
            cluster_grid_box(&g, tx, ty, k, lo, hi);
            for (int a = 0; a < 3; a++) {
                float o = fmaxf(fmaxf(lo[a] - spheres[i][a], spheres[i][a] - hi[a]), 0.0f);
                d2 += o * o;
            }
            float reach = spheres[i][3] * 1.001f + 1e-3f * glm_vec3_norm(spheres[i]);
            assert_true(d2 <= reach * reach);
            entries++;
        }
    }
    assert_int_equal(entries, l.entries);
    /* the small sphere far away sits in few clusters, not in a whole column of slices */
    int small = 0;
    for (int c = 0; c < l.clusters; c++)
        small += listed(&l, c, 8);
    assert_true(small >= 1 && small <= 4);
    cluster_lists_destroy(&l);
}

static void test_lists_in_light_order_and_overflow(void **s)
{
    (void)s;
    cluster_grid g;
    make_grid(&g, 24, W, H);
    const float spheres[3][4] = {{0, 0, -5, 1}, {0.2f, 0, -5, 1}, {0, 0, -5, CLUSTER_INFINITE_RADIUS}};
    cluster_lists l = {0};
    assert_true(cluster_lists_assign(&l, &g, spheres, 3, 0));
    int c = cluster_grid_index(&g, W / 2, H / 2, 5.0f);
    assert_int_equal(l.ranges[2 * c + 1], 3);
    for (int k = 0; k < 3; k++)
        assert_int_equal(l.indices[l.ranges[2 * c] + k], k);
    for (int i = 0; i < l.clusters; i++) /* the infinite light is everywhere */
        assert_true(listed(&l, i, 2));
    /* a limit of 2 entries: the clusters with 3 fall back to every light, the others keep theirs */
    assert_true(cluster_lists_assign(&l, &g, spheres, 3, 2));
    assert_int_equal(l.ranges[2 * c + 1], -1);
    assert_true(l.overflowed > 0);
    int corner = cluster_grid_index(&g, 0, 0, FAR * 0.9f);
    assert_int_equal(l.ranges[2 * corner + 1], 1);
    cluster_lists_destroy(&l);
}

/* The comparison --assign check makes: the same lists are the same; one entry or one count changed
 * is found, at its cluster. */
static void test_lists_first_difference(void **s)
{
    (void)s;
    cluster_grid g;
    make_grid(&g, 0, W, H);
    const float spheres[2][4] = {{0, 0, -5, 1}, {0.2f, 0, -5, 1}};
    cluster_lists a = {0}, b = {0};
    assert_true(cluster_lists_assign(&a, &g, spheres, 2, 0));
    assert_true(cluster_lists_assign(&b, &g, spheres, 2, 0));
    assert_int_equal(cluster_lists_first_difference(&a, &b), -1);
    int c = cluster_grid_index(&g, W / 2, H / 2, 5.0f);
    b.indices[b.ranges[2 * c] + 1] = 0; /* light order broken */
    assert_int_equal(cluster_lists_first_difference(&a, &b), c);
    b.indices[b.ranges[2 * c] + 1] = 1;
    b.ranges[2 * c + 1] = -1; /* overflowed on one side only */
    assert_int_equal(cluster_lists_first_difference(&a, &b), c);
    cluster_lists_destroy(&a);
    cluster_lists_destroy(&b);
}

/* A spot's bounding sphere holds its cone cut by its sphere, narrow and wide. */
static void test_spot_bounds(void **s)
{
    (void)s;
    rng r = rng_seed(3);
    const float pos[3] = {1, 2, 3}, dir[3] = {0, 0.6f, -0.8f}, radius = 5.0f;
    for (int a = 5; a <= 85; a += 10) {
        float c = cosf(glm_rad((float)a)), b[4];
        cluster_light_bounds(pos, dir, radius, c, b);
        assert_true(b[3] <= radius + 1e-5f);
        for (int n = 0; n < 5000; n++) {
            vec3 d = {(float)rng_uniform(&r, -1, 1), (float)rng_uniform(&r, -1, 1),
                      (float)rng_uniform(&r, -1, 1)};
            float len = glm_vec3_norm(d);
            if (len < 1e-3f || len > 1.0f || glm_vec3_dot(d, (float *)dir) < c * len)
                continue; /* outside the ball or the cone */
            vec3 p;
            glm_vec3_scale(d, radius / len * (n % 2 ? 1.0f : len), d);
            glm_vec3_add((float *)pos, d, p);
            assert_true(glm_vec3_distance(p, b) <= b[3] * (1.0f + 1e-5f));
        }
    }
    float b[4];
    cluster_light_bounds(pos, dir, radius, -1.0f, b); /* a point light: its own sphere */
    assert_float_equal(b[3], radius, 0);
    assert_float_equal(b[0], pos[0], 0);
}

UNIT_TEST_MAIN(NULL, NULL, cmocka_unit_test(test_slice_of_depth), cmocka_unit_test(test_cubic_slices),
               cmocka_unit_test(test_sphere_in_every_cluster_it_touches),
               cmocka_unit_test(test_lists_in_light_order_and_overflow),
               cmocka_unit_test(test_lists_first_difference), cmocka_unit_test(test_spot_bounds))
