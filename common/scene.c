/* scene.c - the text scene parser; the format itself is described in docs/scene-format.md.
 *
 * The parser works one line at a time: check the bytes (length, NUL, control bytes, UTF-8),
 * copy the line into a buffer, cut it into tokens, and hand the tokens to the function for
 * the line's directive. Every error is reported once, as "PATH:LINE: message", at the place
 * where it is detected; the partly built scene is then freed and the caller's left zeroed.
 */
#include "scene.h"

#include "log.h"

#include <assert.h>
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <locale.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define SCENE_LINE_MAX 4096                      /* bytes per line, without the line break */
#define SCENE_TOKEN_MAX (SCENE_LINE_MAX / 2 + 1) /* a token and a separator take two bytes */
#define SCENE_SHOW_MAX 48                        /* longest piece of a token quoted in a message */
#define SCENE_FILE_MAX (1L << 30)                /* refuse scene files above 1 GiB */
#define SCENE_SPHERE_MAX 4096

/* Default camera when the file has no camera line. */
static const scene_camera DEFAULT_CAMERA = {
    .eye = {0.0f, 2.0f, 6.0f},
    .target = {0.0f, 0.0f, 0.0f},
    .up = {0.0f, 1.0f, 0.0f},
    .fovy_deg = 60.0f,
    .near_plane = 0.1f,
    .far_plane = 100.0f,
};

/* What a number must satisfy beyond being finite. */
typedef enum number_rule {
    NUMBER_ANY,
    NUMBER_NON_NEGATIVE, /* >= 0 */
    NUMBER_POSITIVE,     /* > 0 */
} number_rule;

/* Name -> index, open addressing. The names live in the scene's arrays (which move when they
 * grow), so a slot keeps the index and the hash, and the caller says where the names are. */
typedef struct name_slot {
    uint32_t hash;
    int index; /* -1: empty */
    int line;  /* where the name was declared, for the "declared twice" message */
} name_slot;

typedef struct name_table {
    name_slot *slots;
    int capacity; /* a power of two, or 0 */
    int count;
} name_table;

typedef struct name_list {
    const char *first; /* name of element 0 */
    size_t stride;     /* bytes from one element's name to the next */
} name_list;

typedef enum last_kind { LAST_NONE, LAST_OBJECT, LAST_LIGHT } last_kind;

typedef struct parser {
    const char *name;     /* file name used in messages */
    const char *base_dir; /* folder that model paths are relative to ("" = as written) */
    int line;
    char buf[SCENE_LINE_MAX + 1];
    char *tok[SCENE_TOKEN_MAX];
    int count; /* tokens on this line */
    int pos;   /* next token to read */
    scene s;
    int mesh_cap, material_cap, object_cap, light_cap;
    name_table mesh_names, material_names;
    int camera_line, ambient_line; /* 0 until given */
    last_kind last;                /* what a "key" line attaches to */
    int last_key_cap;              /* capacity of that object's or light's key array */
} parser;

/* ---- messages ---------------------------------------------------------------------------- */

static bool fail(parser *p, const char *fmt, ...) LOG_PRINTF(2, 3);

static bool fail(parser *p, const char *fmt, ...)
{
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    log_error("%s:%d: %s", p->name, p->line, msg);
    return false;
}

/* A token as it appears in a message: cut at SCENE_SHOW_MAX bytes on a UTF-8 boundary. */
typedef struct shown {
    char text[SCENE_SHOW_MAX + 4];
} shown;

static shown show(const char *token)
{
    shown out;
    size_t n = strlen(token);
    if (n <= SCENE_SHOW_MAX) {
        memcpy(out.text, token, n + 1);
        return out;
    }
    n = SCENE_SHOW_MAX;
    while (n > 0 && ((unsigned char)token[n] & 0xC0) == 0x80)
        n--; /* do not split a multi-byte character */
    memcpy(out.text, token, n);
    memcpy(out.text + n, "...", 4);
    return out;
}

/* ---- growing arrays and name tables ------------------------------------------------------ */

/* Returns the array with room for one more element (doubling), or NULL after logging. */
static void *grow_array(parser *p, void *array, int count, int *capacity, size_t size)
{
    if (count < *capacity)
        return array;
    if (*capacity > INT_MAX / 2) {
        fail(p, "too many entries");
        return NULL;
    }
    int cap = *capacity ? *capacity * 2 : 8;
    void *grown = realloc(array, (size_t)cap * size);
    if (!grown) {
        fail(p, "out of memory");
        return NULL;
    }
    *capacity = cap;
    return grown;
}

