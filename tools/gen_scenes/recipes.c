/* recipes.c - the city, bunnies, sphere, teapots and PBR teapots scenes, and writing them with their models. */
#include "recipes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gen_format.h"
#include "gen_path.h"
#include "rng.h"
#include "gen_color.h"
#include "gen_scene.h"
#include "log.h"
#include "loop.h"
#include "mesh_data.h"

#define BUNNY_LOOP_LEVELS 2
#define BUNNY_REFINED "bunny_loop2.ply"
#include "mesh_data.h"
#include "pbr_textures.h"
#include "teapot.h"

#define RECIPES_PI 3.14159265358979323846

static const double ONE[3] = {1, 1, 1};

/* ---- the city: 10 x 10 blocks of 5 x 5 lots ---- */

enum { CITY_BLOCKS = 10, CITY_LOTS = 5, CITY_MERGES = 10, CITY_LIGHTS = 757 };

typedef struct city_grid {
    double street; /* width of the streets between blocks and of the ring road */
    double lot;    /* side of one lot */
    double pitch;  /* block + street: from one block's corner to the next */
    double origin; /* x and z of the first block's corner; the grid is centred on 0 */
} city_grid;

static void recipes_add_city_materials(gen_scene *s, rng *r, int concrete[8])
{
    for (int i = 0; i < 8; i++) {
        double grey = rng_uniform(r, 0.45, 0.8), tint[3];
        gen_color_random(r, 0.05, 0.2, tint);
        double albedo[3] = {grey * tint[0], grey * tint[1], grey * tint[2]};
        char name[32];
        snprintf(name, sizeof name, "concrete%d", i);
        double specular = rng_uniform(r, 0.15, 0.35);
        concrete[i] = gen_scene_add_material(s, name, albedo, specular, 16 + 8 * rng_below(r, 3));
    }
}

/* One building on the lot at (x0, z0), width_lots wide: a random footprint inside the lot, and a
 * height that grows towards downtown (the origin). */
static void recipes_add_city_building(gen_scene *s, rng *r, const city_grid *g, double x0, double z0,
                                      double width_lots, int box, const int concrete[8])
{
    double lot = g->lot;
    double w = lot * width_lots * rng_uniform(r, 0.62, 0.92);
    double d = lot * rng_uniform(r, 0.62, 0.92);
    double cx = x0 + 0.5 * lot * width_lots;
    cx += rng_uniform(r, -0.5, 0.5) * (lot * width_lots - w);
    double cz = z0 + 0.5 * lot + rng_uniform(r, -0.5, 0.5) * (lot - d);
    double dist = sqrt(cx * cx + cz * cz) / 50.0, u = rng_uniform(r, 0, 1);
    double h = 0.8 + rng_uniform(r, 0, 2.0) + 10.0 * exp(-3.0 * dist * dist) * u * u;
    if (rng_below(r, 60) == 0) {
        h += rng_uniform(r, 4, 9); /* the odd tower outside downtown */
    }
    gen_scene_add_object(s, box, concrete[rng_below(r, 8)], (double[3]){cx, 0.5 * h, cz}, 0,
                         (double[3]){w, h, d});
}

/* Ten random pairs of lots merge into wide buildings, which leaves exactly 2,490 buildings. */
static void recipes_add_city_buildings(gen_scene *s, rng *r, const city_grid *g, int box,
                                       const int concrete[8])
{
    /* merged[b][row][col]: 1 = left half of a wide building, 2 = its right half (skipped) */
    unsigned char merged[CITY_BLOCKS * CITY_BLOCKS][CITY_LOTS][CITY_LOTS] = {{{0}}};
    for (int m = 0; m < CITY_MERGES;) {
        int b = rng_below(r, CITY_BLOCKS * CITY_BLOCKS), row = rng_below(r, CITY_LOTS);
        int col = rng_below(r, CITY_LOTS - 1);
        if (merged[b][row][col] == 0 && merged[b][row][col + 1] == 0) {
            merged[b][row][col] = 1;
            merged[b][row][col + 1] = 2;
            m++;
        }
    }
    for (int bz = 0; bz < CITY_BLOCKS; bz++) {
        for (int bx = 0; bx < CITY_BLOCKS; bx++) {
            int b = bz * CITY_BLOCKS + bx;
            for (int row = 0; row < CITY_LOTS; row++) {
                for (int col = 0; col < CITY_LOTS; col++) {
                    if (merged[b][row][col] == 2) {
                        continue;
                    }
                    double x0 = g->origin + bx * g->pitch + col * g->lot;
                    double z0 = g->origin + bz * g->pitch + row * g->lot;
                    double width_lots = merged[b][row][col] == 1 ? 2.0 : 1.0;
                    recipes_add_city_building(s, r, g, x0, z0, width_lots, box, concrete);
                }
            }
        }
    }
}

