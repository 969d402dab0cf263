/* pbr_textures.c - see pbr_textures.h. Each image is a function of the pixel: a shape (where the tile
 * or the rivet is, how high the surface stands there) and a few values read from it. */
#include "pbr_textures.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "gen_path.h"
#include "image.h"

/* A repeatable value in [0, 1) for integer coordinates (a hash, not a generator: any order of calls). */
static double hash01(uint32_t x, uint32_t y, uint32_t salt)
{
    uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ salt * 0xcb1ab31fu;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return (double)(h & 0xffffffu) / 16777216.0;
}

static unsigned char byte_of(double v)
{
    v = v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v;
    return (unsigned char)floor(v * 255.0 + 0.5);
}

/* Linear [0, 1] to an sRGB code (the images' colour is stored as sRGB, like any photograph). */
static unsigned char srgb_byte(double v)
{
    v = v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v;
    return byte_of(v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055);
}

static void put(image *img, int x, int y, unsigned char r, unsigned char g, unsigned char b)
{
    unsigned char *p = img->pixels + 4 * ((size_t)y * img->width + x);
    p[0] = r, p[1] = g, p[2] = b, p[3] = 255;
}

/* A unit normal from the height field's slopes (dh/dx, dh/dy in height per pixel, y up the image). */
static void put_normal(image *img, int x, int y, double sx, double sy)
{
    double l = sqrt(sx * sx + sy * sy + 1.0);
    put(img, x, y, byte_of(0.5 - 0.5 * sx / l), byte_of(0.5 - 0.5 * sy / l), byte_of(0.5 + 0.5 / l));
}

/* The four images of one set as DIR/NAME_base.png, _mr, _normal and _ao; each destroyed. */
static bool write_set(const char *dir, const char *name, bool ok, image *base, image *mr, image *normal, image *ao)
{
    static const char *const suffixes[4] = {"base", "mr", "normal", "ao"};
    image *images[4] = {base, mr, normal, ao};
    for (int i = 0; i < 4; i++) {
        char file[64], path[GEN_PATH_MAX];
        snprintf(file, sizeof file, "%s_%s.png", name, suffixes[i]);
        ok = ok && gen_path_join(dir, file, path) && image_write_png(path, images[i]);
    }
    for (int i = 0; i < 4; i++)
        image_destroy(images[i]);
    return ok;
}

/* ---- the floor: stone tiles, their bevelled edges, grout ----------------------------------- */

#define TILE_BEVEL 5.0 /* pixels over which a tile's edge falls to the grout */
#define TILE_GROUT 2.0 /* half the grout's width, pixels */

/* Height in [0, 1] at pixel (x, y), rows counted up the image: 1 on a tile, 0 in the grout. */
static double tile_height(double x, double y, int *tile_x, int *tile_y)
{
    double pitch = (double)PBR_TILES_SIZE / PBR_TILES_PER_SIDE;
    *tile_x = (int)floor(x / pitch), *tile_y = (int)floor(y / pitch);
    double fx = x - *tile_x * pitch, fy = y - *tile_y * pitch;
    double edge = fmin(fmin(fx, pitch - fx), fmin(fy, pitch - fy)) - TILE_GROUT;
    return edge <= 0.0 ? 0.0 : edge >= TILE_BEVEL ? 1.0 : edge / TILE_BEVEL;
}

