// ibl.glsl - chapter 19's ambient term (programs built with IMAGE_BASED_LIGHT; shading_features.glsl
// includes it): the light of the probes picked this frame, blended per pixel, in place of the constant
// ambient. docs/19_image_based_light.md has the formulas; chapters/ibl_probes.c sets the uniforms.
//   diffuse:  albedo * E(n) / pi, E from each probe's 9 spherical-harmonics coefficients
//   specular: prefiltered(r', roughness) * (F0 A + B), F0 = the material's specular, A and B the
//             split-sum table at (n.v, roughness), roughness = (2 / (shininess + 2))^(1/4), r' the
//             mirror direction bent towards n (ibl_dominant)
//   blend:    w_i = (1 - (d_i / R_i)^2)^2 inside probe i's radius; sum w_i L_i / max(sum w_i, 1),
//             plus max(1 - sum w_i, 0) times the constant ambient (shade_ambient): outside every
//             probe's radius, the picture of chapter 11
#ifndef IBL_GLSL
#define IBL_GLSL

uniform bool u_ibl_on;
uniform int u_probe_count;                                  // picked: 0 to SHADER_IBL_MAX_PICKED
uniform vec4 u_probe_sphere[SHADER_IBL_MAX_PICKED];         // centre, radius
uniform vec3 u_probe_sh[SHADER_IBL_MAX_PICKED * SHADER_IBL_SH_COEFFS];
uniform samplerCube u_probe_specular0, u_probe_specular1, u_probe_specular2, u_probe_specular3;
uniform float u_probe_lods;                                 // the prefiltered cubes' last mip level
uniform sampler2D u_ibl_brdf;                               // (n.v, roughness) -> A, B

float ibl_weight(int i, vec3 p)
{
    vec3 d = p - u_probe_sphere[i].xyz;
    float x = 1.0 - dot(d, d) / (u_probe_sphere[i].w * u_probe_sphere[i].w);
    return x > 0.0 ? x * x : 0.0;
}

// E(n) / pi from probe i's coefficients (chapters/ibl_sh.c: ibl_sh_irradiance, the same sum).
vec3 ibl_irradiance(int i, vec3 n)
{
    int b = i * SHADER_IBL_SH_COEFFS;
    vec3 e = u_probe_sh[b] * 0.282095;
    e += (2.0 / 3.0) * 0.488603 * (u_probe_sh[b + 1] * n.y + u_probe_sh[b + 2] * n.z + u_probe_sh[b + 3] * n.x);
    e += 0.25 * (u_probe_sh[b + 4] * (1.092548 * n.x * n.y) + u_probe_sh[b + 5] * (1.092548 * n.y * n.z) +
                 u_probe_sh[b + 6] * (0.315392 * (3.0 * n.z * n.z - 1.0)) + u_probe_sh[b + 7] * (1.092548 * n.x * n.z) +
                 u_probe_sh[b + 8] * (0.546274 * (n.x * n.x - n.y * n.y)));
    return max(e, vec3(0.0));
}

float ibl_roughness(float shininess) { return pow(2.0 / (shininess + 2.0), 0.25); }

// The probes' two terms at p before the material, blended: irradiance (E / pi) and the prefiltered
// radiance; coverage = sum of the weights (0: outside every probe), and the probe weighing most.
struct ibl_terms {
    vec3 irradiance;
    vec3 prefiltered;
    float coverage;
    int strongest; // -1: none
};

// Where to read the prefiltered cube: the mirror direction bent towards n as the lobe widens
// (Lagarde and de Rousiers 2014): the real lobe leans to the normal, most at grazing angles.
vec3 ibl_dominant(vec3 n, vec3 v, float roughness)
{
    vec3 r = reflect(-v, n);
    float a = roughness * roughness, s = 1.0 - a;
    return normalize(mix(n, r, s * (sqrt(s) + a)));
}

// Probe slot i's share at p, added to t (weight w_i, its irradiance and its prefiltered radiance
// along r). GLSL 3.30 indexes an array of samplers only with a constant, so each slot has its own
// sampler, passed in: one lookup per slot, where a branch per sampler would cost four on a SIMD rasteriser.
void ibl_add(int i, samplerCube specular, vec3 p, vec3 n, vec3 r, float lod, inout ibl_terms t, inout float best)
{
    if (i >= u_probe_count)
        return;
    float w = ibl_weight(i, p);
    if (w <= 0.0)
        return;
    t.irradiance += w * ibl_irradiance(i, n);
    t.prefiltered += w * textureLod(specular, r, lod).rgb;
    t.coverage += w;
    if (w > best)
        best = w, t.strongest = i;
}

ibl_terms ibl_gather(vec3 p, vec3 n, vec3 v, float roughness)
{
    ibl_terms t = ibl_terms(vec3(0.0), vec3(0.0), 0.0, -1);
    vec3 r = ibl_dominant(n, v, roughness);
    float lod = roughness * u_probe_lods, best = 0.0;
    ibl_add(0, u_probe_specular0, p, n, r, lod, t, best);
    ibl_add(1, u_probe_specular1, p, n, r, lod, t, best);
    ibl_add(2, u_probe_specular2, p, n, r, lod, t, best);
    ibl_add(3, u_probe_specular3, p, n, r, lod, t, best);
    float norm = max(t.coverage, 1.0);
    t.irradiance /= norm, t.prefiltered /= norm;
    return t;
}

// The split sum's table at (n.v, roughness): F0's scale and bias.
vec2 ibl_brdf(vec3 n, vec3 v, float roughness)
{
    return texture(u_ibl_brdf, vec2(clamp(dot(n, v), 0.0, 1.0), roughness)).rg;
}

// The ambient term: diffuse from the irradiance, specular from the prefiltered cube with the split
// sum; the uncovered rest, the constant ambient. A Blinn-Phong material: F0 its specular, roughness
// from its shininess; a metallic-roughness one (chapter 18): F0 = mix(0.04, base, metallic), the
// diffuse base * (1 - metallic), its own roughness.
vec3 ibl_ambient(vec3 p, vec3 n, vec3 v, vec3 albedo, float specular, float shininess)
{
    if (!u_ibl_on)
        return shade_ambient(albedo);
    bool pbr = material_is_pbr(shininess);
    float roughness = pbr ? clamp(-1.0 - shininess, 0.0, 1.0) : ibl_roughness(shininess);
    vec3 f0 = pbr ? mix(vec3(0.04), albedo, specular) : vec3(specular);
    ibl_terms t = ibl_gather(p, n, v, roughness);
    vec2 ab = ibl_brdf(n, v, roughness);
    vec3 c = (pbr ? albedo * (1.0 - specular) : albedo) * t.irradiance + t.prefiltered * (f0 * ab.x + ab.y);
    // with AMBIENT_OCCLUSION (chapter 19's --ssao) the occlusion scales the probes' light as it
    // scales the constant's (shade_ambient)
    return min(t.coverage, 1.0) * ambient_visibility() * c + max(1.0 - t.coverage, 0.0) * shade_ambient(albedo);
}

#endif
