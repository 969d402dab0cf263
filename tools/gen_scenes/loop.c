/* loop.c - see loop.h. */
#include "loop.h"

#include "log.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define LOOP_PI 3.14159265358979323846

/* One side of a triangle: the undirected edge {lo, hi}, its triangle, which side, and the corner
 * opposite it. */
typedef struct half_edge {
    int lo, hi, triangle, side, opposite;
} half_edge;

static int by_edge(const void *x, const void *y)
{
    const half_edge *a = x, *b = y;
    if (a->lo != b->lo)
        return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi)
        return a->hi < b->hi ? -1 : 1;
    return (a->triangle > b->triangle) - (a->triangle < b->triangle);
}

static const float *weld_vertices; /* qsort has no context argument */

static int by_position(const void *x, const void *y)
{
    const float *a = weld_vertices + (size_t)*(const int *)x * MESH_VERTEX_FLOATS;
    const float *b = weld_vertices + (size_t)*(const int *)y * MESH_VERTEX_FLOATS;
    for (int k = 0; k < 3; k++)
        if (a[k] != b[k])
            return a[k] < b[k] ? -1 : 1;
    return (*(const int *)x > *(const int *)y) - (*(const int *)x < *(const int *)y);
}

bool loop_from_mesh_data(const mesh_data *m, loop_mesh *out)
{
    memset(out, 0, sizeof *out);
    int n = m->vertex_count;
    int *order = malloc((size_t)n * sizeof *order), *map = malloc((size_t)n * sizeof *map);
    out->positions = malloc((size_t)n * 3 * sizeof *out->positions);
    out->triangles = malloc((size_t)m->index_count * sizeof *out->triangles);
    if (!order || !map || !out->positions || !out->triangles) {
        free(order), free(map), loop_destroy(out);
        log_error("loop: out of memory for %d vertices", n);
        return false;
    }
    for (int i = 0; i < n; i++)
        order[i] = i;
    weld_vertices = m->vertices;
    qsort(order, (size_t)n, sizeof *order, by_position);
    for (int i = 0; i < n; i++) { /* equal positions are neighbours in `order` */
        const float *p = m->vertices + (size_t)order[i] * MESH_VERTEX_FLOATS;
        if (i == 0 || memcmp(p, m->vertices + (size_t)order[i - 1] * MESH_VERTEX_FLOATS, 3 * sizeof *p) != 0) {
            for (int k = 0; k < 3; k++)
                out->positions[3 * out->vertex_count + k] = p[k];
            out->vertex_count++;
        }
        map[order[i]] = out->vertex_count - 1;
    }
    for (int i = 0; i < m->index_count; i++)
        out->triangles[i] = map[m->indices[i]];
    out->triangle_count = m->index_count / 3;
    free(order), free(map);
    return true;
}

/* Every side of every triangle, sorted so that the sides of one edge are together. */
static half_edge *sorted_sides(const loop_mesh *in)
{
    half_edge *h = malloc((size_t)in->triangle_count * 3 * sizeof *h);
    if (!h)
        return NULL;
    for (int t = 0; t < in->triangle_count; t++)
        for (int s = 0; s < 3; s++) {
            int a = in->triangles[3 * t + s], b = in->triangles[3 * t + (s + 1) % 3];
            h[3 * t + s] = (half_edge){a < b ? a : b, a < b ? b : a, t, s, in->triangles[3 * t + (s + 2) % 3]};
        }
    qsort(h, (size_t)in->triangle_count * 3, sizeof *h, by_edge);
    return h;
}

/* Per old vertex: sum and count of all neighbours, and of the neighbours along boundary edges. */
typedef struct ring {
    double sum[3], boundary_sum[3];
    int valence, boundary;
} ring;

static void add_neighbour(ring *r, const double *p, bool boundary)
{
    for (int k = 0; k < 3; k++)
        r->sum[k] += p[k], r->boundary_sum[k] += boundary ? p[k] : 0.0;
    r->valence++;
    r->boundary += boundary;
}

static void move_old_vertex(const double *v, const ring *r, double *out)
{
    for (int k = 0; k < 3; k++)
        out[k] = v[k];
    if (r->boundary == 2) {
        for (int k = 0; k < 3; k++)
            out[k] = 0.75 * v[k] + 0.125 * r->boundary_sum[k];
    } else if (r->boundary == 0 && r->valence >= 3) {
        double n = r->valence, c = 0.375 + 0.25 * cos(2.0 * LOOP_PI / n);
        double beta = (0.625 - c * c) / n;
        for (int k = 0; k < 3; k++)
            out[k] = (1.0 - n * beta) * v[k] + beta * r->sum[k];
    }
}

