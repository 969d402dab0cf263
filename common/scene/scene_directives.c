/* scene_directives.c - one function per scene directive (camera, ambient, material, mesh, object,
 * falloff), each reading the rest of its line into the scene being built, and the dispatch by the
 * line's first word; the lights (light, spot) and their keys are in scene_lights.c, the model
 * directive in scene_model.c. The format and
 * its limits are in docs/scene-format.md; the token readers are in scene_parser.c.
 */
#include "scene_internal.h"

#include "data_dir.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define SCENE_SPHERE_MAX 4096

/* ---- camera and ambient ------------------------------------------------------------------ */

/* Attribute indexes double as bits of the `seen` mask (scene_parser_take_attribute). */
enum { CAMERA_EYE, CAMERA_TARGET, CAMERA_UP, CAMERA_FOVY, CAMERA_NEAR, CAMERA_FAR };
static const char *const CAMERA_ATTRIBUTES[] = {"eye", "target", "up", "fovy", "near", "far", NULL};

static bool take_camera_attribute(parser *p, scene_camera *c, unsigned *seen)
{
    int attribute = scene_parser_take_attribute(p, "camera", CAMERA_ATTRIBUTES,
                                                "eye, target, up, fovy, near or far", seen);
    switch (attribute) {
    case CAMERA_EYE: return scene_parser_take_vec3(p, "camera eye", NUMBER_ANY, c->eye);
    case CAMERA_TARGET: return scene_parser_take_vec3(p, "camera target", NUMBER_ANY, c->target);
    case CAMERA_UP: return scene_parser_take_vec3(p, "camera up", NUMBER_ANY, c->up);
    case CAMERA_FOVY:
        if (!scene_parser_take_number(p, "camera fovy", NUMBER_POSITIVE, &c->fovy_deg))
            return false;
        if (!(c->fovy_deg < 180.0f))
            return scene_parser_fail(p, "camera fovy: must be between 0 and 180 degrees, got '%s'",
                                     scene_parser_show_token(p->tok[p->pos - 1]).text);
        if (!(c->fovy_deg >= (float)SCENE_FOVY_MIN))
            return scene_parser_fail(p, "camera fovy: must be at least %g degrees, got '%s'", SCENE_FOVY_MIN,
                                     scene_parser_show_token(p->tok[p->pos - 1]).text);
        return true;
    case CAMERA_NEAR: return scene_parser_take_number(p, "camera near", NUMBER_POSITIVE, &c->near_plane);
    case CAMERA_FAR: return scene_parser_take_number(p, "camera far", NUMBER_POSITIVE, &c->far_plane);
    default: return false; /* already reported */
    }
}

/* The checks that need the whole line: a camera that a view matrix can be built from. */
static bool check_camera(parser *p, scene_camera *c, unsigned seen)
{
    if (!(seen & (1u << CAMERA_EYE)))
        return scene_parser_fail(p, "camera: missing 'eye X Y Z'");
    if (!(seen & (1u << CAMERA_TARGET)))
        return scene_parser_fail(p, "camera: missing 'target X Y Z'");
    if (!(c->far_plane > c->near_plane))
        return scene_parser_fail(p, "camera: far (%g) must be greater than near (%g)", c->far_plane,
                                 c->near_plane);
    if (!((double)c->far_plane / c->near_plane <= SCENE_DEPTH_RATIO_MAX))
        return scene_parser_fail(p, "camera: far / near is %g, more than a depth buffer can hold (%.0f = 2^24: "
                                 "the farther half of the view would share one depth step)",
                                 (double)c->far_plane / c->near_plane, SCENE_DEPTH_RATIO_MAX);
    vec3 view, side;
    glm_vec3_sub(c->target, c->eye, view);
    float view_len = glm_vec3_norm(view);
    if (!(view_len > 1e-6f))
        return scene_parser_fail(p, "camera: eye and target are the same point");
    /* Differences of huge finite coordinates can overflow to inf. */
    if (!isfinite(view_len))
        return scene_parser_fail(p, "camera: eye and target are too far apart");
    glm_vec3_cross(view, c->up, side);
    float up_len = glm_vec3_norm(c->up);
    if (!(glm_vec3_norm(side) > 1e-6f * view_len * up_len) || !isfinite(glm_vec3_norm(side))) {
        /* Suggest the world axis most nearly at right angles to the view. */
        int best = 1;
        for (int k = 0; k < 3; k++)
            if (fabsf(view[k]) < fabsf(view[best]))
                best = k;
        return scene_parser_fail(p,
                                 "camera: up (%g %g %g) is zero or parallel to the view direction: "
                                 "try up %d %d %d",
                                 c->up[0], c->up[1], c->up[2], best == 0, best == 1, best == 2);
    }
    return true;
}

