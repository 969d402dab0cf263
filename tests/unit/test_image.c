/* test_image.c - PNG round trip, atomic writes, and the statistics that golden tests rely on. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "image.h"
#include "test_util.h"

#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

/* Statistics are sums of small integers divided once, so they match the hand computation closely. */
#define EPS 1e-9
/* cmocka's float assertion works in single precision; these are doubles. */
#define ASSERT_NEAR(got, want) assert_true(fabs((got) - (want)) <= EPS)

static int setup_dir(void **state)
{
    (void)state;
    return tmp_dir_create("/tmp/test_image_XXXXXX");
}

static void set_pixel(image *img, int x, int y, int r, int g, int b, int a)
{
    unsigned char *p = img->pixels + 4 * ((size_t)y * (size_t)img->width + (size_t)x);
    p[0] = (unsigned char)r;
    p[1] = (unsigned char)g;
    p[2] = (unsigned char)b;
    p[3] = (unsigned char)a;
}

static const unsigned char *pixel_at(const image *img, int x, int y)
{
    return img->pixels + 4 * ((size_t)y * (size_t)img->width + (size_t)x);
}

/* Two blank width x height pictures, as a test that fills and compares them starts. */
static void create_pair(image *a, image *b, int width, int height)
{
    assert_true(image_create(a, width, height));
    assert_true(image_create(b, width, height));
}

/* Frees the pictures a test made, up to three (NULL for fewer). */
static void destroy_images(image *a, image *b, image *c)
{
    image_destroy(a);
    image_destroy(b);
    image_destroy(c);
}

/* Distinct values everywhere, including alpha, so a swapped channel or row cannot go unnoticed. */
static void fill_pattern(image *img)
{
    for (int y = 0; y < img->height; ++y)
        for (int x = 0; x < img->width; ++x)
            set_pixel(img, x, y, 20 * x + 3, 40 * y + 7, (x * 7 + y * 13) % 256, 255 - 10 * x - y);
}

static long file_size(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 ? (long)st.st_size : -1;
}

/* No PATH.tmp-* file may survive a write, whether it succeeded or not. */
static int count_temp_files(void)
{
    char cmd[160];
    snprintf(cmd, sizeof cmd, "ls -a '%s' | grep -c '\\.tmp-'", tmp_dir);
    FILE *p = popen(cmd, "r");
    int n = -1;
    if (p) {
        if (fscanf(p, "%d", &n) != 1)
            n = -1;
        pclose(p);
    }
    return n;
}

static void test_create_rejects_bad_size(void **state)
{
    (void)state;
    image img;
    assert_false(image_create(&img, 0, 4));
    assert_null(img.pixels);
    assert_false(image_create(&img, 3, -1));
    assert_true(image_create(&img, 3, 2));
    assert_int_equal(img.width, 3);
    assert_int_equal(img.height, 2);
    for (int i = 0; i < 3 * 2 * 4; ++i)
        assert_int_equal(img.pixels[i], 0);
    image_destroy(&img);
    assert_null(img.pixels);
}

static void test_round_trip(void **state)
{
    (void)state;
    const char *path = tmp_path("round.png");
    image src, back;
    assert_true(image_create(&src, 7, 5));
    fill_pattern(&src);
    assert_true(image_write_png(path, &src));
    assert_true(image_load_png(path, &back));
    assert_int_equal(back.width, 7);
    assert_int_equal(back.height, 5);
    assert_memory_equal(back.pixels, src.pixels, 7 * 5 * 4);
    assert_int_equal(count_temp_files(), 0);
    destroy_images(&src, &back, NULL);
}

static void test_write_replaces_old_file(void **state)
{
    (void)state;
    const char *path = tmp_path("replace.png");
    image first, second, back;
    assert_true(image_create(&first, 2, 2));
    assert_true(image_create(&second, 3, 1));
    fill_pattern(&second);
    assert_true(image_write_png(path, &first));
    assert_true(image_write_png(path, &second));
    assert_true(image_load_png(path, &back));
    assert_int_equal(back.width, 3);
    assert_memory_equal(back.pixels, second.pixels, 3 * 1 * 4);
    destroy_images(&first, &second, &back);
}

