/* gen_scenes.c - writes the four benchmark scenes and the tessellated Utah teapot.
 *
 *   gen_scenes --out DIR [--models DIR]
 *
 * The scenes rebuild, in spirit, the test scenes of published deferred-shading
 * results (a city of cubes, a field of bunnies, one dense sphere, a table of
 * teapots), so the course's timings can be set beside them. Everything is drawn
 * from one small PRNG with a fixed seed per scene: the files are reproducible
 * byte for byte, and regenerating one scene never shifts another.
 *
 * The bunny model is not generated here (tools/bunny_to_ply.mjs converts it); its
 * triangle count is read from the PLY header for the scene's comment block.
 */
/* realpath() is an X/Open extension in glibc's headers. */
#define _XOPEN_SOURCE 700

#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "light.h"
#include "log.h"
#include "mesh_data.h"
#include "teapot_patches.h"

#define GEN_PI 3.14159265358979323846
#define GEN_MAX_MESHES 4
#define GEN_MAX_MATERIALS 16
#define GEN_MAX_OBJECTS 4096
#define GEN_MAX_LIGHTS 1024
#define GEN_MAX_NOTES 8
#define GEN_PATH_MAX 4096

/* Quads per patch edge: the welded teapot then has 18,529 vertices, the closest a uniform
 * tessellation gets to the 18,906 of the published scene's model. */
#define TEAPOT_PATCH_STEPS 24

/* ---- a small deterministic PRNG (xorshift32): the same numbers on every platform ---- */

typedef struct rng {
    uint32_t state;
} rng;

static uint32_t rng_next_u32(rng *r)
{
    uint32_t x = r->state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    r->state = x;
    return x;
}

/* Uniform in [lo, hi): 24 bits are exact in a float and plenty here. */
static double rng_uniform(rng *r, double lo, double hi)
{
    return lo + (hi - lo) * (double)(rng_next_u32(r) >> 8) / 16777216.0;
}

static int rng_below(rng *r, int n)
{
    return (int)(rng_next_u32(r) % (uint32_t)n);
}

/* ---- an in-memory scene, written out in one go so the header can state its counts ---- */

typedef struct gen_mesh {
    char name[32];
    char spec[GEN_PATH_MAX]; /* what follows the name: "cube", "sphere 100 100", "file ../models/x.ply" */
    long triangles;
} gen_mesh;

typedef struct gen_material {
    char name[32];
    double albedo[3];
    double specular, shininess;
} gen_material;

typedef struct gen_object {
    int mesh, material;
    double position[3];
    double rotate_y;
    double scale[3];
} gen_object;

typedef struct gen_light {
    double position[3];
    double color[3];
    double intensity;
} gen_light;

typedef struct gen_scene {
    const char *notes[GEN_MAX_NOTES]; /* the opening comment: what the scene reproduces */
    double eye[3], target[3];
    double fovy, near_plane, far_plane;
    double ambient[3];
    double kc, kl, kq; /* one attenuation for every light of the scene */
    gen_mesh meshes[GEN_MAX_MESHES];
    int mesh_count;
    gen_material materials[GEN_MAX_MATERIALS];
    int material_count;
    gen_object objects[GEN_MAX_OBJECTS];
    int object_count;
    gen_light lights[GEN_MAX_LIGHTS];
    int light_count;
} gen_scene;

static int gen_add_mesh(gen_scene *s, const char *name, const char *spec, long triangles)
{
    gen_mesh *m = &s->meshes[s->mesh_count];
    snprintf(m->name, sizeof m->name, "%s", name);
    snprintf(m->spec, sizeof m->spec, "%s", spec);
    m->triangles = triangles;
    return s->mesh_count++;
}

static int gen_add_material(gen_scene *s, const char *name, const double albedo[3], double specular,
                            double shininess)
{
    gen_material *m = &s->materials[s->material_count];
    snprintf(m->name, sizeof m->name, "%s", name);
    memcpy(m->albedo, albedo, sizeof m->albedo);
    m->specular = specular;
    m->shininess = shininess;
    return s->material_count++;
}

static void gen_add_object(gen_scene *s, int mesh, int material, const double position[3], double rotate_y,
                           const double scale[3])
{
    gen_object *o = &s->objects[s->object_count++];
    o->mesh = mesh;
    o->material = material;
    memcpy(o->position, position, sizeof o->position);
    o->rotate_y = rotate_y;
    memcpy(o->scale, scale, sizeof o->scale);
}

