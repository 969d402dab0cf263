/* test_ibl_reference.c - chapter 19's probes against exact references, in double precision on the
 * CPU, from what the GPU made (read back): the probe's captured cube map, its prefiltered chain,
 * its spherical harmonics and the split-sum table.
 *
 *   1. specular: for 12 normals x 4 view angles per roughness, the Monte Carlo integral of the cube
 *      map against the full GGX BRDF (D, Smith-Schlick G with k = alpha / 2, Schlick F with F0 0.5;
 *      65,536 importance-sampled half vectors) against the split sum, prefiltered(r) (F0 A + B):
 *      the split sum's error by roughness (relative, in luminance), printed and bounded. The
 *      integral is tools/reference/split_sum_reference.c, which the benchmark measures with too
 *   2. irradiance: for the same normals, the brute-force cosine integral over every texel of the
 *      cube, E(n) / pi, against the 9 coefficients' value
 *   3. hard cases: roughness 0 (level 0 of the prefiltered chain is the capture itself); a seam (the
 *      coarsest level sampled just either side of a face edge: close with seamless cube maps, apart
 *      without); a probe inside an object (ibl_inside.scene: the same harmonics as without it)
 *
 * usage: test_ibl_reference SCENE INSIDE_SCENE MAX_MEAN_0 MAX_MEAN_1 ... (one bound per level)
 */
#include "fbo.h"
#include "gl_util.h"
#include "gpu_scene.h"
#include "hard_util.h"
#include "ibl_probes.h"
#include "ibl_sh.h"
#include "probe_readback.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { W = 64, H = 64, MC_SAMPLES = 65536 };
static const double F0 = 0.5;

static ibl probes;

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static bool capture_scene(const char *path, bool drop_last, ibl *b)
{
    scene s;
    gpu_scene gs;
    if (!scene_load(path, &s))
        return false;
    if (drop_last)
        s.object_count--; /* the last object has no keys: nothing of it is left to free */
    bool ok = gpu_scene_create(&s, &gs) && gpu_scene_update(&gs, 0.0f, 5.0 / 256.0, W, H) &&
              ibl_probes_capture(b, &gs);
    gpu_scene_destroy(&gs);
    scene_destroy(&s);
    return ok;
}

/* 1 and 2: the probe 0 of what b holds. */
static void check_reference(ibl *b, char **bounds, int bound_count)
{
    const ibl_probe *p = &b->probes[0];
    split_sum_probe read;
    bool ok = probe_readback(b, 0, &read);
    if (!hard_expect(ok, "read the probe, its prefiltered levels and the split-sum table back")) {
        probe_readback_free(&read);
        return;
    }
    const cube_level *radiance = &read.radiance, *levels = read.levels;
    printf("split sum against Monte Carlo (F0 %.2f, %d normals x n.v {1, .75, .5, .25}, %d samples), relative\n"
           "error in luminance, looked up along the mirror direction r and along the chapter's dominant direction:\n",
           F0, SPLIT_SUM_NORMALS, MC_SAMPLES);
    printf("  roughness  mirror: mean    max     dominant: mean  max     n.v = 1: mean\n");
    for (int l = 0; l < b->desc.levels; l++) {
        split_sum_errors e;
        split_sum_error(&read, l, F0, MC_SAMPLES, &e);
        printf("  %-9.2f  %-12.4f  %-6.4f  %-14.4f  %-6.4f  %.4f\n", e.roughness, e.mirror_mean, e.mirror_max,
               e.dominant_mean, e.dominant_max, e.head_on_mean);
        if (l < bound_count)
            hard_expect(e.dominant_mean <= atof(bounds[l]), "roughness %.2f: mean relative error %.4f (at most %s)",
                        e.roughness, e.dominant_mean, bounds[l]);
    }
    /* 2. the irradiance: every texel, cosine-weighted, against the 9 coefficients */
    double sh[SHADER_IBL_SH_COEFFS][3], sum = 0.0, worst = 0.0;
    for (int k = 0; k < SHADER_IBL_SH_COEFFS; k++)
        for (int c = 0; c < 3; c++)
            sh[k][c] = p->sh[k][c];
    for (int i = 0; i < SPLIT_SUM_NORMALS; i++) {
        double nn[3], e[3] = {0, 0, 0}, fit[3];
        split_sum_normal(i, nn);
        int size = radiance->size;
        for (int f = 0; f < 6; f++)
            for (int y = 0; y < size; y++)
                for (int x = 0; x < size; x++) {
                    double d[3];
                    ibl_cube_direction(f, size, x + 0.5, y + 0.5, d);
                    double w = dot3(nn, d) * ibl_cube_solid_angle(size, x, y) / GLM_PI;
                    for (int c = 0; w > 0.0 && c < 3; c++)
                        e[c] += w * radiance->faces[f][4 * (y * size + x) + c];
                }
        ibl_sh_irradiance((const double(*)[3])sh, nn, fit);
        double err = fabs(split_sum_luminance(fit) - split_sum_luminance(e)) / fmax(split_sum_luminance(e), 1e-4);
        sum += err, worst = fmax(worst, err);
    }
    printf("irradiance (9 coefficients) against the cosine integral of every texel: mean rel. error %.4f, max %.4f\n",
           sum / SPLIT_SUM_NORMALS, worst);
    hard_expect(sum / SPLIT_SUM_NORMALS <= 0.05, "irradiance: mean relative error %.4f (at most 0.05)", sum / SPLIT_SUM_NORMALS);
    /* 3a. roughness 0: level 0 is the capture */
    double diff = 0.0, top = 0.0;
    for (int f = 0; f < 6; f++)
        for (long k = 0; k < 4L * radiance->size * radiance->size; k++)
            diff = fmax(diff, fabs(radiance->faces[f][k] - levels[0].faces[f][k])), top = fmax(top, radiance->faces[f][k]);
    hard_expect(diff <= 1e-3 * top, "roughness 0: level 0 against the capture, max difference %.3g (largest value %.3g)",
                diff, top);
    probe_readback_free(&read);
}