static uint32_t name_hash(const char *name)
{
    uint32_t h = 2166136261u; /* FNV-1a */
    for (const unsigned char *c = (const unsigned char *)name; *c; c++)
        h = (h ^ *c) * 16777619u;
    return h;
}

static const char *name_at(name_list list, int index)
{
    return list.first + (size_t)index * list.stride;
}

/* The slot holding `name`, or NULL. */
static const name_slot *table_find(const name_table *t, name_list list, const char *name, uint32_t h)
{
    if (t->capacity == 0)
        return NULL;
    unsigned mask = (unsigned)t->capacity - 1;
    for (unsigned i = h & mask;; i = (i + 1) & mask) {
        const name_slot *slot = &t->slots[i];
        if (slot->index < 0)
            return NULL;
        if (slot->hash == h && strcmp(name_at(list, slot->index), name) == 0)
            return slot;
    }
}

static void table_put(name_slot *slots, int capacity, name_slot entry)
{
    unsigned mask = (unsigned)capacity - 1;
    unsigned i = entry.hash & mask;
    while (slots[i].index >= 0)
        i = (i + 1) & mask;
    slots[i] = entry;
}

static bool table_add(parser *p, name_table *t, uint32_t h, int index)
{
    /* Keep the table at most half full so that probe runs stay short. */
    if ((t->count + 1) * 2 > t->capacity) {
        if (t->capacity > INT_MAX / 4)
            return fail(p, "too many names");
        int cap = t->capacity ? t->capacity * 2 : 64;
        name_slot *slots = malloc((size_t)cap * sizeof *slots);
        if (!slots)
            return fail(p, "out of memory");
        for (int i = 0; i < cap; i++)
            slots[i].index = -1;
        for (int i = 0; i < t->capacity; i++)
            if (t->slots[i].index >= 0)
                table_put(slots, cap, t->slots[i]);
        free(t->slots);
        t->slots = slots;
        t->capacity = cap;
    }
    table_put(t->slots, t->capacity, (name_slot){.hash = h, .index = index, .line = p->line});
    t->count++;
    return true;
}

static name_list mesh_list(const parser *p)
{
    return (name_list){p->s.meshes ? p->s.meshes[0].name : NULL, sizeof(scene_mesh)};
}

static name_list material_list(const parser *p)
{
    return (name_list){p->s.materials ? p->s.materials[0].name : NULL, sizeof(scene_material)};
}

/* ---- reading tokens ---------------------------------------------------------------------- */

static bool at_end(const parser *p)
{
    return p->pos >= p->count;
}

static bool expect_end(parser *p, const char *what)
{
    if (at_end(p))
        return true;
    return fail(p, "%s: unexpected extra token '%s'", what, show(p->tok[p->pos]).text);
}

/* strtod with every check the format asks for; *message says why it failed. */
static bool number_parse(const char *token, double *out, const char **message)
{
    char *end;
    errno = 0;
    double v = strtod(token, &end);
    if (end == token || *end != '\0') {
        *message = "expected a number";
        return false;
    }
    /* "1e999" overflows a double (ERANGE); "1e39" fits a double but not a float. */
    if (errno == ERANGE && fabs(v) > 1.0) {
        *message = "number out of range";
        return false;
    }
    if (!isfinite(v)) {
        *message = "not a finite number"; /* "nan", "inf", "infinity" */
        return false;
    }
    if (fabs(v) > FLT_MAX) {
        *message = "number out of range";
        return false;
    }
    *out = v; /* underflow (ERANGE with a tiny result) is fine: it is as near zero as a float gets */
    return true;
}

static bool take_number(parser *p, const char *what, number_rule rule, float *out)
{
    if (at_end(p))
        return fail(p, "%s: missing number", what);
    const char *token = p->tok[p->pos++];
    double v;
    const char *message;
    if (!number_parse(token, &v, &message))
        return fail(p, "%s: %s, got '%s'", what, message, show(token).text);
    if (rule == NUMBER_NON_NEGATIVE && v < 0.0)
        return fail(p, "%s: must be >= 0, got '%s'", what, show(token).text);
    if (rule == NUMBER_POSITIVE && !(v > 0.0))
        return fail(p, "%s: must be > 0, got '%s'", what, show(token).text);
    *out = (float)v;
    return true;
}

static bool take_vec3(parser *p, const char *what, number_rule rule, vec3 out)
{
    for (int i = 0; i < 3; i++) {
        if (at_end(p))
            return fail(p, "%s: expected 3 numbers, got %d", what, i);
        if (!take_number(p, what, rule, &out[i]))
            return false;
    }
    return true;
}

