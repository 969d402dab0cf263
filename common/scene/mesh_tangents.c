/* mesh_tangents.c - tangents for the vertices that came without one (mesh_data.h): a normal map's
 * x and y axes on the surface, from how the texture coordinates run across each triangle.
 *
 * For a triangle with edges e1 = p1 - p0, e2 = p2 - p0 and texture steps (du1, dv1), (du2, dv2), the
 * directions in which u and v grow are T = (e1 dv2 - e2 dv1) / det and B = (e2 du1 - e1 du2) / det,
 * det = du1 dv2 - du2 dv1. Each vertex sums the T and B of its triangles (weighted by their area in
 * texture space, as the sums are not normalised per triangle), then keeps T's part at right angles to
 * its normal, and w = +1 or -1 for whether B runs along cross(n, T) or against it (a mirrored layout).
 */
#include "mesh_data.h"

#include <math.h>
#include <stdlib.h>

/* Any unit vector at right angles to n: the cross product with the axis n leans on least. */
static void any_perpendicular(const float n[3], float out[3])
{
    float ax = fabsf(n[0]), ay = fabsf(n[1]), az = fabsf(n[2]);
    float axis[3] = {0.0f, 0.0f, 0.0f};
    axis[ax <= ay && ax <= az ? 0 : (ay <= az ? 1 : 2)] = 1.0f;
    float c[3] = {axis[1] * n[2] - axis[2] * n[1], axis[2] * n[0] - axis[0] * n[2], axis[0] * n[1] - axis[1] * n[0]};
    float len = sqrtf(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    if (!(len > 1e-20f) || !isfinite(len)) { /* a zero or broken normal: still a unit vector */
        out[0] = 1.0f, out[1] = 0.0f, out[2] = 0.0f;
        return;
    }
    for (int k = 0; k < 3; k++)
        out[k] = c[k] / len;
}

/* Adds triangle (a, b, c)'s u and v directions to its vertices' sums; a triangle whose texture
 * coordinates have no area (det 0: no UVs, or a degenerate UV triangle) adds nothing. */
static void add_triangle(const mesh_data *m, const uint32_t idx[3], double *sums)
{
    const float *p[3], *t[3];
    for (int k = 0; k < 3; k++) {
        p[k] = m->vertices + (size_t)idx[k] * MESH_VERTEX_FLOATS;
        t[k] = p[k] + MESH_VERTEX_UV;
    }
    double du1 = (double)t[1][0] - t[0][0], dv1 = (double)t[1][1] - t[0][1];
    double du2 = (double)t[2][0] - t[0][0], dv2 = (double)t[2][1] - t[0][1];
    double det = du1 * dv2 - du2 * dv1;
    if (!(fabs(det) > 1e-20) || !isfinite(det))
        return;
    double sign = det > 0.0 ? 1.0 : -1.0; /* |det| weights: a triangle's share grows with its UV area */
    for (int k = 0; k < 3; k++) {
        double e1 = (double)p[1][k] - p[0][k], e2 = (double)p[2][k] - p[0][k];
        double tk = (e1 * dv2 - e2 * dv1) * sign, bk = (e2 * du1 - e1 * du2) * sign;
        for (int c = 0; c < 3; c++) {
            sums[6 * idx[c] + k] += tk;
            sums[6 * idx[c] + 3 + k] += bk;
        }
    }
}

void mesh_data_generate_tangents(mesh_data *m)
{
    double *sums = calloc((size_t)m->vertex_count * 6 + 1, sizeof *sums);
    if (sums)
        for (int f = 0; f + 2 < m->index_count; f += 3)
            add_triangle(m, m->indices + f, sums);
    for (int i = 0; i < m->vertex_count; i++) {
        float *v = m->vertices + (size_t)i * MESH_VERTEX_FLOATS;
        float *tangent = v + MESH_VERTEX_TANGENT;
        if (tangent[3] != 0.0f)
            continue; /* the file gave one */
        const float *n = v + MESH_VERTEX_NORMAL;
        double t[3] = {0, 0, 0}, b[3] = {0, 0, 0};
        for (int k = 0; sums && k < 3; k++)
            t[k] = sums[6 * i + k], b[k] = sums[6 * i + 3 + k];
        double tn = t[0] * n[0] + t[1] * n[1] + t[2] * n[2];
        for (int k = 0; k < 3; k++)
            t[k] -= tn * n[k];
        double len = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
        /* Relative to the sums' size: texture coordinates that barely move along n leave noise. */
        double scale = sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]) + fabs(tn);
        if (!(len > 1e-6 * scale) || !(len > 1e-30) || !isfinite(len)) {
            any_perpendicular(n, tangent);
            tangent[3] = 1.0f;
            continue;
        }
        for (int k = 0; k < 3; k++)
            tangent[k] = (float)(t[k] / len);
        double c[3] = {n[1] * t[2] - n[2] * t[1], n[2] * t[0] - n[0] * t[2], n[0] * t[1] - n[1] * t[0]};
        tangent[3] = c[0] * b[0] + c[1] * b[1] + c[2] * b[2] < 0.0 ? -1.0f : 1.0f;
    }
    free(sums);
}
