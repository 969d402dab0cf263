#version 330 core
// msaa_deferred.frag - chapter 13's full-screen passes over a multisampled G-buffer
// (GBUFFER_MULTISAMPLE, MSAA_SAMPLES samples per pixel), into a linear float target:
//   MSAA_EDGES (its own program) keeps, for the stencil, only the edge pixels: those whose samples
//                            do not all hold the same surface; discards the others
//   u_pass MSAA_PASS_PIXEL   a pixel whose samples hold one surface: shaded once, at the pixel centre
//   u_pass MSAA_PASS_SAMPLES an edge pixel: each sample shaded at its own position, the results
//                            averaged in linear radiance (the resolve, done while lighting)
// Without GBUFFER_MULTISAMPLE (--samples 1) the pixel pass is chapter 11's clustered deferred pass.
// The lights come from chapter 11's cluster lists (clusters.glsl), through the one shading function.
// Built twice: with MSAA_EDGES, the edge pass alone (it discards); without, the two lighting passes,
// which never discard, so that the stencil test can reject a fragment before its shader runs.
// variants: MSAA_SAMPLES 1 | MSAA_SAMPLES 4, GBUFFER_MULTISAMPLE 1, MSAA_MULTISAMPLE 1 | MSAA_SAMPLES 4, GBUFFER_MULTISAMPLE 1, MSAA_MULTISAMPLE 1, MSAA_EDGES 1
#include "shading.glsl"
#include "gbuffer_read.glsl"
#include "heat.glsl"
#include "clusters.glsl"

#define MSAA_PASS_EDGES 0
#define MSAA_PASS_PIXEL 1
#define MSAA_PASS_SAMPLES 2
// How far off sample 0's plane another sample may lie, per unit of distance from the eye: above
// the depth's rounding, below any step between two surfaces in the scenes (docs/13_msaa.md).
#define MSAA_PLANE_TOLERANCE 1e-3

uniform int u_pass;
uniform bool u_show_edges;                   // the edges view: edge pixels in one flat colour
uniform vec2 u_sample_offsets[MSAA_SAMPLES]; // each sample's position in its pixel, in [0, 1)
uniform vec2 u_mean_offset;                  // their mean: (0.5, 0.5) in the usual symmetric patterns
uniform vec4 u_edge_colour;

out vec4 o_color;

float sample_depth(ivec2 p, int s)
{
    return texelFetch(u_gbuffer_depth, p, s).r;
}

vec3 sample_point(ivec2 p, int s)
{
    return gbuffer_position_at(vec2(p) + u_sample_offsets[s], sample_depth(p, s));
}

// One primitive writes the same albedo and normal/material to every sample it covers (gbuffer.frag
// runs once per pixel per primitive), so an exact comparison is right. The depth differs between the
// samples of one sloped primitive: what must hold is that they lie on one plane, the plane of sample
// 0's normal (two boxes of one colour, one behind the other, have the same values and another depth).
bool is_edge(ivec2 p)
{
    vec4 albedo = texelFetch(u_gbuffer_albedo, p, 0);
    vec4 normal = texelFetch(u_gbuffer_normal, p, 0);
    vec3 emissive = gbuffer_emissive(p, 0);
    bool background = gbuffer_is_background(sample_depth(p, 0));
    for (int s = 1; s < MSAA_SAMPLES; s++)
        if (texelFetch(u_gbuffer_albedo, p, s) != albedo || texelFetch(u_gbuffer_normal, p, s) != normal ||
            gbuffer_emissive(p, s) != emissive || gbuffer_is_background(sample_depth(p, s)) != background)
            return true;
    if (background)
        return false;
    vec3 n = gbuffer_read_sample(p, 0, vec3(0.0)).normal, p0 = sample_point(p, 0);
    float tolerance = MSAA_PLANE_TOLERANCE * distance(p0, u_eye);
    for (int s = 1; s < MSAA_SAMPLES; s++)
        if (abs(dot(sample_point(p, s) - p0, n)) > tolerance)
            return true;
    return false;
}

// Where forward shades sample s's surface. A sample's depth is the depth AT the sample, but forward
// shades each primitive once, at the pixel centre, its attributes extrapolated there: the point where
// the centre's eye ray meets the primitive's plane. So: the sample's point, then along its plane
// (through it, normal n: exact for flat faces) to the centre's ray; at a grazing angle, the point.
vec3 centre_on_plane(ivec2 p, int s, vec3 n)
{
    float depth = sample_depth(p, s);
    vec3 at_sample = sample_point(p, s);
    vec3 ray = gbuffer_position_at(vec2(p) + 0.5, depth) - u_eye;
    float facing = dot(ray, n);
    float t = dot(at_sample - u_eye, n) / facing;
    return abs(facing) > 1e-3 * length(ray) && t > 0.0 ? u_eye + t * ray : at_sample;
}

// Linear radiance of one surface with its cluster's lights; the background is forward's clear colour.
vec3 shade_surface(surface s)
{
    if (s.background)
        return vec3(0.0);
    ivec2 range = cluster_range(cluster_index(gl_FragCoord.xy, cluster_view_depth(s.position)));
    vec3 v = safe_normalize(u_eye - s.position, s.normal);
    return cluster_shade(range, s.position, s.normal, v, s.albedo, s.specular, s.shininess, s.occlusion) +
           s.emissive;
}

#ifdef MSAA_EDGES
void main()
{
    if (!is_edge(ivec2(gl_FragCoord.xy)))
        discard;
    o_color = vec4(0.0);
}
#else
void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    if (u_pass == MSAA_PASS_SAMPLES) {
        if (u_show_edges) {
            o_color = u_edge_colour;
            return;
        }
        vec3 sum = vec3(0.0);
        for (int s = 0; s < MSAA_SAMPLES; s++) {
            surface su = gbuffer_read_sample(p, s, vec3(0.0));
            su.position = centre_on_plane(p, s, su.normal);
            sum += shade_surface(su);
        }
        o_color = vec4(sum / float(MSAA_SAMPLES), 1.0);
        return;
    }
    // One surface, one plane: the mean of the samples' depths is the depth at the mean of their
    // positions (window depth is affine over a triangle), which is the pixel centre where forward shades.
    float depth = 0.0;
    for (int s = 0; s < MSAA_SAMPLES; s++)
        depth += sample_depth(p, s);
    depth /= float(MSAA_SAMPLES);
    surface s = gbuffer_read_at(p, depth, gbuffer_position_at(vec2(p) + u_mean_offset, depth));
    o_color = vec4(shade_surface(s), 1.0);
}
#endif