static bool take_int(parser *p, const char *what, int min, int max, int *out)
{
    if (at_end(p))
        return fail(p, "%s: missing integer", what);
    const char *token = p->tok[p->pos++];
    char *end;
    errno = 0;
    long v = strtol(token, &end, 10);
    if (end == token || *end != '\0')
        return fail(p, "%s: expected an integer, got '%s'", what, show(token).text);
    if (errno == ERANGE || v < min || v > max)
        return fail(p, "%s: must be between %d and %d, got '%s'", what, min, max, show(token).text);
    *out = (int)v;
    return true;
}

/* Names: letters, digits, '_', '-', '.'; that keeps them printable and free of '#'. */
static bool take_name(parser *p, const char *what, char out[SCENE_NAME_MAX])
{
    if (at_end(p))
        return fail(p, "%s: missing name", what);
    const char *token = p->tok[p->pos++];
    size_t n = strlen(token);
    if (n >= SCENE_NAME_MAX)
        return fail(p, "%s: name '%s' is longer than %d characters", what, show(token).text,
                    SCENE_NAME_MAX - 1);
    for (size_t i = 0; i < n; i++) {
        unsigned char c = (unsigned char)token[i];
        bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                  c == '-' || c == '.';
        if (!ok)
            return fail(p, "%s: invalid name '%s' (use letters, digits, '_', '-', '.')", what,
                        show(token).text);
    }
    memcpy(out, token, n + 1);
    return true;
}

/* An attribute may appear once per line; `seen` collects a bit per attribute. */
static bool first_time(parser *p, const char *what, const char *attribute, unsigned *seen, unsigned bit)
{
    if (*seen & bit)
        return fail(p, "%s: '%s' given twice", what, attribute);
    *seen |= bit;
    return true;
}

/* A token that is not an attribute name: an extra number, or a misspelt attribute. */
static bool bad_attribute(parser *p, const char *what, const char *token, const char *valid)
{
    double v;
    const char *message;
    if (number_parse(token, &v, &message))
        return fail(p, "%s: unexpected extra token '%s'", what, show(token).text);
    return fail(p, "%s: unknown attribute '%s' (expected %s)", what, show(token).text, valid);
}

/* ---- directives -------------------------------------------------------------------------- */

static bool parse_camera(parser *p)
{
    if (p->camera_line)
        return fail(p, "camera: given twice (first on line %d)", p->camera_line);
    scene_camera c = DEFAULT_CAMERA;
    unsigned seen = 0;
    while (!at_end(p)) {
        const char *a = p->tok[p->pos++];
        bool ok;
        if (strcmp(a, "eye") == 0)
            ok = first_time(p, "camera", a, &seen, 1) && take_vec3(p, "camera eye", NUMBER_ANY, c.eye);
        else if (strcmp(a, "target") == 0)
            ok = first_time(p, "camera", a, &seen, 2) && take_vec3(p, "camera target", NUMBER_ANY, c.target);
        else if (strcmp(a, "up") == 0)
            ok = first_time(p, "camera", a, &seen, 4) && take_vec3(p, "camera up", NUMBER_ANY, c.up);
        else if (strcmp(a, "fovy") == 0) {
            ok = first_time(p, "camera", a, &seen, 8) &&
                 take_number(p, "camera fovy", NUMBER_POSITIVE, &c.fovy_deg);
            if (ok && !(c.fovy_deg < 180.0f))
                return fail(p, "camera fovy: must be between 0 and 180 degrees, got '%s'",
                            show(p->tok[p->pos - 1]).text);
        } else if (strcmp(a, "near") == 0)
            ok = first_time(p, "camera", a, &seen, 16) &&
                 take_number(p, "camera near", NUMBER_POSITIVE, &c.near_plane);
        else if (strcmp(a, "far") == 0)
            ok = first_time(p, "camera", a, &seen, 32) &&
                 take_number(p, "camera far", NUMBER_POSITIVE, &c.far_plane);
        else
            return bad_attribute(p, "camera", a, "eye, target, up, fovy, near or far");
        if (!ok)
            return false;
    }
    if (!(seen & 1))
        return fail(p, "camera: missing 'eye X Y Z'");
    if (!(seen & 2))
        return fail(p, "camera: missing 'target X Y Z'");
    if (!(c.far_plane > c.near_plane))
        return fail(p, "camera: far (%g) must be greater than near (%g)", c.far_plane, c.near_plane);
    vec3 view, side;
    glm_vec3_sub(c.target, c.eye, view);
    float view_len = glm_vec3_norm(view);
    if (!(view_len > 1e-6f))
        return fail(p, "camera: eye and target are the same point");
    /* Differences of huge finite coordinates can overflow to inf. */
    if (!isfinite(view_len))
        return fail(p, "camera: eye and target are too far apart");
    glm_vec3_cross(view, c.up, side);
    float up_len = glm_vec3_norm(c.up);
    if (!(glm_vec3_norm(side) > 1e-6f * view_len * up_len) || !isfinite(glm_vec3_norm(side)))
        return fail(p, "camera: up (%g %g %g) is zero or parallel to the view direction", c.up[0], c.up[1],
                    c.up[2]);
    p->s.camera = c;
    p->camera_line = p->line;
    return true;
}

