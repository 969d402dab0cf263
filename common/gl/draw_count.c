/* draw_count.c - see draw_count.h. */
#include "draw_count.h"

#include "frame_timer.h"
#include "gl_util.h"
#include "log.h"

#include <string.h>

static struct {
    draw_counts *out; /* NULL: not counting */
    GLuint query;
    GLuint outer;       /* the GL_SAMPLES_PASSED query gl_samples_begin started; 0: none */
    long outer_missed;  /* samples the outer query did not see while a draw was counted */
    bool in_draw;
} state;


/* Bits of the unmasked channels of colour attachment `buffer` of the draw framebuffer. */
static int colour_bits(GLenum buffer, const GLboolean mask[4])
{
    static const GLenum channels[4] = {GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE, GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE,
                                       GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE, GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE};
    GLint type = GL_NONE, bits = 0, sum = 0;
    glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, buffer, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    for (int c = 0; type != GL_NONE && c < 4; c++)
        if (mask[c]) {
            glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, buffer, channels[c], &bits);
            sum += bits;
        }
    return sum;
}

static int attachment_bits(GLenum attachment, GLenum size)
{
    GLint type = GL_NONE, bits = 0;
    glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type != GL_NONE)
        glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment, size, &bits);
    return bits;
}

/* What one sample that passes writes, and what blending reads back, in bits. */
static void sample_bits(int *written, int *blend_read)
{
    *written = *blend_read = 0;
    GLint framebuffer = 0, max_buffers = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    if (framebuffer == 0)
        return; /* the course draws into its own framebuffers; a window's is not counted */
    glGetIntegerv(GL_MAX_DRAW_BUFFERS, &max_buffers);
    for (int i = 0; i < max_buffers; i++) {
        GLint buffer = GL_NONE;
        glGetIntegerv(GL_DRAW_BUFFER0 + (GLenum)i, &buffer);
        if (buffer < (GLint)GL_COLOR_ATTACHMENT0 || buffer > (GLint)GL_COLOR_ATTACHMENT0 + 31)
            continue;
        GLboolean mask[4];
        glGetBooleani_v(GL_COLOR_WRITEMASK, (GLuint)i, mask);
        int bits = colour_bits((GLenum)buffer, mask);
        *written += bits;
        if (glIsEnabledi(GL_BLEND, (GLuint)i))
            *blend_read += bits;
    }
    GLboolean depth_mask = GL_FALSE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask);
    if (glIsEnabled(GL_DEPTH_TEST) && depth_mask)
        *written += attachment_bits(GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE);
    /* a sample that passed both tests takes the depth-pass operation: GL_KEEP writes nothing */
    GLint stencil_mask = 0, front = GL_KEEP, back = GL_KEEP;
    glGetIntegerv(GL_STENCIL_WRITEMASK, &stencil_mask);
    glGetIntegerv(GL_STENCIL_PASS_DEPTH_PASS, &front);
    glGetIntegerv(GL_STENCIL_BACK_PASS_DEPTH_PASS, &back);
    if (glIsEnabled(GL_STENCIL_TEST) && stencil_mask && (front != GL_KEEP || back != GL_KEEP))
        *written += attachment_bits(GL_STENCIL_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE);
}

static bool is_2d_sampler(GLenum type, bool *multisample)
{
    *multisample = type == GL_SAMPLER_2D_MULTISAMPLE || type == GL_INT_SAMPLER_2D_MULTISAMPLE ||
                   type == GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE;
    return *multisample || type == GL_SAMPLER_2D || type == GL_INT_SAMPLER_2D || type == GL_UNSIGNED_INT_SAMPLER_2D;
}

/* Bits of one texel of the texture bound at `unit`, times its samples. */
static int texel_bits(GLint unit, bool multisample)
{
    static const GLenum channels[6] = {GL_TEXTURE_RED_SIZE,  GL_TEXTURE_GREEN_SIZE, GL_TEXTURE_BLUE_SIZE,
                                       GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_DEPTH_SIZE, GL_TEXTURE_STENCIL_SIZE};
    const GLenum target = multisample ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D;
    GLint active = 0, texture = 0, bits = 0, sum = 0, samples = 1;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    glActiveTexture(GL_TEXTURE0 + (GLenum)unit);
    glGetIntegerv(multisample ? GL_TEXTURE_BINDING_2D_MULTISAMPLE : GL_TEXTURE_BINDING_2D, &texture);
    for (int c = 0; texture && c < 6; c++) {
        glGetTexLevelParameteriv(target, 0, channels[c], &bits);
        sum += bits;
    }
    if (texture && multisample)
        glGetTexLevelParameteriv(target, 0, GL_TEXTURE_SAMPLES, &samples);
    glActiveTexture((GLenum)active);
    return sum * (samples > 0 ? samples : 1);
}

