/* teapot.c - Bezier patch tessellation, vertex welding, the patches' texture coordinates and the OBJ
 * writer. */
#include "teapot.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gen_format.h"
#include "gen_path.h"
#include "log.h"
#include "teapot_patches.h"

/* Open addressing on the position rounded to 1e-6: seams of neighbouring patches are the same
 * curve evaluated from two sides, equal up to rounding, and must become one vertex so the
 * loader's smooth normals do not show the patch borders. */
typedef struct weld_table {
    int *slots; /* vertex index + 1, 0 when empty */
    int capacity;
} weld_table;

static void teapot_bezier_weights(double t, double out[4])
{
    double s = 1.0 - t;
    out[0] = s * s * s;
    out[1] = 3.0 * s * s * t;
    out[2] = 3.0 * s * t * t;
    out[3] = t * t * t;
}

/* FNV-1a over the rounded coordinates, folded to 32 bits. */
static uint32_t teapot_weld_hash(const long long key[3])
{
    uint64_t h = 1469598103934665603ull;
    for (int i = 0; i < 3; i++) {
        h ^= (uint64_t)key[i];
        h *= 1099511628211ull;
    }
    return (uint32_t)(h ^ (h >> 32));
}

/* The index of the vertex at p, added to the mesh the first time p is seen. */
static int teapot_weld_vertex(teapot_mesh *m, weld_table *w, const double p[3])
{
    long long key[3];
    for (int i = 0; i < 3; i++) {
        key[i] = llround(p[i] * 1e6);
    }
    uint32_t slot = teapot_weld_hash(key) % (uint32_t)w->capacity;
    for (;;) {
        int v = w->slots[slot] - 1;
        if (v < 0) {
            break;
        }
        const double *q = m->positions[v];
        if (llround(q[0] * 1e6) == key[0] && llround(q[1] * 1e6) == key[1] && llround(q[2] * 1e6) == key[2]) {
            return v;
        }
        slot = (slot + 1) % (uint32_t)w->capacity;
    }
    memcpy(m->positions[m->vertex_count], p, sizeof m->positions[0]);
    w->slots[slot] = m->vertex_count + 1;
    return m->vertex_count++;
}

/* A triangle of grid points: their welded vertices and their grid numbers (the texture coordinate's
 * index, since every patch maps its parameter square onto the same image). */
static void teapot_add_triangle(teapot_mesh *m, const int *index, int a, int b, int c)
{
    if (index[a] == index[b] || index[b] == index[c] || index[a] == index[c]) {
        return; /* the collapsed row at the knob tip and the centre of the bottom */
    }
    const int corner[3] = {a, b, c};
    for (int k = 0; k < 3; k++) {
        m->triangles[m->triangle_count][k] = index[corner[k]];
        m->texcoord_triangles[m->triangle_count][k] = corner[k];
    }
    m->triangle_count++;
}

/* The texture coordinate of grid line k of steps: 1 - k / steps, so that s = 1 - v, t = 1 - u. The
 * patches wind (u, v) clockwise seen from outside with u running down the body from the rim; both
 * reversed, the image stands upright (t up) and unmirrored (s to the right) on the body. */
static double teapot_texcoord(int steps, int k)
{
    return (double)(steps - k) / steps;
}

/* y up, standing on y = 0, 1 unit tall: the data is z up and 3.15 tall. */
static void teapot_evaluate(int patch, double u, double v, double out[3])
{
    double bu[4], bv[4], p[3] = {0, 0, 0};
    teapot_bezier_weights(u, bu);
    teapot_bezier_weights(v, bv);
    for (int i = 0; i < 4; i++) {
        for (int j = 0; j < 4; j++) {
            const float *c = teapot_control_points[teapot_patches[patch][4 * i + j]];
            for (int k = 0; k < 3; k++) {
                p[k] += bu[i] * bv[j] * c[k];
            }
        }
    }
    out[0] = p[0] / 3.15;
    out[1] = p[2] / 3.15;
    out[2] = -p[1] / 3.15;
}