static bool parse_ambient(parser *p)
{
    if (p->ambient_line)
        return fail(p, "ambient: given twice (first on line %d)", p->ambient_line);
    if (!take_vec3(p, "ambient", NUMBER_NON_NEGATIVE, p->s.ambient) || !expect_end(p, "ambient"))
        return false;
    p->ambient_line = p->line;
    return true;
}

static bool parse_material(parser *p)
{
    scene_material m = {.specular = 0.0f, .shininess = 32.0f};
    if (!take_name(p, "material", m.name))
        return false;
    uint32_t h = name_hash(m.name);
    const name_slot *dup = table_find(&p->material_names, material_list(p), m.name, h);
    if (dup)
        return fail(p, "material '%s' is already declared on line %d", m.name, dup->line);
    if (at_end(p))
        return fail(p, "material '%s': missing 'albedo R G B'", m.name);
    if (strcmp(p->tok[p->pos], "albedo") != 0)
        return fail(p, "material '%s': expected 'albedo', got '%s'", m.name, show(p->tok[p->pos]).text);
    p->pos++;
    if (!take_vec3(p, "material albedo", NUMBER_NON_NEGATIVE, m.albedo))
        return false;
    unsigned seen = 0;
    while (!at_end(p)) {
        const char *a = p->tok[p->pos++];
        bool ok;
        if (strcmp(a, "specular") == 0)
            ok = first_time(p, "material", a, &seen, 1) &&
                 take_number(p, "material specular", NUMBER_NON_NEGATIVE, &m.specular);
        else if (strcmp(a, "shininess") == 0)
            ok = first_time(p, "material", a, &seen, 2) &&
                 take_number(p, "material shininess", NUMBER_POSITIVE, &m.shininess);
        else
            return bad_attribute(p, "material", a, "specular or shininess");
        if (!ok)
            return false;
    }
    scene_material *grown =
        grow_array(p, p->s.materials, p->s.material_count, &p->material_cap, sizeof *grown);
    if (!grown)
        return false;
    p->s.materials = grown;
    p->s.materials[p->s.material_count] = m;
    if (!table_add(p, &p->material_names, h, p->s.material_count))
        return false;
    p->s.material_count++;
    return true;
}

/* Model paths are relative to the scene file's folder; absolute paths are kept. */
static bool resolve_model(parser *p, const char *given, char out[SCENE_PATH_MAX])
{
    size_t base = strlen(p->base_dir);
    const char *sep = base > 0 && p->base_dir[base - 1] != '/' ? "/" : "";
    int n = given[0] == '/' || base == 0 ? snprintf(out, SCENE_PATH_MAX, "%s", given)
                                         : snprintf(out, SCENE_PATH_MAX, "%s%s%s", p->base_dir, sep, given);
    if (n < 0 || n >= SCENE_PATH_MAX)
        return fail(p, "model path '%s' is longer than %d characters", show(given).text, SCENE_PATH_MAX - 1);
    /* Only check that the file is there and readable: the mesh loader reads it later. */
    FILE *f = fopen(out, "rb");
    if (!f)
        return fail(p, "cannot open model '%s': %s", out, strerror(errno));
    struct stat st;
    bool regular = fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode);
    fclose(f);
    if (!regular)
        return fail(p, "cannot open model '%s': not a regular file", out);
    return true;
}

