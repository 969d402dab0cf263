/* hard_util.c - see hard_util.h. */
#include "hard_util.h"

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
        .backend = CLI_BACKEND_EGL, .width = width, .height = height, .title = "hard", .gl_debug = true};
    int rc = platform_create(&desc);
    if (rc != CLI_EXIT_OK) {
        printf("skip: no GL context\n");
        exit(CLI_EXIT_SKIP); /* never pass without a context */
    }
}

static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        log_error("%s: cannot read", path);
        return NULL;
    }
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *buf = n >= 0 ? malloc((size_t)n + 1) : NULL;
    if (buf && fread(buf, 1, (size_t)n, f) != (size_t)n) {
        free(buf);
        buf = NULL;
    }
    if (buf)
        buf[n] = '\0';
    fclose(f);
    return buf;
}

/* The source with its include line replaced by shaders/shading.glsl, so the test shades with the
 * renderers' own function rather than a copy of it. */
static char *expand_source(const char *src)
{
    static const char directive[] = "#include \"shading.glsl\"";
    const char *at = strstr(src, directive);
    if (!at)
        return strdup(src);
    char path[1024];
    snprintf(path, sizeof path, "%s/shading.glsl", gl_shader_dir());
    char *inc = read_text(path);
    if (!inc)
        return NULL;
    size_t head = (size_t)(at - src), inc_len = strlen(inc), tail = strlen(at + sizeof directive - 1);
    char *out = malloc(head + inc_len + tail + 2);
    if (out) {
        memcpy(out, src, head);
        memcpy(out + head, inc, inc_len);
        out[head + inc_len] = '\n';
        memcpy(out + head + inc_len + 1, at + sizeof directive - 1, tail + 1);
    }
    free(inc);
    return out;
}

static GLuint compile(GLenum type, const char *src)
{
    char *text = expand_source(src);
    if (!text)
        return 0;
    GLuint s = glCreateShader(type);
    const char *p = text;
    glShaderSource(s, 1, &p, NULL);
    glCompileShader(s);
    free(text);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char info[2048];
        glGetShaderInfoLog(s, sizeof info, NULL, info);
        log_error("test shader: %s", info);
        glDeleteShader(s);
        return 0;
    }
    return s;
}

GLuint hard_program_create(const char *vert, const char *frag)
{
    GLuint vs = compile(GL_VERTEX_SHADER, vert), fs = compile(GL_FRAGMENT_SHADER, frag);
    if (!vs || !fs) {
        glDeleteShader(vs);
        glDeleteShader(fs);
        return 0;
    }
    GLuint p = glCreateProgram();
    glAttachShader(p, vs);
    glAttachShader(p, fs);
    glLinkProgram(p);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char info[2048];
        glGetProgramInfoLog(p, sizeof info, NULL, info);
        log_error("test program: %s", info);
        glDeleteProgram(p);
        return 0;
    }
    return p;
}

void hard_read_rgba_float(GLuint fbo, int width, int height, float *out)
{
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, out);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
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
