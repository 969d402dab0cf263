/* vis_meshes.h - beside chapter 16 only: the triangles its shading pass fetches by id. Every mesh's
 * vertex and index buffers, copied on the GPU into one buffer each and exposed to the shader as
 * texture buffers, and per object where its mesh begins in them (docs/16_visibility_buffer.md).
 *
 *   vis_meshes_create(vm, gs)            copies every mesh of gs; false (logged) on failure
 *   vis_meshes_destroy(vm)
 *   vis_meshes_bind(vm, program, unit)   u_vertices, u_indices, u_object_meshes on unit, unit + 1,
 *                                        unit + 2
 */
#ifndef CHAPTERS_VIS_MESHES_H
#define CHAPTERS_VIS_MESHES_H

#include "gpu_scene.h"

/* The three tables, each a buffer seen through a texture buffer. */
enum {
    VIS_VERTICES, /* R32F: MESH_VERTEX_FLOATS per vertex (position, normal), every mesh's */
    VIS_INDICES,  /* R32UI: each mesh's indices as its own buffer holds them */
    VIS_OBJECTS,  /* RG32I per object: its mesh's first index, first vertex */
    VIS_TABLES
};

typedef struct vis_meshes {
    GLuint buffer[VIS_TABLES], texture[VIS_TABLES];
} vis_meshes;

bool vis_meshes_create(vis_meshes *vm, const gpu_scene *gs);
void vis_meshes_destroy(vis_meshes *vm);
void vis_meshes_bind(const vis_meshes *vm, GLuint program, int unit);

#endif