static bool parse_camera(parser *p)
{
    if (p->camera_line)
        return scene_parser_fail(p, "camera: given twice (first on line %d)", p->camera_line);
    /* Attributes left out keep their defaults, which scene.c put in the scene before the parse
     * and nothing has changed since: this is the first camera line. */
    scene_camera c = p->s.camera;
    unsigned seen = 0;
    while (!scene_parser_at_end(p))
        if (!take_camera_attribute(p, &c, &seen))
            return false;
    if (!check_camera(p, &c, seen))
        return false;
    p->s.camera = c;
    p->camera_line = p->line;
    return true;
}

static bool parse_ambient(parser *p)
{
    if (p->ambient_line)
        return scene_parser_fail(p, "ambient: given twice (first on line %d)", p->ambient_line);
    if (!scene_parser_take_vec3(p, "ambient", NUMBER_NON_NEGATIVE, p->s.ambient) ||
        !scene_parser_expect_end(p, "ambient"))
        return false;
    p->ambient_line = p->line;
    return true;
}

/* ---- materials and meshes ---------------------------------------------------------------- */

static name_list mesh_list(const parser *p)
{
    return (name_list){p->s.meshes ? p->s.meshes[0].name : NULL, sizeof(scene_mesh)};
}

static name_list material_list(const parser *p)
{
    return (name_list){p->s.materials ? p->s.materials[0].name : NULL, sizeof(scene_material)};
}

enum { MATERIAL_SPECULAR, MATERIAL_SHININESS, MATERIAL_OPACITY };
static const char *const MATERIAL_ATTRIBUTES[] = {"specular", "shininess", "opacity", NULL};

/* 0 < A <= 1: an opacity of 0 would be an object nobody can see, drawn at full cost. */
bool scene_parser_take_opacity(parser *p, float *opacity)
{
    if (!scene_parser_take_number(p, "material opacity", NUMBER_POSITIVE, opacity))
        return false;
    if (!(*opacity <= 1.0f))
        return scene_parser_fail(p, "material opacity: must be at most 1 (1 is opaque), got '%s'",
                                 scene_parser_show_token(p->tok[p->pos - 1]).text);
    return true;
}

static bool take_material_attribute(parser *p, scene_material *m, unsigned *seen)
{
    int attribute = scene_parser_take_attribute(p, "material", MATERIAL_ATTRIBUTES,
                                                "specular, shininess or opacity", seen);
    switch (attribute) {
    case MATERIAL_SPECULAR:
        return scene_parser_take_number(p, "material specular", NUMBER_NON_NEGATIVE, &m->specular);
    case MATERIAL_SHININESS:
        return scene_parser_take_number(p, "material shininess", NUMBER_POSITIVE, &m->shininess);
    case MATERIAL_OPACITY: return scene_parser_take_opacity(p, &m->opacity);
    default: return false; /* already reported */
    }
}

/* The rest of a Blinn-Phong material's line: albedo, then its attributes. */
static bool take_blinn_phong(parser *p, scene_material *m)
{
    if (strcmp(p->tok[p->pos], "albedo") != 0)
        return scene_parser_fail(p, "material '%s': expected 'albedo' or 'pbr', got '%s'", m->name,
                                 scene_parser_show_token(p->tok[p->pos]).text);
    p->pos++;
    if (!scene_parser_take_vec3(p, "material albedo", NUMBER_NON_NEGATIVE, m->albedo))
        return false;
    unsigned seen = 0;
    while (!scene_parser_at_end(p))
        if (!take_material_attribute(p, m, &seen))
            return false;
    return true;
}

