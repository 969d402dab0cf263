/* hard_depth.c - case 5: how well the G-buffer's depth gives back the view-space distance.
 *
 * A plane facing the camera is drawn at a known distance into a depth buffer of each kind, the depth
 * is read back, and the distance is rebuilt the way the lighting shader does it (inverse projection in
 * float) and exactly (the closed form in double, from the same stored depth). The table shows the
 * largest relative and absolute error over the plane's pixels. Formats:
 *   d24        24-bit fixed point, standard depth (-1..1 clip z, clear 1, GL_LESS)
 *   d32f       32-bit float, standard depth (what common/render/gbuffer.c uses)
 *   d32f-rev   32-bit float, reversed-Z: glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE), near -> 1,
 *              far -> 0, clear 0, GL_GREATER (only where the context has clip control)
 * Bounds asserted (why in docs/hard-cases.md, case 5):
 *   standard formats   relative error <= 4 * 2^-24 * z / n + 1e-6: the stored value 1 - n/z is kept to
 *                      a step of 2^-24 near 1 (24-bit grid, or float's spacing just below 1), and a
 *                      step in depth is a step of z^2/n in distance
 *   reversed float     relative error <= 1e-5 at every distance: the value n/z keeps float's relative
 *                      precision, whatever its size
 *   at z >= 1000       reversed float at least 100 times better than d24
 */
#include "hard_util.h"

#include "fbo.h"
#include "gl_util.h"

#include <cglm/cglm.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define SIZE 16
#define FOVY 60.0

static const char *const VERT = "#version 330 core\n"
                                "uniform mat4 u_proj;\n"
                                "uniform float u_dist;\n"
                                "void main()\n"
                                "{\n"
                                "    vec2 c = vec2(gl_VertexID & 1, gl_VertexID >> 1) * 2.0 - 1.0;\n"
                                "    gl_Position = u_proj * vec4(c * u_dist * 2.0, -u_dist, 1.0);\n"
                                "}\n";
static const char *const FRAG = "#version 330 core\n"
                                "out vec4 o_color;\n"
                                "void main() { o_color = vec4(1.0); }\n";

typedef enum depth_kind { KIND_D24, KIND_D32F, KIND_D32F_REVERSED, KIND_COUNT } depth_kind;
static const char *const KIND_NAMES[KIND_COUNT] = {"d24", "d32f", "d32f-rev"};

typedef struct result {
    double rel_float, abs_float, rel_double, abs_double;
} result;

static struct {
    GLuint program, vao;
    GLint loc_proj, loc_dist;
    bool have_clip_control;
} state;

/* OpenGL's standard projection (clip z -1..1) or the reversed one (near -> 1, far -> 0 with
 * ZERO_TO_ONE): clip z = a * z_view + b, w = -z_view, a = n / (f - n), b = n f / (f - n). */
static void make_projection(depth_kind kind, double n, double f, mat4 out)
{
    glm_perspective((float)glm_rad(FOVY), 1.0f, (float)n, (float)f, out);
    if (kind == KIND_D32F_REVERSED) {
        out[2][2] = (float)(n / (f - n));
        out[3][2] = (float)(n * f / (f - n));
    }
}

