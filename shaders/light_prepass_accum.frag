#version 330 core
// light_prepass_accum.frag - chapter 15's light accumulation: one full-screen triangle; each pixel
// reads the thin pass's normal, shininess and depth, finds its cluster (chapter 11's lists) and adds
// up its lights' two terms, before any material (shade_light_terms): the diffuse light
// sum f E (n.l) and the specular light sum f E (n.h)^s. Written once, no blending:
//   target 0: diffuse RGB, and the specular sum's luminance in A (the mono light buffer)
//   target 1: the specular sum's RGB (--specular rgb only; mono leaves it unattached)
// LIGHT_PREPASS_PBR (a scene with metallic-roughness materials, docs/15_light_prepass.md "Metallic-
// roughness"): the thin target holds half floats, and a metallic-roughness pixel (negative shininess)
// sums three terms instead, each linear in what the second pass knows (F0, base, metallic):
//   target 0: C = (1 - w(n.v)) sum f E (n.l) (1 - w(n.l))   the diffuse, w(x) = (1 - x)^5
//   target 1: A = sum f E (n.l) pi D V (1 - w(v.h))          the specular, times F0 later
//   target 2: B = sum f E (n.l) pi D V w(v.h)                the specular's Fresnel rise, times 1
// A Blinn-Phong pixel of the same scene writes its two sums into targets 0 and 1 and 0 into target 2.
// SHADOWS (--shadows N, chapter 14's atlas): every term of a light times how much of it reaches p.
#include "shading.glsl"
#include "material_pbr.glsl"
#include "light_prepass.glsl"
#include "gbuffer_read.glsl"
#include "heat.glsl"
#include "clusters.glsl"

uniform sampler2D u_thin_normal; // RGBA8: light_prepass_thin.frag's packed normal and shininess
uniform sampler2D u_thin_depth;  // the thin pass's depth

layout(location = 0) out vec4 o_diffuse;
layout(location = 1) out vec4 o_specular;
#ifdef LIGHT_PREPASS_PBR
layout(location = 2) out vec4 o_fresnel;

// The largest finite half float: a mirror-like highlight (GGX's peak is 1 / (pi alpha^2), 7.8e4 at
// the clamped roughness) must not become an infinity, which F0 = 0 (a black metal) would turn to NaN.
const float HALF_MAX = 65504.0;

// One light's three terms at a metallic-roughness pixel (pbr_brdf's factors that know no material).
void shade_light_terms_pbr(int i, vec3 p, vec3 n, vec3 v, float ndv, float a2, inout vec3 C, inout vec3 A,
                           inout vec3 B)
{
    light_data L = light_fetch(i);
    light_reach r;
    if (!shade_light_reach(L, light_fetch_cone(i), p, n, v, -1.0, r))
        return;
    vec3 e = light_visible(r.f * L.radiance * r.ndl, i, L.position, p, n); // as shade_light_terms does
    vec3 h = safe_normalize(r.l + v, n);
    float ndl = clamp(r.ndl, 0.0, 1.0);
    float D, V;
    pbr_distribution_visibility(ndl, ndv, clamp(dot(n, h), 0.0, 1.0), a2, D, V);
    float w = pow(1.0 - clamp(dot(v, h), 0.0, 1.0), 5.0);
    vec3 s = e * (PI * D * V);
    C += e * (1.0 - pow(1.0 - ndl, 5.0));
    A += s * (1.0 - w);
    B += s * w;
}
#endif

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(u_thin_depth, pixel, 0).r;
    o_diffuse = o_specular = vec4(0.0);
#ifdef LIGHT_PREPASS_PBR
    o_fresnel = vec4(0.0);
#endif
    if (gbuffer_is_background(depth))
        return;
    vec4 t = texelFetch(u_thin_normal, pixel, 0);
    vec3 p = gbuffer_position(pixel, depth);
#ifdef LIGHT_PREPASS_PBR
    vec3 n = octahedral_decode(t.xy);
    float shininess = t.z; // as the material gave it: -1 - roughness, or Blinn-Phong's exponent
#else
    vec3 n = octahedral_decode_codes(gbuffer_unpack_12_12(t.xyz), 2047.0);
    float shininess = 1.0 + 255.0 * t.w; // shininess_store undone
#endif
    vec3 v = safe_normalize(u_eye - p, n);
    ivec2 range = cluster_range(cluster_index(gl_FragCoord.xy, cluster_view_depth(p)));
    vec3 diffuse = vec3(0.0), specular = vec3(0.0);
    int count = cluster_loop_count(range);
#ifdef LIGHT_PREPASS_PBR
    if (material_is_pbr(shininess)) {
        float ndv = pbr_ndv(n, v), a2 = pbr_alpha2(shininess);
        vec3 fresnel = vec3(0.0);
        for (int k = 0; k < count; k++)
            shade_light_terms_pbr(range.y < 0 ? k : texelFetch(u_cluster_lights, range.x + k).r, p, n, v, ndv, a2,
                                  diffuse, specular, fresnel);
        diffuse *= 1.0 - pow(1.0 - ndv, 5.0);
        o_diffuse = vec4(min(diffuse, HALF_MAX), 0.0);
        o_specular = vec4(min(specular, HALF_MAX), 1.0);
        o_fresnel = vec4(min(fresnel, HALF_MAX), 1.0);
        return;
    }
#endif
    for (int k = 0; k < count; k++)
        shade_light_terms(range.y < 0 ? k : texelFetch(u_cluster_lights, range.x + k).r, p, n, v, shininess,
                          diffuse, specular);
    o_diffuse = vec4(diffuse, dot(specular, LUMINANCE));
    o_specular = vec4(specular, 1.0);
}
