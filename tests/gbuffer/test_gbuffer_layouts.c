/* test_gbuffer_layouts.c - the G-buffer layouts of common/render/gbuffer.h hold what they say:
 *
 *   1. names: every layout has its name (gbuffer_layout_names[], the command line's), find works
 *   2. bytes: gbuffer_layout_bytes() is the sum of the bits GL reports for the textures it made, with
 *      and without stencil, every internal format is the layout's, and the default is <= 12 bytes
 *   3. reversed-Z: the depth written is 1 - the standard depth (to float rounding), the background
 *      is 0, and chapter 07's frame drawn with it (volumes mirrored by gbuffer_depth_test_begin)
 *      agrees with the same frame in standard depth and with forward within 1/255 on 99.99 % of
 *      pixels, on the default scene and the city
 *   4. the runner's guard: a reversed layout does not fit a lighting pass written for standard depth
 *   5. gbuffer_set_default_layout() is what gbuffer_create() then makes
 *
 * Exit 0 when every check holds, 1 when one fails, 77 when no GL context can be made.
 */
#include "cli.h"
#include "data_dir.h"
#include "deferred_volumes.h"
#include "fbo.h"
#include "gbuffer.h"
#include "gl_util.h"
#include "image.h"
#include "light.h"
#include "platform.h"
#include "chapters.h"
#include "scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WIDTH 320
#define HEIGHT 240

static int failures;

static void expect(bool ok, const char *what)
{
    printf("%s %s\n", ok ? "ok  " : "FAIL", what);
    failures += !ok;
}

/* ---- 1. names ---------------------------------------------------------------------------------- */

static void check_names(void)
{
    bool same = gbuffer_layout_names[GBUFFER_LAYOUT_COUNT] == NULL;
    for (int l = 0; l < GBUFFER_LAYOUT_COUNT; l++)
        same = same && gbuffer_layout_names[l] &&
               strcmp(gbuffer_layout_names[l], gbuffer_layout_name(&gbuffer_layouts[l])) == 0 &&
               gbuffer_layout_find(gbuffer_layout_names[l]) == &gbuffer_layouts[l];
    expect(same, "--gbuffer's choices are gbuffer_layouts[]'s names, in order, and each is found");
    expect(gbuffer_layout_find("no-such-layout") == NULL && gbuffer_layout_find(NULL) == NULL,
           "an unknown name finds nothing");
}

/* ---- 2. bytes ---------------------------------------------------------------------------------- */

static GLint level_param(GLuint texture, GLenum pname)
{
    GLint v = 0;
    glBindTexture(GL_TEXTURE_2D, texture);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, pname, &v);
    glBindTexture(GL_TEXTURE_2D, 0);
    return v;
}

static int texture_bits(GLuint texture)
{
    static const GLenum sizes[] = {GL_TEXTURE_RED_SIZE,   GL_TEXTURE_GREEN_SIZE, GL_TEXTURE_BLUE_SIZE,
                                   GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_DEPTH_SIZE, GL_TEXTURE_STENCIL_SIZE};
    int bits = 0;
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++)
        bits += level_param(texture, sizes[i]);
    return bits;
}

