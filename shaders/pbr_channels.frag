#version 330 core
// pbr_channels.frag - chapter 18's G-buffer channel views: one channel of what the geometry pass
// stored for the lighting pass, after the material's images were applied (shaders/material_maps.glsl).
// Colour is display-encoded like a lit picture; the other channels are numbers, shown as grey levels.
// A Blinn-Phong surface has no metallic, roughness, occlusion or emissive channel: it shows dark blue there.
#include "shading.glsl"
#include "material_pbr.glsl"
#include "gbuffer_read.glsl"

uniform int u_channel; // PBR_CHANNEL_* (chapters/18_pbr_materials.c's views, in order)
uniform vec2 u_near_far;

#define PBR_CHANNEL_ALBEDO 1
#define PBR_CHANNEL_METALLIC 2
#define PBR_CHANNEL_ROUGHNESS 3
#define PBR_CHANNEL_NORMAL 4
#define PBR_CHANNEL_OCCLUSION 5
#define PBR_CHANNEL_DEPTH 6
#define PBR_CHANNEL_EMISSIVE 7

out vec4 o_color;

const vec3 NOT_PBR = vec3(0.0, 0.0, 0.25);

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(u_gbuffer_depth, pixel, 0).r;
    surface s = gbuffer_read_at(pixel, depth, gbuffer_position(pixel, depth));
    if (s.background) {
        o_color = vec4(vec3(u_channel == PBR_CHANNEL_DEPTH ? 1.0 : 0.0), 1.0);
        return;
    }
    bool pbr = material_is_pbr(s.shininess);
    vec3 c = vec3(0.0);
    if (u_channel == PBR_CHANNEL_ALBEDO)
        c = display_encode(s.albedo);
    else if (u_channel == PBR_CHANNEL_METALLIC)
        c = pbr ? vec3(pbr_metallic(s.specular)) : NOT_PBR;
    else if (u_channel == PBR_CHANNEL_ROUGHNESS) // as stored, before the shading's lower clamp
        c = pbr ? vec3(clamp(-1.0 - s.shininess, 0.0, 1.0)) : NOT_PBR;
    else if (u_channel == PBR_CHANNEL_NORMAL)
        c = s.normal * 0.5 + 0.5; // world-space axes: +x red, +y green, +z blue
    else if (u_channel == PBR_CHANNEL_OCCLUSION)
        c = pbr ? vec3(s.occlusion) : NOT_PBR;
    else if (u_channel == PBR_CHANNEL_DEPTH) // view distance, near black, far white
        c = vec3((distance(s.position, u_eye) - u_near_far.x) / (u_near_far.y - u_near_far.x));
    else if (u_channel == PBR_CHANNEL_EMISSIVE) // RT2, display-encoded; black where the scene has none
        c = pbr ? display_encode(s.emissive) : NOT_PBR;
    o_color = vec4(c, 1.0);
}
