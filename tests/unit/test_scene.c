/* test_scene.c - the scene parser: defaults, every directive, keys, the world matrix, errors and their
 * messages, model paths relative to the scene's folder, and a 100k-line scene. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "scene.h"
#include "test_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

/* Parsed floats are the nearest float to the decimal text; interpolation adds a few ulps. */
#define EPS 1e-5f

/* Every realloc of this program, the scene module's included, passes here: tests/CMakeLists.txt links
 * it with -Wl,--wrap=realloc, so that a test can count how often an array was grown. */
void *__real_realloc(void *p, size_t n);
void *__wrap_realloc(void *p, size_t n);
static long realloc_calls;
void *__wrap_realloc(void *p, size_t n)
{
    realloc_calls++;
    return __real_realloc(p, n);
}

static int setup_dir(void **state)
{
    (void)state;
    return tmp_dir_create("/tmp/test_scene_XXXXXX");
}

static void write_file(const char *path, const char *bytes, size_t size)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(bytes, 1, size, f), size);
    assert_int_equal(fclose(f), 0);
}

/* ---- stderr capture: the parser reports through log_error, which writes to fd 2 ---------------- */

static struct {
    int saved_fd;
    FILE *file;
    char text[8192];
} capture;

static void capture_begin(void)
{
    fflush(stderr);
    capture.file = tmpfile();
    assert_non_null(capture.file);
    capture.saved_fd = dup(2);
    assert_true(capture.saved_fd >= 0);
    assert_true(dup2(fileno(capture.file), 2) >= 0);
}

/* Returns what was written to stderr since capture_begin. */
static const char *capture_end(void)
{
    fflush(stderr);
    assert_true(dup2(capture.saved_fd, 2) >= 0);
    close(capture.saved_fd);
    rewind(capture.file);
    size_t n = fread(capture.text, 1, sizeof capture.text - 1, capture.file);
    capture.text[n] = '\0';
    fclose(capture.file);
    return capture.text;
}

static int count_lines(const char *text)
{
    int n = 0;
    for (; *text; text++)
        n += *text == '\n';
    return n;
}

static bool scene_is_zero(const scene *s)
{
    static const scene zero;
    return memcmp(s, &zero, sizeof zero) == 0;
}

static void parse_ok(const char *text, scene *out)
{
    capture_begin();
    bool ok = scene_parse_string(text, "t.scene", tmp_dir, out);
    const char *err = capture_end();
    if (!ok || err[0])
        print_error("unexpected failure: %s\n", err);
    assert_true(ok);
    assert_string_equal(err, "");
}

/* Parsing must fail with exactly one line on stderr that contains `want`, and leave *out zeroed. */
static void check_error_text(const char *text, size_t size, const char *want, bool from_file)
{
    scene s;
    memset(&s, 0xAB, sizeof s); /* garbage, so "left zeroed" is really checked */
    char path[128];
    snprintf(path, sizeof path, "%s/t.scene", tmp_dir);
    if (from_file)
        write_file(path, text, size);
    capture_begin();
    bool ok = from_file ? scene_load(path, &s) : scene_parse_string(text, "t.scene", tmp_dir, &s);
    const char *err = capture_end();
    if (ok || !strstr(err, want) || count_lines(err) != 1)
        print_error("input:\n%s\nwanted '%s', got '%s'\n", text, want, err);
    assert_false(ok);
    assert_true(scene_is_zero(&s));
    assert_int_equal(count_lines(err), 1);
    assert_non_null(strstr(err, want));
}

static void check_error(const char *text, const char *want)
{
    check_error_text(text, strlen(text), want, false);
}

/* ---- defaults and directives ------------------------------------------------------------------ */

/* Every field of a parsed material. */
static void assert_material(const scene_material *m, const char *name, const float albedo[3], float specular,
                            float shininess)
{
    assert_string_equal(m->name, name);
    for (int i = 0; i < 3; i++)
        assert_float_equal(m->albedo[i], albedo[i], EPS);
    assert_float_equal(m->specular, specular, EPS);
    assert_float_equal(m->shininess, shininess, EPS);
}

static void test_defaults(void **state)
{
    (void)state;
    scene s;
    parse_ok("mesh ball sphere\nmaterial m albedo 0.5 0.25 1\nobject ball m\nlight\n", &s);
    assert_string_equal(s.path, "t.scene");
    /* No camera line: the documented default camera. */
    assert_float_equal(s.camera.eye[0], 0.0f, EPS);
    assert_float_equal(s.camera.eye[1], 2.0f, EPS);
    assert_float_equal(s.camera.eye[2], 6.0f, EPS);
    assert_float_equal(s.camera.target[1], 0.0f, EPS);
    assert_float_equal(s.camera.up[1], 1.0f, EPS);
    assert_float_equal(s.camera.fovy_deg, 60.0f, EPS);
    assert_float_equal(s.camera.near_plane, 0.1f, EPS);
    assert_float_equal(s.camera.far_plane, 100.0f, EPS);
    for (int i = 0; i < 3; i++)
        assert_float_equal(s.ambient[i], 0.0f, 0.0f);

    assert_int_equal(s.mesh_count, 1);
    assert_int_equal(s.meshes[0].kind, SCENE_MESH_SPHERE);
    assert_int_equal(s.meshes[0].slices, 32);
    assert_int_equal(s.meshes[0].stacks, 16);
    assert_int_equal(s.meshes[0].line, 1);

    assert_int_equal(s.material_count, 1);
    assert_material(&s.materials[0], "m", (const float[3]){0.5f, 0.25f, 1.0f}, 0.0f, 32.0f);

    assert_int_equal(s.object_count, 1);
    const scene_object *o = &s.objects[0];
    assert_int_equal(o->mesh, 0);
    assert_int_equal(o->material, 0);
    assert_float_equal(o->rotate_y_deg, 0.0f, 0.0f);
    for (int i = 0; i < 3; i++) {
        assert_float_equal(o->position[i], 0.0f, 0.0f);
        assert_float_equal(o->scale[i], 1.0f, 0.0f);
    }
    assert_null(o->keys);
    assert_int_equal(o->key_count, 0);

    assert_int_equal(s.light_count, 1);
    const scene_light *l = &s.lights[0];
    for (int i = 0; i < 3; i++) {
        assert_float_equal(l->position[i], 0.0f, 0.0f);
        assert_float_equal(l->color[i], 1.0f, 0.0f);
    }
    assert_float_equal(l->intensity, 1.0f, EPS);
    assert_float_equal(l->kc, 1.0f, EPS);
    assert_float_equal(l->kl, 0.14f, EPS);
    assert_float_equal(l->kq, 0.07f, EPS);
    scene_destroy(&s);
    assert_true(scene_is_zero(&s));
    scene_destroy(&s); /* twice is harmless */
}

