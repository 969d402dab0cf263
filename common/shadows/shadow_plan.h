/* shadow_plan.h - chapter 14's shadow bookkeeping, without GL: which lights get shadows, how big their
 * tiles are, where the tiles lie in the atlas, which casters each tile draws, and which tiles must be
 * drawn again this frame (docs/14_shadows.md has the formulas). In common/ with the atlas it plans
 * (shadow_atlas.h), which chapters 15 to 19 reuse.
 *
 *   shadow_plan_create(p, desc)            an empty plan for an atlas of desc->atlas_size texels
 *   shadow_plan_destroy(p)
 *   shadow_plan_frame(p, eye, lights, n, casters, m)
 *                                          this frame's plan: importance and tier of every light
 *                                          (with hysteresis against the last frame's tiers), the N
 *                                          most important (--shadows N) packed into the atlas, the
 *                                          least important made smaller, then dropped, when they do
 *                                          not fit; each tile's matrix, its casters (those whose box
 *                                          meets the light's sphere and the tile's frustum, unless
 *                                          desc.cull is off) and whether it is drawn again (its light,
 *                                          tier or place changed, or a caster in its sphere moved)
 *   shadow_importance(eye, light)          the light's sphere's angular radius as a sine,
 *                                          min(1, r / |eye - p|): 1 with the eye inside the sphere
 *   shadow_tier(importance, previous)      the tier for that importance: 0 (largest tiles) from
 *                                          SHADOW_TIER0_IMPORTANCE, each next tier at half of it; a
 *                                          light leaves its previous tier only when the importance
 *                                          passes the border by the factor SHADOW_HYSTERESIS
 *   shadow_far_plane(radius)               the far plane of a light's shadow maps: just beyond its
 *                                          radius (1e6 when infinite), never nearer than 2 x SHADOW_NEAR
 *   shadow_cube_face(d)                    the cube face (+X -X +Y -Y +Z -Z: 0..5) that sees the
 *                                          direction d from the light: its major axis, as
 *                                          shaders/shadows.glsl chooses it
 *   shadow_box_meets_sphere(lo, hi, c, r)  whether a box and a sphere share a point
 *   shadow_box_meets_frustum(lo, hi, m)    whether a box may meet the frustum of the matrix m (the
 *                                          box against each of its six planes: never false when they
 *                                          meet, rarely true when they do not)
 *
 * Tiles are squares of power-of-two sides packed in Z order: sorted largest first, each starts where
 * the one before ended, so every tile lies aligned, no two overlap and the atlas fills without holes.
 */
#ifndef COMMON_SHADOW_PLAN_H
#define COMMON_SHADOW_PLAN_H

#include <cglm/cglm.h>
#include <stdbool.h>

#define SHADOW_TIERS 4
#define SHADOW_TIER0_SIZE 1024       /* tier k: 1024 >> k texels a side (never more than the atlas) */
#define SHADOW_TIER0_IMPORTANCE 0.5f /* tier k from importance 0.5 / 2^k */
#define SHADOW_HYSTERESIS 1.2f
#define SHADOW_NEAR 0.05f   /* the shadow maps' near plane (world units) */
#define SHADOW_SPOT_MAX_DEG 60.0f /* a spot with a wider outer cone is shadowed as a point light */

/* What the plan needs of a light (the chapter fills it from gpu_scene's lights). */
typedef struct shadow_light {
    vec3 position;
    float radius; /* FLT_MAX when infinite */
    vec3 direction; /* a spot's unit axis */
    float outer_deg; /* a spot's outer half-angle; 0 for a point light */
    bool shadow_off; /* the scene's `shadow off` */
    int source;      /* its index in the scene: what the cache remembers it by */
} shadow_light;

/* What the plan needs of an object. */
typedef struct shadow_caster {
    vec3 lo, hi;  /* world-space bounding box */
    long triangles;
    bool cast_off; /* the scene's `cast off` */
} shadow_caster;

typedef enum shadow_status {
    SHADOW_SHADOWED,
    SHADOW_OFF,        /* `shadow off` in the scene */
    SHADOW_NOT_CHOSEN, /* beyond --shadows N */
    SHADOW_DROPPED,    /* no room left in the atlas */
} shadow_status;

typedef struct shadow_tile {
    int light, face; /* face 0..5 of a point light; 0 for a spot */
    int x, y, size;  /* texels in the atlas */
    float tan_half;  /* tan of half the tile's field of view (wider than 90 degrees by the gutter) */
    mat4 view_proj;
    bool redraw;
    int *casters, caster_count; /* into p->tile_casters */
} shadow_tile;

typedef struct shadow_plan_desc {
    int atlas_size;      /* texels a side, a power of two */
    int max_shadowed;    /* --shadows N; < 0: every light */
    int pcf;             /* 1, 3 or 5 taps a side */
    float normal_offset; /* texels */
    bool cull;           /* per-tile caster culling */
} shadow_plan_desc;

typedef struct shadow_frame_stats {
    int shadowed, off, not_chosen, dropped;
    int tiles, tiles_drawn;
    long draws, triangles;                     /* drawn in the tiles drawn again */
    long draws_unculled, triangles_unculled;   /* the same tiles without the culling */
    int lights_per_tier[SHADOW_TIERS];
} shadow_frame_stats;

typedef struct shadow_cache_entry { /* a light's tiles as last drawn, by its scene index */
    bool valid;
    vec3 position, direction;
    float radius;
    int tier, x, y;
} shadow_cache_entry;

typedef struct shadow_plan {
    shadow_plan_desc desc;
    int gutter; /* texels round each tile's 90-degree square: PCF and the normal offset stay inside */
    int light_count, light_cap;
    float *importance;
    int *tier, *first_tile, *faces, *order;
    shadow_status *status;
    int *previous_tier; /* by scene index */
    shadow_cache_entry *cache;
    int source_cap;
    shadow_tile *tiles;
    int tile_count, tile_cap;
    int *tile_casters;
    long tile_caster_cap;
    shadow_caster *last_casters; /* last frame's boxes: what moved */
    int caster_count, caster_cap;
    shadow_frame_stats stats;
} shadow_plan;

bool shadow_plan_create(shadow_plan *p, const shadow_plan_desc *desc);
void shadow_plan_destroy(shadow_plan *p);
bool shadow_plan_frame(shadow_plan *p, const vec3 eye, const shadow_light *lights, int n, const shadow_caster *casters,
                       int m);
float shadow_importance(const vec3 eye, const shadow_light *l);
int shadow_tier(float importance, int previous);
float shadow_far_plane(float radius);
int shadow_cube_face(const vec3 d);
bool shadow_box_meets_sphere(const vec3 lo, const vec3 hi, const vec3 c, float r);
bool shadow_box_meets_frustum(const vec3 lo, const vec3 hi, mat4 m);

#endif
