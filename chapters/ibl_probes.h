/* ibl_probes.h - chapter 19's probes on the GPU: each captures the scene around it into a cube map
 * with chapter 00's forward renderer, then its irradiance (9 spherical-harmonics coefficients,
 * projected on the CPU) and its prefiltered specular mip chain; one split-sum table for all.
 *
 *   ibl_probes_create(ibl, desc)        the programs, the capture target and the split-sum table
 *   ibl_probes_capture(ibl, gs)         (again) every probe of gs's scene, at gs's time
 *   ibl_probes_pick(ibl, eye)           the IBL_MAX_PICKED most important probes for this frame
 *   ibl_probes_bind(program, ibl)       their uniforms and textures on a program built with
 *                                       IMAGE_BASED_LIGHT (a gl_program_extra's bind)
 *   ibl_probes_bytes(ibl)               the GPU memory the probes and the table take
 *   ibl_probes_destroy(ibl)
 */
#ifndef CHAPTERS_IBL_PROBES_H
#define CHAPTERS_IBL_PROBES_H

#include "forward.h"
#include "gpu_scene.h"

typedef struct ibl_probe {
    GLuint radiance;  /* RGBA16F cube, size^2 per face, with its mip chain (the capture) */
    GLuint specular;  /* RGBA16F cube, IBL levels: roughness = level / (levels - 1) */
    float sh[SHADER_IBL_SH_COEFFS][3];
    scene_probe sphere;
} ibl_probe;

typedef struct ibl_desc {
    int size;             /* capture face size (a power of two, >= 16) */
    int levels;           /* prefiltered mip levels, the last one size >> (levels - 1) texels */
    int samples;          /* GGX samples per prefiltered texel */
    int brdf_size, brdf_samples;
} ibl_desc;

typedef struct ibl {
    ibl_desc desc;
    ibl_probe probes[SCENE_PROBE_MAX];
    int count;
    int picked[SHADER_IBL_MAX_PICKED], picked_count;
    GLuint brdf;  /* RG16F brdf_size^2: A, B */
    GLuint prefilter_program, brdf_program, framebuffer, depth;
    forward capture; /* chapter 00's forward renderer, with the constant ambient */
    bool on;
    double capture_ms; /* the last ibl_probes_capture, on the CPU's clock after glFinish */
} ibl;

bool ibl_probes_create(ibl *b, const ibl_desc *desc);
bool ibl_probes_capture(ibl *b, const gpu_scene *gs);
void ibl_probes_pick(ibl *b, const float eye[3]);
void ibl_probes_bind(GLuint program, const void *ibl_state);
long ibl_probes_bytes(const ibl *b);
void ibl_probes_destroy(ibl *b);

#endif
