/* test_light_generate.c - the --lights generator: reproducible, inside the scene, distinct colours,
 * and radii that follow the documented rule. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "light.h"
#include "scene.h"
#include "test_util.h"

/* Box expected for the test scene, worked out by hand from light.h's rule: object positions and
 * keys span x -3..6, y 0..5, z -4..2; widened by 10% of each side; y from 0.1 to top + 1. */
static const float EXPECTED_LO[3] = {-3.9f, 0.1f, -4.6f};
static const float EXPECTED_HI[3] = {6.9f, 6.5f, 2.6f};
#define EXPECTED_EXTENT 10.8 /* x side */
#define BOX_EPSILON 1e-5f    /* the rule is evaluated in float */

static scene_key keys_c[2] = {{0.0f, {0.0f, 5.0f, 0.0f}}, {1.0f, {-3.0f, 1.0f, 0.0f}}};

static scene make_scene(void)
{
    static scene_object objects[3];
    memset(objects, 0, sizeof objects);
    glm_vec3_copy((vec3){-2.0f, 0.0f, -4.0f}, objects[0].position);
    glm_vec3_copy((vec3){6.0f, 3.0f, 2.0f}, objects[1].position);
    glm_vec3_copy((vec3){0.0f, 0.0f, 0.0f}, objects[2].position);
    objects[2].keys = keys_c;
    objects[2].key_count = 2;
    scene s = {0};
    s.objects = objects;
    s.object_count = 3;
    glm_vec3_copy((vec3){0.0f, 1.0f, 0.0f}, s.camera.target);
    return s;
}

/* Gives the scene two lights with heap keys, as the loader would, so replacing them must free. */
static void add_old_lights(scene *s)
{
    s->lights = calloc(2, sizeof *s->lights);
    assert_non_null(s->lights);
    s->light_count = 2;
    for (int i = 0; i < 2; i++) {
        s->lights[i].keys = calloc(3, sizeof(scene_key));
        assert_non_null(s->lights[i].keys);
        s->lights[i].key_count = 3;
    }
}

static void free_lights(scene *s)
{
    for (int i = 0; i < s->light_count; i++)
        free(s->lights[i].keys);
    free(s->lights);
    s->lights = NULL;
    s->light_count = 0;
}

static bool lights_equal(const scene_light *a, const scene_light *b)
{
    return memcmp(a->position, b->position, sizeof a->position) == 0 &&
           memcmp(a->color, b->color, sizeof a->color) == 0 && a->intensity == b->intensity &&
           a->kc == b->kc && a->kl == b->kl && a->kq == b->kq && a->keys == NULL && b->keys == NULL;
}

static void test_bounds_follow_the_rule(void **state)
{
    (void)state;
    scene s = make_scene();
    float lo[3], hi[3];
    light_generate_bounds(&s, lo, hi);
    for (int a = 0; a < 3; a++) {
        assert_true(fabsf(lo[a] - EXPECTED_LO[a]) <= BOX_EPSILON);
        assert_true(fabsf(hi[a] - EXPECTED_HI[a]) <= BOX_EPSILON);
    }
    assert_true(fabs(light_generate_radius(lo, hi, 16) - EXPECTED_EXTENT * 1.5 / 4.0) <= 1e-5);
    assert_true(fabs(light_generate_radius(lo, hi, 1) - EXPECTED_EXTENT) <= 1e-5); /* clamped down */
    assert_true(light_generate_radius(lo, hi, 65536) == 0.5);                      /* clamped up */

    /* No objects: a 10 x 10 square around the camera target (0 1 0), y 0.1 .. 1 + 1. */
    scene empty = {0};
    glm_vec3_copy((vec3){0.0f, 1.0f, 0.0f}, empty.camera.target);
    light_generate_bounds(&empty, lo, hi);
    const float lo_empty[3] = {-5.0f, 0.1f, -5.0f}, hi_empty[3] = {5.0f, 2.0f, 5.0f};
    for (int a = 0; a < 3; a++) {
        assert_true(fabsf(lo[a] - lo_empty[a]) <= BOX_EPSILON);
        assert_true(fabsf(hi[a] - hi_empty[a]) <= BOX_EPSILON);
    }
}

