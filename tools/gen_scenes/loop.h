/* loop.h - Loop subdivision of a triangle mesh (Charles Loop, 1987), for the bunny the benchmark's
 * geometry-heavy scene needs: each level splits every triangle into four and smooths the surface.
 *
 *   loop_from_mesh_data(m, out)       positions and triangles of a loaded mesh, vertices welded by
 *                                     position (the loader splits them where normals differ)
 *   loop_subdivide(in, out)           one level: V + E vertices, 4 F triangles
 *   loop_write_ply(m, path, comments) binary little-endian PLY (positions and faces), atomically
 *   loop_destroy(m)
 *
 * The rules (docs in assets/scenes/README.md): a new vertex on an interior edge (a, b) with
 * opposite vertices c, d is 3/8 (a + b) + 1/8 (c + d), on a boundary edge (a + b) / 2; an old
 * interior vertex of valence n moves to (1 - n beta) v + beta * (sum of its neighbours) with
 * beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n; an old boundary vertex to 3/4 v + 1/8 (b1 + b2)
 * with its two boundary neighbours; a vertex where the surface is not a disc or a half-disc
 * (more than two boundary edges, an edge of three faces) stays where it is.
 */
#ifndef TOOLS_GEN_SCENES_LOOP_H
#define TOOLS_GEN_SCENES_LOOP_H

#include "mesh_data.h"

#include <stdbool.h>

typedef struct loop_mesh {
    double *positions; /* xyz per vertex */
    int *triangles;    /* 3 vertex indices per triangle */
    int vertex_count, triangle_count;
} loop_mesh;

bool loop_from_mesh_data(const mesh_data *m, loop_mesh *out);
bool loop_subdivide(const loop_mesh *in, loop_mesh *out);
bool loop_write_ply(const loop_mesh *m, const char *path, const char *const *comments);
void loop_destroy(loop_mesh *m);

#endif
