/* split_sum_reference.c - see split_sum_reference.h. */
#include "split_sum_reference.h"

#include <math.h>

#define SPLIT_SUM_PI 3.14159265358979323846

static const double view_cosines[SPLIT_SUM_VIEWS] = {1.0, 0.75, 0.5, 0.25};

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

void split_sum_cube_sample(const cube_level *c, const double d[3], double out[3])
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

double split_sum_luminance(const double c[3]) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }
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
static void reference_specular(const cube_level *radiance, const double n[3], const double v[3], double r,
                               double f0, unsigned samples, double out[3])
{
    double alpha = r * r, k = alpha * 0.5, tx[3], ty[3], ndv = dot3(n, v);
    frame_of(n, tx, ty);
    double sum[3] = {0, 0, 0};
    for (unsigned i = 0; i < samples; i++) {
        double u1 = (i + 0.5) / samples, u2 = radical_inverse(i);
        double phi = 2.0 * SPLIT_SUM_PI * u1, ct = sqrt((1.0 - u2) / (1.0 + (alpha * alpha - 1.0) * u2));
        double st = sqrt(1.0 - ct * ct), h[3], l[3];
        for (int c = 0; c < 3; c++)
            h[c] = tx[c] * cos(phi) * st + ty[c] * sin(phi) * st + n[c] * ct;
        double vdh = dot3(v, h);
        for (int c = 0; c < 3; c++)
            l[c] = 2.0 * vdh * h[c] - v[c];
        double ndl = dot3(n, l), ndh = dot3(n, h);
        if (ndl <= 0.0 || vdh <= 0.0)
            continue;
        double f = f0 + (1.0 - f0) * pow(1.0 - vdh, 5.0);
        double w = f * g1(ndv, k) * g1(ndl, k) * vdh / (ndh * ndv), L[3];
        split_sum_cube_sample(radiance, l, L);
        for (int c = 0; c < 3; c++)
            sum[c] += w * L[c];
    }
    for (int c = 0; c < 3; c++)
        out[c] = sum[c] / samples;
}

/* The split-sum table bilinear at (n.v, roughness), as texture() reads it. */
static void table_sample(const float *table, int size, double ndv, double r, double ab[2])
{
    double x = fmin(fmax(ndv * size - 0.5, 0.0), size - 1.0), y = fmin(fmax(r * size - 0.5, 0.0), size - 1.0);
    int x0 = (int)x, y0 = (int)y, x1 = x0 + 1 < size ? x0 + 1 : x0, y1 = y0 + 1 < size ? y0 + 1 : y0;
    double fx = x - x0, fy = y - y0;
    for (int k = 0; k < 2; k++)
        ab[k] = (1 - fy) * ((1 - fx) * table[2 * (y0 * size + x0) + k] + fx * table[2 * (y0 * size + x1) + k]) +
                fy * ((1 - fx) * table[2 * (y1 * size + x0) + k] + fx * table[2 * (y1 * size + x1) + k]);
}

void split_sum_normal(int i, double n[3])
{
    double z = 1.0 - 2.0 * (i + 0.5) / SPLIT_SUM_NORMALS, rho = sqrt(1.0 - z * z);
    double phi = i * SPLIT_SUM_PI * (3.0 - sqrt(5.0));
    n[0] = rho * cos(phi), n[1] = z, n[2] = rho * sin(phi);
}

void split_sum_error(const split_sum_probe *probe, int level, double f0, int samples, split_sum_errors *out)
{
    double r = (double)level / (probe->level_count - 1), sum[2] = {0, 0}, worst[2] = {0, 0}, head_on = 0.0;
    for (int i = 0; i < SPLIT_SUM_NORMALS; i++)
        for (int j = 0; j < SPLIT_SUM_VIEWS; j++) {
            double nn[3], tx[3], ty[3], v[3], ref[3], ab[2], dirs[2][3];
            split_sum_normal(i, nn);
            frame_of(nn, tx, ty);
            double c = view_cosines[j], s = sqrt(1.0 - c * c);
            for (int k = 0; k < 3; k++)
                v[k] = nn[k] * c + tx[k] * s, dirs[0][k] = 2.0 * c * nn[k] - v[k];
            /* shaders/ibl.glsl's ibl_dominant(): towards n as the lobe widens */
            double a = r * r, sm = 1.0 - a, t = sm * (sqrt(sm) + a);
            for (int k = 0; k < 3; k++)
                dirs[1][k] = nn[k] + (dirs[0][k] - nn[k]) * t;
            normalize3(dirs[1]);
            reference_specular(&probe->radiance, nn, v, r, f0, (unsigned)samples, ref);
            table_sample(probe->table, probe->table_size, c, r, ab);
            for (int d = 0; d < 2; d++) {
                double pre[3], split[3];
                split_sum_cube_sample(&probe->levels[level], dirs[d], pre);
                for (int k = 0; k < 3; k++)
                    split[k] = pre[k] * (f0 * ab[0] + ab[1]);
                double e = fabs(split_sum_luminance(split) - split_sum_luminance(ref)) /
                           fmax(split_sum_luminance(ref), 1e-4);
                sum[d] += e, worst[d] = fmax(worst[d], e), head_on += j == 0 && d == 1 ? e : 0.0;
            }
        }
    const double cases = SPLIT_SUM_NORMALS * SPLIT_SUM_VIEWS;
    *out = (split_sum_errors){.roughness = r, .mirror_mean = sum[0] / cases, .mirror_max = worst[0],
                              .dominant_mean = sum[1] / cases, .dominant_max = worst[1],
                              .head_on_mean = head_on / SPLIT_SUM_NORMALS};
}