static void test_load_missing_or_garbage(void **state)
{
    (void)state;
    image img;
    const char *path = tmp_path("missing.png");
    assert_false(image_load_png(path, &img));
    assert_null(img.pixels);

    path = tmp_path("garbage.png");
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    fputs("not a png at all", f);
    fclose(f);
    assert_false(image_load_png(path, &img));
    assert_null(img.pixels);
}

/* Root ignores permissions, so the failures are structural: a path that is a directory, a parent that is a
 * file, and a write cut short by the file-size limit (which behaves like a full disk). */
static void test_write_fails_on_directory_target(void **state)
{
    (void)state;
    const char *dir = tmp_path("target_dir.png");
    char inside[160];
    assert_int_equal(mkdir(dir, 0755), 0);
    snprintf(inside, sizeof inside, "%s/keep", dir);
    FILE *f = fopen(inside, "w");
    assert_non_null(f);
    fclose(f);

    image img;
    assert_true(image_create(&img, 4, 4));
    assert_false(image_write_png(dir, &img));
    struct stat st;
    assert_int_equal(stat(dir, &st), 0);
    assert_true(S_ISDIR(st.st_mode));
    assert_int_equal(file_size(inside), 0);
    assert_int_equal(count_temp_files(), 0);
    image_destroy(&img);
}

static void test_write_fails_when_parent_is_file(void **state)
{
    (void)state;
    const char *parent = tmp_path("plain_file");
    char path[160];
    FILE *f = fopen(parent, "w");
    assert_non_null(f);
    fputs("x", f);
    fclose(f);
    snprintf(path, sizeof path, "%s/out.png", parent);

    image img;
    assert_true(image_create(&img, 4, 4));
    assert_false(image_write_png(path, &img));
    assert_int_equal(file_size(parent), 1);
    image_destroy(&img);
}

static void test_write_failure_keeps_old_file(void **state)
{
    (void)state;
    const char *path = tmp_path("keep.png");
    image small, noisy, back;
    assert_true(image_create(&small, 2, 2));
    fill_pattern(&small);
    assert_true(image_write_png(path, &small));
    long old_size = file_size(path);
    assert_true(old_size > 0);

    /* Noise does not compress, so this PNG is far larger than the limit set below. */
    assert_true(image_create(&noisy, 64, 64));
    srand(12345);
    for (int i = 0; i < 64 * 64 * 4; ++i)
        noisy.pixels[i] = (unsigned char)(rand() & 0xff);

    struct rlimit saved, limited;
    assert_int_equal(getrlimit(RLIMIT_FSIZE, &saved), 0);
    limited = saved;
    limited.rlim_cur = 1024;
    void (*old_handler)(int) = signal(SIGXFSZ, SIG_IGN); /* get EFBIG instead of being killed */
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &limited), 0);
    bool ok = image_write_png(path, &noisy);
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &saved), 0);
    signal(SIGXFSZ, old_handler);

    assert_false(ok);
    assert_int_equal(file_size(path), old_size);
    assert_true(image_load_png(path, &back));
    assert_memory_equal(back.pixels, small.pixels, 2 * 2 * 4);
    assert_int_equal(count_temp_files(), 0);
    destroy_images(&small, &noisy, &back);
}

static void test_flip_rows(void **state)
{
    (void)state;
    image img, orig;
    for (int h = 1; h <= 4; ++h) { /* odd heights keep the middle row in place */
        create_pair(&img, &orig, 3, h);
        fill_pattern(&img);
        memcpy(orig.pixels, img.pixels, (size_t)3 * h * 4);
        image_flip_rows(&img);
        for (int y = 0; y < h; ++y)
            assert_memory_equal(pixel_at(&img, 0, y), pixel_at(&orig, 0, h - 1 - y), 3 * 4);
        image_flip_rows(&img);
        assert_memory_equal(img.pixels, orig.pixels, (size_t)3 * h * 4);
        destroy_images(&img, &orig, NULL);
    }
}

