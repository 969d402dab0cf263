/* gl_util.c - see gl_util.h. */
#include "gl_util.h"

#include "log.h"

#include <stdlib.h>
#include <string.h>

static struct {
    long live_objects;
    long errors;
    GLuint fullscreen_vao;
    const gl_draw_hooks *hooks;
} state;

#define COUNTED_PAIR(kind, gen, del)                                                                         \
    GLuint gl_##kind##_create(void)                                                                          \
    {                                                                                                        \
        GLuint id = 0;                                                                                       \
        gen(1, &id);                                                                                         \
        if (id)                                                                                              \
            state.live_objects++;                                                                            \
        return id;                                                                                           \
    }                                                                                                        \
    void gl_##kind##_destroy(GLuint *id)                                                                     \
    {                                                                                                        \
        if (*id) {                                                                                           \
            del(1, id);                                                                                      \
            state.live_objects--;                                                                            \
            *id = 0;                                                                                         \
        }                                                                                                    \
    }

COUNTED_PAIR(texture, glGenTextures, glDeleteTextures)
COUNTED_PAIR(buffer, glGenBuffers, glDeleteBuffers)
COUNTED_PAIR(framebuffer, glGenFramebuffers, glDeleteFramebuffers)
COUNTED_PAIR(vertex_array, glGenVertexArrays, glDeleteVertexArrays)
COUNTED_PAIR(query, glGenQueries, glDeleteQueries)
COUNTED_PAIR(renderbuffer, glGenRenderbuffers, glDeleteRenderbuffers)

long gl_live_objects(void) { return state.live_objects; }

void gl_live_objects_add(long delta) { state.live_objects += delta; }

const char *gl_error_name(GLenum e)
{
    switch (e) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "unknown GL error";
    }
}

bool gl_check(const char *where)
{
    bool ok = true;
    for (GLenum e; (e = glGetError()) != GL_NO_ERROR;) {
        log_error("GL error %s (0x%04x) after %s", gl_error_name(e), e, where);
        state.errors++;
        ok = false;
    }
    return ok;
}

static void GLAD_API_PTR debug_callback(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                                    const GLchar *message, const void *user)
{
    (void)id;
    (void)length;
    (void)user;
    /* A shader that fails to compile is reported once, with file names, by gl_program_load. */
    if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) {
        log_debug("GL: %s", message);
        return;
    }
    if (type == GL_DEBUG_TYPE_ERROR) {
        state.errors++;
        log_error("GL error: %s", message);
    } else if (severity != GL_DEBUG_SEVERITY_NOTIFICATION) {
        log_warn("GL: %s", message);
    } else {
        log_debug("GL: %s", message);
    }
}

void gl_debug_enable(void)
{
    if (!GLAD_GL_KHR_debug) {
        log_warn("KHR_debug is missing: GL errors are checked with glGetError after each frame");
        return;
    }
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(debug_callback, NULL);
}

long gl_debug_error_count(void) { return state.errors; }

void gl_draw_fullscreen(void)
{
    if (!state.fullscreen_vao)
        state.fullscreen_vao = gl_vertex_array_create();
    glBindVertexArray(state.fullscreen_vao);
    gl_draw_hooks_begin(true);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    gl_draw_hooks_end();
}

/* glStencilOpSeparate for one face; a triple left out of the literal ({0, 0, 0}) keeps the value
 * (GL_KEEP is not 0, and GL_ZERO is: one zero among set values is GL_ZERO). */
static void stencil_ops(GLenum face, const GLenum op[3])
{
    if (!op[0] && !op[1] && !op[2])
        glStencilOpSeparate(face, GL_KEEP, GL_KEEP, GL_KEEP);
    else
        glStencilOpSeparate(face, op[0], op[1], op[2]);
}

void gl_pass_state_apply(const gl_pass_state *s)
{
    if (s->blend[0] || s->blend[1]) {
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(s->blend[0], s->blend[1]);
    } else {
        glDisable(GL_BLEND);
    }
    if (s->cull) {
        glEnable(GL_CULL_FACE);
        glCullFace(s->cull);
    } else {
        glDisable(GL_CULL_FACE);
    }
    if (s->depth_func) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(s->depth_func);
    } else {
        glDisable(GL_DEPTH_TEST);
    }
    glDepthMask(s->depth_write ? GL_TRUE : GL_FALSE);
    if (s->depth_clamp)
        glEnable(GL_DEPTH_CLAMP);
    else
        glDisable(GL_DEPTH_CLAMP);
    if (s->stencil_func) {
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(s->stencil_func, 0, 0xFF);
        stencil_ops(GL_FRONT, s->stencil_front);
        stencil_ops(GL_BACK, s->stencil_back);
    } else {
        glDisable(GL_STENCIL_TEST);
    }
    GLboolean color = s->stencil_only ? GL_FALSE : GL_TRUE;
    glColorMask(color, color, color, color);
}

