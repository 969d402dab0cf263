/* test_ibl_sh.c - chapter 19's arithmetic without GL (chapters/ibl_sh.c): cube texels that tile the
 * sphere (solid angles summing to 4 pi, face centres on the axes, GL's orientation), harmonics that
 * give back a constant and a linear radiance's irradiance exactly, the per-frame pick (at most
 * IBL_MAX_PICKED, most important first, a probe around the eye first of all), the per-pixel weight
 * (1 at the centre, 0 from the radius on) and the shininess-to-roughness map.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "ibl_sh.h"

#include <math.h>
#include <stdlib.h>

enum { N = 16 };

static void test_solid_angles(void **state)
{
    (void)state;
    double sum = 0.0;
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++)
            sum += 6.0 * ibl_cube_solid_angle(N, i, j);
    assert_float_equal(sum, 4.0 * GLM_PI, 1e-9);
    /* a corner texel sees less of the sphere than a centre one */
    assert_true(ibl_cube_solid_angle(N, 0, 0) < ibl_cube_solid_angle(N, N / 2, N / 2));
}

static void test_directions(void **state)
{
    (void)state;
    static const double axes[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int f = 0; f < 6; f++) {
        double d[3];
        ibl_cube_direction(f, N, N / 2.0, N / 2.0, d);
        for (int k = 0; k < 3; k++)
            assert_float_equal(d[k], axes[f][k], 1e-12);
    }
    /* GL's table: on +X, s grows towards -z and t towards -y */
    double d[3];
    ibl_cube_direction(0, N, N, N, d);
    assert_true(d[2] < 0.0 && d[1] < 0.0);
    ibl_cube_direction(2, N, N, N, d); /* +Y: s towards +x, t towards +z */
    assert_true(d[0] > 0.0 && d[2] > 0.0);
}

/* Radiance a + b . d over the cube, projected, must give E / pi = a + (2/3) b . n exactly: bands 0
 * and 1 hold it whole, and the cosine lobe scales band 1 by 2/3. */
static void test_sh_linear(void **state)
{
    (void)state;
    const double a = 0.7, b[3] = {0.2, -0.1, 0.3};
    float *faces[6];
    for (int f = 0; f < 6; f++) {
        faces[f] = malloc(sizeof(float) * 3 * N * N);
        for (int j = 0; j < N; j++)
            for (int i = 0; i < N; i++) {
                double d[3];
                ibl_cube_direction(f, N, i + 0.5, j + 0.5, d);
                for (int c = 0; c < 3; c++)
                    faces[f][3 * (j * N + i) + c] = (float)(a + b[0] * d[0] + b[1] * d[1] + b[2] * d[2]);
            }
    }
    double sh[SHADER_IBL_SH_COEFFS][3], out[3];
    ibl_sh_project((const float *const *)faces, N, sh);
    const double n[3] = {0.6, 0.0, 0.8};
    ibl_sh_irradiance((const double(*)[3])sh, n, out);
    /* the texel centres stand for their texels: a 16^2 face is exact to about 1e-3 */
    for (int c = 0; c < 3; c++)
        assert_float_equal(out[c], a + 2.0 / 3.0 * (b[0] * n[0] + b[1] * n[1] + b[2] * n[2]), 2e-3);
    for (int f = 0; f < 6; f++)
        free(faces[f]);
}

static void test_pick(void **state)
{
    (void)state;
    const scene_probe probes[6] = {{{10, 0, 0}, 1}, {{0, 0, 0}, 1}, {{5, 0, 0}, 1},
                                   {{20, 0, 0}, 1}, {{3, 0, 0}, 1}, {{40, 0, 0}, 30}};
    const float eye[3] = {0, 0, 0.5f};
    int out[SHADER_IBL_MAX_PICKED];
    int n = ibl_probes_pick_indices(probes, 6, eye, out);
    assert_int_equal(n, SHADER_IBL_MAX_PICKED);
    assert_int_equal(out[0], 1); /* the eye is inside it: importance 1 */
    assert_int_equal(out[1], 5); /* 30 / 40: large and far beats small and near */
    assert_int_equal(out[2], 4);
    assert_int_equal(out[3], 2);
    assert_int_equal(ibl_probes_pick_indices(probes, 2, eye, out), 2);
    assert_int_equal(ibl_probes_pick_indices(probes, 0, eye, out), 0);
}

static void test_weight_and_roughness(void **state)
{
    (void)state;
    const scene_probe p = {{1, 2, 3}, 2};
    const double centre[3] = {1, 2, 3}, edge[3] = {3, 2, 3}, outside[3] = {1, 5, 3}, half[3] = {1, 3, 3};
    assert_float_equal(ibl_probe_weight(&p, centre), 1.0, 0.0);
    assert_float_equal(ibl_probe_weight(&p, edge), 0.0, 0.0);
    assert_float_equal(ibl_probe_weight(&p, outside), 0.0, 0.0);
    assert_float_equal(ibl_probe_weight(&p, half), 0.5625, 1e-12); /* (1 - 1/4)^2 */
    assert_float_equal(ibl_shininess_roughness(0.0), 1.0, 1e-12);
    assert_true(ibl_shininess_roughness(256.0) < ibl_shininess_roughness(16.0));
    assert_float_equal(pow(ibl_shininess_roughness(64.0), 4.0), 2.0 / 66.0, 1e-12);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_solid_angles), cmocka_unit_test(test_directions), cmocka_unit_test(test_sh_linear),
        cmocka_unit_test(test_pick), cmocka_unit_test(test_weight_and_roughness),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