/* The pixels image_compare compared, its largest channel difference and the first pixel that has it. */
static void assert_largest_difference(const image_stats *s, long pixels, int max_abs, int x, int y)
{
    assert_int_equal(s->pixels, pixels);
    assert_int_equal(s->max_abs, max_abs);
    assert_int_equal(s->max_x, x);
    assert_int_equal(s->max_y, y);
}

static void test_compare_identical(void **state)
{
    (void)state;
    image a, b, heat;
    create_pair(&a, &b, 5, 4);
    fill_pattern(&a);
    memcpy(b.pixels, a.pixels, 5 * 4 * 4);
    b.pixels[3] = 0; /* alpha is not compared */
    image_stats s;
    assert_true(image_compare(&a, &b, NULL, 0, &s, &heat));
    assert_largest_difference(&s, 20, 0, 0, 0);
    assert_true(s.mean_abs == 0.0);
    assert_true(s.rmse == 0.0);
    assert_true(isinf(s.psnr) && s.psnr > 0);
    assert_int_equal(s.over, 0);
    assert_true(s.frac_over == 0.0);
    assert_int_equal(heat.width, 5);
    assert_int_equal(heat.height, 4);
    for (int i = 0; i < 20; ++i) {
        const unsigned char *p = heat.pixels + 4 * i;
        assert_true(p[0] == 0 && p[1] == 0 && p[2] == 0 && p[3] == 255);
    }
    destroy_images(&a, &b, &heat);
}

/* A 4x3 pair with three differing pixels, sums worked out by hand:
 *   (1,0): R+2            channel diffs 2, 0, 0
 *   (3,1): G-5, B+5       channel diffs 0, 5, 5   (first pixel with the maximum 5)
 *   (0,2): R+5            channel diffs 5, 0, 0   (same maximum, later in row-major order)
 * Sum |d| = 17, sum d^2 = 4 + 25 + 25 + 25 = 79, over 12 pixels * 3 channels = 36 samples. */
static void make_known_pair(image *a, image *b)
{
    create_pair(a, b, 4, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x) {
            set_pixel(a, x, y, 100 + x, 50 + y, 200, 255);
            set_pixel(b, x, y, 100 + x, 50 + y, 200, 255);
        }
    set_pixel(b, 1, 0, 103, 50, 200, 255);
    set_pixel(b, 3, 1, 103, 46, 205, 255);
    set_pixel(b, 0, 2, 105, 52, 200, 17);
}

static void test_compare_known_differences(void **state)
{
    (void)state;
    image a, b, heat;
    make_known_pair(&a, &b);
    image_stats s;
    assert_true(image_compare(&a, &b, NULL, 2, &s, &heat));
    assert_largest_difference(&s, 12, 5, 3, 1);
    ASSERT_NEAR(s.mean_abs, 17.0 / 36.0);
    ASSERT_NEAR(s.rmse, sqrt(79.0 / 36.0));
    ASSERT_NEAR(s.psnr, 20.0 * log10(255.0 / sqrt(79.0 / 36.0)));
    assert_int_equal(s.over, 2); /* tolerance 2: the pixel with diff 2 is within */
    ASSERT_NEAR(s.frac_over, 2.0 / 12.0);

    /* Heat: black where equal, dim slate blue within the tolerance (the diff-2 pixel), clearly red
     * over it, and no pixel over the tolerance as dark as one within it. */
    assert_int_equal(pixel_at(&heat, 0, 0)[0], 0);
    const unsigned char *within = pixel_at(&heat, 1, 0), *over = pixel_at(&heat, 3, 1);
    assert_true(within[2] > within[0] && within[0] + within[1] + within[2] < 255);
    assert_true(over[0] >= 96 && over[0] > over[2]);
    assert_true(over[0] + over[1] + over[2] > within[0] + within[1] + within[2]);
    image_destroy(&heat);
    /* Tolerance 1: the same diff-2 pixel is over it, red. */
    assert_true(image_compare(&a, &b, NULL, 1, &s, &heat));
    assert_true(pixel_at(&heat, 1, 0)[0] >= 96 && pixel_at(&heat, 1, 0)[0] > pixel_at(&heat, 1, 0)[2]);
    image_destroy(&heat);

    assert_true(image_compare(&a, &b, NULL, 1, &s, NULL));
    assert_int_equal(s.over, 3);
    assert_true(image_compare(&a, &b, NULL, 5, &s, NULL));
    assert_int_equal(s.over, 0);
    destroy_images(&a, &b, NULL);
}

