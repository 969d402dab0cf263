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

#define OVERLAY_QUADS 16384 /* about 40 lines of 60 characters */
#define VERTEX_BYTES 16     /* stb_easy_font's vertex: x, y, z floats and 4 colour bytes */
#define TEXT_MAX 4096
#define PAD 4.0f            /* font units around the text */

bool overlay_create(overlay *o)
{
    memset(o, 0, sizeof *o);
    o->quad_capacity = OVERLAY_QUADS;
    o->scratch = malloc((size_t)o->quad_capacity * 4 * VERTEX_BYTES);
    GLuint *index = malloc((size_t)o->quad_capacity * 6 * sizeof *index);
    o->program = gl_program_load("overlay.vert", "overlay.frag", "");
    if (!o->scratch || !index || !o->program) {
        free(index);
        overlay_destroy(o);
        return false;
    }
    for (GLuint q = 0; q < (GLuint)o->quad_capacity; q++) { /* quads as two triangles */
        const GLuint corner[6] = {0, 1, 2, 0, 2, 3};
        for (int k = 0; k < 6; k++)
            index[q * 6 + (GLuint)k] = q * 4 + corner[k];
    }
    o->vao = gl_vertex_array_create();
    o->vertices = gl_buffer_create();
    o->indices = gl_buffer_create();
    glBindVertexArray(o->vao);
    glBindBuffer(GL_ARRAY_BUFFER, o->vertices);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)o->quad_capacity * 4 * VERTEX_BYTES, NULL, GL_STREAM_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, o->indices);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)o->quad_capacity * 6 * (GLsizeiptr)sizeof *index, index, GL_STATIC_DRAW);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, VERTEX_BYTES, (void *)0);
    glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, VERTEX_BYTES, (void *)12);
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    free(index);
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
 * returns their number. */
static int layout_at(overlay *o, char *text, float x, float y)
{
    float w = (float)stb_easy_font_width(text) + 2 * PAD, h = (float)stb_easy_font_height(text) + 2 * PAD;
    unsigned char *v = o->scratch;
    put_box(v, x, y, x + w, y + h);
    unsigned char white[4] = {255, 255, 255, 255};
    int quads = stb_easy_font_print(x + PAD, y + PAD, text, white, v + 4 * VERTEX_BYTES,
                                    (o->quad_capacity - 1) * 4 * VERTEX_BYTES);
    return 1 + quads;
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
    glBufferSubData(GL_ARRAY_BUFFER, 0, (GLsizeiptr)quads * 4 * VERTEX_BYTES, o->scratch);
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

/* The width of text[0..n) in font units. */
static float span_width(const char *text, size_t n)
{
    char line[TEXT_MAX];
    n = n < sizeof line - 1 ? n : sizeof line - 1;
    memcpy(line, text, n);
    line[n] = '\0';
    return (float)stb_easy_font_width(line);
}

/* Appends line[0..n) to out, wrapped to max_width font units at spaces (continuations indented two
 * spaces; a word wider than the line is cut); returns the lines written. */
static int wrap_line(const char *line, size_t n, float max_width, char *out, size_t size, size_t *used)
{
    int lines = 0;
    bool first = true;
    while (n > 0 || first) {
        const char *indent = first ? "" : "  ";
        size_t fit = n, cut = n;
        while (fit > 0 && span_width(line, fit) + span_width(indent, strlen(indent)) > max_width)
            fit--;
        if (fit < n) { /* break at the last space that fits, else where it stops fitting */
            cut = fit;
            while (cut > 0 && line[cut] != ' ')
                cut--;
            cut = cut > 0 ? cut : (fit > 0 ? fit : 1);
        }
        int k = snprintf(out + *used, size - *used, "%s%.*s\n", indent, (int)cut, line);
        *used = k < 0 || (size_t)k >= size - *used ? size - 1 : *used + (size_t)k;
        lines++, first = false;
        while (cut < n && line[cut] == ' ')
            cut++;
        line += cut, n -= cut;
    }
    return lines;
}

/* text wrapped to the width and cut at the height (in font units), into out. */
static void fit_text(const char *text, float max_width, float max_height, char *out, size_t size)
{
    char wrapped[TEXT_MAX];
    size_t used = 0;
    wrapped[0] = '\0';
    for (const char *p = text; *p;) {
        size_t n = strcspn(p, "\n");
        wrap_line(p, n, max_width, wrapped, sizeof wrapped, &used);
        p += n + (p[n] == '\n');
    }
    if (used > 0 && wrapped[used - 1] == '\n')
        wrapped[--used] = '\0';
    /* keep the lines that fit in the height; the last kept says how many were cut */
    float line_h = (float)stb_easy_font_height("M\nM") - (float)stb_easy_font_height("M");
    int max_lines = (int)((max_height - 2 * PAD) / line_h), total = 1;
    for (const char *p = wrapped; *p; p++)
        total += *p == '\n';
    if (total <= max_lines || max_lines < 2) {
        snprintf(out, size, "%s", wrapped);
        return;
    }
    const char *p = wrapped;
    for (int k = 0; k < max_lines - 1; k++)
        p = strchr(p, '\n') + 1;
    snprintf(out, size, "%.*s(%d more lines: enlarge the window)", (int)(p - wrapped), wrapped, total - max_lines + 1);
}

void overlay_draw(overlay *o, GLuint fbo, int width, int height, const char *text, overlay_corner corner,
                  float content_scale)
{
    char clean[TEXT_MAX];
    size_t n = 0;
    for (; text[n] && n + 1 < sizeof clean; n++) /* stb_easy_font indexes its table by c - 32 */
        clean[n] = text[n] == '\n' || (text[n] >= 32 && text[n] < 127) ? text[n] : ' ';
    clean[n] = '\0';
    float scale = text_scale(width, height, content_scale);
    char fitted[TEXT_MAX];
    fit_text(clean, (float)width / scale - 2 * PAD, (float)height / scale, fitted, sizeof fitted);
    draw_quads(o, fbo, width, height, scale, layout(o, fitted, scale, width, corner));
}

void overlay_draw_label(overlay *o, GLuint fbo, int width, int height, const char *text, float x, float y,
                        float content_scale)
{
    char label[128];
    snprintf(label, sizeof label, "%s", text);
    float scale = text_scale(width, height, content_scale);
    float w = (float)stb_easy_font_width(label) + 2 * PAD, h = (float)stb_easy_font_height(label) + 2 * PAD;
    float fx = fminf(fmaxf(x / scale, 0.0f), fmaxf((float)width / scale - w, 0.0f));
    float fy = fminf(fmaxf(y / scale, 0.0f), fmaxf((float)height / scale - h, 0.0f));
    draw_quads(o, fbo, width, height, scale, layout_at(o, label, fx, fy));
}