/* 3b. the seam: the coarsest level sampled at pairs of directions either side of the +X / +Z edge. */
static double seam_gap(GLuint cube, float lod, bool seamless)
{
    static const char *vert = "#version 330 core\nvoid main() { vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, "
                              "gl_VertexID == 2 ? 3.0 : -1.0); gl_Position = vec4(p, 0.0, 1.0); }\n";
    static const char *frag = "#version 330 core\nuniform samplerCube u_cube; uniform float u_lod; out vec4 o;\n"
                              "void main() { int i = int(gl_FragCoord.x); float y = -0.8 + 0.2 * float(i / 2);\n"
                              "  float e = (i % 2 == 0) ? 1e-3 : -1e-3;\n"
                              "  o = vec4(textureLod(u_cube, vec3(1.0 - e, y, 1.0 + e), u_lod).rgb, 1.0); }\n";
    enum { PAIRS = 9 };
    GLuint prog = hard_program_create(vert, frag);
    fbo target = {0};
    const fbo_desc desc = {.color_formats = {GL_RGBA32F}, .color_count = 1, .name = "seam samples"};
    float px[4 * 2 * PAIRS];
    if (!prog || !fbo_create(&target, &desc, 2 * PAIRS, 1))
        return -1.0;
    (seamless ? glEnable : glDisable)(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    glBindFramebuffer(GL_FRAMEBUFFER, target.id);
    glViewport(0, 0, 2 * PAIRS, 1);
    glUseProgram(prog);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
    glUniform1i(glGetUniformLocation(prog, "u_cube"), 0);
    glUniform1f(glGetUniformLocation(prog, "u_lod"), lod);
    gl_draw_fullscreen();
    bool ok = fbo_read_float(&target, 0, px);
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    fbo_destroy(&target);
    gl_program_destroy(&prog);
    double worst = 0.0;
    for (int i = 0; ok && i < PAIRS; i++) {
        double a[3] = {px[8 * i], px[8 * i + 1], px[8 * i + 2]}, b[3] = {px[8 * i + 4], px[8 * i + 5], px[8 * i + 6]};
        worst = fmax(worst, fabs(split_sum_luminance(a) - split_sum_luminance(b)) / fmax(fmax(split_sum_luminance(a), split_sum_luminance(b)), 1e-4));
    }
    return ok ? worst : -1.0;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: %s SCENE INSIDE_SCENE [MAX_MEAN_PER_LEVEL...]\n", argv[0]);
        return 2;
    }
    hard_context_create(W, H);
    const ibl_desc desc = {.size = 128, .levels = 5, .samples = 256, .brdf_size = 64, .brdf_samples = 512};
    if (!hard_expect(ibl_probes_create(&probes, &desc), "the probes' programs and the split-sum table") ||
        !hard_expect(capture_scene(argv[1], false, &probes) && probes.count > 0, "capture %s", argv[1]))
        return hard_finish();
    check_reference(&probes, argv + 3, argc - 3);
    double on = seam_gap(probes.probes[0].specular, (float)(desc.levels - 1), true);
    double off = seam_gap(probes.probes[0].specular, (float)(desc.levels - 1), false);
    printf("seam (+X / +Z edge, level %d): largest relative step %.4f seamless, %.4f without\n", desc.levels - 1, on, off);
    hard_expect(on >= 0.0 && on <= 0.02 && off > on, "seam: step %.4f with seamless cube maps (at most 0.02), %.4f without",
                on, off);
    /* 3c. a probe inside a closed box: the same harmonics as without the box */
    float with[SHADER_IBL_SH_COEFFS][3], top = 0.0f, diff = 0.0f;
    bool ok = hard_expect(capture_scene(argv[2], false, &probes), "capture %s", argv[2]);
    memcpy(with, probes.probes[0].sh, sizeof with);
    ok = ok && hard_expect(capture_scene(argv[2], true, &probes), "capture %s without its last object", argv[2]);
    for (int k = 0; ok && k < SHADER_IBL_SH_COEFFS; k++)
        for (int c = 0; c < 3; c++)
            diff = fmaxf(diff, fabsf(with[k][c] - probes.probes[0].sh[k][c])), top = fmaxf(top, fabsf(with[k][c]));
    hard_expect(ok && top > 0.0f && diff <= 1e-5f * top,
                "probe inside a box: harmonics with and without the box differ by %.3g (largest %.3g)", diff, top);
    ibl_probes_destroy(&probes);
    return hard_finish();
}
