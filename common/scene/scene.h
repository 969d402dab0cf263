/* scene.h - the course's text scene format (docs/scene-format.md).
 *
 *   scene_load(path, scene)            parse a file; false + one "file:line: message" on error
 *   scene_parse_string(text, name, base_dir, scene)
 *                                      parse text already in memory (tests, fuzzing)
 *   scene_destroy(scene)               free what a successful parse allocated
 *   scene_object_world_at(scene, i, t, out)   world matrix T*Ry*S (*base) of object i at time t
 *   scene_light_position_at(scene, i, t, out) position of light i at time t (a spot's too)
 *   scene_add_light(scene, light)      append a light (used by the --lights generator); the array
 *                                      grows by doubling, so n lights cost O(n), not O(n^2)
 *   scene_map_attribute(map)           the material attribute that names a map ("base_map", ...)
 *
 * Everything is linear RGB, right-handed, +Y up; angles in the file are
 * degrees, stored here as given (degrees).
 */
#ifndef COMMON_SCENE_H
#define COMMON_SCENE_H

#include "shader_layout.h"

#include <stdbool.h>

#include <cglm/cglm.h>

#define SCENE_NAME_MAX 64
#define SCENE_PATH_MAX 1024
/* A camera's limits. fovy: below 0.01 degrees the projection magnifies by more than 10^4 and a
 * 1e-30 degree view is a black picture. far/near: 2^24; beyond it the farther half of the view,
 * [far/2, far], falls into a single step of a 24-bit or a 32-bit float depth buffer (whose
 * precision near 1.0 is 2^-24), so every surface there fights every other. */
#define SCENE_FOVY_MIN 0.01
#define SCENE_DEPTH_RATIO_MAX 16777216.0

typedef enum scene_mesh_kind {
    SCENE_MESH_CUBE,
    SCENE_MESH_PLANE,
    SCENE_MESH_SPHERE,
    SCENE_MESH_FILE,
} scene_mesh_kind;

typedef struct scene_key {
    float time;
    vec3 position;
} scene_key;

typedef struct scene_camera {
    vec3 eye, target, up; /* up defaults to 0 1 0 */
    float fovy_deg;       /* vertical, default 60 */
    float near_plane;     /* default 0.1 */
    float far_plane;      /* default 100 */
} scene_camera;

typedef struct scene_mesh {
    char name[SCENE_NAME_MAX];
    scene_mesh_kind kind;
    int slices, stacks;         /* sphere only; extension "sphere [SLICES STACKS]", default 32 16 */
    char path[SCENE_PATH_MAX];  /* file only: resolved relative to the scene file's folder */
    int line;                   /* line of the declaration, for later error messages */
    int part;                   /* file only: -1 (default) every mesh of the file merged into one;
                                   >= 0 the file's mesh of that index alone (directive `model`) */
} scene_mesh;

/* The texture maps of a metallic-roughness material, in the order of scene_material.maps. */
typedef enum scene_map {
    SCENE_MAP_BASE,        /* base colour, sRGB, alpha = opacity */
    SCENE_MAP_METAL_ROUGH, /* linear: G = roughness, B = metallic (glTF 2.0's packing) */
    SCENE_MAP_NORMAL,      /* linear: tangent-space normal, 0..1 encoding */
    SCENE_MAP_OCCLUSION,   /* linear: R = ambient occlusion */
    SCENE_MAP_EMISSIVE,    /* sRGB */
    SCENE_MAP_COUNT,
} scene_map;

/* An image a material samples: a file, or an image embedded in a model file (.glb, data URI). */
typedef struct scene_texture {
    char path[SCENE_PATH_MAX]; /* a file: its real path (realpath: one texture per file, however it is
                                  spelt); embedded: "MODEL#N", for messages */
    unsigned char *data;       /* embedded: the encoded bytes (PNG, JPEG), owned by the scene; else NULL */
    size_t size;               /* embedded: bytes in data */
    bool srgb;                 /* colour data (base colour, emissive), decoded from sRGB */
    /* Where the scene first names it, for the messages of a later decode: "SCENE:LINE: material
     * 'NAME' base_map 'PATH': ..." (line 0: not from a scene file) */
    int line;
    char material[SCENE_NAME_MAX];
    scene_map map;
} scene_texture;