static void check_bytes(void)
{
    for (int l = 0; l < GBUFFER_LAYOUT_COUNT; l++)
        for (int stencil = 0; stencil < 2; stencil++) {
            const gbuffer_layout *layout = &gbuffer_layouts[l];
            char what[200];
            if (!gbuffer_layout_available(layout)) {
                printf("skip %s: not available in this context\n", gbuffer_layout_name(layout));
                continue;
            }
            gbuffer g;
            bool made =
                gbuffer_create_with(&g, 32, 16, &(gbuffer_desc){.stencil = stencil, .layout = layout});
            snprintf(what, sizeof what, "%s%s: created", gbuffer_layout_name(layout), stencil ? " with stencil" : "");
            expect(made, what);
            if (!made)
                continue;
            GLenum depth_format = gbuffer_layout_depth_format(layout, stencil);
            bool formats =
                level_param(g.fbo.color[0], GL_TEXTURE_INTERNAL_FORMAT) == (GLint)layout->albedo_format &&
                level_param(g.fbo.color[1], GL_TEXTURE_INTERNAL_FORMAT) == (GLint)layout->normal_format &&
                level_param(g.fbo.depth, GL_TEXTURE_INTERNAL_FORMAT) == (GLint)depth_format;
            int bits =
                texture_bits(g.fbo.color[0]) + texture_bits(g.fbo.color[1]) + texture_bits(g.fbo.depth);
            int stencil_bits = level_param(g.fbo.depth, GL_TEXTURE_STENCIL_SIZE);
            snprintf(what, sizeof what,
                     "%s%s: formats as declared; GL reports %d bits = %d bytes, "
                     "gbuffer_layout_bytes says %d; stencil bits %d",
                     gbuffer_layout_name(layout), stencil ? " with stencil" : "", bits, bits / 8,
                     gbuffer_layout_bytes(layout, stencil), stencil_bits);
            expect(formats && bits % 8 == 0 && bits / 8 == gbuffer_layout_bytes(layout, stencil) &&
                       (!stencil || stencil_bits == 8),
                   what);
            gbuffer_destroy(&g);
        }
    char what[120];
    snprintf(what, sizeof what, "the default layout (%s) is %d bytes per pixel, at most 12",
             gbuffer_layout_name(gbuffer_default_layout()), gbuffer_bytes_per_pixel());
    expect(gbuffer_default_layout() == &gbuffer_layouts[GBUFFER_LAYOUT_DEFAULT] &&
               gbuffer_bytes_per_pixel() <= 12,
           what);
}

/* ---- 3. reversed-Z ----------------------------------------------------------------------------- */

typedef struct frame_set {
    fbo target;
    gbuffer g;
    deferred_volumes dv;
} frame_set;

/* Chapter 07's frame with a layout, as the G-buffer sweep draws it (chapter_07_draw_with). */
static bool draw_07(frame_set *f, const gpu_scene *gs)
{
    return chapter_07_draw_with(&f->g, &f->dv, gs, f->target.id, (deferred_volumes_frame){.accum_format = GL_RGBA16F});
}

static bool read_picture(const fbo *f, image *img)
{
    if (!image_create(img, f->width, f->height))
        return false;
    return fbo_read_rgba8(f, 0, img->pixels);
}

static void compare(const char *scene_name, const char *what_a, const image *a, const char *what_b,
                    const image *b)
{
    image_stats st;
    char what[200];
    image_compare(a, b, NULL, 1, &st, NULL);
    snprintf(what, sizeof what,
             "%s: %s agrees with %s: max %d, %ld pixels over 1/255 (%.4f %%, at most 0.01 %%)", scene_name,
             what_a, what_b, st.max_abs, st.over, 100.0 * st.frac_over);
    expect(st.frac_over <= 0.0001, what);
}

