// gbuffer_read.glsl - decodes one G-buffer pixel, whatever its layout (common/render/gbuffer.h).
// The uniforms are set by gbuffer_bind_textures(); include after "shading.glsl" or alone. Built for a
// scene without images, metallic-roughness or emissive materials (scene_features.glsl), the decoding
// leaves out what those store: the occlusion, chapter 18's roughness, RT2.
#ifndef GBUFFER_READ_GLSL
#define GBUFFER_READ_GLSL
#include "scene_features.glsl"
#include "octahedral.glsl"

// GBUFFER_MULTISAMPLE (chapter 13): the targets are multisampled; texelFetch's last argument is
// then the sample, not the mip level, so gbuffer_read(pixel) reads sample 0.
#ifdef GBUFFER_MULTISAMPLE
#define GBUFFER_SAMPLER sampler2DMS
#else
#define GBUFFER_SAMPLER sampler2D
#endif
uniform GBUFFER_SAMPLER u_gbuffer_albedo; // SRGB8_ALPHA8 (texelFetch returns linear albedo) or RGBA8
uniform GBUFFER_SAMPLER u_gbuffer_normal; // the normal, and the material where RT0 has no room for it
uniform GBUFFER_SAMPLER u_gbuffer_depth;  // window-space depth in [0,1]
uniform GBUFFER_SAMPLER u_gbuffer_emissive; // RT2 RGBA16F: emissive, where u_gbuffer_has_emissive
uniform bool u_gbuffer_has_emissive;   // the scene has emissive materials, so the G-buffer has RT2
uniform int u_gbuffer_normal_encoding; // SHADER_GBUFFER_NORMAL_*: how RT1 holds the normal
uniform bool u_gbuffer_reversed_z;     // near 1, far 0 (glClipControl: NDC z = window depth)
uniform mat4 u_inv_view_proj;       // of the projection the depth was written with
uniform vec3 u_eye;
uniform vec2 u_viewport_size;       // G-buffer size in pixels

struct surface {
    vec3 position; // world space
    vec3 normal;   // world space, unit length
    vec3 albedo;   // linear
    float specular;
    float shininess;
    float occlusion; // of the ambient light: an occlusion map's (chapter 18), else 1
    vec3 emissive;   // linear radiance the surface gives off (chapter 18's RT2), else 0
    bool background; // nothing was drawn here (depth is the clear value: 1, or 0 reversed)
};

// World position of the pixel's centre at window depth `depth`: undo the viewport transform to
// NDC, then the projection and the view with one matrix, then the perspective divide. Reversed-Z
// uses glClipControl's [0,1] depth range, so there NDC z is the window depth itself.
vec3 gbuffer_position_at(vec2 window_xy, float depth)
{
    vec2 ndc = window_xy / u_viewport_size * 2.0 - 1.0;
    float z = u_gbuffer_reversed_z ? depth : depth * 2.0 - 1.0;
    vec4 world = u_inv_view_proj * vec4(ndc, z, 1.0);
    return world.xyz / world.w;
}

vec3 gbuffer_position(ivec2 pixel, float depth)
{
    return gbuffer_position_at(vec2(pixel) + 0.5, depth);
}

bool gbuffer_is_background(float depth)
{
    return u_gbuffer_reversed_z ? depth <= 0.0 : depth >= 1.0;
}

// A fixed-point channel back to its integer code (texelFetch returns code / (2^bits - 1)).
vec2 gbuffer_codes(vec2 c, float scale)
{
    return floor(c * scale + 0.5);
}

// Three bytes back to two 12-bit codes (gbuffer.frag's pack_12_12).
vec2 gbuffer_unpack_12_12(vec3 c)
{
    vec3 b = floor(c * 255.0 + 0.5);
    float x_lo = floor(b.y / 16.0);
    return vec2(b.x * 16.0 + x_lo, (b.y - x_lo * 16.0) * 256.0 + b.z);
}

// The surface from its two stored texels, its depth and its position.
surface gbuffer_decode(vec4 albedo, vec4 nm, float depth, vec3 position)
{
    surface s;
    s.background = gbuffer_is_background(depth);
    s.position = position;
    s.albedo = albedo.rgb;
    s.occlusion = 1.0;
    s.emissive = vec3(0.0);
    if (u_gbuffer_normal_encoding == SHADER_GBUFFER_NORMAL_HALF) {
#ifdef MATERIAL_MAPS
        s.occlusion = albedo.a; // 1 but under an occlusion map
#endif
        s.normal = octahedral_decode(nm.xy);
        s.specular = nm.z;
        s.shininess = nm.w;
        return s;
    }
    if (u_gbuffer_normal_encoding == SHADER_GBUFFER_NORMAL_BYTES)
        s.normal = octahedral_decode_codes(gbuffer_codes(nm.xy, 255.0), 127.0);
    else if (u_gbuffer_normal_encoding == SHADER_GBUFFER_NORMAL_PACKED)
        s.normal = octahedral_decode_codes(gbuffer_unpack_12_12(nm.xyz), 2047.0);
    else
        s.normal = octahedral_decode_codes(gbuffer_codes(nm.xy, 65535.0), 32767.0);
    s.specular = albedo.a;
    s.shininess = 1.0 + 255.0 * nm.w; // gbuffer.frag's shininess_store
#ifdef MATERIAL_PBR
    if (u_gbuffer_normal_encoding == SHADER_GBUFFER_NORMAL_SHORTS && nm.z > 0.25) { // metallic-roughness
        s.occlusion = nm.z * 2.0 - 1.0;
        s.shininess = -1.0 - floor(nm.w * 1024.0 + 0.5) / 1024.0;
    }
#endif
    return s;
}

// RT2's emissive where the G-buffer has it; 0 where the scene has none (no RT2 is made then).
vec3 gbuffer_emissive(ivec2 pixel, int sample_index)
{
#ifdef MATERIAL_EMISSIVE
    return u_gbuffer_has_emissive ? texelFetch(u_gbuffer_emissive, pixel, sample_index).rgb : vec3(0.0);
#else
    return vec3(0.0);
#endif
}

// The surface at a pixel whose depth the caller has already read (and its position computed).
surface gbuffer_read_at(ivec2 pixel, float depth, vec3 position)
{
    surface s = gbuffer_decode(texelFetch(u_gbuffer_albedo, pixel, 0), texelFetch(u_gbuffer_normal, pixel, 0),
                               depth, position);
    s.emissive = gbuffer_emissive(pixel, 0);
    return s;
}

// One sample of a multisampled pixel, at the position the caller rebuilt for it (plain textures
// have sample 0 only: there the index is the mip level).
surface gbuffer_read_sample(ivec2 pixel, int sample_index, vec3 position)
{
    surface s = gbuffer_decode(texelFetch(u_gbuffer_albedo, pixel, sample_index),
                               texelFetch(u_gbuffer_normal, pixel, sample_index),
                               texelFetch(u_gbuffer_depth, pixel, sample_index).r, position);
    s.emissive = gbuffer_emissive(pixel, sample_index);
    return s;
}

surface gbuffer_read(ivec2 pixel)
{
    float depth = texelFetch(u_gbuffer_depth, pixel, 0).r;
    return gbuffer_read_at(pixel, depth, gbuffer_position(pixel, depth));
}

#endif
