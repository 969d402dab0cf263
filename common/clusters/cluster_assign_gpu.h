/* cluster_assign_gpu.h - chapter 11's light assignment by compute shaders (GL 4.3): the same lists
 * as cluster_lists_assign (cluster_lists.h), written straight into the two buffers the shading
 * passes read, so that the shaders that read them do not change.
 *
 *   cluster_assign_gpu_create(a)      its buffers; the programs are made on first use
 *   cluster_assign_gpu_destroy(a)
 *   cluster_assign_gpu_prepare(a, g, spheres, count, cluster_limit, out)
 *        what the CPU does before the compute passes, for the view-space spheres (xyz centre, w
 *        radius; w >= 1e30: infinite) and grid g: per light what is cheap (its slices, and the tiles
 *        of each: a candidate list per slice and tile row), uploaded with every cluster's box; the
 *        programs built, the output buffers sized (out->range_buffer RG32I per cluster (first,
 *        count), out->list_buffer R32I the light indices, both attached to their buffer textures)
 *        and every buffer bound to its shader-storage slot; a->groups workgroups per pass. false
 *        (logged) on a GL error or out of memory. chapters/11_clustered.c then dispatches the three
 *        passes of shaders/cluster_assign.comp (count, prefix sum, fill: per cluster the sphere
 *        against the cluster's box, and the list; a cluster reached by more than cluster_limit
 *        spheres gets count -1 and no entries), each program set by
 *   cluster_assign_gpu_use(a, pass)      its program in use with the grid's uniforms, and ends with
 *   cluster_assign_gpu_finish()          the storage slots unbound
 *   cluster_assign_gpu_read(out, clusters, lists)
 *        read the buffers back into lists->ranges and lists->indices (grown as needed; entries
 *        set): what the shading passes will read, for comparison with the CPU's
 *
 * shaders/cluster_assign.comp has the three passes: count, prefix sum, fill.
 */
#ifndef COMMON_CLUSTER_ASSIGN_GPU_H
#define COMMON_CLUSTER_ASSIGN_GPU_H

#include "cluster_lists.h"

#include <glad/gl.h>

typedef struct cluster_assign_buffers {
    GLuint range_buffer, range_texture, list_buffer, list_texture;
} cluster_assign_buffers;

typedef enum cluster_assign_pass {
    CLUSTER_ASSIGN_COUNT, /* per (slice, tile row): how many lights each of its clusters gets */
    CLUSTER_ASSIGN_SCAN,  /* one workgroup: where each row's entries begin */
    CLUSTER_ASSIGN_FILL,  /* per (slice, tile row): each cluster's (first, count) and list */
    CLUSTER_ASSIGN_PASSES
} cluster_assign_pass;

typedef struct cluster_assign_gpu {
    GLuint programs[CLUSTER_ASSIGN_PASSES];
    GLuint groups;         /* workgroups of the count and fill passes (one invocation per row) */
    cluster_grid grid;     /* the grid of the last prepare, and its list limit */
    int limit;
    GLuint sphere_buffer, candidate_buffer, row_buffer, box_buffer, cursor_buffer, hit_buffer;
    cluster_grid box_grid; /* the grid the box table was made for */
    float (*spheres)[4];   /* per light: view-space centre, grown radius */
    int (*records)[4];     /* per (light, slice): light, slice, tiles x0 | x1 << 16, y0 | y1 << 16 */
    int (*candidates)[2];  /* per (slice, tile row, light): light, tiles x0 | x1 << 16 */
    int *row_first;        /* slices x tile rows + 1: where each (slice, row)'s candidates begin; as many
                            * again: where its hit bits begin, in 32-bit words */
    float *boxes;          /* per (tile column, slice) x, per (tile row, slice) y, per slice z */
    int sphere_cap, record_cap, candidate_cap, row_cap, box_cap;
} cluster_assign_gpu;

bool cluster_assign_gpu_create(cluster_assign_gpu *a);
void cluster_assign_gpu_destroy(cluster_assign_gpu *a);
bool cluster_assign_gpu_prepare(cluster_assign_gpu *a, const cluster_grid *g, const float (*spheres)[4],
                                int count, int cluster_limit, const cluster_assign_buffers *out);
void cluster_assign_gpu_use(cluster_assign_gpu *a, cluster_assign_pass pass);
void cluster_assign_gpu_finish(void);
bool cluster_assign_gpu_read(const cluster_assign_buffers *out, int clusters, cluster_lists *lists);

#endif
