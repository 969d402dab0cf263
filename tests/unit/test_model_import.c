/* test_model_import.c - glTF 2.0 through the `model` directive (common/scene/model_import.c,
 * scene_model.c): the course's own tests/models/lights.gltf read into exact meshes, materials, objects
 * (node matrices), lights and its embedded texture; the placement of the line applied to objects and
 * lights; one mesh of the file built alone; the kept import; and assimp-testmodels' samples (skipped
 * when that package is not installed), good ones with their counts and textures, refused ones with
 * their reason. The whole corpus, through scene_check, is tests/bad/gltf.expect. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "light.h"
#include "mesh_data.h"
#include "model_import.h"
#include "scene.h"
#include "test_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define SAMPLES "/usr/share/assimp/models/glTF2/"
#define EPS 1e-5f

static char source[1024];

/* "model PATH ARGS" parsed with base_dir = tests/models. */
static bool parse_model(const char *path, const char *args, scene *s)
{
    char text[2048], base[1100];
    snprintf(text, sizeof text, "model %s %s\n", path, args);
    snprintf(base, sizeof base, "%s/tests/models", source);
    return scene_parse_string(text, "test.scene", base, s);
}

static void assert_vec3(const float *v, float x, float y, float z)
{
    if (fabsf(v[0] - x) > EPS || fabsf(v[1] - y) > EPS || fabsf(v[2] - z) > EPS)
        fail_msg("(%g, %g, %g), expected (%g, %g, %g)", v[0], v[1], v[2], x, y, z);
}

static void test_lights_gltf_contents(void **state)
{
    (void)state;
    scene s;
    assert_true(parse_model("lights.gltf", "position 1 0 0", &s));
    assert_int_equal(s.mesh_count, 2);
    assert_int_equal(s.material_count, 3); /* Painted, Glass, and the default Assimp adds */
    assert_int_equal(s.object_count, 2);
    assert_int_equal(s.light_count, 2); /* the directional light is left out */
    assert_int_equal(s.texture_count, 1);
    for (int i = 0; i < 2; i++) {
        assert_int_equal(s.meshes[i].kind, SCENE_MESH_FILE);
        assert_int_equal(s.meshes[i].part, i);
        assert_int_equal(s.meshes[i].line, 1);
        assert_non_null(strstr(s.meshes[i].path, "tests/models/lights.gltf"));
    }
    /* Painted: textured, metallic-roughness factors, emissive. */
    const scene_material *painted = &s.materials[0], *glass = &s.materials[1];
    assert_true(painted->pbr);
    assert_vec3(painted->albedo, 0.8f, 0.2f, 0.1f);
    assert_float_equal(painted->metallic, 0.25f, EPS);
    assert_float_equal(painted->roughness, 0.6f, EPS);
    assert_vec3(painted->emissive, 0.1f, 0.0f, 0.0f);
    assert_float_equal(painted->opacity, 1.0f, EPS);
    assert_int_equal(painted->maps[SCENE_MAP_BASE], 0);
    for (int k = SCENE_MAP_METAL_ROUGH; k < SCENE_MAP_COUNT; k++)
        assert_int_equal(painted->maps[k], -1);
    /* Glass: alpha mode BLEND is the course's glass. */
    assert_float_equal(glass->opacity, 0.5f, EPS);
    assert_float_equal(glass->roughness, 0.1f, EPS);
    assert_int_equal(glass->maps[SCENE_MAP_BASE], -1);
    /* The embedded PNG, copied. */
    const scene_texture *t = &s.textures[0];
    assert_true(t->srgb);
    assert_non_null(t->data);
    assert_true(t->size > 8 && memcmp(t->data, "\x89PNG", 4) == 0);
    assert_non_null(strstr(t->path, "lights.gltf#0"));
    /* Floor: Root (translate 0 1 0) * Floor (a quarter turn about X, scale 4), then the line's
     * position 1 0 0: the quad's corner (0.5, 0.5, 0) lands at (1 + 2, 1, -2). */
    assert_true(s.objects[0].has_base);
    mat4 world;
    scene_object_world_at(&s, 0, 0.0f, world);
    vec4 corner = {0.5f, 0.5f, 0.0f, 1.0f}, out;
    glm_mat4_mulv(world, corner, out);
    assert_vec3(out, 3.0f, 1.0f, -2.0f);
    assert_int_equal(s.objects[0].material, 0);
    assert_int_equal(s.objects[1].material, 1);
    /* Bulb: colour 1 0.9 0.8, intensity 5 (candela), at Root + (1, 2, 0) + the line's (1, 0, 0). */
    const scene_light *bulb = &s.lights[0], *spot = &s.lights[1];
    assert_false(bulb->spot);
    assert_vec3(bulb->position, 2.0f, 3.0f, 0.0f);
    assert_vec3(bulb->color, 1.0f, 0.9f, 0.8f);
    assert_float_equal(bulb->intensity, 5.0f, EPS);
    assert_float_equal(bulb->kc, MODEL_LIGHT_KC, EPS);
    assert_float_equal(bulb->kl, 0.0f, EPS);
    assert_float_equal(bulb->kq, 1.0f, EPS);
    /* Spot: turned to point down, cone half-angles 0.3 and 0.6 radians. */
    assert_true(spot->spot);
    assert_vec3(spot->position, 1.0f, 4.0f, 0.0f);
    assert_vec3(spot->direction, 0.0f, -1.0f, 0.0f);
    assert_float_equal(spot->inner_deg, 0.3f * 180.0f / GLM_PIf, 1e-3f);
    assert_float_equal(spot->outer_deg, 0.6f * 180.0f / GLM_PIf, 1e-3f);
    scene_destroy(&s);
}

