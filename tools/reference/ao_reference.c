/* ao_reference.c - see ao_reference.h. */
#include "ao_reference.h"

#include "mat4d.h"

#include <math.h>

#define AO_PI 3.14159265358979323846

static void normalize3(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; k++)
        v[k] /= l;
}

void ao_reference_begin(ao_reference *a, const ray_scene *rays, const float view_proj[16], const float eye[3],
                        int width, int height, double radius, int side)
{
    double vp[16];
    *a = (ao_reference){.rays = rays, .radius = radius, .width = width, .height = height, .side = side};
    mat4d_from_float(view_proj, vp);
    mat4d_invert(vp, a->inv_view_proj);
    for (int k = 0; k < 3; k++)
        a->eye[k] = eye[k];
    a->jitter = rng_seed(1), a->again = rng_seed(2);
}

/* The share of side x side cosine-weighted rays from p (about n) that meet nothing within the radius. */
static double open_share(const ao_reference *a, const double p[3], const double n[3], rng *r)
{
    double t[3], b[3], o[3];
    const int g = a->side;
    if (fabs(n[0]) < 0.5) /* cross((1,0,0), n) */
        t[0] = 0.0, t[1] = -n[2], t[2] = n[1];
    else /* cross((0,1,0), n) */
        t[0] = n[2], t[1] = 0.0, t[2] = -n[0];
    normalize3(t);
    b[0] = n[1] * t[2] - n[2] * t[1], b[1] = n[2] * t[0] - n[0] * t[2], b[2] = n[0] * t[1] - n[1] * t[0];
    for (int k = 0; k < 3; k++)
        o[k] = p[k] + 1e-7 * n[k]; /* off the surface's own triangle */
    int open = 0;
    for (int i = 0; i < g; i++)
        for (int j = 0; j < g; j++) {
            double u = (i + rng_unit(r)) / g, phi = 2.0 * AO_PI * (j + rng_unit(r)) / g, s = sqrt(u), d[3];
            const double *tri;
            for (int k = 0; k < 3; k++)
                d[k] = s * cos(phi) * t[k] + s * sin(phi) * b[k] + sqrt(1.0 - u) * n[k];
            open += ray_scene_trace(a->rays, o, d, 0.0, a->radius, RAY_ANY, &tri) < 0.0;
        }
    return (double)open / (g * g);
}

/* The surface through pixel (x, y)'s centre: its point and normal (towards the eye); false if none. */
static bool surface_at(const ao_reference *a, int x, int y, double p[3], double n[3])
{
    double ndc[4] = {2.0 * (x + 0.5) / a->width - 1.0, 2.0 * (y + 0.5) / a->height - 1.0, 1.0, 1.0};
    double far_point[4] = {0}, d[3];
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++)
            far_point[r] += a->inv_view_proj[4 * c + r] * ndc[c];
    for (int k = 0; k < 3; k++)
        d[k] = far_point[k] / far_point[3] - a->eye[k];
    const double *v;
    double t = ray_scene_trace(a->rays, a->eye, d, 1e-9, 1.0, RAY_NEAREST, &v);
    if (t <= 0.0)
        return false;
    double e1[3], e2[3];
    for (int k = 0; k < 3; k++)
        p[k] = a->eye[k] + t * d[k], e1[k] = v[3 + k] - v[k], e2[k] = v[6 + k] - v[k];
    n[0] = e1[1] * e2[2] - e1[2] * e2[1], n[1] = e1[2] * e2[0] - e1[0] * e2[2], n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    normalize3(n);
    if (n[0] * d[0] + n[1] * d[1] + n[2] * d[2] > 0.0)
        for (int k = 0; k < 3; k++)
            n[k] = -n[k];
    return true;
}

double ao_reference_pixel(ao_reference *a, int x, int y, double p[3])
{
    double at[3], n[3];
    if (!p)
        p = at;
    if (!surface_at(a, x, y, p, n))
        return -1.0;
    double open = open_share(a, p, n, &a->jitter);
    if ((x + y * a->width) % 4 == 0) {
        double e = fabs(open_share(a, p, n, &a->again) - open);
        a->noise_sum += e, a->noise_max = fmax(a->noise_max, e), a->noise_count++;
    }
    return open;
}

bool ao_reference_noise(const ao_reference *a, double *mean, double *max)
{
    *mean = a->noise_count ? a->noise_sum / (double)a->noise_count : 0.0;
    *max = a->noise_max;
    return a->noise_count > 0;
}
