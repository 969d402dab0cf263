/* scene_lights.c - the scene directives that make lights (light, spot) and the "key" lines that
 * animate the object or light before them (docs/scene-format.md); scene_directives.c dispatches to
 * them.
 */
#include "scene_internal.h"

#include <stdio.h>
#include <string.h>

/* A new object or light: the "key" lines that follow animate it, into a key array of its own. */
void scene_parser_start_keys(parser *p, last_kind last)
{
    p->last = last;
    p->last_key_cap = 0;
}

/* The light read, appended; the key lines that follow animate it. */
static bool add_light(parser *p, const scene_light *l)
{
    scene_light *grown = scene_parser_append(p, p->s.lights, &p->s.light_count, &p->s.light_capacity, l, sizeof *l);
    if (!grown)
        return false;
    p->s.lights = grown;
    scene_parser_start_keys(p, LAST_LIGHT);
    return true;
}

/* A spot takes a light's attributes (same indexes) and its cone's. */
enum { LIGHT_POSITION, LIGHT_COLOR, LIGHT_INTENSITY, LIGHT_ATTENUATION, LIGHT_SHADOW, SPOT_DIRECTION, SPOT_CONE };
static const char *const LIGHT_ATTRIBUTES[] = {"position", "color", "intensity", "attenuation", "shadow", NULL};
static const char *const SPOT_ATTRIBUTES[] = {"position",  "color",     "intensity", "attenuation",
                                              "shadow",    "direction", "cone",      NULL};

/* "light color", "spot color": the name of an attribute in messages. */
static const char *attribute_name(char out[32], const char *what, const char *attribute)
{
    snprintf(out, 32, "%s %s", what, attribute);
    return out;
}

/* The attributes a point light and a spot share; `what` ("light" or "spot") starts the messages. */
static bool take_shared_attribute(parser *p, const char *what, int attribute, scene_light *l)
{
    char name[32];
    switch (attribute) {
    case LIGHT_POSITION:
        return scene_parser_take_vec3(p, attribute_name(name, what, "position"), NUMBER_ANY, l->position);
    case LIGHT_COLOR:
        return scene_parser_take_vec3(p, attribute_name(name, what, "color"), NUMBER_NON_NEGATIVE, l->color);
    case LIGHT_INTENSITY:
        return scene_parser_take_number(p, attribute_name(name, what, "intensity"), NUMBER_NON_NEGATIVE,
                                        &l->intensity);
    case LIGHT_ATTENUATION:
        attribute_name(name, what, "attenuation");
        if (!scene_parser_take_number(p, name, NUMBER_ANY, &l->kc) ||
            !scene_parser_take_number(p, name, NUMBER_NON_NEGATIVE, &l->kl) ||
            !scene_parser_take_number(p, name, NUMBER_NON_NEGATIVE, &l->kq))
            return false;
        /* kc is the whole denominator at distance 0: zero there means infinite light. */
        if (!(l->kc > 0.0f))
            return scene_parser_fail(p,
                                     "%s: KC must be > 0 (the light would be infinitely "
                                     "bright at its centre), got '%s'",
                                     name, scene_parser_show_token(p->tok[p->pos - 3]).text);
        return true;
    case LIGHT_SHADOW: return scene_parser_take_switch(p, attribute_name(name, what, "shadow"), &l->shadow_off);
    default: return false; /* already reported */
    }
}

static bool take_light_attribute(parser *p, scene_light *l, unsigned *seen)
{
    int attribute = scene_parser_take_attribute(p, "light", LIGHT_ATTRIBUTES,
                                                "position, color, intensity, attenuation or shadow", seen);
    return take_shared_attribute(p, "light", attribute, l);
}

bool scene_parser_parse_light(parser *p)
{
    scene_light l = {.color = {1.0f, 1.0f, 1.0f}, .intensity = 1.0f, .kc = 1.0f, .kl = 0.14f, .kq = 0.07f};
    unsigned seen = 0;
    while (!scene_parser_at_end(p))
        if (!take_light_attribute(p, &l, &seen))
            return false;
    return add_light(p, &l);
}

/* cone INNER OUTER: half-angles in degrees, 0 < inner <= outer < 90 (a cone of 90 degrees or more
 * is no cone: docs/09_spot_lights.md, "Pitfalls"). */