void gl_pass_state_reset(void)
{
    gl_pass_state_apply(&(gl_pass_state){.depth_write = true});
    glDepthFunc(GL_LESS);
}

void gl_texture_buffer_upload(GLuint buffer, GLuint texture, GLenum format, const void *data, size_t bytes)
{
    glBindBuffer(GL_TEXTURE_BUFFER, buffer);
    glBufferData(GL_TEXTURE_BUFFER, (GLsizeiptr)bytes, data, GL_STREAM_DRAW);
    glBindTexture(GL_TEXTURE_BUFFER, texture);
    glTexBuffer(GL_TEXTURE_BUFFER, format, buffer);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

void gl_texture_buffer_bind(GLuint program, const char *uniform, int unit, GLuint texture)
{
    glActiveTexture(GL_TEXTURE0 + (GLenum)unit);
    glBindTexture(GL_TEXTURE_BUFFER, texture);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(glGetUniformLocation(program, uniform), unit);
}

void gl_buffer_read(GLuint buffer, size_t bytes, void *out)
{
    glBindBuffer(GL_COPY_READ_BUFFER, buffer);
    glGetBufferSubData(GL_COPY_READ_BUFFER, 0, (GLsizeiptr)bytes, out);
    glBindBuffer(GL_COPY_READ_BUFFER, 0);
}

/* One read-back: tight rows (GL_PACK_ALIGNMENT 1), then the read binding back to 0. */
static void read_pixels(GLuint framebuffer, GLenum buffer, int width, int height, GLenum format, GLenum type,
                        void *out)
{
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    if (buffer != GL_NONE)
        glReadBuffer(buffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, format, type, out);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

void gl_read_rgba8(GLuint framebuffer, int attachment, int width, int height, unsigned char *out)
{
    read_pixels(framebuffer, GL_COLOR_ATTACHMENT0 + (GLenum)attachment, width, height, GL_RGBA, GL_UNSIGNED_BYTE,
                out);
}

void gl_read_rgba_float(GLuint framebuffer, int attachment, int width, int height, float *out)
{
    read_pixels(framebuffer, GL_COLOR_ATTACHMENT0 + (GLenum)attachment, width, height, GL_RGBA, GL_FLOAT, out);
}

void gl_read_depth(GLuint framebuffer, int width, int height, float *out)
{
    read_pixels(framebuffer, GL_NONE, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, out); /* no read buffer */
}

void gl_samples_begin(GLuint query, bool on)
{
    if (!on)
        return;
    glBeginQuery(GL_SAMPLES_PASSED, query);
    if (state.hooks)
        state.hooks->samples_begin(query); /* a counted draw inside suspends it (draw_count.h) */
}

long gl_samples_end(GLuint query, bool on)
{
    if (!on)
        return -1;
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint samples = 0;
    glGetQueryObjectuiv(query, GL_QUERY_RESULT, &samples);
    return (long)samples + (state.hooks ? state.hooks->samples_end() : 0);
}

void gl_draw_hooks_set(const gl_draw_hooks *hooks) { state.hooks = hooks; }

void gl_draw_hooks_begin(bool fullscreen)
{
    if (state.hooks)
        state.hooks->draw_begin(fullscreen);
}

void gl_draw_hooks_end(void)
{
    if (state.hooks)
        state.hooks->draw_end();
}

void gl_util_shutdown(void) { gl_vertex_array_destroy(&state.fullscreen_vao); }

bool gl_have_compute(void)
{
    const char *hide = getenv("COURSE_NO_COMPUTE");
    return GLAD_GL_VERSION_4_3 && !(hide && *hide && strcmp(hide, "0") != 0);
}

void gl_texture_sampling(GLenum target, GLint min_filter, GLint mag_filter, GLint wrap)
{
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, min_filter);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, mag_filter);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, wrap);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, wrap);
    if (target == GL_TEXTURE_CUBE_MAP || target == GL_TEXTURE_3D)
        glTexParameteri(target, GL_TEXTURE_WRAP_R, wrap);
}
