// scene_features.glsl - what the scene this program draws uses, as the runner defines it before the
// program is built (common/gl/shader_features.h, gl_program_set_scene_defines):
//   LIGHT_POINT, LIGHT_SPOT            the light kinds present
//   MATERIAL_BLINN_PHONG, MATERIAL_PBR the material models present (chapter 00's, chapter 18's)
//   MATERIAL_MAPS                      some metallic-roughness material samples an image
//   MATERIAL_EMISSIVE                  some material gives off light
// A program built without them (SCENE_FEATURES undefined: a test's or a tool's own) gets every one,
// so it draws any scene. A chapter's own features are its own defines: SHADOWS (14),
// AMBIENT_OCCLUSION (17), IMAGE_BASED_LIGHT (19).
#ifndef SCENE_FEATURES_GLSL
#define SCENE_FEATURES_GLSL

#ifndef SCENE_FEATURES
#define LIGHT_POINT 1
#define LIGHT_SPOT 1
#define MATERIAL_BLINN_PHONG 1
#define MATERIAL_PBR 1
#define MATERIAL_MAPS 1
#define MATERIAL_EMISSIVE 1
#endif

#endif
