/* cluster_assign_gpu.h - chapter 11's light assignment by compute shaders (GL 4.3): the same lists
 * as cluster_lists_assign (cluster_lists.h), written straight into the two buffers the shading
 * passes read, so that the shaders that read them do not change.
 *
 *   cluster_assign_gpu_create(a)      its buffers; the programs are made on first use
 *   cluster_assign_gpu_destroy(a)
 *   cluster_assign_gpu_run(a, g, spheres, count, cluster_limit, out)
 *        for the view-space spheres (xyz centre, w radius; w >= 1e30: infinite), the lists of grid
 *        g: per cluster (first, count) into out->range_buffer (RG32I), the light indices into
 *        out->list_buffer (R32I), both attached to their buffer textures; a cluster reached by more
 *        than cluster_limit spheres gets count -1 and no entries. The CPU does per light what is
 *        cheap (its slices, and the tiles of each: a candidate list per slice and tile row), the
 *        GPU per cluster what is not (the sphere against the cluster's box, and the list). false
 *        (logged) on a GL error or out of memory
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

typedef struct cluster_assign_gpu {
    GLuint programs[3]; /* count, prefix sum, fill */
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
bool cluster_assign_gpu_run(cluster_assign_gpu *a, const cluster_grid *g, const float (*spheres)[4],
                            int count, int cluster_limit, const cluster_assign_buffers *out);
bool cluster_assign_gpu_read(const cluster_assign_buffers *out, int clusters, cluster_lists *lists);

#endif
