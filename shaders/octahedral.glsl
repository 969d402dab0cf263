// octahedral.glsl - a unit normal in two numbers: project onto the octahedron |x|+|y|+|z| = 1,
// unfold the lower half (z < 0) over the diagonals into the corners of the [-1,1] square.
// docs/02_mrt_gbuffer.md has the formulas; tests/unit/test_octahedral.c mirrors this in C.
#ifndef OCTAHEDRAL_GLSL
#define OCTAHEDRAL_GLSL

// sign() returns 0 at 0: the fold needs +-1 so that points on the axes land on a corner.
vec2 octahedral_sign(vec2 v)
{
    return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0);
}

// n must be unit length; the result lies in [-1,1]^2.
vec2 octahedral_encode(vec3 n)
{
    vec2 p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
    return n.z >= 0.0 ? p : (1.0 - abs(p.yx)) * octahedral_sign(p);
}

vec3 octahedral_decode(vec2 e)
{
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    if (n.z < 0.0)
        n.xy = (1.0 - abs(n.yx)) * octahedral_sign(n.xy);
    return normalize(n); // |n|_1 = 1, never zero
}

// Distance between neighbouring half floats around x, for |x| <= 1: 2^(e-10) when
// 2^e <= |x| < 2^(e+1), and 2^-24 below 2^-14 (subnormals). GLSL 3.30 has no frexp().
float half_spacing(float x)
{
    float a = abs(x);
    float e = a > 0.0 ? floor(log2(a)) : -14.0;
    if (exp2(e) > a) // log2 is approximate: put e in the right binade
        e -= 1.0;
    else if (exp2(e + 1.0) <= a)
        e += 1.0;
    return exp2(max(e, -14.0) - 10.0);
}

// For a half-float target: of the four half-float pairs around the exact encoding, keep the one
// whose decoded direction is closest to n, instead of letting the store round each number alone
// (max error 0.040 instead of 0.058 degrees, tests/unit/test_octahedral.c). The candidates are
// exact half floats, so the store does not round them again.
vec2 octahedral_encode_half(vec3 n)
{
    vec2 e = octahedral_encode(n);
    vec2 s = vec2(half_spacing(e.x), half_spacing(e.y));
    vec2 lo = floor(e / s) * s; // exact: s is a power of two
    vec2 best = lo;
    float best_d2 = 1e30;
    for (int i = 0; i < 4; i++) {
        vec2 c = clamp(lo + vec2(i & 1, i >> 1) * s, -1.0, 1.0);
        // Distance, not dot(): cos(0.01 degrees) = 1 - 1.5e-8 is below float's resolution.
        vec3 d = octahedral_decode(c) - n;
        float d2 = dot(d, d);
        if (d2 < best_d2) {
            best_d2 = d2;
            best = c;
        }
    }
    return best;
}

// For a fixed-point target of n bits per number (RGBA8: n = 8, RGBA16: n = 16, or 12 bits packed
// over three bytes): the number e in [-1,1] is the integer code q in [0, 2m] as e = (q - m) / m,
// m = 2^(n-1) - 1. One code of the 2^n is left unused so that 0 (and +-1) are codes exactly, as in
// a snorm format: the axes, the floor's (0, 1, 0) among them, are stored without error. Of the four
// code pairs around the exact encoding, the one whose decoded direction is closest to n, as above.
vec2 octahedral_encode_codes(vec3 n, float m)
{
    vec2 lo = floor(octahedral_encode(n) * m + m); // codes are integers: exact in float up to 2^24
    vec2 best = lo;
    float best_d2 = 1e30;
    for (int i = 0; i < 4; i++) {
        vec2 q = clamp(lo + vec2(i & 1, i >> 1), 0.0, 2.0 * m);
        vec3 d = octahedral_decode((q - m) / m) - n;
        float d2 = dot(d, d);
        if (d2 < best_d2) {
            best_d2 = d2;
            best = q;
        }
    }
    return best;
}

vec3 octahedral_decode_codes(vec2 q, float m)
{
    return octahedral_decode((q - m) / m);
}

#endif
