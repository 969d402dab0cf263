/* mesh_data.h - triangle meshes on the CPU: the built-in shapes and model files.
 *
 *   mesh_data_cube(m)                    corners at +-0.5, flat normals (24 vertices)
 *   mesh_data_plane(m)                   unit square at y = 0, normal +Y, single-sided
 *   mesh_data_sphere(m, slices, stacks)  unit UV sphere: 2*slices*(stacks-1) triangles
 *   mesh_data_icosphere(m, subdivisions) unit-circumradius icosphere (20 * 4^n triangles)
 *   mesh_data_load(m, path, origin)      a model file through Assimp (.obj, .ply, .off, .stl, .gltf,
 *                                        .glb), within the limits of model_file.h and validated before
 *                                        any post-processing; origin ("scene.scene:7") prefixes errors
 *   mesh_data_load_memory(m, name, data, size, origin)
 *                                        the same from bytes (format from name's extension; files
 *                                        the model names are not read): the fuzz target's way in
 *   mesh_data_from_scene(m, s, decl)     the mesh a scene's `mesh` line declares (built-in or
 *                                        file), errors at that line; a `model` line's part (part >= 0):
 *                                        that mesh of the file alone, in the file's own space (the
 *                                        node's matrix is the object's base), from the import
 *                                        model_import.c keeps
 *   mesh_data_put_vertex(m, i, pos, normal, uv, tangent)
 *                                        write vertex i (tangent: xyz and the handedness w, +-1, of
 *                                        the bitangent cross(normal, tangent) * w; all 0 when the
 *                                        file has none); today the format keeps position and normal.
 *                                        uv is Assimp's: glTF's v already flipped (1 - v), so v = 0
 *                                        is the image's bottom row (its last row in the file)
 *   mesh_data_destroy(m)
 *   mesh_data_inradius(m)                smallest distance from the origin to a face's plane:
 *                                        scale a volume mesh by r / inradius to contain the sphere r
 *
 * Vertices are interleaved: position xyz, normal xyz (6 floats). Indices are 32-bit.
 */
#ifndef COMMON_MESH_DATA_H
#define COMMON_MESH_DATA_H

#include "scene.h"
#include "shader_layout.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define MESH_VERTEX_FLOATS SHADER_MESH_VERTEX_FLOATS /* written once: chapter 16's shader reads them */

typedef struct mesh_data {
    float *vertices;
    uint32_t *indices;
    int vertex_count;
    int index_count;
    float bounds_min[3], bounds_max[3];
    float bound_radius; /* largest distance of a vertex from the origin */
} mesh_data;

bool mesh_data_cube(mesh_data *m);
bool mesh_data_plane(mesh_data *m);
bool mesh_data_sphere(mesh_data *m, int slices, int stacks);
bool mesh_data_icosphere(mesh_data *m, int subdivisions);
bool mesh_data_load(mesh_data *m, const char *path, const char *origin);
bool mesh_data_load_memory(mesh_data *m, const char *name, const void *data, size_t size, const char *origin);
bool mesh_data_from_scene(mesh_data *m, const scene *s, const scene_mesh *decl);
void mesh_data_put_vertex(mesh_data *m, int i, const float pos[3], const float normal[3], const float uv[2],
                          const float tangent[4]);
void mesh_data_destroy(mesh_data *m);
double mesh_data_inradius(const mesh_data *m);

#endif
