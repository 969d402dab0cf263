/* gl_program.c - see gl_program.h. */
#include "gl_program.h"

#include "data_dir.h"
#include "gl_util.h"
#include "log.h"
#include "shader_layout.h"
#include "shader_log.h"

#include <assert.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_SOURCES 32

/* The scene's feature defines (gl_program_set_scene_defines), added to every program. */
static char scene_defines[512];

/* The programs compiled since the context was made: what each was built from (gl_program_compiled). */
#define MAX_COMPILED 256
static gl_program_info compiled_list[MAX_COMPILED];
static int compiled_count, compiled_total;

const char *gl_shader_dir(void)
{
    static char dir[4200];
    const char *env = getenv("COURSE_SHADER_DIR");
    if (env && *env)
        return env;
    if (!data_dir_path("shaders", dir, sizeof dir))
        return "shaders";
    return dir;
}

/* ---- sources with #include ------------------------------------------------------------- */

typedef struct source_text {
    char *text;
    size_t len, cap;
    char names[MAX_SOURCES][128]; /* GLSL source-string number -> file name, for error logs */
    int count;
} source_text;

static bool text_append(source_text *s, const char *str, size_t n)
{
    if (s->len + n + 1 > s->cap) {
        size_t cap = s->cap ? s->cap * 2 : 4096;
        while (cap < s->len + n + 1)
            cap *= 2;
        char *t = realloc(s->text, cap);
        if (!t) {
            log_error("out of memory reading shaders");
            return false;
        }
        s->text = t;
        s->cap = cap;
    }
    memcpy(s->text + s->len, str, n);
    s->len += n;
    s->text[s->len] = '\0';
    return true;
}

static bool text_printf(source_text *s, const char *fmt, int a, int b)
{
    char buf[64];
    int n = snprintf(buf, sizeof buf, fmt, a, b);
    return text_append(s, buf, (size_t)n);
}