/* A saturated but not garish colour with its brightest channel at 1, so intensity alone sets the peak. */
static void gen_random_color(rng *r, double saturation_lo, double saturation_hi, double out[3])
{
    double h = rng_uniform(r, 0.0, 6.0);
    double s = rng_uniform(r, saturation_lo, saturation_hi);
    int sector = (int)h;
    double f = h - sector;
    double p = 1.0 - s, q = 1.0 - s * f, t = 1.0 - s * (1.0 - f);
    double rgb[6][3] = {{1, t, p}, {q, 1, p}, {p, 1, t}, {p, q, 1}, {t, p, 1}, {1, p, q}};
    memcpy(out, rgb[sector % 6], sizeof rgb[0]);
}

static void gen_add_light(gen_scene *s, rng *r, const double position[3])
{
    gen_light *l = &s->lights[s->light_count++];
    memcpy(l->position, position, sizeof l->position);
    gen_random_color(r, 0.35, 0.85, l->color);
    l->intensity = rng_uniform(r, 0.8, 1.2);
}

/* Shortest decimal with at most `decimals` digits: "1.5", "0", "-0.25". */
static const char *gen_format(char buf[32], double v, int decimals)
{
    snprintf(buf, 32, "%.*f", decimals, v);
    char *dot = strchr(buf, '.');
    if (dot) {
        char *end = buf + strlen(buf) - 1;
        while (end > dot && *end == '0') {
            *end-- = '\0';
        }
        if (end == dot) {
            *end = '\0';
        }
    }
    if (strcmp(buf, "-0") == 0) {
        strcpy(buf, "0");
    }
    return buf;
}

static void gen_write_vec3(FILE *f, const double v[3], int decimals)
{
    char a[32], b[32], c[32];
    fprintf(f, "%s %s %s", gen_format(a, v[0], decimals), gen_format(b, v[1], decimals),
            gen_format(c, v[2], decimals));
}

/* A count with thousands separators, as the published tables print them: "18,529". */
static const char *gen_format_count(char buf[32], long n)
{
    char digits[32];
    int len = snprintf(digits, sizeof digits, "%ld", n), k = 0;
    for (int i = 0; i < len; i++) {
        if (i > 0 && digits[i - 1] != '-' && (len - i) % 3 == 0) {
            buf[k++] = ',';
        }
        buf[k++] = digits[i];
    }
    buf[k] = '\0';
    return buf;
}

static void gen_write_thousands(FILE *f, long n)
{
    char buf[32];
    fputs(gen_format_count(buf, n), f);
}

static void gen_write_header(FILE *f, const gen_scene *s)
{
    long triangles = 0;
    int per_mesh[GEN_MAX_MESHES] = {0};
    for (int i = 0; i < s->object_count; i++) {
        triangles += s->meshes[s->objects[i].mesh].triangles;
        per_mesh[s->objects[i].mesh]++;
    }
    double reach_lo = INFINITY, reach_hi = 0.0;
    for (int i = 0; i < s->light_count; i++) {
        const gen_light *l = &s->lights[i];
        const float color[3] = {(float)l->color[0], (float)l->color[1], (float)l->color[2]};
        double peak = light_peak(color, l->intensity);
        double reach = light_radius(s->kc, s->kl, s->kq, peak, LIGHT_DEFAULT_CUTOFF);
        reach_lo = fmin(reach_lo, reach);
        reach_hi = fmax(reach_hi, reach);
    }
    for (int i = 0; i < GEN_MAX_NOTES && s->notes[i]; i++) {
        fprintf(f, "# %s\n", s->notes[i]);
    }
    fprintf(f, "#\n# objects: ");
    gen_write_thousands(f, s->object_count);
    fprintf(f, " (");
    for (int m = 0; m < s->mesh_count; m++) {
        fprintf(f, "%s", m ? ", " : "");
        gen_write_thousands(f, per_mesh[m]);
        fprintf(f, " %s", s->meshes[m].name);
    }
    fprintf(f, ")\n# triangles: ");
    gen_write_thousands(f, triangles);
    fprintf(f, "\n# lights: ");
    gen_write_thousands(f, s->light_count);
    fprintf(f, ", reaching %.1f to %.1f units at the 5/256 cut-off\n", reach_lo, reach_hi);
    fprintf(f, "#\n# Generated by tools/gen_scenes.c; edit the generator, not this file.\n\n");
}

