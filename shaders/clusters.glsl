// clusters.glsl - chapter 11's cluster lookup, shared by the clustered deferred pass
// (clustered_deferred.frag) and Forward+ (forward_plus.frag). Include after shading.glsl.
// A cluster is a screen tile (u_cluster_tile pixels square) times a view-depth slice; slice k holds
// view depths near * (far / near)^(k / S) .. near * (far / near)^((k + 1) / S), S = u_cluster_grid.z
// (docs/11_clustered.md has the figure). The lists are made on the CPU (common/clusters/cluster_grid.c, whose
// cluster_grid_index is this file's cluster_index): per cluster (first, count) in u_cluster_ranges,
// count -1 when the cluster's list overflowed (then every light); the light indices in
// u_cluster_lights, in light order.
#ifndef CLUSTERS_GLSL
#define CLUSTERS_GLSL

// The two views beside SHADER_VIEW_LIT and SHADER_VIEW_OVERDRAW (common/clusters/clusters.c has the same).
#define VIEW_CLUSTERS 3
#define VIEW_COUNT 4

uniform isamplerBuffer u_cluster_ranges; // RG32I, one texel per cluster
uniform isamplerBuffer u_cluster_lights; // R32I light indices
uniform ivec3 u_cluster_grid;            // tiles in x, tiles in y, slices
uniform int u_cluster_tile;              // tile size in pixels
uniform vec4 u_cluster_depth_row;        // row 2 of the view matrix: view depth = -dot(row, (p, 1))
uniform vec2 u_cluster_slicing;          // near plane, slices / ln(far / near)

// The view depth of a world-space point: its distance in front of the eye along the view axis.
float cluster_view_depth(vec3 world)
{
    return -dot(u_cluster_depth_row, vec4(world, 1.0));
}

// floor(ln(depth / near) * S / ln(far / near)), clamped to the grid. At depth = near (and before it,
// where rounding can put a visible surface) ln is 0 or less: slice 0, and ln(0) is never taken.
int cluster_slice(float depth)
{
    if (!(depth > u_cluster_slicing.x))
        return 0;
    int k = int(floor(log(depth / u_cluster_slicing.x) * u_cluster_slicing.y));
    return clamp(k, 0, u_cluster_grid.z - 1);
}

// The cluster of a fragment: its tile from gl_FragCoord, its slice from its view depth.
int cluster_index(vec2 frag_coord, float depth)
{
    ivec2 tile = min(ivec2(frag_coord) / u_cluster_tile, u_cluster_grid.xy - 1);
    return (cluster_slice(depth) * u_cluster_grid.y + tile.y) * u_cluster_grid.x + tile.x;
}

// (first, count) of a cluster's list; count -1: the list overflowed, loop over every light.
ivec2 cluster_range(int cluster)
{
    return texelFetch(u_cluster_ranges, cluster).xy;
}

// How many lights the loop below runs for that range.
int cluster_loop_count(ivec2 range)
{
    return range.y < 0 ? u_light_count : range.y;
}

// Ambient (times the surface's occlusion, 1 but for an occlusion map), then every light of the
// cluster's list through the one shading function.
vec3 cluster_shade(ivec2 range, vec3 p, vec3 n, vec3 v, vec3 albedo, float specular, float shininess, float occlusion)
{
    vec3 c = shade_ambient_at(p, n, v, albedo, specular, shininess, occlusion);
    int count = cluster_loop_count(range);
    for (int k = 0; k < count; k++) {
        int i = range.y < 0 ? k : texelFetch(u_cluster_lights, range.x + k).r;
        c += shade_light_index(i, p, n, v, albedo, specular, shininess);
    }
    return c;
}

vec3 cluster_shade(ivec2 range, vec3 p, vec3 n, vec3 v, vec3 albedo, float specular, float shininess)
{
    return cluster_shade(range, p, n, v, albedo, specular, shininess, 1.0);
}

// The clusters view: the cluster's list length as the heat map; odd slices darker so that the slice
// boundaries show as bands, and an empty cluster a dark grey of its slice's shade.
vec3 cluster_view_colour(ivec2 range, float depth)
{
    int count = cluster_loop_count(range);
    bool odd = (cluster_slice(depth) & 1) == 1;
    vec3 c = count > 0 ? heat(count) : vec3(0.12);
    return odd ? c * 0.55 : c;
}

// What a view writes (u_view_mode): the picture, display-encoded or linear (u_output_linear), the
// loop's length as the heat map, the clusters view, or for the count pass (VIEW_COUNT) raw numbers:
// 1 per covered pixel and the loop's length, added up on the CPU.
vec4 cluster_output(int mode, bool linear, ivec2 range, float depth, vec3 c)
{
    if (mode == SHADER_VIEW_OVERDRAW)
        return vec4(heat(cluster_loop_count(range)), 1.0);
    if (mode == VIEW_CLUSTERS)
        return vec4(cluster_view_colour(range, depth), 1.0);
    if (mode == VIEW_COUNT)
        return vec4(1.0, float(cluster_loop_count(range)), 0.0, 0.0);
    return linear ? vec4(c, 1.0) : vec4(display_encode(c), 1.0);
}

#endif