static bool parse_mesh(parser *p)
{
    scene_mesh m = {.line = p->line};
    if (!take_name(p, "mesh", m.name))
        return false;
    uint32_t h = name_hash(m.name);
    const name_slot *dup = table_find(&p->mesh_names, mesh_list(p), m.name, h);
    if (dup)
        return fail(p, "mesh '%s' is already declared on line %d", m.name, dup->line);
    if (at_end(p))
        return fail(p, "mesh '%s': missing kind (cube, plane, sphere or file)", m.name);
    const char *kind = p->tok[p->pos++];
    if (strcmp(kind, "cube") == 0) {
        m.kind = SCENE_MESH_CUBE;
    } else if (strcmp(kind, "plane") == 0) {
        m.kind = SCENE_MESH_PLANE;
    } else if (strcmp(kind, "sphere") == 0) {
        m.kind = SCENE_MESH_SPHERE;
        m.slices = 32;
        m.stacks = 16;
        if (!at_end(p) && (!take_int(p, "mesh sphere slices", 3, SCENE_SPHERE_MAX, &m.slices) ||
                           !take_int(p, "mesh sphere stacks", 2, SCENE_SPHERE_MAX, &m.stacks)))
            return false;
    } else if (strcmp(kind, "file") == 0) {
        m.kind = SCENE_MESH_FILE;
        if (at_end(p))
            return fail(p, "mesh '%s': missing model path after 'file'", m.name);
        if (!resolve_model(p, p->tok[p->pos++], m.path))
            return false;
    } else {
        return fail(p, "mesh '%s': unknown kind '%s' (expected cube, plane, sphere or file)", m.name,
                    show(kind).text);
    }
    if (!expect_end(p, "mesh"))
        return false;
    scene_mesh *grown = grow_array(p, p->s.meshes, p->s.mesh_count, &p->mesh_cap, sizeof *grown);
    if (!grown)
        return false;
    p->s.meshes = grown;
    p->s.meshes[p->s.mesh_count] = m;
    if (!table_add(p, &p->mesh_names, h, p->s.mesh_count))
        return false;
    p->s.mesh_count++;
    return true;
}

static bool parse_object(parser *p)
{
    scene_object o = {.scale = {1.0f, 1.0f, 1.0f}};
    char name[SCENE_NAME_MAX];
    if (!take_name(p, "object mesh", name))
        return false;
    const name_slot *mesh = table_find(&p->mesh_names, mesh_list(p), name, name_hash(name));
    if (!mesh)
        return fail(p, "unknown mesh '%s' (declare it with a mesh line first)", name);
    o.mesh = mesh->index;
    if (!take_name(p, "object material", name))
        return false;
    const name_slot *material = table_find(&p->material_names, material_list(p), name, name_hash(name));
    if (!material)
        return fail(p, "unknown material '%s' (declare it with a material line first)", name);
    o.material = material->index;
    unsigned seen = 0;
    while (!at_end(p)) {
        const char *a = p->tok[p->pos++];
        bool ok;
        if (strcmp(a, "position") == 0) {
            ok = first_time(p, "object", a, &seen, 1) &&
                 take_vec3(p, "object position", NUMBER_ANY, o.position);
        } else if (strcmp(a, "rotate_y") == 0) {
            ok = first_time(p, "object", a, &seen, 2) &&
                 take_number(p, "object rotate_y", NUMBER_ANY, &o.rotate_y_deg);
        } else if (strcmp(a, "scale") == 0) {
            /* "scale S" or "scale X Y Z": three numbers in a row mean the second form. */
            ok = first_time(p, "object", a, &seen, 4) &&
                 take_number(p, "object scale", NUMBER_POSITIVE, &o.scale[0]);
            double unused;
            const char *message;
            if (ok && !at_end(p) && number_parse(p->tok[p->pos], &unused, &message))
                ok = take_number(p, "object scale", NUMBER_POSITIVE, &o.scale[1]) &&
                     take_number(p, "object scale", NUMBER_POSITIVE, &o.scale[2]);
            else if (ok)
                o.scale[1] = o.scale[2] = o.scale[0];
        } else {
            return bad_attribute(p, "object", a, "position, rotate_y or scale");
        }
        if (!ok)
            return false;
    }
    scene_object *grown = grow_array(p, p->s.objects, p->s.object_count, &p->object_cap, sizeof *grown);
    if (!grown)
        return false;
    p->s.objects = grown;
    p->s.objects[p->s.object_count++] = o;
    p->last = LAST_OBJECT;
    p->last_key_cap = 0;
    return true;
}