static bool gen_scene_write(const gen_scene *s, const char *path)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        log_error("%s: cannot write: %s", path, strerror(errno));
        return false;
    }
    char a[32], b[32], c[32], d[32];
    gen_write_header(f, s);

    fprintf(f, "camera eye ");
    gen_write_vec3(f, s->eye, 3);
    fprintf(f, " target ");
    gen_write_vec3(f, s->target, 3);
    fprintf(f, " fovy %s near %s far %s\n", gen_format(a, s->fovy, 2), gen_format(b, s->near_plane, 3),
            gen_format(c, s->far_plane, 1));
    fprintf(f, "ambient ");
    gen_write_vec3(f, s->ambient, 3);
    fprintf(f, "\n\n");

    for (int i = 0; i < s->material_count; i++) {
        const gen_material *m = &s->materials[i];
        fprintf(f, "material %s albedo ", m->name);
        gen_write_vec3(f, m->albedo, 3);
        fprintf(f, " specular %s shininess %s\n", gen_format(a, m->specular, 3),
                gen_format(b, m->shininess, 1));
    }
    fprintf(f, "\n");
    for (int i = 0; i < s->mesh_count; i++) {
        fprintf(f, "mesh %s %s\n", s->meshes[i].name, s->meshes[i].spec);
    }
    fprintf(f, "\n");

    for (int i = 0; i < s->object_count; i++) {
        const gen_object *o = &s->objects[i];
        fprintf(f, "object %s %s position ", s->meshes[o->mesh].name, s->materials[o->material].name);
        gen_write_vec3(f, o->position, 3);
        if (o->rotate_y != 0.0) {
            fprintf(f, " rotate_y %s", gen_format(a, o->rotate_y, 1));
        }
        if (o->scale[0] == o->scale[1] && o->scale[1] == o->scale[2]) {
            if (o->scale[0] != 1.0) {
                fprintf(f, " scale %s", gen_format(a, o->scale[0], 3));
            }
        } else {
            fprintf(f, " scale ");
            gen_write_vec3(f, o->scale, 3);
        }
        fprintf(f, "\n");
    }
    fprintf(f, "\n");

    for (int i = 0; i < s->light_count; i++) {
        const gen_light *l = &s->lights[i];
        fprintf(f, "light position ");
        gen_write_vec3(f, l->position, 3);
        fprintf(f, " color ");
        gen_write_vec3(f, l->color, 3);
        fprintf(f, " intensity %s attenuation %s %s %s\n", gen_format(a, l->intensity, 3),
                gen_format(b, s->kc, 4), gen_format(c, s->kl, 4), gen_format(d, s->kq, 4));
    }

    bool ok = !ferror(f);
    if (fclose(f) != 0) {
        ok = false;
    }
    if (!ok) {
        log_error("%s: write failed", path);
    }
    return ok;
}

/* ---- the teapot: 32 Bezier patches tessellated and welded into one indexed mesh ---- */

typedef struct teapot_mesh {
    double (*positions)[3];
    int vertex_count;
    int (*triangles)[3];
    int triangle_count;
} teapot_mesh;

static void bezier_weights(double t, double out[4])
{
    double s = 1.0 - t;
    out[0] = s * s * s;
    out[1] = 3.0 * s * s * t;
    out[2] = 3.0 * s * t * t;
    out[3] = t * t * t;
}

/* Open addressing on the position rounded to 1e-6: seams of neighbouring patches are the same
 * curve evaluated from two sides, equal up to rounding, and must become one vertex so the
 * loader's smooth normals do not show the patch borders. */
typedef struct weld_table {
    int *slots; /* vertex index + 1, 0 when empty */
    int capacity;
} weld_table;

static uint32_t weld_hash(const long long key[3])
{
    uint64_t h = 1469598103934665603ull;
    for (int i = 0; i < 3; i++) {
        h ^= (uint64_t)key[i];
        h *= 1099511628211ull;
    }
    return (uint32_t)(h ^ (h >> 32));
}

static int teapot_weld_vertex(teapot_mesh *m, weld_table *w, const double p[3])
{
    long long key[3];
    for (int i = 0; i < 3; i++) {
        key[i] = llround(p[i] * 1e6);
    }
    uint32_t slot = weld_hash(key) % (uint32_t)w->capacity;
    for (;;) {
        int v = w->slots[slot] - 1;
        if (v < 0) {
            break;
        }
        const double *q = m->positions[v];
        if (llround(q[0] * 1e6) == key[0] && llround(q[1] * 1e6) == key[1] && llround(q[2] * 1e6) == key[2]) {
            return v;
        }
        slot = (slot + 1) % (uint32_t)w->capacity;
    }
    memcpy(m->positions[m->vertex_count], p, sizeof m->positions[0]);
    w->slots[slot] = m->vertex_count + 1;
    return m->vertex_count++;
}

