/* light.c - see light.h. */
#include "light.h"

#include "rng.h"

#include <math.h>
#include <stdlib.h>

#include "log.h"
#include "scene.h"

double light_attenuation(double kc, double kl, double kq, double d)
{
    return 1.0 / (kc + kl * d + kq * d * d);
}

double light_peak(const float color[3], double intensity)
{
    double m = fmax(fmax(color[0], color[1]), color[2]);
    return intensity * m;
}

static bool is_valid_coefficient(double x)
{
    return isfinite(x) && x >= 0.0;
}

double light_radius(double kc, double kl, double kq, double peak, double cutoff)
{
    if (!is_valid_coefficient(kc) || !is_valid_coefficient(kl) || !is_valid_coefficient(kq) ||
        !is_valid_coefficient(peak) || !is_valid_coefficient(cutoff))
        return NAN;
    if (cutoff == 0.0)
        return peak == 0.0 ? 0.0 : INFINITY;
    if (peak == 0.0)
        return 0.0;

    /* Solve kq r^2 + kl r = c with c = peak / cutoff - kc. Every quantity is split into a mantissa
     * and a power of two so that nothing overflows: peak / cutoff alone can be 1e600 while r is
     * still a double. c is formed as (peak - kc cutoff) / cutoff with the product's rounding error
     * kept (fma), so a light barely brighter than the cut-off keeps its digits. */
    int p_e, k_e;
    double p_m = frexp(peak, &p_e), k_m = frexp(cutoff, &k_e);
    double n = p_m; /* (peak - kc * cutoff) / 2^p_e */
    if (kc > 0.0) {
        int kc_e;
        double kc_m = frexp(kc, &kc_e);
        int shift = kc_e + k_e - p_e;
        if (shift >= 2)
            return 0.0; /* kc * cutoff >= 1/4 * 2^2 > peak mantissa: never reaches the cut-off */
        double prod = kc_m * k_m;
        double err = fma(kc_m, k_m, -prod);
        /* Near cancellation the first difference is exact (Sterbenz), leaving one rounding. */
        n = (p_m - ldexp(prod, shift)) - ldexp(err, shift);
    }
    if (n <= 0.0)
        return 0.0;
    int c_e;
    double c_m = frexp(n / k_m, &c_e);
    c_e += p_e - k_e;

    if (kq == 0.0) {
        if (kl == 0.0)
            return INFINITY;
        int l_e;
        double l_m = frexp(kl, &l_e);
        return ldexp(c_m / l_m, c_e - l_e);
    }

    /* r = r0 / (t + sqrt(t^2 + 1)) with r0 = sqrt(c / kq) and t = kl / (2 sqrt(kq c)): the
     * textbook (-kl + sqrt(kl^2 + 4 kq c)) / (2 kq) cancels catastrophically when kq is small,
     * this form adds only positive terms. */
    int q_e;
    double q_m = frexp(kq, &q_e);
    if ((c_e - q_e) % 2 != 0) {
        c_m *= 2.0;
        c_e -= 1;
    }
    double r0_m = sqrt(c_m / q_m);
    int r0_e = (c_e - q_e) / 2;
    double den = 1.0;
    if (kl > 0.0) {
        int l_e;
        double l_m = frexp(kl, &l_e);
        int t_e = l_e - (c_e + q_e) / 2;
        if (t_e > 60) /* t > 2^57: kq r^2 is below double precision, the light is linear */
            return ldexp(c_m / l_m, c_e - l_e);
        double t = ldexp(l_m / (2.0 * sqrt(c_m * q_m)), t_e);
        den = t + sqrt(t * t + 1.0);
    }
    return ldexp(r0_m / den, r0_e);
}

static float rng_range(rng *r, float lo, float hi)
{
    float v = (float)(lo + rng_unit(r) * ((double)hi - lo));
    return fminf(fmaxf(v, lo), hi); /* rounding must not step outside the box */
}

/* HSV with value 1 to RGB: the largest component is exactly 1. */
static void hue_to_rgb(double hue, double saturation, vec3 out)
{
    double h6 = hue * 6.0;
    int sector = (int)h6 % 6;
    double f = h6 - floor(h6);
    float v = 1.0f;
    float p = (float)(1.0 - saturation);
    float q = (float)(1.0 - saturation * f);
    float t = (float)(1.0 - saturation * (1.0 - f));
    float rgb[6][3] = {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}};
    glm_vec3_copy(rgb[sector], out);
}