static void test_every_attribute(void **state)
{
    (void)state;
    char model[128];
    snprintf(model, sizeof model, "%s/box.obj", tmp_dir);
    write_file(model, "v 0 0 0\n", 8);
    const char *text = "camera eye 1 2 3 target 4 5 7 up 0 0 1 fovy 45 near 0.5 far 250\n"
                       "ambient 0.1 0.2 0.3\n"
                       "material red albedo 0.9 0.1 0.05 specular 0.5 shininess 64\n"
                       "material blue albedo 0 0 1 shininess 8 specular 0.25\n"
                       "mesh floor plane\n"
                       "mesh box cube\n"
                       "mesh ball sphere 12 6\n"
                       "mesh model file box.obj\n"
                       "object ball blue scale 2 rotate_y -45 position -1 0.5 2\n"
                       "object model red position 1 2 3 rotate_y 90 scale 1 2 3\n"
                       "object floor red\n"
                       "light position 1 2 3 color 0.5 0.6 0.7 intensity 4 attenuation 1 0.35 0.44\n"
                       "light attenuation 2 0 0\n";
    scene s;
    parse_ok(text, &s);
    const float want_eye[3] = {1, 2, 3}, want_target[3] = {4, 5, 7}, want_up[3] = {0, 0, 1};
    for (int i = 0; i < 3; i++) {
        assert_float_equal(s.camera.eye[i], want_eye[i], EPS);
        assert_float_equal(s.camera.target[i], want_target[i], EPS);
        assert_float_equal(s.camera.up[i], want_up[i], EPS);
    }
    assert_float_equal(s.camera.fovy_deg, 45.0f, EPS);
    assert_float_equal(s.camera.near_plane, 0.5f, EPS);
    assert_float_equal(s.camera.far_plane, 250.0f, EPS);
    assert_float_equal(s.ambient[0], 0.1f, EPS);
    assert_float_equal(s.ambient[2], 0.3f, EPS);

    assert_int_equal(s.material_count, 2);
    assert_material(&s.materials[0], "red", (const float[3]){0.9f, 0.1f, 0.05f}, 0.5f, 64.0f);
    assert_material(&s.materials[1], "blue", (const float[3]){0.0f, 0.0f, 1.0f}, 0.25f, 8.0f);

    assert_int_equal(s.mesh_count, 4);
    assert_int_equal(s.meshes[0].kind, SCENE_MESH_PLANE);
    assert_int_equal(s.meshes[1].kind, SCENE_MESH_CUBE);
    assert_int_equal(s.meshes[2].kind, SCENE_MESH_SPHERE);
    assert_int_equal(s.meshes[2].slices, 12);
    assert_int_equal(s.meshes[2].stacks, 6);
    assert_int_equal(s.meshes[3].kind, SCENE_MESH_FILE);
    assert_string_equal(s.meshes[3].path, model);
    assert_int_equal(s.meshes[3].line, 8);

    assert_int_equal(s.object_count, 3);
    assert_int_equal(s.objects[0].mesh, 2);
    assert_int_equal(s.objects[0].material, 1);
    assert_float_equal(s.objects[0].rotate_y_deg, -45.0f, EPS);
    assert_float_equal(s.objects[0].position[1], 0.5f, EPS);
    for (int i = 0; i < 3; i++)
        assert_float_equal(s.objects[0].scale[i], 2.0f, EPS); /* "scale S" is uniform */
    assert_int_equal(s.objects[1].mesh, 3);
    assert_int_equal(s.objects[1].material, 0);
    assert_float_equal(s.objects[1].scale[0], 1.0f, EPS);
    assert_float_equal(s.objects[1].scale[1], 2.0f, EPS);
    assert_float_equal(s.objects[1].scale[2], 3.0f, EPS);
    assert_int_equal(s.objects[2].mesh, 0);

    assert_int_equal(s.light_count, 2);
    assert_float_equal(s.lights[0].position[2], 3.0f, EPS);
    assert_float_equal(s.lights[0].color[1], 0.6f, EPS);
    assert_float_equal(s.lights[0].intensity, 4.0f, EPS);
    assert_float_equal(s.lights[0].kl, 0.35f, EPS);
    assert_float_equal(s.lights[0].kq, 0.44f, EPS);
    assert_float_equal(s.lights[1].kc, 2.0f, EPS);
    assert_float_equal(s.lights[1].kl, 0.0f, 0.0f);
    scene_destroy(&s);
}

