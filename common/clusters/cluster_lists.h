/* cluster_lists.h - chapter 11's per-cluster light lists, made on the CPU without GL from the grid
 * of cluster_grid.h (common/clusters/clusters.c uploads them; common/clusters/cluster_assign_gpu.c makes the same
 * lists with compute shaders).
 *
 *   cluster_lists_assign(lists, g, spheres, count, cluster_limit)
 *                                         for every view-space sphere (xyz centre, w radius; w >= 1e30:
 *                                         infinite, in every cluster), in order, the clusters it can
 *                                         reach; then per cluster (first, count) in lists->ranges and
 *                                         the sphere indices in lists->indices, each list in sphere
 *                                         order. A cluster reached by more than cluster_limit spheres
 *                                         (> 0; the list overflows) gets count -1 and no entries: its
 *                                         pixels loop over every light. false when out of memory
 *   cluster_lists_first_difference(a, b)  the first cluster whose (first, count) or entries differ
 *                                         between two sets of lists (or whose cluster counts do); -1
 *                                         when they are the same
 *   cluster_lists_destroy(lists)
 */
#ifndef COMMON_CLUSTER_LISTS_H
#define COMMON_CLUSTER_LISTS_H

#include "cluster_grid.h"

#include <stdbool.h>

typedef struct cluster_lists {
    int *ranges;      /* per cluster: first entry, count (-1: every light) */
    int *indices;     /* the entries */
    int entries;      /* used in indices */
    int clusters;     /* ranges holds 2 * clusters ints */
    long pairs_total; /* (cluster, light) hits before any cluster fell back to every light */
    int overflowed;   /* clusters whose count is -1 */
    /* work space */
    int *pairs, pair_cap, range_cap, index_cap;
} cluster_lists;

bool cluster_lists_assign(cluster_lists *lists, const cluster_grid *g, const float (*spheres)[4], int count,
                          int cluster_limit);
int cluster_lists_first_difference(const cluster_lists *a, const cluster_lists *b);
void cluster_lists_destroy(cluster_lists *lists);

#endif
