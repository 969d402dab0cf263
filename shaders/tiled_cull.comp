#version 430 core
// tiled_cull.comp - chapter 10's compute path (OpenGL 4.3): one workgroup per TILE_SIZE x TILE_SIZE
// tile, one invocation per pixel, makes that tile's light list.
//   a. depth bounds: each invocation reads its pixel's surface (gbuffer_read) and folds its view depth
//      into the tile's minimum and maximum with shared-memory atomics: for non-negative floats the
//      order of their bit patterns (floatBitsToUint) is the order of the values. Background pixels
//      are left out; so are the invocations of a partial tile beyond the screen's edge.
//   b. culling: the tile's frustum is made once, in shared memory (tiled_cull.glsl); invocation k
//      tests a run of consecutive lights, k * run to (k + 1) * run - 1, by their bounding spheres in
//      view space (u_light_spheres, made by the chapter once per frame), and counts its hits in
//      shared memory; a prefix sum over the counts (16 row
//      sums, then each invocation adds up what comes before it) gives each invocation where its hits
//      go, so the list comes out in light order, the order forward adds the lights up in.
// Every barrier() is in straight-line code: llvmpipe runs a shader with a barrier inside a loop or a
// branch several times slower, even where that code does not run.
// The list goes to tile_lights[tile * u_tile_capacity ...]; tile_ranges[tile] = (first, count, covered
// pixels, 0), count -1 when the tile had more lights than its capacity: the shading pass then loops
// over every light.
// chapters/10_tiled_deferred.c draws the shading pass (tiled_shade.frag) with these lists.
#include "tiled.glsl"
#include "gbuffer_read.glsl"
#include "tiled_cull.glsl"

layout(local_size_x = TILE_SIZE, local_size_y = TILE_SIZE) in;

layout(std430, binding = 0) writeonly restrict buffer tile_light_buffer { int tile_lights[]; };
layout(std430, binding = 1) writeonly restrict buffer tile_range_buffer { ivec4 tile_ranges[]; };
uniform samplerBuffer u_light_spheres; // view-space centre, radius
uniform int u_light_count;
uniform mat4 u_view_matrix;  // world to view: the depth of a surface is -z there
uniform int u_tile_capacity; // list entries per tile

const int GROUP = TILE_SIZE * TILE_SIZE;

shared uint s_depth_min, s_depth_max, s_covered;
shared tile_frustum s_frustum;
shared int s_hits[GROUP];         // hits per invocation
shared int s_row_hits[TILE_SIZE]; // hits per row of TILE_SIZE invocations

void main()
{
    int me = int(gl_LocalInvocationIndex);
    if (me == 0) {
        s_depth_min = 0xffffffffu;
        s_depth_max = 0u;
        s_covered = 0u;
    }
    memoryBarrierShared();
    barrier();

    // a. the tile's depth bounds
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (all(lessThan(vec2(pixel), u_viewport_size))) {
        surface s = gbuffer_read(pixel);
        if (!s.background) {
            uint d = floatBitsToUint(max(-(u_view_matrix * vec4(s.position, 1.0)).z, 0.0));
            atomicMin(s_depth_min, d);
            atomicMax(s_depth_max, d);
            atomicAdd(s_covered, 1u);
        }
    }
    memoryBarrierShared();
    barrier();

    // b. the tile's frustum, made once in shared memory; then this invocation's run of lights against
    // it. A tile of background only tests none (no branch around the barriers below: the runs are
    // empty instead).
    if (me == 0) {
        vec2 origin = vec2(gl_WorkGroupID.xy * uint(TILE_SIZE));
        vec2 end = min(origin + float(TILE_SIZE), u_viewport_size);
        vec4 rect = vec4(origin, end) / u_viewport_size.xyxy * 2.0 - 1.0;
        s_frustum = tile_frustum_make(rect, vec2(uintBitsToFloat(s_depth_min), uintBitsToFloat(s_depth_max)));
    }
    memoryBarrierShared();
    barrier();
    tile_frustum f = s_frustum;
    int run = (u_light_count + GROUP - 1) / GROUP, first_light = me * run;
    int last_light = s_covered > 0u ? min(first_light + run, u_light_count) : first_light;
    uint hit_bits = 0u; // light first_light + j hit: bit j (runs of up to 32 lights)
    int hits = 0;
    for (int i = first_light; i < last_light; i++) {
        if (tile_sphere_visible(f, texelFetch(u_light_spheres, i))) {
            hit_bits |= i - first_light < 32 ? 1u << uint(i - first_light) : 0u;
            hits++;
        }
    }
    s_hits[me] = hits;
    memoryBarrierShared();
    barrier();
    if (me < TILE_SIZE) {
        int sum = 0;
        for (int k = 0; k < TILE_SIZE; k++)
            sum += s_hits[me * TILE_SIZE + k];
        s_row_hits[me] = sum;
    }
    memoryBarrierShared();
    barrier();

    // The hits of the invocations before this one come first: the whole rows before its row, then
    // the invocations before it in its row. Only invocations with hits need to know (shared-memory
    // reads are not free: one per invocation and word).
    int tile = int(gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x);
    int first = tile * u_tile_capacity;
    if (hits > 0) {
        int row = me / TILE_SIZE, before = 0;
        for (int r = 0; r < row; r++)
            before += s_row_hits[r];
        for (int k = row * TILE_SIZE; k < me; k++)
            before += s_hits[k];
        for (int i = first_light; i < last_light; i++) {
            bool hit = run <= 32 ? (hit_bits & (1u << uint(i - first_light))) != 0u
                                 : tile_sphere_visible(f, texelFetch(u_light_spheres, i));
            if (hit && before < u_tile_capacity)
                tile_lights[first + before] = i;
            before += hit ? 1 : 0;
        }
    }
    if (me == 0) {
        int count = 0;
        for (int r = 0; r < TILE_SIZE; r++)
            count += s_row_hits[r];
        tile_ranges[tile] = ivec4(first, count <= u_tile_capacity ? count : -1, int(s_covered), 0);
    }
}