/* What the current program fetches per fragment from the 2D textures it samples, in bits. */
static int fetch_bits(void)
{
    GLint program = 0, uniforms = 0, sum = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    if (!program)
        return 0;
    glGetProgramiv((GLuint)program, GL_ACTIVE_UNIFORMS, &uniforms);
    for (GLint u = 0; u < uniforms; u++) {
        char name[128];
        GLint size = 0, unit = 0;
        GLenum type = 0;
        bool multisample;
        glGetActiveUniform((GLuint)program, (GLuint)u, sizeof name, NULL, &size, &type, name);
        if (!is_2d_sampler(type, &multisample))
            continue;
        glGetUniformiv((GLuint)program, glGetUniformLocation((GLuint)program, name), &unit);
        sum += texel_bits(unit, multisample);
    }
    return sum;
}

static struct {
    int written_bits, blend_bits, fetch_bits, target_samples;
    long long every_pixel; /* > 0: the fragments that run whatever passes (draw_begin) */
} draw;

static void begin_counted_draw(void)
{
    draw.every_pixel = 0;
    state.in_draw = true;
    if (state.outer) { /* one GL_SAMPLES_PASSED query at a time: the outer one's count so far */
        glEndQuery(GL_SAMPLES_PASSED);
        GLuint samples = 0;
        glGetQueryObjectuiv(state.outer, GL_QUERY_RESULT, &samples);
        state.outer_missed += (long)samples;
    }
    sample_bits(&draw.written_bits, &draw.blend_bits);
    draw.fetch_bits = fetch_bits();
    GLint samples = 0;
    glGetIntegerv(GL_SAMPLES, &samples); /* of the draw framebuffer */
    draw.target_samples = samples > 0 ? samples : 1;
    glBeginQuery(GL_SAMPLES_PASSED, state.query);
}

static void draw_begin(bool fullscreen)
{
    if (!state.out || state.in_draw)
        return;
    begin_counted_draw();
    if (!fullscreen)
        return;
    /* Without a depth or stencil test that can reject, every pixel of the viewport runs the shader,
     * and fetches, even where it then discards (GL_SAMPLES_PASSED counts only the fragments kept). */
    GLint viewport[4] = {0}, depth_func = GL_ALWAYS, stencil_func = GL_ALWAYS, stencil_back = GL_ALWAYS;
    glGetIntegerv(GL_VIEWPORT, viewport);
    glGetIntegerv(GL_DEPTH_FUNC, &depth_func);
    glGetIntegerv(GL_STENCIL_FUNC, &stencil_func);
    glGetIntegerv(GL_STENCIL_BACK_FUNC, &stencil_back);
    const bool depth_rejects = glIsEnabled(GL_DEPTH_TEST) && depth_func != GL_ALWAYS;
    const bool stencil_rejects = glIsEnabled(GL_STENCIL_TEST) && (stencil_func != GL_ALWAYS || stencil_back != GL_ALWAYS);
    if (!depth_rejects && !stencil_rejects)
        draw.every_pixel = (long long)viewport[2] * viewport[3];
}

static draw_count_pass *current_pass(void)
{
    const char *name = frame_timer_pass();
    if (!name)
        name = "(no pass)";
    draw_counts *c = state.out;
    for (int i = 0; i < c->count; i++)
        if (strcmp(c->passes[i].name, name) == 0)
            return &c->passes[i];
    if (c->count == DRAW_COUNT_MAX_PASSES)
        return &c->passes[c->count - 1];
    c->passes[c->count].name = name;
    return &c->passes[c->count++];
}

static void draw_end(void)
{
    if (!state.out || !state.in_draw)
        return;
    state.in_draw = false;
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint samples = 0;
    glGetQueryObjectuiv(state.query, GL_QUERY_RESULT, &samples);
    draw_count_pass *p = current_pass();
    long long s = (long long)samples;
    p->draws++;
    p->samples += s;
    p->written += s * draw.written_bits / 8;
    const long long fragments = draw.every_pixel > 0 ? draw.every_pixel : s / draw.target_samples;
    p->read += (s * draw.blend_bits + fragments * draw.fetch_bits) / 8;
    if (state.outer) { /* the outer query counts this draw too, then goes on */
        state.outer_missed += (long)samples;
        glBeginQuery(GL_SAMPLES_PASSED, state.outer);
    }
}

static void outer_begin(GLuint query)
{
    state.outer = query;
    state.outer_missed = 0;
}

static long outer_end(void)
{
    long missed = state.outer_missed;
    state.outer = 0;
    state.outer_missed = 0;
    return missed;
}

static const gl_draw_hooks hooks = {draw_begin, draw_end, outer_begin, outer_end};

bool draw_count_begin(draw_counts *out)
{
    if (state.out) {
        log_error("draw_count_begin: already counting");
        return false;
    }
    memset(out, 0, sizeof *out);
    state.query = gl_query_create();
    state.out = out;
    gl_draw_hooks_set(&hooks);
    return gl_check("draw_count_begin");
}

void draw_count_end(void)
{
    gl_draw_hooks_set(NULL);
    gl_query_destroy(&state.query);
    state.out = NULL;
}
