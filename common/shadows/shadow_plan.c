/* shadow_plan.c - chapter 14's shadow bookkeeping: importance, tiers, packing, casters, the cache
 * (shadow_plan.h; docs/14_shadows.md). No GL: the unit tests run it as it is.
 */
#include "shadow_plan.h"

#include "log.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

float shadow_far_plane(float radius)
{
    float far_plane = radius < 1e6f ? radius * 1.01f : 1e6f;
    return far_plane < 2.0f * SHADOW_NEAR ? 2.0f * SHADOW_NEAR : far_plane;
}

/* ---- arrays ------------------------------------------------------------------------------------ */

/* *a grown to hold n elements of `size` bytes (new ones zeroed); false (logged) when out of memory. */
static bool grow(void **a, int *cap, int n, size_t size)
{
    if (n <= *cap)
        return true;
    int c = *cap ? *cap : 16;
    while (c < n)
        c *= 2;
    void *g = realloc(*a, (size_t)c * size);
    if (!g) {
        log_error("shadows: out of memory for %d entries", c);
        return false;
    }
    memset((char *)g + (size_t)*cap * size, 0, (size_t)(c - *cap) * size);
    *a = g;
    *cap = c;
    return true;
}

bool shadow_plan_create(shadow_plan *p, const shadow_plan_desc *desc)
{
    memset(p, 0, sizeof *p);
    p->desc = *desc;
    p->gutter = desc->pcf / 2 + 1 + (int)ceilf(desc->normal_offset);
    return true;
}

void shadow_plan_destroy(shadow_plan *p)
{
    free(p->importance), free(p->tier), free(p->first_tile), free(p->faces), free(p->order), free(p->status);
    free(p->previous_tier), free(p->cache), free(p->tiles), free(p->tile_casters), free(p->last_casters);
    memset(p, 0, sizeof *p);
}

static bool grow_lights(shadow_plan *p, const shadow_light *lights, int n)
{
    void **per_light[] = {(void **)&p->importance, (void **)&p->tier,  (void **)&p->first_tile,
                          (void **)&p->faces,      (void **)&p->order, (void **)&p->status};
    const size_t sizes[] = {sizeof(float), sizeof(int), sizeof(int), sizeof(int), sizeof(int), sizeof(shadow_status)};
    int cap = p->light_cap, sources = 0;
    for (int k = 0; k < 6; k++) {
        cap = p->light_cap;
        if (!grow(per_light[k], &cap, n, sizes[k]))
            return false;
    }
    p->light_cap = cap;
    for (int i = 0; i < n; i++)
        sources = lights[i].source + 1 > sources ? lights[i].source + 1 : sources;
    int old = p->source_cap, cache_cap = p->source_cap;
    if (!grow((void **)&p->cache, &cache_cap, sources, sizeof(shadow_cache_entry)) ||
        !grow((void **)&p->previous_tier, &p->source_cap, sources, sizeof(int)))
        return false;
    for (int s = old; s < p->source_cap; s++)
        p->previous_tier[s] = -1;
    return true;
}

/* ---- importance and tiers ---------------------------------------------------------------------- */

float shadow_importance(const vec3 eye, const shadow_light *l)
{
    float d = glm_vec3_distance((float *)eye, (float *)l->position);
    return d <= l->radius ? 1.0f : l->radius / d;
}

/* The tier an importance falls in without hysteresis: 0 from SHADOW_TIER0_IMPORTANCE, then halves. */
static int tier_of(float importance)
{
    float border = SHADOW_TIER0_IMPORTANCE;
    int t = 0;
    while (t < SHADOW_TIERS - 1 && importance < border)
        t++, border *= 0.5f;
    return t;
}

int shadow_tier(float importance, int previous)
{
    int t = tier_of(importance);
    if (previous < 0 || t == previous)
        return t;
    /* up only past the border times the factor, down only below it divided by the factor */
    int held = tier_of(t < previous ? importance / SHADOW_HYSTERESIS : importance * SHADOW_HYSTERESIS);
    return t < previous ? (held < previous ? held : previous) : (held > previous ? held : previous);
}

static int tier_size(const shadow_plan *p, int tier)
{
    int s = SHADOW_TIER0_SIZE >> tier;
    return s < p->desc.atlas_size ? s : p->desc.atlas_size;
}

/* ---- geometry ---------------------------------------------------------------------------------- */

