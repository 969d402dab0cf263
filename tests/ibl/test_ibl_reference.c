/* test_ibl_reference.c - chapter 19's probes against exact references, in double precision on the
 * CPU, from what the GPU made (read back): the probe's captured cube map, its prefiltered chain,
 * its spherical harmonics and the split-sum table.
 *
 *   1. specular: for 12 normals x 4 view angles per roughness, the Monte Carlo integral of the cube
 *      map against the full GGX BRDF (D, Smith-Schlick G with k = alpha / 2, Schlick F with F0 0.5;
 *      65,536 importance-sampled half vectors) against the split sum, prefiltered(r) (F0 A + B):
 *      the split sum's error by roughness (relative, in luminance), printed and bounded
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

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { W = 64, H = 64, NORMALS = 12, VIEWS = 4, MC_SAMPLES = 65536 };
static const double F0 = 0.5;
static const double view_cosines[VIEWS] = {1.0, 0.75, 0.5, 0.25};

static ibl probes;

/* One cube level read back: 6 faces of size^2 RGBA floats. */
typedef struct cube_level {
    int size;
    float *faces[6];
} cube_level;

static bool level_read(GLuint cube, int level, int size, cube_level *out)
{
    out->size = size;
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
    for (int f = 0; f < 6; f++) {
        out->faces[f] = malloc(sizeof(float) * 4 * (size_t)size * (size_t)size);
        if (!out->faces[f])
            return false;
        glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, level, GL_RGBA, GL_FLOAT, out->faces[f]);
    }
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    return gl_check("read a cube level");
}

static void level_free(cube_level *c)
{
    for (int f = 0; f < 6; f++)
        free(c->faces[f]);
}

/* The face and its (s, t) a direction falls on: the GL spec's selection table. */
static int cube_select(const double d[3], double *s, double *t)
{
    double ax = fabs(d[0]), ay = fabs(d[1]), az = fabs(d[2]), sc, tc, ma;
    int face;
    if (ax >= ay && ax >= az)
        face = d[0] > 0 ? 0 : 1, ma = ax, sc = d[0] > 0 ? -d[2] : d[2], tc = -d[1];
    else if (ay >= az)
        face = d[1] > 0 ? 2 : 3, ma = ay, sc = d[0], tc = d[1] > 0 ? d[2] : -d[2];
    else
        face = d[2] > 0 ? 4 : 5, ma = az, sc = d[2] > 0 ? d[0] : -d[0], tc = -d[1];
    *s = (sc / ma + 1.0) * 0.5, *t = (tc / ma + 1.0) * 0.5;
    return face;
}

/* Bilinear within the face (clamped at its edges), as a texture lookup without seams would be. */
static void level_sample(const cube_level *c, const double d[3], double out[3])
{
    double s, t;
    int f = cube_select(d, &s, &t), n = c->size;
    double x = fmin(fmax(s * n - 0.5, 0.0), n - 1.0), y = fmin(fmax(t * n - 0.5, 0.0), n - 1.0);
    int x0 = (int)x, y0 = (int)y, x1 = x0 + 1 < n ? x0 + 1 : x0, y1 = y0 + 1 < n ? y0 + 1 : y0;
    double fx = x - x0, fy = y - y0;
    const float *p = c->faces[f];
    for (int k = 0; k < 3; k++)
        out[k] = (1 - fy) * ((1 - fx) * p[4 * (y0 * n + x0) + k] + fx * p[4 * (y0 * n + x1) + k]) +
                 fy * ((1 - fx) * p[4 * (y1 * n + x0) + k] + fx * p[4 * (y1 * n + x1) + k]);
}

static double luminance(const double c[3]) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }
static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void normalize3(double v[3])
{
    double l = sqrt(dot3(v, v));
    for (int k = 0; k < 3; k++)
        v[k] /= l;
}

/* Two unit vectors completing n to an orthonormal frame. */
static void frame_of(const double n[3], double tx[3], double ty[3])
{
    double up[3] = {fabs(n[2]) < 0.999 ? 0 : 1, 0, fabs(n[2]) < 0.999 ? 1 : 0};
    tx[0] = up[1] * n[2] - up[2] * n[1], tx[1] = up[2] * n[0] - up[0] * n[2], tx[2] = up[0] * n[1] - up[1] * n[0];
    normalize3(tx);
    ty[0] = n[1] * tx[2] - n[2] * tx[1], ty[1] = n[2] * tx[0] - n[0] * tx[2], ty[2] = n[0] * tx[1] - n[1] * tx[0];
}

