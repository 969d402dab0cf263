/* model_gltf_internal.h - what the two halves of the glTF pre-scan share: model_gltf.c (the
 * container, the JSON, fields, files, buffers and views, the whole document) and model_gltf_parts.c
 * (accessors, meshes, nodes, skins, images, lights, animations, materials). */
#ifndef COMMON_MODEL_GLTF_INTERNAL_H
#define COMMON_MODEL_GLTF_INTERNAL_H

#include "model_file.h"

#include <cjson/cJSON.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#define GLTF_ITEMS_MAX 65536              /* entries of any one top-level array (buffers, accessors, ...) */
#define GLTF_PRIMITIVES_MAX 65536         /* primitives of all meshes together */
#define GLTF_WHOLE_MAX 9007199254740991LL /* 2^53 - 1: every whole number a double holds exactly */

typedef struct gltf_list {
    cJSON **at;
    long long count;
} gltf_list;

typedef struct gltf {
    const char *name; /* the model file */
    bool siblings;    /* files it names may be read */
    const model_limits *lim;
    const unsigned char *bin; /* a .glb's BIN chunk */
    long long bin_size;
    bool has_bin;
    gltf_list buffers, views, accessors, meshes, nodes, images, textures, skins, lights, scenes, animations,
        materials, samplers, cameras;
    unsigned char **data;  /* per buffer, decoded when a sparse accessor's indices are read */
    char **files;          /* per buffer, the file its URI names, resolved by check_buffers */
    long long named_bytes; /* of the files it names, together */
    long long vertices, faces, memory;
    char *why;
    size_t n;
} gltf;

static inline uint32_t gltf_le32(const unsigned char *p)
{
    return p[0] | p[1] << 8 | p[2] << 16 | (uint32_t)p[3] << 24;
}

static inline bool gltf_is_data_uri(const char *uri)
{
    return strncmp(uri, "data:", 5) == 0;
}

/* model_gltf.c: fields (each false with *why, as model_fail) and the files a URI names. */
long long gltf_index_of(const cJSON *v, long long count);
bool gltf_field_whole(gltf *g, const cJSON *obj, const char *key, long long fallback, long long hi,
                      long long *out, const char *what, long long index);
bool gltf_field_index(gltf *g, const cJSON *obj, const char *key, bool required, const gltf_list *list,
                      long long *out, const char *what, long long index);
bool gltf_numbers(gltf *g, const cJSON *obj, const char *key, int count, const char *what, long long index);
bool gltf_list_of(gltf *g, const cJSON *parent, const char *key, long long max, gltf_list *out);
bool gltf_uri_file(gltf *g, const char *uri, const char *what, long long index, char *path, size_t pn,
                   long long *size);

/* model_gltf_parts.c: each part of the document checked; false with g->why. */
bool gltf_check_accessors(gltf *g);
bool gltf_check_meshes(gltf *g);
bool gltf_check_nodes(gltf *g);
bool gltf_check_skins_scenes(gltf *g);
bool gltf_check_images(gltf *g);
bool gltf_check_lights(gltf *g);
bool gltf_check_animations(gltf *g);
bool gltf_check_material_textures(gltf *g, const cJSON *obj, long long i);

#endif
