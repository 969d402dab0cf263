/* gl_util.h - small OpenGL helpers every module uses.
 *
 *   gl_program_load(vert, frag, defines)  compile + link shaders/<vert> and shaders/<frag>;
 *                                         `#include "x.glsl"` is expanded, `defines` ("A 1\nB 2")
 *                                         become #defines; errors name the file and line
 *   gl_program_create(name, vert_text, frag_text, defines)
 *                                         the same from source text in memory (tests); `name` labels
 *                                         its messages, and #include still reads from shaders/
 *   gl_program_destroy(&program)
 *   gl_texture_create / gl_buffer_create / gl_framebuffer_create / gl_vertex_array_create / gl_query_create
 *   gl_texture_destroy / gl_buffer_destroy / gl_framebuffer_destroy / gl_vertex_array_destroy / ..._destroy
 *                                         create/delete pairs that count live objects
 *   gl_live_objects()                     objects created and not yet destroyed (leak checks)
 *   gl_check(where)                       glGetError loop; logs and returns false on error
 *   gl_debug_enable()                     KHR_debug messages to the log; errors are remembered
 *   gl_debug_error_count()                GL errors seen since gl_debug_enable (or by gl_check)
 *   gl_shader_dir()                       where shaders are read from ($COURSE_SHADER_DIR overrides)
 *   gl_draw_fullscreen()                  one triangle covering the viewport (gl_VertexID based)
 */
#ifndef COMMON_GL_UTIL_H
#define COMMON_GL_UTIL_H

#include <glad/gl.h>
#include <stdbool.h>

GLuint gl_program_load(const char *vert, const char *frag, const char *defines);
GLuint gl_program_create(const char *name, const char *vert_text, const char *frag_text, const char *defines);
void gl_program_destroy(GLuint *program);

GLuint gl_texture_create(void);
GLuint gl_buffer_create(void);
GLuint gl_framebuffer_create(void);
GLuint gl_vertex_array_create(void);
GLuint gl_query_create(void);
void gl_texture_destroy(GLuint *id);
void gl_buffer_destroy(GLuint *id);
void gl_framebuffer_destroy(GLuint *id);
void gl_vertex_array_destroy(GLuint *id);
void gl_query_destroy(GLuint *id);
long gl_live_objects(void);

bool gl_check(const char *where);
void gl_debug_enable(void);
long gl_debug_error_count(void);

const char *gl_shader_dir(void);
void gl_draw_fullscreen(void);
void gl_util_shutdown(void);

#endif
