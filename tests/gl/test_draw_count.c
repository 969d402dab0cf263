/* test_draw_count.c - the byte counter behind the benchmark's storage table (common/gl/draw_count.h)
 * counts what the GL state says, on draws whose answer is known: full-screen triangles into a
 * 32 x 16 target of RGBA16F colour (8 bytes) and 32-bit float depth (4 bytes), 512 pixels.
 *
 * Exit 0 when every check holds, 1 when one fails, 77 when no GL context can be made.
 */
#include "draw_count.h"
#include "fbo.h"
#include "frame_timer.h"
#include "gl_program.h"
#include "gl_util.h"
#include "log.h"
#include "platform.h"

#include <stdio.h>
#include <string.h>

#define W 32
#define H 16
#define PIXELS (W * H)

static int failures;

static void expect(bool ok, const char *what)
{
    printf("%s %s\n", ok ? "ok  " : "FAIL", what);
    failures += !ok;
}

static const char *const vert = "#version 330 core\n#include \"fullscreen.glsl\"\n"
                                "void main() { gl_Position = fullscreen_position(gl_VertexID); }\n";
static const char *const write_frag = "#version 330 core\nout vec4 o;\nvoid main() { o = vec4(0.25); }\n";
/* Reads one RGBA8 texel, then keeps no fragment: the fetch happens, nothing passes. */
static const char *const discard_frag = "#version 330 core\nuniform sampler2D u_tex;\nout vec4 o;\n"
                                        "void main() { o = texelFetch(u_tex, ivec2(gl_FragCoord.xy), 0);\n"
                                        "  if (o.a < 2.0) discard; }\n";

static const draw_count_pass *pass(const draw_counts *c, const char *name)
{
    for (int i = 0; i < c->count; i++)
        if (strcmp(c->passes[i].name, name) == 0)
            return &c->passes[i];
    return NULL;
}

int main(void)
{
    const platform_desc pd = {.backend = BACKEND_EGL, .width = W, .height = H, .title = "test_draw_count"};
    int rc = platform_create(&pd);
    if (rc != EXIT_CODE_OK)
        return rc == EXIT_CODE_SKIP ? 77 : 1;
    fbo target;
    const fbo_desc desc = {.color_formats = {GL_RGBA16F}, .color_count = 1, .depth_format = GL_DEPTH_COMPONENT32F,
                           .name = "counted"};
    GLuint writer = gl_program_create("write", vert, write_frag, NULL);
    GLuint reader = gl_program_create("discard", vert, discard_frag, NULL);
    GLuint texture = gl_texture_create(), query = gl_query_create();
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, W, H, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glBindTexture(GL_TEXTURE_2D, 0);
    frame_timer t;
    if (!writer || !reader || !fbo_create(&target, &desc, W, H) || !frame_timer_create(&t))
        return 1;
    glBindFramebuffer(GL_FRAMEBUFFER, target.id);
    glViewport(0, 0, W, H);

    draw_counts c;
    expect(draw_count_begin(&c), "counting starts");
    expect(!draw_count_begin(&c), "a second start while counting is refused");
    frame_timer_begin(&t);
    /* 1. colour and depth written by every sample: 8 + 4 bytes each */
    frame_timer_mark("colour and depth");
    glUseProgram(writer);
    gl_pass_state_apply(&(gl_pass_state){.depth_func = GL_ALWAYS, .depth_write = true});
    gl_draw_fullscreen();
    /* 2. inside another GL_SAMPLES_PASSED query, the red channel only (2 bytes), no depth write:
     * the outer query still sees the draw's samples */
    frame_timer_mark("red only");
    gl_pass_state_apply(&(gl_pass_state){0});
    glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE);
    gl_samples_begin(query, true);
    gl_draw_fullscreen();
    long outer = gl_samples_end(query, true);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    /* 3. additive blending: every sample reads its colour back */
    frame_timer_mark("blended");
    gl_pass_state_apply(&(gl_pass_state){.blend = {GL_ONE, GL_ONE}});
    gl_draw_fullscreen();
    /* 4. a shader that fetches one RGBA8 texel and discards: nothing passes, every pixel read */
    frame_timer_mark("discarded");
    gl_pass_state_apply(&(gl_pass_state){0});
    glUseProgram(reader);
    glBindTexture(GL_TEXTURE_2D, texture);
    glUniform1i(glGetUniformLocation(reader, "u_tex"), 0);
    gl_draw_fullscreen();
    frame_timer_end(&t);
    draw_count_end();
    gl_pass_state_reset();

    const draw_count_pass *p1 = pass(&c, "colour and depth"), *p2 = pass(&c, "red only"),
                          *p3 = pass(&c, "blended"), *p4 = pass(&c, "discarded");
    expect(c.count == 4 && p1 && p2 && p3 && p4, "four passes, named by the frame timer");
    if (p1 && p2 && p3 && p4) {
        expect(p1->draws == 1 && p1->samples == PIXELS, "a full-screen draw passes every pixel");
        expect(p1->written == 12LL * PIXELS && p1->read == 0, "RGBA16F + D32F: 12 bytes a sample, nothing read");
        expect(p2->written == 2LL * PIXELS, "one unmasked 16-bit channel, no depth write: 2 bytes a sample");
        expect(outer == PIXELS, "the suspended outer query still counts the draw's samples");
        expect(p3->written == 8LL * PIXELS && p3->read == 8LL * PIXELS, "blending reads the colour it writes");
        expect(p4->samples == 0 && p4->written == 0, "a discarding draw passes and writes nothing");
        expect(p4->read == 4LL * PIXELS, "but every pixel ran the shader and fetched its 4-byte texel");
    }
    /* 5. off again: a plain query counts alone */
    glUseProgram(writer);
    gl_samples_begin(query, true);
    gl_draw_fullscreen();
    expect(gl_samples_end(query, true) == PIXELS, "with counting off, gl_samples counts as before");
    expect(gl_check("test_draw_count"), "no GL error");

    gl_query_destroy(&query);
    gl_texture_destroy(&texture);
    gl_program_destroy(&writer);
    gl_program_destroy(&reader);
    frame_timer_destroy(&t);
    fbo_destroy(&target);
    gl_util_shutdown();
    platform_destroy();
    return failures ? 1 : 0;
}
