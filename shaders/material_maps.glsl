// material_maps.glsl - a metallic-roughness material's images (chapter 18, docs/18_pbr_materials.md),
// applied where a surface is first known: forward.frag, forward_plus.frag and gbuffer.frag, after
// forward.vert. Include after "shading.glsl". A Blinn-Phong material, and a metallic-roughness one
// without maps, comes back exactly as given.
#ifndef MATERIAL_MAPS_GLSL
#define MATERIAL_MAPS_GLSL

uniform sampler2DArray u_maps_srgb;   // base colour, emissive (material_emissive): GL_SRGB8_ALPHA8, sampled as linear values
uniform sampler2DArray u_maps_linear; // metal-rough, normal, occlusion: GL_RGBA8, sampled as stored

// MATERIAL_MAPS_GRAD is defined by chapter 16's visibility_shade.frag above its #include, and by no
// program the loader builds with defines: the usual case, forward.vert's varyings, comes first.
#ifndef MATERIAL_MAPS_GRAD
in vec2 v_uv;
in vec4 v_tangent;
flat in vec4 v_maps;     // layers: base, metal-rough, normal, occlusion; -1 for none
flat in vec4 v_emissive; // emissive rgb, its map's layer
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
}

// The light the surface gives off itself, linear radiance: the emissive factor times the emissive
// map's texel (colour data: sRGB, read back as linear) where there is a map, as glTF 2.0 defines it.
// emissive is the object's texel SHADER_OBJECT_TEXEL_EMISSIVE: rgb, and the map's layer (-1 none);
// a Blinn-Phong material's is 0 (common/gl/gpu_scene.c). Added once per pixel, where the ambient is.
vec3 material_emissive_at(vec2 uv, vec4 emissive)
{
    vec3 e = emissive.rgb;
    if (emissive.w >= 0.0 && e != vec3(0.0))
        e *= MAP_SAMPLE(u_maps_srgb, vec3(uv, emissive.w)).rgb;
    return e;
}

#ifndef MATERIAL_MAPS_GRAD
// The surface the rasterizer interpolated (forward.vert's varyings).
void material_apply_maps(inout vec3 albedo, inout float specular, inout float shininess, inout vec3 n,
                         out float occlusion)
{
    material_apply_maps_at(v_uv, v_tangent, v_maps, albedo, specular, shininess, n, occlusion);
}

vec3 material_emissive()
{
    return material_emissive_at(v_uv, v_emissive);
}
#endif

#endif
