/* split_sum_reference.h - chapter 19's split sum against the integral it approximates: the specular
 * reflection of a probe's captured cube map under the full GGX BRDF (D, Smith-Schlick G with
 * k = alpha / 2, Schlick F), by Monte Carlo in double precision on the CPU, from what the GPU made
 * and the caller read back (probe_readback.h): the capture, the prefiltered levels and the split-sum
 * table. hard.ibl_reference (tests/ibl/) and the benchmark's --ambient-sweep both measure with it.
 *
 * For one roughness, SPLIT_SUM_NORMALS normals spread over the sphere x SPLIT_SUM_VIEWS views
 * (n.v = 1, 0.75, 0.5, 0.25), the integral with `samples` importance-sampled half vectors (65,536
 * in the test) against the split sum, prefiltered(r) (F0 A + B), looked up along the mirror
 * direction and along the chapter's dominant direction (shaders/ibl.glsl's ibl_dominant); the error
 * is relative, in luminance.
 *
 *   split_sum_error(probe, level, f0, samples, out)  the errors of prefiltered level `level`
 *                                                    (roughness level / (levels - 1))
 *   split_sum_cube_sample(level, d, out)             bilinear within the face d falls on (clamped
 *                                                    at its edges), as a lookup without seams
 *   split_sum_luminance(c)
 *   split_sum_normal(i, n)                           normal i of the spread (a Fibonacci spiral)
 */
#ifndef TOOLS_SPLIT_SUM_REFERENCE_H
#define TOOLS_SPLIT_SUM_REFERENCE_H

enum { SPLIT_SUM_NORMALS = 12, SPLIT_SUM_VIEWS = 4, SPLIT_SUM_MAX_LEVELS = 16 };

/* One cube map level read back: 6 faces of size^2 RGBA floats. */
typedef struct cube_level {
    int size;
    float *faces[6];
} cube_level;

/* A probe as read back: its capture (level 0), its prefiltered chain and the split-sum table. */
typedef struct split_sum_probe {
    cube_level radiance;
    cube_level levels[SPLIT_SUM_MAX_LEVELS];
    int level_count;
    float *table; /* RG floats, table_size^2: A and B over (n.v, roughness) */
    int table_size;
} split_sum_probe;

typedef struct split_sum_errors {
    double roughness;
    double mirror_mean, mirror_max;     /* looked up along the mirror direction */
    double dominant_mean, dominant_max; /* along the dominant direction: what the chapter does */
    double head_on_mean;                /* dominant, n.v = 1 only */
} split_sum_errors;

void split_sum_error(const split_sum_probe *probe, int level, double f0, int samples, split_sum_errors *out);
void split_sum_cube_sample(const cube_level *c, const double d[3], double out[3]);
double split_sum_luminance(const double c[3]);
void split_sum_normal(int i, double n[3]);

#endif