static bool parse_material(parser *p)
{
    _Static_assert(SCENE_MAP_COUNT == 5, "one -1 per map below");
    scene_material m = {.specular = 0.0f, .shininess = 32.0f, .opacity = 1.0f, .maps = {-1, -1, -1, -1, -1}};
    if (!scene_parser_take_name(p, "material", m.name))
        return false;
    const name_slot *dup = scene_parser_find_name(&p->material_names, material_list(p), m.name);
    if (dup)
        return scene_parser_fail(p, "material '%s' is already declared on line %d", m.name, dup->line);
    if (scene_parser_at_end(p))
        return scene_parser_fail(p, "material '%s': missing 'albedo R G B'", m.name);
    if (strcmp(p->tok[p->pos], "pbr") == 0) {
        p->pos++;
        if (!scene_parser_take_pbr(p, &m))
            return false;
    } else if (!take_blinn_phong(p, &m)) {
        return false;
    }
    scene_material *grown =
        scene_parser_append(p, p->s.materials, &p->s.material_count, &p->material_cap, &m, sizeof m);
    if (!grown)
        return false;
    p->s.materials = grown;
    return scene_parser_add_name(p, &p->material_names, m.name, p->s.material_count - 1);
}

/* "cannot open model 'PATH': why", or, for a file a material names (owner "material 'm' base_map"),
 * "material 'm' base_map 'PATH': cannot open image: why". */
static bool fail_open(parser *p, const char *owner, const char *what, const char *path, const char *why)
{
    if (owner)
        return scene_parser_fail(p, "%s '%s': cannot open %s: %s", owner, path, what, why);
    return scene_parser_fail(p, "cannot open %s '%s': %s", what, path, why);
}

/* Model and image paths are relative to the scene file's folder, then to the data folder; absolute
 * paths are kept. `what` names the file in messages ("model", "image"), after `owner` if not NULL. */
bool scene_parser_resolve_file(parser *p, const char *owner, const char *what, const char *given,
                               char out[SCENE_PATH_MAX])
{
    size_t base = given[0] == '/' ? 0 : strlen(p->base_dir);
    if (base + 1 + strlen(given) >= SCENE_PATH_MAX)
        return scene_parser_fail(p, "%s%s%s path '%s' is longer than %d characters", owner ? owner : "",
                                 owner ? ": " : "", what, scene_parser_show_token(given).text,
                                 SCENE_PATH_MAX - 1);
    char tried[2 * SCENE_PATH_MAX + 4400], why[sizeof tried + 64];
    if (!data_dir_find(given, p->base_dir, out, SCENE_PATH_MAX, tried, sizeof tried)) {
        snprintf(why, sizeof why, "No such file or directory (looked for %s)", tried);
        return fail_open(p, owner, what, out, why);
    }
    /* Only check that the file is there, regular and readable: its loader reads it later. A named
     * pipe is refused here without waiting for a writer. */
    const char *reason;
    FILE *f = data_dir_open_input(out, &reason);
    if (!f)
        return fail_open(p, owner, what, out, reason);
    fclose(f);
    return true;
}

/* The kind after the mesh's name, and what that kind takes. */
static bool take_mesh_kind(parser *p, scene_mesh *m)
{
    if (scene_parser_at_end(p))
        return scene_parser_fail(p, "mesh '%s': missing kind (cube, plane, sphere or file)", m->name);
    const char *kind = p->tok[p->pos++];
    if (strcmp(kind, "cube") == 0) {
        m->kind = SCENE_MESH_CUBE;
    } else if (strcmp(kind, "plane") == 0) {
        m->kind = SCENE_MESH_PLANE;
    } else if (strcmp(kind, "sphere") == 0) {
        m->kind = SCENE_MESH_SPHERE;
        m->slices = 32;
        m->stacks = 16;
        if (!scene_parser_at_end(p) &&
            (!scene_parser_take_int(p, "mesh sphere slices", 3, SCENE_SPHERE_MAX, &m->slices) ||
             !scene_parser_take_int(p, "mesh sphere stacks", 2, SCENE_SPHERE_MAX, &m->stacks)))
            return false;
    } else if (strcmp(kind, "file") == 0) {
        m->kind = SCENE_MESH_FILE;
        if (scene_parser_at_end(p))
            return scene_parser_fail(p, "mesh '%s': missing model path after 'file'", m->name);
        if (!scene_parser_resolve_file(p, NULL, "model", p->tok[p->pos++], m->path))
            return false;
    } else {
        return scene_parser_fail(p, "mesh '%s': unknown kind '%s' (expected cube, plane, sphere or file)",
                                 m->name, scene_parser_show_token(kind).text);
    }
    return true;
}