static bool parse_light(parser *p)
{
    scene_light l = {.color = {1.0f, 1.0f, 1.0f}, .intensity = 1.0f, .kc = 1.0f, .kl = 0.14f, .kq = 0.07f};
    unsigned seen = 0;
    while (!at_end(p)) {
        const char *a = p->tok[p->pos++];
        bool ok;
        if (strcmp(a, "position") == 0) {
            ok =
                first_time(p, "light", a, &seen, 1) && take_vec3(p, "light position", NUMBER_ANY, l.position);
        } else if (strcmp(a, "color") == 0) {
            ok = first_time(p, "light", a, &seen, 2) &&
                 take_vec3(p, "light color", NUMBER_NON_NEGATIVE, l.color);
        } else if (strcmp(a, "intensity") == 0) {
            ok = first_time(p, "light", a, &seen, 4) &&
                 take_number(p, "light intensity", NUMBER_NON_NEGATIVE, &l.intensity);
        } else if (strcmp(a, "attenuation") == 0) {
            ok = first_time(p, "light", a, &seen, 8) &&
                 take_number(p, "light attenuation", NUMBER_ANY, &l.kc) &&
                 take_number(p, "light attenuation", NUMBER_NON_NEGATIVE, &l.kl) &&
                 take_number(p, "light attenuation", NUMBER_NON_NEGATIVE, &l.kq);
            /* kc is the whole denominator at distance 0: zero there means infinite light. */
            if (ok && !(l.kc > 0.0f))
                return fail(p,
                            "light attenuation: KC must be > 0 (the light would be infinitely "
                            "bright at its centre), got '%s'",
                            show(p->tok[p->pos - 3]).text);
        } else {
            return bad_attribute(p, "light", a, "position, color, intensity or attenuation");
        }
        if (!ok)
            return false;
    }
    scene_light *grown = grow_array(p, p->s.lights, p->s.light_count, &p->light_cap, sizeof *grown);
    if (!grown)
        return false;
    p->s.lights = grown;
    p->s.lights[p->s.light_count++] = l;
    p->last = LAST_LIGHT;
    p->last_key_cap = 0;
    return true;
}

static bool parse_key(parser *p)
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
        return fail(p, "key: no object or light before it to animate");
    }
    scene_key k;
    if (!take_number(p, "key time", NUMBER_ANY, &k.time))
        return false;
    if (*count > 0 && !(k.time > (*keys)[*count - 1].time))
        return fail(p, "key time '%s' must be greater than the previous key's time (%g)",
                    show(p->tok[p->pos - 1]).text, (*keys)[*count - 1].time);
    if (at_end(p))
        return fail(p, "key: missing 'position X Y Z'");
    if (strcmp(p->tok[p->pos], "position") != 0)
        return fail(p, "key: expected 'position', got '%s'", show(p->tok[p->pos]).text);
    p->pos++;
    if (!take_vec3(p, "key position", NUMBER_ANY, k.position) || !expect_end(p, "key"))
        return false;
    scene_key *grown = grow_array(p, *keys, *count, &p->last_key_cap, sizeof *grown);
    if (!grown)
        return false;
    *keys = grown;
    (*keys)[(*count)++] = k;
    return true;
}

/* ---- lines ------------------------------------------------------------------------------- */

/* Rejects what a text file should not hold, so that tokens are printable UTF-8. */
static bool check_bytes(parser *p, const unsigned char *s, size_t n)
{
    for (size_t i = 0; i < n;) {
        unsigned c = s[i];
        if (c == 0)
            return fail(p, "NUL byte at column %zu (is this a binary file?)", i + 1);
        if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7F)
            return fail(p, "control byte 0x%02X at column %zu", c, i + 1);
        if (c < 0x80) {
            i++;
            continue;
        }
        /* Length of the sequence and the allowed range of its second byte (no overlong forms,
         * no surrogates, nothing above U+10FFFF). */
        size_t len;
        unsigned lo = 0x80, hi = 0xBF;
        if (c >= 0xC2 && c <= 0xDF)
            len = 2;
        else if (c >= 0xE0 && c <= 0xEF)
            len = 3, lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;
        else if (c >= 0xF0 && c <= 0xF4)
            len = 4, lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
        else
            return fail(p, "invalid UTF-8 byte 0x%02X at column %zu", c, i + 1);
        if (n - i < len || s[i + 1] < lo || s[i + 1] > hi)
            return fail(p, "invalid UTF-8 sequence at column %zu", i + 1);
        for (size_t k = 2; k < len; k++)
            if ((s[i + k] & 0xC0) != 0x80)
                return fail(p, "invalid UTF-8 sequence at column %zu", i + 1);
        i += len;
    }
    return true;
}