static void teapot_add_triangle(teapot_mesh *m, int a, int b, int c)
{
    if (a == b || b == c || a == c) {
        return; /* the collapsed row at the knob tip and the centre of the bottom */
    }
    m->triangles[m->triangle_count][0] = a;
    m->triangles[m->triangle_count][1] = b;
    m->triangles[m->triangle_count][2] = c;
    m->triangle_count++;
}

/* y up, standing on y = 0, 1 unit tall: the data is z up and 3.15 tall. */
static void teapot_evaluate(int patch, double u, double v, double out[3])
{
    double bu[4], bv[4], p[3] = {0, 0, 0};
    bezier_weights(u, bu);
    bezier_weights(v, bv);
    for (int i = 0; i < 4; i++) {
        for (int j = 0; j < 4; j++) {
            const float *c = teapot_control_points[teapot_patches[patch][4 * i + j]];
            for (int k = 0; k < 3; k++) {
                p[k] += bu[i] * bv[j] * c[k];
            }
        }
    }
    out[0] = p[0] / 3.15;
    out[1] = p[2] / 3.15;
    out[2] = -p[1] / 3.15;
}

static bool teapot_build_mesh(int steps, teapot_mesh *out)
{
    int grid = (steps + 1) * (steps + 1);
    int max_vertices = TEAPOT_PATCH_COUNT * grid;
    int *index = malloc(sizeof *index * (size_t)grid);
    weld_table w = {.capacity = 4 * max_vertices};
    w.slots = calloc((size_t)w.capacity, sizeof *w.slots);
    *out = (teapot_mesh){0};
    out->positions = malloc(sizeof *out->positions * (size_t)max_vertices);
    out->triangles = malloc(sizeof *out->triangles * (size_t)(TEAPOT_PATCH_COUNT * steps * steps * 2));
    if (!index || !w.slots || !out->positions || !out->triangles) {
        log_error("teapot: out of memory");
        free(index);
        free(w.slots);
        free(out->positions);
        free(out->triangles);
        return false;
    }
    for (int patch = 0; patch < TEAPOT_PATCH_COUNT; patch++) {
        for (int i = 0; i <= steps; i++) {
            for (int j = 0; j <= steps; j++) {
                double p[3];
                teapot_evaluate(patch, (double)i / steps, (double)j / steps, p);
                index[i * (steps + 1) + j] = teapot_weld_vertex(out, &w, p);
            }
        }
        /* The patch data winds (u, v) clockwise seen from outside, hence a-d-c and a-c-b. */
        for (int i = 0; i < steps; i++) {
            for (int j = 0; j < steps; j++) {
                int a = index[i * (steps + 1) + j], b = index[(i + 1) * (steps + 1) + j];
                int c = index[(i + 1) * (steps + 1) + j + 1], d = index[i * (steps + 1) + j + 1];
                teapot_add_triangle(out, a, d, c);
                teapot_add_triangle(out, a, c, b);
            }
        }
    }
    free(index);
    free(w.slots);
    return true;
}

static void teapot_destroy(teapot_mesh *m)
{
    free(m->positions);
    free(m->triangles);
    *m = (teapot_mesh){0};
}

static bool teapot_write_obj(const teapot_mesh *m, const char *path)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        log_error("%s: cannot write: %s", path, strerror(errno));
        return false;
    }
    fprintf(f, "# Utah teapot (Martin Newell's 32 Bezier patches), tessellated by tools/gen_scenes.c\n");
    fprintf(f, "# %d x %d quads per patch, seams welded, degenerate triangles dropped\n", TEAPOT_PATCH_STEPS,
            TEAPOT_PATCH_STEPS);
    fprintf(f, "# y up, standing on y = 0, height 1; %d vertices, %d triangles\n", m->vertex_count,
            m->triangle_count);
    for (int i = 0; i < m->vertex_count; i++) {
        fprintf(f, "v ");
        gen_write_vec3(f, m->positions[i], 6);
        fprintf(f, "\n");
    }
    for (int i = 0; i < m->triangle_count; i++) {
        fprintf(f, "f %d %d %d\n", m->triangles[i][0] + 1, m->triangles[i][1] + 1, m->triangles[i][2] + 1);
    }
    bool ok = !ferror(f);
    if (fclose(f) != 0) {
        ok = false;
    }
    if (!ok) {
        log_error("%s: write failed", path);
    }
    return ok;
}

/* ---- paths: scenes name their models relative to the scene file ---- */

