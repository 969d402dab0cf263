/* cluster_lists.c - see cluster_lists.h. */
#include "cluster_lists.h"

#include "log.h"

#include <stdlib.h>

static bool grow(int **p, int *cap, long need)
{
    if (need <= *cap)
        return true;
    long n = *cap ? *cap : 4096;
    while (n < need)
        n *= 2;
    int *q = realloc(*p, (size_t)n * sizeof *q);
    if (!q) {
        log_error("out of memory for the cluster lists");
        return false;
    }
    *p = q, *cap = (int)n;
    return true;
}

static bool add_pair(cluster_lists *l, int *hits, int cluster, int light)
{
    if (!grow(&l->pairs, &l->pair_cap, 2L * (*hits + 1)))
        return false;
    l->pairs[2 * *hits] = cluster, l->pairs[2 * *hits + 1] = light;
    ++*hits;
    l->ranges[2 * cluster + 1]++;
    return true;
}

/* One sphere into every cluster it can reach: per slice of its depth span, the tiles of its box's
 * screen rectangle there, each tested against the cluster's box. */
static bool assign_sphere(cluster_lists *l, const cluster_grid *g, const float s[4], int light, int *hits)
{
    int clusters = cluster_grid_count(g);
    if (s[3] >= CLUSTER_INFINITE_RADIUS) {
        for (int c = 0; c < clusters; c++)
            if (!add_pair(l, hits, c, light))
                return false;
        return true;
    }
    float r;
    int k[2];
    if (!cluster_grid_sphere_slices(g, s, &r, k))
        return true;
    for (int slice = k[0]; slice <= k[1]; slice++) {
        int tx[2], ty[2];
        cluster_grid_sphere_tiles(g, s, r, slice, tx, ty);
        for (int y = ty[0]; y <= ty[1]; y++) {
            for (int x = tx[0]; x <= tx[1]; x++) {
                if (cluster_grid_sphere_touches(g, x, y, slice, s, s[3]) &&
                    !add_pair(l, hits, (slice * g->tiles_y + y) * g->tiles_x + x, light))
                    return false;
            }
        }
    }
    return true;
}

bool cluster_lists_assign(cluster_lists *l, const cluster_grid *g, const float (*spheres)[4], int count,
                          int cluster_limit)
{
    int clusters = cluster_grid_count(g), hits = 0;
    if (!grow(&l->ranges, &l->range_cap, 2L * clusters))
        return false;
    l->clusters = clusters;
    for (int c = 0; c < clusters; c++)
        l->ranges[2 * c] = 0, l->ranges[2 * c + 1] = 0; /* count of hits, for now */
    for (int i = 0; i < count; i++)
        if (!assign_sphere(l, g, spheres[i], i, &hits))
            return false;
    /* Each cluster's range. A cluster over the limit keeps none and loops over every light
     * instead: slower, never wrong. */
    l->pairs_total = hits;
    int share = cluster_limit > 0 ? cluster_limit : hits;
    int entries = 0;
    l->overflowed = 0;
    for (int c = 0; c < clusters; c++) {
        int n = l->ranges[2 * c + 1];
        bool over = n > share;
        l->ranges[2 * c] = entries;
        l->ranges[2 * c + 1] = over ? -1 : 0;
        entries += over ? 0 : n;
        l->overflowed += over;
    }
    if (!grow(&l->indices, &l->index_cap, entries + 1L))
        return false;
    for (int h = 0; h < hits; h++) {
        int *range = &l->ranges[2 * l->pairs[2 * h]];
        if (range[1] >= 0)
            l->indices[range[0] + range[1]++] = l->pairs[2 * h + 1];
    }
    l->entries = entries;
    return true;
}

int cluster_lists_first_difference(const cluster_lists *a, const cluster_lists *b)
{
    if (a->clusters != b->clusters)
        return 0;
    for (int c = 0; c < a->clusters; c++) {
        const int *ra = &a->ranges[2 * c], *rb = &b->ranges[2 * c];
        if (ra[0] != rb[0] || ra[1] != rb[1])
            return c;
        for (int i = 0; i < ra[1]; i++)
            if (a->indices[ra[0] + i] != b->indices[rb[0] + i])
                return c;
    }
    return -1;
}

void cluster_lists_destroy(cluster_lists *l)
{
    free(l->ranges), free(l->indices), free(l->pairs);
    *l = (cluster_lists){0};
}
