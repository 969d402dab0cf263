/* scene_materials.c - the metallic-roughness material: `material NAME pbr base R G B metallic M
 * roughness R [emissive R G B] [opacity A] [base_map PATH] [metal_rough_map PATH] [normal_map PATH]
 * [occlusion_map PATH] [emissive_map PATH]` (docs/scene-format.md), and the table of images its maps
 * name, each file once per colour space.
 */
#define _XOPEN_SOURCE 700 /* realpath */

#include "scene_internal.h"

#include "data_dir.h"
#include "model_image.h"
#include "model_import.h"

#include <errno.h>
#include <limits.h>
#include <stb_image.h>
#include <stdio.h>
#include <stdlib.h>
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

const char *scene_map_attribute(scene_map map)
{
    return map >= 0 && map < SCENE_MAP_COUNT ? PBR_ATTRIBUTES[PBR_FIRST_MAP + map] : "map";
}

/* The index of the image at real path `real` in the scene's texture table, or -2 when it is new. The
 * same file read as colour and as data is two textures: the GPU decodes each once, its own way. */
static int find_texture(const parser *p, const char *real, bool srgb)
{
    for (int i = 0; i < p->s.texture_count; i++)
        if (p->s.textures[i].srgb == srgb && !p->s.textures[i].data &&
            strcmp(p->s.textures[i].path, real) == 0)
            return i;
    return -2;
}

/* A new texture for `real`, of w x h texels, named on this line by material m's map; -1 (logged)
 * when the scene's maps would then hold more than MODEL_TEXELS_MAX texels, a model's own budget. */
static int add_texture(parser *p, const char *owner, const char *real, const scene_material *m, int map,
                       int w, int h)
{
    long long texels = (long long)w * h;
    if (texels > MODEL_TEXELS_MAX - p->texels) {
        scene_parser_fail(p, "%s '%s': %d x %d texels: the scene's maps would hold more than %lld in all",
                          owner, real, w, h, MODEL_TEXELS_MAX);
        return -1;
    }
    scene_texture t = {.srgb = map_is_srgb(map), .line = p->line, .map = (scene_map)map};
    memcpy(t.path, real, strlen(real) + 1); /* checked to fit SCENE_PATH_MAX */
    memcpy(t.material, m->name, sizeof t.material);
    scene_texture *grown =
        scene_parser_append(p, p->s.textures, &p->s.texture_count, &p->texture_cap, &t, sizeof t);
    if (!grown)
        return -1;
    p->s.textures = grown;
    p->texels += texels;
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

/* The header only (its kind and size): a file that is no image stb_image reads, or one too large to
 * decode, fails here, on its line, not when the renderer decodes it. Read from the file opened as a
 * regular one, so that a file swapped in since is not what is read. */
static bool take_header(parser *p, const char *owner, const char *real, int *w, int *h)
{
    const char *why;
    FILE *f = data_dir_open_input(real, &why);
    if (!f)
        return scene_parser_fail(p, "%s '%s': cannot open image: %s", owner, real, why);
    int channels = 0;
    bool known = stbi_info_from_file(f, w, h, &channels) != 0;
    fclose(f);
    if (!known)
        return scene_parser_fail(p, "%s '%s': not an image the course reads (PNG, JPEG, TGA, BMP): %s", owner,
                                 real, stbi_failure_reason() ? stbi_failure_reason() : "unknown format");
    if (*w < 1 || *h < 1 || *w > MODEL_IMAGE_SIDE_MAX || *h > MODEL_IMAGE_SIDE_MAX)
        return scene_parser_fail(p, "%s '%s': %d x %d texels, more than %d a side", owner, real, *w, *h,
                                 MODEL_IMAGE_SIDE_MAX);
    return true;
}

static bool take_map(parser *p, scene_material *m, int map)
{
    char owner[SCENE_NAME_MAX + 48]; /* "material 'NAME' base_map": every message about the map says it */
    snprintf(owner, sizeof owner, "material '%s' %s", m->name, PBR_ATTRIBUTES[PBR_FIRST_MAP + map]);
    if (scene_parser_at_end(p))
        return scene_parser_fail(p, "%s: missing image path", owner);
    char path[SCENE_PATH_MAX], real[PATH_MAX];
    if (!scene_parser_resolve_file(p, owner, "image", p->tok[p->pos++], path))
        return false;
    /* One texture per file, however the path spells it ("a.png", "./a.png", "x/../a.png", a link). */
    if (!realpath(path, real))
        return scene_parser_fail(p, "%s '%s': cannot open image: %s", owner, path, strerror(errno));
    if (strlen(real) >= SCENE_PATH_MAX)
        return scene_parser_fail(p, "%s '%s': its real path '%s' is longer than %d characters", owner, path,
                                 scene_parser_show_token(real).text, SCENE_PATH_MAX - 1);
    int w = 0, h = 0;
    if (!take_header(p, owner, real, &w, &h))
        return false;
    int known = find_texture(p, real, map_is_srgb(map));
    m->maps[map] = known >= 0 ? known : add_texture(p, owner, real, m, map, w, h);
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
