// shading_features.glsl - what a program adds to chapter 00's shading for its scene and its chapter,
// each from the file of the chapter that teaches it, and only where it is built for it:
//   material models   MATERIAL_BLINN_PHONG, MATERIAL_PBR (scene_features.glsl): material_is_pbr,
//                     material_highlight, material_light; a scene of one model compiles only that one
//                     (chapter 18's in material_pbr.glsl)
//   shadows           SHADOWS (chapter 14, shadows.glsl): light_visible, what of light i reaches p
//   ambient occlusion AMBIENT_OCCLUSION (chapter 17, ambient_occlusion.glsl): ambient_visibility
//   image-based light IMAGE_BASED_LIGHT (chapter 19, ibl.glsl): shade_ambient_at
// Without a feature its hook is the identity (1, the light unchanged, the constant ambient): the
// picture of the chapter before, and none of its instructions. Included once, by shading.glsl.

// ---- the material models ----
#ifdef MATERIAL_PBR
#include "material_pbr.glsl"
#endif

// A metallic-roughness material travels with a negative shininess (material_pbr.glsl). Built for one
// model, the answer is known and the other model's code is left out.
bool material_is_pbr(float shininess)
{
#if defined(MATERIAL_PBR) && defined(MATERIAL_BLINN_PHONG)
    return shininess < 0.0;
#elif defined(MATERIAL_PBR)
    return true;
#else
    return false;
#endif
}

// Blinn-Phong's highlight (n.h)^shininess; none for a metallic-roughness material.
float material_highlight(vec3 n, vec3 h, float shininess)
{
    return material_is_pbr(shininess) ? 0.0 : pow(max(dot(n, h), 0.0), shininess);
}

// What light L (reach r, radiance E) brings to the surface, in its material's model.
vec3 material_light(light_reach r, vec3 radiance, vec3 n, vec3 v, vec3 albedo, float specular, float shininess)
{
#ifdef MATERIAL_PBR
    if (material_is_pbr(shininess))
        return pbr_light(r, radiance, n, v, albedo, specular, shininess);
#endif
    return blinn_phong_light(r, radiance, albedo, specular);
}

// ---- what of light i reaches p ----
#ifdef SHADOWS
#include "shadows.glsl"
#endif

// c, light i's contribution at p, times the fraction of the light that reaches p: looked up in
// chapter 14's atlas, and only where the light adds something.
vec3 light_visible(vec3 c, int i, vec3 light_position, vec3 p, vec3 n)
{
#ifdef SHADOWS
    if (c != vec3(0.0))
        c *= shadow_visibility(i, light_position, p, n);
#endif
    return c;
}

// ---- the ambient light ----
// fragment only: AMBIENT_OCCLUSION
#ifdef AMBIENT_OCCLUSION
#include "ambient_occlusion.glsl"
#endif

// The share of the ambient light that reaches this pixel: chapter 17's occlusion, or 1.
float ambient_visibility()
{
#ifdef AMBIENT_OCCLUSION
    return ambient_occlusion();
#else
    return 1.0;
#endif
}

#ifdef IMAGE_BASED_LIGHT
#include "ibl.glsl"
#endif

// The ambient term where the surface is known: shade_ambient() times the material's occlusion, or in
// a program built with IMAGE_BASED_LIGHT (chapter 19) the light of the probes around p (ibl.glsl).
vec3 shade_ambient_at(vec3 p, vec3 n, vec3 v, vec3 albedo, float specular, float shininess, float occlusion)
{
#ifdef IMAGE_BASED_LIGHT
    return occlusion * ibl_ambient(p, n, v, albedo, specular, shininess);
#else
    return shade_ambient(albedo * occlusion);
#endif
}
