/* shader_features.c - see shader_features.h. */
#include "shader_features.h"

#include <stdio.h>
#include <string.h>

/* What one drawn material asks of the shaders. A Blinn-Phong material samples no image and gives off
 * no light (common/gl/gpu_scene.c writes neither for it), whatever the scene file says of it. */
static void add_material(shader_features *f, const scene *s, const scene_material *m)
{
    if (!m->pbr) {
        f->blinn_phong = true;
    } else {
        f->pbr = true;
        for (int k = 0; k < SCENE_MAP_COUNT; k++)
            f->maps[k] = f->maps[k] || (m->maps[k] >= 0 && m->maps[k] < s->texture_count);
        f->emissive = f->emissive || m->emissive[0] > 0.0f || m->emissive[1] > 0.0f ||
                      m->emissive[2] > 0.0f || m->maps[SCENE_MAP_EMISSIVE] >= 0;
    }
    f->glass = f->glass || m->opacity < 1.0f;
}

shader_features shader_features_of(const scene *s)
{
    shader_features f = {0};
    for (int i = 0; i < s->light_count; i++) {
        f.spot = f.spot || s->lights[i].spot;
        f.point = f.point || !s->lights[i].spot;
    }
    for (int i = 0; i < s->object_count; i++) {
        int m = s->objects[i].material;
        if (m >= 0 && m < s->material_count)
            add_material(&f, s, &s->materials[m]);
    }
    /* A scene of no objects still draws with a material model: chapter 00's. */
    if (!f.blinn_phong && !f.pbr)
        f.blinn_phong = true;
    return f;
}

bool shader_features_any_map(const shader_features *f)
{
    for (int k = 0; k < SCENE_MAP_COUNT; k++)
        if (f->maps[k])
            return true;
    return false;
}

/* The features as (define, word) pairs, in one order for both functions below. */
typedef struct feature_name {
    const char *define, *word;
} feature_name;

static int feature_names(const shader_features *f, feature_name *out)
{
    int n = 0;
    if (f->point)
        out[n++] = (feature_name){"LIGHT_POINT", "point"};
    if (f->spot)
        out[n++] = (feature_name){"LIGHT_SPOT", "spot"};
    if (f->blinn_phong)
        out[n++] = (feature_name){"MATERIAL_BLINN_PHONG", "blinn-phong"};
    if (f->pbr)
        out[n++] = (feature_name){"MATERIAL_PBR", "metallic-roughness"};
    if (shader_features_any_map(f))
        out[n++] = (feature_name){"MATERIAL_MAPS", "maps"};
    if (f->emissive)
        out[n++] = (feature_name){"MATERIAL_EMISSIVE", "emissive"};
    if (f->glass)
        out[n++] = (feature_name){NULL, "glass"};
    return n;
}

bool shader_features_defines(const shader_features *f, char *out, size_t size)
{
    feature_name names[8];
    int n = feature_names(f, names);
    size_t used = (size_t)snprintf(out, size, "SCENE_FEATURES 1");
    for (int i = 0; i < n && used < size; i++)
        if (names[i].define)
            used += (size_t)snprintf(out + used, size - used, "\n%s 1", names[i].define);
    return used < size;
}

bool shader_features_describe(const shader_features *f, char *out, size_t size)
{
    feature_name names[8];
    int n = feature_names(f, names);
    size_t used = 0;
    if (size)
        out[0] = '\0';
    for (int i = 0; i < n && used < size; i++)
        used += (size_t)snprintf(out + used, size - used, "%s%s", i ? "," : "", names[i].word);
    return used < size;
}
