/* gen_scenes.c - writes the four benchmark scenes, the textured PBR teapots, the tessellated Utah
 * teapot and the PBR scene's procedural images.
 *
 *   gen_scenes --out DIR [--models DIR] [--textures DIR]
 *
 * The scenes rebuild, in spirit, the test scenes of published deferred-shading
 * results (a city of cubes, a field of bunnies, one dense sphere, a table of
 * teapots), so the course's timings can be set beside them. Everything is drawn
 * from common/base/rng.h with a fixed seed per scene: the files are reproducible
 * byte for byte, and regenerating one scene never shifts another.
 *
 * This file is the command line only. The work is in tools/gen_scenes/ (not in tools/
 * itself, where the build makes every .c file a program of its own):
 *   recipes.c     the five scenes, and writing them with the teapot model
 *   pbr_textures.c  the PBR scene's images (stone tiles, a riveted metal panel), as PNG
 *   gen_scene.c   the in-memory scene and the .scene writer
 *   teapot.c      Bezier patch tessellation, welding, the OBJ writer
 *   gen_color.c   random colours (drawn from common/base/rng.c, the course's one generator)
 *   gen_format.c  number formatting;  gen_path.c  folders and output files
 *
 * The bunny model is not generated here (tools/bunny_to_ply.mjs converts it); its
 * triangle count is read from the model for the scene's comment block.
 */
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "gen_scenes/gen_path.h"
#include "gen_scenes/recipes.h"
#include "log.h"

static void print_usage(FILE *stream)
{
    fprintf(stream, "usage: gen_scenes --out DIR [--models DIR] [--textures DIR]\n"
                    "\n"
                    "Writes city.scene, bunnies.scene, sphere.scene, teapots.scene and pbr_teapots.scene\n"
                    "into --out, the tessellated teapot.obj into --models (default: DIR/../models) and the\n"
                    "PBR scene's PNG images into --textures (default: DIR/../textures). The scenes name the\n"
                    "models and images relative to --out. The bunny model must already be in --models as bunny.ply\n"
                    "(node tools/bunny_to_ply.mjs PATH_TO/node_modules/bunny MODELS/bunny.ply).\n"
                    "The output is deterministic: running it again reproduces the files byte for byte.\n");
}

int main(int argc, char **argv)
{
    const char *out_dir = NULL, *models_dir = NULL, *textures_dir = NULL;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            print_usage(stdout);
            return 0;
        } else if (strcmp(argv[i], "--out") == 0 && i + 1 < argc) {
            out_dir = argv[++i];
        } else if (strcmp(argv[i], "--models") == 0 && i + 1 < argc) {
            models_dir = argv[++i];
        } else if (strcmp(argv[i], "--textures") == 0 && i + 1 < argc) {
            textures_dir = argv[++i];
        } else {
            log_error("gen_scenes: unknown or incomplete option '%s'", argv[i]);
            print_usage(stderr);
            return 2;
        }
    }
    if (!out_dir) {
        print_usage(stderr);
        return 2;
    }
    char default_models[GEN_PATH_MAX];
    if (!models_dir) {
        if (!gen_path_join(out_dir, "../models", default_models)) {
            return 2;
        }
        models_dir = default_models;
    }
    char default_textures[GEN_PATH_MAX];
    if (!textures_dir) {
        if (!gen_path_join(out_dir, "../textures", default_textures)) {
            return 2;
        }
        textures_dir = default_textures;
    }
    if (!gen_path_make_dir(out_dir) || !gen_path_make_dir(models_dir) || !gen_path_make_dir(textures_dir)) {
        return 1;
    }
    return recipes_write_all(out_dir, models_dir, textures_dir) ? 0 : 1;
}
