/* test_texture_data.c - a material's image decoded for the GPU (common/scene/texture_data.c), from
 * files that changed after the scene was read: every failure is one line that starts where the scene
 * names the image (SCENE:LINE: material 'NAME' ATTRIBUTE 'PATH'), a truncated PNG, a named pipe and a
 * header declaring a huge picture included; none of them waits or allocates the picture. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "scene.h"
#include "test_util.h"
#include "texture_data.h"

#include <stb_image_write.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define SIDE 8

static int setup_dir(void **state)
{
    (void)state;
    alarm(60); /* a decode that waits on a named pipe fails the test instead of hanging it */
    return tmp_dir_create("/tmp/test_texture_data_XXXXXX");
}

/* An 8 x 8 PNG of noise (so that its data is more than a few bytes) at tmp_path(name). */
static void write_png(const char *name)
{
    unsigned char rgba[SIDE * SIDE * 4];
    for (size_t i = 0; i < sizeof rgba; i++)
        rgba[i] = (unsigned char)(i * 2654435761u >> 13);
    assert_true(stbi_write_png(tmp_path(name), SIDE, SIDE, 4, rgba, SIDE * 4) != 0);
}

/* The scene the images belong to: the map's image on line 3. */
static void parse_scene(const char *image, scene *s)
{
    char text[256];
    snprintf(text, sizeof text,
             "# maps\n\nmaterial brick pbr base 1 1 1 metallic 0 roughness 0.5 base_map %s\n", image);
    assert_true(scene_parse_string(text, "x.scene", tmp_dir, s));
    assert_int_equal(s->texture_count, 1);
}

/* texture_data_load with stderr in `err`; its result. */
static bool load_captured(const scene *s, unsigned char *rgba, char *err, size_t size)
{
    stderr_capture c;
    stderr_capture_begin(&c);
    assert_non_null(c.file);
    bool ok = texture_data_load(s, 0, SIDE, rgba);
    stderr_capture_end(&c, err, size);
    return ok;
}

/* The one line, and that it starts where the scene names the image. */
static void assert_one_line(const char *err, const char *image, const char *then)
{
    char want[1024];
    snprintf(want, sizeof want, "x.scene:3: material 'brick' base_map '%s': %s", tmp_path(image), then);
    if (!strstr(err, want))
        print_error("wanted '%s', got '%s'\n", want, err);
    assert_non_null(strstr(err, want));
    assert_ptr_equal(strchr(err, '\n'), err + strlen(err) - 1);
}

static void test_good_image_loads(void **state)
{
    (void)state;
    write_png("good.png");
    scene s;
    parse_scene("good.png", &s);
    unsigned char rgba[SIDE * SIDE * 4];
    char err[1024];
    assert_true(load_captured(&s, rgba, err, sizeof err));
    assert_string_equal(err, "");
    scene_destroy(&s);
}

/* The header is whole (the scene reads it), the pixels are not: the decode fails, on the map's line. */
static void test_truncated_png(void **state)
{
    (void)state;
    write_png("cut.png");
    struct stat st;
    assert_int_equal(stat(tmp_path("cut.png"), &st), 0);
    assert_int_equal(truncate(tmp_path("cut.png"), st.st_size - 40), 0); /* IEND and the end of IDAT */
    scene s;
    parse_scene("cut.png", &s);
    unsigned char rgba[SIDE * SIDE * 4];
    char err[1024];
    assert_false(load_captured(&s, rgba, err, sizeof err));
    assert_one_line(err, "cut.png", "cannot read image: ");
    scene_destroy(&s);
}

/* A named pipe where the image was: refused, not opened to wait for a writer. */
static void test_image_became_a_pipe(void **state)
{
    (void)state;
    write_png("pipe.png");
    scene s;
    parse_scene("pipe.png", &s);
    assert_int_equal(unlink(tmp_path("pipe.png")), 0);
    assert_int_equal(mkfifo(tmp_path("pipe.png"), 0600), 0);
    unsigned char rgba[SIDE * SIDE * 4];
    char err[1024];
    int w = 0, h = 0;
    assert_false(texture_data_size(&s, 0, &w, &h));
    assert_false(load_captured(&s, rgba, err, sizeof err));
    assert_one_line(err, "pipe.png", "cannot open image: not a regular file");
    scene_destroy(&s);
    unlink(tmp_path("pipe.png"));
}

/* A header declaring 25,500 x 25,500 grey texels where the image was (stb_image's own limit, 2^30
 * bytes as stored, lets it through; decoded to RGBA8 it is 2.6 GB): refused from the header, before
 * stb_image allocates anything for it. */
static void test_image_became_huge(void **state)
{
    (void)state;
    write_png("huge.png");
    scene s;
    parse_scene("huge.png", &s);
    FILE *f = fopen(tmp_path("huge.png"), "r+b");
    assert_non_null(f);
    /* IHDR's width and height (25500 each), bit depth 8, colour type 0 (grey); stb_image skips CRCs */
    const unsigned char header[10] = {0, 0, 0x63, 0x9c, 0, 0, 0x63, 0x9c, 8, 0};
    assert_int_equal(fseek(f, 16, SEEK_SET), 0);
    assert_int_equal(fwrite(header, 1, sizeof header, f), sizeof header);
    assert_int_equal(fclose(f), 0);
    unsigned char rgba[SIDE * SIDE * 4];
    char err[1024];
    assert_false(load_captured(&s, rgba, err, sizeof err));
    assert_one_line(err, "huge.png", "25500 x 25500 texels, more than 16384 a side");
    scene_destroy(&s);
}

UNIT_TEST_MAIN(setup_dir, tmp_dir_remove, cmocka_unit_test(test_good_image_loads),
               cmocka_unit_test(test_truncated_png), cmocka_unit_test(test_image_became_a_pipe),
               cmocka_unit_test(test_image_became_huge))
