/* test_gl_error.c - a GL error must be seen: by the KHR_debug callback (gl_debug_enable) and by
 * gl_check's glGetError loop, which is also the fallback when KHR_debug is missing.
 *
 * Exit 0 when every check holds, 1 when one fails, 77 when no GL context can be made.
 */
#include "gl_util.h"
#include "log.h"
#include "platform.h"

#include <stdio.h>

static int failures;

static void expect(bool ok, const char *what)
{
    printf("%s %s\n", ok ? "ok  " : "FAIL", what);
    failures += !ok;
}

int main(void)
{
    const platform_desc pd = {
        .backend = BACKEND_EGL, .width = 64, .height = 64, .title = "test_gl_error"};
    int rc = platform_create(&pd);
    if (rc != EXIT_CODE_OK)
        return rc == EXIT_CODE_SKIP ? 77 : 1;

    /* 1. Without KHR_debug only gl_check notices. GL_INVALID_ENUM: 0x1234 is no capability. */
    expect(gl_check("a clean start"), "a fresh context has no pending error");
    long before = gl_debug_error_count();
    glEnable(0x1234);
    expect(gl_debug_error_count() == before, "no callback is installed yet, so nothing is counted");
    expect(!gl_check("glEnable(0x1234)"), "gl_check reports the pending GL_INVALID_ENUM");
    expect(gl_debug_error_count() == before + 1, "gl_check counts the error it reported");
    expect(gl_check("after the error was read"), "glGetError cleared the flag");

    /* 2. With the callback the error is counted at the call that caused it. */
    gl_debug_enable();
    expect(GLAD_GL_KHR_debug != 0, "KHR_debug is available (Mesa has it in every context)");
    before = gl_debug_error_count();
    GLuint texture = gl_texture_create();
    glBindTexture(GL_TEXTURE_2D, texture);
    /* GL_INVALID_VALUE: a negative size. */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, -1, -1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    long after_call = gl_debug_error_count();
    expect(after_call == before + 1, "the callback counted exactly one error, synchronously");
    expect(!gl_check("glTexImage2D(-1, -1)"), "gl_check still sees the error flag the callback saw");
    expect(gl_debug_error_count() == after_call + 1, "gl_check adds its own count");

    /* 3. Correct calls count nothing: no false alarms from the callback. */
    before = gl_debug_error_count();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    GLuint framebuffer = gl_framebuffer_create();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    expect(gl_check("valid calls") && gl_debug_error_count() == before, "valid calls raise no error");

    /* 4. A GL_INVALID_OPERATION from the state machine rather than an argument check. */
    before = gl_debug_error_count();
    glUseProgram(12345); /* no such program */
    /* At least one error: drivers word and count their messages differently (NVIDIA sends more). */
    expect(gl_debug_error_count() > before, "glUseProgram(unknown) is counted by the callback");
    gl_check("glUseProgram(12345)");

    gl_framebuffer_destroy(&framebuffer);
    gl_texture_destroy(&texture);
    gl_util_shutdown();
    expect(gl_live_objects() == 0, "every object made here was destroyed");
    platform_destroy();
    printf("%s\n", failures ? "FAILED" : "passed");
    return failures ? 1 : 0;
}