static void test_comments_and_layout(void **state)
{
    (void)state;
    /* A byte order mark, comments (whole-line, trailing, glued to a token), tabs, CRLF, and no final
     * line break. */
    const char *text = "\xEF\xBB\xBF# a scene\n"
                       "\n"
                       "   \t  \n"
                       "ambient\t0.5 0.5 0.5   # grey\r\n"
                       "mesh box cube# no space before the comment\n"
                       "# material ignored albedo 1 1 1\n"
                       "material m albedo 1 1 1\n"
                       "object box m position 1e0 +2 -3.5e-0";
    scene s;
    parse_ok(text, &s);
    assert_float_equal(s.ambient[1], 0.5f, EPS);
    assert_int_equal(s.mesh_count, 1);
    assert_int_equal(s.meshes[0].line, 5);
    assert_int_equal(s.material_count, 1);
    assert_int_equal(s.object_count, 1);
    assert_float_equal(s.objects[0].position[0], 1.0f, EPS);
    assert_float_equal(s.objects[0].position[1], 2.0f, EPS);
    assert_float_equal(s.objects[0].position[2], -3.5f, EPS);
    scene_destroy(&s);

    /* An empty file is a valid scene: default camera, nothing else. */
    parse_ok("", &s);
    assert_int_equal(s.object_count, 0);
    assert_float_equal(s.camera.eye[2], 6.0f, EPS);
    scene_destroy(&s);
}

/* ---- keys and matrices --------------------------------------------------------------------------- */

static void assert_vec3_near(const float *got, float x, float y, float z)
{
    assert_float_equal(got[0], x, EPS);
    assert_float_equal(got[1], y, EPS);
    assert_float_equal(got[2], z, EPS);
}

static void test_keys(void **state)
{
    (void)state;
    const char *text = "mesh box cube\n"
                       "material m albedo 1 1 1\n"
                       "object box m position 9 9 9\n" /* ignored: the object has keys */
                       "key 1 position 0 0 0\n"
                       "key 3 position 2 4 -6\n"
                       "key 4 position 2 4 0\n"
                       "object box m position 5 6 7\n"
                       "light position 1 1 1\n"
                       "key -2 position 0 10 0\n"
                       "material after_light albedo 1 1 1\n" /* keys still go to the light */
                       "key 2 position 4 10 0\n";
    scene s;
    parse_ok(text, &s);
    assert_int_equal(s.objects[0].key_count, 3);
    assert_int_equal(s.objects[1].key_count, 0);
    assert_int_equal(s.lights[0].key_count, 2);

    mat4 m;
    scene_object_world_at(&s, 0, 0.0f, m); /* before the first key: the first key */
    assert_vec3_near(m[3], 0, 0, 0);
    scene_object_world_at(&s, 0, 1.0f, m);
    assert_vec3_near(m[3], 0, 0, 0);
    scene_object_world_at(&s, 0, 2.0f, m); /* halfway between keys 1 and 2 */
    assert_vec3_near(m[3], 1, 2, -3);
    scene_object_world_at(&s, 0, 3.5f, m); /* halfway between keys 2 and 3 */
    assert_vec3_near(m[3], 2, 4, -3);
    scene_object_world_at(&s, 0, 100.0f, m); /* after the last key: the last key */
    assert_vec3_near(m[3], 2, 4, 0);
    scene_object_world_at(&s, 0, NAN, m);
    assert_vec3_near(m[3], 0, 0, 0);
    scene_object_world_at(&s, 1, 2.0f, m); /* no keys: the position attribute */
    assert_vec3_near(m[3], 5, 6, 7);

    vec3 p;
    scene_light_position_at(&s, 0, -5.0f, p);
    assert_vec3_near(p, 0, 10, 0);
    scene_light_position_at(&s, 0, 1.0f, p); /* 3/4 of the way from -2 to 2 */
    assert_vec3_near(p, 3, 10, 0);
    scene_light_position_at(&s, 0, 7.0f, p);
    assert_vec3_near(p, 4, 10, 0);
    scene_destroy(&s);
}

static void test_world_matrix(void **state)
{
    (void)state;
    scene s;
    parse_ok("mesh box cube\nmaterial m albedo 1 1 1\n"
             "object box m position 1 2 3 rotate_y 30 scale 2 3 4\n"
             "object box m rotate_y 90\n",
             &s);
    /* T * Ry(30) * S by hand, column-major (m[column][row]); cos 30 = 0.8660254, sin 30 = 0.5.
     * Ry maps x to (c, 0, -s) and z to (s, 0, c); S scales each column first. */
    const float want[4][4] = {
        {2 * 0.8660254f, 0, -2 * 0.5f, 0},
        {0, 3, 0, 0},
        {4 * 0.5f, 0, 4 * 0.8660254f, 0},
        {1, 2, 3, 1},
    };
    mat4 m;
    scene_object_world_at(&s, 0, 0.0f, m);
    for (int c = 0; c < 4; c++)
        for (int r = 0; r < 4; r++)
            assert_float_equal(m[c][r], want[c][r], EPS);

    /* The point (1, 1, 1): scaled to (2, 3, 4), rotated to (2c + 4s, 3, -2s + 4c), moved by (1, 2, 3). */
    vec4 point = {1, 1, 1, 1}, moved;
    glm_mat4_mulv(m, point, moved);
    assert_float_equal(moved[0], 2 * 0.8660254f + 4 * 0.5f + 1, EPS);
    assert_float_equal(moved[1], 5.0f, EPS);
    assert_float_equal(moved[2], -1.0f + 4 * 0.8660254f + 3, EPS);

    /* A quarter turn about +Y, right-handed: +X goes to -Z, +Z goes to +X. */
    scene_object_world_at(&s, 1, 0.0f, m);
    assert_vec3_near(m[0], 0, 0, -1);
    assert_vec3_near(m[2], 1, 0, 0);
    scene_destroy(&s);
}

