/* overlay.c - see overlay.h. */
#include "overlay.h"

#include "gl_program.h"
#include "gl_util.h"
#include "log.h"

#include <math.h>
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

/* The box and the glyphs as quads in o->scratch; returns their number. */
static int layout(overlay *o, char *text, float scale, int width, overlay_corner corner)
{
    float w = (float)stb_easy_font_width(text) + 2 * PAD, h = (float)stb_easy_font_height(text) + 2 * PAD;
    float x = corner == OVERLAY_TOP_RIGHT ? (float)width / scale - w : 0.0f;
    unsigned char *v = o->scratch;
    put_box(v, x, 0.0f, x + w, h);
    unsigned char white[4] = {255, 255, 255, 255};
    int quads = stb_easy_font_print(x + PAD, PAD, text, white, v + 4 * VERTEX_BYTES,
                                    (o->quad_capacity - 1) * 4 * VERTEX_BYTES);
    return 1 + quads;
}

void overlay_draw(overlay *o, GLuint fbo, int width, int height, const char *text, overlay_corner corner)
{
    char clean[TEXT_MAX];
    size_t n = 0;
    for (; text[n] && n + 1 < sizeof clean; n++) /* stb_easy_font indexes its table by c - 32 */
        clean[n] = text[n] == '\n' || (text[n] >= 32 && text[n] < 127) ? text[n] : ' ';
    clean[n] = '\0';
    /* 2x at 480 px, 4x at 960 px; smaller when the text would not fit, never below 1x */
    float box_w = (float)stb_easy_font_width(clean) + 2 * PAD, box_h = (float)stb_easy_font_height(clean) + 2 * PAD;
    float scale = fminf(roundf((float)height / 240.0f), fminf(floorf((float)width / box_w), floorf((float)height / box_h)));
    scale = fmaxf(scale, 1.0f);
    int quads = layout(o, clean, scale, width, corner);

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