/* The new vertex of each edge (sides h[first .. first + count)), and the edge's index per side. */
static void make_edge_vertices(const loop_mesh *in, const half_edge *h, int sides, ring *rings, loop_mesh *out,
                               int *edge_of_side)
{
    for (int i = 0; i < sides;) {
        int count = 1;
        while (i + count < sides && h[i + count].lo == h[i].lo && h[i + count].hi == h[i].hi)
            count++;
        const double *a = in->positions + 3 * h[i].lo, *b = in->positions + 3 * h[i].hi;
        double *e = out->positions + 3 * out->vertex_count;
        bool interior = count == 2;
        for (int k = 0; k < 3; k++)
            e[k] = interior ? 0.375 * (a[k] + b[k]) +
                                  0.125 * (in->positions[3 * h[i].opposite + k] + in->positions[3 * h[i + 1].opposite + k])
                            : 0.5 * (a[k] + b[k]);
        add_neighbour(&rings[h[i].lo], b, !interior);
        add_neighbour(&rings[h[i].hi], a, !interior);
        if (count > 2) /* an edge of three or more faces: pin both ends */
            rings[h[i].lo].boundary = rings[h[i].hi].boundary = 3;
        for (int j = i; j < i + count; j++)
            edge_of_side[3 * h[j].triangle + h[j].side] = out->vertex_count;
        out->vertex_count++;
        i += count;
    }
}

bool loop_subdivide(const loop_mesh *in, loop_mesh *out)
{
    memset(out, 0, sizeof *out);
    int sides = in->triangle_count * 3;
    half_edge *h = sorted_sides(in);
    ring *rings = calloc((size_t)in->vertex_count, sizeof *rings);
    int *edge_of_side = malloc((size_t)sides * sizeof *edge_of_side);
    out->positions = malloc(((size_t)in->vertex_count + (size_t)sides) * 3 * sizeof *out->positions);
    out->triangles = malloc((size_t)in->triangle_count * 12 * sizeof *out->triangles);
    if (!h || !rings || !edge_of_side || !out->positions || !out->triangles) {
        free(h), free(rings), free(edge_of_side), loop_destroy(out);
        log_error("loop: out of memory for %d triangles", in->triangle_count);
        return false;
    }
    out->vertex_count = in->vertex_count; /* old vertices first, then one per edge */
    make_edge_vertices(in, h, sides, rings, out, edge_of_side);
    for (int v = 0; v < in->vertex_count; v++)
        move_old_vertex(in->positions + 3 * v, &rings[v], out->positions + 3 * v);
    for (int t = 0; t < in->triangle_count; t++) { /* the corners and the middle, same winding */
        const int *c = in->triangles + 3 * t, *e = edge_of_side + 3 * t; /* e[s]: edge c[s] -> c[s+1] */
        const int split[4][3] = {{c[0], e[0], e[2]}, {e[0], c[1], e[1]}, {e[2], e[1], c[2]}, {e[0], e[1], e[2]}};
        memcpy(out->triangles + 12 * t, split, sizeof split);
    }
    out->triangle_count = in->triangle_count * 4;
    free(h), free(rings), free(edge_of_side);
    return true;
}

static bool put_le32(FILE *f, uint32_t v)
{
    const unsigned char b[4] = {v & 255u, (v >> 8) & 255u, (v >> 16) & 255u, v >> 24};
    return fwrite(b, 1, 4, f) == 4;
}

static bool write_body(FILE *f, const loop_mesh *m)
{
    bool ok = true;
    for (int i = 0; i < m->vertex_count * 3 && ok; i++) {
        float x = (float)m->positions[i];
        uint32_t bits;
        memcpy(&bits, &x, sizeof bits);
        ok = put_le32(f, bits);
    }
    for (int t = 0; t < m->triangle_count && ok; t++) {
        ok = fputc(3, f) != EOF;
        for (int k = 0; k < 3 && ok; k++)
            ok = put_le32(f, (uint32_t)m->triangles[3 * t + k]);
    }
    return ok;
}

bool loop_write_ply(const loop_mesh *m, const char *path, const char *const *comments)
{
    char tmp[4200];
    snprintf(tmp, sizeof tmp, "%s.tmp-%ld", path, (long)getpid());
    FILE *f = fopen(tmp, "wb");
    if (!f) {
        log_error("%s: cannot write", tmp);
        return false;
    }
    fprintf(f, "ply\nformat binary_little_endian 1.0\n");
    for (int i = 0; comments && comments[i]; i++)
        fprintf(f, "comment %s\n", comments[i]);
    fprintf(f, "element vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
               "element face %d\nproperty list uchar int vertex_indices\nend_header\n",
            m->vertex_count, m->triangle_count);
    bool ok = write_body(f, m);
    ok = fclose(f) == 0 && ok;
    if (!ok || rename(tmp, path) != 0) {
        remove(tmp);
        log_error("%s: cannot write", path);
        return false;
    }
    return true;
}

void loop_destroy(loop_mesh *m)
{
    free(m->positions);
    free(m->triangles);
    m->positions = NULL, m->triangles = NULL;
}