static bool take_spot_cone(parser *p, scene_light *l)
{
    if (!scene_parser_take_number(p, "spot cone", NUMBER_POSITIVE, &l->inner_deg) ||
        !scene_parser_take_number(p, "spot cone", NUMBER_POSITIVE, &l->outer_deg))
        return false;
    if (!(l->outer_deg < 90.0f))
        return scene_parser_fail(p, "spot cone: the outer angle must be below 90 degrees, got '%s'",
                                 scene_parser_show_token(p->tok[p->pos - 1]).text);
    if (!(l->inner_deg <= l->outer_deg))
        return scene_parser_fail(p, "spot cone: the inner angle (%g) must not exceed the outer angle (%g)",
                                 l->inner_deg, l->outer_deg);
    return true;
}

static bool take_spot_attribute(parser *p, scene_light *l, unsigned *seen)
{
    int attribute = scene_parser_take_attribute(
        p, "spot", SPOT_ATTRIBUTES, "position, direction, cone, color, intensity, attenuation or shadow", seen);
    switch (attribute) {
    case SPOT_DIRECTION: {
        if (!scene_parser_take_vec3(p, "spot direction", NUMBER_ANY, l->direction))
            return false;
        /* In double: the squares of large floats still fit, and the renderers normalise it. */
        double x = l->direction[0], y = l->direction[1], z = l->direction[2];
        if (!(x * x + y * y + z * z > 0.0))
            return scene_parser_fail(p, "spot direction: must not be zero");
        return true;
    }
    case SPOT_CONE: return take_spot_cone(p, l);
    default: return take_shared_attribute(p, "spot", attribute, l);
    }
}

/* spot: a point light seen only inside a cone; direction and cone are required. */
bool scene_parser_parse_spot(parser *p)
{
    scene_light l = {.color = {1.0f, 1.0f, 1.0f}, .intensity = 1.0f, .kc = 1.0f, .kl = 0.14f, .kq = 0.07f,
                     .spot = true};
    unsigned seen = 0;
    while (!scene_parser_at_end(p))
        if (!take_spot_attribute(p, &l, &seen))
            return false;
    if (!(seen & (1u << SPOT_DIRECTION)))
        return scene_parser_fail(p, "spot: missing 'direction X Y Z'");
    if (!(seen & (1u << SPOT_CONE)))
        return scene_parser_fail(p, "spot: missing 'cone INNER OUTER' (half-angles in degrees)");
    return add_light(p, &l);
}

bool scene_parser_parse_key(parser *p)
{
    scene_key **keys;
    int *count;
    if (p->last == LAST_OBJECT) {
        keys = &p->s.objects[p->s.object_count - 1].keys;
        count = &p->s.objects[p->s.object_count - 1].key_count;
    } else if (p->last == LAST_LIGHT) {
        keys = &p->s.lights[p->s.light_count - 1].keys;
        count = &p->s.lights[p->s.light_count - 1].key_count;
    } else {
        return scene_parser_fail(p, "key: no object or light before it to animate");
    }
    scene_key k;
    if (!scene_parser_take_number(p, "key time", NUMBER_ANY, &k.time))
        return false;
    if (*count > 0 && !(k.time > (*keys)[*count - 1].time))
        return scene_parser_fail(p, "key time '%s' must be greater than the previous key's time (%g)",
                                 scene_parser_show_token(p->tok[p->pos - 1]).text, (*keys)[*count - 1].time);
    if (scene_parser_at_end(p))
        return scene_parser_fail(p, "key: missing 'position X Y Z'");
    if (strcmp(p->tok[p->pos], "position") != 0)
        return scene_parser_fail(p, "key: expected 'position', got '%s'",
                                 scene_parser_show_token(p->tok[p->pos]).text);
    p->pos++;
    if (!scene_parser_take_vec3(p, "key position", NUMBER_ANY, k.position) ||
        !scene_parser_expect_end(p, "key"))
        return false;
    scene_key *grown = scene_parser_append(p, *keys, count, &p->last_key_cap, &k, sizeof k);
    if (!grown)
        return false;
    *keys = grown;
    return true;
}