/* rotate_y and scale place the lights as they place the objects. */
static void test_placement_moves_lights(void **state)
{
    (void)state;
    scene s;
    assert_true(parse_model("lights.gltf", "rotate_y 90 scale 2", &s));
    /* Bulb at (1, 3, 0) in the file's space: scaled (2, 6, 0), a quarter turn about +Y (0, 6, -2). */
    assert_vec3(s.lights[0].position, 0.0f, 6.0f, -2.0f);
    scene_destroy(&s);
}

/* --lights N places its lights around where the parts are, node matrices included: the floor
 * (4 x 4 after its node's scale) placed at x = 10 spans x 8..12 at least. */
static void test_generated_lights_cover_parts(void **state)
{
    (void)state;
    scene s;
    assert_true(parse_model("lights.gltf", "position 10 0 0", &s));
    float lo[3], hi[3];
    light_generate_bounds(&s, lo, hi);
    assert_true(lo[0] <= 8.0f && hi[0] >= 12.0f);
    assert_true(lo[2] <= -2.0f && hi[2] >= 2.0f);
    scene_destroy(&s);
}

/* A part is its mesh alone, in the file's space, with the normals the file gives. */
static void test_part_mesh(void **state)
{
    (void)state;
    scene s;
    assert_true(parse_model("lights.gltf", "", &s));
    for (int i = 0; i < s.mesh_count; i++) {
        mesh_data m;
        assert_true(mesh_data_from_scene(&m, &s, &s.meshes[i]));
        assert_int_equal(m.vertex_count, 4);
        assert_int_equal(m.index_count, 6);
        assert_vec3(m.bounds_min, -0.5f, -0.5f, 0.0f);
        assert_vec3(m.bounds_max, 0.5f, 0.5f, 0.0f);
        assert_vec3(m.vertices + 3, 0.0f, 0.0f, 1.0f);
        mesh_data_destroy(&m);
    }
    scene_destroy(&s);
}

/* The meshes of one file come from one import; another file, or a release, ends it. */
static void test_kept_import(void **state)
{
    (void)state;
    char path[1100], why[512];
    snprintf(path, sizeof path, "%s/tests/models/lights.gltf", source);
    const struct aiScene *a = model_import_cached(path, why, sizeof why);
    assert_non_null(a);
    assert_ptr_equal(model_import_cached(path, why, sizeof why), a);
    model_import_release();
    assert_non_null(model_import_cached(path, why, sizeof why));
    model_import_release();
}

/* The line's own errors, and a format the directive does not read. */
static void test_directive_errors(void **state)
{
    (void)state;
    scene s;
    assert_false(parse_model("lights.gltf", "scale 0", &s));
    assert_false(parse_model("lights.gltf", "colour 1", &s));
    assert_false(parse_model("missing.gltf", "", &s));
    assert_false(scene_parse_string("model\n", "test.scene", source, &s));
    char why[512];
    char path[1100];
    snprintf(path, sizeof path, "%s/assets/models/teapot.obj", source);
    assert_false(model_import_scene(path, "test", &s, why, sizeof why));
    assert_non_null(strstr(why, "reads glTF 2.0 files"));
    /* A key line cannot animate a model. */
    snprintf(path, sizeof path, "model lights.gltf\nkey 1 position 0 0 0\n");
    char base[1100];
    snprintf(base, sizeof base, "%s/tests/models", source);
    assert_false(scene_parse_string(path, "test.scene", base, &s));
}