int shadow_cube_face(const vec3 d)
{
    float x = fabsf(d[0]), y = fabsf(d[1]), z = fabsf(d[2]);
    if (x >= y && x >= z)
        return d[0] >= 0.0f ? 0 : 1;
    if (y >= z)
        return d[1] >= 0.0f ? 2 : 3;
    return d[2] >= 0.0f ? 4 : 5;
}

bool shadow_box_meets_sphere(const vec3 lo, const vec3 hi, const vec3 c, float r)
{
    double d2 = 0.0;
    for (int k = 0; k < 3; k++) {
        double e = c[k] < lo[k] ? lo[k] - c[k] : c[k] > hi[k] ? c[k] - hi[k] : 0.0;
        d2 += e * e;
    }
    return d2 <= (double)r * r;
}

bool shadow_box_meets_frustum(const vec3 lo, const vec3 hi, mat4 m)
{
    for (int plane = 0; plane < 6; plane++) { /* row 3 plus or minus row 0, 1, 2 (clip space) */
        int row = plane / 2;
        float sign = plane % 2 ? -1.0f : 1.0f, eq[4];
        for (int c = 0; c < 4; c++)
            eq[c] = m[c][3] + sign * m[c][row];
        float far_side = eq[3]; /* the box corner farthest along the plane's normal */
        for (int k = 0; k < 3; k++)
            far_side += eq[k] * (eq[k] >= 0.0f ? hi[k] : lo[k]);
        if (far_side < 0.0f)
            return false;
    }
    return true;
}

/* A tile's matrix: the light's view along the face's axis (a spot's along its own), then a square
 * perspective of half-field atan(tan_half), from SHADOW_NEAR to the light's radius. */
