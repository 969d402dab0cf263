/* gen_scene.h - a scene held in memory while a recipe builds it, then written out in one go so
 * the comment block at the top can state its counts.
 *
 *   gen_scene_add_mesh(s, name, spec, triangles)          the new mesh's index
 *   gen_scene_add_material(s, name, albedo, specular, shininess)
 *                                                         the new material's index
 *   gen_scene_add_pbr_material(s, name, base, metallic, roughness, maps)
 *                                                         a metallic-roughness one; maps is the rest
 *                                                         of its line ("base_map PATH ...") or ""
 *   gen_scene_add_object(s, mesh, material, position, rotate_y, scale)
 *   gen_scene_add_light(s, r, position)                   a light of random colour and intensity
 *                                                         (0.8..1.2) drawn from r
 *   gen_scene_write(s, path)                              the .scene file common/scene/scene.c reads
 *
 * The add functions do not check the GEN_MAX_* limits: the recipes are fixed and stay inside
 * them. A scene is large (the object and light arrays): allocate it, do not put it on the stack.
 * gen_scene_write logs its own error and returns false.
 */
#ifndef TOOLS_GEN_SCENES_GEN_SCENE_H
#define TOOLS_GEN_SCENES_GEN_SCENE_H

#include <stdbool.h>

#include "gen_path.h"
#include "rng.h"

#define GEN_MAX_MESHES 4
#define GEN_MAX_MATERIALS 16
#define GEN_MAX_OBJECTS 4096
#define GEN_MAX_LIGHTS 1024
#define GEN_MAX_NOTES 8

typedef struct gen_mesh {
    char name[32];
    char spec[GEN_PATH_MAX]; /* what follows the name: "cube", "sphere 100 100", "file ../models/x.ply" */
    long triangles;
} gen_mesh;

typedef struct gen_material {
    char name[32];
    double albedo[3]; /* a metallic-roughness material's base colour */
    double specular, shininess;
    bool pbr;
    double metallic, roughness;
    char maps[GEN_PATH_MAX]; /* "base_map PATH normal_map PATH ...", or "" */
} gen_material;

typedef struct gen_object {
    int mesh, material;
    double position[3];
    double rotate_y;
    double scale[3];
} gen_object;

typedef struct gen_light {
    double position[3];
    double color[3];
    double intensity;
} gen_light;

typedef struct gen_scene {
    const char *notes[GEN_MAX_NOTES]; /* the opening comment: what the scene reproduces */
    double eye[3], target[3];
    double fovy, near_plane, far_plane;
    double ambient[3];
    double kc, kl, kq; /* one attenuation for every light of the scene */
    gen_mesh meshes[GEN_MAX_MESHES];
    int mesh_count;
    gen_material materials[GEN_MAX_MATERIALS];
    int material_count;
    gen_object objects[GEN_MAX_OBJECTS];
    int object_count;
    gen_light lights[GEN_MAX_LIGHTS];
    int light_count;
} gen_scene;

int gen_scene_add_mesh(gen_scene *s, const char *name, const char *spec, long triangles);
int gen_scene_add_material(gen_scene *s, const char *name, const double albedo[3], double specular,
                           double shininess);
int gen_scene_add_pbr_material(gen_scene *s, const char *name, const double base[3], double metallic,
                               double roughness, const char *maps);
void gen_scene_add_object(gen_scene *s, int mesh, int material, const double position[3], double rotate_y,
                          const double scale[3]);
void gen_scene_add_light(gen_scene *s, rng *r, const double position[3]);
bool gen_scene_write(const gen_scene *s, const char *path);

#endif
