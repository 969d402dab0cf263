/* test_scene_pbr.c - the metallic-roughness material line: its fields, its defaults, its maps (paths
 * relative to the scene, each image once per colour space) and every way it can be wrong, with the
 * file:line message each gets. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "scene.h"
#include "test_util.h"

#include <stdio.h>
#include <string.h>
#include <unistd.h>

/* Parsed floats are the nearest float to the decimal text. */
#define EPS 1e-6f

static int setup_dir(void **state)
{
    (void)state;
    if (tmp_dir_create("/tmp/test_scene_pbr_XXXXXX") != 0)
        return -1;
    /* The parser reads an image's header: a 1 x 1 PNG will do; not_image.png is text. */
    static const unsigned char png[] = {
        0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00,
        0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x02, 0x00, 0x00, 0x00, 0x90, 0x77, 0x53, 0xde, 0x00,
        0x00, 0x00, 0x0c, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xf8, 0xcf, 0xc0, 0x00, 0x00, 0x03, 0x01,
        0x01, 0x00, 0xc9, 0xfe, 0x92, 0xef, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60,
        0x82};
    static const char *const images[] = {"base.png", "mr.png", "n.png", "ao.png", "e.png"};
    for (size_t i = 0; i < sizeof images / sizeof images[0]; i++) {
        FILE *f = fopen(tmp_path(images[i]), "wb");
        if (!f || fwrite(png, 1, sizeof png, f) != sizeof png || fclose(f) != 0)
            return -1;
    }
    FILE *f = fopen(tmp_path("not_image.png"), "wb");
    if (!f || fputs("this is text", f) < 0 || fclose(f) != 0)
        return -1;
    return 0;
}

/* The parser's one message goes to stderr: send it to a file and read it back. */
static bool parse(const char *text, scene *out, char *err, size_t size)
{
    stderr_capture c;
    stderr_capture_begin(&c);
    assert_non_null(c.file);
    bool ok = scene_parse_string(text, "t.scene", tmp_dir, out);
    stderr_capture_end(&c, err, size);
    return ok;
}

static void test_fields(void **state)
{
    (void)state;
    scene s;
    char err[1024];
    bool ok = parse("material gold pbr base 1 0.78 0.34 metallic 1 roughness 0.25\n"
                    "material lamp pbr roughness 1 metallic 0 base 0.5 0.5 0.5 emissive 2 1 0.5 opacity 0.5\n"
                    "material plain albedo 0.5 0.5 0.5\n",
                    &s, err, sizeof err);
    if (!ok)
        print_error("%s", err);
    assert_true(ok);
    assert_int_equal(s.material_count, 3);
    const scene_material *gold = &s.materials[0];
    assert_true(gold->pbr);
    assert_float_equal(gold->albedo[1], 0.78f, EPS);
    assert_float_equal(gold->metallic, 1.0f, 0.0f);
    assert_float_equal(gold->roughness, 0.25f, 0.0f);
    assert_float_equal(gold->opacity, 1.0f, 0.0f);
    assert_float_equal(gold->emissive[0], 0.0f, 0.0f);
    for (int k = 0; k < SCENE_MAP_COUNT; k++)
        assert_int_equal(gold->maps[k], -1);
    const scene_material *lamp = &s.materials[1];
    assert_float_equal(lamp->emissive[0], 2.0f, 0.0f);
    assert_float_equal(lamp->emissive[2], 0.5f, 0.0f);
    assert_float_equal(lamp->opacity, 0.5f, 0.0f);
    assert_false(s.materials[2].pbr);
    assert_int_equal(s.materials[2].maps[SCENE_MAP_BASE], -1);
    assert_int_equal(s.texture_count, 0);
    scene_destroy(&s);
}

