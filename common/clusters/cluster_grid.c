/* cluster_grid.c - see cluster_grid.h. */
#include "cluster_grid.h"

#include <math.h>

void cluster_grid_init(cluster_grid *g, int width, int height, int tile_size, int slices,
                       const float proj[16], float near_plane, float far_plane)
{
    g->width = width > 0 ? width : 1;
    g->height = height > 0 ? height : 1;
    g->tile_size = tile_size > 0 ? tile_size : 1;
    g->tiles_x = (g->width + g->tile_size - 1) / g->tile_size;
    g->tiles_y = (g->height + g->tile_size - 1) / g->tile_size;
    g->near_plane = near_plane;
    g->far_plane = far_plane > near_plane ? far_plane : near_plane * 2.0f;
    g->slices =
        slices > 0 ? slices : cluster_grid_cubic_slices(proj, g->tiles_y, g->near_plane, g->far_plane);
    g->log_scale = (float)g->slices / logf(g->far_plane / g->near_plane);
    g->p00 = proj[0], g->p11 = proj[5], g->p20 = proj[8], g->p21 = proj[9];
}

int cluster_grid_cubic_slices(const float proj[16], int tiles_y, float near_plane, float far_plane)
{
    /* a tile row spans 2 / (p11 tiles_y) of the depth it is seen at */
    double step = log(1.0 + 2.0 / ((double)proj[5] * (tiles_y > 0 ? tiles_y : 1)));
    double s = ceil(log((double)far_plane / (double)near_plane) / step);
    return s < 1.0 ? 1 : s > CLUSTER_MAX_SLICES ? CLUSTER_MAX_SLICES : (int)s;
}

int cluster_grid_slice(const cluster_grid *g, float depth)
{
    /* at or before the near plane (and NaN): slice 0; log() of 0 or less is never taken */
    if (!(depth > g->near_plane))
        return 0;
    int k = (int)floorf(logf(depth / g->near_plane) * g->log_scale);
    return k < 0 ? 0 : k >= g->slices ? g->slices - 1 : k;
}

float cluster_grid_slice_depth(const cluster_grid *g, int k)
{
    if (k >= g->slices)
        return g->far_plane;
    return g->near_plane * powf(g->far_plane / g->near_plane, (float)k / (float)g->slices);
}

int cluster_grid_count(const cluster_grid *g)
{
    return g->tiles_x * g->tiles_y * g->slices;
}

static int clampi(int v, int lo, int hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

int cluster_grid_index(const cluster_grid *g, int x, int y, float depth)
{
    int tx = clampi(x / g->tile_size, 0, g->tiles_x - 1), ty = clampi(y / g->tile_size, 0, g->tiles_y - 1);
    return (cluster_grid_slice(g, depth) * g->tiles_y + ty) * g->tiles_x + tx;
}

/* The NDC edges of tile t along an axis of `pixels` pixels. */
static void tile_ndc(const cluster_grid *g, int t, int pixels, float out[2])
{
    int a = t * g->tile_size, b = (t + 1) * g->tile_size;
    out[0] = (float)a / (float)pixels * 2.0f - 1.0f;
    out[1] = (float)(b < pixels ? b : pixels) / (float)pixels * 2.0f - 1.0f;
}

void cluster_grid_box(const cluster_grid *g, int tx, int ty, int k, float lo[3], float hi[3])
{
    float d[2] = {cluster_grid_slice_depth(g, k), cluster_grid_slice_depth(g, k + 1)};
    float nx[2], ny[2];
    tile_ndc(g, tx, g->width, nx);
    tile_ndc(g, ty, g->height, ny);
    /* x = d (ndc_x + p20) / p00: linear in d for a fixed ndc, so the box's corners are among these */
    lo[0] = lo[1] = INFINITY, hi[0] = hi[1] = -INFINITY;
    for (int i = 0; i < 2; i++) {
        for (int j = 0; j < 2; j++) {
            float x = d[i] * (nx[j] + g->p20) / g->p00, y = d[i] * (ny[j] + g->p21) / g->p11;
            lo[0] = fminf(lo[0], x), hi[0] = fmaxf(hi[0], x);
            lo[1] = fminf(lo[1], y), hi[1] = fmaxf(hi[1], y);
        }
    }
    lo[2] = -d[1], hi[2] = -d[0]; /* view space looks down -z */
}

/* The radius grown so that float rounding (here and in the shaders' slice) never cuts a light. */
static float safe_radius(const float c[3], float r)
{
    return r + 1e-4f * (r + sqrtf(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]));
}