static bool path_make_dir(const char *dir)
{
    if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
        log_error("%s: cannot create: %s", dir, strerror(errno));
        return false;
    }
    return true;
}

/* The path from directory `from` to directory `to`, both made absolute first ("../models"). */
static bool path_relative(const char *from, const char *to, char *out, size_t size)
{
    char a[GEN_PATH_MAX], b[GEN_PATH_MAX];
    if (!realpath(from, a) || !realpath(to, b)) {
        log_error("%s or %s: %s", from, to, strerror(errno));
        return false;
    }
    size_t common = 0;
    for (size_t i = 0;; i++) {
        bool end_a = a[i] == '\0' || a[i] == '/', end_b = b[i] == '\0' || b[i] == '/';
        if (end_a && end_b) {
            common = i;
        }
        if (a[i] != b[i] || a[i] == '\0') {
            break;
        }
    }
    out[0] = '\0';
    size_t used = 0;
    for (const char *p = a + common; *p; p++) {
        if (*p == '/') {
            used += (size_t)snprintf(out + used, size - used, "%s..", used ? "/" : "");
        }
    }
    const char *rest = b + common;
    if (*rest == '/') {
        rest++;
    }
    if (*rest) {
        used += (size_t)snprintf(out + used, size - used, "%s%s", used ? "/" : "", rest);
    }
    if (used == 0) {
        snprintf(out, size, ".");
    }
    return used < size;
}

static bool path_join(const char *dir, const char *name, char out[GEN_PATH_MAX])
{
    int n = snprintf(out, GEN_PATH_MAX, "%s/%s", dir, name);
    if (n < 0 || n >= GEN_PATH_MAX) {
        log_error("%s/%s: path too long", dir, name);
        return false;
    }
    return true;
}

/* Triangle counts come from the course's own mesh code, so the comment block states what the
 * renderer will draw (and a model the loader rejects is caught here). */
static long mesh_count_file_triangles(const char *path)
{
    mesh_data m = {0};
    if (!mesh_data_load(&m, path, "gen_scenes")) {
        return -1;
    }
    long triangles = m.index_count / 3;
    mesh_data_destroy(&m);
    return triangles;
}

static long mesh_count_sphere_triangles(int slices, int stacks)
{
    mesh_data m = {0};
    if (!mesh_data_sphere(&m, slices, stacks)) {
        return -1;
    }
    long triangles = m.index_count / 3;
    mesh_data_destroy(&m);
    return triangles;
}

/* ---- the four scenes ---- */

static const double ONE[3] = {1, 1, 1};

/* 10 x 10 blocks of 5 x 5 lots; ten random pairs of lots merge into wide buildings,
 * which leaves exactly 2,490 buildings. Towers cluster downtown. */