/* Maps: resolved against the scene's folder; one texture per (file, colour space). */
static void test_maps(void **state)
{
    (void)state;
    scene s;
    char err[1024];
    bool ok = parse("material a pbr base 1 1 1 metallic 0 roughness 1 base_map base.png metal_rough_map mr.png "
                    "normal_map n.png occlusion_map ao.png emissive_map e.png\n"
                    "material b pbr base 1 1 1 metallic 0 roughness 1 base_map base.png normal_map n.png\n"
                    "material c pbr base 1 1 1 metallic 0 roughness 1 occlusion_map base.png\n",
                    &s, err, sizeof err);
    if (!ok)
        print_error("%s", err);
    assert_true(ok);
    assert_int_equal(s.texture_count, 6); /* five files, base.png twice: as colour and as data */
    const scene_material *a = &s.materials[0], *b = &s.materials[1], *c = &s.materials[2];
    for (int k = 0; k < SCENE_MAP_COUNT; k++)
        assert_int_equal(a->maps[k], k);
    assert_string_equal(s.textures[0].path, tmp_path("base.png"));
    assert_true(s.textures[SCENE_MAP_BASE].srgb);
    assert_true(s.textures[SCENE_MAP_EMISSIVE].srgb);
    assert_false(s.textures[SCENE_MAP_METAL_ROUGH].srgb);
    assert_false(s.textures[SCENE_MAP_NORMAL].srgb);
    assert_false(s.textures[SCENE_MAP_OCCLUSION].srgb);
    assert_int_equal(b->maps[SCENE_MAP_BASE], a->maps[SCENE_MAP_BASE]);
    assert_int_equal(b->maps[SCENE_MAP_NORMAL], a->maps[SCENE_MAP_NORMAL]);
    assert_int_equal(b->maps[SCENE_MAP_OCCLUSION], -1);
    assert_int_equal(c->maps[SCENE_MAP_OCCLUSION], 5);
    assert_false(s.textures[5].srgb);
    assert_null(s.textures[0].data);
    scene_destroy(&s);
}

static void test_errors(void **state)
{
    (void)state;
    static const struct {
        const char *text, *want;
    } cases[] = {
        {"material m pbr\n", "t.scene:1: material 'm': missing 'base R G B'"},
        {"material m pbr base 1 1 1 roughness 1\n", "t.scene:1: material 'm': missing 'metallic M'"},
        {"material m pbr base 1 1 1 metallic 1\n", "t.scene:1: material 'm': missing 'roughness R'"},
        {"material m pbr base 1 1.5 1 metallic 0 roughness 1\n",
         "t.scene:1: material base: must be between 0 and 1, got '1.5'"},
        {"material m pbr base 1 1 1 metallic -0.5 roughness 1\n",
         "t.scene:1: material metallic: must be >= 0, got '-0.5'"},
        {"material m pbr base 1 1 1 metallic 0 roughness 2\n",
         "t.scene:1: material roughness: must be between 0 and 1, got '2'"},
        {"material m pbr base 1 1 1 metallic 0 roughness nan\n",
         "t.scene:1: material roughness: not a finite number, got 'nan'"},
        {"material m pbr base 1 1 1 metallic 0 roughness 1 emissive 1 -1 1\n",
         "t.scene:1: material emissive: must be >= 0, got '-1'"},
        {"material m pbr base 1 1 1 metallic 0 roughness 1 opacity 0\n",
         "t.scene:1: material opacity: must be > 0, got '0'"},
        {"material m pbr base 1 1 1 metallic 0 roughness 1 specular 1\n",
         "t.scene:1: material: unknown attribute 'specular' (expected base, metallic"},
        {"material m pbr base 1 1 1 metallic 0 roughness 1 metallic 1\n",
         "t.scene:1: material: 'metallic' given twice"},
        {"material m pbr base 1 1 1 metallic 0 roughness 1 base_map\n",
         "t.scene:1: material 'm' base_map: missing image path"},
        {"\nmaterial m pbr base 1 1 1 metallic 0 roughness 1 normal_map nothere.png\n",
         "t.scene:2: material 'm' normal_map '"},
        {"material m pbr base 1 1 1 metallic 0 roughness 1 normal_map .\n", "not a regular file"},
        {"\n\nmaterial m pbr base 1 1 1 metallic 0 roughness 1 base_map not_image.png\n",
         "t.scene:3: material 'm' base_map '"},
        {"material m pbr base 1 1 1 metallic 0 roughness 1 0.5\n",
         "t.scene:1: material: unexpected extra token '0.5'"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        scene s;
        char err[1024];
        bool ok = parse(cases[i].text, &s, err, sizeof err);
        if (ok || !strstr(err, cases[i].want))
            print_error("input: %swanted '%s', got '%s'\n", cases[i].text, cases[i].want, err);
        assert_false(ok);
        assert_non_null(strstr(err, cases[i].want));
        assert_int_equal(s.texture_count, 0); /* a failed parse leaves nothing allocated */
    }
}

UNIT_TEST_MAIN(setup_dir, tmp_dir_remove, cmocka_unit_test(test_fields), cmocka_unit_test(test_maps),
               cmocka_unit_test(test_errors))