static char *read_file(const char *path)
{
    const char *why; /* the caller says "cannot read shader"; a named pipe is refused, not waited on */
    FILE *f = data_dir_open_input(path, &why);
    if (!f)
        return NULL;
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

static bool append_source(source_text *s, const char *label, const char *text, const char *defines, int depth);

/* Appends shaders/<name> to s; the top-level file keeps its #version line first, then the defines. */
static bool append_file(source_text *s, const char *name, const char *defines, int depth)
{
    if (depth > 6 || s->count >= MAX_SOURCES) {
        log_error("shaders/%s: includes nested too deeply", name);
        return false;
    }
    char path[4400];
    snprintf(path, sizeof path, "%s/%s", gl_shader_dir(), name);
    char *text = read_file(path);
    if (!text) {
        log_error("%s: cannot read shader", path);
        return false;
    }
    char label[160];
    snprintf(label, sizeof label, "shaders/%s", name);
    bool ok = append_source(s, label, text, defines, depth);
    free(text);
    return ok;
}

/* shader_layout.h's constants as #defines: the shaders read the numbers the C code writes. */
static bool append_layout(source_text *s)
{
    bool ok = true;
    char line[96];
#define APPEND_DEFINE(name, value)                                                                          \
    snprintf(line, sizeof line, "#define SHADER_%s %d\n", #name, value);                                   \
    ok = ok && text_append(s, line, strlen(line));
    SHADER_LAYOUT(APPEND_DEFINE)
#undef APPEND_DEFINE
    return ok;
}

/* "A 1\nB 2" as #define lines. */
static bool append_defines(source_text *s, const char *defines)
{
    bool ok = true;
    for (const char *d = defines; ok && d && *d;) {
        const char *e = strchr(d, '\n');
        size_t dn = e ? (size_t)(e - d) : strlen(d);
        ok = text_append(s, "#define ", 8) && text_append(s, d, dn) && text_append(s, "\n", 1);
        d = e ? e + 1 : d + dn;
    }
    return ok;
}

/* Appends `text` (named `label` in error messages), expanding its #include lines; the top-level
 * source keeps its #version line first, then the defines and shader_layout.h's constants. */
static bool append_source(source_text *s, const char *label, const char *text, const char *defines, int depth)
{
    if (depth > 4 || s->count >= MAX_SOURCES) {
        log_error("%s: includes nested too deeply", label);
        return false;
    }
    int id = s->count++;
    snprintf(s->names[id], sizeof s->names[id], "%s", label);
    bool ok = depth == 0 || text_printf(s, "#line %d %d\n", 1, id);
    int line_no = 0;
    for (const char *line = text; ok && *line;) {
        const char *end = strchr(line, '\n');
        size_t n = end ? (size_t)(end - line) + 1 : strlen(line);
        line_no++;
        char inc[128];
        if (sscanf(line, " #include \"%127[^\"]\"", inc) == 1) {
            ok = append_file(s, inc, NULL, depth + 1) && text_printf(s, "#line %d %d\n", line_no + 1, id);
        } else {
            ok = text_append(s, line, n);
            if (ok && !end)
                ok = text_append(s, "\n", 1);
            if (ok && depth == 0 && line_no == 1) {
                if (strncmp(line, "#version", 8) != 0) {
                    log_error("%s:1: the first line must be #version", s->names[id]);
                    ok = false;
                } else {
                    ok = append_defines(s, defines) && append_defines(s, scene_defines) && append_layout(s) &&
                         text_printf(s, "#line %d %d\n", 2, id);
                }
            }
        }
        line = end ? end + 1 : line + n;
    }
    return ok;
}

/* Each message at its file and line: "shaders/file.glsl:L[:C]: error: ..." (shader_log.h knows the
 * drivers' formats). */
static void log_info_log(const source_text *s, const char *what, const char *log)
{
    log_error("%s failed:", what);
    for (const char *line = log; *line;) {
        const char *end = strchr(line, '\n');
        int n = end ? (int)(end - line) : (int)strlen(line);
        shader_log_line p;
        if (shader_log_parse(line, n, &p) && p.source < s->count) {
            char place[160];
            int k = snprintf(place, sizeof place, "%s:%d", s->names[p.source], p.line);
            if (p.column > 0 && k > 0 && k < (int)sizeof place)
                snprintf(place + k, sizeof place - (size_t)k, ":%d", p.column);
            log_error("%s: %s%s%.*s", place, p.severity, *p.severity ? ": " : "", p.message_len, p.message);
        } else if (n > 0) {
            log_error("%.*s", n, line);
        }
        line = end ? end + 1 : line + n;
    }
}

/* One stage from shaders/<name>, or from `text` (called `name` in messages) when text is given. */
static GLuint compile(GLenum type, const char *name, const char *text, const char *defines)
{
    source_text s = {0};
    bool ok = text ? append_source(&s, name, text, defines, 0) : append_file(&s, name, defines, 0);
    if (!ok) {
        free(s.text);
        return 0;
    }
    GLuint sh = glCreateShader(type);
    const char *src = s.text;
    glShaderSource(sh, 1, &src, NULL);
    glCompileShader(sh);
    GLint status = 0;
    glGetShaderiv(sh, GL_COMPILE_STATUS, &status);
    if (!status) {
        char log[8192];
        glGetShaderInfoLog(sh, sizeof log, NULL, log);
        char what[192];
        snprintf(what, sizeof what, "compiling %s%s", text ? "" : "shaders/", name);
        log_info_log(&s, what, log);
        glDeleteShader(sh);
        sh = 0;
    }
    free(s.text);
    return sh;
}

/* A program linked: what it was built from, for gl_program_compiled. */
static void note_compiled(GLuint program, const char *what, const char *defines)
{
    compiled_total++;
    if (compiled_count == MAX_COMPILED)
        return;
    gl_program_info *c = &compiled_list[compiled_count++];
    c->program = program;
    snprintf(c->name, sizeof c->name, "%s", what);
    snprintf(c->defines, sizeof c->defines, "%s", defines ? defines : "");
    for (char *d = c->defines; *d; d++)
        *d = *d == '\n' ? ' ' : *d;
}

/* The stages (0 where one failed to compile: nothing is linked) into one program; `what` names it,
 * `defines` are the program's own (the scene's are noted once, gl_program_scene_defines). */
static GLuint link(const GLuint *stages, int count, const char *what, const char *defines)
{
    bool compiled = true;
    for (int i = 0; i < count; i++)
        compiled = compiled && stages[i];
    GLuint p = compiled ? glCreateProgram() : 0;
    for (int i = 0; i < count; i++) {
        if (p)
            glAttachShader(p, stages[i]);
        glDeleteShader(stages[i]);
    }
    if (!p)
        return 0;
    glLinkProgram(p);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096];
        glGetProgramInfoLog(p, sizeof log, NULL, log);
        log_error("linking %s failed: %s", what, log);
        glDeleteProgram(p);
        return 0;
    }
    gl_live_objects_add(1);
    note_compiled(p, what, defines);
    /* The material images' samplers (shaders/material_maps.glsl) on their own units from the start: a
     * pass that binds no images must not leave them on unit 0, where another sampler type is
     * (two types on one unit make every draw GL_INVALID_OPERATION). */
    GLint srgb = glGetUniformLocation(p, "u_maps_srgb"), linear = glGetUniformLocation(p, "u_maps_linear");
    if (srgb >= 0 || linear >= 0) {
        GLint current = 0;
        glGetIntegerv(GL_CURRENT_PROGRAM, &current);
        glUseProgram(p);
        glUniform1i(srgb, SHADER_UNIT_MAPS_SRGB);
        glUniform1i(linear, SHADER_UNIT_MAPS_LINEAR);
        /* the program in use before, unless it was deleted while in use and went when p replaced it */
        glUseProgram(current && glIsProgram((GLuint)current) ? (GLuint)current : 0);
    }
    return p;
}

/* "a + b", for link's messages. */
static const char *pair_name(const char *a, const char *b, char *out, size_t size)
{
    snprintf(out, size, "%s + %s", a, b);
    return out;
}