/* Lights on the street centre lines (the 9 between blocks and the ring road), 1-3 units up. */
static void recipes_add_city_lights(gen_scene *s, rng *r, const city_grid *g)
{
    for (int i = 0; i < CITY_LIGHTS; i++) {
        int street_index = rng_below(r, CITY_BLOCKS + 1);
        double across = g->origin - 0.5 * g->street + street_index * g->pitch + rng_uniform(r, -0.4, 0.4);
        double along = rng_uniform(r, g->origin - g->street, -g->origin + g->street);
        double y = rng_uniform(r, 1.0, 3.0);
        bool along_x = rng_below(r, 2) == 0;
        gen_scene_add_light(s, r, along_x ? (double[3]){along, y, across} : (double[3]){across, y, along});
    }
}

/* Towers cluster downtown; one ground plane lies under the buildings. */
static void recipes_build_city(gen_scene *s)
{
    const double block = 8.0, street = 2.4;
    const city_grid g = {.street = street,
                         .lot = block / CITY_LOTS,
                         .pitch = block + street,
                         .origin = -0.5 * (CITY_BLOCKS * block + (CITY_BLOCKS - 1) * street)};
    rng r = rng_seed(0x0c17u * 2654435761u);

    *s = (gen_scene){
        .notes = {"city.scene - a student deferred-rendering paper's city scene, rebuilt: 2,490 cube",
                  "buildings of varied heights and footprints on a 10 x 10 grid of blocks, 757 coloured",
                  "point lights along the streets 1-3 units up, seen from above at an angle; the",
                  "paper rendered it at 800 x 800. One ground plane is added under the buildings."},
        .eye = {0, 74, 86}, .target = {0, -6, 4}, .fovy = 50, .near_plane = 1, .far_plane = 300,
        .ambient = {0.1, 0.1, 0.11}, .kc = 1, .kl = 0.35, .kq = 0.9};
    int box = gen_scene_add_mesh(s, "box", "cube", 12);
    int ground = gen_scene_add_mesh(s, "ground", "plane", 2);
    int asphalt = gen_scene_add_material(s, "asphalt", (double[3]){0.22, 0.22, 0.24}, 0.05, 8);
    int concrete[8];
    recipes_add_city_materials(s, &r, concrete);
    gen_scene_add_object(s, ground, asphalt, (double[3]){0, 0, 0}, 0, (double[3]){120, 1, 120});
    recipes_add_city_buildings(s, &r, &g, box, concrete);
    recipes_add_city_lights(s, &r, &g);
}

/* ---- the bunnies, the sphere, the teapots ---- */