/* The radical inverse in base 2: the second coordinate of the Hammersley points. */
static double radical_inverse(unsigned i)
{
    double r = 0.0, f = 0.5;
    for (; i; i >>= 1, f *= 0.5)
        r += f * (i & 1u);
    return r;
}

static double g1(double ndx, double k) { return ndx / (ndx * (1.0 - k) + k); }

/* The exact specular reflection of the radiance cube at (n, v) for roughness r, by Monte Carlo. */
static void reference_specular(const cube_level *radiance, const double n[3], const double v[3], double r, double out[3])
{
    double alpha = r * r, k = alpha * 0.5, tx[3], ty[3], ndv = dot3(n, v);
    frame_of(n, tx, ty);
    double sum[3] = {0, 0, 0};
    for (unsigned i = 0; i < MC_SAMPLES; i++) {
        double u1 = (i + 0.5) / MC_SAMPLES, u2 = radical_inverse(i);
        double phi = 2.0 * GLM_PI * u1, ct = sqrt((1.0 - u2) / (1.0 + (alpha * alpha - 1.0) * u2)), st = sqrt(1.0 - ct * ct);
        double h[3], l[3];
        for (int c = 0; c < 3; c++)
            h[c] = tx[c] * cos(phi) * st + ty[c] * sin(phi) * st + n[c] * ct;
        double vdh = dot3(v, h);
        for (int c = 0; c < 3; c++)
            l[c] = 2.0 * vdh * h[c] - v[c];
        double ndl = dot3(n, l), ndh = dot3(n, h);
        if (ndl <= 0.0 || vdh <= 0.0)
            continue;
        double f = F0 + (1.0 - F0) * pow(1.0 - vdh, 5.0);
        double w = f * g1(ndv, k) * g1(ndl, k) * vdh / (ndh * ndv), L[3];
        level_sample(radiance, l, L);
        for (int c = 0; c < 3; c++)
            sum[c] += w * L[c];
    }
    for (int c = 0; c < 3; c++)
        out[c] = sum[c] / MC_SAMPLES;
}

/* The split-sum table (RG floats, size^2) bilinear at (n.v, roughness), as texture() reads it. */
static void table_sample(const float *table, int size, double ndv, double r, double ab[2])
{
    double x = fmin(fmax(ndv * size - 0.5, 0.0), size - 1.0), y = fmin(fmax(r * size - 0.5, 0.0), size - 1.0);
    int x0 = (int)x, y0 = (int)y, x1 = x0 + 1 < size ? x0 + 1 : x0, y1 = y0 + 1 < size ? y0 + 1 : y0;
    double fx = x - x0, fy = y - y0;
    for (int k = 0; k < 2; k++)
        ab[k] = (1 - fy) * ((1 - fx) * table[2 * (y0 * size + x0) + k] + fx * table[2 * (y0 * size + x1) + k]) +
                fy * ((1 - fx) * table[2 * (y1 * size + x0) + k] + fx * table[2 * (y1 * size + x1) + k]);
}

