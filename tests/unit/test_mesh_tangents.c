/* test_mesh_tangents.c - texture coordinates and tangents: the built-in shapes' (unit, at right angles
 * to the normal, along the direction u grows, right-handed), a mirrored layout's handedness, and the
 * hard cases: no texture coordinates, a degenerate UV triangle and a zero normal still give a unit
 * tangent at right angles to the normal, never NaN. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "mesh_data.h"
#include "test_util.h"

#include <math.h>

/* Tangents are sums of float products normalised in double: a few ulps. */
#define EPS 1e-5f

static const float *vertex(const mesh_data *m, int i) { return m->vertices + (size_t)i * MESH_VERTEX_FLOATS; }

static void assert_tangent_frame(const mesh_data *m)
{
    for (int i = 0; i < m->vertex_count; i++) {
        const float *n = vertex(m, i) + MESH_VERTEX_NORMAL, *t = vertex(m, i) + MESH_VERTEX_TANGENT;
        float len = sqrtf(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
        float nlen = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        assert_float_equal(len, 1.0f, EPS);
        if (nlen > 0.5f)
            assert_float_equal(n[0] * t[0] + n[1] * t[1] + n[2] * t[2], 0.0f, EPS);
        assert_true(t[3] == 1.0f || t[3] == -1.0f);
    }
}

static void test_shapes(void **state)
{
    (void)state;
    mesh_data m;
    assert_true(mesh_data_plane(&m));
    assert_tangent_frame(&m);
    for (int i = 0; i < 4; i++) {
        const float *v = vertex(&m, i);
        /* s grows along +X, t along -Z: tangent +X, bitangent cross(+Y, +X) = -Z, so w = +1. */
        assert_float_equal(v[MESH_VERTEX_UV], v[0] + 0.5f, EPS);
        assert_float_equal(v[MESH_VERTEX_UV + 1], 0.5f - v[2], EPS);
        assert_float_equal(v[MESH_VERTEX_TANGENT], 1.0f, EPS);
        assert_float_equal(v[MESH_VERTEX_TANGENT + 3], 1.0f, 0.0f);
    }
    mesh_data_destroy(&m);
    assert_true(mesh_data_cube(&m));
    assert_tangent_frame(&m);
    for (int i = 0; i < m.vertex_count; i++)
        assert_float_equal(vertex(&m, i)[MESH_VERTEX_TANGENT + 3], 1.0f, 0.0f); /* no face is mirrored */
    mesh_data_destroy(&m);
    assert_true(mesh_data_sphere(&m, 16, 8));
    assert_tangent_frame(&m);
    /* On the equator the tangent follows longitude: at phi = 0 (+X) u grows towards -Z. */
    const float *e = vertex(&m, 4 * 17);
    assert_float_equal(e[0], 1.0f, EPS);
    assert_float_equal(e[MESH_VERTEX_TANGENT + 2], -1.0f, EPS);
    mesh_data_destroy(&m);
    assert_true(mesh_data_icosphere(&m, 1));
    assert_tangent_frame(&m); /* no texture coordinates at all: the fallback everywhere */
    mesh_data_destroy(&m);
}

/* One triangle in the z = 0 plane, normal +Z, with the texture coordinates given. */
static void triangle(mesh_data *m, const float uv[3][2], const float normal[3])
{
    static const float pos[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    *m = (mesh_data){0};
    m->vertices = calloc(3 * MESH_VERTEX_FLOATS, sizeof(float));
    m->indices = calloc(3, sizeof(uint32_t));
    assert_non_null(m->vertices);
    assert_non_null(m->indices);
    m->vertex_count = m->index_count = 3;
    for (int i = 0; i < 3; i++) {
        mesh_data_put_vertex(m, i, pos[i], normal, uv ? uv[i] : NULL, NULL);
        m->indices[i] = (uint32_t)i;
    }
    mesh_data_generate_tangents(m);
}

static void test_handedness_and_hard_cases(void **state)
{
    (void)state;
    static const float up[3] = {0, 0, 1}, zero[3] = {0, 0, 0};
    mesh_data m;
    triangle(&m, (const float[3][2]){{0, 0}, {1, 0}, {0, 1}}, up);
    assert_tangent_frame(&m);
    assert_float_equal(vertex(&m, 0)[MESH_VERTEX_TANGENT], 1.0f, EPS);
    assert_float_equal(vertex(&m, 0)[MESH_VERTEX_TANGENT + 3], 1.0f, 0.0f);
    mesh_data_destroy(&m);
    /* Mirrored: u runs along -X, v still along +Y: against cross(n, T) = -Y, so w = -1. */
    triangle(&m, (const float[3][2]){{1, 0}, {0, 0}, {1, 1}}, up);
    assert_tangent_frame(&m);
    assert_float_equal(vertex(&m, 0)[MESH_VERTEX_TANGENT], -1.0f, EPS);
    assert_float_equal(vertex(&m, 0)[MESH_VERTEX_TANGENT + 3], -1.0f, 0.0f);
    mesh_data_destroy(&m);
    triangle(&m, NULL, up); /* no texture coordinates */
    assert_tangent_frame(&m);
    mesh_data_destroy(&m);
    triangle(&m, (const float[3][2]){{0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}}, up); /* a UV point */
    assert_tangent_frame(&m);
    mesh_data_destroy(&m);
    triangle(&m, (const float[3][2]){{0, 0}, {1, 1}, {2, 2}}, up); /* a UV line */
    assert_tangent_frame(&m);
    mesh_data_destroy(&m);
    triangle(&m, (const float[3][2]){{0, 0}, {1, 0}, {0, 1}}, zero); /* a zero normal: finite, unit */
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 4; k++)
            assert_true(isfinite(vertex(&m, i)[MESH_VERTEX_TANGENT + k]));
    assert_tangent_frame(&m);
    mesh_data_destroy(&m);
}

/* A tangent given to put_vertex is kept as given (a model file's). */
static void test_given_tangent_kept(void **state)
{
    (void)state;
    mesh_data m = {0};
    m.vertices = calloc(MESH_VERTEX_FLOATS, sizeof(float));
    assert_non_null(m.vertices);
    m.vertex_count = 1;
    mesh_data_put_vertex(&m, 0, (const float[3]){1, 2, 3}, (const float[3]){0, 1, 0}, (const float[2]){0.25f, 0.75f},
                         (const float[4]){0, 0, 1, -1});
    mesh_data_generate_tangents(&m);
    const float *v = vertex(&m, 0);
    assert_float_equal(v[MESH_VERTEX_UV + 1], 0.75f, 0.0f);
    assert_float_equal(v[MESH_VERTEX_TANGENT + 2], 1.0f, 0.0f);
    assert_float_equal(v[MESH_VERTEX_TANGENT + 3], -1.0f, 0.0f);
    mesh_data_destroy(&m);
}

UNIT_TEST_MAIN(NULL, NULL, cmocka_unit_test(test_shapes), cmocka_unit_test(test_handedness_and_hard_cases),
               cmocka_unit_test(test_given_tangent_kept))
