/* teapot.h - the Utah teapot: Martin Newell's 32 Bezier patches (tools/teapot_patches.h)
 * tessellated and welded into one indexed mesh, and written as OBJ.
 *
 *   teapot_build_mesh(steps, out)   steps x steps quads per patch; seams welded into shared
 *                                   vertices, degenerate triangles dropped
 *   teapot_destroy(m)
 *   teapot_write_obj(m, path)       positions and texture coordinates to 6 decimals, 1-based
 *                                   faces, a comment header
 *
 * The mesh is y up, standing on y = 0 and 1 unit tall, wound counter-clockwise seen from
 * outside. Each patch's parameter square (u, v) is mapped onto the whole image, (s, t) =
 * (1 - v, 1 - u): the texture coordinates break at every patch border (a vertex there has one
 * position and one texture coordinate per patch), the positions do not (docs/18_pbr_materials.md).
 * Both fallible functions log their own error and return false.
 */
#ifndef TOOLS_GEN_SCENES_TEAPOT_H
#define TOOLS_GEN_SCENES_TEAPOT_H

#include <stdbool.h>

/* Quads per patch edge: the welded teapot then has 18,529 vertices, the closest a uniform
 * tessellation gets to the 18,906 of the published scene's model. */
#define TEAPOT_PATCH_STEPS 24

typedef struct teapot_mesh {
    int steps; /* quads per patch edge, for the OBJ's comment */
    double (*positions)[3];
    int vertex_count;
    int (*triangles)[3];          /* welded vertex numbers */
    int (*texcoord_triangles)[3]; /* grid numbers i * (steps + 1) + j: the patch's (u, v) = (i, j) / steps */
    int triangle_count;
} teapot_mesh;

bool teapot_build_mesh(int steps, teapot_mesh *out);
void teapot_destroy(teapot_mesh *m);
bool teapot_write_obj(const teapot_mesh *m, const char *path);

#endif
