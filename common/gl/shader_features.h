/* shader_features.h - what a scene uses, so that the shaders hold only that ("model only what a scene
 * needs", docs/00_forward.md): light kinds, material models, which images the materials sample,
 * emissive, glass. The runner works them out once per scene and every program it builds from then
 * on is compiled with their defines (gl_program_set_scene_defines); a chapter's own features
 * (chapter 14's shadows, 17's occlusion, 19's probes) are defines it adds to its programs itself.
 *
 *   shader_features_of(scene)              the features of a scene, as loaded
 *   shader_features_defines(f, out, size)  their GLSL defines, "SCENE_FEATURES 1\nLIGHT_POINT 1\n...";
 *                                         false if out is too small
 *   shader_features_describe(f, out, size) the same in words for --bench: "point+spot,blinn-phong,..."
 *
 * shaders/scene_features.glsl reads the defines; a program built without SCENE_FEATURES (a test's or
 * a tool's own) gets every feature, so it draws any scene.
 */
#ifndef COMMON_SHADER_FEATURES_H
#define COMMON_SHADER_FEATURES_H

#include "scene.h"

#include <stdbool.h>
#include <stddef.h>

typedef struct shader_features {
    bool point, spot;           /* light kinds present (LIGHT_POINT, LIGHT_SPOT) */
    bool blinn_phong, pbr;      /* material models present (MATERIAL_BLINN_PHONG, MATERIAL_PBR) */
    bool maps[SCENE_MAP_COUNT]; /* which images some material samples (MATERIAL_MAPS: any of them) */
    bool emissive;              /* some material gives off light (MATERIAL_EMISSIVE) */
    bool glass;                 /* some object is see-through (chapter 12 draws it; no define) */
} shader_features;

shader_features shader_features_of(const scene *s);
bool shader_features_defines(const shader_features *f, char *out, size_t size);
bool shader_features_describe(const shader_features *f, char *out, size_t size);
bool shader_features_any_map(const shader_features *f);

#endif