/* 5 x 5 x 5 bunnies, each turned at random, with 100 lights in and around the lattice. */
static void recipes_build_bunnies(gen_scene *s, const char *bunny_spec, long bunny_triangles)
{
    enum { GRID = 5 };
    const double spacing = 1.6;
    rng r = rng_seed(0xb0bbu * 2654435761u);

    *s = (gen_scene){
        .notes = {"bunnies.scene - a student deferred-rendering paper's bunny scene, rebuilt: 125",
                  "Stanford bunnies in a 5 x 5 x 5 lattice, each turned at random, lit by 100 coloured",
                  "point lights scattered through the lattice."},
        .eye = {9.5, 5.5, 11.5}, .target = {0, -0.5, 0}, .fovy = 45, .near_plane = 0.1, .far_plane = 60,
        .ambient = {0.1, 0.1, 0.11}, .kc = 1, .kl = 1, .kq = 4};
    int bunny = gen_scene_add_mesh(s, "bunny", bunny_spec, bunny_triangles);
    int fur[6];
    const double palette[6][3] = {{0.85, 0.82, 0.78}, {0.9, 0.65, 0.55}, {0.6, 0.75, 0.9},
                                  {0.7, 0.85, 0.6},   {0.9, 0.85, 0.5},  {0.75, 0.65, 0.85}};
    for (int i = 0; i < 6; i++) {
        char name[32];
        snprintf(name, sizeof name, "fur%d", i);
        fur[i] = gen_scene_add_material(s, name, palette[i], 0.3, 32);
    }
    const double half = 0.5 * (GRID - 1) * spacing;
    for (int y = 0; y < GRID; y++) {
        for (int z = 0; z < GRID; z++) {
            for (int x = 0; x < GRID; x++) {
                double p[3] = {x * spacing - half, y * spacing - half - 0.5, z * spacing - half};
                /* One draw per statement: argument evaluation order is unspecified in C. */
                int material = fur[rng_below(&r, 6)];
                gen_scene_add_object(s, bunny, material, p, (double)rng_below(&r, 360), ONE);
            }
        }
    }
    for (int i = 0; i < 100; i++) {
        double p[3];
        for (int k = 0; k < 3; k++) {
            p[k] = rng_uniform(&r, -half - 0.8, half + 0.8);
        }
        gen_scene_add_light(s, &r, p);
    }
}

/* Triangle counts come from the course's own mesh code, so the comment block states what the
 * renderer will draw (and a model the loader rejects is caught here). loaded: whether m was
 * filled; -1 when not. */
static long recipes_take_triangles(mesh_data *m, bool loaded)
{
    if (!loaded) {
        return -1;
    }
    long triangles = m->index_count / 3;
    mesh_data_destroy(m);
    return triangles;
}

static long recipes_count_file_triangles(const char *path)
{
    mesh_data m = {0};
    return recipes_take_triangles(&m, mesh_data_load(&m, path, "gen_scenes"));
}

/* One sphere of 20,000 triangles wrapped in 100 lights spread evenly over a shell around it.
 * The built-in UV sphere has 2 * slices * (stacks - 1) triangles: 100 x 101 gives 20,000. */
static bool recipes_build_sphere(gen_scene *s)
{
    enum { SLICES = 100, STACKS = 101, LIGHTS = 100 };
    const double radius = 2.0;
    rng r = rng_seed(0x5e7eu * 2654435761u);

    *s = (gen_scene){
        .notes = {"sphere.scene - a student deferred-rendering paper's sphere scene, rebuilt: one",
                  "sphere of 20,000 triangles lit by 100 coloured point lights on a shell around it."},
        .eye = {0, 2.2, 7.2}, .target = {0, 0, 0}, .fovy = 45, .near_plane = 0.1, .far_plane = 40,
        .ambient = {0.04, 0.04, 0.05}, .kc = 1, .kl = 3, .kq = 16};
    char spec[32];
    snprintf(spec, sizeof spec, "sphere %d %d", SLICES, STACKS);
    mesh_data m = {0};
    long triangles = recipes_take_triangles(&m, mesh_data_sphere(&m, SLICES, STACKS));
    if (triangles < 0) {
        return false;
    }
    int ball = gen_scene_add_mesh(s, "ball", spec, triangles);
    int white = gen_scene_add_material(s, "porcelain", (double[3]){0.85, 0.85, 0.85}, 0.5, 64);
    gen_scene_add_object(s, ball, white, (double[3]){0, 0, 0}, 0, (double[3]){radius, radius, radius});

    /* A Fibonacci spiral gives even coverage; the jitter keeps it from looking machined. */
    const double golden = RECIPES_PI * (3.0 - sqrt(5.0));
    for (int i = 0; i < LIGHTS; i++) {
        double y = 1.0 - 2.0 * (i + 0.5) / LIGHTS, ring = sqrt(1.0 - y * y), phi = golden * i;
        double shell = radius + rng_uniform(&r, 0.15, 0.6);
        double p[3] = {shell * ring * cos(phi), shell * y, shell * ring * sin(phi)};
        gen_scene_add_light(s, &r, p);
    }
    return true;
}

