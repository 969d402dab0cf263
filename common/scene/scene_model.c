/* scene_model.c - the `model PATH [position X Y Z] [rotate_y D] [scale S | scale X Y Z] [cast on|off]`
 * directive (docs/scene-format.md): a glTF 2.0 file's meshes, materials, textures, node objects and
 * lights (model_import.c reads them) appended to the scene, the whole model placed as one object
 * would be. The course's own lines can add lights and a camera around it.
 */
#define _XOPEN_SOURCE 700 /* realpath */

#include "scene_internal.h"

#include "model_import.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The scene's texture equal to t (same image, same colour space), appended when there is none; a
 * file is known by its real path, as a material's map is (scene_materials.c), so a model's image and
 * a map naming the same file share one texture. The first material to use it names it in messages. */
static int merge_texture(parser *p, scene_texture *t, const scene_material *m, int map)
{
    char real[PATH_MAX];
    if (!t->data && realpath(t->path, real) && strlen(real) < sizeof t->path)
        memcpy(t->path, real, strlen(real) + 1);
    for (int i = 0; i < p->s.texture_count; i++)
        if (p->s.textures[i].srgb == t->srgb && strcmp(p->s.textures[i].path, t->path) == 0)
            return i;
    t->line = p->line;
    t->map = (scene_map)map;
    memcpy(t->material, m->name, sizeof t->material);
    scene_texture *grown =
        scene_parser_append(p, p->s.textures, &p->s.texture_count, &p->texture_cap, t, sizeof *t);
    if (!grown)
        return -1;
    p->s.textures = grown;
    t->data = NULL; /* the scene owns it now */
    return p->s.texture_count - 1;
}

/* The scene's mesh for part `part` of the file (one `model` line per file is usual; a second one
 * draws the same meshes again). */
static int merge_mesh(parser *p, const scene_mesh *m)
{
    for (int i = 0; i < p->s.mesh_count; i++)
        if (p->s.meshes[i].kind == SCENE_MESH_FILE && p->s.meshes[i].part == m->part &&
            strcmp(p->s.meshes[i].path, m->path) == 0)
            return i;
    scene_mesh copy = *m;
    copy.line = p->line;
    scene_mesh *grown =
        scene_parser_append(p, p->s.meshes, &p->s.mesh_count, &p->mesh_cap, &copy, sizeof copy);
    if (!grown)
        return -1;
    p->s.meshes = grown;
    return p->s.mesh_count - 1;
}

/* Everything of `part` into the scene, with the indices moved to the scene's; objects keep their
 * node matrix as base and get the line's placement, lights are placed by it. */
static bool merge(parser *p, scene *part, const scene_object *place, int *mesh_at, int *material_at)
{
    int textures[SCENE_MAP_COUNT];
    for (int i = 0; i < part->mesh_count; i++)
        if ((mesh_at[i] = merge_mesh(p, &part->meshes[i])) < 0)
            return false;
    for (int i = 0; i < part->material_count; i++) {
        scene_material m = part->materials[i];
        for (int k = 0; k < SCENE_MAP_COUNT; k++)
            if (m.maps[k] >= 0 && (textures[k] = merge_texture(p, &part->textures[m.maps[k]], &m, k)) < 0)
                return false;
        for (int k = 0; k < SCENE_MAP_COUNT; k++)
            m.maps[k] = m.maps[k] >= 0 ? textures[k] : -1;
        scene_material *grown =
            scene_parser_append(p, p->s.materials, &p->s.material_count, &p->material_cap, &m, sizeof m);
        if (!grown)
            return false;
        p->s.materials = grown;
        material_at[i] = p->s.material_count - 1;
    }
    for (int i = 0; i < part->object_count; i++) {
        scene_object o = *place;
        o.mesh = mesh_at[part->objects[i].mesh];
        o.material = material_at[part->objects[i].material];
        o.has_base = true;
        glm_mat4_copy(part->objects[i].base, o.base);
        scene_object *grown =
            scene_parser_append(p, p->s.objects, &p->s.object_count, &p->object_cap, &o, sizeof o);
        if (!grown)
            return false;
        p->s.objects = grown;
    }
    /* The line's placement, as scene_object_world_at builds it: T * Ry * S. */
    mat4 world, rotated;
    glm_translate_make(world, (float *)place->position);
    glm_rotate_y(world, glm_rad(place->rotate_y_deg), rotated);
    glm_scale_to(rotated, (float *)place->scale, world);
    for (int i = 0; i < part->light_count; i++) {
        scene_light l = part->lights[i];
        vec4 at = {l.position[0], l.position[1], l.position[2], 1.0f}, placed;
        glm_mat4_mulv(world, at, placed);
        glm_vec3_copy(placed, l.position);
        mat3 turn;
        glm_mat4_pick3(world, turn);
        glm_mat3_mulv(turn, part->lights[i].direction, l.direction);
        scene_light *grown =
            scene_parser_append(p, p->s.lights, &p->s.light_count, &p->s.light_capacity, &l, sizeof l);
        if (!grown)
            return false;
        p->s.lights = grown;
    }
    return true;
}

bool scene_parser_parse_model(parser *p)
{
    if (scene_parser_at_end(p))
        return scene_parser_fail(p,
                                 "model: missing path (model PATH [position X Y Z] [rotate_y D] [scale S])");
    char path[SCENE_PATH_MAX];
    if (!scene_parser_resolve_file(p, NULL, "model", p->tok[p->pos++], path))
        return false;
    scene_object place = {.scale = {1.0f, 1.0f, 1.0f}};
    unsigned seen = 0;
    while (!scene_parser_at_end(p))
        if (!scene_parser_take_placement(p, "model", &place, &seen))
            return false;
    char origin[SCENE_PATH_MAX + 16], why[512];
    snprintf(origin, sizeof origin, "%s:%d", p->name, p->line);
    scene part;
    if (!model_import_scene(path, origin, &part, why, sizeof why))
        return scene_parser_fail(p, "cannot load model '%s': %s", path, why);
    int *mesh_at = calloc((size_t)part.mesh_count + 1, sizeof *mesh_at);
    int *material_at = calloc((size_t)part.material_count + 1, sizeof *material_at);
    bool ok = mesh_at && material_at ? merge(p, &part, &place, mesh_at, material_at)
                                     : scene_parser_fail(p, "out of memory");
    free(mesh_at);
    free(material_at);
    model_import_free(&part);
    scene_parser_start_keys(p, LAST_NONE); /* a key line cannot animate a model */
    return ok;
}
