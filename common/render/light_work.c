/* light_work.c - see light_work.h. */
#include "light_work.h"

#include "gpu_scene.h"
#include "mat4d.h"

#include <float.h>
#include <math.h>

/* out = m * (x, y, z, 1), m column-major. */
static void transform_point(const double m[16], double x, double y, double z, double out[4])
{
    for (int r = 0; r < 4; r++)
        out[r] = m[r] * x + m[4 + r] * y + m[8 + r] * z + m[12 + r];
}

void light_work_positions(const float *depth, int width, int height, const float *view_proj, double *out)
{
    double vp[16], inv[16];
    mat4d_from_float(view_proj, vp);
    /* In double: a float inverse would put its own error into the "exact" count. */
    bool ok = mat4d_invert(vp, inv);
    for (int y = 0; y < height; y++) {
        for (int x = 0; x < width; x++) {
            size_t i = (size_t)y * (size_t)width + (size_t)x;
            double *p = out + 4 * i;
            p[0] = p[1] = p[2] = p[3] = 0.0;
            double d = depth[i];
            if (!ok || d >= 1.0)
                continue;
            /* Pixel centre and depth back to NDC, exactly as shaders/gbuffer_read.glsl does. */
            double ndc[3] = {((double)x + 0.5) / width * 2.0 - 1.0, ((double)y + 0.5) / height * 2.0 - 1.0,
                             d * 2.0 - 1.0};
            double w[4];
            transform_point(inv, ndc[0], ndc[1], ndc[2], w);
            if (w[3] == 0.0)
                continue;
            p[0] = w[0] / w[3], p[1] = w[1] / w[3], p[2] = w[2] / w[3], p[3] = 1.0;
        }
    }
}

/* Pixel rectangle [x0,x1] x [y0,y1] that holds the light's sphere on screen: the projection of
 * the sphere's bounding box, or the whole screen when part of the box is behind the eye. */
static void light_screen_rect(const double vp[16], const gpu_light *l, int width, int height, int rect[4])
{
    rect[0] = 0, rect[1] = 0, rect[2] = width - 1, rect[3] = height - 1;
    double r = l->radius;
    if (!(r < FLT_MAX))
        return;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int c = 0; c < 8; c++) {
        double clip[4];
        transform_point(vp, l->position[0] + (c & 1 ? r : -r), l->position[1] + (c & 2 ? r : -r),
                        l->position[2] + (c & 4 ? r : -r), clip);
        if (clip[3] <= 1e-9)
            return;
        for (int k = 0; k < 2; k++) {
            double v = clip[k] / clip[3];
            lo[k] = fmin(lo[k], v);
            hi[k] = fmax(hi[k], v);
        }
    }
    /* ndc -> pixel index whose centre is inside, widened by one pixel against rounding. */
    int size[2] = {width, height};
    for (int k = 0; k < 2; k++) {
        double a = (lo[k] + 1.0) * 0.5 * size[k] - 0.5, b = (hi[k] + 1.0) * 0.5 * size[k] - 0.5;
        double a_clamped = fmax(floor(a) - 1.0, 0.0), b_clamped = fmin(ceil(b) + 1.0, size[k] - 1.0);
        rect[k] = (int)a_clamped;
        rect[k + 2] = (int)b_clamped;
    }
}

long long light_work_ideal_pairs(const double *pos, int width, int height, const float *view_proj,
                                 const gpu_light *lights, int count)
{
    double vp[16];
    mat4d_from_float(view_proj, vp);
    long long pairs = 0;
    for (int k = 0; k < count; k++) {
        const gpu_light *l = &lights[k];
        int rect[4];
        light_screen_rect(vp, l, width, height, rect);
        bool infinite = !(l->radius < FLT_MAX);
        double r2 = (double)l->radius * (double)l->radius;
        for (int y = rect[1]; y <= rect[3]; y++) {
            const double *p = pos + 4 * ((size_t)y * (size_t)width + (size_t)rect[0]);
            for (int x = rect[0]; x <= rect[2]; x++, p += 4) {
                if (p[3] == 0.0)
                    continue;
                double dx = p[0] - l->position[0], dy = p[1] - l->position[1], dz = p[2] - l->position[2];
                if (infinite || dx * dx + dy * dy + dz * dz <= r2)
                    pairs++;
            }
        }
    }
    return pairs;
}