static void check_reversed_scene(const char *scene_name)
{
    char path[4200], what[200];
    snprintf(path, sizeof path, "assets/scenes/%s.scene", scene_name);
    char full[4200];
    scene sc;
    gpu_scene gs;
    if (!data_dir_path(path, full, sizeof full) || !scene_load(full, &sc)) {
        expect(false, "scene loads");
        return;
    }
    bool ok = gpu_scene_create(&sc, &gs) && gpu_scene_update(&gs, 0.0f, LIGHT_DEFAULT_CUTOFF, WIDTH, HEIGHT);
    const fbo_desc target = {.color_formats = {GL_RGBA8},
                             .color_count = 1,
                             .depth_format = GL_DEPTH_COMPONENT32F,
                             .name = "target"};
    const gbuffer_layout *layouts[2] = {&gbuffer_layouts[GBUFFER_LAYOUT_COMPACT],
                                        &gbuffer_layouts[GBUFFER_LAYOUT_REVERSED_Z]};
    frame_set f[2];
    memset(f, 0, sizeof f);
    image pictures[3] = {{0}};
    float *depth[2] = {malloc(WIDTH * HEIGHT * sizeof(float)), malloc(WIDTH * HEIGHT * sizeof(float))};
    for (int k = 0; ok && k < 2; k++)
        ok = depth[k] && fbo_create(&f[k].target, &target, WIDTH, HEIGHT) &&
             gbuffer_create_with(&f[k].g, WIDTH, HEIGHT, &(gbuffer_desc){.layout = layouts[k]}) &&
             deferred_volumes_create(&f[k].dv, &f[k].g, GL_RGBA16F) && draw_07(&f[k], &gs) &&
             read_picture(&f[k].target, &pictures[k]) && fbo_read_depth(&f[k].g.fbo, depth[k]);
    app_forward r = {0}; /* the forward renderer every chapter switches to */
    ok = ok && app_forward_draw(&r, "forward", &gs, f[0].target.id, (app_forward_options){0}, NULL) &&
         read_picture(&f[0].target, &pictures[2]);
    snprintf(what, sizeof what, "%s: chapter 07's frame drawn with compact, reversed-z and forward",
             scene_name);
    expect(ok, what);
    if (ok) {
        /* Where both see a surface, d_reversed = 1 - d_standard up to float rounding; the background
         * keeps each one's clear value. */
        long background_ok = 0, surface = 0, off = 0;
        double worst = 0.0;
        for (int p = 0; p < WIDTH * HEIGHT; p++) {
            float d = depth[0][p], r_ = depth[1][p];
            if (d >= 1.0f) {
                background_ok += r_ == 0.0f;
                continue;
            }
            surface++;
            double e = fabs((double)r_ - (1.0 - (double)d));
            worst = fmax(worst, e);
            off += e > 1e-5;
        }
        long background = WIDTH * HEIGHT - surface;
        snprintf(what, sizeof what,
                 "%s: reversed depth is 1 - standard depth (largest gap %.2g over %ld surface "
                 "pixels, %ld over 1e-5), background 0 at %ld of %ld",
                 scene_name, worst, surface, off, background_ok, background);
        expect(surface > 0 && off == 0 && background_ok == background, what);
        compare(scene_name, "reversed-z", &pictures[1], "compact (standard depth)", &pictures[0]);
        compare(scene_name, "reversed-z", &pictures[1], "forward", &pictures[2]);
    }
    app_forward_destroy(&r);
    for (int k = 0; k < 3; k++)
        image_destroy(&pictures[k]);
    for (int k = 0; k < 2; k++) {
        free(depth[k]);
        deferred_volumes_destroy(&f[k].dv);
        gbuffer_destroy(&f[k].g);
        fbo_destroy(&f[k].target);
    }
    gpu_scene_destroy(&gs);
    scene_destroy(&sc);
}

/* ---- 4, 5. the runner's guard, the default ----------------------------------------------------- */

static void check_guard_and_default(void)
{
    const gbuffer_layout *reversed = &gbuffer_layouts[GBUFFER_LAYOUT_REVERSED_Z];
    const gl_pass_state volume_pass = {.cull = GL_FRONT, .depth_func = GL_GREATER};
    expect(!gbuffer_layout_fits_pass(reversed, &volume_pass) && gbuffer_layout_fits_pass(reversed, NULL) &&
               gbuffer_layout_fits_pass(&gbuffer_layouts[GBUFFER_LAYOUT_COMPACT], &volume_pass),
           "reversed-z is refused only where a chapter's lighting pass was written for standard depth");

    const gbuffer_layout *d24 = &gbuffer_layouts[GBUFFER_LAYOUT_COMPACT_D24S8];
    gbuffer g;
    bool ok = gbuffer_set_default_layout(d24) && gbuffer_create(&g, 16, 16);
    expect(ok && g.desc.layout == d24 && gbuffer_bytes_per_pixel() == gbuffer_layout_bytes(d24, false),
           "gbuffer_set_default_layout: gbuffer_create then makes that layout");
    if (ok)
        gbuffer_destroy(&g);
    expect(!gbuffer_set_default_layout(NULL), "no layout is refused");
    gbuffer_set_default_layout(&gbuffer_layouts[GBUFFER_LAYOUT_DEFAULT]);
}

int main(void)
{
    const platform_desc pd = {
        .backend = BACKEND_EGL, .width = 64, .height = 64, .title = "test_gbuffer_layouts", .gl_debug = true};
    int rc = platform_create(&pd);
    if (rc != EXIT_CODE_OK)
        return rc == EXIT_CODE_SKIP ? 77 : 1;
    check_names();
    check_bytes();
    check_guard_and_default();
    if (gbuffer_layout_available(&gbuffer_layouts[GBUFFER_LAYOUT_REVERSED_Z])) {
        check_reversed_scene("default");
        check_reversed_scene("city");
    } else {
        printf("skip reversed-z: this context has no glClipControl\n");
    }
    gl_util_shutdown();
    expect(gl_debug_error_count() == 0, "KHR_debug reported no GL error");
    platform_destroy();
    printf("%s\n", failures ? "FAILED" : "passed");
    return failures ? 1 : 0;
}
