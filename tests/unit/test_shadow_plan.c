/* test_shadow_plan.c - chapter 14's shadow bookkeeping (common/shadows/shadow_plan.c), without GL:
 * importance and tiers with hysteresis, tiles that never overlap and stay inside the atlas, the least
 * important lights shrunk then dropped when the atlas is full, --shadows N, per-tile caster culling
 * (never losing a caster that can reach the tile), and the cache (a still frame draws nothing; a
 * moved light or caster redraws exactly the lights it can touch), and an empty plan (no light, every
 * light `shadow off`, --shadows 0).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "shadow_plan.h"
#include "test_util.h"

#include <math.h>

static shadow_light point(float x, float y, float z, float radius, int source)
{
    return (shadow_light){.position = {x, y, z}, .radius = radius, .source = source};
}

static shadow_caster box(float x, float y, float z, float half)
{
    return (shadow_caster){.lo = {x - half, y - half, z - half}, .hi = {x + half, y + half, z + half}, .triangles = 12};
}

static const shadow_plan_desc DESC = {.atlas_size = 4096, .max_shadowed = -1, .pcf = 3, .normal_offset = 1.5f,
                                      .cull = true};

/* Importance: the sine of the sphere's angular radius, 1 with the eye inside it. */
static void test_importance(void **state)
{
    (void)state;
    shadow_light l = point(0, 0, 0, 2, 0);
    assert_float_equal(shadow_importance((vec3){0, 0, 8}, &l), 0.25f, 1e-6f);
    assert_float_equal(shadow_importance((vec3){0, 0, 1}, &l), 1.0f, 0.0f);
    assert_int_equal(shadow_tier(1.0f, -1), 0);
    assert_int_equal(shadow_tier(0.3f, -1), 1);
    assert_int_equal(shadow_tier(0.2f, -1), 2);
    assert_int_equal(shadow_tier(0.01f, -1), 3);
    /* hysteresis: just across a border keeps the old tier, well across it moves */
    assert_int_equal(shadow_tier(0.26f, 2), 2);
    assert_int_equal(shadow_tier(0.31f, 2), 1);
    assert_int_equal(shadow_tier(0.24f, 1), 1);
    assert_int_equal(shadow_tier(0.20f, 1), 2);
}

/* The cube face: the major axis of the light-to-point vector; ties to x, then y. */
static void test_cube_face(void **state)
{
    (void)state;
    assert_int_equal(shadow_cube_face((vec3){2, 1, -1}), 0);
    assert_int_equal(shadow_cube_face((vec3){-2, 1, -1}), 1);
    assert_int_equal(shadow_cube_face((vec3){0.5f, 3, 1}), 2);
    assert_int_equal(shadow_cube_face((vec3){0.5f, -3, 1}), 3);
    assert_int_equal(shadow_cube_face((vec3){0.5f, 0, 1}), 4);
    assert_int_equal(shadow_cube_face((vec3){0.5f, 0, -1}), 5);
    assert_int_equal(shadow_cube_face((vec3){1, 1, 1}), 0);  /* a corner */
    assert_int_equal(shadow_cube_face((vec3){0, -1, -1}), 3); /* an edge */
}

static bool overlap(const shadow_tile *a, const shadow_tile *b)
{
    return a->x < b->x + b->size && b->x < a->x + a->size && a->y < b->y + b->size && b->y < a->y + a->size;
}

/* 100 lights at many distances: tiles inside the atlas, none overlapping, six per point light. */
static void test_packing(void **state)
{
    (void)state;
    shadow_light lights[100];
    for (int i = 0; i < 100; i++)
        lights[i] = point((float)(i % 10), 0, (float)(i / 10) * 3.0f, 1.0f + 0.05f * (float)i, i);
    shadow_plan p;
    shadow_plan_create(&p, &DESC);
    assert_true(shadow_plan_frame(&p, (vec3){0, 2, 0}, lights, 100, NULL, 0));
    assert_int_equal(p.stats.shadowed + p.stats.dropped, 100);
    assert_int_equal(p.tile_count, 6 * p.stats.shadowed);
    for (int a = 0; a < p.tile_count; a++) {
        const shadow_tile *t = &p.tiles[a];
        assert_true(t->x >= 0 && t->y >= 0 && t->x + t->size <= 4096 && t->y + t->size <= 4096);
        assert_true(t->tan_half > 1.0f); /* the gutter widens the 90 degrees */
        for (int b = a + 1; b < p.tile_count; b++)
            assert_false(overlap(t, &p.tiles[b]));
    }
    shadow_plan_destroy(&p);
}

/* A full atlas: the least important lights take the smallest tiles, then are dropped, never the
 * most important; --shadows N leaves the rest unshadowed. */
static void test_overflow(void **state)
{
    (void)state;
    shadow_light lights[64];
    for (int i = 0; i < 64; i++)
        lights[i] = point(0, 0, -1.0f - (float)i, 3.0f, i); /* light 0 the nearest to the eye */
    shadow_plan_desc small = DESC;
    small.atlas_size = 512; /* 16 tiles of 128: two point lights */
    shadow_plan p;
    shadow_plan_create(&p, &small);
    assert_true(shadow_plan_frame(&p, (vec3){0, 0, 0}, lights, 64, NULL, 0));
    assert_int_equal(p.stats.shadowed, 2);
    assert_int_equal(p.stats.dropped, 62);
    assert_int_equal(p.status[0], SHADOW_SHADOWED);
    assert_int_equal(p.status[1], SHADOW_SHADOWED);
    assert_int_equal(p.status[63], SHADOW_DROPPED);
    shadow_plan_destroy(&p);

    shadow_plan_desc few = DESC;
    few.max_shadowed = 5;
    lights[3].shadow_off = true;
    shadow_plan_create(&p, &few);
    assert_true(shadow_plan_frame(&p, (vec3){0, 0, 0}, lights, 64, NULL, 0));
    assert_int_equal(p.stats.shadowed, 5);
    assert_int_equal(p.stats.off, 1);
    assert_int_equal(p.stats.not_chosen, 58);
    assert_int_equal(p.status[5], SHADOW_SHADOWED); /* the fifth most important with a shadow */
    shadow_plan_destroy(&p);
}

