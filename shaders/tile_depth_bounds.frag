#version 330 core
// tile_depth_bounds.frag - chapter 10's reduction pass (the GL 3.3 path): drawn over a target of one
// pixel per tile, each fragment reads the TILE_SIZE x TILE_SIZE pixels of its tile (fewer at the
// right and top edges, where the tile is cut by the screen) and writes the nearest and farthest view
// depth of their surfaces and how many pixels have one. Background pixels count in neither: a tile of
// background only writes (huge, 0, 0), and the CPU gives it no lights. tiled_cull.comp finds the same
// numbers with shared-memory atomics.
#include "tiled.glsl"
#include "gbuffer_read.glsl"

uniform mat4 u_view_matrix; // world to view: the depth of a surface is -z there

out vec4 o_bounds; // nearest depth, farthest depth, covered pixels, 0

void main()
{
    ivec2 origin = ivec2(gl_FragCoord.xy) * TILE_SIZE;
    ivec2 end = min(origin + TILE_SIZE, ivec2(u_viewport_size));
    float nearest = 3.0e38, farthest = 0.0;
    int covered = 0;
    for (int y = origin.y; y < end.y; y++) {
        for (int x = origin.x; x < end.x; x++) {
            surface s = gbuffer_read(ivec2(x, y));
            if (s.background)
                continue;
            float d = max(-(u_view_matrix * vec4(s.position, 1.0)).z, 0.0);
            nearest = min(nearest, d);
            farthest = max(farthest, d);
            covered++;
        }
    }
    o_bounds = vec4(nearest, farthest, float(covered), 0.0);
}