/* One patch's (steps + 1)^2 grid, welded into the mesh; index receives the grid's vertex numbers. */
static void teapot_add_patch(teapot_mesh *m, weld_table *w, int patch, int steps, int *index)
{
    for (int i = 0; i <= steps; i++) {
        for (int j = 0; j <= steps; j++) {
            double p[3];
            teapot_evaluate(patch, (double)i / steps, (double)j / steps, p);
            index[i * (steps + 1) + j] = teapot_weld_vertex(m, w, p);
        }
    }
    /* The patch data winds (u, v) clockwise seen from outside, hence a-d-c and a-c-b. */
    for (int i = 0; i < steps; i++) {
        for (int j = 0; j < steps; j++) {
            int a = i * (steps + 1) + j, b = (i + 1) * (steps + 1) + j;
            int c = (i + 1) * (steps + 1) + j + 1, d = i * (steps + 1) + j + 1;
            teapot_add_triangle(m, index, a, d, c);
            teapot_add_triangle(m, index, a, c, b);
        }
    }
}

bool teapot_build_mesh(int steps, teapot_mesh *out)
{
    int grid = (steps + 1) * (steps + 1);
    int max_vertices = TEAPOT_PATCH_COUNT * grid;
    int *index = malloc(sizeof *index * (size_t)grid);
    /* A quarter full at most, so the linear probes stay short. */
    weld_table w = {.capacity = 4 * max_vertices};
    w.slots = calloc((size_t)w.capacity, sizeof *w.slots);
    *out = (teapot_mesh){.steps = steps};
    out->positions = malloc(sizeof *out->positions * (size_t)max_vertices);
    out->triangles = malloc(sizeof *out->triangles * (size_t)(TEAPOT_PATCH_COUNT * steps * steps * 2));
    out->texcoord_triangles = malloc(sizeof *out->texcoord_triangles * (size_t)(TEAPOT_PATCH_COUNT * steps * steps * 2));
    bool ok = index && w.slots && out->positions && out->triangles && out->texcoord_triangles;
    if (!ok) {
        log_error("teapot: out of memory");
        teapot_destroy(out);
    }
    for (int patch = 0; ok && patch < TEAPOT_PATCH_COUNT; patch++) {
        teapot_add_patch(out, &w, patch, steps, index);
    }
    free(index);
    free(w.slots);
    return ok;
}

void teapot_destroy(teapot_mesh *m)
{
    free(m->positions);
    free(m->triangles);
    free(m->texcoord_triangles);
    *m = (teapot_mesh){0};
}

bool teapot_write_obj(const teapot_mesh *m, const char *path)
{
    FILE *f = gen_path_open_file(path);
    if (!f) {
        return false;
    }
    fprintf(f, "# Utah teapot (Martin Newell's 32 Bezier patches), tessellated by tools/gen_scenes.c\n");
    fprintf(f, "# %d x %d quads per patch, seams welded, degenerate triangles dropped\n", m->steps, m->steps);
    fprintf(f, "# y up, standing on y = 0, height 1; %d vertices, %d triangles\n", m->vertex_count,
            m->triangle_count);
    fprintf(f, "# texture coordinates: each patch's parameter square on the whole image, s = 1 - v, t = 1 - u\n");
    for (int i = 0; i < m->vertex_count; i++) {
        fprintf(f, "v ");
        gen_format_write_vec3(m->positions[i], 6, f);
        fprintf(f, "\n");
    }
    /* The grid's (steps + 1)^2 parameter pairs, numbered as teapot_add_patch numbers a patch's points. */
    for (int i = 0; i <= m->steps; i++) {
        for (int j = 0; j <= m->steps; j++) {
            char s[32], t[32];
            fprintf(f, "vt %s %s\n", gen_format_number(teapot_texcoord(m->steps, j), 6, s),
                    gen_format_number(teapot_texcoord(m->steps, i), 6, t));
        }
    }
    for (int i = 0; i < m->triangle_count; i++) {
        const int *p = m->triangles[i], *t = m->texcoord_triangles[i];
        fprintf(f, "f %d/%d %d/%d %d/%d\n", p[0] + 1, t[0] + 1, p[1] + 1, t[1] + 1, p[2] + 1, t[2] + 1);
    }
    return gen_path_close_file(f, path);
}
