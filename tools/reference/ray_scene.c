/* ray_scene.c - see ray_scene.h. */
#include "ray_scene.h"

#include "mesh_data.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define LEAF_TRIANGLES 4

static void box_empty(double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++)
        lo[k] = DBL_MAX, hi[k] = -DBL_MAX;
}

static void box_add_triangle(double lo[3], double hi[3], const double *v)
{
    for (int i = 0; i < 9; i++)
        lo[i % 3] = fmin(lo[i % 3], v[i]), hi[i % 3] = fmax(hi[i % 3], v[i]);
}

static double centroid(const double *v, int axis) { return (v[axis] + v[3 + axis] + v[6 + axis]) / 3.0; }

/* Triangles [first, first + count) split at the median centroid of their box's longest axis. */
static int split(ray_object *t, int first, int count, const double lo[3], const double hi[3])
{
    int axis = 0;
    for (int k = 1; k < 3; k++)
        if (hi[k] - lo[k] > hi[axis] - lo[axis])
            axis = k;
    int a = first, b = first + count - 1, mid = first + count / 2;
    while (a < b) { /* quickselect of the median on the centroids */
        double pivot = centroid(&t->v[9 * ((a + b) / 2)], axis);
        int i = a, j = b;
        while (i <= j) {
            while (centroid(&t->v[9 * i], axis) < pivot)
                i++;
            while (centroid(&t->v[9 * j], axis) > pivot)
                j--;
            if (i <= j) {
                double tmp[9];
                memcpy(tmp, &t->v[9 * i], sizeof tmp);
                memcpy(&t->v[9 * i], &t->v[9 * j], sizeof tmp);
                memcpy(&t->v[9 * j], tmp, sizeof tmp);
                i++, j--;
            }
        }
        if (mid <= j)
            b = j;
        else if (mid >= i)
            a = i;
        else
            break;
    }
    return mid - first;
}

/* Node n over triangles [first, first + count), its children built after it. */
static void build_node(ray_object *t, int n, int first, int count)
{
    ray_node *node = &t->nodes[n];
    box_empty(node->lo, node->hi);
    for (int i = first; i < first + count; i++)
        box_add_triangle(node->lo, node->hi, &t->v[9 * i]);
    if (count <= LEAF_TRIANGLES) {
        node->first = first, node->count = count;
        return;
    }
    int left = split(t, first, count, node->lo, node->hi), child = t->node_count;
    t->node_count += 2;
    node->first = child, node->count = 0;
    build_node(t, child, first, left);
    build_node(t, child + 1, first + left, count - left);
}

bool ray_scene_build(ray_scene *rs, const scene *s, float time)
{
    memset(rs, 0, sizeof *rs);
    rs->objects = calloc((size_t)s->object_count, sizeof *rs->objects);
    if (!rs->objects)
        return false;
    rs->object_count = s->object_count;
    for (int o = 0; o < s->object_count; o++) {
        mesh_data md;
        if (!mesh_data_from_scene(&md, s, &s->meshes[s->objects[o].mesh]))
            return false;
        mat4 world;
        scene_object_world_at(s, o, time, world);
        ray_object *t = &rs->objects[o];
        t->count = md.index_count / 3, t->casts = !s->objects[o].cast_off;
        t->v = malloc((size_t)md.index_count * 3 * sizeof(double));
        t->nodes = malloc((size_t)(2 * t->count + 1) * sizeof *t->nodes);
        for (int i = 0; t->v && i < md.index_count; i++) {
            const float *p = &md.vertices[MESH_VERTEX_FLOATS * md.indices[i]];
            for (int r = 0; r < 3; r++) {
                double x = world[3][r];
                for (int c = 0; c < 3; c++)
                    x += (double)world[c][r] * p[c];
                t->v[3 * i + r] = x;
            }
        }
        mesh_data_destroy(&md);
        if (!t->v || !t->nodes)
            return false;
        t->node_count = 1;
        build_node(t, 0, 0, t->count);
        memcpy(t->lo, t->nodes[0].lo, sizeof t->lo);
        memcpy(t->hi, t->nodes[0].hi, sizeof t->hi);
    }
    return true;
}

/* Whether the segment o + t d, t in [0, tmax], meets the box (slabs). */
static bool ray_box(const double o[3], const double d[3], double tmax, const double lo[3], const double hi[3])
{
    double t0 = 0.0, t1 = tmax;
    for (int k = 0; k < 3; k++) {
        double inv = 1.0 / d[k], a = (lo[k] - o[k]) * inv, b = (hi[k] - o[k]) * inv;
        t0 = fmax(t0, fmin(a, b)), t1 = fmin(t1, fmax(a, b));
        if (t0 > t1 + 1e-12)
            return false;
    }
    return true;
}

/* Moller-Trumbore in double: the distance along d to triangle v (both sides), or -1. */
static double ray_triangle(const double o[3], const double d[3], const double *v)
{
    double e1[3], e2[3], p[3], q[3], s[3];
    for (int k = 0; k < 3; k++)
        e1[k] = v[3 + k] - v[k], e2[k] = v[6 + k] - v[k], s[k] = o[k] - v[k];
    p[0] = d[1] * e2[2] - d[2] * e2[1], p[1] = d[2] * e2[0] - d[0] * e2[2], p[2] = d[0] * e2[1] - d[1] * e2[0];
    double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    if (fabs(det) < 1e-300)
        return -1.0;
    double u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
    if (u < 0.0 || u > 1.0)
        return -1.0;
    q[0] = s[1] * e1[2] - s[2] * e1[1], q[1] = s[2] * e1[0] - s[0] * e1[2], q[2] = s[0] * e1[1] - s[1] * e1[0];
    double w = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
    if (w < 0.0 || u + w > 1.0)
        return -1.0;
    return (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
}

/* One object's hierarchy; *best and *tri updated; true when an any-hit ray may stop. */
static bool trace_object(const ray_object *t, const double o[3], const double d[3], double tmin, double tmax,
                         bool any, double *best, const double **tri)
{
    int stack[128], top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const ray_node *n = &t->nodes[stack[--top]];
        if (!ray_box(o, d, *best > 0.0 ? *best : tmax, n->lo, n->hi))
            continue;
        if (n->count == 0) {
            stack[top++] = n->first, stack[top++] = n->first + 1; /* depth <= log2(count) + 1 */
            continue;
        }
        for (int i = n->first; i < n->first + n->count; i++) {
            double h = ray_triangle(o, d, &t->v[9 * i]);
            if (h > tmin && h < tmax && (*best < 0.0 || h < *best)) {
                *best = h;
                if (tri)
                    *tri = &t->v[9 * i];
                if (any)
                    return true;
            }
        }
    }
    return false;
}

double ray_scene_trace(const ray_scene *rs, const double o[3], const double d[3], double tmin, double tmax, int filter,
                       const double **tri)
{
    double best = -1.0;
    for (int b = 0; b < rs->object_count; b++) {
        const ray_object *t = &rs->objects[b];
        if (((filter & RAY_CASTERS) && !t->casts) || !ray_box(o, d, tmax, t->lo, t->hi))
            continue;
        if (trace_object(t, o, d, tmin, tmax, filter & RAY_ANY, &best, tri))
            return best;
    }
    return best;
}

void ray_scene_destroy(ray_scene *rs)
{
    for (int b = 0; rs->objects && b < rs->object_count; b++)
        free(rs->objects[b].v), free(rs->objects[b].nodes);
    free(rs->objects);
    memset(rs, 0, sizeof *rs);
}
