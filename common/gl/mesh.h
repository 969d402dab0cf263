/* mesh.h - a mesh_data uploaded to the GPU.
 *
 *   mesh_create(data, mesh)         VAO with position (location 0) and normal (location 1)
 *   mesh_destroy(mesh)
 *   mesh_draw(mesh)                 glDrawElements of all triangles
 *   mesh_draw_instanced(mesh, n)
 */
#ifndef COMMON_MESH_H
#define COMMON_MESH_H

#include "mesh_data.h"

#include <glad/gl.h>

typedef struct mesh {
    GLuint vao, vbo, ibo;
    GLsizei index_count;
    float bounds_min[3], bounds_max[3];
    float bound_radius;
} mesh;

bool mesh_create(const mesh_data *data, mesh *out);
void mesh_destroy(mesh *m);
void mesh_draw(const mesh *m);
void mesh_draw_instanced(const mesh *m, int instances);

#endif
