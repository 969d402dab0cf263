/* test_mat4d.c - the double-precision 4x4 inverse (common/base/mat4d.c, compiled in by
 * tests/CMakeLists.txt): a view-projection times its inverse is the identity, a known inverse comes
 * out exact, and a singular matrix is refused. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "mat4d.h"
#include "test_util.h"

#include <cglm/cglm.h>
#include <math.h>

/* out = a * b, column-major. */
static void multiply(const double a[16], const double b[16], double out[16])
{
    for (int c = 0; c < 4; c++)
        for (int r = 0; r < 4; r++) {
            out[4 * c + r] = 0.0;
            for (int k = 0; k < 4; k++)
                out[4 * c + r] += a[4 * k + r] * b[4 * c + k];
        }
}

/* The matrices the course inverts: a perspective projection times a camera's view. The tolerance
 * is a few hundred ulps of double on entries near 1 (the far plane's terms reach 1e3). */
static void test_view_proj_inverse(void **state)
{
    (void)state;
    mat4 proj, view, vp;
    glm_perspective(glm_rad(60.0f), 1.25f, 0.1f, 300.0f, proj);
    glm_lookat((vec3){3.0f, 4.0f, 9.0f}, (vec3){0.5f, 0.0f, -1.0f}, (vec3){0.0f, 1.0f, 0.0f}, view);
    glm_mat4_mul(proj, view, vp);
    double m[16], inv[16], id[16];
    mat4d_from_float((const float *)vp, m);
    assert_true(mat4d_invert(m, inv));
    multiply(m, inv, id);
    for (int i = 0; i < 16; i++)
        assert_true(fabs(id[i] - (i % 5 == 0 ? 1.0 : 0.0)) <= 1e-12);
}

/* A scale and a translation: every number of the inverse is a power of two, so it comes out exact. */
static void test_known_inverse(void **state)
{
    (void)state;
    const double m[16] = {2, 0, 0, 0, 0, 4, 0, 0, 0, 0, 0.5, 0, 8, -2, 1, 1};
    const double want[16] = {0.5, 0, 0, 0, 0, 0.25, 0, 0, 0, 0, 2, 0, -4, 0.5, -2, 1};
    double inv[16];
    assert_true(mat4d_invert(m, inv));
    for (int i = 0; i < 16; i++)
        assert_true(inv[i] == want[i]);
}

static void test_singular_refused(void **state)
{
    (void)state;
    const double m[16] = {1, 2, 3, 4, 2, 4, 6, 8, 0, 1, 0, 0, 0, 0, 1, 0}; /* column 1 = 2 x column 0 */
    double inv[16];
    assert_false(mat4d_invert(m, inv));
}

UNIT_TEST_MAIN(NULL, NULL, cmocka_unit_test(test_view_proj_inverse), cmocka_unit_test(test_known_inverse),
               cmocka_unit_test(test_singular_refused))
