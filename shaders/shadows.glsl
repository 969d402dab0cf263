// shadows.glsl - chapter 14's shadow lookup (docs/14_shadows.md): how much of light i reaches p, from
// the depth atlas. Included through shading_features.glsl in programs built with SHADOWS only, so the
// chapters before 14, and chapter 14 with no light shadowed, compile none of it.
// Tables (common/base/shader_layout.h; common/shadows/shadow_atlas.c fills them):
//   u_shadow_lights, one texel per light: first tile (-1: unshadowed), faces (6: a cube, 1: a spot),
//     the normal offset in texels, 0 (unused)
// SHADOW_PCF, the taps a side, comes with SHADOWS (shadow_atlas_extra), so the lookup's loop is known
// when the program is built.
//   u_shadow_tiles, SHADER_SHADOW_TILE_TEXELS per tile: the light's view-projection for that face,
//     then (x, y, size) of the tile in the atlas in texels and the tangent of half its field
#ifdef SHADOWS
#ifndef SHADOW_PCF
#define SHADOW_PCF 1 // a program built with SHADOWS alone (the GLSL check): chapter 14's default
#endif
uniform sampler2DShadow u_shadow_atlas; // depth, compared with GL_LEQUAL, GL_LINEAR: 2 x 2 comparisons, weighted
uniform samplerBuffer u_shadow_lights;
uniform samplerBuffer u_shadow_tiles;

// The cube face that sees direction d from the light, +X -X +Y -Y +Z -Z = 0..5: its major axis, ties
// to x before y before z (common/shadows/shadow_plan.c, shadow_cube_face, decides the same).
int shadow_cube_face(vec3 d)
{
    vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z)
        return d.x >= 0.0 ? 0 : 1;
    if (a.y >= a.z)
        return d.y >= 0.0 ? 2 : 3;
    return d.z >= 0.0 ? 4 : 5;
}

// The fraction of the PCF taps round p that see p: 1 lit, 0 in shadow. The face comes from the
// light-to-point vector; p is first moved along its normal by the normal offset (in texels of that
// face at p's distance); the taps lie one texel apart round p's own position (not snapped to the
// texel grid: each is a bilinear 2 x 2 comparison, so the result moves smoothly with p), every one
// clamped inside the tile, whose gutter (the field wider than 90 degrees) holds the neighbouring
// faces' texels, so no tap reads another light's tile.
float shadow_visibility(int i, vec3 light_position, vec3 p, vec3 n)
{
    vec4 info = texelFetch(u_shadow_lights, i);
    if (info.x < 0.0)
        return 1.0;
    int face = info.y > 1.5 ? shadow_cube_face(p - light_position) : 0;
    int t = (int(info.x) + face) * SHADER_SHADOW_TILE_TEXELS;
    mat4 m = mat4(texelFetch(u_shadow_tiles, t), texelFetch(u_shadow_tiles, t + 1), texelFetch(u_shadow_tiles, t + 2),
                  texelFetch(u_shadow_tiles, t + 3));
    vec4 tile = texelFetch(u_shadow_tiles, t + 4);
    float texel_world = 2.0 * (m * vec4(p, 1.0)).w * tile.w / tile.z; // one texel's width at p's depth
    vec4 c = m * vec4(p + n * (info.z * texel_world), 1.0);
    vec3 ndc = c.xyz / c.w;
    vec2 st = (ndc.xy * 0.5 + 0.5) * tile.z;
    float ref = min(ndc.z * 0.5 + 0.5, 1.0);
    vec2 atlas = vec2(textureSize(u_shadow_atlas, 0));
#if SHADOW_PCF == 1
    // PCF 1, the default: one comparison, no loop
    return texture(u_shadow_atlas, vec3((tile.xy + clamp(st, vec2(1.0), vec2(tile.z - 1.0))) / atlas, ref));
#else
    const int r = SHADOW_PCF / 2;
    float lit = 0.0;
    for (int y = -r; y <= r; y++)
        for (int x = -r; x <= r; x++) {
            vec2 s = clamp(st + vec2(x, y), vec2(1.0), vec2(tile.z - 1.0));
            lit += texture(u_shadow_atlas, vec3((tile.xy + s) / atlas, ref));
        }
    return lit / float((2 * r + 1) * (2 * r + 1));
#endif
}
#endif
