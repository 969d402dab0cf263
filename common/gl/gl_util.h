/* gl_util.h - small OpenGL helpers every module uses (shader programs: gl_program.h).
 *
 *   gl_texture_create / gl_buffer_create / gl_framebuffer_create / gl_vertex_array_create / gl_query_create
 *   / gl_renderbuffer_create
 *   gl_texture_destroy / gl_buffer_destroy / gl_framebuffer_destroy / gl_vertex_array_destroy / ..._destroy
 *                                         create/delete pairs that count live objects
 *   gl_live_objects()                     objects created and not yet destroyed (leak checks)
 *   gl_texture_sampling(target, min, mag, wrap)
 *                                         the bound texture's filters, and one wrap mode on every axis
 *   gl_live_objects_add(delta)            count objects made without the pairs above (gl_program.c's)
 *   gl_check(where)                       glGetError loop; logs and returns false on error
 *   gl_error_name(e)                      "GL_OUT_OF_MEMORY", ... for a glGetError value
 *   gl_debug_enable()                     KHR_debug messages to the log; errors are remembered
 *   gl_debug_error_count()                GL errors seen since gl_debug_enable (or by gl_check)
 *   gl_draw_fullscreen()                  one triangle covering the viewport (gl_VertexID based)
 *   gl_pass_state_apply(state)            blend, cull, depth test, depth write, depth clamp and the
 *                                         stencil test from one literal (zero fields: off)
 *   gl_pass_state_reset()                 the state every pass starts from and leaves behind: all of
 *                                         the above off, depth writes on, glDepthFunc(GL_LESS),
 *                                         colour writes on
 *   gl_texture_buffer_upload(buffer, texture, format, data, bytes)
 *                                         fill `buffer` and attach it to the buffer texture
 *                                         `texture` as `format` (GL_R32I, GL_RGBA32F); unbinds both
 *   gl_texture_buffer_bind(program, uniform, unit, texture)
 *                                         the buffer texture on texture unit `unit`, and the
 *                                         sampler `uniform` of `program` (in use) set to it
 *   gl_buffer_read(buffer, bytes, out)    the first `bytes` of a buffer back into memory
 *   gl_read_rgba8(framebuffer, attachment, w, h, out)
 *   gl_read_rgba_float(framebuffer, attachment, w, h, out)
 *                                         colour attachment `attachment` of the framebuffer object
 *                                         as w x h RGBA bytes or floats, bottom row first; the read
 *                                         framebuffer binding is 0 again after
 *   gl_read_depth(framebuffer, w, h, out) its depth as w x h floats in [0, 1], bottom row first
 *   gl_have_compute()                     compute shaders on this context (GLAD_GL_VERSION_4_3), unless
 *                                         $COURSE_NO_COMPUTE is set: the tests run the GL 3.3 paths on
 *                                         a newer driver that way
 *   gl_samples_begin(query, on) / gl_samples_end(query, on)
 *                                         count the fragments that pass (GL_SAMPLES_PASSED) between
 *                                         the two; end returns the count, or -1 when `on` is false
 *   gl_draw_hooks_set(hooks)              functions called around every draw the course issues and
 *                                         around gl_samples_begin/end (draw_count.h installs them
 *                                         while it counts); NULL: none
 *   gl_draw_hooks_begin(fullscreen) / gl_draw_hooks_end()
 *                                         around a draw (mesh.c's, gl_draw_fullscreen's): the hooks'
 *                                         draw_begin / draw_end when set
 */
#ifndef COMMON_GL_UTIL_H
#define COMMON_GL_UTIL_H


#include <glad/gl.h>
#include <stdbool.h>
#include <stddef.h>

GLuint gl_texture_create(void);
void gl_texture_sampling(GLenum target, GLint min_filter, GLint mag_filter, GLint wrap);
GLuint gl_buffer_create(void);
GLuint gl_framebuffer_create(void);
GLuint gl_vertex_array_create(void);
GLuint gl_query_create(void);
GLuint gl_renderbuffer_create(void);
void gl_texture_destroy(GLuint *id);
void gl_buffer_destroy(GLuint *id);
void gl_framebuffer_destroy(GLuint *id);
void gl_vertex_array_destroy(GLuint *id);
void gl_query_destroy(GLuint *id);
void gl_renderbuffer_destroy(GLuint *id);
long gl_live_objects(void);
void gl_live_objects_add(long delta);

bool gl_check(const char *where);
const char *gl_error_name(GLenum e);
void gl_debug_enable(void);
long gl_debug_error_count(void);

void gl_draw_fullscreen(void);

/* A pass's fixed-function state as one designated-initialiser literal, so a chapter's lesson reads
 * as data: {.blend = {GL_ONE, GL_ONE}, .cull = GL_FRONT, .depth_func = GL_GREATER}. */
typedef struct gl_pass_state {
    GLenum blend[2];   /* source and destination factors (glBlendFunc); {0, 0}: no blending */
    GLenum cull;       /* the faces culled (GL_FRONT, GL_BACK); 0: none */
    GLenum depth_func; /* the depth test (GL_LEQUAL, GL_GREATER, ...); 0: no depth test */
    bool depth_write;  /* glDepthMask */
    bool depth_clamp;  /* GL_DEPTH_CLAMP: depth clamped to [0, 1] instead of clipping at near and far */
    /* The stencil test (chapter 08), against reference 0 with every bit read and written: */
    GLenum stencil_func;     /* glStencilFunc (GL_ALWAYS, GL_NOTEQUAL, ...); 0: no stencil test */
    GLenum stencil_front[3]; /* glStencilOpSeparate(GL_FRONT, sfail, dpfail, dppass); {0, 0, 0}: keep */
    GLenum stencil_back[3];  /* the same for back faces (GL_ZERO is 0: spell out all three) */
    bool stencil_only;       /* glColorMask all off: the pass writes the stencil (and depth) only */
} gl_pass_state;

void gl_pass_state_apply(const gl_pass_state *state);
void gl_pass_state_reset(void);
void gl_texture_buffer_upload(GLuint buffer, GLuint texture, GLenum format, const void *data, size_t bytes);
void gl_texture_buffer_bind(GLuint program, const char *uniform, int unit, GLuint texture);
void gl_buffer_read(GLuint buffer, size_t bytes, void *out);
void gl_read_rgba8(GLuint framebuffer, int attachment, int width, int height, unsigned char *out);
void gl_read_rgba_float(GLuint framebuffer, int attachment, int width, int height, float *out);
void gl_read_depth(GLuint framebuffer, int width, int height, float *out);
bool gl_have_compute(void);
/* What a counter does around every draw and every gl_samples_begin/end (common/gl/draw_count.h). */
typedef struct gl_draw_hooks {
    void (*draw_begin)(bool fullscreen);
    void (*draw_end)(void);
    void (*samples_begin)(GLuint query); /* after glBeginQuery */
    long (*samples_end)(void);           /* after the result: samples to add to it */
} gl_draw_hooks;

void gl_draw_hooks_set(const gl_draw_hooks *hooks);
void gl_draw_hooks_begin(bool fullscreen);
void gl_draw_hooks_end(void);
void gl_samples_begin(GLuint query, bool on);
long gl_samples_end(GLuint query, bool on);
void gl_util_shutdown(void);

#endif
