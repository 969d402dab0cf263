// shading.glsl - the one shading model every renderer uses (docs/00_forward.md has the formulas,
// docs/09_spot_lights.md the spot's cone). Included by forward.frag and every deferred lighting
// shader, never copied.

uniform samplerBuffer u_lights; // SHADER_LIGHT_TEXELS RGBA32F texels per light (common/base/shader_layout.h)
uniform int u_light_count;
uniform vec3 u_ambient;
uniform int u_falloff; // SHADER_FALLOFF_HARD or SHADER_FALLOFF_WINDOWED

struct light_data {
    vec3 position;
    float radius;
    vec3 radiance;    // intensity * colour
    vec3 attenuation; // kc, kl, kq
};

light_data light_fetch(int i)
{
    int t = SHADER_LIGHT_TEXELS * i;
    vec4 a = texelFetch(u_lights, t);
    vec4 b = texelFetch(u_lights, t + 1);
    vec4 c = texelFetch(u_lights, t + 2);
    return light_data(a.xyz, a.w, b.rgb, c.xyz);
}

// A spot's cone: its unit axis and the cosines of its half-angles. A point light is a spot without
// one (direction 0, both cosines -1): spot_factor() is 1 for it everywhere.
struct light_cone {
    vec3 direction;
    float cos_outer;
    float cos_inner;
};

const light_cone NO_CONE = light_cone(vec3(0.0), -1.0, -1.0);

light_cone light_fetch_cone(int i)
{
    int t = SHADER_LIGHT_TEXELS * i;
    return light_cone(texelFetch(u_lights, t + SHADER_LIGHT_TEXEL_SPOT).xyz, texelFetch(u_lights, t + 1).w,
                      texelFetch(u_lights, t + 2).w);
}

// smoothstep(cos(outer), cos(inner), dot(-l, D)), l the unit vector from the surface to the light:
// 1 inside the inner cone, 0 outside the outer one. With inner = outer smoothstep is undefined
// (its edges are equal): a hard edge instead.
float spot_factor(light_cone C, vec3 l)
{
    float c = dot(-l, C.direction);
    if (C.cos_inner <= C.cos_outer)
        return c >= C.cos_outer ? 1.0 : 0.0;
    return smoothstep(C.cos_outer, C.cos_inner, c);
}

// normalize() of a zero vector is NaN: degenerate input falls back instead.
vec3 safe_normalize(vec3 v, vec3 fallback)
{
    float len2 = dot(v, v);
    return len2 > 1e-30 ? v * inversesqrt(len2) : fallback;
}

// ---- the material: Blinn-Phong, or metallic-roughness (chapter 18, docs/18_pbr_materials.md) ----
// Every renderer hands a surface's material to the shading functions as (albedo, specular, shininess).
// Blinn-Phong's shininess is positive; a metallic-roughness material travels in the same three values
// with a negative shininess: specular = metallic, shininess = -1 - roughness. One signature, so no
// renderer's loop changes and a Blinn-Phong scene runs exactly the instructions it ran before.
const float PI = 3.14159265358979;
// Perceptual roughness is clamped here: below it GGX's peak (1 / (pi alpha^2)) outgrows a float's
// useful range for the highlight of a point light, and roughness 0 would be 0 / 0 at n.h = 1.
const float PBR_ROUGHNESS_MIN = 0.045;

bool material_is_pbr(float shininess)
{
    return shininess < 0.0;
}

// The values the G-buffer keeps, so forward and deferred shade the same numbers: metallic to 8 bits,
// roughness to the 1/1024 steps a half float holds -1 - roughness in.
float pbr_metallic(float specular)
{
    return floor(clamp(specular, 0.0, 1.0) * 255.0 + 0.5) / 255.0;
}

float pbr_roughness(float shininess)
{
    float r = floor(clamp(-1.0 - shininess, 0.0, 1.0) * 1024.0 + 0.5) / 1024.0;
    return max(r, PBR_ROUGHNESS_MIN);
}

// pbr_brdf's factors that know only the roughness and the directions (chapter 15's light buffer sums
// them before the material): GGX's D and the visibility V, a2 = alpha^2 = roughness^4, n.l > 0.
void pbr_distribution_visibility(float ndl, float ndv, float ndh, float a2, out float D, out float V)
{
    float d = ndh * ndh * (a2 - 1.0) + 1.0;
    D = a2 / (PI * d * d);
    V = 0.5 / (ndl * sqrt(ndv * ndv * (1.0 - a2) + a2) + ndv * sqrt(ndl * ndl * (1.0 - a2) + a2));
}