static void test_add_light(void **state)
{
    (void)state;
    scene s;
    parse_ok("light position 1 0 0\n", &s);
    scene_key keys[2] = {{.time = 0, .position = {0, 0, 0}}, {.time = 2, .position = {2, 0, 0}}};
    scene_light extra = {.color = {1, 0, 0}, .intensity = 3, .kc = 1, .keys = keys, .key_count = 2};
    for (int i = 0; i < 100; i++)
        assert_true(scene_add_light(&s, &extra));
    assert_int_equal(s.light_count, 101);
    keys[1].position[0] = 99; /* the scene holds its own copy of the keys */
    assert_true(s.lights[100].keys != keys);
    assert_float_equal(s.lights[100].intensity, 3.0f, EPS);
    vec3 p;
    scene_light_position_at(&s, 100, 1.0f, p);
    assert_vec3_near(p, 1, 0, 0);
    scene_light_position_at(&s, 0, 1.0f, p);
    assert_vec3_near(p, 1, 0, 0);
    scene_destroy(&s);

    /* A zeroed scene accepts lights too. */
    scene empty = {0};
    extra.keys = NULL;
    extra.key_count = 0;
    assert_true(scene_add_light(&empty, &extra));
    assert_int_equal(empty.light_count, 1);
    assert_null(empty.lights[0].keys);
    scene_destroy(&empty);
}

/* The --lights generator's 65,536 lights through scene_add_light: the array doubles (8, 16, ...,
 * 65,536: 14 reallocations), where growing it one light at a time made 65,536 (seconds under ASan). */
static void test_add_light_grows_by_doubling(void **state)
{
    (void)state;
    scene s = {0};
    const scene_light l = {.color = {1, 1, 1}, .intensity = 1, .kc = 1};
    long before = realloc_calls;
    for (int i = 0; i < 65536; i++)
        assert_true(scene_add_light(&s, &l));
    long grown = realloc_calls - before;
    if (grown > 14)
        print_error("65536 lights took %ld reallocations\n", grown);
    assert_int_equal(s.light_count, 65536);
    assert_true(grown <= 14);
    assert_float_equal(s.lights[65535].kc, 1.0f, EPS);
    scene_destroy(&s);
}

/* ---- errors ------------------------------------------------------------------------------------- */

