/* overlay.c - see overlay.h. */
#include "overlay.h"

#include "gl_program.h"
#include "gl_util.h"
#include "log.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* stb_easy_font is a header of static functions; the ones this file does not call would warn. */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

#define OVERLAY_QUADS 16384 /* to start with: about 40 lines of 60 characters; grows for more */
#define VERTEX_BYTES 16     /* stb_easy_font's vertex: x, y, z floats and 4 colour bytes */
#define QUAD_BYTES (4 * VERTEX_BYTES)
#define PAD 4.0f            /* font units around the text */

/* Room for `quads` quads: the scratch vertices, the GL vertex buffer and the index buffer (two
 * triangles a quad). False (logged) when out of memory; the old room is kept then. */
static bool reserve_quads(overlay *o, int quads)
{
    if (quads <= o->quad_capacity)
        return true;
    void *scratch = realloc(o->scratch, (size_t)quads * QUAD_BYTES);
    GLuint *index = malloc((size_t)quads * 6 * sizeof *index);
    if (scratch)
        o->scratch = scratch;
    if (!scratch || !index) {
        free(index);
        log_error("overlay: out of memory for %d quads of text", quads);
        return false;
    }
    for (GLuint q = 0; q < (GLuint)quads; q++) { /* quads as two triangles */
        const GLuint corner[6] = {0, 1, 2, 0, 2, 3};
        for (int k = 0; k < 6; k++)
            index[q * 6 + (GLuint)k] = q * 4 + corner[k];
    }
    glBindVertexArray(o->vao);
    glBindBuffer(GL_ARRAY_BUFFER, o->vertices);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)quads * QUAD_BYTES, NULL, GL_STREAM_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, o->indices);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)quads * 6 * (GLsizeiptr)sizeof *index, index, GL_STATIC_DRAW);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    free(index);
    o->quad_capacity = quads;
    return gl_check("overlay: room for text");
}

bool overlay_create(overlay *o)
{
    memset(o, 0, sizeof *o);
    o->program = gl_program_load("overlay.vert", "overlay.frag", "");
    if (!o->program) {
        overlay_destroy(o);
        return false;
    }
    o->vao = gl_vertex_array_create();
    o->vertices = gl_buffer_create();
    o->indices = gl_buffer_create();
    glBindVertexArray(o->vao);
    glBindBuffer(GL_ARRAY_BUFFER, o->vertices);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, VERTEX_BYTES, (void *)0);
    glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, VERTEX_BYTES, (void *)12);
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    if (!reserve_quads(o, OVERLAY_QUADS)) {
        overlay_destroy(o);
        return false;
    }
    return gl_check("overlay_create");
}

void overlay_destroy(overlay *o)
{
    gl_program_destroy(&o->program);
    gl_vertex_array_destroy(&o->vao);
    gl_buffer_destroy(&o->vertices);
    gl_buffer_destroy(&o->indices);
    free(o->scratch);
    o->scratch = NULL;
    o->quad_capacity = 0;
}

/* One quad of stb_easy_font's layout, for the box behind the text. */
static void put_box(unsigned char *v, float x0, float y0, float x1, float y1)
{
    const float xy[4][2] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    const unsigned char shade[4] = {0, 0, 0, 170};
    for (int k = 0; k < 4; k++) {
        const float p[3] = {xy[k][0], xy[k][1], 0.0f};
        memcpy(v + k * VERTEX_BYTES, p, sizeof p);
        memcpy(v + k * VERTEX_BYTES + 12, shade, 4);
    }
}

/* The box and the glyphs as quads in o->scratch, the box's top-left corner at (x, y) font units;
 * returns their number, 0 when there is no room for them all (logged). stb_easy_font stops at a full
 * buffer without saying so: the room grows until a segment more would still have fitted. */