static void tokenize(parser *p)
{
    p->count = 0;
    p->pos = 0;
    char *c = p->buf;
    for (;;) {
        while (*c == ' ' || *c == '\t' || *c == '\r')
            c++;
        if (*c == '\0' || *c == '#')
            return;
        p->tok[p->count++] = c;
        while (*c != '\0' && *c != ' ' && *c != '\t' && *c != '\r' && *c != '#')
            c++;
        if (*c == '#') { /* a comment glued to a token: the token ends here, and so does the line */
            *c = '\0';
            return;
        }
        if (*c != '\0')
            *c++ = '\0';
    }
}

static const struct {
    const char *name;
    bool (*parse)(parser *p);
} DIRECTIVES[] = {
    {"camera", parse_camera}, {"ambient", parse_ambient}, {"material", parse_material}, {"mesh", parse_mesh},
    {"object", parse_object}, {"light", parse_light},     {"key", parse_key},
};

static bool parse_line(parser *p)
{
    tokenize(p);
    if (p->count == 0)
        return true;
    const char *directive = p->tok[p->pos++];
    for (size_t i = 0; i < sizeof DIRECTIVES / sizeof DIRECTIVES[0]; i++)
        if (strcmp(directive, DIRECTIVES[i].name) == 0)
            return DIRECTIVES[i].parse(p);
    return fail(p, "unknown directive '%s' (expected camera, ambient, material, mesh, object, light or key)",
                show(directive).text);
}

static bool parse_text(parser *p, const char *text, size_t len)
{
    size_t at = 0;
    if (len >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0)
        at = 3; /* a UTF-8 byte order mark some editors write */
    while (at < len) {
        if (p->line == INT_MAX)
            return fail(p, "too many lines");
        p->line++;
        const char *start = text + at;
        const char *newline = memchr(start, '\n', len - at);
        size_t n = newline ? (size_t)(newline - start) : len - at;
        at += n + (newline ? 1 : 0);
        if (n > 0 && start[n - 1] == '\r')
            n--; /* CRLF line ends */
        if (n > SCENE_LINE_MAX)
            return fail(p, "line is longer than %d characters", SCENE_LINE_MAX);
        if (!check_bytes(p, (const unsigned char *)start, n))
            return false;
        memcpy(p->buf, start, n);
        p->buf[n] = '\0';
        if (!parse_line(p))
            return false;
    }
    return true;
}

/* Parses into a heap parser (it holds a line buffer and token table too big for some stacks). */
static bool parse_buffer(const char *text, size_t len, const char *name, const char *base_dir, scene *out)
{
    parser *p = calloc(1, sizeof *p);
    if (!p) {
        log_error("%s: out of memory", name);
        return false;
    }
    p->name = name;
    p->base_dir = base_dir ? base_dir : "";
    p->s.camera = DEFAULT_CAMERA;
    snprintf(p->s.path, sizeof p->s.path, "%s", name);
    /* Numbers always use '.', whatever locale the program has chosen: strtod follows LC_NUMERIC. */
    locale_t c_numeric = newlocale(LC_NUMERIC_MASK, "C", (locale_t)0);
    locale_t previous = c_numeric ? uselocale(c_numeric) : (locale_t)0;
    bool ok = parse_text(p, text, len);
    if (c_numeric) {
        uselocale(previous);
        freelocale(c_numeric);
    }
    free(p->mesh_names.slots);
    free(p->material_names.slots);
    if (ok)
        *out = p->s;
    else
        scene_destroy(&p->s);
    free(p);
    return ok;
}

/* ---- public functions -------------------------------------------------------------------- */

bool scene_parse_string(const char *text, const char *name, const char *base_dir, scene *out)
{
    memset(out, 0, sizeof *out);
    if (!name)
        name = "<string>";
    if (!text) {
        log_error("%s: no scene text", name);
        return false;
    }
    if (strlen(name) >= SCENE_PATH_MAX) {
        log_error("%s: scene name is longer than %d characters", name, SCENE_PATH_MAX - 1);
        return false;
    }
    return parse_buffer(text, strlen(text), name, base_dir, out);
}