GLuint gl_program_load(const char *vert, const char *frag, const char *defines)
{
    GLuint vs = compile(GL_VERTEX_SHADER, vert, NULL, defines);
    const GLuint stages[2] = {vs, vs ? compile(GL_FRAGMENT_SHADER, frag, NULL, defines) : 0};
    char what[400];
    return link(stages, 2, pair_name(vert, frag, what, sizeof what), defines);
}

GLuint gl_program_load_extra(const char *vert, const char *frag, const char *defines, const gl_program_extra *extra)
{
    if (!extra || !extra->defines)
        return gl_program_load(vert, frag, defines);
    if (!defines)
        return gl_program_load(vert, frag, extra->defines);
    char all[1024];
    if (snprintf(all, sizeof all, "%s\n%s", defines ? defines : "", extra->defines) >= (int)sizeof all) {
        log_error("%s + %s: defines longer than %zu bytes", vert, frag, sizeof all - 1);
        return 0;
    }
    return gl_program_load(vert, frag, all);
}

void gl_program_extra_bind(const gl_program_extra *extra, GLuint program)
{
    if (extra && extra->bind)
        extra->bind(program, extra->user);
}

static void bind_pair(GLuint program, const void *user)
{
    const gl_program_extra_pair *pair = user;
    gl_program_extra_bind(&pair->first, program);
    gl_program_extra_bind(&pair->second, program);
}

gl_program_extra gl_program_extra_join(gl_program_extra_pair *pair, const gl_program_extra *first,
                                       const gl_program_extra *second)
{
    pair->first = *first, pair->second = *second;
    const char *a = first->defines, *b = second->defines;
    int n = snprintf(pair->defines, sizeof pair->defines, "%s%s%s", a ? a : "", a && b ? "\n" : "", b ? b : "");
    assert(n < (int)sizeof pair->defines); /* the chapters' own short literals */
    (void)n;
    return (gl_program_extra){.defines = a || b ? pair->defines : NULL, .bind = bind_pair, .user = pair};
}

GLuint gl_compute_program_load(const char *comp, const char *defines)
{
    const GLuint stage = compile(GL_COMPUTE_SHADER, comp, NULL, defines);
    return link(&stage, 1, comp, defines);
}

GLuint gl_program_create(const char *name, const char *vert_text, const char *frag_text, const char *defines)
{
    char vname[160], fname[160];
    snprintf(vname, sizeof vname, "%s (vertex)", name);
    snprintf(fname, sizeof fname, "%s (fragment)", name);
    GLuint vs = compile(GL_VERTEX_SHADER, vname, vert_text, defines);
    const GLuint stages[2] = {vs, vs ? compile(GL_FRAGMENT_SHADER, fname, frag_text, defines) : 0};
    char what[400];
    return link(stages, 2, pair_name(vname, fname, what, sizeof what), defines);
}

void gl_program_destroy(GLuint *program)
{
    if (*program) {
        for (int i = 0; i < compiled_count; i++)
            if (compiled_list[i].program == *program)
                compiled_list[i].program = 0;
        glDeleteProgram(*program);
        gl_live_objects_add(-1);
        *program = 0;
    }
}

GLuint gl_program_variant(gl_program_variants *v, const char *vert, const char *frag, const char *defines,
                          const gl_program_extra *extra)
{
    char key[sizeof v->slot[0].key];
    const char *more = extra && extra->defines ? extra->defines : "";
    if (snprintf(key, sizeof key, "%s|%s", defines ? defines : "", more) >= (int)sizeof key) {
        log_error("%s + %s: defines longer than %zu bytes", vert, frag, sizeof key - 1);
        return 0;
    }
    for (int i = 0; i < GL_PROGRAM_VARIANTS; i++)
        if (v->slot[i].program && strcmp(v->slot[i].key, key) == 0)
            return v->slot[i].program;
    int at = 0;
    while (at < GL_PROGRAM_VARIANTS && v->slot[at].program)
        at++;
    if (at == GL_PROGRAM_VARIANTS) {
        at = v->next;
        v->next = (v->next + 1) % GL_PROGRAM_VARIANTS;
        gl_program_destroy(&v->slot[at].program);
    }
    v->slot[at].program = gl_program_load_extra(vert, frag, defines, extra);
    memcpy(v->slot[at].key, key, sizeof key);
    return v->slot[at].program;
}

void gl_program_variants_destroy(gl_program_variants *v)
{
    for (int i = 0; i < GL_PROGRAM_VARIANTS; i++)
        gl_program_destroy(&v->slot[i].program);
    memset(v, 0, sizeof *v);
}

bool gl_program_set_scene_defines(const char *defines)
{
    int n = snprintf(scene_defines, sizeof scene_defines, "%s", defines ? defines : "");
    if (n < (int)sizeof scene_defines)
        return true;
    log_error("the scene's shader defines are longer than %zu bytes", sizeof scene_defines - 1);
    scene_defines[0] = '\0';
    return false;
}

const char *gl_program_scene_defines(void)
{
    return scene_defines;
}

int gl_program_compiled(const gl_program_info **list)
{
    if (list)
        *list = compiled_list;
    return compiled_count;
}

int gl_program_compiled_total(void)
{
    return compiled_total;
}

void gl_program_compiled_reset(void)
{
    compiled_count = compiled_total = 0;
}