typedef struct scene_material {
    char name[SCENE_NAME_MAX];
    vec3 albedo;
    float specular;  /* default 0 */
    float shininess; /* default 32 */
    float opacity;   /* default 1 (opaque); 0 < opacity <= 1, below 1 the object is glass: blended
                        over what lies behind it, final = A * shaded + (1 - A) * behind, in linear
                        radiance (docs/scene-format.md, docs/12_transparency.md) */
    /* Metallic-roughness (`material NAME pbr ...` or a model's material); albedo is the base colour.
     * Blinn-Phong materials have pbr false and ignore the fields below. */
    bool pbr;
    float metallic;  /* 0..1 */
    float roughness; /* 0..1, perceptual (squared for the distribution) */
    vec3 emissive;   /* linear radiance added, default 0 */
    int maps[SCENE_MAP_COUNT]; /* index into scene.textures, -1 for none (the factor alone) */
} scene_material;

typedef struct scene_object {
    int mesh;     /* index into scene.meshes */
    int material; /* index into scene.materials */
    vec3 position;
    float rotate_y_deg;
    vec3 scale; /* default 1 1 1 */
    scene_key *keys; /* sorted by time; NULL when static */
    int key_count;
    bool cast_off; /* `cast off`: casts no shadow (chapter 14); default false: it casts */
    bool has_base; /* a model's node: world = T * Ry * S * base (base: the node's transform in the file) */
    mat4 base;
} scene_object;

/* A point light, or (directive `spot`) a spot light: the same light inside a cone. Zero spot fields
 * are a point light, so code that builds lights without them makes point lights. */
typedef struct scene_light {
    vec3 position;
    vec3 color;      /* default 1 1 1 */
    float intensity; /* default 1 */
    float kc, kl, kq; /* default 1 0.14 0.07 */
    scene_key *keys;
    int key_count;
    bool spot;                  /* false: a point light (the fields below are 0) */
    vec3 direction;             /* spot: the cone's axis, as given (not zero; not normalised) */
    float inner_deg, outer_deg; /* spot: half-angles from the axis, 0 < inner <= outer < 90 */
    bool shadow_off;            /* `shadow off`: never shadowed (chapter 14); default false */
} scene_light;

/* A light probe (chapter 19): the scene's radiance is captured at `position`, and lights the
 * surfaces within `radius` of it (docs/19_image_based_light.md). */
#define SCENE_PROBE_MAX 16
typedef struct scene_probe {
    vec3 position;
    float radius; /* > 0 */
} scene_probe;

typedef struct scene {
    char path[SCENE_PATH_MAX]; /* as given to scene_load, or the name given to scene_parse_string */
    scene_camera camera;
    vec3 ambient;
    int falloff; /* SHADER_FALLOFF_HARD (default) or SHADER_FALLOFF_WINDOWED (directive `falloff`) */
    scene_mesh *meshes;
    int mesh_count;
    scene_material *materials;
    int material_count;
    scene_object *objects;
    int object_count;
    scene_light *lights;
    int light_count;
    int light_capacity; /* lights allocated (scene_add_light doubles it); 0: as many as light_count */
    scene_texture *textures; /* the images materials sample (scene_material.maps) */
    int texture_count;
    scene_probe *probes; /* directive `probe`, at most SCENE_PROBE_MAX */
    int probe_count;
} scene;

bool scene_load(const char *path, scene *out);
bool scene_parse_string(const char *text, const char *name, const char *base_dir, scene *out);
void scene_destroy(scene *s);

void scene_object_world_at(const scene *s, int index, float time, mat4 out);
void scene_light_position_at(const scene *s, int index, float time, vec3 out);
bool scene_add_light(scene *s, const scene_light *light);
const char *scene_map_attribute(scene_map map);

#endif