static bool write_tiles(const char *dir)
{
    const int n = PBR_TILES_SIZE;
    image base, mr, normal, ao;
    bool ok = image_create(&base, n, n) && image_create(&mr, n, n) && image_create(&normal, n, n) &&
              image_create(&ao, n, n);
    for (int y = 0; ok && y < n; y++) {
        for (int x = 0; x < n; x++) {
            int tx, ty, ux, uy, row = n - 1 - y; /* images are stored top row first; the pattern counts up */
            double h = tile_height(x + 0.5, row + 0.5, &tx, &ty);
            double hx = tile_height(x + 1.5, row + 0.5, &ux, &uy) - tile_height(x - 0.5, row + 0.5, &ux, &uy);
            double hy = tile_height(x + 0.5, row + 1.5, &ux, &uy) - tile_height(x + 0.5, row - 0.5, &ux, &uy);
            /* Each tile its own warm stone tint; a faint grain within it. */
            double tint = hash01((uint32_t)tx, (uint32_t)ty, 1), grain = hash01((uint32_t)x / 4, (uint32_t)row / 4, 2);
            double stone[3] = {0.42 + 0.2 * tint, 0.36 + 0.16 * tint, 0.3 + 0.1 * tint};
            double grout = 0.12, k = 0.94 + 0.06 * grain;
            put(&base, x, y, srgb_byte(k * (h * stone[0] + (1 - h) * grout)),
                srgb_byte(k * (h * stone[1] + (1 - h) * grout)), srgb_byte(k * (h * stone[2] + (1 - h) * grout)));
            /* Polished tiles, some more worn than others; rough grout; no metal. */
            double rough = h * (0.35 + 0.3 * hash01((uint32_t)tx, (uint32_t)ty, 3)) + (1 - h) * 0.95;
            put(&mr, x, y, 255, byte_of(rough), 0);
            put_normal(&normal, x, y, hx, hy); /* central differences: a bevel leans about 20 degrees */
            double occlusion = 0.55 + 0.45 * h;
            put(&ao, x, y, byte_of(occlusion), byte_of(occlusion), byte_of(occlusion));
        }
    }
    return write_set(dir, "tiles", ok, &base, &mr, &normal, &ao);
}

/* ---- the box: brushed metal, a painted band, rivets ---------------------------------------- */

#define RIVET_RADIUS 7.0
#define RIVET_INSET 18.0 /* from the panel's edge to a rivet's centre */

/* Height of the rivets (hemispheres) at (x, y), 0 elsewhere; one near each corner and mid-edge. */
static double rivet_height(double x, double y)
{
    const double n = PBR_PANEL_SIZE, at[3] = {RIVET_INSET, 0.5 * n, n - RIVET_INSET};
    double h = 0.0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            if (i == 1 && j == 1)
                continue;
            double dx = x - at[i], dy = y - at[j], d2 = (dx * dx + dy * dy) / (RIVET_RADIUS * RIVET_RADIUS);
            if (d2 < 1.0)
                h = fmax(h, sqrt(1.0 - d2));
        }
    return h;
}

static bool write_panel(const char *dir)
{
    const int n = PBR_PANEL_SIZE;
    image base, mr, normal, ao;
    bool ok = image_create(&base, n, n) && image_create(&mr, n, n) && image_create(&normal, n, n) &&
              image_create(&ao, n, n);
    for (int y = 0; ok && y < n; y++) {
        for (int x = 0; x < n; x++) {
            int row = n - 1 - y;
            double fx = x + 0.5, fy = row + 0.5;
            /* Brushing: streaks along x, each row its own brightness, smoothed over 8 pixels of x. */
            double streak = 0.5 * hash01((uint32_t)x / 8, (uint32_t)row, 4) + 0.5 * hash01((uint32_t)x / 8 + 1, (uint32_t)row, 4);
            bool band = fy > 0.4 * n && fy < 0.6 * n;
            double rivet = rivet_height(fx, fy);
            if (band && rivet == 0.0) { /* paint: a dielectric, the colour of the base map */
                put(&base, x, y, srgb_byte(0.55), srgb_byte(0.06), srgb_byte(0.04));
                put(&mr, x, y, 255, byte_of(0.45 + 0.05 * streak), 0);
            } else {                    /* bare steel: metallic, the base map its reflectance */
                double k = 0.6 + 0.08 * streak;
                put(&base, x, y, srgb_byte(k), srgb_byte(k), srgb_byte(k * 1.02));
                put(&mr, x, y, 255, byte_of(0.22 + 0.2 * streak), 255);
            }
            double sx = 2.0 * (rivet_height(fx + 1.0, fy) - rivet_height(fx - 1.0, fy));
            double sy = 2.0 * (rivet_height(fx, fy + 1.0) - rivet_height(fx, fy - 1.0));
            put_normal(&normal, x, y, sx, sy);
            /* The paint's edge and the rivets' rims catch less ambient light. */
            double edge = fmin(fabs(fy - 0.4 * n), fabs(fy - 0.6 * n));
            double occlusion = fmin(1.0, 0.7 + 0.3 * fmin(edge / 3.0, 1.0));
            if (rivet == 0.0 && rivet_height(fx + 2.0, fy) + rivet_height(fx - 2.0, fy) > 0.0)
                occlusion = fmin(occlusion, 0.6);
            put(&ao, x, y, byte_of(occlusion), byte_of(occlusion), byte_of(occlusion));
        }
    }
    return write_set(dir, "panel", ok, &base, &mr, &normal, &ao);
}