static void city_build(gen_scene *s)
{
    enum { BLOCKS = 10, LOTS = 5, MERGES = 10 };
    const double block = 8.0, street = 2.4, lot = block / LOTS;
    const double pitch = block + street, origin = -0.5 * (BLOCKS * block + (BLOCKS - 1) * street);
    rng r = {0x0c17u * 2654435761u};

    *s = (gen_scene){
        .notes = {"city.scene - a student deferred-rendering paper's city scene, rebuilt: 2,490 cube",
                  "buildings of varied heights and footprints on a 10 x 10 grid of blocks, 757 coloured",
                  "point lights along the streets 1-3 units up, seen from above at an angle; the",
                  "paper rendered it at 800 x 800. One ground plane is added under the buildings."},
        .eye = {0, 74, 86}, .target = {0, -6, 4}, .fovy = 50, .near_plane = 1, .far_plane = 300,
        .ambient = {0.1, 0.1, 0.11}, .kc = 1, .kl = 0.35, .kq = 0.9};
    int box = gen_add_mesh(s, "box", "cube", 12);
    int ground = gen_add_mesh(s, "ground", "plane", 2);
    int asphalt = gen_add_material(s, "asphalt", (double[3]){0.22, 0.22, 0.24}, 0.05, 8);
    int concrete[8];
    for (int i = 0; i < 8; i++) {
        double grey = rng_uniform(&r, 0.45, 0.8), tint[3];
        gen_random_color(&r, 0.05, 0.2, tint);
        double albedo[3] = {grey * tint[0], grey * tint[1], grey * tint[2]};
        char name[32];
        snprintf(name, sizeof name, "concrete%d", i);
        double specular = rng_uniform(&r, 0.15, 0.35);
        concrete[i] = gen_add_material(s, name, albedo, specular, 16 + 8 * rng_below(&r, 3));
    }

    gen_add_object(s, ground, asphalt, (double[3]){0, 0, 0}, 0, (double[3]){120, 1, 120});

    /* merged[b][row][col]: 1 = left half of a wide building, 2 = its right half (skipped) */
    unsigned char merged[BLOCKS * BLOCKS][LOTS][LOTS] = {{{0}}};
    for (int m = 0; m < MERGES;) {
        int b = rng_below(&r, BLOCKS * BLOCKS), row = rng_below(&r, LOTS), col = rng_below(&r, LOTS - 1);
        if (merged[b][row][col] == 0 && merged[b][row][col + 1] == 0) {
            merged[b][row][col] = 1;
            merged[b][row][col + 1] = 2;
            m++;
        }
    }
    for (int bz = 0; bz < BLOCKS; bz++) {
        for (int bx = 0; bx < BLOCKS; bx++) {
            int b = bz * BLOCKS + bx;
            for (int row = 0; row < LOTS; row++) {
                for (int col = 0; col < LOTS; col++) {
                    if (merged[b][row][col] == 2) {
                        continue;
                    }
                    double width_lots = merged[b][row][col] == 1 ? 2.0 : 1.0;
                    double x0 = origin + bx * pitch + col * lot, z0 = origin + bz * pitch + row * lot;
                    double w = lot * width_lots * rng_uniform(&r, 0.62, 0.92);
                    double d = lot * rng_uniform(&r, 0.62, 0.92);
                    double cx = x0 + 0.5 * lot * width_lots;
                    cx += rng_uniform(&r, -0.5, 0.5) * (lot * width_lots - w);
                    double cz = z0 + 0.5 * lot + rng_uniform(&r, -0.5, 0.5) * (lot - d);
                    double dist = sqrt(cx * cx + cz * cz) / 50.0, u = rng_uniform(&r, 0, 1);
                    double h = 0.8 + rng_uniform(&r, 0, 2.0) + 10.0 * exp(-3.0 * dist * dist) * u * u;
                    if (rng_below(&r, 60) == 0) {
                        h += rng_uniform(&r, 4, 9); /* the odd tower outside downtown */
                    }
                    gen_add_object(s, box, concrete[rng_below(&r, 8)], (double[3]){cx, 0.5 * h, cz}, 0,
                                   (double[3]){w, h, d});
                }
            }
        }
    }

    /* Lights on the street centre lines (the 9 between blocks and the ring road), 1-3 units up. */
    for (int i = 0; i < 757; i++) {
        int street_index = rng_below(&r, BLOCKS + 1);
        double across = origin - 0.5 * street + street_index * pitch + rng_uniform(&r, -0.4, 0.4);
        double along = rng_uniform(&r, origin - street, -origin + street);
        double y = rng_uniform(&r, 1.0, 3.0);
        bool along_x = rng_below(&r, 2) == 0;
        gen_add_light(s, &r, along_x ? (double[3]){along, y, across} : (double[3]){across, y, along});
    }
}

/* 5 x 5 x 5 bunnies, each turned at random, with 100 lights in and around the lattice. */
static void bunnies_build(gen_scene *s, const char *bunny_spec, long bunny_triangles)
{
    enum { GRID = 5 };
    const double spacing = 1.6;
    rng r = {0xb0bbu * 2654435761u};

    *s = (gen_scene){
        .notes = {"bunnies.scene - a student deferred-rendering paper's bunny scene, rebuilt: 125",
                  "Stanford bunnies in a 5 x 5 x 5 lattice, each turned at random, lit by 100 coloured",
                  "point lights scattered through the lattice."},
        .eye = {9.5, 5.5, 11.5}, .target = {0, -0.5, 0}, .fovy = 45, .near_plane = 0.1, .far_plane = 60,
        .ambient = {0.1, 0.1, 0.11}, .kc = 1, .kl = 1, .kq = 4};
    int bunny = gen_add_mesh(s, "bunny", bunny_spec, bunny_triangles);
    int fur[6];
    const double palette[6][3] = {{0.85, 0.82, 0.78}, {0.9, 0.65, 0.55}, {0.6, 0.75, 0.9},
                                  {0.7, 0.85, 0.6},   {0.9, 0.85, 0.5},  {0.75, 0.65, 0.85}};
    for (int i = 0; i < 6; i++) {
        char name[32];
        snprintf(name, sizeof name, "fur%d", i);
        fur[i] = gen_add_material(s, name, palette[i], 0.3, 32);
    }
    const double half = 0.5 * (GRID - 1) * spacing;
    for (int y = 0; y < GRID; y++) {
        for (int z = 0; z < GRID; z++) {
            for (int x = 0; x < GRID; x++) {
                double p[3] = {x * spacing - half, y * spacing - half - 0.5, z * spacing - half};
                /* One draw per statement: argument evaluation order is unspecified in C. */
                int material = fur[rng_below(&r, 6)];
                gen_add_object(s, bunny, material, p, (double)rng_below(&r, 360), ONE);
            }
        }
    }
    for (int i = 0; i < 100; i++) {
        double p[3];
        for (int k = 0; k < 3; k++) {
            p[k] = rng_uniform(&r, -half - 0.8, half + 0.8);
        }
        gen_add_light(s, &r, p);
    }
}