static void test_same_seed_same_lights(void **state)
{
    (void)state;
    scene a = make_scene(), b = make_scene(), c = make_scene();
    add_old_lights(&a);
    assert_true(light_generate(&a, 1000, 42));
    assert_true(light_generate(&b, 1000, 42));
    assert_true(light_generate(&c, 1000, 43));
    assert_int_equal(a.light_count, 1000);
    assert_int_equal(b.light_count, 1000);
    int same_as_other_seed = 0;
    for (int i = 0; i < 1000; i++) {
        assert_true(lights_equal(&a.lights[i], &b.lights[i]));
        same_as_other_seed += memcmp(a.lights[i].position, c.lights[i].position, sizeof(vec3)) == 0;
    }
    assert_int_equal(same_as_other_seed, 0);
    /* Regenerating over existing lights gives the same set again. */
    assert_true(light_generate(&b, 1000, 42));
    for (int i = 0; i < 1000; i++)
        assert_true(lights_equal(&a.lights[i], &b.lights[i]));
    free_lights(&a);
    free_lights(&b);
    free_lights(&c);
}

static void test_zero_lights(void **state)
{
    (void)state;
    scene s = make_scene();
    add_old_lights(&s);
    assert_true(light_generate(&s, 0, 7));
    assert_int_equal(s.light_count, 0);
    assert_null(s.lights);
}

/* Every property the header promises, on a large set. */
static void check_lights(const scene *s, int count)
{
    assert_int_equal(s->light_count, count);
    float lo[3], hi[3];
    light_generate_bounds(s, lo, hi);
    double radius = light_generate_radius(lo, hi, count);
    float seen_lo[3] = {INFINITY, INFINITY, INFINITY}, seen_hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    int dominant[3] = {0, 0, 0};
    for (int i = 0; i < count; i++) {
        const scene_light *l = &s->lights[i];
        for (int a = 0; a < 3; a++) {
            assert_true(isfinite(l->position[a]) && isfinite(l->color[a]));
            assert_true(l->position[a] >= lo[a] && l->position[a] <= hi[a]);
            seen_lo[a] = fminf(seen_lo[a], l->position[a]);
            seen_hi[a] = fmaxf(seen_hi[a], l->position[a]);
            assert_true(l->color[a] >= 0.0f && l->color[a] <= 1.0f);
        }
        float top = fmaxf(fmaxf(l->color[0], l->color[1]), l->color[2]);
        float bottom = fminf(fminf(l->color[0], l->color[1]), l->color[2]);
        assert_true(top == 1.0f);
        assert_true(bottom <= 0.3f + 1e-6f); /* saturation >= 0.7 */
        dominant[l->color[0] == 1.0f ? 0 : l->color[1] == 1.0f ? 1 : 2]++;
        assert_true(l->intensity == 1.0f && l->kc == 1.0f && l->kl == 0.0f);
        assert_true(isfinite(l->kq) && l->kq > 0.0f);
        assert_null(l->keys);
        assert_int_equal(l->key_count, 0);
        double peak = light_peak(l->color, l->intensity);
        double r = light_radius(l->kc, l->kl, l->kq, peak, LIGHT_DEFAULT_CUTOFF);
        assert_true(fabs(r - radius) <= 1e-6 * radius); /* kq is stored as a float */
    }
    /* Uniform placement reaches the box's edges; hues are spread over all three primaries
     * (a large set only: a few lights may cluster by chance). */
    for (int a = 0; a < 3 && count >= 10000; a++) {
        float side = hi[a] - lo[a];
        assert_true(seen_lo[a] - lo[a] < 0.01f * side);
        assert_true(hi[a] - seen_hi[a] < 0.01f * side);
        assert_true(dominant[a] > count / 4);
    }
}

static void test_many_lights(void **state)
{
    (void)state;
    scene s = make_scene();
    add_old_lights(&s);
    assert_true(light_generate(&s, 65536, 1));
    float lo[3], hi[3];
    light_generate_bounds(&s, lo, hi);
    for (int a = 0; a < 3; a++) {
        assert_true(fabsf(lo[a] - EXPECTED_LO[a]) <= BOX_EPSILON);
        assert_true(fabsf(hi[a] - EXPECTED_HI[a]) <= BOX_EPSILON);
    }
    check_lights(&s, 65536);
    assert_true(light_generate(&s, 16, 1));
    check_lights(&s, 16);
    free_lights(&s);
}

static void test_million_lights_empty_scene(void **state)
{
    (void)state;
    scene s = {0};
    glm_vec3_copy((vec3){2.0f, 0.0f, -3.0f}, s.camera.target);
    assert_true(light_generate(&s, 1000000, 99));
    check_lights(&s, 1000000);
    free_lights(&s);
}

UNIT_TEST_MAIN(NULL, NULL, cmocka_unit_test(test_bounds_follow_the_rule),
               cmocka_unit_test(test_same_seed_same_lights), cmocka_unit_test(test_zero_lights),
               cmocka_unit_test(test_many_lights), cmocka_unit_test(test_million_lights_empty_scene))
