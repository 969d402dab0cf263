/* model_file.h - an untrusted model file brought to Assimp within limits, and Assimp's answer
 * checked before any post-processing. mesh_data_load is its one caller; the fuzz target
 * (tests/fuzz/fuzz_model.c) reaches it through mesh_data_load_memory.
 *
 *   model_limits_get(lim, why, n)      the limits: the defaults below, each overridable by an
 *                                      environment variable (COURSE_MODEL_MAX_BYTES, _VERTICES,
 *                                      _FACES); false with *why when a variable is not a number
 *   model_format_of(path)              the format the course reads for that file name (by its
 *                                      extension: obj, ply, off, stl, gltf, glb), or NULL
 *   model_prescan(data, size, format, lim, why, n)
 *                                      the counts a header declares (OFF, PLY, OBJ lines, binary
 *                                      STL) against the limits and against the bytes that follow
 *                                      them, before Assimp allocates anything from them
 *   model_import(name, data, size, siblings, lim, post, why, n)
 *                                      Assimp's import with aiProcess_ValidateDataStructure only,
 *                                      the counts checked, then the import again with the steps
 *                                      `post` (validation first); the
 *                                      file `name` is read from `data`, other files it names (an
 *                                      OBJ's .mtl, a glTF's .bin) from disk when `siblings`, each
 *                                      a regular file and all of them within lim->bytes
 *   model_gltf_check(name, data, size, siblings, lim, out_size, why, n)
 *                                      a glTF 2.0 file (.gltf, or a .glb's chunks) checked before
 *                                      Assimp sees it (model_gltf.c): the JSON's depth and keys, every
 *                                      index, every accessor's bytes inside its view and buffer, the
 *                                      files it names, the counts and the memory its import would
 *                                      take; the checked document as Assimp is to read it (malloc'd,
 *                                      *out_size bytes), or NULL with *why. model_import calls it.
 *   model_path_inside(model, path, resolved, size, why, n)
 *                                      whether `path` is a regular file inside the model's folder once
 *                                      `..` and symbolic links are resolved (*size: its bytes; that
 *                                      resolved path in resolved[MODEL_PATH_MAX] unless NULL)
 *   model_uri_decode(uri, out, n)      a URI's `%` escapes decoded ("a%20b.png" -> "a b.png"); false
 *                                      on a broken escape, an escaped NUL, or no room in out[n]
 *   model_quote(text, out, n)          a message of Assimp's as one printable line, cut short
 *   model_read_file(path, lim, size, why, n)
 *                                      the whole of a regular file of at most lim->bytes, malloc'd
 *                                      (*size bytes), or NULL with *why: what the checks and Assimp
 *                                      then read is the same bytes
 *
 * Why these bound memory: Assimp's memory grows with the bytes it reads and with the counts it
 * reserves from headers. The bytes are limited here; a count is accepted only when the file has
 * the bytes to hold that many elements, so a 300-byte file cannot make Assimp reserve 8 GB.
 */
#ifndef COMMON_MODEL_FILE_H
#define COMMON_MODEL_FILE_H

#include <stdbool.h>
#include <stddef.h>

/* Defaults: forty times the largest model the course ships (assets/models/teapot.obj, 1.6 MB),
 * and small enough that what Assimp makes of them stays within a few GB (docs/scene-format.md). */
#define MODEL_MAX_BYTES_DEFAULT (64LL << 20)
#define MODEL_MAX_VERTICES_DEFAULT 4000000L
#define MODEL_MAX_FACES_DEFAULT 4000000L
#define MODEL_QUOTE_MAX 160 /* characters of an Assimp message kept */
/* What one glTF import may take (COURSE_MODEL_MAX_MB), estimated before Assimp runs from what its
 * meshes declare: about twice the bytes a vertex measured (scene_check 77, chapter 11 60 beyond its
 * own: docs/scene-format.md, "Files from elsewhere"), so that a model accepted fits. */
#define MODEL_MAX_MB_DEFAULT 512LL
#define MODEL_BYTES_PER_VERTEX 160
#define MODEL_BYTES_PER_FACE 64
/* glTF's structure: nodes and their nesting (Assimp recurses through both), the JSON's nesting,
 * and lights (Assimp 5.2's validation compares every light with every other one). */
#define MODEL_NODES_MAX 65536
#define MODEL_DEPTH_MAX 64
#define MODEL_JSON_DEPTH_MAX 32
#define MODEL_LIGHTS_MAX 4096
#define MODEL_PATH_MAX 4096

typedef struct model_limits {
    long long bytes; /* the file, and separately all the files it names */
    long vertices;   /* declared in a header, and in the imported meshes together */
    long faces;
    long long memory; /* bytes one import may take, estimated (MODEL_MAX_MB_DEFAULT) */
} model_limits;

struct aiScene;

bool model_limits_get(model_limits *lim, char *why, size_t n);
const char *model_format_of(const char *path);
bool model_prescan(const char *data, size_t size, const char *format, const model_limits *lim, char *why,
                   size_t n);
const struct aiScene *model_import(const char *name, const char *data, size_t size, bool siblings,
                                   const model_limits *lim, unsigned post, char *why, size_t n);
char *model_gltf_check(const char *name, const char *data, size_t size, bool siblings, const model_limits *lim,
                       size_t *out_size, char *why, size_t n);
bool model_uri_decode(const char *uri, char *out, size_t n);
bool model_path_inside(const char *model, const char *path, char *resolved, long long *size, char *why,
                       size_t n);
void model_quote(const char *text, char *out, size_t n);
char *model_read_file(const char *path, const model_limits *lim, size_t *size, char *why, size_t n);
/* The pre-scan (model_scan.c) and the import (model_file.c) say what is wrong the same way:
 * printf-style into why[n], then false. */
bool model_fail(char *why, size_t n, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

#endif
