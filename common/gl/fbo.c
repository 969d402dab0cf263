/* fbo.c - see fbo.h. */
#include "fbo.h"

#include "gl_util.h"
#include "log.h"

#include <string.h>

const char *fbo_status_name(GLenum status)
{
    switch (status) {
    case GL_FRAMEBUFFER_COMPLETE: return "GL_FRAMEBUFFER_COMPLETE";
    case GL_FRAMEBUFFER_UNDEFINED: return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
    case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS: return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
    default: return "unknown framebuffer status";
    }
}

/* glTexImage2D needs a client format and type even when no data is uploaded. */
static void client_format(GLenum internal, GLenum *format, GLenum *type)
{
    switch (internal) {
    case GL_DEPTH_COMPONENT16:
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH_COMPONENT32: *format = GL_DEPTH_COMPONENT, *type = GL_UNSIGNED_INT; return;
    case GL_DEPTH_COMPONENT32F: *format = GL_DEPTH_COMPONENT, *type = GL_FLOAT; return;
    case GL_DEPTH24_STENCIL8: *format = GL_DEPTH_STENCIL, *type = GL_UNSIGNED_INT_24_8; return;
    case GL_DEPTH32F_STENCIL8: *format = GL_DEPTH_STENCIL, *type = GL_FLOAT_32_UNSIGNED_INT_24_8_REV; return;
    case GL_R8UI:
    case GL_R16UI:
    case GL_R32UI: *format = GL_RED_INTEGER, *type = GL_UNSIGNED_INT; return;
    case GL_RG16UI:
    case GL_RG32UI: *format = GL_RG_INTEGER, *type = GL_UNSIGNED_INT; return;
    case GL_RGBA16UI:
    case GL_RGBA32UI: *format = GL_RGBA_INTEGER, *type = GL_UNSIGNED_INT; return;
    default: *format = GL_RGBA, *type = GL_FLOAT; return;
    }
}

static GLuint make_texture(GLenum internal, int width, int height, int samples)
{
    if (samples > 1) { /* fixed sample locations: every attachment's samples lie at the same places */
        GLuint t = gl_texture_create();
        glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, t);
        glTexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples, internal, width, height, GL_TRUE);
        glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
        return t;
    }
    GLenum format, type;
    client_format(internal, &format, &type);
    GLuint t = gl_texture_create();
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)internal, width, height, 0, format, type, NULL);
    gl_texture_sampling(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    return t;
}

bool fbo_create(fbo *f, const fbo_desc *desc, int width, int height)
{
    memset(f, 0, sizeof *f);
    f->width = width;
    f->height = height;
    f->samples = desc->samples > 1 ? desc->samples : 1;
    const GLenum target = f->samples > 1 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D;
    f->id = gl_framebuffer_create();
    glBindFramebuffer(GL_FRAMEBUFFER, f->id);
    GLenum draw[FBO_MAX_COLOR];
    for (int i = 0; i < desc->color_count; i++) {
        f->color[i] = make_texture(desc->color_formats[i], width, height, f->samples);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + (GLenum)i, target, f->color[i], 0);
        draw[i] = GL_COLOR_ATTACHMENT0 + (GLenum)i;
    }
    f->color_count = desc->color_count;
    glDrawBuffers(desc->color_count, draw);
    if (desc->shared_depth || desc->depth_format) {
        bool stencil = desc->depth_format == GL_DEPTH24_STENCIL8 || desc->depth_format == GL_DEPTH32F_STENCIL8;
        f->owns_depth = !desc->shared_depth;
        f->depth = desc->shared_depth ? desc->shared_depth : make_texture(desc->depth_format, width, height, f->samples);
        glFramebufferTexture2D(GL_FRAMEBUFFER, stencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                               target, f->depth, 0);
    }
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        /* An attachment the driver could not allocate leaves GL_OUT_OF_MEMORY behind: that is the cause
         * to name (read here in every build, not only where the debug callback would show it). */
        GLenum cause = GL_NO_ERROR;
        for (GLenum e; (e = glGetError()) != GL_NO_ERROR;)
            cause = cause == GL_NO_ERROR || e == GL_OUT_OF_MEMORY ? e : cause;
        log_error("framebuffer '%s' (%dx%d) is not complete: %s%s%s%s", desc->name ? desc->name : "?", width, height,
                  fbo_status_name(status), cause != GL_NO_ERROR ? ", because of " : "",
                  cause != GL_NO_ERROR ? gl_error_name(cause) : "",
                  cause == GL_OUT_OF_MEMORY ? " (its textures do not fit in the memory the driver has: try a "
                                              "smaller --size)"
                                            : "");
        fbo_destroy(f);
        return false;
    }
    return gl_check("fbo_create");
}

void fbo_destroy(fbo *f)
{
    for (int i = 0; i < f->color_count; i++)
        gl_texture_destroy(&f->color[i]);
    if (f->owns_depth)
        gl_texture_destroy(&f->depth);
    gl_framebuffer_destroy(&f->id);
    memset(f, 0, sizeof *f);
}

bool fbo_read_rgba8(const fbo *f, int attachment, unsigned char *rgba)
{
    gl_read_rgba8(f->id, attachment, f->width, f->height, rgba);
    return gl_check("fbo_read_rgba8");
}

bool fbo_read_float(const fbo *f, int attachment, float *rgba)
{
    gl_read_rgba_float(f->id, attachment, f->width, f->height, rgba);
    return gl_check("fbo_read_float");
}

bool fbo_read_depth(const fbo *f, float *depth)
{
    gl_read_depth(f->id, f->width, f->height, depth);
    return gl_check("fbo_read_depth");
}

bool fbo_samples_supported(int n, int cap, const char *what)
{
    GLint max_samples = 0, max_color = 0, max_depth = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
    glGetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &max_color);
    glGetIntegerv(GL_MAX_DEPTH_TEXTURE_SAMPLES, &max_depth);
    int max = max_samples < max_color ? max_samples : max_color;
    max = max < max_depth ? max : max_depth;
    max = max < cap ? max : cap;
    if (n <= max)
        return true;
    log_error("%s '%d': this context allows at most %d (GL_MAX_SAMPLES %d, GL_MAX_COLOR_TEXTURE_SAMPLES %d, "
              "GL_MAX_DEPTH_TEXTURE_SAMPLES %d)", what, n, max, max_samples, max_color, max_depth);
    return false;
}
