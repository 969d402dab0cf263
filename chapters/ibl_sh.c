/* ibl_sh.c - chapter 19's arithmetic without GL (ibl_sh.h). */
#include "ibl_sh.h"

#include <math.h>

void ibl_cube_direction(int face, int size, double x, double y, double dir[3])
{
    /* GL's table (the spec's "cube map texture selection"), read backwards: s = (sc / |ma| + 1) / 2 */
    double u = 2.0 * x / size - 1.0, v = 2.0 * y / size - 1.0;
    double d[6][3] = {{1, -v, -u}, {-1, -v, u}, {u, 1, v}, {u, -1, -v}, {u, -v, 1}, {-u, -v, -1}};
    double len = sqrt(d[face][0] * d[face][0] + d[face][1] * d[face][1] + d[face][2] * d[face][2]);
    for (int k = 0; k < 3; k++)
        dir[k] = d[face][k] / len;
}

/* The solid angle of the face rectangle from the centre to (u, v) on the plane at distance 1. */
static double corner_area(double u, double v) { return atan2(u * v, sqrt(u * u + v * v + 1.0)); }

double ibl_cube_solid_angle(int size, int i, int j)
{
    double u0 = 2.0 * i / size - 1.0, u1 = 2.0 * (i + 1) / size - 1.0;
    double v0 = 2.0 * j / size - 1.0, v1 = 2.0 * (j + 1) / size - 1.0;
    return corner_area(u1, v1) - corner_area(u0, v1) - corner_area(u1, v0) + corner_area(u0, v0);
}

/* The 9 real spherical harmonics Y_lm at a unit direction (bands 0, 1, 2). */
static void sh_basis(const double d[3], double y[SHADER_IBL_SH_COEFFS])
{
    double x = d[0], yy = d[1], z = d[2];
    y[0] = 0.282095;
    y[1] = 0.488603 * yy, y[2] = 0.488603 * z, y[3] = 0.488603 * x;
    y[4] = 1.092548 * x * yy, y[5] = 1.092548 * yy * z, y[6] = 0.315392 * (3.0 * z * z - 1.0);
    y[7] = 1.092548 * x * z, y[8] = 0.546274 * (x * x - yy * yy);
}

void ibl_sh_project(const float *const faces[6], int size, double sh[SHADER_IBL_SH_COEFFS][3])
{
    for (int k = 0; k < SHADER_IBL_SH_COEFFS; k++)
        sh[k][0] = sh[k][1] = sh[k][2] = 0.0;
    for (int f = 0; f < 6; f++)
        for (int j = 0; j < size; j++)
            for (int i = 0; i < size; i++) {
                double d[3], y[SHADER_IBL_SH_COEFFS];
                ibl_cube_direction(f, size, i + 0.5, j + 0.5, d);
                sh_basis(d, y);
                double w = ibl_cube_solid_angle(size, i, j);
                const float *c = faces[f] + 3 * ((long)j * size + i);
                for (int k = 0; k < SHADER_IBL_SH_COEFFS; k++)
                    for (int ch = 0; ch < 3; ch++)
                        sh[k][ch] += c[ch] * y[k] * w;
            }
}

void ibl_sh_irradiance(const double sh[SHADER_IBL_SH_COEFFS][3], const double n[3], double out[3])
{
    /* The cosine lobe's bands (Ramamoorthi and Hanrahan 2001): pi, 2 pi / 3, pi / 4; over pi. */
    static const double band[SHADER_IBL_SH_COEFFS] = {1.0, 2.0 / 3, 2.0 / 3, 2.0 / 3, 0.25, 0.25, 0.25, 0.25, 0.25};
    double y[SHADER_IBL_SH_COEFFS];
    sh_basis(n, y);
    for (int ch = 0; ch < 3; ch++) {
        out[ch] = 0.0;
        for (int k = 0; k < SHADER_IBL_SH_COEFFS; k++)
            out[ch] += band[k] * sh[k][ch] * y[k];
        out[ch] = out[ch] > 0.0 ? out[ch] : 0.0;
    }
}

double ibl_probe_importance(const scene_probe *probe, const float eye[3])
{
    double dx = eye[0] - probe->position[0], dy = eye[1] - probe->position[1], dz = eye[2] - probe->position[2];
    double d = sqrt(dx * dx + dy * dy + dz * dz);
    return d <= probe->radius ? 1.0 : probe->radius / d;
}

int ibl_probes_pick_indices(const scene_probe *probes, int count, const float eye[3], int out[SHADER_IBL_MAX_PICKED])
{
    int picked = 0;
    for (int i = 0; i < count; i++) {
        double w = ibl_probe_importance(&probes[i], eye);
        /* insertion into the sorted short list; an equal importance keeps the earlier probe first */
        int at = picked;
        while (at > 0 && ibl_probe_importance(&probes[out[at - 1]], eye) < w)
            at--;
        if (at >= SHADER_IBL_MAX_PICKED)
            continue;
        for (int k = (picked < SHADER_IBL_MAX_PICKED ? picked : SHADER_IBL_MAX_PICKED - 1); k > at; k--)
            out[k] = out[k - 1];
        out[at] = i;
        if (picked < SHADER_IBL_MAX_PICKED)
            picked++;
    }
    return picked;
}

double ibl_probe_weight(const scene_probe *probe, const double p[3])
{
    double d2 = 0.0;
    for (int k = 0; k < 3; k++)
        d2 += (p[k] - probe->position[k]) * (p[k] - probe->position[k]);
    double x = 1.0 - d2 / ((double)probe->radius * probe->radius);
    return x > 0.0 ? x * x : 0.0;
}

double ibl_shininess_roughness(double shininess) { return pow(2.0 / (shininess + 2.0), 0.25); }
