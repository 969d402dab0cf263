/* gpu_textures.h - the scene's material images on the GPU: two texture arrays, so that objects with
 * different textures still share one draw call (docs/18_pbr_materials.md, "One array per colour space").
 *
 *   gpu_textures_create(s, out)          every image of s.textures as a layer of one of two arrays:
 *                                        GL_SRGB8_ALPHA8 for colour (base colour, emissive), GL_RGBA8
 *                                        for data (metal-rough, normal, occlusion); each array's layers
 *                                        are square, the side of its largest image rounded up to a power
 *                                        of two (at most GPU_TEXTURES_SIDE_MAX and the context's limit),
 *                                        smaller images resampled up to it; mipmapped, trilinear, and
 *                                        anisotropic (GPU_TEXTURES_ANISOTROPY) where the context has it
 *   gpu_textures_set_anisotropy(n)       --anisotropy: at most n samples along a footprint from now on
 *                                        (1: trilinear only); default GPU_TEXTURES_ANISOTROPY
 *   gpu_textures_destroy(t)
 *   gpu_textures_bind(t, program)        u_maps_srgb and u_maps_linear on units SHADER_UNIT_MAPS_SRGB and
 *                                        SHADER_UNIT_MAPS_LINEAR
 *
 * layer[i] is scene texture i's layer in its array; a scene without images of a kind gets a 1x1
 * white array for it, so the samplers are always complete.
 */
#ifndef COMMON_GPU_TEXTURES_H
#define COMMON_GPU_TEXTURES_H

#include "gl_util.h"
#include "scene.h"

#define GPU_TEXTURES_SIDE_MAX 2048 /* an 8k image is 256 MiB a layer; 2048 is 16 MiB, 21 with mipmaps */
#define GPU_TEXTURES_ANISOTROPY 8.0f

typedef struct gpu_textures {
    GLuint srgb, linear; /* GL_TEXTURE_2D_ARRAY */
    int srgb_side, linear_side, srgb_layers, linear_layers;
    int *layer;          /* per scene texture */
    float anisotropy;    /* 1 where the context has no anisotropic filtering */
} gpu_textures;

bool gpu_textures_create(const scene *s, gpu_textures *out);
void gpu_textures_set_anisotropy(float most);
void gpu_textures_destroy(gpu_textures *t);
void gpu_textures_bind(const gpu_textures *t, GLuint program);

#endif
