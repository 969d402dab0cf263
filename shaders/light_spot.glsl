// light_spot.glsl - chapter 09's spot light (docs/09_spot_lights.md): a point light inside a cone.
// Included through light_kinds.glsl, after its light_cone, in programs built for a scene with spots
// (LIGHT_SPOT).

// A spot's cone (light_kinds.glsl's light_cone) from its texels. A point light is a spot without one
// (NO_CONE: direction 0, both cosines -1): spot_factor() is 1 for it everywhere.
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

// What shading.glsl multiplies a light by: its spot factor (1 for a point light).
float light_cone_factor(light_cone C, vec3 l)
{
    return spot_factor(C, l);
}