static int layout_at(overlay *o, char *text, float x, float y)
{
    float w = (float)stb_easy_font_width(text) + 2 * PAD, h = (float)stb_easy_font_height(text) + 2 * PAD;
    unsigned char white[4] = {255, 255, 255, 255};
    for (;;) {
        unsigned char *v = o->scratch;
        put_box(v, x, y, x + w, y + h);
        int room = (o->quad_capacity - 1) * QUAD_BYTES;
        int quads = stb_easy_font_print(x + PAD, y + PAD, text, white, v + QUAD_BYTES, room);
        if (quads * QUAD_BYTES + QUAD_BYTES <= room)
            return 1 + quads;
        if (!reserve_quads(o, 2 * o->quad_capacity))
            return 0;
    }
}

static int layout(overlay *o, char *text, float scale, int width, overlay_corner corner)
{
    float w = (float)stb_easy_font_width(text) + 2 * PAD;
    return layout_at(o, text, corner == OVERLAY_TOP_RIGHT ? (float)width / scale - w : 0.0f, 0.0f);
}

/* The quads in o->scratch over framebuffer fbo. */
static void draw_quads(overlay *o, GLuint fbo, int width, int height, float scale, int quads)
{
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, width, height);
    gl_pass_state_apply(&(gl_pass_state){.blend = {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA}});
    glUseProgram(o->program);
    glUniform2f(glGetUniformLocation(o->program, "u_viewport"), (float)width, (float)height);
    glUniform1f(glGetUniformLocation(o->program, "u_scale"), scale);
    glBindVertexArray(o->vao);
    glBindBuffer(GL_ARRAY_BUFFER, o->vertices);
    glBufferSubData(GL_ARRAY_BUFFER, 0, (GLsizeiptr)quads * QUAD_BYTES, o->scratch);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glDrawElements(GL_TRIANGLES, quads * 6, GL_UNSIGNED_INT, NULL);
    glBindVertexArray(0);
    glUseProgram(0);
    gl_pass_state_reset();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

/* Text scale: 2x at 480 px on a 1x screen, times the screen's content scale; never so large that
 * OVERLAY_MIN_COLUMNS characters would not fit in the width, never below 1x. */
static float text_scale(int width, int height, float content_scale)
{
    float column = (float)stb_easy_font_width("M");
    float scale = roundf((float)height / 240.0f * fmaxf(content_scale, 1.0f));
    while (scale > 1.0f && (float)width / scale < OVERLAY_MIN_COLUMNS * column + 2 * PAD)
        scale -= 1.0f;
    return fmaxf(scale, 1.0f);
}

/* The width of one character in font units: what stb_easy_font_width adds for it. */
static float char_width(char c)
{
    char one[2] = {c, '\0'};
    return (float)stb_easy_font_width(one);
}

/* Writes line[0..n) to out, wrapped to max_width font units at spaces (continuations indented two
 * spaces; a word wider than the line is cut); returns the lines written. */
static int wrap_line(const char *line, size_t n, float max_width, FILE *out)
{
    int lines = 0;
    bool first = true;
    while (n > 0 || first) {
        const char *indent = first ? "" : "  ";
        float used = first ? 0.0f : 2.0f * char_width(' ');
        size_t fit = 0, cut = n;
        while (fit < n && used + char_width(line[fit]) <= max_width) /* the longest start that fits */
            used += char_width(line[fit++]);
        if (fit < n) { /* break at the last space that fits, else where it stops fitting */
            cut = fit;
            while (cut > 0 && line[cut] != ' ')
                cut--;
            cut = cut > 0 ? cut : (fit > 0 ? fit : 1);
        }
        fprintf(out, "%s%.*s\n", indent, (int)cut, line);
        lines++, first = false;
        while (cut < n && line[cut] == ' ')
            cut++;
        line += cut, n -= cut;
    }
    return lines;
}

/* text wrapped to the width and cut at the height (in font units), *cut the lines left out (0: none):
 * a string to free, NULL when out of memory (logged). Every buffer is as long as the text needs
 * (open_memstream). */