static bool have_samples(void)
{
    struct stat st;
    return stat(SAMPLES, &st) == 0 && S_ISDIR(st.st_mode);
}

static void test_good_samples(void **state)
{
    (void)state;
    if (!have_samples())
        skip();
    static const struct {
        const char *path;
        int objects, meshes, materials, textures;
        bool embedded;
    } cases[] = {
        {"BoxTextured-glTF/BoxTextured.gltf", 1, 1, 2, 1, false},
        {"BoxTextured-glTF-Binary/BoxTextured.glb", 1, 1, 2, 1, true},
        {"BoxTextured-glTF-Embedded/BoxTextured.gltf", 1, 1, 2, 1, true},
        {"ClearCoat-glTF/ClearCoatTest.gltf", 27, 27, 20, 5, false},
        {"2CylinderEngine-glTF-Binary/2CylinderEngine.glb", 115, 34, 35, 0, false},
    };
    scene s;
    assert_false(parse_model(SAMPLES, "", &s)); /* a folder is no model */
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char path[512];
        snprintf(path, sizeof path, SAMPLES "%s", cases[i].path);
        assert_true(parse_model(path, "", &s));
        assert_int_equal(s.object_count, cases[i].objects);
        assert_int_equal(s.mesh_count, cases[i].meshes);
        assert_int_equal(s.material_count, cases[i].materials);
        assert_int_equal(s.texture_count, cases[i].textures);
        assert_int_equal(s.light_count, 0);
        for (int k = 0; k < s.texture_count; k++) {
            assert_true((s.textures[k].data != NULL) == cases[i].embedded);
            if (!cases[i].embedded) {
                struct stat st;
                assert_int_equal(stat(s.textures[k].path, &st), 0);
            }
        }
        /* Every mesh builds, with triangles. */
        for (int k = 0; k < s.mesh_count; k++) {
            mesh_data m;
            assert_true(mesh_data_from_scene(&m, &s, &s.meshes[k]));
            assert_true(m.index_count >= 3);
            mesh_data_destroy(&m);
        }
        scene_destroy(&s);
    }
}

static void test_refused_samples(void **state)
{
    (void)state;
    if (!have_samples())
        skip();
    static const struct {
        const char *path, *why;
    } cases[] = {
        {"simple_skin/simple_skin.gltf", "skins are not supported"},
        {"glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf", "morph targets"},
        {"BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf", "specular-glossiness"},
        {"textureTransform/TextureTransformTest.gltf", "KHR_texture_transform is not supported"},
        {"BoxTexcoords-glTF/boxTexcoords.gltf", "UV set 1"},
        {"RecursiveNodes/RecursiveNodes.gltf", "its nodes form a cycle"},
        {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_00.gltf", "no mesh of triangles"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char path[512], why[512];
        snprintf(path, sizeof path, SAMPLES "%s", cases[i].path);
        scene s;
        assert_false(model_import_scene(path, "test", &s, why, sizeof why));
        if (!strstr(why, cases[i].why))
            fail_msg("%s: '%s' lacks '%s'", cases[i].path, why, cases[i].why);
        assert_null(strchr(why, '\n'));
    }
    model_import_release();
}

static int group_setup(void **state)
{
    (void)state;
    const char *dir = getenv("COURSE_SOURCE_DIR");
    snprintf(source, sizeof source, "%s", dir ? dir : ".");
    return 0;
}

UNIT_TEST_MAIN(group_setup, NULL, cmocka_unit_test(test_lights_gltf_contents),
               cmocka_unit_test(test_placement_moves_lights),
               cmocka_unit_test(test_generated_lights_cover_parts), cmocka_unit_test(test_part_mesh),
               cmocka_unit_test(test_kept_import), cmocka_unit_test(test_directive_errors),
               cmocka_unit_test(test_good_samples), cmocka_unit_test(test_refused_samples))