/* ---- the teapots: hammered metal (or glaze), one dimple per cell, the image tiling ----------- */

/* Depth of the dimples at (x, y) in [-1, 0]: each cell of the PBR_TEAPOT_DIMPLES x PBR_TEAPOT_DIMPLES grid
 * holds one, its centre and radius jittered by the cell's hash; cells wrap round the image's edges, so
 * the image tiles and a patch's border meets its neighbour's without a step. The profile -(1 - d^2)^2
 * meets the flat surface without a crease. */
static double dimple_height(double x, double y, double *deepest)
{
    const double n = PBR_TEAPOT_SIZE, pitch = n / PBR_TEAPOT_DIMPLES;
    int cx = (int)floor(x / pitch), cy = (int)floor(y / pitch);
    double h = 0.0;
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            int kx = cx + dx, ky = cy + dy;
            uint32_t hx = (uint32_t)((kx + PBR_TEAPOT_DIMPLES) % PBR_TEAPOT_DIMPLES);
            uint32_t hy = (uint32_t)((ky + PBR_TEAPOT_DIMPLES) % PBR_TEAPOT_DIMPLES);
            double ox = (kx + 0.5 + 0.3 * (hash01(hx, hy, 5) - 0.5)) * pitch;
            double oy = (ky + 0.5 + 0.3 * (hash01(hx, hy, 6) - 0.5)) * pitch;
            double r = pitch * (0.38 + 0.12 * hash01(hx, hy, 7));
            double d2 = ((x - ox) * (x - ox) + (y - oy) * (y - oy)) / (r * r);
            if (d2 < 1.0)
                h = fmin(h, -(1.0 - d2) * (1.0 - d2));
        }
    if (deepest)
        *deepest = -h;
    return h;
}

static bool write_teapot(const char *dir)
{
    const int n = PBR_TEAPOT_SIZE;
    const double depth = 2.0; /* pixels: a dimple's sides lean at most about 14 degrees */
    image base, mr, normal, ao;
    bool ok = image_create(&base, n, n) && image_create(&mr, n, n) && image_create(&normal, n, n) &&
              image_create(&ao, n, n);
    for (int y = 0; ok && y < n; y++) {
        for (int x = 0; x < n; x++) {
            int row = n - 1 - y;
            double fx = x + 0.5, fy = row + 0.5, dimple;
            dimple_height(fx, fy, &dimple);
            /* A near-white map: the material's base colour is the finish, the map its hammering. The
             * hammer polished the dimples; the flats between them keep a faint tarnish. */
            double grain = hash01((uint32_t)x / 2, (uint32_t)row / 2, 8);
            double k = 0.86 + 0.06 * grain + 0.08 * dimple;
            put(&base, x, y, srgb_byte(k), srgb_byte(k), srgb_byte(k));
            put(&mr, x, y, 255, byte_of(1.0 - 0.3 * dimple), 255); /* the material's numbers, or less */
            double sx = 0.5 * depth * (dimple_height(fx + 1.0, fy, NULL) - dimple_height(fx - 1.0, fy, NULL));
            double sy = 0.5 * depth * (dimple_height(fx, fy + 1.0, NULL) - dimple_height(fx, fy - 1.0, NULL));
            put_normal(&normal, x, y, sx, sy);
            double occlusion = 1.0 - 0.15 * dimple;
            put(&ao, x, y, byte_of(occlusion), byte_of(occlusion), byte_of(occlusion));
        }
    }
    return write_set(dir, "teapot", ok, &base, &mr, &normal, &ao);
}

bool pbr_textures_write(const char *dir)
{
    return write_tiles(dir) && write_panel(dir) && write_teapot(dir);
}
