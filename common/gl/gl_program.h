/* gl_program.h - shader programs from the files in shaders/: the GLSL `#include` expander and the
 * compile and link steps, with errors at their file and line.
 *
 *   gl_program_load(vert, frag, defines)  compile + link shaders/<vert> and shaders/<frag>;
 *                                         `#include "x.glsl"` is expanded, `defines` ("A 1\nB 2")
 *                                         become #defines; errors name the file and line
 *   gl_program_create(name, vert_text, frag_text, defines)
 *                                         the same from source text in memory (tests); `name` labels
 *                                         its messages, and #include still reads from shaders/
 *   gl_compute_program_load(comp, defines)
 *                                         the same for one compute shader, shaders/<comp> (GL 4.3:
 *                                         the caller checks gl_have_compute() first)
 *   gl_program_load_extra(vert, frag, defines, extra)
 *                                         gl_program_load with extra->defines after `defines` (extra
 *                                         may be NULL: none)
 *   gl_program_extra_bind(extra, program) extra->bind(program, extra->user), when there is one
 *   gl_program_extra_join(pair, first, second)
 *                                         both extras as one: their defines joined (first's, then
 *                                         second's), a bind that calls first's then second's; `pair`
 *                                         holds them and must outlive every draw with the programs
 *   gl_program_destroy(&program)
 *   gl_program_variant(v, vert, frag, defines, extra)
 *                                         one program of a set kept per variant: the one built with
 *                                         these defines and extra's, built on first use and found again
 *                                         by them (chapter 14's shadows on and off: each set once)
 *   gl_program_variants_destroy(v)
 *   gl_shader_dir()                       where shaders are read from: data_dir()/shaders, or
 *                                         $COURSE_SHADER_DIR
 *   gl_program_set_scene_defines(defines) defines every program compiled from now on gets after its
 *                                         own: the scene's features (common/scene/shader_features.h),
 *                                         set by the runner before a chapter builds its programs;
 *                                         NULL or "": none (a program then gets every feature)
 *   gl_program_scene_defines()            those defines
 *   gl_program_compiled(&list)            the programs linked since the last reset, in order (at most
 *                                         256 kept): name, own defines, and the program while it lives
 *                                         (0 once destroyed); --bench prints them, tests inspect them
 *   gl_program_compiled_total()           how many were linked, the ones past 256 too
 *   gl_program_compiled_reset()           forget them (the runner, when it opens a scene)
 *
 * After the #version line every program gets the `defines`, then shader_layout.h's constants as
 * #defines (SHADER_...). Each included file is its own GLSL source-string number (#line L S), so
 * the driver's messages can be put back at the file they came from (shader_log.h). Programs count
 * in gl_live_objects() (gl_util.h).
 */
#ifndef COMMON_GL_PROGRAM_H
#define COMMON_GL_PROGRAM_H

#include <glad/gl.h>

#include <stdbool.h>

/* What a later chapter adds to the programs a module builds (chapter 14's shadows in chapter 00's
 * forward renderer and chapter 11's cluster passes): defines after the module's own, and a function
 * that sets its inputs on each of those programs, called with the program in use before it draws. */
typedef struct gl_program_extra {
    const char *defines; /* "A 1\nB 2", or NULL */
    void (*bind)(GLuint program, const void *user);
    const void *user;
} gl_program_extra;

/* Two extras made one (chapter 17's occlusion and chapter 14's shadows): gl_program_extra_join's. */
typedef struct gl_program_extra_pair {
    gl_program_extra first, second;
    char defines[256];
} gl_program_extra_pair;

/* A program as gl_program_compiled lists it. */
typedef struct gl_program_info {
    GLuint program; /* 0 once destroyed */
    char name[96];  /* "forward.vert + forward.frag" */
    char defines[256]; /* its own defines, space-separated ("TRANSPARENT 1 SHADOWS 1"), the scene's not */
} gl_program_info;

/* gl_program_variant's set: up to GL_PROGRAM_VARIANTS programs of one pair of files, by their defines
 * (the oldest goes when a new one needs its place). Zero is an empty set. */
#define GL_PROGRAM_VARIANTS 4
typedef struct gl_program_variants {
    struct {
        char key[384]; /* the defines, then the extra's */
        GLuint program;
    } slot[GL_PROGRAM_VARIANTS];
    int next; /* the slot the next new variant takes when all are used */
} gl_program_variants;

GLuint gl_program_load(const char *vert, const char *frag, const char *defines);
GLuint gl_program_load_extra(const char *vert, const char *frag, const char *defines, const gl_program_extra *extra);
void gl_program_extra_bind(const gl_program_extra *extra, GLuint program);
gl_program_extra gl_program_extra_join(gl_program_extra_pair *pair, const gl_program_extra *first,
                                       const gl_program_extra *second);
GLuint gl_compute_program_load(const char *comp, const char *defines);
GLuint gl_program_create(const char *name, const char *vert_text, const char *frag_text, const char *defines);
void gl_program_destroy(GLuint *program);
GLuint gl_program_variant(gl_program_variants *v, const char *vert, const char *frag, const char *defines,
                          const gl_program_extra *extra);
void gl_program_variants_destroy(gl_program_variants *v);
const char *gl_shader_dir(void);
bool gl_program_set_scene_defines(const char *defines);
const char *gl_program_scene_defines(void);
int gl_program_compiled(const gl_program_info **list);
int gl_program_compiled_total(void);
void gl_program_compiled_reset(void);

#endif
