/* hard_util.c - see hard_util.h. */
#include "hard_util.h"

#include "gl_program.h"
#include "gl_util.h"
#include "platform.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures;

void hard_context_create(int width, int height)
{
    const platform_desc desc = {
        .backend = BACKEND_EGL, .width = width, .height = height, .title = "hard", .gl_debug = true};
    int rc = platform_create(&desc);
    if (rc != EXIT_CODE_OK) {
        printf("skip: no GL context\n");
        exit(EXIT_CODE_SKIP); /* never pass without a context */
    }
}

GLuint hard_program_create(const char *vert, const char *frag)
{
    return gl_program_create("test program", vert, frag, NULL);
}

bool hard_expect(bool ok, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    printf("%s ", ok ? "ok  " : "FAIL");
    vprintf(fmt, ap);
    printf("\n");
    va_end(ap);
    if (!ok)
        failures++;
    fflush(stdout);
    return ok;
}

int hard_failures(void)
{
    return failures;
}

int hard_finish(void)
{
    gl_check("end of test");
    hard_expect(gl_debug_error_count() == 0, "no GL errors (%ld)", gl_debug_error_count());
    platform_destroy();
    printf("%s: %d failure(s)\n", failures ? "FAILED" : "passed", failures);
    return failures ? 1 : 0;
}

double hard_encode(double c)
{
    c = c < 0 ? 0 : c > 1 ? 1 : c;
    double e = c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
    return e * 255.0;
}