/* Eight teapots in a ring on a floor, each pouring towards the next, with 80 lights low over it. */
static void recipes_build_teapots(gen_scene *s, const char *teapot_spec, int teapot_vertices,
                                  long teapot_triangles)
{
    rng r = rng_seed(0x7ea0u * 2654435761u);
    static char model_note[160]; /* the scene keeps a pointer to it until it is written */
    char count[32];
    snprintf(model_note, sizeof model_note,
             "teapots (tessellated from the 32 Bezier patches to %s vertices each; the paper's",
             gen_format_count(teapot_vertices, count));

    *s = (gen_scene){
        .notes = {"teapots.scene - a student deferred-rendering paper's teapot scene, rebuilt: 8 Utah",
                  model_note,
                  "model had 18,906) in a ring on a floor, lit by 80 coloured point lights."},
        .eye = {0, 10, 10.5}, .target = {0, 0, 0.3}, .fovy = 50, .near_plane = 0.1, .far_plane = 60,
        .ambient = {0.05, 0.05, 0.05}, .kc = 1, .kl = 0.8, .kq = 4};
    int teapot = gen_scene_add_mesh(s, "teapot", teapot_spec, teapot_triangles);
    int floor_mesh = gen_scene_add_mesh(s, "floor", "plane", 2);
    int wood = gen_scene_add_material(s, "floor", (double[3]){0.55, 0.5, 0.45}, 0.1, 16);
    int glaze[4];
    const double palette[4][3] = {{0.9, 0.9, 0.88}, {0.75, 0.2, 0.15}, {0.2, 0.45, 0.75}, {0.85, 0.7, 0.3}};
    for (int i = 0; i < 4; i++) {
        char name[32];
        snprintf(name, sizeof name, "glaze%d", i);
        glaze[i] = gen_scene_add_material(s, name, palette[i], 0.6, 64);
    }
    gen_scene_add_object(s, floor_mesh, wood, (double[3]){0, 0, 0}, 0, (double[3]){50, 1, 50});
    const double ring = 4.6;
    for (int i = 0; i < 8; i++) {
        double angle = 45.0 * i, a = angle * RECIPES_PI / 180.0;
        double p[3] = {ring * cos(a), 0, ring * sin(a)};
        /* The spout is +x in model space; R_y(-angle - 90) turns it along the ring. */
        double turn = fmod(-angle - 90.0 + rng_uniform(&r, -10, 10) + 720.0, 360.0);
        gen_scene_add_object(s, teapot, glaze[i % 4], p, turn, (double[3]){1.5, 1.5, 1.5});
    }
    for (int i = 0; i < 80; i++) {
        double radius = 7.5 * sqrt(rng_uniform(&r, 0, 1)), a = rng_uniform(&r, 0, 2.0 * RECIPES_PI);
        double p[3] = {radius * cos(a), rng_uniform(&r, 0.3, 2.5), radius * sin(a)};
        gen_scene_add_light(s, &r, p);
    }
}

/* The same ring of teapots and the same 80 lights, in metallic-roughness materials, round a riveted
 * metal box on a tiled floor, all textured (tools/gen_scenes/pbr_textures.c): the teapots' four finishes
 * share the hammered images, on each patch's own parameter square (teapot.h). */
