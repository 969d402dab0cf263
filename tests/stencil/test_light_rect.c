/* test_light_rect.c - chapter 08's batches are only right if each light's rectangle holds every
 * pixel its volume can touch: two lights of one batch must never share a pixel, or their stencil
 * counts mix and a light goes missing (common/render/light_batches.c, light_batches_rect).
 *
 * For random cameras (eye, target, field of view, near plane, size) and random spheres, points
 * sampled over the sphere are projected with the camera's matrices in double; every point in front
 * of the eye and inside the view must fall in a pixel of the rectangle. The volume mesh lies inside
 * the sphere it is given (its vertices on it, light_batches_make passes radius x 1 / inradius), so
 * the sphere's pixels hold the mesh's. Not vacuous: the rectangles must also be small where the
 * sphere is (a sphere far in front of the camera gets less than the whole view), and a sphere around
 * the eye or behind it gets the whole view. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <cmocka.h>

#include "light_batches.h"
#include "../unit/test_util.h"

#define CAMERAS 200
#define SPHERES 200
#define SAMPLES 400 /* points over each sphere */

static double uniform(double lo, double hi) { return lo + (hi - lo) * ((double)rand() / RAND_MAX); }

static void make_view(frame_view *v, unsigned seed)
{
    srand(seed);
    v->width = (int)uniform(1, 1600), v->height = (int)uniform(1, 1200);
    vec3 eye = {(float)uniform(-20, 20), (float)uniform(0, 10), (float)uniform(-20, 20)};
    vec3 target = {(float)uniform(-5, 5), (float)uniform(-1, 3), (float)uniform(-5, 5)};
    vec3 up = {0, 1, 0};
    glm_lookat(eye, target, up, v->view);
    glm_perspective((float)uniform(0.3, 2.0), (float)v->width / (float)v->height, (float)uniform(0.01, 2.0),
                    (float)uniform(30, 1000), v->proj);
    glm_mat4_mul(v->proj, v->view, v->view_proj);
    glm_vec3_copy(eye, v->eye);
}

/* The pixel that a point lands in, or false when it is behind the eye or outside the view. */
static bool pixel_of(const frame_view *v, const double p[3], int pixel[2])
{
    double clip[4];
    for (int r = 0; r < 4; r++)
        clip[r] = v->view_proj[0][r] * p[0] + v->view_proj[1][r] * p[1] + v->view_proj[2][r] * p[2] +
                  v->view_proj[3][r];
    if (clip[3] <= 1e-9 || fabs(clip[0]) > clip[3] || fabs(clip[1]) > clip[3])
        return false;
    const int size[2] = {v->width, v->height};
    for (int k = 0; k < 2; k++) {
        double at = (clip[k] / clip[3] + 1.0) * 0.5 * size[k];
        pixel[k] = (int)fmin(floor(at), size[k] - 1);
    }
    return true;
}

static void test_rect_holds_the_sphere(void **state)
{
    (void)state;
    long checked = 0, small = 0;
    for (unsigned c = 0; c < CAMERAS; c++) {
        frame_view v;
        make_view(&v, 1000 + c);
        for (int s = 0; s < SPHERES; s++) {
            float centre[3] = {(float)uniform(-30, 30), (float)uniform(-5, 15), (float)uniform(-30, 30)};
            float radius = (float)exp(uniform(log(0.05), log(40.0)));
            int rect[4];
            light_batches_rect(&v, centre, radius, rect);
            assert_true(0 <= rect[0] && rect[0] <= rect[2] && rect[2] < v.width);
            assert_true(0 <= rect[1] && rect[1] <= rect[3] && rect[3] < v.height);
            small += (long)(rect[2] - rect[0] + 1) * (rect[3] - rect[1] + 1) < (long)v.width * v.height;
            for (int i = 0; i < SAMPLES; i++) {
                /* a point on the sphere, and one a quarter of the way in */
                double z = uniform(-1, 1), a = uniform(0, 2 * acos(-1.0)), rho = sqrt(1 - z * z);
                double scale = i % 4 ? 1.0 : 0.75;
                double p[3] = {centre[0] + scale * radius * rho * cos(a), centre[1] + scale * radius * rho * sin(a),
                               centre[2] + scale * radius * z};
                int px[2];
                if (!pixel_of(&v, p, px))
                    continue;
                checked++;
                if (px[0] < rect[0] || px[0] > rect[2] || px[1] < rect[1] || px[1] > rect[3])
                    fail_msg("camera %u sphere %d (%g %g %g r %g): pixel %d %d outside [%d %d] x [%d %d]", c, s,
                             centre[0], centre[1], centre[2], radius, px[0], px[1], rect[0], rect[2], rect[1],
                             rect[3]);
            }
        }
    }
    print_message("%ld points checked; %ld of %d rectangles smaller than the view\n", checked, small,
                  CAMERAS * SPHERES);
    assert_true(checked > 1000000);
    assert_true(small > CAMERAS * SPHERES / 2);
}

static void test_whole_view_around_or_behind_the_eye(void **state)
{
    (void)state;
    frame_view v;
    make_view(&v, 7);
    int rect[4];
    /* around the eye */
    light_batches_rect(&v, v.eye, 1.0f, rect);
    assert_int_equal(rect[0], 0), assert_int_equal(rect[1], 0);
    assert_int_equal(rect[2], v.width - 1), assert_int_equal(rect[3], v.height - 1);
    /* a small sphere far in front: a small rectangle; the same behind the eye: the whole view */
    vec3 forward = {-v.view[0][2], -v.view[1][2], -v.view[2][2]};
    float front[3], behind[3];
    for (int k = 0; k < 3; k++)
        front[k] = v.eye[k] + 20.0f * forward[k], behind[k] = v.eye[k] - 20.0f * forward[k];
    light_batches_rect(&v, front, 0.1f, rect);
    assert_true((long)(rect[2] - rect[0] + 1) * (rect[3] - rect[1] + 1) < (long)v.width * v.height / 4);
    light_batches_rect(&v, behind, 0.1f, rect);
    assert_int_equal(rect[2] - rect[0] + 1, v.width);
    assert_int_equal(rect[3] - rect[1] + 1, v.height);
}

UNIT_TEST_MAIN(NULL, NULL, cmocka_unit_test(test_rect_holds_the_sphere),
               cmocka_unit_test(test_whole_view_around_or_behind_the_eye))