static bool box_touches(const float lo[3], const float hi[3], const float c[3], float r)
{
    float d2 = 0.0f;
    for (int i = 0; i < 3; i++) {
        float e = c[i] < lo[i] ? lo[i] - c[i] : c[i] > hi[i] ? c[i] - hi[i] : 0.0f;
        d2 += e * e;
    }
    return d2 <= r * r;
}

bool cluster_grid_sphere_touches(const cluster_grid *g, int tx, int ty, int k, const float centre[3],
                                 float radius)
{
    if (radius >= CLUSTER_INFINITE_RADIUS)
        return true;
    float lo[3], hi[3];
    cluster_grid_box(g, tx, ty, k, lo, hi);
    return box_touches(lo, hi, centre, safe_radius(centre, radius));
}

void cluster_light_bounds(const float position[3], const float direction[3], float radius, float cos_outer,
                          float out[4])
{
    float c = cos_outer;
    bool point = c <= 0.0f || radius >= CLUSTER_INFINITE_RADIUS, narrow = c >= 0.70710678f;
    float along = point ? 0.0f : narrow ? radius / (2.0f * c) : radius * c;
    for (int k = 0; k < 3; k++)
        out[k] = position[k] + along * direction[k];
    out[3] = point ? radius : narrow ? along : radius * sqrtf(1.0f - c * c);
}

/* The tiles [t0, t1] along an axis whose NDC is scale * v / d - offset, for v in [v0, v1] and
 * d in [d0, d1] (d > 0): the extremes are at the corners. */
static void tile_span(const cluster_grid *g, float scale, float offset, float v0, float v1, float d0,
                      float d1, int pixels, int tiles, int out[2])
{
    float lo = INFINITY, hi = -INFINITY;
    const float v[2] = {v0, v1}, d[2] = {d0, d1};
    for (int i = 0; i < 2; i++) {
        for (int j = 0; j < 2; j++) {
            float n = scale * v[i] / d[j] - offset;
            lo = fminf(lo, n), hi = fmaxf(hi, n);
        }
    }
    lo = fmaxf(lo, -1.0f), hi = fminf(hi, 1.0f);
    out[0] = clampi((int)floorf((lo + 1.0f) * 0.5f * (float)pixels) / g->tile_size, 0, tiles - 1);
    out[1] = clampi((int)floorf((hi + 1.0f) * 0.5f * (float)pixels) / g->tile_size, 0, tiles - 1);
}

bool cluster_grid_sphere_slices(const cluster_grid *g, const float s[4], float *r_out, int k[2])
{
    float r = safe_radius(s, s[3]), depth = -s[2];
    *r_out = r;
    if (depth + r < g->near_plane || depth - r > g->far_plane)
        return false; /* wholly before the near plane or beyond the far plane: no visible surface */
    k[0] = cluster_grid_slice(g, depth - r), k[1] = cluster_grid_slice(g, depth + r);
    return true;
}

void cluster_grid_sphere_tiles(const cluster_grid *g, const float s[4], float r, int k, int tx[2], int ty[2])
{
    float depth = -s[2];
    float d0 = fmaxf(cluster_grid_slice_depth(g, k), depth - r);
    float d1 = fminf(cluster_grid_slice_depth(g, k + 1), depth + r);
    if (k == g->slices - 1)
        d1 = depth + r; /* the last slice also holds what rounds past the far plane */
    if (d0 <= 0.0f)
        d0 = g->near_plane;
    tile_span(g, g->p00, g->p20, s[0] - r, s[0] + r, d0, d1, g->width, g->tiles_x, tx);
    tile_span(g, g->p11, g->p21, s[1] - r, s[1] + r, d0, d1, g->height, g->tiles_y, ty);
}