static bool parse_mesh(parser *p)
{
    scene_mesh m = {.line = p->line, .part = -1};
    if (!scene_parser_take_name(p, "mesh", m.name))
        return false;
    const name_slot *dup = scene_parser_find_name(&p->mesh_names, mesh_list(p), m.name);
    if (dup)
        return scene_parser_fail(p, "mesh '%s' is already declared on line %d", m.name, dup->line);
    if (!take_mesh_kind(p, &m) || !scene_parser_expect_end(p, "mesh"))
        return false;
    scene_mesh *grown = scene_parser_append(p, p->s.meshes, &p->s.mesh_count, &p->mesh_cap, &m, sizeof m);
    if (!grown)
        return false;
    p->s.meshes = grown;
    return scene_parser_add_name(p, &p->mesh_names, m.name, p->s.mesh_count - 1);
}

/* ---- objects, lights and their keys ------------------------------------------------------ */

/* "unknown mesh 'x' (declared: a, b)": the names a learner could have meant. */
static bool fail_unknown(parser *p, const char *what, const char *name, name_list list, int count)
{
    char declared[256] = "";
    size_t used = 0;
    for (int i = 0; i < count && used + 4 < sizeof declared; i++) {
        int n = snprintf(declared + used, sizeof declared - used, "%s%s", i ? ", " : "",
                         list.first + (size_t)i * list.stride);
        used = n > 0 ? used + (size_t)n : used;
    }
    if (count == 0)
        return scene_parser_fail(p, "unknown %s '%s' (none declared yet: declare it with a %s line first)",
                                 what, name, what);
    return scene_parser_fail(p, "unknown %s '%s' (declared: %s; a %s line must come first)", what, name,
                             declared, what);
}

/* The object's mesh and material, by the names declared on earlier lines. */
static bool take_object_refs(parser *p, scene_object *o)
{
    char name[SCENE_NAME_MAX];
    if (!scene_parser_take_name(p, "object mesh", name))
        return false;
    const name_slot *mesh = scene_parser_find_name(&p->mesh_names, mesh_list(p), name);
    if (!mesh)
        return fail_unknown(p, "mesh", name, mesh_list(p), p->s.mesh_count);
    o->mesh = mesh->index;
    if (!scene_parser_take_name(p, "object material", name))
        return false;
    const name_slot *material = scene_parser_find_name(&p->material_names, material_list(p), name);
    if (!material)
        return fail_unknown(p, "material", name, material_list(p), p->s.material_count);
    o->material = material->index;
    return true;
}

enum { OBJECT_POSITION, OBJECT_ROTATE_Y, OBJECT_SCALE, OBJECT_CAST };
static const char *const OBJECT_ATTRIBUTES[] = {"position", "rotate_y", "scale", "cast", NULL};

/* `what` ("object", "model") starts the messages: "object scale: must be > 0". */
bool scene_parser_take_placement(parser *p, const char *what, scene_object *o, unsigned *seen)
{
    int attribute =
        scene_parser_take_attribute(p, what, OBJECT_ATTRIBUTES, "position, rotate_y, scale or cast", seen);
    char name[32];
    snprintf(name, sizeof name, "%s %s", what, attribute >= 0 ? OBJECT_ATTRIBUTES[attribute] : "");
    switch (attribute) {
    case OBJECT_POSITION: return scene_parser_take_vec3(p, name, NUMBER_ANY, o->position);
    case OBJECT_ROTATE_Y: return scene_parser_take_number(p, name, NUMBER_ANY, &o->rotate_y_deg);
    case OBJECT_CAST: return scene_parser_take_switch(p, name, &o->cast_off);
    case OBJECT_SCALE:
        if (!scene_parser_take_number(p, name, NUMBER_POSITIVE, &o->scale[0]))
            return false;
        /* "scale S" or "scale X Y Z": a number after the first means the second form. */
        if (!scene_parser_next_is_number(p)) {
            o->scale[1] = o->scale[2] = o->scale[0];
            return true;
        }
        return scene_parser_take_number(p, name, NUMBER_POSITIVE, &o->scale[1]) &&
               scene_parser_take_number(p, name, NUMBER_POSITIVE, &o->scale[2]);
    default: return false; /* already reported */
    }
}