/* One sphere of 20,000 triangles wrapped in 100 lights spread evenly over a shell around it.
 * The built-in UV sphere has 2 * slices * (stacks - 1) triangles: 100 x 101 gives 20,000. */
static bool sphere_build(gen_scene *s)
{
    enum { SLICES = 100, STACKS = 101, LIGHTS = 100 };
    const double radius = 2.0;
    rng r = {0x5e7eu * 2654435761u};

    *s = (gen_scene){
        .notes = {"sphere.scene - a student deferred-rendering paper's sphere scene, rebuilt: one",
                  "sphere of 20,000 triangles lit by 100 coloured point lights on a shell around it."},
        .eye = {0, 2.2, 7.2}, .target = {0, 0, 0}, .fovy = 45, .near_plane = 0.1, .far_plane = 40,
        .ambient = {0.04, 0.04, 0.05}, .kc = 1, .kl = 3, .kq = 16};
    char spec[32];
    snprintf(spec, sizeof spec, "sphere %d %d", SLICES, STACKS);
    long triangles = mesh_count_sphere_triangles(SLICES, STACKS);
    if (triangles < 0) {
        return false;
    }
    int ball = gen_add_mesh(s, "ball", spec, triangles);
    int white = gen_add_material(s, "porcelain", (double[3]){0.85, 0.85, 0.85}, 0.5, 64);
    gen_add_object(s, ball, white, (double[3]){0, 0, 0}, 0, (double[3]){radius, radius, radius});

    /* A Fibonacci spiral gives even coverage; the jitter keeps it from looking machined. */
    const double golden = GEN_PI * (3.0 - sqrt(5.0));
    for (int i = 0; i < LIGHTS; i++) {
        double y = 1.0 - 2.0 * (i + 0.5) / LIGHTS, ring = sqrt(1.0 - y * y), phi = golden * i;
        double shell = radius + rng_uniform(&r, 0.15, 0.6);
        double p[3] = {shell * ring * cos(phi), shell * y, shell * ring * sin(phi)};
        gen_add_light(s, &r, p);
    }
    return true;
}

/* Eight teapots in a ring on a floor, each pouring towards the next, with 80 lights low over it. */
static void teapots_build(gen_scene *s, const char *teapot_spec, int teapot_vertices, long teapot_triangles)
{
    rng r = {0x7ea0u * 2654435761u};
    static char model_note[160];
    char count[32];
    snprintf(model_note, sizeof model_note,
             "teapots (tessellated from the 32 Bezier patches to %s vertices each; the paper's",
             gen_format_count(count, teapot_vertices));

    *s = (gen_scene){
        .notes = {"teapots.scene - a student deferred-rendering paper's teapot scene, rebuilt: 8 Utah",
                  model_note,
                  "model had 18,906) in a ring on a floor, lit by 80 coloured point lights."},
        .eye = {0, 10, 10.5}, .target = {0, 0, 0.3}, .fovy = 50, .near_plane = 0.1, .far_plane = 60,
        .ambient = {0.05, 0.05, 0.05}, .kc = 1, .kl = 0.8, .kq = 4};
    int teapot = gen_add_mesh(s, "teapot", teapot_spec, teapot_triangles);
    int floor_mesh = gen_add_mesh(s, "floor", "plane", 2);
    int wood = gen_add_material(s, "floor", (double[3]){0.55, 0.5, 0.45}, 0.1, 16);
    int glaze[4];
    const double palette[4][3] = {{0.9, 0.9, 0.88}, {0.75, 0.2, 0.15}, {0.2, 0.45, 0.75}, {0.85, 0.7, 0.3}};
    for (int i = 0; i < 4; i++) {
        char name[32];
        snprintf(name, sizeof name, "glaze%d", i);
        glaze[i] = gen_add_material(s, name, palette[i], 0.6, 64);
    }
    gen_add_object(s, floor_mesh, wood, (double[3]){0, 0, 0}, 0, (double[3]){50, 1, 50});
    const double ring = 4.6;
    for (int i = 0; i < 8; i++) {
        double angle = 45.0 * i, a = angle * GEN_PI / 180.0;
        double p[3] = {ring * cos(a), 0, ring * sin(a)};
        /* The spout is +x in model space; R_y(-angle - 90) turns it along the ring. */
        double turn = fmod(-angle - 90.0 + rng_uniform(&r, -10, 10) + 720.0, 360.0);
        gen_add_object(s, teapot, glaze[i % 4], p, turn, (double[3]){1.5, 1.5, 1.5});
    }
    for (int i = 0; i < 80; i++) {
        double radius = 7.5 * sqrt(rng_uniform(&r, 0, 1)), a = rng_uniform(&r, 0, 2.0 * GEN_PI);
        double p[3] = {radius * cos(a), rng_uniform(&r, 0.3, 2.5), radius * sin(a)};
        gen_add_light(s, &r, p);
    }
}