static bool recipes_build_pbr_teapots(gen_scene *s, const char *teapot_spec, long teapot_triangles,
                                      const char *textures_rel)
{
    gen_scene *kept = malloc(sizeof *kept); /* large: see gen_scene.h */
    if (!kept) {
        log_error("gen_scenes: out of memory");
        return false;
    }
    recipes_build_teapots(kept, teapot_spec, 0, teapot_triangles); /* the places, turns and lights */
    *s = (gen_scene){
        .notes = {"pbr_teapots.scene - teapots.scene in metallic-roughness materials (chapter 18): the 8",
                  "teapots in hammered gold, copper, red plastic and blue ceramic round a riveted steel box",
                  "on a tiled floor, all textured with the generated images of ../textures, and the 80 lights."},
        .eye = {0, 7.5, 9.5}, .target = {0, 0.4, 0.3}, .fovy = 50, .near_plane = 0.1, .far_plane = 60,
        .ambient = {0.05, 0.05, 0.05}, .kc = 1, .kl = 0.8, .kq = 4};
    int teapot = gen_scene_add_mesh(s, "teapot", teapot_spec, teapot_triangles);
    int floor_mesh = gen_scene_add_mesh(s, "floor", "plane", 2);
    int box = gen_scene_add_mesh(s, "box", "cube", 12);
    char maps[4 * GEN_PATH_MAX + 128]; /* four paths and their words */
    snprintf(maps, sizeof maps,
             "base_map %s/tiles_base.png metal_rough_map %s/tiles_mr.png normal_map %s/tiles_normal.png "
             "occlusion_map %s/tiles_ao.png",
             textures_rel, textures_rel, textures_rel, textures_rel);
    int tiles = gen_scene_add_pbr_material(s, "tiles", ONE, 1, 1, maps);
    snprintf(maps, sizeof maps,
             "base_map %s/panel_base.png metal_rough_map %s/panel_mr.png normal_map %s/panel_normal.png "
             "occlusion_map %s/panel_ao.png",
             textures_rel, textures_rel, textures_rel, textures_rel);
    int panel = gen_scene_add_pbr_material(s, "panel", ONE, 1, 1, maps);
    static const struct {
        const char *name;
        double base[3], metallic, roughness;
    } finishes[4] = {{"gold", {1.0, 0.78, 0.34}, 1, 0.35},
                     {"red_plastic", {0.7, 0.08, 0.06}, 0, 0.3},
                     {"copper", {0.95, 0.64, 0.54}, 1, 0.5},
                     {"blue_ceramic", {0.15, 0.35, 0.7}, 0, 0.55}};
    int finish[4];
    snprintf(maps, sizeof maps,
             "base_map %s/teapot_base.png metal_rough_map %s/teapot_mr.png normal_map %s/teapot_normal.png "
             "occlusion_map %s/teapot_ao.png",
             textures_rel, textures_rel, textures_rel, textures_rel);
    for (int i = 0; i < 4; i++)
        finish[i] = gen_scene_add_pbr_material(s, finishes[i].name, finishes[i].base, finishes[i].metallic,
                                               finishes[i].roughness, maps);
    gen_scene_add_object(s, floor_mesh, tiles, (double[3]){0, 0, 0}, 0, (double[3]){24, 1, 24});
    gen_scene_add_object(s, box, panel, (double[3]){0, 0.8, 0}, 30, (double[3]){1.6, 1.6, 1.6});
    for (int i = 1; i < kept->object_count; i++) /* object 0 was the floor */
        gen_scene_add_object(s, teapot, finish[(i - 1) % 4], kept->objects[i].position, kept->objects[i].rotate_y,
                             kept->objects[i].scale);
    memcpy(s->lights, kept->lights, sizeof kept->lights[0] * (size_t)kept->light_count);
    s->light_count = kept->light_count;
    free(kept);
    return true;
}

/* ---- writing: the teapot model first, since its scene states the model's counts ---- */

/* teapot.obj into models_dir; the triangle count as the loader reads it back, -1 on failure. */
static long recipes_write_teapot(const char *models_dir, int *vertices)
{
    char path[GEN_PATH_MAX];
    teapot_mesh teapot;
    if (!teapot_build_mesh(TEAPOT_PATCH_STEPS, &teapot)) {
        return -1;
    }
    bool ok = gen_path_join(models_dir, "teapot.obj", path) && teapot_write_obj(&teapot, path);
    if (ok) {
        log_info("%s: %d vertices, %d triangles", path, teapot.vertex_count, teapot.triangle_count);
    }
    *vertices = teapot.vertex_count;
    teapot_destroy(&teapot);
    return ok ? recipes_count_file_triangles(path) : -1;
}

