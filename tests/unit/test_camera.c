/* test_camera.c - the window's camera moves: distances kept, never over the pole, zoom never
 * through the target, F frames the box, and the printed pose reads back exactly. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "camera.h"
#include "scene.h"
#include "test_util.h"

#include <cglm/cglm.h>
#include <math.h>
#include <string.h>

#define EPS 1e-4f /* single-precision rotations of unit-sized vectors */

static scene_camera start(void)
{
    return (scene_camera){.eye = {0.0f, 2.0f, 6.0f}, .target = {0.0f, 0.0f, 0.0f}, .up = {0.0f, 1.0f, 0.0f},
                          .fovy_deg = 60.0f, .near_plane = 0.1f, .far_plane = 100.0f};
}

static float dist(const float *a, const float *b) { return glm_vec3_distance((float *)a, (float *)b); }

static void test_orbit_keeps_distance_and_target(void **state)
{
    (void)state;
    scene_camera c = start();
    float d0 = dist(c.eye, c.target);
    for (int i = 0; i < 100; i++)
        camera_orbit(&c, 0.1f, 0.05f);
    assert_float_equal(dist(c.eye, c.target), d0, EPS * d0);
    assert_float_equal(c.target[0], 0.0f, 0.0f);
    assert_float_equal(c.target[1], 0.0f, 0.0f);
}

/* Pitching far past the pole stops 2 degrees short of it, where the view is still defined; a
 * positive pitch raises the eye. */
static void test_orbit_stops_before_the_pole(void **state)
{
    (void)state;
    scene_camera c = start();
    camera_orbit(&c, 0.0f, 10.0f);
    vec3 offset;
    glm_vec3_sub(c.eye, c.target, offset);
    float angle = acosf(offset[1] / glm_vec3_norm(offset));
    assert_float_equal(angle, 0.035f, 1e-3f);
    camera_orbit(&c, 0.0f, -10.0f);
    glm_vec3_sub(c.eye, c.target, offset);
    assert_float_equal(acosf(offset[1] / glm_vec3_norm(offset)), GLM_PIf - 0.035f, 1e-3f);
}

static void test_look_keeps_the_eye(void **state)
{
    (void)state;
    scene_camera c = start();
    float d0 = dist(c.eye, c.target);
    camera_look(&c, 0.7f, -0.2f);
    assert_float_equal(c.eye[2], 6.0f, 0.0f);
    assert_float_equal(dist(c.eye, c.target), d0, EPS * d0);
    assert_true(c.target[0] != 0.0f);
}

static void test_fly_moves_both_along_the_view(void **state)
{
    (void)state;
    scene_camera c = start();
    vec3 dir;
    glm_vec3_sub(c.target, c.eye, dir);
    glm_vec3_normalize(dir);
    camera_fly(&c, 2.0f, 0.0f);
    assert_float_equal(c.eye[1], 2.0f + 2.0f * dir[1], EPS);
    assert_float_equal(c.eye[2], 6.0f + 2.0f * dir[2], EPS);
    assert_float_equal(c.target[2], 2.0f * dir[2], EPS);
    camera_fly(&c, 0.0f, 1.0f); /* right of a view along -z is +x */
    assert_float_equal(c.eye[0], 1.0f, EPS);
}

static void test_zoom_never_passes_the_target(void **state)
{
    (void)state;
    scene_camera c = start();
    float d0 = dist(c.eye, c.target);
    camera_zoom(&c, 1.0f);
    assert_float_equal(dist(c.eye, c.target), 0.85f * d0, EPS * d0);
    camera_zoom(&c, 1000.0f);
    assert_float_equal(dist(c.eye, c.target), 2.0f * c.near_plane, EPS);
    camera_zoom(&c, -2.0f);
    assert_true(dist(c.eye, c.target) > 2.0f * c.near_plane);
}

/* The box's bounding sphere exactly fills the narrower angle of view. */
static void test_frame_fits_the_box(void **state)
{
    (void)state;
    scene_camera c = start();
    const float lo[3] = {-10.0f, 0.0f, -4.0f}, hi[3] = {10.0f, 2.0f, 4.0f};
    camera_frame(&c, lo, hi, 0.5f); /* a tall window: the horizontal angle is the narrower */
    float radius = 0.5f * dist(lo, hi);
    float half_h = atanf(tanf(glm_rad(30.0f)) * 0.5f);
    assert_float_equal(c.target[1], 1.0f, EPS);
    assert_float_equal(dist(c.eye, c.target), radius / sinf(half_h), 1e-3f);
    assert_true(c.far_plane >= dist(c.eye, c.target) + radius);
}

/* %.9g round-trips a float: the printed line, parsed as a scene's camera, is the same camera. */
static void test_format_reads_back_exactly(void **state)
{
    (void)state;
    scene_camera c = start();
    camera_orbit(&c, 0.123f, 0.456f);
    camera_fly(&c, 0.789f, -0.321f);
    char line[512];
    assert_true(camera_format(&c, line, sizeof line) < (int)sizeof line);
    assert_int_equal(strncmp(line, "camera eye ", 11), 0);
    scene s;
    assert_true(scene_parse_string(line, "pose", "", &s));
    assert_memory_equal(&s.camera, &c, sizeof c);
    scene_destroy(&s);
}

UNIT_TEST_MAIN(NULL, NULL, cmocka_unit_test(test_orbit_keeps_distance_and_target),
               cmocka_unit_test(test_orbit_stops_before_the_pole), cmocka_unit_test(test_look_keeps_the_eye),
               cmocka_unit_test(test_fly_moves_both_along_the_view), cmocka_unit_test(test_zoom_never_passes_the_target),
               cmocka_unit_test(test_frame_fits_the_box), cmocka_unit_test(test_format_reads_back_exactly))