static void test_heat_ramp(void **state)
{
    (void)state;
    image a, b, heat;
    create_pair(&a, &b, 40, 1);
    for (int x = 0; x < 40; ++x)
        set_pixel(&b, x, 0, 0, x, 0, 255);
    image_stats s;
    assert_true(image_compare(&a, &b, NULL, 0, &s, &heat));
    /* Brightness grows with the difference up to the saturation point, then stays. */
    int prev = 0;
    for (int x = 1; x < 40; ++x) {
        const unsigned char *p = pixel_at(&heat, x, 0);
        int sum = p[0] + p[1] + p[2];
        assert_true(sum >= prev);
        prev = sum;
    }
    assert_true(pixel_at(&heat, 1, 0)[0] > pixel_at(&heat, 1, 0)[1]); /* diff 1 is red */
    assert_true(pixel_at(&heat, 32, 0)[1] > 200);                       /* diff 32 is yellow-white */
    assert_memory_equal(pixel_at(&heat, 32, 0), pixel_at(&heat, 39, 0), 4);
    destroy_images(&a, &b, &heat);
}

static void test_compare_with_mask(void **state)
{
    (void)state;
    image a, b, mask, heat;
    make_known_pair(&a, &b);
    assert_true(image_create(&mask, 4, 3));
    for (int i = 0; i < 12; ++i)
        mask.pixels[4 * i] = 255;
    mask.pixels[4 * (1 * 4 + 3)] = 0; /* exclude (3,1) */
    mask.pixels[4 * (2 * 4 + 0) + 1] = 255; /* only red counts: (0,2) stays included */
    image_stats s;
    assert_true(image_compare(&a, &b, &mask, 2, &s, &heat));
    assert_largest_difference(&s, 11, 5, 0, 2);
    ASSERT_NEAR(s.mean_abs, 7.0 / 33.0);
    ASSERT_NEAR(s.rmse, sqrt(29.0 / 33.0));
    assert_int_equal(s.over, 1);
    const unsigned char *masked = pixel_at(&heat, 3, 1);
    assert_true(masked[2] > 0 && masked[0] == 0 && masked[1] == 0); /* dark blue */

    /* Masking out every difference leaves identical images. */
    mask.pixels[4 * (0 * 4 + 1)] = 0;
    mask.pixels[4 * (2 * 4 + 0)] = 0;
    image_destroy(&heat);
    assert_true(image_compare(&a, &b, &mask, 0, &s, NULL));
    assert_int_equal(s.pixels, 9);
    assert_int_equal(s.max_abs, 0);
    assert_true(isinf(s.psnr));
    destroy_images(&a, &b, &mask);
}

static void test_compare_size_mismatch(void **state)
{
    (void)state;
    image a, b, mask, heat;
    assert_true(image_create(&a, 4, 3));
    assert_true(image_create(&b, 3, 4));
    image_stats s;
    assert_false(image_compare(&a, &b, NULL, 1, &s, &heat));
    assert_null(heat.pixels);
    assert_true(image_create(&mask, 2, 2));
    assert_false(image_compare(&a, &a, &mask, 1, &s, NULL));
    destroy_images(&a, &b, &mask);
}

UNIT_TEST_MAIN(setup_dir, tmp_dir_remove, cmocka_unit_test(test_create_rejects_bad_size),
               cmocka_unit_test(test_round_trip), cmocka_unit_test(test_write_replaces_old_file),
               cmocka_unit_test(test_load_missing_or_garbage),
               cmocka_unit_test(test_write_fails_on_directory_target),
               cmocka_unit_test(test_write_fails_when_parent_is_file),
               cmocka_unit_test(test_write_failure_keeps_old_file), cmocka_unit_test(test_flip_rows),
               cmocka_unit_test(test_compare_identical), cmocka_unit_test(test_compare_known_differences),
               cmocka_unit_test(test_heat_ramp), cmocka_unit_test(test_compare_with_mask),
               cmocka_unit_test(test_compare_size_mismatch))
