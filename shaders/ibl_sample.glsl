// ibl_sample.glsl - chapter 19's sampling, shared by its two start-up passes (ibl_prefilter.frag,
// ibl_brdf.frag) and nothing else: the Hammersley points, GGX half vectors drawn by their
// distribution, and the direction of a cube-map texel (docs/19_image_based_light.md has the formulas).
#ifndef IBL_SAMPLE_GLSL
#define IBL_SAMPLE_GLSL

const float IBL_PI = 3.14159265358979;

// Point i of n in [0,1)^2: i / n and the bits of i mirrored about the binary point.
vec2 ibl_hammersley(uint i, uint n)
{
    uint b = i;
    b = (b << 16u) | (b >> 16u);
    b = ((b & 0x55555555u) << 1u) | ((b & 0xAAAAAAAAu) >> 1u);
    b = ((b & 0x33333333u) << 2u) | ((b & 0xCCCCCCCCu) >> 2u);
    b = ((b & 0x0F0F0F0Fu) << 4u) | ((b & 0xF0F0F0F0u) >> 4u);
    b = ((b & 0x00FF00FFu) << 8u) | ((b & 0xFF00FF00u) >> 8u);
    return vec2(float(i) / float(n), float(b) * 2.3283064365386963e-10);
}

// A half vector around n drawn with density D(h) (n.h) for GGX's alpha = roughness^2.
vec3 ibl_ggx_half(vec2 xi, vec3 n, float alpha)
{
    float phi = 2.0 * IBL_PI * xi.x;
    float cos_t = sqrt((1.0 - xi.y) / (1.0 + (alpha * alpha - 1.0) * xi.y));
    float sin_t = sqrt(1.0 - cos_t * cos_t);
    vec3 up = abs(n.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    vec3 tx = normalize(cross(up, n));
    vec3 ty = cross(n, tx);
    return normalize(tx * (cos(phi) * sin_t) + ty * (sin(phi) * sin_t) + n * cos_t);
}

// GGX's normal distribution D(h) for alpha = roughness^2.
float ibl_ggx_d(float ndh, float alpha)
{
    float a2 = alpha * alpha;
    float q = ndh * ndh * (a2 - 1.0) + 1.0;
    return a2 / (IBL_PI * q * q);
}

// The unit direction through (x, y) of cube face `face` (GL's order +X -X +Y -Y +Z -Z), x and y in
// texels of a size x size face: the C side's ibl_cube_direction() (chapters/ibl_sh.c).
vec3 ibl_cube_direction(int face, vec2 xy, float size)
{
    vec2 uv = 2.0 * xy / size - 1.0;
    vec3 d = face == 0 ? vec3(1.0, -uv.y, -uv.x)
           : face == 1 ? vec3(-1.0, -uv.y, uv.x)
           : face == 2 ? vec3(uv.x, 1.0, uv.y)
           : face == 3 ? vec3(uv.x, -1.0, -uv.y)
           : face == 4 ? vec3(uv.x, -uv.y, 1.0)
                       : vec3(-uv.x, -uv.y, -1.0);
    return normalize(d);
}

#endif
