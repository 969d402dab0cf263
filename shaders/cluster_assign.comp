#version 430 core
// cluster_assign.comp - chapter 11's light assignment on the GPU (OpenGL 4.3): the lists that
// cluster_lists_assign (common/clusters/cluster_grid.c) makes on the CPU, bit for bit, in three passes built
// from this file by a define (common/clusters/cluster_assign_gpu.c). The CPU has sorted each light's tiles
// per slice into one candidate list per (slice, tile row), in light order: rows[b] .. rows[b + 1] - 1
// for b = slice * tile rows + row, each (light, first | last tile column << 16).
//   PASS_COUNT  one invocation per (slice, tile row) walks its candidates and, for each, the
//               clusters of its tile columns: where the sphere reaches the cluster's box, that
//               cluster's count goes up (no two invocations touch the same cluster: no atomics)
//               and the pair's bit is set in the row's hit bits; then the entries of the row: its
//               counts, those over u_limit left out
//   PASS_SCAN   one workgroup turns the rows' entries into where each row's first entry goes: each
//               invocation adds up a run of rows, then what the runs before its own hold
//   PASS_FILL   per (slice, tile row) again: each cluster's (first, count) from the row's first
//               entry on, a count over u_limit made -1 (no entries, the cluster loops over every
//               light); then the walk of PASS_COUNT again, reading the hit bits instead of testing
//               again, writing each hit at its cluster's cursor: in candidate order, light order
// The test is cluster_grid_sphere_touches's, on the same floats (the boxes come from the CPU, the
// radius is already grown), with `precise` so that no multiply-add is fused: the CPU does not fuse.

#define CLUSTER_INFINITE_RADIUS 1e30
#define GROUP_SIZE 64
#define SCAN_SIZE 256

#ifdef PASS_SCAN
layout(local_size_x = SCAN_SIZE) in;
#else
layout(local_size_x = GROUP_SIZE) in;
#endif

layout(std430, binding = 0) readonly restrict buffer sphere_buffer { vec4 spheres[]; }; // view space
layout(std430, binding = 1) readonly restrict buffer candidate_buffer { ivec2 candidates[]; };
// per (slice, tile row) + 1: its first candidate; then as many: its first word of hit bits
layout(std430, binding = 2) readonly restrict buffer row_buffer { int rows[]; };
layout(std430, binding = 3) readonly restrict buffer box_buffer { float boxes[]; };
layout(std430, binding = 4) restrict buffer range_buffer { ivec2 ranges[]; }; // first, count
layout(std430, binding = 5) writeonly restrict buffer list_buffer { int lights[]; };
// per cluster, where its next entry goes (-1: none); then per (slice, tile row), its entries, then
// where they begin
layout(std430, binding = 6) restrict buffer scratch_buffer { int scratch[]; };
layout(std430, binding = 7) restrict buffer hit_buffer { uint hits[]; }; // one bit per pair tested
uniform ivec3 u_grid; // tiles in x, tiles in y, slices
uniform int u_limit;  // most entries a list holds

// The distance from the sphere's centre to the box, squared, against the radius squared: as
// common/clusters/cluster_grid.c's box_touches adds it up, axis by axis.
bool sphere_touches(vec4 s, vec2 bx, vec2 by, vec2 bz)
{
    if (s.w >= CLUSTER_INFINITE_RADIUS)
        return true;
    precise float ex = s.x < bx.x ? bx.x - s.x : s.x > bx.y ? s.x - bx.y : 0.0;
    precise float ey = s.y < by.x ? by.x - s.y : s.y > by.y ? s.y - by.y : 0.0;
    precise float ez = s.z < bz.x ? bz.x - s.z : s.z > bz.y ? s.z - bz.y : 0.0;
    precise float d2 = ex * ex + ey * ey;
    d2 = d2 + ez * ez;
    precise float r2 = s.w * s.w;
    return d2 <= r2;
}

#define CURSOR(cluster) scratch[cluster]
#define ROW_ENTRIES(row) scratch[u_grid.x * u_grid.y * u_grid.z + (row)]

#ifdef PASS_SCAN
shared int run_sum[SCAN_SIZE];

void main()
{
    int n = u_grid.y * u_grid.z, per = (n + SCAN_SIZE - 1) / SCAN_SIZE;
    int i = int(gl_LocalInvocationID.x), a = min(i * per, n), b = min(a + per, n);
    int sum = 0;
    for (int r = a; r < b; r++)
        sum += ROW_ENTRIES(r);
    run_sum[i] = sum;
    memoryBarrierShared();
    barrier();
    int first = 0;
    for (int j = 0; j < i; j++)
        first += run_sum[j];
    for (int r = a; r < b; r++) {
        int entries = ROW_ENTRIES(r);
        ROW_ENTRIES(r) = first;
        first += entries;
    }
}
#else
void main()
{
    int bucket = int(gl_GlobalInvocationID.x), buckets = u_grid.y * u_grid.z;
    if (bucket >= buckets)
        return;
    int k = bucket / u_grid.y, row = bucket * u_grid.x; // the row's first cluster
    int word = rows[buckets + 1 + bucket], bit = 0;     // the row's hit bits
    uint bits = 0u;
#ifdef PASS_COUNT
    int x0 = 2 * k * u_grid.x, y0 = 2 * u_grid.z * u_grid.x, z0 = y0 + 2 * u_grid.z * u_grid.y;
    vec2 by = vec2(boxes[y0 + 2 * bucket], boxes[y0 + 2 * bucket + 1]);
    vec2 bz = vec2(boxes[z0 + 2 * k], boxes[z0 + 2 * k + 1]);
    for (int tx = 0; tx < u_grid.x; tx++)
        ranges[row + tx] = ivec2(0);
#else
    int first = ROW_ENTRIES(bucket);
    for (int tx = 0; tx < u_grid.x; tx++) {
        int count = ranges[row + tx].y;
        bool over = count > u_limit;
        ranges[row + tx] = ivec2(first, over ? -1 : count);
        CURSOR(row + tx) = over ? -1 : first;
        first += over ? 0 : count;
    }
#endif
    for (int j = rows[bucket]; j < rows[bucket + 1]; j++) {
        ivec2 c = candidates[j];
#ifdef PASS_COUNT
        vec4 s = spheres[c.x];
#endif
        for (int tx = c.y & 0xffff; tx <= c.y >> 16; tx++) {
#ifdef PASS_COUNT
            vec2 bx = vec2(boxes[x0 + 2 * tx], boxes[x0 + 2 * tx + 1]);
            if (sphere_touches(s, bx, by, bz)) {
                ranges[row + tx].y += 1;
                bits |= 1u << bit;
            }
            if (++bit == 32) {
                hits[word++] = bits;
                bits = 0u, bit = 0;
            }
#else
            if (bit == 0)
                bits = hits[word++];
            if ((bits & (1u << bit)) != 0u) {
                int at = CURSOR(row + tx);
                if (at >= 0) {
                    lights[at] = c.x;
                    CURSOR(row + tx) = at + 1;
                }
            }
            bit = (bit + 1) & 31;
#endif
        }
    }
#ifdef PASS_COUNT
    if (bit > 0)
        hits[word] = bits;
    int entries = 0;
    for (int tx = 0; tx < u_grid.x; tx++)
        entries += ranges[row + tx].y <= u_limit ? ranges[row + tx].y : 0;
    ROW_ENTRIES(bucket) = entries;
#endif
}
#endif