static void test_errors(void **state)
{
    (void)state;
    static const struct {
        const char *text;
        const char *want;
    } cases[] = {
        {"frobnicate 1 2\n", "t.scene:1: unknown directive 'frobnicate'"},
        {"mesh a cube\nmaterial m albedo 1 1 1\nobject b m\n", "t.scene:3: unknown mesh 'b'"},
        {"mesh a cube\nmaterial m albedo 1 1 1\nobject a n\n", "t.scene:3: unknown material 'n'"},
        {"mesh a cube\n\nmesh a plane\n", "t.scene:3: mesh 'a' is already declared on line 1"},
        {"material m albedo 1 1 1\nmaterial m albedo 0 0 0\n", "t.scene:2: material 'm' is already declared"},
        {"ambient 1 nan 1\n", "t.scene:1: ambient: not a finite number, got 'nan'"},
        {"ambient 1 -inf 1\n", "t.scene:1: ambient: not a finite number, got '-inf'"},
        {"ambient 1 1e999 1\n", "t.scene:1: ambient: number out of range, got '1e999'"},
        {"ambient 1 1e39 1\n", "t.scene:1: ambient: number out of range, got '1e39'"},
        {"ambient 1 -1 1\n", "t.scene:1: ambient: must be >= 0, got '-1'"},
        {"ambient 1 1\n", "t.scene:1: ambient: expected 3 numbers, got 2"},
        {"ambient 1 1 1 1\n", "t.scene:1: ambient: unexpected extra token '1'"},
        {"ambient 1 x 1\n", "t.scene:1: ambient: expected a number, got 'x'"},
        {"ambient 1 1.5.2 1\n", "t.scene:1: ambient: expected a number, got '1.5.2'"},
        {"ambient 1 1 1\nambient 0 0 0\n", "t.scene:2: ambient: given twice (first on line 1)"},
        {"camera eye 1 1 1 target 1 1 1\n", "t.scene:1: camera: eye and target are the same point"},
        {"camera eye 0 0 5 target 0 0 0 near 2 far 1\n",
         "t.scene:1: camera: far (1) must be greater than near (2)"},
        {"camera eye 0 0 5 target 0 0 0 near 0\n", "t.scene:1: camera near: must be > 0, got '0'"},
        {"camera eye 0 5 0 target 0 0 0\n", "t.scene:1: camera: up (0 1 0) is zero or parallel"},
        {"camera eye 0 0 5 target 0 0 0 up 0 0 0\n", "t.scene:1: camera: up (0 0 0) is zero or parallel"},
        {"camera eye 0 0 5 target 0 0 0 fovy 180\n", "t.scene:1: camera fovy: must be between 0 and 180"},
        {"camera eye 0 0 5 target 0 0 0 fovy -10\n", "t.scene:1: camera fovy: must be > 0, got '-10'"},
        {"camera target 0 0 0\n", "t.scene:1: camera: missing 'eye X Y Z'"},
        {"camera eye 0 0 5\n", "t.scene:1: camera: missing 'target X Y Z'"},
        {"camera eye 0 0 5 target 0 0 0 zoom 2\n", "t.scene:1: camera: unknown attribute 'zoom'"},
        {"camera eye 0 0 5 1 target 0 0 0\n", "t.scene:1: camera: unexpected extra token '1'"},
        {"camera eye 0 0 5 target 0 0 0\ncamera eye 0 0 2 target 0 0 0\n", "t.scene:2: camera: given twice"},
        {"light attenuation 0 1 1\n", "t.scene:1: light attenuation: KC must be > 0"},
        {"light attenuation 1 -0.1 1\n", "t.scene:1: light attenuation: must be >= 0, got '-0.1'"},
        {"light attenuation 1 0.1\n", "t.scene:1: light attenuation: missing number"},
        {"light color 1 1 1 intensity inf\n", "t.scene:1: light intensity: not a finite number, got 'inf'"},
        {"light color 1 -1 1\n", "t.scene:1: light color: must be >= 0, got '-1'"},
        {"light colour 1 1 1\n", "t.scene:1: light: unknown attribute 'colour'"},
        {"light intensity 1 intensity 2\n", "t.scene:1: light: 'intensity' given twice"},
        {"key 0 position 1 1 1\n", "t.scene:1: key: no object or light before it"},
        {"light\nkey 1 position 0 0 0\nkey 1 position 1 1 1\n", "t.scene:3: key time '1' must be greater"},
        {"light\nkey 1 position 0 0 0\nkey 0.5 position 1 1 1\n",
         "t.scene:3: key time '0.5' must be greater"},
        {"light\nkey 1 place 0 0 0\n", "t.scene:2: key: expected 'position', got 'place'"},
        {"light\nkey 1\n", "t.scene:2: key: missing 'position X Y Z'"},
        {"light\nkey 1 position 0 0 0 0\n", "t.scene:2: key: unexpected extra token '0'"},
        {"mesh s sphere 2 2\n", "t.scene:1: mesh sphere slices: must be between 3 and 4096, got '2'"},
        {"mesh s sphere 8 1\n", "t.scene:1: mesh sphere stacks: must be between 2 and 4096, got '1'"},
        {"mesh s sphere 8 99999999999999999999\n",
         "t.scene:1: mesh sphere stacks: must be between 2 and 4096"},
        {"mesh s sphere 8\n", "t.scene:1: mesh sphere stacks: missing integer"},
        {"mesh s sphere 8.5 4\n", "t.scene:1: mesh sphere slices: expected an integer, got '8.5'"},
        {"mesh s sphere 8 4 2\n", "t.scene:1: mesh: unexpected extra token '2'"},
        {"mesh s\n", "t.scene:1: mesh 's': missing kind"},
        {"mesh\n", "t.scene:1: mesh: missing name"},
        {"mesh s cone\n", "t.scene:1: mesh 's': unknown kind 'cone'"},
        {"mesh s file\n", "t.scene:1: mesh 's': missing model path"},
        {"mesh s file nothere.obj\n", "/nothere.obj': No such file or directory"},
        {"\n\n   # comment\nmesh bad/name cube\n", "t.scene:4: mesh: invalid name 'bad/name'"},
        {"mesh a234567890123456789012345678901234567890123456789012345678901234 cube\n",
         "t.scene:1: mesh: name 'a23456789012345678901234567890123456789012345678...' is longer than 63"},
        {"material m\n", "t.scene:1: material 'm': missing 'albedo R G B'"},
        {"material m color 1 1 1\n", "t.scene:1: material 'm': expected 'albedo' or 'pbr', got 'color'"},
        {"material m albedo 1 1 1 shininess 0\n", "t.scene:1: material shininess: must be > 0, got '0'"},
        {"material m albedo 1 1 1 specular -1\n", "t.scene:1: material specular: must be >= 0, got '-1'"},
        {"material m albedo 1 1 1 shininess\n", "t.scene:1: material shininess: missing number"},
        {"mesh a cube\nmaterial m albedo 1 1 1\nobject a m scale 0\n",
         "t.scene:3: object scale: must be > 0"},
        {"mesh a cube\nmaterial m albedo 1 1 1\nobject a m scale 1 2\n",
         "t.scene:3: object scale: missing number"},
        {"mesh a cube\nmaterial m albedo 1 1 1\nobject a m position 1 2 3 position 1 2 3\n",
         "t.scene:3: object: 'position' given twice"},
        {"mesh a cube\nmaterial m albedo 1 1 1\nobject a\n", "t.scene:3: object material: missing name"},
        {"mesh a cube\nmaterial m albedo 1 1 1\nobject a m rotate_y\n",
         "t.scene:3: object rotate_y: missing number"},
        {"ambient 1 1 1\xff\n", "t.scene:1: invalid UTF-8 byte 0xFF at column 14"},
        {"ambient 1 1 1 # caf\xc3(\n", "t.scene:1: invalid UTF-8 sequence at column 20"},
        {"ambient 1 1 1 # \xed\xa0\x80\n", "t.scene:1: invalid UTF-8 sequence"}, /* a surrogate */
        {"ambient\x01 1 1 1\n", "t.scene:1: control byte 0x01 at column 8"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        check_error(cases[i].text, cases[i].want);
}

/* ---- spot lights ---------------------------------------------------------------------------- */

/* A spot is a light with a cone: every light attribute, plus direction and cone, in any order; keys
 * animate its position as a light's. A plain light stays a point light (spot false, cone zero). */
static void test_spot(void **state)
{
    (void)state;
    const char *text = "light position 0 1 0\n"
                       "spot direction 0 -2 0 cone 20 35 position 1 4 2 color 1 0.5 0.25 intensity 3 "
                       "attenuation 1 0.09 0.032\n"
                       "spot cone 30 30 direction 1e-30 0 0\n" /* tiny but not zero; inner = outer */
                       "key 0 position 0 3 0\n"
                       "key 2 position 2 3 0\n"
                       "spot position -1 2 0 direction 1 -1 0 cone 0.5 89.9\n";
    scene s;
    parse_ok(text, &s);
    assert_int_equal(s.light_count, 4);
    assert_false(s.lights[0].spot);
    assert_float_equal(s.lights[0].outer_deg, 0.0f, 0.0f);

    const scene_light *a = &s.lights[1];
    assert_true(a->spot);
    assert_vec3_near(a->position, 1, 4, 2);
    assert_vec3_near(a->direction, 0, -2, 0); /* as given: the renderers normalise it */
    assert_float_equal(a->inner_deg, 20.0f, EPS);
    assert_float_equal(a->outer_deg, 35.0f, EPS);
    assert_vec3_near(a->color, 1, 0.5f, 0.25f);
    assert_float_equal(a->intensity, 3.0f, EPS);
    assert_float_equal(a->kl, 0.09f, EPS);
    assert_float_equal(a->kq, 0.032f, EPS);
    assert_int_equal(a->key_count, 0);

    const scene_light *b = &s.lights[2]; /* a light's defaults */
    assert_true(b->spot);
    assert_float_equal(b->direction[0], 1e-30f, 1e-36f);
    assert_float_equal(b->inner_deg, 30.0f, EPS);
    assert_float_equal(b->outer_deg, 30.0f, EPS);
    assert_vec3_near(b->color, 1, 1, 1);
    assert_float_equal(b->kc, 1.0f, EPS);
    assert_float_equal(b->kl, 0.14f, EPS);
    assert_float_equal(b->kq, 0.07f, EPS);
    assert_int_equal(b->key_count, 2);
    vec3 p;
    scene_light_position_at(&s, 2, 1.0f, p);
    assert_vec3_near(p, 1, 3, 0);

    assert_float_equal(s.lights[3].inner_deg, 0.5f, EPS);
    assert_float_equal(s.lights[3].outer_deg, 89.9f, EPS);
    scene_destroy(&s);
}

static void test_spot_errors(void **state)
{
    (void)state;
    static const struct {
        const char *text;
        const char *want;
    } cases[] = {
        {"spot cone 20 30\n", "t.scene:1: spot: missing 'direction X Y Z'"},
        {"spot direction 0 -1 0\n", "t.scene:1: spot: missing 'cone INNER OUTER'"},
        {"\nspot direction 0 0 0 cone 20 30\n", "t.scene:2: spot direction: must not be zero"},
        {"spot direction 0 -1 cone 20 30\n", "t.scene:1: spot direction: expected a number, got 'cone'"},
        {"spot direction 0 -1 nan cone 20 30\n", "t.scene:1: spot direction: not a finite number, got 'nan'"},
        {"spot direction 0 -1 0 cone 0 30\n", "t.scene:1: spot cone: must be > 0, got '0'"},
        {"spot direction 0 -1 0 cone -5 30\n", "t.scene:1: spot cone: must be > 0, got '-5'"},
        {"spot direction 0 -1 0 cone 20\n", "t.scene:1: spot cone: missing number"},
        {"spot direction 0 -1 0 cone 20 90\n",
         "t.scene:1: spot cone: the outer angle must be below 90 degrees, got '90'"},
        {"spot direction 0 -1 0 cone 95 120\n",
         "t.scene:1: spot cone: the outer angle must be below 90 degrees, got '120'"},
        {"spot direction 0 -1 0 cone 40 30\n",
         "t.scene:1: spot cone: the inner angle (40) must not exceed the outer angle (30)"},
        {"spot direction 0 -1 0 cone 20 30 40\n", "t.scene:1: spot: unexpected extra token '40'"},
        {"spot direction 0 -1 0 cone 20 30 cone 10 20\n", "t.scene:1: spot: 'cone' given twice"},
        {"spot direction 0 -1 0 cone 20 30 angle 5\n",
         "t.scene:1: spot: unknown attribute 'angle' (expected position, direction, cone, color, "
         "intensity, attenuation or shadow)"},
        {"spot direction 0 -1 0 cone 20 30 attenuation 0 1 1\n", "t.scene:1: spot attenuation: KC must be > 0"},
        {"spot direction 0 -1 0 cone 20 30 color 1 -1 1\n", "t.scene:1: spot color: must be >= 0, got '-1'"},
        {"spot direction 0 -1 0 cone 20 30 intensity inf\n",
         "t.scene:1: spot intensity: not a finite number, got 'inf'"},
        {"light direction 0 -1 0\n", "t.scene:1: light: unknown attribute 'direction'"},
        {"spot direction 0 -1 0 cone 20 30\nkey 1 position 0 0 0\nkey 1 position 1 1 1\n",
         "t.scene:3: key time '1' must be greater"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        check_error(cases[i].text, cases[i].want);
}

/* ---- opacity ---------------------------------------------------------------------------------- */

/* A material's opacity: 1 when not given, any value in (0, 1] when given, in any attribute order. */
static void test_opacity(void **state)
{
    (void)state;
    const char *text = "material stone albedo 0.5 0.5 0.5\n"
                       "material glass albedo 0.2 0.4 0.9 opacity 0.35 specular 1 shininess 128\n"
                       "material tint albedo 1 0 0 opacity 1e-6\n"
                       "material solid albedo 1 1 1 shininess 8 opacity 1\n";
    scene s;
    parse_ok(text, &s);
    assert_int_equal(s.material_count, 4);
    assert_float_equal(s.materials[0].opacity, 1.0f, 0.0f);
    assert_float_equal(s.materials[1].opacity, 0.35f, EPS);
    assert_material(&s.materials[1], "glass", (const float[3]){0.2f, 0.4f, 0.9f}, 1.0f, 128.0f);
    assert_float_equal(s.materials[2].opacity, 1e-6f, 1e-12f);
    assert_float_equal(s.materials[3].opacity, 1.0f, 0.0f);
    assert_float_equal(s.materials[3].shininess, 8.0f, EPS);
    scene_destroy(&s);
}

/* Chapter 14's switches: a light or spot casts shadows and an object casts them unless `off`. */
static void test_shadow_switches(void **state)
{
    (void)state;
    const char *text = "material m albedo 1 1 1\n"
                       "mesh box cube\n"
                       "object box m cast off position 0 1 0\n"
                       "object box m cast on\n"
                       "object box m\n"
                       "light position 0 2 0 shadow off\n"
                       "light shadow on position 1 2 0\n"
                       "spot position 0 3 0 direction 0 -1 0 cone 20 30 shadow off\n"
                       "spot position 0 3 0 direction 0 -1 0 cone 20 30\n";
    scene s;
    parse_ok(text, &s);
    assert_true(s.objects[0].cast_off);
    assert_false(s.objects[1].cast_off);
    assert_false(s.objects[2].cast_off);
    assert_float_equal(s.objects[0].position[1], 1.0f, 0.0f);
    assert_true(s.lights[0].shadow_off);
    assert_false(s.lights[1].shadow_off);
    assert_float_equal(s.lights[1].position[0], 1.0f, 0.0f);
    assert_true(s.lights[2].shadow_off);
    assert_false(s.lights[3].shadow_off);
    scene_destroy(&s);
}

static void test_opacity_errors(void **state)
{
    (void)state;
    static const struct {
        const char *text;
        const char *want;
    } cases[] = {
        {"material m albedo 1 1 1 opacity 0\n", "t.scene:1: material opacity: must be > 0, got '0'"},
        {"material m albedo 1 1 1 opacity -0.5\n", "t.scene:1: material opacity: must be > 0, got '-0.5'"},
        {"\nmaterial m albedo 1 1 1 opacity 1.5\n",
         "t.scene:2: material opacity: must be at most 1 (1 is opaque), got '1.5'"},
        {"material m albedo 1 1 1 opacity 1.0000001\n", "t.scene:1: material opacity: must be at most 1"},
        {"material m albedo 1 1 1 opacity\n", "t.scene:1: material opacity: missing number"},
        {"material m albedo 1 1 1 opacity half\n",
         "t.scene:1: material opacity: expected a number, got 'half'"},
        {"material m albedo 1 1 1 opacity nan\n",
         "t.scene:1: material opacity: not a finite number, got 'nan'"},
        {"material m albedo 1 1 1 opacity 0.5 0.5\n", "t.scene:1: material: unexpected extra token '0.5'"},
        {"material m albedo 1 1 1 opacity 0.5 opacity 0.2\n", "t.scene:1: material: 'opacity' given twice"},
        {"material m albedo 1 1 1 alpha 0.5\n",
         "t.scene:1: material: unknown attribute 'alpha' (expected specular, shininess or opacity)"},
        {"mesh a cube\nmaterial m albedo 1 1 1\nobject a m opacity 0.5\n",
         "t.scene:3: object: unknown attribute 'opacity'"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        check_error(cases[i].text, cases[i].want);
}

static void test_error_long_line(void **state)
{
    (void)state;
    size_t n = 5000;
    char *text = malloc(n + 32);
    assert_non_null(text);
    strcpy(text, "ambient 0 0 0\n#");
    memset(text + strlen(text), 'x', n);
    text[15 + n] = '\0';
    check_error(text, "t.scene:2: line is longer than 4096 characters");
    /* 4096 characters exactly is fine. */
    text[15 + 4095] = '\0';
    scene s;
    parse_ok(text, &s);
    scene_destroy(&s);
    free(text);
}

static void test_error_from_file(void **state)
{
    (void)state;
    /* Bytes a C string cannot hold reach the parser only through scene_load. */
    static const char with_nul[] = "ambient 0 0 0\nmesh a\0 cube\n";
    check_error_text(with_nul, sizeof with_nul - 1, "t.scene:2: NUL byte at column 7", true);
    unsigned char garbage[256];
    for (int i = 0; i < 256; i++)
        garbage[i] = (unsigned char)(255 - i);
    check_error_text((const char *)garbage, sizeof garbage, "t.scene:1: invalid UTF-8 byte 0xFF", true);

    char missing[128];
    snprintf(missing, sizeof missing, "%s/no_such.scene", tmp_dir);
    char want[256];
    snprintf(want, sizeof want, "%s: cannot open scene: No such file or directory\n", missing);
    scene s;
    memset(&s, 0x5A, sizeof s);
    capture_begin();
    bool ok = scene_load(missing, &s);
    const char *err = capture_end();
    assert_false(ok);
    assert_true(scene_is_zero(&s));
    assert_string_equal(err, want);
}

/* ---- model paths --------------------------------------------------------------------------------- */

static void test_model_paths(void **state)
{
    (void)state;
    char dir[128], model[192], scene_path[192], want[192];
    snprintf(dir, sizeof dir, "%s/models", tmp_dir);
    assert_int_equal(mkdir(dir, 0755), 0);
    snprintf(model, sizeof model, "%s/box.obj", dir);
    write_file(model, "v 0 0 0\n", 8);

    /* Relative to the folder of the scene file, not the working directory. */
    snprintf(scene_path, sizeof scene_path, "%s/room.scene", tmp_dir);
    const char *text = "mesh box file models/box.obj\n";
    write_file(scene_path, text, strlen(text));
    scene s;
    capture_begin();
    bool ok = scene_load(scene_path, &s);
    assert_string_equal(capture_end(), "");
    assert_true(ok);
    assert_string_equal(s.path, scene_path);
    snprintf(want, sizeof want, "%s/models/box.obj", tmp_dir);
    assert_string_equal(s.meshes[0].path, want);
    scene_destroy(&s);

    /* From a string, relative to the base folder given; with a trailing slash too. */
    char base[160];
    snprintf(base, sizeof base, "%s/", dir);
    assert_true(scene_parse_string("mesh box file box.obj\n", "mem", base, &s));
    assert_string_equal(s.meshes[0].path, model);
    scene_destroy(&s);

    /* Absolute paths are kept as written, whatever the base folder. */
    char abs_text[256];
    snprintf(abs_text, sizeof abs_text, "mesh box file %s\n", model);
    assert_true(scene_parse_string(abs_text, "mem", "/nonexistent/folder", &s));
    assert_string_equal(s.meshes[0].path, model);
    scene_destroy(&s);

    /* A model missing next to the scene is reported with the path that was tried. */
    snprintf(want, sizeof want, "t.scene:1: cannot open model '%s/models/gone.obj': No such file", tmp_dir);
    check_error("mesh box file models/gone.obj\n", want);
    /* A folder is not a model. */
    check_error("mesh box file models\n", "not a regular file");
}

/* ---- size ---------------------------------------------------------------------------------------- */

static void test_large_scene(void **state)
{
    (void)state;
    enum { MATERIALS = 5000, OBJECTS = 40000, LIGHTS = 7000 };
    size_t cap = 16u << 20, len = 0;
    char *text = malloc(cap);
    assert_non_null(text);
#define APPEND(...) (len += (size_t)snprintf(text + len, cap - len, __VA_ARGS__), assert_true(len < cap))
    APPEND("camera eye 0 50 120 target 0 0 0 far 500\nmesh box cube\nmesh ball sphere 8 4\n");
    for (int i = 0; i < MATERIALS; i++)
        APPEND("material mat%d albedo %d.25 0.5 0.5 shininess %d\n", i, i % 3, 1 + i % 100);
    for (int i = 0; i < OBJECTS; i++) {
        APPEND("object %s mat%d position %d 0 %d rotate_y %d # object %d\n", i % 2 ? "box" : "ball",
               (i * 7) % MATERIALS, i % 200, i / 200, i % 360, i);
        APPEND("key 0 position %d 0 0\n", i);
    }
    for (int i = 0; i < LIGHTS; i++) {
        APPEND("light position %d 5 %d color 1 0.5 0.25 intensity 2\n", i % 100, i / 100);
        APPEND("key 0 position 0 5 0\nkey 2 position %d 5 0\n", i);
    }
#undef APPEND
    int lines = count_lines(text);
    assert_true(lines >= 100000);

    /* The parser's own CPU time, not wall time: other processes loading the machine (ctest -j) do
     * not add to it, while a parser quadratic in the lines (about 1e10 steps here) would. */
    struct timespec t0, t1;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t0);
    scene s;
    parse_ok(text, &s);
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t1);
    double seconds = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    print_message("parsed %d lines in %.3f s of CPU time\n", lines, seconds);
    /* Linear work: well under a second normally; the bound leaves room for sanitizers. */
    assert_true(seconds < 10.0);

    assert_int_equal(s.material_count, MATERIALS);
    assert_int_equal(s.object_count, OBJECTS);
    assert_int_equal(s.light_count, LIGHTS);
    int i = 31337;
    assert_int_equal(s.objects[i].mesh, 0); /* odd objects use "box", declared first */
    assert_int_equal(s.objects[i].material, (i * 7) % MATERIALS);
    assert_float_equal(s.materials[s.objects[i].material].albedo[0], (float)((i * 7) % MATERIALS % 3) + 0.25f,
                       EPS);
    assert_float_equal(s.objects[i].position[2], (float)(i / 200), EPS);
    assert_int_equal(s.objects[i].key_count, 1);
    mat4 m;
    scene_object_world_at(&s, i, 5.0f, m);
    assert_vec3_near(m[3], (float)i, 0, 0);
    vec3 p;
    scene_light_position_at(&s, 4321, 1.0f, p);
    assert_vec3_near(p, 4321 / 2.0f, 5, 0);
    scene_destroy(&s);
    free(text);
}

UNIT_TEST_MAIN(setup_dir, tmp_dir_remove, cmocka_unit_test(test_defaults),
               cmocka_unit_test(test_every_attribute), cmocka_unit_test(test_comments_and_layout),
               cmocka_unit_test(test_keys), cmocka_unit_test(test_world_matrix),
               cmocka_unit_test(test_add_light), cmocka_unit_test(test_add_light_grows_by_doubling),
               cmocka_unit_test(test_errors),
               cmocka_unit_test(test_spot), cmocka_unit_test(test_spot_errors),
               cmocka_unit_test(test_opacity), cmocka_unit_test(test_opacity_errors),
               cmocka_unit_test(test_shadow_switches),
               cmocka_unit_test(test_error_long_line), cmocka_unit_test(test_error_from_file),
               cmocka_unit_test(test_model_paths), cmocka_unit_test(test_large_scene))