static void tile_matrix(const shadow_light *l, int face, bool spot, float tan_half, mat4 out)
{
    static const float axes[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const float ups[6][3] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    vec3 axis, up = {0.0f, 1.0f, 0.0f}, centre;
    if (spot) {
        glm_vec3_copy((float *)l->direction, axis);
        if (fabsf(axis[1]) > 0.9f)
            glm_vec3_copy((vec3){1.0f, 0.0f, 0.0f}, up);
    } else {
        glm_vec3_copy((float *)axes[face], axis);
        glm_vec3_copy((float *)ups[face], up);
    }
    glm_vec3_add((float *)l->position, axis, centre);
    float far_plane = shadow_far_plane(l->radius);
    mat4 view, proj;
    glm_lookat((float *)l->position, centre, up, view);
    glm_perspective(2.0f * atanf(tan_half), 1.0f, SHADOW_NEAR, far_plane, proj);
    glm_mat4_mul(proj, view, out);
}

static bool is_spot_tile(const shadow_light *l) { return l->outer_deg > 0.0f && l->outer_deg <= SHADOW_SPOT_MAX_DEG; }

/* ---- choosing and fitting ---------------------------------------------------------------------- */

static const shadow_plan *sort_plan;
static int by_importance(const void *a, const void *b)
{
    int i = *(const int *)a, j = *(const int *)b;
    float x = sort_plan->importance[i], y = sort_plan->importance[j];
    return x > y ? -1 : x < y ? 1 : i - j;
}

/* Texels of the smallest tile, and the atlas's room counted in them. */
static int unit_size(const shadow_plan *p) { return tier_size(p, SHADOW_TIERS - 1); }

static long light_units(const shadow_plan *p, int i)
{
    long s = tier_size(p, p->tier[i]) / unit_size(p);
    return p->faces[i] * s * s;
}

/* Over budget: the least important lights give up a tier at a time (sweeps from the least important
 * up), then, all at the smallest tiles, the least important go unshadowed. */
static void fit(shadow_plan *p, int n)
{
    long room = (long)(p->desc.atlas_size / unit_size(p)) * (p->desc.atlas_size / unit_size(p)), used = 0;
    for (int k = 0; k < n; k++)
        if (p->status[k] == SHADOW_SHADOWED)
            used += light_units(p, k);
    for (bool shrunk = true; used > room && shrunk;) {
        shrunk = false;
        for (int r = n - 1; r >= 0 && used > room; r--) {
            int i = p->order[r];
            if (p->status[i] != SHADOW_SHADOWED || p->tier[i] == SHADOW_TIERS - 1)
                continue;
            used -= light_units(p, i);
            p->tier[i]++, shrunk = true;
            used += light_units(p, i);
        }
    }
    for (int r = n - 1; r >= 0 && used > room; r--) {
        int i = p->order[r];
        if (p->status[i] == SHADOW_SHADOWED)
            used -= light_units(p, i), p->status[i] = SHADOW_DROPPED;
    }
}

static void choose(shadow_plan *p, const vec3 eye, const shadow_light *lights, int n)
{
    int chosen = 0;
    for (int i = 0; i < n; i++) {
        p->order[i] = i;
        p->importance[i] = shadow_importance(eye, &lights[i]);
        p->faces[i] = is_spot_tile(&lights[i]) ? 1 : 6;
        p->first_tile[i] = -1;
    }
    sort_plan = p;
    if (n > 1) /* with no light the array is NULL, which qsort may not be given even for 0 elements */
        qsort(p->order, (size_t)n, sizeof *p->order, by_importance);
    for (int r = 0; r < n; r++) {
        int i = p->order[r];
        int *previous = &p->previous_tier[lights[i].source];
        p->tier[i] = shadow_tier(p->importance[i], *previous);
        *previous = p->tier[i];
        p->status[i] = lights[i].shadow_off ? SHADOW_OFF
                       : p->desc.max_shadowed >= 0 && chosen >= p->desc.max_shadowed ? SHADOW_NOT_CHOSEN
                                                                                      : SHADOW_SHADOWED;
        chosen += p->status[i] == SHADOW_SHADOWED;
    }
    fit(p, n);
}

/* ---- packing ----------------------------------------------------------------------------------- */

static int by_size(const void *a, const void *b)
{
    const shadow_tile *s = a, *t = b;
    if (s->size != t->size)
        return t->size - s->size;
    return s->light != t->light ? s->light - t->light : s->face - t->face;
}

/* Every k-th unit of the Z-order curve: x from the even bits, y from the odd ones. */
static void z_order(long k, int *x, int *y)
{
    *x = *y = 0;
    for (int b = 0; b < 16; b++) {
        *x |= (int)((k >> (2 * b)) & 1) << b;
        *y |= (int)((k >> (2 * b + 1)) & 1) << b;
    }
}

static bool pack(shadow_plan *p, const shadow_light *lights, int n)
{
    p->tile_count = 0;
    for (int i = 0; i < n; i++) {
        if (p->status[i] != SHADOW_SHADOWED)
            continue;
        if (!grow((void **)&p->tiles, &p->tile_cap, p->tile_count + p->faces[i], sizeof *p->tiles))
            return false;
        for (int f = 0; f < p->faces[i]; f++)
            p->tiles[p->tile_count++] = (shadow_tile){.light = i, .face = f, .size = tier_size(p, p->tier[i])};
    }
    if (p->tile_count > 1) /* no light shadowed: no tile array at all */
        qsort(p->tiles, (size_t)p->tile_count, sizeof *p->tiles, by_size);
    long cursor = 0;
    const int unit = unit_size(p);
    for (int t = 0; t < p->tile_count; t++) {
        shadow_tile *tile = &p->tiles[t];
        const shadow_light *l = &lights[tile->light];
        const long side = tile->size / unit;
        z_order(cursor, &tile->x, &tile->y);
        tile->x *= unit, tile->y *= unit;
        cursor += side * side;
        /* the tile's 90 degrees (a spot's cone) inside its gutter: tan grows by size / (size - 2 gutter) */
        float widen = (float)tile->size / (float)(tile->size - 2 * p->gutter);
        bool spot = p->faces[tile->light] == 1;
        tile->tan_half = (spot ? tanf(glm_rad(l->outer_deg)) : 1.0f) * widen;
        tile_matrix(l, tile->face, spot, tile->tan_half, tile->view_proj);
        if (tile->face == 0)
            p->first_tile[tile->light] = t;
    }
    return true;
}

/* ---- casters and the cache --------------------------------------------------------------------- */

static bool box_moved(const shadow_caster *a, const shadow_caster *b)
{
    return !glm_vec3_eqv((float *)a->lo, (float *)b->lo) || !glm_vec3_eqv((float *)a->hi, (float *)b->hi);
}

/* Whether light i's tiles must be drawn again: new, changed, or a caster in its sphere moved. */
static bool light_dirty(shadow_plan *p, const shadow_light *l, int i, const shadow_caster *casters, int m,
                        bool all_moved)
{
    shadow_cache_entry *e = &p->cache[l->source];
    const shadow_tile *first = &p->tiles[p->first_tile[i]];
    bool dirty = all_moved || !e->valid || e->tier != p->tier[i] || e->x != first->x || e->y != first->y ||
                 e->radius != l->radius || !glm_vec3_eqv(e->position, (float *)l->position) ||
                 !glm_vec3_eqv(e->direction, (float *)l->direction);
    for (int o = 0; !dirty && o < m; o++)
        dirty = box_moved(&casters[o], &p->last_casters[o]) &&
                (shadow_box_meets_sphere(casters[o].lo, casters[o].hi, l->position, l->radius) ||
                 shadow_box_meets_sphere(p->last_casters[o].lo, p->last_casters[o].hi, l->position, l->radius));
    *e = (shadow_cache_entry){.valid = true, .radius = l->radius, .tier = p->tier[i], .x = first->x, .y = first->y};
    glm_vec3_copy((float *)l->position, e->position);
    glm_vec3_copy((float *)l->direction, e->direction);
    return dirty;
}

/* Tile t's casters: every object that casts, whose box meets the light's sphere and the tile's frustum. */
static bool tile_casters(shadow_plan *p, int t, const shadow_light *l, const shadow_caster *casters, int m,
                         long *used)
{
    shadow_tile *tile = &p->tiles[t];
    tile->caster_count = 0;
    for (int o = 0; o < m; o++) {
        const shadow_caster *c = &casters[o];
        if (c->cast_off)
            continue;
        if (tile->redraw)
            p->stats.draws_unculled++, p->stats.triangles_unculled += c->triangles;
        if (p->desc.cull && (!shadow_box_meets_sphere(c->lo, c->hi, l->position, l->radius) ||
                             !shadow_box_meets_frustum(c->lo, c->hi, tile->view_proj)))
            continue;
        p->tile_casters[(*used)++] = o;
        tile->caster_count++;
        if (tile->redraw)
            p->stats.draws++, p->stats.triangles += c->triangles;
    }
    return true;
}

static bool plan_casters(shadow_plan *p, const shadow_light *lights, int n, const shadow_caster *casters, int m)
{
    const bool all_moved = m != p->caster_count;
    long need = (long)p->tile_count * m, used = 0;
    if (need > p->tile_caster_cap) {
        int *g = realloc(p->tile_casters, (size_t)need * sizeof *g);
        if (!g)
            return log_error("shadows: out of memory for %ld caster entries", need), false;
        p->tile_casters = g, p->tile_caster_cap = need;
    }
    for (int i = 0; i < n; i++) {
        if (p->status[i] != SHADOW_SHADOWED) {
            p->cache[lights[i].source].valid = false;
            continue;
        }
        bool dirty = light_dirty(p, &lights[i], i, casters, m, all_moved);
        for (int f = 0; f < p->faces[i]; f++)
            p->tiles[p->first_tile[i] + f].redraw = dirty; /* a light's faces stay together (by_size) */
    }
    for (int t = 0; t < p->tile_count; t++) {
        p->tiles[t].casters = NULL;
        tile_casters(p, t, &lights[p->tiles[t].light], casters, m, &used);
        p->stats.tiles_drawn += p->tiles[t].redraw;
    }
    for (int t = 0, at = 0; t < p->tile_count; at += p->tiles[t].caster_count, t++)
        p->tiles[t].casters = p->tile_casters + at;
    if (!grow((void **)&p->last_casters, &p->caster_cap, m, sizeof *casters))
        return false;
    if (m > 0)
        memcpy(p->last_casters, casters, (size_t)m * sizeof *casters);
    p->caster_count = m;
    return true;
}

bool shadow_plan_frame(shadow_plan *p, const vec3 eye, const shadow_light *lights, int n, const shadow_caster *casters,
                       int m)
{
    memset(&p->stats, 0, sizeof p->stats);
    if (!grow_lights(p, lights, n))
        return false;
    choose(p, eye, lights, n);
    if (!pack(p, lights, n) || !plan_casters(p, lights, n, casters, m))
        return false;
    for (int i = 0; i < n; i++) {
        shadow_frame_stats *s = &p->stats;
        s->shadowed += p->status[i] == SHADOW_SHADOWED, s->off += p->status[i] == SHADOW_OFF;
        s->not_chosen += p->status[i] == SHADOW_NOT_CHOSEN, s->dropped += p->status[i] == SHADOW_DROPPED;
        if (p->status[i] == SHADOW_SHADOWED)
            s->lights_per_tier[p->tier[i]]++;
    }
    p->stats.tiles = p->tile_count;
    return true;
}
