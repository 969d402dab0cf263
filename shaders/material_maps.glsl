// material_maps.glsl - a metallic-roughness material's images (chapter 18, docs/18_pbr_materials.md),
// applied where a surface is first known: forward.frag, forward_plus.frag and gbuffer.frag, after
// forward.vert. Include after "shading.glsl". A Blinn-Phong material, and a metallic-roughness one
// without maps, comes back exactly as given. Built for a scene whose materials sample no image
// (MATERIAL_MAPS undefined, scene_features.glsl) nothing is sampled and no sampler declared; for one
// that gives off no light (MATERIAL_EMISSIVE undefined) the emissive is 0, read from nowhere.
#ifndef MATERIAL_MAPS_GLSL
#define MATERIAL_MAPS_GLSL

#ifdef MATERIAL_MAPS
uniform sampler2DArray u_maps_srgb;   // base colour, emissive (material_emissive): GL_SRGB8_ALPHA8, sampled as linear values
uniform sampler2DArray u_maps_linear; // metal-rough, normal, occlusion: GL_RGBA8, sampled as stored
#endif

// MATERIAL_MAPS_GRAD is defined by chapter 16's visibility_shade.frag above its #include, and by no
// program the loader builds with defines: the usual case, forward.vert's varyings, comes first.
#ifndef MATERIAL_MAPS_GRAD
#ifdef MATERIAL_MAPS
in vec2 v_uv;
in vec4 v_tangent;
flat in vec4 v_maps;     // layers: base, metal-rough, normal, occlusion; -1 for none
#endif
#ifdef MATERIAL_EMISSIVE
flat in vec4 v_emissive; // emissive rgb, its map's layer
#endif
#define MAP_SAMPLE(sampler, uvw) texture(sampler, uvw)
#else
// Chapter 16's shading pass has no rasterised varyings: it rebuilds the texture coordinate and its
// screen derivatives from the triangle, sets these two, and the maps are read with textureGrad, so a
// texture's mip level is chosen from the same footprint as the rasterizer's implicit derivatives.
vec2 g_map_dx, g_map_dy;
#define MAP_SAMPLE(sampler, uvw) textureGrad(sampler, uvw, g_map_dx, g_map_dy)
#endif

// A normal-map texel (0..1 per channel) to a world-space normal. The tangent is made perpendicular to
// n here (interpolation bends it); a texel that decodes below the surface (z <= 0, such as (0, 0, 0),
// which a broken or blank map holds) keeps the surface's own normal instead.
vec3 material_normal_from_map(vec3 n, vec4 tangent, vec3 texel)
{
    vec3 m = texel * 2.0 - 1.0;
    if (m.z <= 1e-3)
        return n;
    vec3 t = safe_normalize(tangent.xyz - n * dot(n, tangent.xyz), vec3(0.0));
    if (t == vec3(0.0))
        return n; // no usable tangent: the map cannot be oriented
    vec3 b = (tangent.w < 0.0 ? -1.0 : 1.0) * cross(n, t);
    return safe_normalize(m.x * t + m.y * b + m.z * n, n);
}

// The maps times the material's factors, as glTF 2.0 defines them: base colour times the base map,
// roughness times the map's G, metallic times its B; the normal from the normal map; occlusion from
// the occlusion map's R (1 without one).
void material_apply_maps_at(vec2 uv, vec4 tangent, vec4 maps, inout vec3 albedo, inout float specular,
                            inout float shininess, inout vec3 n, out float occlusion)
{
    occlusion = 1.0;
#ifdef MATERIAL_MAPS
    if (!material_is_pbr(shininess))
        return;
    if (maps.x >= 0.0)
        albedo *= MAP_SAMPLE(u_maps_srgb, vec3(uv, maps.x)).rgb;
    if (maps.y >= 0.0) {
        vec4 mr = MAP_SAMPLE(u_maps_linear, vec3(uv, maps.y));
        specular *= mr.b;
        shininess = -1.0 - (-1.0 - shininess) * mr.g;
    }
    if (maps.z >= 0.0)
        n = material_normal_from_map(n, tangent, MAP_SAMPLE(u_maps_linear, vec3(uv, maps.z)).rgb);
    if (maps.w >= 0.0)
        occlusion = MAP_SAMPLE(u_maps_linear, vec3(uv, maps.w)).r;
#endif
}

// The light the surface gives off itself, linear radiance: the emissive factor times the emissive
// map's texel (colour data: sRGB, read back as linear) where there is a map, as glTF 2.0 defines it.
// emissive is the object's texel SHADER_OBJECT_TEXEL_EMISSIVE: rgb, and the map's layer (-1 none);
// a Blinn-Phong material's is 0 (common/gl/gpu_scene.c). Added once per pixel, where the ambient is.
vec3 material_emissive_at(vec2 uv, vec4 emissive)
{
#ifndef MATERIAL_EMISSIVE
    return vec3(0.0);
#else
    vec3 e = emissive.rgb;
#ifdef MATERIAL_MAPS
    if (emissive.w >= 0.0 && e != vec3(0.0))
        e *= MAP_SAMPLE(u_maps_srgb, vec3(uv, emissive.w)).rgb;
#endif
    return e;
#endif
}

#ifndef MATERIAL_MAPS_GRAD
// The surface the rasterizer interpolated (forward.vert's varyings).
void material_apply_maps(inout vec3 albedo, inout float specular, inout float shininess, inout vec3 n,
                         out float occlusion)
{
#ifdef MATERIAL_MAPS
    material_apply_maps_at(v_uv, v_tangent, v_maps, albedo, specular, shininess, n, occlusion);
#else
    occlusion = 1.0;
#endif
}

vec3 material_emissive()
{
#ifdef MATERIAL_EMISSIVE
#ifdef MATERIAL_MAPS
    return material_emissive_at(v_uv, v_emissive);
#else
    return material_emissive_at(vec2(0.0), v_emissive);
#endif
#else
    return vec3(0.0);
#endif
}
#endif

#endif
