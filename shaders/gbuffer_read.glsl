// gbuffer_read.glsl - decodes one G-buffer pixel (layout in common/gbuffer.h).
// The uniforms are set by gbuffer_bind_textures(); include after "shading.glsl" or alone.
#ifndef GBUFFER_READ_GLSL
#define GBUFFER_READ_GLSL
#include "octahedral.glsl"

uniform sampler2D u_gbuffer_albedo; // SRGB8_ALPHA8: texelFetch returns linear albedo
uniform sampler2D u_gbuffer_normal; // RGBA16F: octahedral normal xy, specular, shininess
uniform sampler2D u_gbuffer_depth;  // DEPTH_COMPONENT32F, window-space depth in [0,1]
uniform mat4 u_inv_view_proj;
uniform vec3 u_eye;
uniform vec2 u_viewport_size;       // G-buffer size in pixels

struct surface {
    vec3 position; // world space
    vec3 normal;   // world space, unit length
    vec3 albedo;   // linear
    float specular;
    float shininess;
    bool background; // nothing was drawn here (depth == 1)
};

// World position of the pixel's centre at window depth `depth`: undo the viewport transform to
// NDC, then the projection and the view with one matrix, then the perspective divide.
vec3 gbuffer_position(ivec2 pixel, float depth)
{
    vec2 ndc = (vec2(pixel) + 0.5) / u_viewport_size * 2.0 - 1.0;
    vec4 world = u_inv_view_proj * vec4(ndc, depth * 2.0 - 1.0, 1.0);
    return world.xyz / world.w;
}

// The surface at a pixel whose depth the caller has already read (and its position computed).
surface gbuffer_read_at(ivec2 pixel, float depth, vec3 position)
{
    surface s;
    vec4 nm = texelFetch(u_gbuffer_normal, pixel, 0);
    s.background = depth >= 1.0;
    s.position = position;
    s.normal = octahedral_decode(nm.xy);
    s.albedo = texelFetch(u_gbuffer_albedo, pixel, 0).rgb;
    s.specular = nm.z;
    s.shininess = nm.w;
    return s;
}

surface gbuffer_read(ivec2 pixel)
{
    float depth = texelFetch(u_gbuffer_depth, pixel, 0).r;
    return gbuffer_read_at(pixel, depth, gbuffer_position(pixel, depth));
}

#endif
