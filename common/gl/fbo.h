/* fbo.h - framebuffers with texture attachments.
 *
 *   fbo_create(fbo, desc, width, height)  textures per desc, completeness checked (status logged by name)
 *   fbo_destroy(fbo)
 *   fbo_status_name(status)               "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT", ...
 *   fbo_read_rgba8(fbo, attachment, rgba) read a colour attachment as width x height RGBA bytes,
 *                                         in GL's row order (bottom row first)
 *   fbo_read_float(fbo, attachment, rgba) the same as width x height RGBA floats
 *   fbo_read_depth(fbo, depth)            the depth attachment as width x height floats in [0, 1]
 *                                         (all three through gl_util.h's gl_read_*, which read any
 *                                         framebuffer object by name)
 *   fbo_samples_supported(n, cap, what)   whether colour and depth textures of n samples can be made
 *                                         (GL_MAX_SAMPLES, GL_MAX_COLOR_TEXTURE_SAMPLES and
 *                                         GL_MAX_DEPTH_TEXTURE_SAMPLES, and the caller's cap); if not,
 *                                         one line naming `what`, the largest count and the three limits
 *
 * desc.shared_depth attaches an existing depth texture instead of making one, so a lighting
 * pass can depth-test against the geometry pass's depth. desc.samples > 1 makes every attachment a
 * GL_TEXTURE_2D_MULTISAMPLE texture with that many samples (fixed sample locations; chapter 13);
 * 0 or 1 is a plain GL_TEXTURE_2D. A shared depth must have the same sample count.
 */
#ifndef COMMON_FBO_H
#define COMMON_FBO_H


#include <glad/gl.h>
#include <stdbool.h>

#define FBO_MAX_COLOR 8

typedef struct fbo_desc {
    GLenum color_formats[FBO_MAX_COLOR]; /* internal formats, e.g. GL_RGBA8, GL_RGBA16F */
    int color_count;
    GLenum depth_format; /* GL_DEPTH_COMPONENT32F, GL_DEPTH24_STENCIL8, ... or 0 */
    GLuint shared_depth; /* attach this depth texture instead (depth_format says its format) */
    const char *name;    /* for messages */
    int samples;         /* > 1: multisampled textures (GL_TEXTURE_2D_MULTISAMPLE); 0, 1: plain */
} fbo_desc;

typedef struct fbo {
    GLuint id;
    GLuint color[FBO_MAX_COLOR];
    int color_count;
    GLuint depth;
    bool owns_depth;
    int width, height;
    int samples; /* 1, or the sample count of multisampled attachments */
} fbo;

bool fbo_create(fbo *f, const fbo_desc *desc, int width, int height);
void fbo_destroy(fbo *f);
const char *fbo_status_name(GLenum status);
bool fbo_read_rgba8(const fbo *f, int attachment, unsigned char *rgba);
bool fbo_read_float(const fbo *f, int attachment, float *rgba);
bool fbo_read_depth(const fbo *f, float *depth);
bool fbo_samples_supported(int n, int cap, const char *what);

#endif
