// tiled_cull.glsl - chapter 10's test of a light against a screen tile (docs/10_tiled_deferred.md).
// A tile's piece of the view is the frustum through its pixels, cut to the view-space depths its
// surfaces span. A light's bounding sphere (view space; chapters/10_tiled_deferred.c makes it, a
// spot's around its cone) is kept when it comes within reach of the four side planes, of the depth
// slab, and of the box around the piece. Conservative: a kept light may still light no pixel of the
// tile (a sphere can pass all three tests beside a corner of the piece), never the reverse. The C
// twin of these two functions is in the chapter, for its GL 3.3 path.
#ifndef TILED_CULL_GLSL
#define TILED_CULL_GLSL

uniform mat4 u_proj;     // view to clip: the side planes come from its rows
uniform mat4 u_inv_proj; // clip to view: the corner rays of the tile

struct tile_frustum {
    vec4 side[4]; // x_clip >= x0 w_clip, x_clip <= x1 w_clip, the same for y; unit normals
    vec2 depth;   // nearest and farthest surface, as distances in front of the eye
    vec3 lo, hi;  // the box around the piece (view space)
};

// The tile whose pixels cover the NDC rectangle rect (x0, y0, x1, y1), between those depths. Row i of
// the projection gives clip coordinate i; x_clip - x0 w_clip >= 0 is the plane row0 - x0 row3. The
// box holds the four corner rays (scaled to z = -1) at both depths.
tile_frustum tile_frustum_make(vec4 rect, vec2 depth)
{
    mat4 rows = transpose(u_proj);
    tile_frustum f;
    f.side[0] = rows[0] - rect.x * rows[3];
    f.side[1] = rect.z * rows[3] - rows[0];
    f.side[2] = rows[1] - rect.y * rows[3];
    f.side[3] = rect.w * rows[3] - rows[1];
    f.lo = vec3(3.0e38);
    f.hi = vec3(-3.0e38);
    for (int k = 0; k < 4; k++) {
        f.side[k] /= length(f.side[k].xyz);
        vec4 p = u_inv_proj * vec4(k % 2 == 0 ? rect.x : rect.z, k < 2 ? rect.y : rect.w, 0.0, 1.0);
        vec3 ray = p.xyz / -p.z;
        f.lo = min(f.lo, min(ray * depth.x, ray * depth.y));
        f.hi = max(f.hi, max(ray * depth.x, ray * depth.y));
    }
    f.depth = depth;
    return f;
}

// Whether the sphere s (view-space centre xyz, radius w) can reach the tile.
bool tile_sphere_visible(tile_frustum f, vec4 s)
{
    if (-s.z + s.w < f.depth.x || -s.z - s.w > f.depth.y)
        return false;
    for (int k = 0; k < 4; k++)
        if (dot(f.side[k].xyz, s.xyz) + f.side[k].w < -s.w)
            return false;
    vec3 outside = max(max(f.lo - s.xyz, s.xyz - f.hi), 0.0);
    return dot(outside, outside) <= s.w * s.w;
}

#endif
