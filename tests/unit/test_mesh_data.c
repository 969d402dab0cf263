/* test_mesh_data.c - the built-in shapes are what docs/scene-format.md promises. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "mesh_data.h"
#include "test_util.h"

static const float *vertex(const mesh_data *m, uint32_t i) { return m->vertices + (size_t)i * MESH_VERTEX_FLOATS; }

/* Every triangle winds counter-clockwise seen from outside: its geometric normal agrees with
 * the vertex normals (flat shapes) or points away from the origin (closed convex shapes). */
static void assert_outward(const mesh_data *m, bool closed)
{
    for (int t = 0; t < m->index_count; t += 3) {
        const float *a = vertex(m, m->indices[t]), *b = vertex(m, m->indices[t + 1]), *c = vertex(m, m->indices[t + 2]);
        double u[3], v[3], n[3], centre[3];
        for (int k = 0; k < 3; k++)
            u[k] = b[k] - a[k], v[k] = c[k] - a[k], centre[k] = (a[k] + b[k] + c[k]) / 3.0;
        n[0] = u[1] * v[2] - u[2] * v[1];
        n[1] = u[2] * v[0] - u[0] * v[2];
        n[2] = u[0] * v[1] - u[1] * v[0];
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        assert_true(len > 0.0);
        double along_normal = (n[0] * a[3] + n[1] * a[4] + n[2] * a[5]) / len;
        assert_true(along_normal > 0.0);
        if (closed)
            assert_true(n[0] * centre[0] + n[1] * centre[1] + n[2] * centre[2] > 0.0);
    }
}

static void assert_unit_normals(const mesh_data *m)
{
    for (int i = 0; i < m->vertex_count; i++) {
        const float *v = vertex(m, (uint32_t)i);
        assert_float_equal(sqrtf(v[3] * v[3] + v[4] * v[4] + v[5] * v[5]), 1.0f, 1e-5f);
    }
}

static void test_cube(void **state)
{
    (void)state;
    mesh_data m;
    assert_true(mesh_data_cube(&m));
    assert_int_equal(m.vertex_count, 24);
    assert_int_equal(m.index_count, 36);
    for (int k = 0; k < 3; k++) {
        assert_float_equal(m.bounds_min[k], -0.5f, 0.0f);
        assert_float_equal(m.bounds_max[k], 0.5f, 0.0f);
    }
    /* flat normals: each vertex's normal is an axis, and its coordinate on that axis is 0.5 */
    for (int i = 0; i < m.vertex_count; i++) {
        const float *v = vertex(&m, (uint32_t)i);
        assert_float_equal(v[0] * v[3] + v[1] * v[4] + v[2] * v[5], 0.5f, 1e-6f);
    }
    assert_float_equal(m.bound_radius, sqrtf(0.75f), 1e-6f);
    assert_unit_normals(&m);
    assert_outward(&m, true);
    mesh_data_destroy(&m);
}

static void test_plane(void **state)
{
    (void)state;
    mesh_data m;
    assert_true(mesh_data_plane(&m));
    assert_int_equal(m.index_count, 6);
    for (int i = 0; i < m.vertex_count; i++) {
        const float *v = vertex(&m, (uint32_t)i);
        assert_float_equal(v[1], 0.0f, 0.0f);
        assert_float_equal(fabsf(v[0]), 0.5f, 0.0f);
        assert_float_equal(fabsf(v[2]), 0.5f, 0.0f);
        assert_float_equal(v[4], 1.0f, 0.0f);
    }
    assert_outward(&m, false); /* single-sided: the front face looks up +Y */
    mesh_data_destroy(&m);
}

static void test_sphere(void **state)
{
    (void)state;
    mesh_data m;
    assert_true(mesh_data_sphere(&m, 100, 101));
    assert_int_equal(m.index_count / 3, 20000); /* 2 * slices * (stacks - 1): sphere.scene's 20,000 faces */
    for (int i = 0; i < m.vertex_count; i++) {
        const float *v = vertex(&m, (uint32_t)i);
        assert_float_equal(sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), 1.0f, 1e-6f);
    }
    assert_unit_normals(&m);
    assert_outward(&m, true);
    mesh_data_destroy(&m);
    assert_false(mesh_data_sphere(&m, 2, 8));
    assert_false(mesh_data_sphere(&m, 8, 1));
}

static void test_icosphere(void **state)
{
    (void)state;
    const int tris[] = {20, 80, 320, 1280};
    for (int s = 0; s <= 3; s++) {
        mesh_data m;
        assert_true(mesh_data_icosphere(&m, s));
        assert_int_equal(m.index_count / 3, tris[s]);
        assert_float_equal(m.bound_radius, 1.0f, 1e-6f);
        assert_outward(&m, true);
        /* The faces lie inside the unit sphere: the inradius is below 1 and grows with subdivision.
         * Icosahedron inradius / circumradius = sqrt(3)(3 + sqrt 5) / 12 / sin(2 pi / 5). */
        double r = mesh_data_inradius(&m);
        assert_true(r < 1.0);
        if (s == 0)
            assert_float_equal(r, 0.7946544722917661, 1e-6);
        mesh_data_destroy(&m);
    }
}

static void test_inradius_of_cube(void **state)
{
    (void)state;
    mesh_data m;
    assert_true(mesh_data_cube(&m));
    assert_float_equal(mesh_data_inradius(&m), 0.5, 1e-9);
    mesh_data_destroy(&m);
}

static void test_load_missing_model(void **state)
{
    (void)state;
    mesh_data m;
    assert_false(mesh_data_load(&m, "/nonexistent/model.obj", "test.scene:3"));
    assert_null(m.vertices);
}

static void test_load_model_normals(void **state)
{
    (void)state;
    /* A tetrahedron-ish OBJ with a zero-area face and a zero normal: loads, every normal finite and unit. */
    char dir[] = "/tmp/test_mesh_data_XXXXXX", path[64];
    assert_non_null(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/degenerate.obj", dir);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 2 0 0\nvn 0 0 0\n"
          "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\nf 1 2 5\nf 2 2 2\n",
          f);
    fclose(f);
    mesh_data m;
    assert_true(mesh_data_load(&m, path, NULL));
    assert_true(m.index_count >= 12);
    for (int i = 0; i < m.vertex_count * MESH_VERTEX_FLOATS; i++)
        assert_true(isfinite(m.vertices[i]));
    assert_unit_normals(&m);
    mesh_data_destroy(&m);
    remove(path);
    rmdir(dir);
}

UNIT_TEST_MAIN(NULL, NULL, cmocka_unit_test(test_cube), cmocka_unit_test(test_plane),
               cmocka_unit_test(test_sphere), cmocka_unit_test(test_icosphere),
               cmocka_unit_test(test_inradius_of_cube), cmocka_unit_test(test_load_missing_model),
               cmocka_unit_test(test_load_model_normals))
