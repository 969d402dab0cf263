/* pbr_textures.h - the procedural images of the textured PBR scene, written as PNG.
 *
 *   pbr_textures_write(dir)   into dir: a tiled stone floor (tiles_base.png sRGB, tiles_mr.png,
 *                             tiles_normal.png, tiles_ao.png) and a riveted metal panel with a painted
 *                             band (panel_base.png sRGB, panel_mr.png, panel_normal.png, panel_ao.png)
 *                             and the teapots' hammered finish, an image that tiles (teapot_base.png
 *                             sRGB, teapot_mr.png, teapot_normal.png, teapot_ao.png)
 *
 * The metal-rough images follow glTF 2.0: G roughness, B metallic (R unused, 255). Normal maps are
 * tangent space, 0..255 for -1..1, +Y towards the image's top. Everything is computed from integer
 * hashes: the files are the same bytes on every run. Logs its own error; false after any.
 */
#ifndef TOOLS_GEN_SCENES_PBR_TEXTURES_H
#define TOOLS_GEN_SCENES_PBR_TEXTURES_H

#include <stdbool.h>

#define PBR_TILES_SIZE 512 /* the floor's images: 12 x 12 tiles of about 43 pixels */
#define PBR_TILES_PER_SIDE 12
#define PBR_PANEL_SIZE 256
#define PBR_TEAPOT_SIZE 256 /* one patch's parameter square: 8 x 8 dimples of 32 pixels */
#define PBR_TEAPOT_DIMPLES 8

bool pbr_textures_write(const char *dir);

#endif
