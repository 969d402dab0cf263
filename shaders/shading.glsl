// shading.glsl - the one shading model every renderer uses (docs/00_forward.md has the formulas):
// Blinn-Phong under point lights with attenuation, and the constant ambient. Included by forward.frag
// and every deferred lighting shader, never copied. What later chapters add (a light's cone, another
// material model, a light's visibility, other ambient light) comes in through shading_features.glsl,
// each from its own chapter's file and only in a program built for a scene that uses it
// (scene_features.glsl; tests/lessons/shading_features.py keeps this file free of them).
#include "scene_features.glsl"

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

// normalize() of a zero vector is NaN: degenerate input falls back instead.
vec3 safe_normalize(vec3 v, vec3 fallback)
{
    float len2 = dot(v, v);
    return len2 > 1e-30 ? v * inversesqrt(len2) : fallback;
}

// The light's kind: its light_cone, light_fetch_cone(i) and light_cone_factor(C, l), 1 for a point
// light (shading_features.glsl).
#include "light_kinds.glsl"

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

// The hooks shading_features.glsl defines for the scene's material models and the ambient light.
float material_highlight(vec3 n, vec3 h, float shininess);
float ambient_visibility();

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
    float cone = light_cone_factor(C, l);
    if (cone <= 0.0)
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
    f *= cone;
    r = light_reach(f, ndl, material_highlight(n, h, shininess), l);
    return true;
}

// Blinn-Phong: what light L brings, E f ((n.l) albedo + specular (n.h)^shininess), E its radiance.
vec3 blinn_phong_light(light_reach r, vec3 radiance, vec3 albedo, float specular)
{
    return r.f * radiance * (r.ndl * albedo + specular * r.highlight);
}

// The constant ambient, times the share of it that reaches this pixel (1 but where a later chapter
// says less).
vec3 shade_ambient(vec3 albedo)
{
    return u_ambient * albedo * ambient_visibility();
}

// The scene's material models (material_light), what reaches p of each light (light_visible) and
// the ambient light where the surface is known (shade_ambient_at).
#include "shading_features.glsl"

// Light i's contribution at p (world space), unit normal n, unit view vector v; C is its cone
// (light_fetch_cone(i)), NO_CONE for a point light.
vec3 shade_light(light_data L, light_cone C, vec3 p, vec3 n, vec3 v, vec3 albedo, float specular,
                 float shininess)
{
    light_reach r;
    if (!shade_light_reach(L, C, p, n, v, shininess, r))
        return vec3(0.0);
    return material_light(r, L.radiance, n, v, albedo, specular, shininess);
}

// A point light: the same function without a cone.
vec3 shade_light(light_data L, vec3 p, vec3 n, vec3 v, vec3 albedo, float specular, float shininess)
{
    return shade_light(L, NO_CONE, p, n, v, albedo, specular, shininess);
}

// Light i's contribution, as the light loops add it up: shade_light() with the light's own cone,
// times the fraction of it that reaches p (light_visible: all of it, but in a later chapter).
vec3 shade_light_index(int i, vec3 p, vec3 n, vec3 v, vec3 albedo, float specular, float shininess)
{
    light_data L = light_fetch(i);
    vec3 c = shade_light(L, light_fetch_cone(i), p, n, v, albedo, specular, shininess);
    return light_visible(c, i, L.position, p, n);
}

// Linear [0,1] to the exact sRGB curve; the 8-bit target then rounds to 255 levels.
vec3 display_encode(vec3 c)
{
    c = clamp(c, 0.0, 1.0);
    vec3 lo = 12.92 * c;
    vec3 hi = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
    return mix(hi, lo, lessThanEqual(c, vec3(0.0031308)));
}