bool scene_load(const char *path, scene *out)
{
    memset(out, 0, sizeof *out);
    if (strlen(path) >= SCENE_PATH_MAX) {
        log_error("%s: scene path is longer than %d characters", path, SCENE_PATH_MAX - 1);
        return false;
    }
    FILE *f = fopen(path, "rb");
    if (!f) {
        log_error("%s: cannot open scene: %s", path, strerror(errno));
        return false;
    }
    /* Read the whole file; its size is not trusted (pipes, files that change). */
    size_t len = 0, cap = 1 << 16;
    char *text = malloc(cap);
    bool ok = text != NULL;
    while (ok) {
        if (len == cap) {
            char *grown = cap < (size_t)SCENE_FILE_MAX ? realloc(text, cap * 2) : NULL;
            if (!grown) {
                log_error("%s: scene file is too large (limit %ld bytes)", path, SCENE_FILE_MAX);
                ok = false;
                break;
            }
            text = grown;
            cap *= 2;
        }
        size_t got = fread(text + len, 1, cap - len, f);
        len += got;
        if (got == 0) {
            if (ferror(f)) {
                log_error("%s: cannot read scene: %s", path, strerror(errno));
                ok = false;
            }
            break;
        }
    }
    if (!text)
        log_error("%s: out of memory", path);
    fclose(f);
    if (ok) {
        /* The folder of the scene file, for model paths: "a/b.scene" -> "a", "/b.scene" -> "/". */
        char base[SCENE_PATH_MAX];
        const char *slash = strrchr(path, '/');
        size_t n = slash ? (size_t)(slash - path) : 0;
        if (slash && n == 0)
            n = 1;
        memcpy(base, path, n);
        base[n] = '\0';
        ok = parse_buffer(text, len, path, base, out);
    }
    free(text);
    return ok;
}

void scene_destroy(scene *s)
{
    if (!s)
        return;
    for (int i = 0; i < s->object_count; i++)
        free(s->objects[i].keys);
    for (int i = 0; i < s->light_count; i++)
        free(s->lights[i].keys);
    free(s->meshes);
    free(s->materials);
    free(s->objects);
    free(s->lights);
    memset(s, 0, sizeof *s);
}

/* Linear interpolation between keys, held at the first and last key outside their range. */
static void key_position_at(const scene_key *keys, int count, const float *fallback, float time, vec3 out)
{
    if (count <= 0 || !keys) {
        glm_vec3_copy((float *)fallback, out);
        return;
    }
    const scene_key *first = &keys[0], *last = &keys[count - 1];
    if (isnan(time) || time <= first->time) {
        glm_vec3_copy((float *)first->position, out);
        return;
    }
    if (time >= last->time) {
        glm_vec3_copy((float *)last->position, out);
        return;
    }
    int lo = 0, hi = count - 1; /* keys[lo].time <= time < keys[hi].time */
    while (hi - lo > 1) {
        int mid = lo + (hi - lo) / 2;
        if (keys[mid].time <= time)
            lo = mid;
        else
            hi = mid;
    }
    float a = (time - keys[lo].time) / (keys[hi].time - keys[lo].time);
    glm_vec3_lerp((float *)keys[lo].position, (float *)keys[hi].position, a, out);
}

void scene_object_world_at(const scene *s, int index, float time, mat4 out)
{
    assert(s && index >= 0 && index < s->object_count);
    const scene_object *o = &s->objects[index];
    vec3 position, scale = {o->scale[0], o->scale[1], o->scale[2]};
    key_position_at(o->keys, o->key_count, o->position, time, position);
    mat4 rotated;
    glm_translate_make(out, position);
    glm_rotate_y(out, glm_rad(o->rotate_y_deg), rotated);
    glm_scale_to(rotated, scale, out);
}

void scene_light_position_at(const scene *s, int index, float time, vec3 out)
{
    assert(s && index >= 0 && index < s->light_count);
    const scene_light *l = &s->lights[index];
    key_position_at(l->keys, l->key_count, l->position, time, out);
}

bool scene_add_light(scene *s, const scene_light *light)
{
    if (s->light_count == INT_MAX) {
        log_error("scene_add_light: too many lights");
        return false;
    }
    /* The scene owns its lights' keys, so the new light gets its own copy. */
    scene_key *keys = NULL;
    if (light->key_count > 0 && light->keys) {
        keys = malloc((size_t)light->key_count * sizeof *keys);
        if (!keys) {
            log_error("scene_add_light: out of memory");
            return false;
        }
        memcpy(keys, light->keys, (size_t)light->key_count * sizeof *keys);
    }
    const scene_light copy = *light; /* `light` may point into s->lights, which realloc may move */
    scene_light *grown = realloc(s->lights, ((size_t)s->light_count + 1) * sizeof *grown);
    if (!grown) {
        free(keys);
        log_error("scene_add_light: out of memory");
        return false;
    }
    s->lights = grown;
    s->lights[s->light_count] = copy;
    s->lights[s->light_count].keys = keys;
    s->lights[s->light_count].key_count = keys ? copy.key_count : 0;
    s->light_count++;
    return true;
}
