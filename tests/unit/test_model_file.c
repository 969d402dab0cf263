/* test_model_file.c - model files within limits (common/model/model_file.c): Assimp's messages as
 * one printable line, the limits and their variables, the pre-scan's counts against the bytes that
 * hold them, and mesh_data_load_memory on good and broken files of every format. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "mesh_data.h"
#include "model_file.h"
#include "test_util.h"

#include <stdlib.h>
#include <string.h>

static void test_quote_is_one_printable_line(void **state)
{
    (void)state;
    char out[MODEL_QUOTE_MAX + 8];
    model_quote("first line\nsecond", out, sizeof out);
    assert_string_equal(out, "first line");
    model_quote("tab\there \x01\xff end", out, sizeof out);
    assert_string_equal(out, "tab?here ?? end");
    char longer[600];
    memset(longer, 'a', sizeof longer - 1);
    longer[sizeof longer - 1] = '\0';
    model_quote(longer, out, sizeof out);
    assert_int_equal(strlen(out), MODEL_QUOTE_MAX + 3); /* cut, and "..." says so */
    assert_string_equal(out + MODEL_QUOTE_MAX, "...");
}

static void test_limits_from_environment(void **state)
{
    (void)state;
    model_limits lim;
    char why[256];
    unsetenv("COURSE_MODEL_MAX_BYTES");
    unsetenv("COURSE_MODEL_MAX_VERTICES");
    unsetenv("COURSE_MODEL_MAX_FACES");
    assert_true(model_limits_get(&lim, why, sizeof why));
    assert_true(lim.bytes == MODEL_MAX_BYTES_DEFAULT);
    assert_int_equal(lim.vertices, MODEL_MAX_VERTICES_DEFAULT);
    setenv("COURSE_MODEL_MAX_VERTICES", "12", 1);
    assert_true(model_limits_get(&lim, why, sizeof why));
    assert_int_equal(lim.vertices, 12);
    setenv("COURSE_MODEL_MAX_VERTICES", "12k", 1);
    assert_false(model_limits_get(&lim, why, sizeof why));
    assert_non_null(strstr(why, "COURSE_MODEL_MAX_VERTICES='12k': expected a whole number from 1 to"));
    unsetenv("COURSE_MODEL_MAX_VERTICES");
}

static void test_formats(void **state)
{
    (void)state;
    assert_string_equal(model_format_of("a/b/bunny.PLY"), "ply");
    assert_string_equal(model_format_of("x.glb"), "glb");
    assert_null(model_format_of("model.3ds"));
    assert_null(model_format_of("dir.obj/noext"));
}

/* The counts a header declares must fit the bytes after it, whatever the limits allow. */
static void test_prescan_counts(void **state)
{
    (void)state;
    model_limits lim = {.bytes = 1 << 20, .vertices = 1000, .faces = 1000};
    char why[256];
    const char *off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    assert_true(model_prescan(off, strlen(off), "off", &lim, why, sizeof why));
    const char *short_off = "OFF\n8 6 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    assert_false(model_prescan(short_off, strlen(short_off), "off", &lim, why, sizeof why));
    assert_string_equal(why, "its header declares 8 vertices and 6 faces, but 4 lines follow");
    const char *many = "OFF\n1001 1 0\n";
    assert_false(model_prescan(many, strlen(many), "off", &lim, why, sizeof why));
    assert_non_null(strstr(why, "it declares 1001 vertices, more than the limit of 1000"));
    const char *ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    assert_true(model_prescan(ply, strlen(ply), "ply", &lim, why, sizeof why));
    assert_false(model_prescan(ply, strlen(ply) - 8, "ply", &lim, why, sizeof why)); /* the face cut off */
    assert_string_equal(why, "the PLY data ends in face 0 of 1");
    lim.bytes = 10;
    assert_false(model_prescan(ply, strlen(ply), "ply", &lim, why, sizeof why));
    assert_non_null(strstr(why, "more than the limit of 10 (COURSE_MODEL_MAX_BYTES)"));
}

static void test_load_memory(void **state)
{
    (void)state;
    mesh_data m;
    const char *quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    assert_true(mesh_data_load_memory(&m, "quad.obj", quad, strlen(quad), NULL));
    assert_int_equal(m.index_count, 6); /* two triangles */
    mesh_data_destroy(&m);
    /* The reproducer: faces naming vertices the file never gives (Assimp: SIGBUS). */
    const char *off = "OFF\n8 6 0\n-0.5 -0.5 0.5\n0.5 -0.5 0.5\n-0.5 0 -0.5\n4 0 1 3 2\n4 2 3 5 4\n4 4 5 7 6\n"
                      "4 6 7 1 0\n4 1 7 5 3\n4 6 0 2 4\n";
    assert_false(mesh_data_load_memory(&m, "t.off", off, strlen(off), "t.scene:1"));
    assert_null(m.vertices);
    /* A face that names a vertex past the end: Assimp's validation or its loader refuses it. */
    const char *range = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n";
    assert_false(mesh_data_load_memory(&m, "range.obj", range, strlen(range), NULL));
    /* Within the file's own limit but over an overridden one. */
    setenv("COURSE_MODEL_MAX_FACES", "1", 1);
    assert_false(mesh_data_load_memory(&m, "quad.obj", quad, strlen(quad), NULL)); /* 2 triangles */
    unsetenv("COURSE_MODEL_MAX_FACES");
    /* A model file cannot make Assimp open another one when loaded from memory. */
    const char *mtl = "mtllib /etc/passwd\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    assert_true(mesh_data_load_memory(&m, "mtl.obj", mtl, strlen(mtl), NULL));
    mesh_data_destroy(&m);
}

UNIT_TEST_MAIN(NULL, NULL, cmocka_unit_test(test_quote_is_one_printable_line),
               cmocka_unit_test(test_limits_from_environment), cmocka_unit_test(test_formats),
               cmocka_unit_test(test_prescan_counts), cmocka_unit_test(test_load_memory))