// alpha^2 from the material's shininess (-1 - roughness).
float pbr_alpha2(float shininess)
{
    float alpha = pbr_roughness(shininess);
    alpha *= alpha;
    return alpha * alpha;
}

// A normal turned from the eye (interpolation, a normal map) gives n.v <= 0: taken as grazing.
float pbr_ndv(vec3 n, vec3 v)
{
    return clamp(dot(n, v), 1e-4, 1.0);
}

// pi times the metallic-roughness BRDF for unit n, v, l with n.l > 0: GGX distribution D, Smith's
// height-correlated visibility V (D V is D G / (4 n.l n.v)), Schlick's Fresnel F with F0 = mix(0.04,
// base, metallic), and Lambert's diffuse times (1 - metallic), weighted by what Fresnel lets into the
// surface at the light's angle and out of it at the eye's, (1 - F(n.l))(1 - F(n.v)): so a white surface
// never returns more light than it receives (tests/unit/test_brdf_furnace.c). pi times, because the
// course's lights are scaled so a white Lambert surface facing a light returns its radiance E
// (Blinn-Phong's E n.l albedo).
vec3 pbr_brdf(vec3 n, vec3 v, vec3 l, vec3 base, float specular, float shininess)
{
    float metallic = pbr_metallic(specular);
    float a2 = pbr_alpha2(shininess);
    vec3 h = safe_normalize(l + v, n);
    float ndl = clamp(dot(n, l), 0.0, 1.0);
    float ndv = pbr_ndv(n, v);
    float ndh = clamp(dot(n, h), 0.0, 1.0);
    float vdh = clamp(dot(v, h), 0.0, 1.0);
    float D, V;
    pbr_distribution_visibility(ndl, ndv, ndh, a2, D, V);
    vec3 f0 = mix(vec3(0.04), base, metallic);
    vec3 F = f0 + (1.0 - f0) * pow(1.0 - vdh, 5.0);
    vec3 into = (1.0 - f0) * (1.0 - pow(1.0 - ndl, 5.0)); // 1 - F(n.l)
    vec3 out_of = (1.0 - f0) * (1.0 - pow(1.0 - ndv, 5.0)); // 1 - F(n.v)
    return into * out_of * (1.0 - metallic) * base + PI * D * V * F;
}

// What light L brings to p before any material meets it: its factor f (attenuation, window, cone),
// n.l, the unit vector l towards it and, for Blinn-Phong, the highlight (n.h)^shininess; false where
// it brings nothing. C is its cone (light_fetch_cone(i)), NO_CONE for a point light; p world space,
// n and v unit.
struct light_reach {
    float f;
    float ndl;
    float highlight;
    vec3 l;
};

bool shade_light_reach(light_data L, light_cone C, vec3 p, vec3 n, vec3 v, float shininess, out light_reach r)
{
    vec3 to_light = L.position - p;
    float d = length(to_light);
    if (d > L.radius)
        return false;
    // A light exactly on the surface (d = 0) lights it head-on, with f(0) = 1 / kc.
    vec3 l = d > 0.0 ? to_light / d : n;
    float ndl = dot(n, l);
    // Both terms vanish when n.l <= 0: no diffuse, and no specular leaking round the terminator.
    if (ndl <= 0.0)
        return false;
    // Outside the cone: nothing (a point light is never outside).
    float spot = spot_factor(C, l);
    if (spot <= 0.0)
        return false;
    vec3 h = safe_normalize(l + v, n);
    float f = 1.0 / (L.attenuation.x + (L.attenuation.y + L.attenuation.z * d) * d);
    // Windowed: (1 - (d/r)^4)^2 takes the light to zero, with zero slope, at its radius, so the
    // cut-off leaves no step (an infinite radius gives x = 0: no window).
    if (u_falloff == SHADER_FALLOFF_WINDOWED) {
        float x = d / L.radius;
        float w = clamp(1.0 - (x * x) * (x * x), 0.0, 1.0);
        f *= w * w;
    }
    f *= spot;
    r = light_reach(f, ndl, material_is_pbr(shininess) ? 0.0 : pow(max(dot(n, h), 0.0), shininess), l);
    return true;
}

