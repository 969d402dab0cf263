/* test_resize_leaks.c - 200 resizes of every size-dependent GL resource leave the number of live GL
 * objects unchanged, and the objects a resize replaced are really gone from GL.
 *
 * Resources: the app's target (RGBA8 + depth, as app.c makes it), the G-buffer, and the light
 * volumes' accumulation buffer, which shares the G-buffer's depth. The window's own resize path is
 * tested by the chapters' --resize-cycle option (tests/robust/robust.cmake).
 *
 * Exit 0 when every check holds, 1 when one fails, 77 when no GL context can be made.
 */
#include "fbo.h"
#include "gbuffer.h"
#include "gl_util.h"
#include "deferred_volumes.h"
#include "platform.h"

#include <stdio.h>

#define RESIZES 200

static int failures;

static void expect(bool ok, const char *what)
{
    if (!ok || failures == 0)
        printf("%s %s\n", ok ? "ok  " : "FAIL", what);
    failures += !ok;
}

static bool make_target(fbo *target, int width, int height)
{
    fbo_destroy(target);
    const fbo_desc desc = {.color_formats = {GL_RGBA8},
                           .color_count = 1,
                           .depth_format = GL_DEPTH_COMPONENT32F,
                           .name = "target"};
    return fbo_create(target, &desc, width, height);
}

/* An id an fbo held before a resize must now be deleted, unless GL handed the same name out again
 * for one of the fbo's new objects. */
static bool texture_gone(GLuint old, const fbo *now)
{
    if (!old || !glIsTexture(old))
        return true;
    for (int i = 0; i < now->color_count; i++)
        if (now->color[i] == old)
            return true;
    return now->depth == old;
}

static bool fbo_replaced(const fbo *before, const fbo *now)
{
    bool ok = texture_gone(before->depth, now);
    for (int i = 0; i < before->color_count; i++)
        ok = ok && texture_gone(before->color[i], now);
    return ok && (before->id == now->id || !glIsFramebuffer(before->id));
}

int main(void)
{
    const platform_desc pd = {
        .backend = BACKEND_EGL, .width = 64, .height = 64, .title = "test_resize_leaks",
        .gl_debug = true};
    int rc = platform_create(&pd);
    if (rc != EXIT_CODE_OK)
        return rc == EXIT_CODE_SKIP ? 77 : 1;

    long empty = gl_live_objects();
    fbo target = {0};
    gbuffer g = {0};
    deferred_volumes dv = {0};
    bool ok = make_target(&target, 96, 64) && gbuffer_create(&g, 96, 64) &&
              deferred_volumes_create(&dv, &g, GL_RGBA16F);
    expect(ok, "target, G-buffer and light volumes created");
    long created = gl_live_objects();
    expect(created > empty, "the helpers counted what they created");

    /* Sizes that change every step, both ways and through odd values; 1x1 and a wide strip included. */
    for (int i = 0; ok && i < RESIZES; i++) {
        int w = 1 + (i * 37) % 301, h = 1 + (i * 53) % 199;
        if (i == RESIZES / 2)
            w = 1024, h = 8;
        fbo old_target = target, old_g = g.fbo, old_accum = dv.accum;
        ok = make_target(&target, w, h) && gbuffer_resize(&g, w, h) && deferred_volumes_resize(&dv, &g);
        char what[160];
        snprintf(what, sizeof what, "resize %d to %dx%d succeeds", i + 1, w, h);
        expect(ok, what);
        snprintf(what, sizeof what, "resize %d: live objects %ld (expected %ld)", i + 1, gl_live_objects(),
                 created);
        expect(gl_live_objects() == created, what);
        expect(target.width == w && g.fbo.width == w && dv.accum.width == w && dv.accum.height == h,
               "every resource follows the new size");
        expect(dv.accum.depth == g.fbo.depth, "the accumulation buffer shares the new G-buffer depth");
        expect(fbo_replaced(&old_target, &target) && fbo_replaced(&old_g, &g.fbo) &&
                   fbo_replaced(&old_accum, &dv.accum),
               "the textures and framebuffers a resize replaced are deleted in GL");
        expect(gl_check("resize"), "no GL error during the resize");
    }
    printf("%s %d resizes, live GL objects %ld before and %ld after\n", failures ? "FAIL" : "ok  ", RESIZES,
           created, gl_live_objects());

    deferred_volumes_destroy(&dv);
    gbuffer_destroy(&g);
    fbo_destroy(&target);
    gl_util_shutdown();
    expect(gl_live_objects() == empty, "destroying everything returns to the empty count");
    expect(gl_debug_error_count() == 0, "KHR_debug reported no GL error");
    platform_destroy();
    printf("%s\n", failures ? "FAILED" : "passed");
    return failures ? 1 : 0;
}