/* Nothing to shadow: no light at all, every light `shadow off`, or --shadows 0. The plan is empty,
 * and getting there sorts no array (qsort(NULL, 0, ...) once stopped every chapter under UBSan). */
static void test_nothing_shadowed(void **state)
{
    (void)state;
    shadow_light lights[3] = {point(0, 0, -2, 3, 0), point(1, 0, -2, 3, 1), point(2, 0, -2, 3, 2)};
    shadow_caster caster = box(0, 0, -1, 0.5f);
    shadow_plan p;
    shadow_plan_create(&p, &DESC);
    assert_true(shadow_plan_frame(&p, (vec3){0, 0, 0}, NULL, 0, &caster, 1));
    assert_int_equal(p.tile_count, 0);
    assert_int_equal(p.stats.shadowed, 0);
    shadow_plan_destroy(&p);

    for (int i = 0; i < 3; i++)
        lights[i].shadow_off = true;
    shadow_plan_create(&p, &DESC);
    assert_true(shadow_plan_frame(&p, (vec3){0, 0, 0}, lights, 3, &caster, 1));
    assert_int_equal(p.tile_count, 0);
    assert_int_equal(p.stats.off, 3);
    shadow_plan_destroy(&p);

    shadow_plan_desc none = DESC;
    none.max_shadowed = 0;
    for (int i = 0; i < 3; i++)
        lights[i].shadow_off = false;
    shadow_plan_create(&p, &none);
    assert_true(shadow_plan_frame(&p, (vec3){0, 0, 0}, lights, 3, &caster, 1));
    assert_int_equal(p.tile_count, 0);
    assert_int_equal(p.stats.not_chosen, 3);
    shadow_plan_destroy(&p);
}

/* Culling: a caster outside the sphere is drawn nowhere; one inside, only in the faces that see it. */
static void test_culling(void **state)
{
    (void)state;
    shadow_light l = point(0, 0, 0, 3, 0);
    shadow_caster casters[3] = {box(2, 0, 0, 0.5f), box(10, 0, 0, 0.5f), box(0, -1, 0, 0.2f)};
    casters[2].cast_off = false;
    shadow_plan p;
    shadow_plan_create(&p, &DESC);
    assert_true(shadow_plan_frame(&p, (vec3){0, 0, 9}, &l, 1, casters, 3));
    for (int t = 0; t < p.tile_count; t++) {
        const shadow_tile *tile = &p.tiles[t];
        bool has[3] = {false, false, false};
        for (int k = 0; k < tile->caster_count; k++)
            has[tile->casters[k]] = true;
        assert_false(has[1]);
        assert_int_equal(has[0], tile->face == 0); /* +X only: the box at x = 2 */
        assert_int_equal(has[2], tile->face == 3); /* -Y only */
    }
    assert_int_equal(p.stats.draws, 2);
    assert_int_equal(p.stats.draws_unculled, 18);
    assert_true(shadow_box_meets_sphere((vec3){2, -1, -1}, (vec3){4, 1, 1}, (vec3){0, 0, 0}, 2.0f));
    assert_false(shadow_box_meets_sphere((vec3){2, 2, -1}, (vec3){4, 4, 1}, (vec3){0, 0, 0}, 2.5f));
    shadow_plan_destroy(&p);
}

/* The cache: a second still frame draws nothing; a moved light redraws its own six tiles; a moved
 * caster redraws the lights whose spheres it was or is in, and no other. */
static void test_cache(void **state)
{
    (void)state;
    shadow_light lights[2] = {point(0, 0, 0, 3, 0), point(20, 0, 0, 3, 1)};
    shadow_caster casters[2] = {box(1.5f, 0, 0, 0.5f), box(21.5f, 0, 0, 0.5f)};
    const vec3 eye = {10, 5, 10};
    shadow_plan p;
    shadow_plan_create(&p, &DESC);
    assert_true(shadow_plan_frame(&p, eye, lights, 2, casters, 2));
    assert_int_equal(p.stats.tiles_drawn, 12);
    assert_true(shadow_plan_frame(&p, eye, lights, 2, casters, 2));
    assert_int_equal(p.stats.tiles_drawn, 0);
    lights[1].position[1] = 0.5f;
    assert_true(shadow_plan_frame(&p, eye, lights, 2, casters, 2));
    assert_int_equal(p.stats.tiles_drawn, 6);
    assert_true(p.tiles[p.first_tile[1]].redraw);
    assert_false(p.tiles[p.first_tile[0]].redraw);
    casters[0].lo[2] += 0.25f, casters[0].hi[2] += 0.25f;
    assert_true(shadow_plan_frame(&p, eye, lights, 2, casters, 2));
    assert_int_equal(p.stats.tiles_drawn, 6);
    assert_true(p.tiles[p.first_tile[0]].redraw);
    shadow_plan_destroy(&p);
}

UNIT_TEST_MAIN(NULL, NULL, cmocka_unit_test(test_importance), cmocka_unit_test(test_cube_face),
               cmocka_unit_test(test_nothing_shadowed),
               cmocka_unit_test(test_packing), cmocka_unit_test(test_overflow), cmocka_unit_test(test_culling),
               cmocka_unit_test(test_cache))