/* bunny.ply refined by BUNNY_LOOP_LEVELS of Loop subdivision into models_dir/BUNNY_REFINED (the
 * paper's bunnies had about 40,000 triangles each; the scanned one here has 3,674); its triangle
 * count as the loader reads it back, -1 on failure. */
static long recipes_write_refined_bunny(const char *models_dir)
{
    char path[GEN_PATH_MAX];
    mesh_data m = {0};
    loop_mesh level[2] = {{0}};
    bool ok = gen_path_join(models_dir, "bunny.ply", path) && mesh_data_load(&m, path, "gen_scenes") &&
              loop_from_mesh_data(&m, &level[0]);
    mesh_data_destroy(&m);
    for (int k = 0; k < BUNNY_LOOP_LEVELS && ok; k++) {
        ok = loop_subdivide(&level[k % 2], &level[(k + 1) % 2]);
        loop_destroy(&level[k % 2]);
    }
    const char *const comments[] = {"the Stanford bunny of bunny.ply after two levels of Loop subdivision",
                                     "written by tools/gen_scenes (tools/gen_scenes/loop.c)", NULL};
    const loop_mesh *fine = &level[BUNNY_LOOP_LEVELS % 2];
    ok = ok && gen_path_join(models_dir, BUNNY_REFINED, path) && loop_write_ply(fine, path, comments);
    if (ok)
        log_info("%s: %d vertices, %d triangles", path, fine->vertex_count, fine->triangle_count);
    loop_destroy(&level[0]), loop_destroy(&level[1]);
    return ok ? recipes_count_file_triangles(path) : -1;
}

static bool recipes_write_scene(const gen_scene *s, const char *dir, const char *name)
{
    char path[GEN_PATH_MAX];
    if (!gen_path_join(dir, name, path) || !gen_scene_write(s, path)) {
        return false;
    }
    log_info("%s: %d objects, %d lights", path, s->object_count, s->light_count);
    return true;
}

bool recipes_write_all(const char *out_dir, const char *models_dir, const char *textures_dir)
{
    char models_rel[GEN_PATH_MAX], textures_rel[GEN_PATH_MAX], spec[GEN_PATH_MAX + 32];
    if (!gen_path_relative(out_dir, models_dir, sizeof models_rel, models_rel) ||
        !gen_path_relative(out_dir, textures_dir, sizeof textures_rel, textures_rel) ||
        !pbr_textures_write(textures_dir)) {
        return false;
    }
    int teapot_vertices = 0;
    long teapot_triangles = recipes_write_teapot(models_dir, &teapot_vertices);
    long bunny_triangles = recipes_write_refined_bunny(models_dir);
    if (teapot_triangles < 0 || bunny_triangles < 0) {
        return false;
    }
    gen_scene *s = malloc(sizeof *s);
    if (!s) {
        log_error("gen_scenes: out of memory");
        return false;
    }
    recipes_build_city(s);
    bool ok = recipes_write_scene(s, out_dir, "city.scene");
    snprintf(spec, sizeof spec, "file %s/%s", models_rel, BUNNY_REFINED);
    recipes_build_bunnies(s, spec, bunny_triangles);
    ok = ok && recipes_write_scene(s, out_dir, "bunnies.scene");
    ok = ok && recipes_build_sphere(s) && recipes_write_scene(s, out_dir, "sphere.scene");
    snprintf(spec, sizeof spec, "file %s/teapot.obj", models_rel);
    recipes_build_teapots(s, spec, teapot_vertices, teapot_triangles);
    ok = ok && recipes_write_scene(s, out_dir, "teapots.scene");
    ok = ok && recipes_build_pbr_teapots(s, spec, teapot_triangles, textures_rel) &&
         recipes_write_scene(s, out_dir, "pbr_teapots.scene");
    free(s);
    return ok;
}
