// gbuffer_encode.glsl - how a geometry pass stores the material's shininess and a packed normal in
// fixed-point channels: the G-buffer's (gbuffer.frag) and chapter 15's thin pass
// (light_prepass_thin.frag); shaders/gbuffer_read.glsl undoes both.
#ifndef GBUFFER_ENCODE_GLSL
#define GBUFFER_ENCODE_GLSL

// Shininess in a fixed-point channel: P = 1 + 255 c, so an 8-bit channel holds the integers
// 1..256 exactly (the course's scenes use 8..256) and a 16-bit one steps of 1/257.
float shininess_store(float p)
{
    return clamp((p - 1.0) / 255.0, 0.0, 1.0);
}

// Two 12-bit codes in three bytes: x's high 8 bits | x's low 4 and y's high 4 | y's low 8.
// Float arithmetic on integers below 2^24 is exact; each byte is written as k / 255.
vec3 pack_12_12(vec2 q)
{
    vec2 hi = floor(q / vec2(16.0, 256.0)); // x >> 4, y >> 8
    vec2 lo = q - hi * vec2(16.0, 256.0);
    return vec3(hi.x, lo.x * 16.0 + hi.y, lo.y) / 255.0;
}

#endif