static void widen_bounds(vec3 lo, vec3 hi, const vec3 p)
{
    for (int a = 0; a < 3; a++) {
        lo[a] = fminf(lo[a], p[a]);
        hi[a] = fmaxf(hi[a], p[a]);
    }
}

void light_generate_bounds(const scene *s, float lo[3], float hi[3])
{
    if (s->object_count == 0) {
        for (int a = 0; a < 3; a++) {
            lo[a] = s->camera.target[a] - 5.0f;
            hi[a] = s->camera.target[a] + 5.0f;
        }
        lo[1] = hi[1] = s->camera.target[1];
    } else {
        glm_vec3_copy(s->objects[0].position, lo);
        glm_vec3_copy(s->objects[0].position, hi);
        for (int i = 0; i < s->object_count; i++) {
            const scene_object *o = &s->objects[i];
            /* The object's own size too, so a single large object does not swallow every light:
             * built-in cubes and planes reach 0.5 from their origin, spheres and models about 1. */
            bool unit_half = o->mesh >= 0 && o->mesh < s->mesh_count &&
                             (s->meshes[o->mesh].kind == SCENE_MESH_CUBE || s->meshes[o->mesh].kind == SCENE_MESH_PLANE);
            float reach = unit_half ? 0.5f : 1.0f;
            if (o->has_base) { /* a model's part: its node matrix may move it far from `position` */
                mat4 world;
                scene_object_world_at(s, i, 0.0f, world);
                for (int c = 0; c < 8; c++) {
                    vec4 corner = {c & 1 ? reach : -reach, c & 2 ? reach : -reach, c & 4 ? reach : -reach, 1.0f};
                    vec4 placed;
                    glm_mat4_mulv(world, corner, placed);
                    widen_bounds(lo, hi, placed);
                }
                continue;
            }
            for (int k = -1; k < o->key_count; k++) {
                const float *p = k < 0 ? o->position : o->keys[k].position;
                vec3 a, b;
                for (int c = 0; c < 3; c++) {
                    a[c] = p[c] - fabsf(o->scale[c]) * reach;
                    b[c] = p[c] + fabsf(o->scale[c]) * reach;
                }
                widen_bounds(lo, hi, a);
                widen_bounds(lo, hi, b);
            }
        }
        for (int a = 0; a < 3; a++) {
            float margin = 0.1f * (hi[a] - lo[a]);
            lo[a] -= margin;
            hi[a] += margin;
        }
    }
    lo[1] = 0.1f;
    hi[1] = fmaxf(hi[1] + 1.0f, 1.1f);
}

double light_generate_radius(const float lo[3], const float hi[3], int count)
{
    double extent = fmax(fmax(hi[0] - lo[0], hi[1] - lo[1]), hi[2] - lo[2]);
    double r = count > 0 ? extent * 1.5 / sqrt((double)count) : extent;
    return fmin(fmax(r, 0.5), fmax(extent, 0.5));
}

bool light_generate(scene *s, int count, uint32_t seed)
{
    if (count < 0) {
        log_error("light_generate: negative light count %d", count);
        return false;
    }
    scene_light *lights = NULL;
    if (count > 0) {
        lights = calloc((size_t)count, sizeof *lights);
        if (!lights) {
            log_error("light_generate: out of memory for %d lights", count);
            return false;
        }
    }

    vec3 lo, hi;
    light_generate_bounds(s, lo, hi);
    double radius = light_generate_radius(lo, hi, count);
    /* kc = 1, kl = 0, peak = 1: the radius is sqrt((1 / cutoff - 1) / kq). */
    float kq = (float)((1.0 / LIGHT_DEFAULT_CUTOFF - 1.0) / (radius * radius));

    rng r = rng_seed(seed);
    for (int i = 0; i < count; i++) {
        scene_light *l = &lights[i];
        for (int a = 0; a < 3; a++)
            l->position[a] = rng_range(&r, lo[a], hi[a]);
        double hue = rng_unit(&r);
        double saturation = 0.7 + 0.3 * rng_unit(&r);
        hue_to_rgb(hue, saturation, l->color);
        l->intensity = 1.0f;
        l->kc = 1.0f;
        l->kl = 0.0f;
        l->kq = kq;
    }

    for (int i = 0; i < s->light_count; i++)
        free(s->lights[i].keys);
    free(s->lights);
    s->lights = lights;
    s->light_count = count;
    s->light_capacity = count;
    return true;
}
