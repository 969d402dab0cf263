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
 *                                        write vertex i; uv NULL: 0 0; tangent NULL: w = 0, one to be
 *                                        made by mesh_data_generate_tangents. uv is Assimp's: glTF's v
 *                                        already flipped (1 - v), so v = 0 is the image's bottom row
 *   mesh_data_generate_tangents(m)       a unit tangent and its handedness for every vertex whose w is
 *                                        0, from its triangles' texture coordinates; where those are
 *                                        degenerate (no UVs, a zero-area UV triangle) any unit vector at
 *                                        right angles to the normal (mesh_tangents.c)
 *   mesh_data_destroy(m)
 *   mesh_data_inradius(m)                smallest distance from the origin to a face's plane:
 *                                        scale a volume mesh by r / inradius to contain the sphere r
 *
 * Vertices are interleaved: position xyz, normal xyz, texture coordinate uv, tangent xyz and w, the
 * handedness: bitangent = w * cross(normal, tangent) (12 floats). Indices are 32-bit. The built-in
 * shapes have texture coordinates (the cube's and the plane's 0..1 per face, the sphere's longitude
 * and latitude) and every mesh has tangents.
 */
#ifndef COMMON_MESH_DATA_H
#define COMMON_MESH_DATA_H

#include "scene.h"
#include "shader_layout.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define MESH_VERTEX_FLOATS SHADER_MESH_VERTEX_FLOATS /* written once: chapter 16's shader reads them */
/* Where each attribute starts in a vertex, in floats. */
enum { MESH_VERTEX_POSITION = 0, MESH_VERTEX_NORMAL = 3, MESH_VERTEX_UV = 6, MESH_VERTEX_TANGENT = 8 };
_Static_assert(MESH_VERTEX_TANGENT + 4 == MESH_VERTEX_FLOATS, "position, normal, uv, tangent");

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
void mesh_data_generate_tangents(mesh_data *m);
void mesh_data_destroy(mesh_data *m);
double mesh_data_inradius(const mesh_data *m);

#endif
