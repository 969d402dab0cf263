/* shader_layout.h - every number the C code and the shaders must agree on, written once.
 *
 * Each X(NAME, VALUE) below is the C constant SHADER_NAME, and the program loader (gl_program.c)
 * injects `#define SHADER_NAME VALUE` into every shader after its #version line, so a shader reads
 * SHADER_LIGHT_TEXELS exactly as the C code that fills the texture does.
 *
 *   light texels (RGBA32F):  position.xyz + radius, radiance + cos(outer), attenuation kc kl kq +
 *                            cos(inner), spot direction xyz (unit) + 0; a point light is a spot
 *                            without a cone: direction 0, both cosines -1 (shaders/shading.glsl)
 *   object texels (RGBA32F): world matrix columns 0-3, normal matrix columns 4-6,
 *                            albedo + specular 7, shininess + opacity 8 (x, y), map layers 9,
 *                            emissive + its map's layer 10 (a metallic-roughness material: specular is
 *                            its metallic, shininess -1 - roughness; shaders/shading.glsl)
 *   views and tone maps:     the values of the u_view and u_tonemap uniforms; the overdraw view's
 *                            count per fragment and the heat map's saturation count
 *   texture units:           where each pass binds its textures (GLSL 3.30 has no binding layout)
 *   G-buffer encodings:      how a layout's RT1 holds the normal (common/render/gbuffer.h lists the layouts)
 *   visibility ids (chapter 16):  one R32UI per pixel, the object + 1 above VIS_TRIANGLE_BITS bits of
 *                            triangle (its index in its mesh, gl_PrimitiveID)
 *   shadow tables (chapter 14, shaders/shadows.glsl): per light one texel (first tile or -1, faces 1 or 6,
 *                            normal offset in texels, 0); per tile SHADOW_TILE_TEXELS
 */
#ifndef COMMON_SHADER_LAYOUT_H
#define COMMON_SHADER_LAYOUT_H

