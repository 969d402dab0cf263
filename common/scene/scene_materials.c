/* scene_materials.c - the metallic-roughness material: `material NAME pbr base R G B metallic M
 * roughness R [emissive R G B] [opacity A] [base_map PATH] [metal_rough_map PATH] [normal_map PATH]
 * [occlusion_map PATH] [emissive_map PATH]` (docs/scene-format.md), and the table of images its maps
 * name, each file once per colour space.
 */
#include "scene_internal.h"

#include <stb_image.h>
#include <stdio.h>
#include <string.h>

enum {
    PBR_BASE,
    PBR_METALLIC,
    PBR_ROUGHNESS,
    PBR_EMISSIVE,
    PBR_OPACITY,
    PBR_FIRST_MAP, /* then one attribute per scene_map, in its order */
};
static const char *const PBR_ATTRIBUTES[] = {"base",         "metallic",     "roughness",     "emissive",
                                             "opacity",      "base_map",     "metal_rough_map", "normal_map",
                                             "occlusion_map", "emissive_map", NULL};
_Static_assert(sizeof PBR_ATTRIBUTES / sizeof PBR_ATTRIBUTES[0] == PBR_FIRST_MAP + SCENE_MAP_COUNT + 1,
               "one attribute per map");

/* Colour maps hold sRGB-encoded values; the others hold numbers (roughness, a normal) read as stored. */
static bool map_is_srgb(int map)
{
    return map == SCENE_MAP_BASE || map == SCENE_MAP_EMISSIVE;
}

/* The index of the image at `path` in the scene's texture table, added when new. The same file read
 * as colour and as data is two textures: the GPU decodes each once, its own way. */
static int add_texture(parser *p, const char *path, bool srgb)
{
    for (int i = 0; i < p->s.texture_count; i++)
        if (p->s.textures[i].srgb == srgb && !p->s.textures[i].data && strcmp(p->s.textures[i].path, path) == 0)
            return i;
    scene_texture t = {.srgb = srgb};
    memcpy(t.path, path, strlen(path) + 1); /* resolved paths fit SCENE_PATH_MAX */
    scene_texture *grown =
        scene_parser_append(p, p->s.textures, &p->s.texture_count, &p->texture_cap, &t, sizeof t);
    if (!grown)
        return -1;
    p->s.textures = grown;
    return p->s.texture_count - 1;
}

/* A number in [0, 1]: metallic and roughness are fractions, and so is a base colour (a surface
 * that reflects more light than reaches it is not a material). */
static bool take_fraction(parser *p, const char *what, float *out)
{
    if (!scene_parser_take_number(p, what, NUMBER_NON_NEGATIVE, out))
        return false;
    if (!(*out <= 1.0f))
        return scene_parser_fail(p, "%s: must be between 0 and 1, got '%s'", what,
                                 scene_parser_show_token(p->tok[p->pos - 1]).text);
    return true;
}

static bool take_map(parser *p, scene_material *m, int map)
{
    char what[48];
    snprintf(what, sizeof what, "material %s", PBR_ATTRIBUTES[PBR_FIRST_MAP + map]);
    if (scene_parser_at_end(p))
        return scene_parser_fail(p, "%s: missing image path", what);
    char path[SCENE_PATH_MAX];
    if (!scene_parser_resolve_file(p, "image", p->tok[p->pos++], path))
        return false;
    /* The header only (its size and kind): a file that is no image stb_image reads fails here, on its
     * line, not when the renderer decodes it. */
    int w = 0, h = 0, channels = 0;
    if (!stbi_info(path, &w, &h, &channels))
        return scene_parser_fail(p, "%s: '%s' is not an image the course reads (PNG, JPEG, TGA, BMP): %s", what,
                                 path, stbi_failure_reason() ? stbi_failure_reason() : "unknown format");
    m->maps[map] = add_texture(p, path, map_is_srgb(map));
    return m->maps[map] >= 0;
}

static bool take_pbr_attribute(parser *p, scene_material *m, unsigned *seen)
{
    int attribute = scene_parser_take_attribute(p, "material", PBR_ATTRIBUTES,
                                                "base, metallic, roughness, emissive, opacity, base_map, "
                                                "metal_rough_map, normal_map, occlusion_map or emissive_map",
                                                seen);
    switch (attribute) {
    case -1: return false; /* already reported */
    case PBR_BASE:
        for (int k = 0; k < 3; k++)
            if (!take_fraction(p, "material base", &m->albedo[k]))
                return false;
        return true;
    case PBR_METALLIC: return take_fraction(p, "material metallic", &m->metallic);
    case PBR_ROUGHNESS: return take_fraction(p, "material roughness", &m->roughness);
    case PBR_EMISSIVE: return scene_parser_take_vec3(p, "material emissive", NUMBER_NON_NEGATIVE, m->emissive);
    case PBR_OPACITY: return scene_parser_take_opacity(p, &m->opacity);
    default: return take_map(p, m, attribute - PBR_FIRST_MAP);
    }
}

bool scene_parser_take_pbr(parser *p, scene_material *m)
{
    m->pbr = true;
    unsigned seen = 0;
    while (!scene_parser_at_end(p))
        if (!take_pbr_attribute(p, m, &seen))
            return false;
    /* The three numbers every metallic-roughness material has: no default would be right for most. */
    static const int required[] = {PBR_BASE, PBR_METALLIC, PBR_ROUGHNESS};
    static const char *const usage[] = {"base R G B", "metallic M", "roughness R"};
    for (int i = 0; i < 3; i++)
        if (!(seen & (1u << required[i])))
            return scene_parser_fail(p, "material '%s': missing '%s'", m->name, usage[i]);
    return true;
}