static bool parse_object(parser *p)
{
    scene_object o = {.scale = {1.0f, 1.0f, 1.0f}};
    if (!take_object_refs(p, &o))
        return false;
    unsigned seen = 0;
    while (!scene_parser_at_end(p))
        if (!scene_parser_take_placement(p, "object", &o, &seen))
            return false;
    scene_object *grown =
        scene_parser_append(p, p->s.objects, &p->s.object_count, &p->object_cap, &o, sizeof o);
    if (!grown)
        return false;
    p->s.objects = grown;
    scene_parser_start_keys(p, LAST_OBJECT);
    return true;
}

/* falloff hard|windowed: how every light fades to its radius (docs/05_attenuation_radius.md). */
static bool parse_falloff(parser *p)
{
    if (p->falloff_line)
        return scene_parser_fail(p, "falloff: given twice (first on line %d)", p->falloff_line);
    if (scene_parser_at_end(p))
        return scene_parser_fail(p, "falloff: expected hard or windowed");
    const char *kind = p->tok[p->pos++];
    if (strcmp(kind, "hard") == 0)
        p->s.falloff = SHADER_FALLOFF_HARD;
    else if (strcmp(kind, "windowed") == 0)
        p->s.falloff = SHADER_FALLOFF_WINDOWED;
    else
        return scene_parser_fail(p, "falloff: unknown kind '%s' (expected hard or windowed)",
                                 scene_parser_show_token(kind).text);
    if (!scene_parser_expect_end(p, "falloff"))
        return false;
    p->falloff_line = p->line;
    return true;
}

/* probe X Y Z radius R: a light probe (chapter 19), at most SCENE_PROBE_MAX. */
static bool parse_probe(parser *p)
{
    scene_probe probe = {0};
    if (p->s.probe_count >= SCENE_PROBE_MAX)
        return scene_parser_fail(p, "probe: more than %d probes", SCENE_PROBE_MAX);
    if (!scene_parser_take_vec3(p, "probe", NUMBER_ANY, probe.position))
        return false;
    if (scene_parser_at_end(p) || strcmp(p->tok[p->pos], "radius") != 0)
        return scene_parser_fail(p, "probe: expected 'radius R' after the position");
    p->pos++;
    if (!scene_parser_take_number(p, "probe radius", NUMBER_POSITIVE, &probe.radius) ||
        !scene_parser_expect_end(p, "probe"))
        return false;
    scene_parser_start_keys(p, LAST_NONE); /* a probe does not move: no key lines after it */
    scene_probe *grown = scene_parser_append(p, p->s.probes, &p->s.probe_count, &p->probe_cap, &probe, sizeof probe);
    if (!grown)
        return false;
    p->s.probes = grown;
    return true;
}

/* ---- dispatch ---------------------------------------------------------------------------- */

static const struct {
    const char *name;
    bool (*parse)(parser *p);
} DIRECTIVES[] = {
    {"camera", parse_camera}, {"ambient", parse_ambient}, {"material", parse_material}, {"mesh", parse_mesh},
    {"object", parse_object}, {"light", scene_parser_parse_light},
    {"spot", scene_parser_parse_spot},
    {"key", scene_parser_parse_key},
    {"falloff", parse_falloff},
    {"model", scene_parser_parse_model},
    {"probe", parse_probe},
};

/* The line's first token names the directive; its function reads the rest of the line. */
bool scene_parser_run_directive(parser *p)
{
    const char *directive = p->tok[p->pos++];
    for (size_t i = 0; i < sizeof DIRECTIVES / sizeof DIRECTIVES[0]; i++)
        if (strcmp(directive, DIRECTIVES[i].name) == 0)
            return DIRECTIVES[i].parse(p);
    return scene_parser_fail(
        p, "unknown directive '%s' (expected camera, ambient, material, mesh, object, model, light, spot, key, falloff "
           "or probe)",
        scene_parser_show_token(directive).text);
}
