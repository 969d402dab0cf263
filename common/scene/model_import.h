/* model_import.h - a glTF 2.0 file as scene content: the `model` directive (docs/scene-format.md).
 *
 *   model_import_scene(path, origin, out, why, n)
 *        the file at `path` (.gltf with its buffers and images beside it or in data URIs, or .glb),
 *        read within model_file.h's limits and validated before any post-processing, into a zeroed
 *        scene `out` (indices local to it): one scene_mesh per mesh of the file (kind
 *        SCENE_MESH_FILE, path, part = its index), one metallic-roughness scene_material per material,
 *        the images those sample as scene_textures (files beside the model, checked; embedded ones
 *        copied, path "MODEL#N"), one scene_object per node-mesh pair (has_base, base = the node's
 *        world matrix) and the KHR_lights_punctual point and spot lights, placed by their nodes.
 *        False with *why (one line) on what the course does not support; one warning line
 *        ("origin: ...") for each kind of thing it leaves out on purpose (directional lights,
 *        animations). Free `out` with model_import_free, not scene_destroy.
 *   model_import_free(out)     free what model_import_scene made (textures' data included)
 *   model_import_cached(path, why, n)
 *        the file's Assimp scene, post-processed (model_import.c: IMPORT_STEPS) and checked as above:
 *        imported once and kept until model_import_release or another file's import, so that the
 *        meshes of one file (mesh_data_from_scene, part >= 0) do not import it once each
 *   model_import_release()     drop the kept import: once a scene's meshes are built (gpu_scene_create,
 *                              scene_check do it), or to read a file again that changed within the
 *                              same clock tick; a kept import is never stale otherwise (its path,
 *                              size and modification time are checked on every use)
 *
 * Limits, beyond model_file.h's (MODEL_NODES_MAX nodes, MODEL_DEPTH_MAX levels of them, checked
 * again here on what Assimp made), MODEL_OBJECTS_MAX node-mesh pairs, images of at most MODEL_IMAGE_SIDE_MAX texels a side and
 * MODEL_TEXELS_MAX texels in all (what decoding them may allocate is bounded before any is decoded).
 */
#ifndef COMMON_MODEL_IMPORT_H
#define COMMON_MODEL_IMPORT_H

#include "model_file.h"
#include "model_image.h"
#include "scene.h"

#include <stdbool.h>
#include <stddef.h>

#define MODEL_OBJECTS_MAX 65536
#define MODEL_TEXELS_MAX (1LL << 28) /* 1 GiB as RGBA8 */
/* The attenuation a glTF light gets: 1 / (KC + d^2), the file's inverse square law kept finite at
 * the light (the course's lights need kc > 0): within 1 % of 1 / d^2 beyond d = 1. */
#define MODEL_LIGHT_KC 0.01f

struct aiScene;

bool model_import_scene(const char *path, const char *origin, scene *out, char *why, size_t n);
void model_import_free(scene *out);
const struct aiScene *model_import_cached(const char *path, char *why, size_t n);
void model_import_release(void);

#endif