#define SHADER_LAYOUT(X)                                                                                   \
    X(LIGHT_TEXELS, 4)                                                                                     \
    X(LIGHT_TEXEL_SPOT, 3) /* the spot's direction; its cosines are the w of texels 1 and 2 */             \
    X(OBJECT_TEXELS, 11)                                                                                   \
    X(OBJECT_TEXEL_NORMAL, 4)                                                                              \
    X(OBJECT_TEXEL_MATERIAL, 7)                                                                            \
    X(OBJECT_TEXEL_SHININESS, 8)                                                                           \
    X(OBJECT_TEXEL_OPACITY, 8) /* the y of the shininess texel: the material's opacity (chapter 12) */     \
    X(OBJECT_TEXEL_MAPS, 9)     /* chapter 18: layers of base, metal-rough, normal, occlusion; -1 none */  \
    X(OBJECT_TEXEL_EMISSIVE, 10) /* chapter 18: emissive rgb, its map's layer (-1 none) */                 \
    X(VIEW_LIT, 0)                                                                                         \
    X(VIEW_RING, 1)                                                                                        \
    X(VIEW_OVERDRAW, 2)                                                                                    \
    X(GBUFFER_VIEW_ALBEDO, 0)                                                                              \
    X(GBUFFER_VIEW_NORMAL, 1)                                                                              \
    X(GBUFFER_VIEW_DEPTH, 2)                                                                               \
    X(GBUFFER_VIEW_SPECULAR, 3)                                                                            \
    X(GBUFFER_VIEW_NORMAL_RAW, 4)   /* the decoded normal as floats (the benchmark's probe) */             \
    X(GBUFFER_VIEW_POSITION_RAW, 5) /* the position rebuilt from depth, as floats (the same) */            \
    X(GBUFFER_NORMAL_HALF, 0)   /* RT1 RGBA16F: octahedral x, y as half floats, specular, shininess */     \
    X(GBUFFER_NORMAL_BYTES, 1)  /* RT1 RGBA8: octahedral 2 x 8 bits in r, g; shininess in a */             \
    X(GBUFFER_NORMAL_PACKED, 2) /* RT1 RGBA8: octahedral 2 x 12 bits packed in r, g, b; shininess in a */  \
    X(GBUFFER_NORMAL_SHORTS, 3) /* RT1 RGBA16: octahedral 2 x 16 bits in r, g; shininess in a */           \
    X(OVERDRAW_SCALE, 16)  /* the overdraw view adds 1 / 16 per lighting fragment */                       \
    X(HEAT_MAX, 16)        /* heat map (shaders/heat.glsl): 16 and more look alike */                      \
    X(TONEMAP_NONE, 0)                                                                                     \
    X(TONEMAP_EXPOSURE, 1)                                                                                 \
    X(TONEMAP_REINHARD, 2)                                                                                 \
    X(FALLOFF_HARD, 0)     /* 1 / (kc + kl d + kq d^2), cut to 0 at the radius */                           \
    X(FALLOFF_WINDOWED, 1) /* the same times (1 - (d / r)^4)^2: zero, with zero slope, at the radius */     \
    X(UNIT_LIGHTS, 0)                                                                                      \
    X(UNIT_LIGHT_LIST, 1)                                                                                  \
    X(UNIT_OBJECTS, 2)                                                                                     \
    X(UNIT_GBUFFER, 3) /* three units: albedo, normal, depth */                                           \
    X(UNIT_GBUFFER_EMISSIVE, 17) /* RT2, where the scene has emissive materials (gbuffer.h): past the maps */ \
    X(UNIT_LIGHT_INDEX, 6)                                                                                 \
    X(UNIT_IMAGE, 0)   /* a full-screen pass's one input texture */                                    \
    X(UNIT_SHADOW_ATLAS, 8)  /* chapter 14: the depth atlas (a comparison sampler) */                       \
    X(UNIT_SHADOW_LIGHTS, 9) /* per light: first tile, faces, normal offset, 0 */                          \
    X(UNIT_SHADOW_TILES, 10) /* per tile: its light-space matrix, its place in the atlas */                \
    X(SHADOW_TILE_TEXELS, 5) /* matrix columns 0-3, then (x, y, size in texels, tan of half the field) */  \
    X(SHADOW_MAX_PCF, 5)     /* the widest PCF kernel: 5 x 5 taps */                                   \
    X(UNIT_VIS_MESHES, 11)   /* chapter 16: vertices, indices, object -> mesh: three units */           \
    X(MESH_VERTEX_FLOATS, 12) /* position xyz, normal xyz, uv, tangent xyzw (common/scene/mesh_data.h) */\
    X(VIS_TRIANGLE_BITS, 20) /* chapter 16's id: (object + 1) << 20 | triangle; 0 is the background */ \
    X(UNIT_AO, 14)           /* chapter 17: the ambient occlusion the ambient term reads */            \
    X(UNIT_MAPS_SRGB, 15)    /* chapter 18: the colour images' array (gpu_textures.h), and beside it */ \
    X(UNIT_MAPS_LINEAR, 16)  /* the data images': past every other unit (chapter 16 reads both) */     \
    X(AO_MAX_SAMPLES, 64)    /* the most SSAO kernel directions (--ao-samples) */                      \
    X(AO_STEPS, 4)           /* points marched along each kernel direction, r/4 apart */               \
    X(AO_NOISE_SIZE, 4)      /* the rotation noise tile: 4 x 4 pixels, removed by a blur that wide */  \
    X(UNIT_IBL_BRDF, 12)     /* chapter 19: the split-sum table (n.v, roughness) -> F0 scale, bias */  \
    X(UNIT_IBL_PROBES, 18)   /* chapter 19: the picked probes' prefiltered cubes, IBL_MAX_PICKED units \
                                past RT2 (chapter 14's shadow units stay free: --shadows N) */    \
    X(IBL_MAX_PICKED, 4)     /* chapter 19: the probes blended per pixel, picked per frame */          \
    X(IBL_SH_COEFFS, 9)      /* chapter 19: spherical harmonics coefficients per probe (bands 0-2) */

#define SHADER_LAYOUT_ENUM(name, value) SHADER_##name = (value),
enum { SHADER_LAYOUT(SHADER_LAYOUT_ENUM) };
#undef SHADER_LAYOUT_ENUM

#endif
