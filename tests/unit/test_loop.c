/* test_loop.c - Loop subdivision (tools/gen_scenes/loop.c): the counts, the masks on a closed
 * surface and on a boundary, the winding, and a flat mesh staying flat. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "loop.h"
#include "test_util.h"

#include <math.h>
#include <string.h>

/* A regular octahedron: every vertex has valence 4, no boundary. */
static loop_mesh octahedron(void)
{
    static double p[] = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
    static int t[] = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
    loop_mesh m = {.vertex_count = 6, .triangle_count = 8};
    m.positions = malloc(sizeof p), m.triangles = malloc(sizeof t);
    memcpy(m.positions, p, sizeof p), memcpy(m.triangles, t, sizeof t);
    return m;
}

static void cross_of(const loop_mesh *m, int tri, double n[3])
{
    const double *a = m->positions + 3 * m->triangles[3 * tri], *b = m->positions + 3 * m->triangles[3 * tri + 1],
                 *c = m->positions + 3 * m->triangles[3 * tri + 2];
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    n[0] = u[1] * v[2] - u[2] * v[1], n[1] = u[2] * v[0] - u[0] * v[2], n[2] = u[0] * v[1] - u[1] * v[0];
}

static void test_closed_surface(void **state)
{
    (void)state;
    loop_mesh in = octahedron(), out;
    assert_true(loop_subdivide(&in, &out));
    assert_int_equal(out.vertex_count, 6 + 12); /* V + E */
    assert_int_equal(out.triangle_count, 32);
    /* An old vertex of valence 4: beta = (5/8 - (3/8 + cos(pi/2)/4)^2) / 4 = 31/256; its 4
     * neighbours are the equator's others (sum 0) except the one opposite: (1 - 4 beta) x. */
    assert_float_equal(out.positions[0], 1.0 - 4.0 * 31.0 / 256.0, 1e-12);
    /* The edge 0-2 (opposite 4 and 5): 3/8 (1,1,0) + 1/8 ((0,0,1) + (0,0,-1)). */
    bool found = false;
    for (int v = 6; v < out.vertex_count; v++)
        found |= fabs(out.positions[3 * v] - 0.375) < 1e-12 && fabs(out.positions[3 * v + 1] - 0.375) < 1e-12 &&
                 fabs(out.positions[3 * v + 2]) < 1e-12;
    assert_true(found);
    /* Every new triangle faces outwards, as the octahedron's do. */
    for (int t = 0; t < out.triangle_count; t++) {
        double n[3], c[3] = {0, 0, 0};
        cross_of(&out, t, n);
        for (int k = 0; k < 3; k++)
            for (int j = 0; j < 3; j++)
                c[j] += out.positions[3 * out.triangles[3 * t + k] + j] / 3.0;
        assert_true(n[0] * c[0] + n[1] * c[1] + n[2] * c[2] > 0.0);
    }
    loop_destroy(&in), loop_destroy(&out);
}

/* Two triangles of a square in the plane z = 0: boundary rules everywhere, and all stays flat. */
static void test_boundary_stays_flat(void **state)
{
    (void)state;
    double p[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    int t[] = {0, 1, 2, 0, 2, 3};
    loop_mesh in = {.positions = p, .triangles = t, .vertex_count = 4, .triangle_count = 2}, out, out2;
    assert_true(loop_subdivide(&in, &out));
    assert_int_equal(out.vertex_count, 4 + 5);
    assert_int_equal(out.triangle_count, 8);
    /* Corner 1 has boundary neighbours 0 and 2: 3/4 (1,0) + 1/8 ((0,0) + (1,1)) = (7/8, 1/8). */
    assert_float_equal(out.positions[3], 0.875, 1e-12);
    assert_float_equal(out.positions[4], 0.125, 1e-12);
    assert_true(loop_subdivide(&out, &out2));
    for (int v = 0; v < out2.vertex_count; v++)
        assert_float_equal(out2.positions[3 * v + 2], 0.0, 0.0);
    loop_destroy(&out), loop_destroy(&out2);
}

UNIT_TEST_MAIN(NULL, NULL, cmocka_unit_test(test_closed_surface), cmocka_unit_test(test_boundary_stays_flat))
