/* cluster_grid.h - chapter 11's clusters without GL: the grid, the slice of a depth, the conservative
 * sphere test and the clusters a sphere may reach (the lists made from them: cluster_lists.h).
 *
 *   cluster_grid_init(g, width, height, tile_size, slices, proj, near, far)
 *        the grid of a view: tiles of tile_size x tile_size pixels (the last row and column may be
 *        narrower) times `slices` exponential view-depth slices between near and far; proj is the
 *        view's projection (column-major, as cglm stores it; a perspective one); slices 0: as many
 *        as cluster_grid_cubic_slices gives
 *   cluster_grid_cubic_slices(proj, tiles_y, near, far)
 *        the slices that make each cluster about as deep as it is tall (Olsson et al. 2012): slice k+1
 *        begins at (1 + 2 tan(fovy / 2) / tiles_y) times slice k's depth; at most CLUSTER_MAX_SLICES
 *   cluster_grid_slice(g, depth)          the slice of view depth `depth` (distance along -z):
 *                                         floor(ln(depth / near) * slices / ln(far / near)), clamped
 *                                         to [0, slices - 1] (depth <= near: 0, depth >= far: the last)
 *   cluster_grid_slice_depth(g, k)        where slice k begins: near * (far / near)^(k / slices);
 *                                         k = slices gives far
 *   cluster_grid_index(g, x, y, depth)    the cluster of pixel (x, y) at view depth `depth`, as the
 *                                         shaders find it (shaders/clusters.glsl): tiles row by row
 *                                         from the bottom left, slice after slice
 *   cluster_grid_count(g)                 tiles_x * tiles_y * slices
 *   cluster_grid_box(g, tx, ty, k, lo, hi)
 *                                         the view-space box around cluster (tx, ty, k): its frustum
 *                                         piece between the slice's two depths
 *   cluster_grid_sphere_touches(g, tx, ty, k, centre, radius)
 *                                         whether a view-space sphere can reach the cluster: its
 *                                         distance to the cluster's box is at most the radius
 *                                         (grown by 1e-4 of the distances involved, so that float
 *                                         rounding never drops a light); conservative, never exact
 *   cluster_grid_sphere_slices(g, sphere, &r, k)
 *                                         a finite view-space sphere's reach in depth: r its radius
 *                                         grown as cluster_grid_sphere_touches grows it, k[0]..k[1]
 *                                         the slices it may reach; false when it lies wholly before
 *                                         the near plane or beyond the far plane (no cluster)
 *   cluster_grid_sphere_tiles(g, sphere, r, k, tx, ty)
 *                                         the tiles tx[0]..tx[1] x ty[0]..ty[1] of its screen
 *                                         rectangle within slice k: the clusters worth testing there
 *                                         (cluster_lists_assign and common/clusters/cluster_assign_gpu.c both
 *                                         test exactly these, so their lists agree)
 *   cluster_light_bounds(position, direction, radius, cos_outer, out)
 *                                         a light's bounding sphere (xyz centre, w radius): a point
 *                                         light's own; a spot's, the smallest around its cone cut by
 *                                         its sphere (as chapter 10's light_bounds)
 */
#ifndef COMMON_CLUSTER_GRID_H
#define COMMON_CLUSTER_GRID_H

#include <stdbool.h>

#define CLUSTER_INFINITE_RADIUS 1e30f
#define CLUSTER_MAX_SLICES 512

typedef struct cluster_grid {
    int width, height;
    int tile_size, tiles_x, tiles_y, slices;
    float near_plane, far_plane;
    float log_scale; /* slices / ln(far / near) */
    float p00, p11;  /* the projection's x and y scales */
    float p20, p21;  /* and its off-centre terms (0 for a symmetric frustum) */
} cluster_grid;

void cluster_grid_init(cluster_grid *g, int width, int height, int tile_size, int slices,
                       const float proj[16], float near_plane, float far_plane);
int cluster_grid_cubic_slices(const float proj[16], int tiles_y, float near_plane, float far_plane);
int cluster_grid_slice(const cluster_grid *g, float depth);
float cluster_grid_slice_depth(const cluster_grid *g, int k);
int cluster_grid_index(const cluster_grid *g, int x, int y, float depth);
int cluster_grid_count(const cluster_grid *g);
void cluster_grid_box(const cluster_grid *g, int tx, int ty, int k, float lo[3], float hi[3]);
bool cluster_grid_sphere_touches(const cluster_grid *g, int tx, int ty, int k, const float centre[3],
                                 float radius);
bool cluster_grid_sphere_slices(const cluster_grid *g, const float sphere[4], float *r, int k[2]);
void cluster_grid_sphere_tiles(const cluster_grid *g, const float sphere[4], float r, int k, int tx[2],
                               int ty[2]);
void cluster_light_bounds(const float position[3], const float direction[3], float radius, float cos_outer,
                          float out[4]);

#endif
