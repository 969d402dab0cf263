// light_prepass.glsl - what chapter 15's two light-buffer shaders share (docs/15_light_prepass.md):
// the luminance one specular channel keeps, and a light's two terms before the material.
#ifndef LIGHT_PREPASS_GLSL
#define LIGHT_PREPASS_GLSL

// Rec. 709 luminance: what ONE specular channel keeps of a light's colour (the mono buffer).
const vec3 LUMINANCE = vec3(0.2126, 0.7152, 0.0722);

// shade_light_index()'s two terms apart, before the material, added to diffuse and specular:
// f E (n.l) and f E (n.h)^shininess, E the light's radiance. shade_light() is albedo * diffuse +
// specular * specular, up to rounding; each term times what of the light reaches p (light_visible).
void shade_light_terms(int i, vec3 p, vec3 n, vec3 v, float shininess, inout vec3 diffuse, inout vec3 specular)
{
    light_data L = light_fetch(i);
    light_reach r;
    if (!shade_light_reach(L, light_fetch_cone(i), p, n, v, shininess, r))
        return;
    vec3 e = light_visible(r.f * L.radiance, i, L.position, p, n);
    diffuse += e * r.ndl;
    specular += e * r.highlight;
}

#endif