static result measure(depth_kind kind, double n, double f, double dist)
{
    GLuint tex = gl_texture_create(), framebuffer = gl_framebuffer_create();
    glBindTexture(GL_TEXTURE_2D, tex);
    GLenum internal = kind == KIND_D24 ? GL_DEPTH_COMPONENT24 : GL_DEPTH_COMPONENT32F;
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)internal, SIZE, SIZE, 0, GL_DEPTH_COMPONENT, GL_FLOAT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, tex, 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        hard_expect(false, "%s framebuffer: %s", KIND_NAMES[kind], fbo_status_name(status));

    bool reversed = kind == KIND_D32F_REVERSED;
    if (reversed)
        glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glViewport(0, 0, SIZE, SIZE);
    glClearDepth(reversed ? 0.0 : 1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(reversed ? GL_GREATER : GL_LESS);
    mat4 proj;
    make_projection(kind, n, f, proj);
    glUseProgram(state.program);
    glUniformMatrix4fv(state.loc_proj, 1, GL_FALSE, (const float *)proj);
    glUniform1f(state.loc_dist, (float)dist);
    glBindVertexArray(state.vao);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);

    float depth[SIZE * SIZE];
    gl_read_depth(framebuffer, SIZE, SIZE, depth);
    if (reversed)
        glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glDepthFunc(GL_LESS);
    glClearDepth(1.0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl_framebuffer_destroy(&framebuffer);
    gl_texture_destroy(&tex);

    mat4 inv;
    glm_mat4_inv(proj, inv);
    /* The z the plane was drawn at, as the GPU saw it (a float uniform). */
    double truth = (double)(float)dist;
    result r = {0};
    for (int i = 0; i < SIZE * SIZE; i++) {
        float d = depth[i];
        /* Like shaders/gbuffer_read.glsl: window depth -> NDC, inverse projection in float, divide. */
        float ndc_z = reversed ? d : d * 2.0f - 1.0f;
        float vz = inv[2][2] * ndc_z + inv[3][2], vw = inv[2][3] * ndc_z + inv[3][3];
        double z_float = -(double)(vz / vw);
        double z_double = reversed ? n * f / ((double)d * (f - n) + n)
                                   : 2.0 * n * f / ((f + n) - (2.0 * (double)d - 1.0) * (f - n));
        double ef = fabs(z_float - truth), ed = fabs(z_double - truth);
        if (!(ef <= r.abs_float))
            r.abs_float = ef; /* NaN or Inf keeps the error at NaN/Inf, so the bound check fails */
        if (!(ed <= r.abs_double))
            r.abs_double = ed;
    }
    r.rel_float = r.abs_float / truth;
    r.rel_double = r.abs_double / truth;
    return r;
}

static void run_range(double n, double f, const double *dists, int count, bool assert_bounds)
{
    printf("\nnear %g, far %g: largest error over a %dx%d plane facing the camera\n", n, f, SIZE, SIZE);
    printf("%-10s %8s | %12s %12s | %12s %12s\n", "format", "z", "rel (float)", "abs (float)", "rel (double)",
           "abs (double)");
    for (int k = 0; k < count; k++) {
        result res[KIND_COUNT];
        for (int kind = 0; kind < KIND_COUNT; kind++) {
            if (kind == KIND_D32F_REVERSED && !state.have_clip_control) {
                printf("%-10s %8g | skipped: no clip control in this context\n", KIND_NAMES[kind], dists[k]);
                continue;
            }
            result r = res[kind] = measure((depth_kind)kind, n, f, dists[k]);
            printf("%-10s %8g | %12.3g %12.3g | %12.3g %12.3g\n", KIND_NAMES[kind], dists[k], r.rel_float,
                   r.abs_float, r.rel_double, r.abs_double);
            if (!assert_bounds)
                continue;
            double bound = kind == KIND_D32F_REVERSED ? 1e-5 : 4.0 * ldexp(1.0, -24) * dists[k] / n + 1e-6;
            hard_expect(r.rel_float <= bound && r.rel_double <= bound, "%s z=%g: relative error %.3g <= %.3g",
                        KIND_NAMES[kind], dists[k], fmax(r.rel_float, r.rel_double), bound);
        }
        if (assert_bounds && state.have_clip_control && dists[k] >= 1000)
            hard_expect(res[KIND_D32F_REVERSED].rel_float * 100 <= res[KIND_D24].rel_float,
                        "z=%g: reversed float (%.3g) at least 100x better than d24 (%.3g)", dists[k],
                        res[KIND_D32F_REVERSED].rel_float, res[KIND_D24].rel_float);
    }
}

int main(void)
{
    hard_context_create(SIZE, SIZE);
    state.program = hard_program_create(VERT, FRAG);
    if (!hard_expect(state.program != 0, "depth program compiles"))
        return hard_finish();
    state.loc_proj = glGetUniformLocation(state.program, "u_proj");
    state.loc_dist = glGetUniformLocation(state.program, "u_dist");
    state.vao = gl_vertex_array_create();
    state.have_clip_control = GLAD_GL_ARB_clip_control && glClipControl != NULL;
    printf("GL %s, %s; clip control: %s\n", (const char *)glGetString(GL_VERSION),
           (const char *)glGetString(GL_RENDERER), state.have_clip_control ? "yes" : "no");

    static const double wide[] = {1, 10, 100, 1000, 9000};
    run_range(0.01, 10000, wide, 5, true);
    /* The range the published figures quote (docs/hard-cases.md), for comparison; reported only. */
    static const double narrow[] = {10, 99};
    run_range(0.1, 100, narrow, 2, false);

    gl_vertex_array_destroy(&state.vao);
    glDeleteProgram(state.program);
    return hard_finish();
}