// Light i's contribution at p (world space), unit normal n, unit view vector v; C is its cone
// (light_fetch_cone(i)), NO_CONE for a point light.
vec3 shade_light(light_data L, light_cone C, vec3 p, vec3 n, vec3 v, vec3 albedo, float specular,
                 float shininess)
{
    light_reach r;
    if (!shade_light_reach(L, C, p, n, v, shininess, r))
        return vec3(0.0);
    if (material_is_pbr(shininess))
        return r.f * L.radiance * r.ndl * pbr_brdf(n, v, r.l, albedo, specular, shininess);
    return r.f * L.radiance * (r.ndl * albedo + specular * r.highlight);
}

// A point light: the same function without a cone.
vec3 shade_light(light_data L, vec3 p, vec3 n, vec3 v, vec3 albedo, float specular, float shininess)
{
    return shade_light(L, NO_CONE, p, n, v, albedo, specular, shininess);
}

// Light i's contribution, as the light loops add it up: shade_light() with the light's own cone; in a
// program built with SHADOWS (chapter 14) times the fraction of the light that reaches p
// (shadows.glsl), looked up only where the light adds something.
#include "shadows.glsl"

vec3 shade_light_index(int i, vec3 p, vec3 n, vec3 v, vec3 albedo, float specular, float shininess)
{
    light_data L = light_fetch(i);
    vec3 c = shade_light(L, light_fetch_cone(i), p, n, v, albedo, specular, shininess);
#ifdef SHADOWS
    if (c != vec3(0.0))
        c *= shadow_visibility(i, L.position, p, n);
#endif
    return c;
}

// shade_light_index()'s two terms apart, before the material (chapter 15's light buffer), added to
// diffuse and specular: f E (n.l) and f E (n.h)^shininess, E the light's radiance. shade_light() is
// albedo * diffuse + specular * specular, up to rounding.
// Rec. 709 luminance: what ONE specular channel keeps of a light's colour (chapter 15's mono buffer).
const vec3 LUMINANCE = vec3(0.2126, 0.7152, 0.0722);

void shade_light_terms(int i, vec3 p, vec3 n, vec3 v, float shininess, inout vec3 diffuse, inout vec3 specular)
{
    light_data L = light_fetch(i);
    light_reach r;
    if (!shade_light_reach(L, light_fetch_cone(i), p, n, v, shininess, r))
        return;
    vec3 e = r.f * L.radiance;
#ifdef SHADOWS
    e *= shadow_visibility(i, L.position, p, n);
#endif
    diffuse += e * r.ndl;
    specular += e * r.highlight;
}

// fragment only: AMBIENT_OCCLUSION
#ifdef AMBIENT_OCCLUSION
// Chapter 17: the share of the ambient light that reaches this pixel's surface (SSAO, blurred), in
// the picture's own pixel grid. It scales the ambient term only: the lights' direct terms already
// know where they come from (docs/17_ssao.md says why).
uniform sampler2D u_ao;
uniform bool u_ao_on;
#endif

// The share of the ambient light that reaches this pixel: the occlusion, or 1.
float ambient_occlusion()
{
#ifdef AMBIENT_OCCLUSION
    if (u_ao_on)
        return texelFetch(u_ao, ivec2(gl_FragCoord.xy), 0).r;
#endif
    return 1.0;
}

vec3 shade_ambient(vec3 albedo)
{
    return u_ambient * albedo * ambient_occlusion();
}

// The ambient term where the surface is known: shade_ambient(), or in a program built with
// IMAGE_BASED_LIGHT (chapter 19) the light of the probes around p (ibl.glsl).
#ifdef IMAGE_BASED_LIGHT
#include "ibl.glsl"
#endif

vec3 shade_ambient_at(vec3 p, vec3 n, vec3 v, vec3 albedo, float specular, float shininess, float occlusion)
{
#ifdef IMAGE_BASED_LIGHT
    return occlusion * ibl_ambient(p, n, v, albedo, specular, shininess);
#else
    return shade_ambient(albedo * occlusion);
#endif
}

// Linear [0,1] to the exact sRGB curve; the 8-bit target then rounds to 255 levels.
vec3 display_encode(vec3 c)
{
    c = clamp(c, 0.0, 1.0);
    vec3 lo = 12.92 * c;
    vec3 hi = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
    return mix(hi, lo, lessThanEqual(c, vec3(0.0031308)));
}