/* ---- main ---- */

static void print_usage(FILE *stream)
{
    fprintf(stream, "usage: gen_scenes --out DIR [--models DIR]\n"
                    "\n"
                    "Writes city.scene, bunnies.scene, sphere.scene and teapots.scene into --out, and the\n"
                    "tessellated teapot.obj into --models (default: DIR/../models). The scenes name the\n"
                    "models relative to --out. The bunny model must already be in --models as bunny.ply\n"
                    "(node tools/bunny_to_ply.mjs PATH_TO/node_modules/bunny MODELS/bunny.ply).\n"
                    "The output is deterministic: running it again reproduces the files byte for byte.\n");
}

static bool write_scene_file(const gen_scene *s, const char *dir, const char *name)
{
    char path[GEN_PATH_MAX];
    if (!path_join(dir, name, path) || !gen_scene_write(s, path)) {
        return false;
    }
    log_info("%s: %d objects, %d lights", path, s->object_count, s->light_count);
    return true;
}

int main(int argc, char **argv)
{
    const char *out_dir = NULL, *models_dir = NULL;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            print_usage(stdout);
            return 0;
        } else if (strcmp(argv[i], "--out") == 0 && i + 1 < argc) {
            out_dir = argv[++i];
        } else if (strcmp(argv[i], "--models") == 0 && i + 1 < argc) {
            models_dir = argv[++i];
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
        if (!path_join(out_dir, "../models", default_models)) {
            return 2;
        }
        models_dir = default_models;
    }
    char models_rel[GEN_PATH_MAX];
    if (!path_make_dir(out_dir) || !path_make_dir(models_dir) ||
        !path_relative(out_dir, models_dir, models_rel, sizeof models_rel)) {
        return 1;
    }

    char path[GEN_PATH_MAX], spec[GEN_PATH_MAX + 16];
    teapot_mesh teapot;
    if (!teapot_build_mesh(TEAPOT_PATCH_STEPS, &teapot)) {
        return 1;
    }
    bool ok = path_join(models_dir, "teapot.obj", path) && teapot_write_obj(&teapot, path);
    int teapot_vertices = teapot.vertex_count;
    log_info("%s: %d vertices, %d triangles", path, teapot.vertex_count, teapot.triangle_count);
    teapot_destroy(&teapot);
    long teapot_triangles = ok ? mesh_count_file_triangles(path) : -1;
    long bunny_triangles = path_join(models_dir, "bunny.ply", path) ? mesh_count_file_triangles(path) : -1;
    if (teapot_triangles < 0 || bunny_triangles < 0) {
        return 1;
    }

    gen_scene *s = malloc(sizeof *s);
    if (!s) {
        log_error("gen_scenes: out of memory");
        return 1;
    }
    city_build(s);
    ok = write_scene_file(s, out_dir, "city.scene");
    snprintf(spec, sizeof spec, "file %s/bunny.ply", models_rel);
    bunnies_build(s, spec, bunny_triangles);
    ok = ok && write_scene_file(s, out_dir, "bunnies.scene");
    ok = ok && sphere_build(s) && write_scene_file(s, out_dir, "sphere.scene");
    snprintf(spec, sizeof spec, "file %s/teapot.obj", models_rel);
    teapots_build(s, spec, teapot_vertices, teapot_triangles);
    ok = ok && write_scene_file(s, out_dir, "teapots.scene");
    free(s);
    return ok ? 0 : 1;
}