static char *fit_text(const char *text, float max_width, float max_height, int *cut)
{
    *cut = 0;
    char *wrapped = NULL, *fitted = NULL;
    size_t used = 0, fitted_size = 0;
    FILE *f = open_memstream(&wrapped, &used);
    if (!f) {
        log_error("overlay: out of memory for the text");
        return NULL;
    }
    for (const char *p = text; *p;) {
        size_t n = strcspn(p, "\n");
        wrap_line(p, n, max_width, f);
        p += n + (p[n] == '\n');
    }
    if (fclose(f) != 0 || !wrapped) {
        log_error("overlay: out of memory for the text");
        free(wrapped);
        return NULL;
    }
    if (used > 0 && wrapped[used - 1] == '\n')
        wrapped[--used] = '\0';
    /* keep the lines that fit in the height; the last kept says how many were cut */
    float line_h = (float)stb_easy_font_height("M\nM") - (float)stb_easy_font_height("M");
    int max_lines = (int)((max_height - 2 * PAD) / line_h), total = 1;
    for (const char *p = wrapped; *p; p++)
        total += *p == '\n';
    if (total <= max_lines || max_lines < 2)
        return wrapped;
    const char *p = wrapped;
    for (int k = 0; k < max_lines - 1; k++)
        p = strchr(p, '\n') + 1;
    *cut = total - max_lines + 1;
    f = open_memstream(&fitted, &fitted_size);
    if (f) {
        fprintf(f, "%.*s(%d more lines: enlarge the window)", (int)(p - wrapped), wrapped, total - max_lines + 1);
        if (fclose(f) != 0)
            free(fitted), fitted = NULL;
    }
    if (!fitted)
        log_error("overlay: out of memory for the text");
    free(wrapped);
    return fitted;
}

void overlay_draw(overlay *o, GLuint fbo, int width, int height, const char *text, overlay_corner corner,
                  float content_scale)
{
    size_t n = strlen(text);
    char *clean = malloc(n + 1);
    if (!clean) {
        log_error("overlay: out of memory for %zu characters", n);
        return;
    }
    for (size_t i = 0; i < n; i++) /* stb_easy_font indexes its table by c - 32 */
        clean[i] = text[i] == '\n' || (text[i] >= 32 && text[i] < 127) ? text[i] : ' ';
    clean[n] = '\0';
    float scale = text_scale(width, height, content_scale);
    int cut = 0;
    char *fitted = fit_text(clean, (float)width / scale - 2 * PAD, (float)height / scale, &cut);
    while (fitted && cut > 0 && scale > 1.0f) { /* smaller letters before fewer lines (F1's long lists) */
        free(fitted);
        scale -= 1.0f;
        fitted = fit_text(clean, (float)width / scale - 2 * PAD, (float)height / scale, &cut);
    }
    if (cut > 0 && cut != o->lines_cut) /* the picture says so too, in its last line */
        log_warn("overlay: %d line(s) do not fit in %dx%d even at the smallest letters: enlarge the window", cut,
                 width, height);
    o->lines_cut = cut;
    int quads = fitted ? layout(o, fitted, scale, width, corner) : 0;
    if (quads > 0)
        draw_quads(o, fbo, width, height, scale, quads);
    free(fitted);
    free(clean);
}

void overlay_draw_label(overlay *o, GLuint fbo, int width, int height, const char *text, float x, float y,
                        float content_scale)
{
    size_t n = strlen(text);
    char *label = malloc(n + 1); /* stb_easy_font takes a char *; any length */
    if (!label) {
        log_error("overlay: out of memory for a label of %zu characters", n);
        return;
    }
    memcpy(label, text, n + 1);
    float scale = text_scale(width, height, content_scale);
    float w = (float)stb_easy_font_width(label) + 2 * PAD, h = (float)stb_easy_font_height(label) + 2 * PAD;
    float fx = fminf(fmaxf(x / scale, 0.0f), fmaxf((float)width / scale - w, 0.0f));
    float fy = fminf(fmaxf(y / scale, 0.0f), fmaxf((float)height / scale - h, 0.0f));
    int quads = layout_at(o, label, fx, fy);
    if (quads > 0)
        draw_quads(o, fbo, width, height, scale, quads);
    free(label);
}