/* Spread normals: a Fibonacci spiral over the sphere. */
static void normal_at(int i, double n[3])
{
    double z = 1.0 - 2.0 * (i + 0.5) / NORMALS, rho = sqrt(1.0 - z * z), phi = i * GLM_PI * (3.0 - sqrt(5.0));
    n[0] = rho * cos(phi), n[1] = z, n[2] = rho * sin(phi);
}

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
    cube_level radiance, levels[8];
    int n = b->desc.brdf_size;
    float *table = malloc(sizeof(float) * 2 * (size_t)n * (size_t)n);
    bool ok = table && level_read(p->radiance, 0, b->desc.size, &radiance);
    for (int l = 0; ok && l < b->desc.levels; l++)
        ok = level_read(p->specular, l, b->desc.size >> l, &levels[l]);
    if (ok) {
        glBindTexture(GL_TEXTURE_2D, b->brdf);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RG, GL_FLOAT, table);
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    if (!hard_expect(ok, "read the probe, its prefiltered levels and the split-sum table back"))
        return;
    printf("split sum against Monte Carlo (F0 %.2f, %d normals x n.v {1, .75, .5, .25}, %d samples), relative\n"
           "error in luminance, looked up along the mirror direction r and along the chapter's dominant direction:\n",
           F0, NORMALS, MC_SAMPLES);
    printf("  roughness  mirror: mean    max     dominant: mean  max     n.v = 1: mean\n");
    for (int l = 0; l < b->desc.levels; l++) {
        double r = (double)l / (b->desc.levels - 1), sum[2] = {0, 0}, worst[2] = {0, 0}, head_on = 0.0;
        for (int i = 0; i < NORMALS; i++)
            for (int j = 0; j < VIEWS; j++) {
                double nn[3], tx[3], ty[3], v[3], ref[3], ab[2], dirs[2][3];
                normal_at(i, nn);
                frame_of(nn, tx, ty);
                double c = view_cosines[j], s = sqrt(1.0 - c * c);
                for (int k = 0; k < 3; k++)
                    v[k] = nn[k] * c + tx[k] * s, dirs[0][k] = 2.0 * c * nn[k] - v[k];
                /* shaders/ibl.glsl's ibl_dominant(): towards n as the lobe widens */
                double a = r * r, sm = 1.0 - a, t = sm * (sqrt(sm) + a);
                for (int k = 0; k < 3; k++)
                    dirs[1][k] = nn[k] + (dirs[0][k] - nn[k]) * t;
                normalize3(dirs[1]);
                reference_specular(&radiance, nn, v, r, ref);
                table_sample(table, n, c, r, ab);
                for (int d = 0; d < 2; d++) {
                    double pre[3], split[3];
                    level_sample(&levels[l], dirs[d], pre);
                    for (int k = 0; k < 3; k++)
                        split[k] = pre[k] * (F0 * ab[0] + ab[1]);
                    double e = fabs(luminance(split) - luminance(ref)) / fmax(luminance(ref), 1e-4);
                    sum[d] += e, worst[d] = fmax(worst[d], e), head_on += j == 0 && d == 1 ? e : 0.0;
                }
            }
        double mean = sum[1] / (NORMALS * VIEWS);
        printf("  %-9.2f  %-12.4f  %-6.4f  %-14.4f  %-6.4f  %.4f\n", r, sum[0] / (NORMALS * VIEWS), worst[0], mean,
               worst[1], head_on / NORMALS);
        if (l < bound_count)
            hard_expect(mean <= atof(bounds[l]), "roughness %.2f: mean relative error %.4f (at most %s)", r, mean,
                        bounds[l]);
    }
    /* 2. the irradiance: every texel, cosine-weighted, against the 9 coefficients */
    double sh[SHADER_IBL_SH_COEFFS][3], sum = 0.0, worst = 0.0;
    for (int k = 0; k < SHADER_IBL_SH_COEFFS; k++)
        for (int c = 0; c < 3; c++)
            sh[k][c] = p->sh[k][c];
    for (int i = 0; i < NORMALS; i++) {
        double nn[3], e[3] = {0, 0, 0}, fit[3];
        normal_at(i, nn);
        int size = radiance.size;
        for (int f = 0; f < 6; f++)
            for (int y = 0; y < size; y++)
                for (int x = 0; x < size; x++) {
                    double d[3];
                    ibl_cube_direction(f, size, x + 0.5, y + 0.5, d);
                    double w = dot3(nn, d) * ibl_cube_solid_angle(size, x, y) / GLM_PI;
                    for (int c = 0; w > 0.0 && c < 3; c++)
                        e[c] += w * radiance.faces[f][4 * (y * size + x) + c];
                }
        ibl_sh_irradiance((const double(*)[3])sh, nn, fit);
        double err = fabs(luminance(fit) - luminance(e)) / fmax(luminance(e), 1e-4);
        sum += err, worst = fmax(worst, err);
    }
    printf("irradiance (9 coefficients) against the cosine integral of every texel: mean rel. error %.4f, max %.4f\n",
           sum / NORMALS, worst);
    hard_expect(sum / NORMALS <= 0.05, "irradiance: mean relative error %.4f (at most 0.05)", sum / NORMALS);
    /* 3a. roughness 0: level 0 is the capture */
    double diff = 0.0, top = 0.0;
    for (int f = 0; f < 6; f++)
        for (long k = 0; k < 4L * radiance.size * radiance.size; k++)
            diff = fmax(diff, fabs(radiance.faces[f][k] - levels[0].faces[f][k])), top = fmax(top, radiance.faces[f][k]);
    hard_expect(diff <= 1e-3 * top, "roughness 0: level 0 against the capture, max difference %.3g (largest value %.3g)",
                diff, top);
    level_free(&radiance);
    for (int l = 0; l < b->desc.levels; l++)
        level_free(&levels[l]);
    free(table);
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
        worst = fmax(worst, fabs(luminance(a) - luminance(b)) / fmax(fmax(luminance(a), luminance(b)), 1e-4));
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
