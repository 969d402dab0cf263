/* recipes.h - the four benchmark scenes, the textured PBR teapots, and the model and images they need.
 *
 *   recipes_write_all(out_dir, models_dir, textures_dir)
 *                                            teapot.obj into models_dir, the PBR scene's images into
 *                                            textures_dir (pbr_textures.h), then city.scene,
 *                                            bunnies.scene, sphere.scene, teapots.scene and
 *                                            pbr_teapots.scene into out_dir, naming their models and
 *                                            images relative to out_dir
 *
 * The scenes rebuild, in spirit, the test scenes of published deferred-shading results (a city
 * of cubes, a field of bunnies, one dense sphere, a table of teapots). Each draws from its own
 * rng with a fixed seed: the files are reproducible byte for byte, and changing one recipe
 * never shifts another's numbers.
 *
 * Both folders must exist, and models_dir must already hold bunny.ply (tools/bunny_to_ply.mjs
 * converts it); its triangle count is read back for the scene's comment block. Errors are
 * logged where they happen; the result is false after any of them.
 */
#ifndef TOOLS_GEN_SCENES_RECIPES_H
#define TOOLS_GEN_SCENES_RECIPES_H

#include <stdbool.h>

bool recipes_write_all(const char *out_dir, const char *models_dir, const char *textures_dir);

#endif
