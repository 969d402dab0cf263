/* scene_internal.h - the scene module's inside: the parser state and the helpers its files share (internal:
 * only scene.c, scene_parser.c, scene_directives.c, scene_materials.c, scene_lights.c and scene_model.c
 * include it; everyone else uses scene.h).
 *
 * scene_parser.c:
 *   scene_parser_fail(p, fmt, ...)                       log "NAME:LINE: message"; returns false
 *   scene_parser_show_token(token)                       a token cut to fit in a message
 *   scene_parser_append(p, array, &n, &cap, &e, size)    add e to an array that grows by doubling
 *   scene_parser_find_name(table, list, name)            the slot of a declared name, or NULL
 *   scene_parser_add_name(p, table, name, index)         declare a name on the current line
 *   scene_parser_at_end(p)                               no tokens left on the line
 *   scene_parser_expect_end(p, what)                     fail on a token left over
 *   scene_parser_next_is_number(p)                       the next token is a number (not read)
 *   scene_parser_take_number(p, what, rule, &out)        read a float
 *   scene_parser_take_vec3(p, what, rule, out)           read three floats
 *   scene_parser_take_int(p, what, min, max, &out)       read an int in [min, max]
 *   scene_parser_take_name(p, what, out)                 read a mesh or material name
 *   scene_parser_take_attribute(p, what, names, valid, &seen)
 *                                                        read an attribute name: its index in names
 *   scene_parser_take_switch(p, what, &off)              read `on` or `off` (off sets *off)
 * scene_directives.c:
 *   scene_parser_run_directive(p)                        parse a tokenized line by its directive
 *   scene_parser_resolve_file(p, owner, what, given, out) a model or image path, found, a regular
 *                                                        file and readable
 *   scene_parser_take_placement(p, what, o, &seen)       an object's position, rotate_y, scale or cast
 *   scene_parser_take_opacity(p, &opacity)               a material's opacity, 0 < A <= 1
 * scene_materials.c:
 *   scene_parser_take_pbr(p, m)                          the rest of a `material NAME pbr ...` line
 * scene_model.c:
 *   scene_parser_parse_model(p)                          the model directive: a glTF 2.0 file's content
 * scene_lights.c:
 *   scene_parser_parse_light(p), scene_parser_parse_spot(p), scene_parser_parse_key(p)
 *                                                        the light, spot and key directives
 *   scene_parser_start_keys(p, last)                     the key lines that follow animate `last`
 *
 * A take/expect/add/append/run function that fails (false, NULL or -1) has logged the one
 * message of the parse by then.
 */
#ifndef COMMON_SCENE_INTERNAL_H
#define COMMON_SCENE_INTERNAL_H

#include "log.h"
#include "scene.h"

#include <stddef.h>
#include <stdint.h>

#define SCENE_LINE_MAX 4096                      /* bytes per line, without the line break */
#define SCENE_TOKEN_MAX (SCENE_LINE_MAX / 2 + 1) /* a token and a separator take two bytes */
#define SCENE_SHOW_MAX 48                        /* longest piece of a token quoted in a message */

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
    int mesh_cap, material_cap, object_cap, texture_cap, probe_cap; /* the lights': s.light_capacity */
    name_table mesh_names, material_names;
    int camera_line, ambient_line, falloff_line; /* 0 until given */
    long long texels;              /* of the maps' images so far, each texture once (MODEL_TEXELS_MAX) */
    last_kind last;                /* what a "key" line attaches to */
    int last_key_cap;              /* capacity of that object's or light's key array */
} parser;

/* A token as it appears in a message. */
typedef struct shown {
    char text[SCENE_SHOW_MAX + 4];
} shown;

bool scene_parser_fail(parser *p, const char *fmt, ...) LOG_PRINTF(2, 3);
shown scene_parser_show_token(const char *token);

void *scene_parser_append(parser *p, void *array, int *count, int *capacity, const void *element,
                          size_t size);
const name_slot *scene_parser_find_name(const name_table *t, name_list list, const char *name);
bool scene_parser_add_name(parser *p, name_table *t, const char *name, int index);

bool scene_parser_at_end(const parser *p);
bool scene_parser_expect_end(parser *p, const char *what);
bool scene_parser_next_is_number(const parser *p);
bool scene_parser_take_number(parser *p, const char *what, number_rule rule, float *out);
bool scene_parser_take_vec3(parser *p, const char *what, number_rule rule, vec3 out);
bool scene_parser_take_int(parser *p, const char *what, int min, int max, int *out);
bool scene_parser_take_name(parser *p, const char *what, char out[SCENE_NAME_MAX]);
int scene_parser_take_attribute(parser *p, const char *what, const char *const names[], const char *valid,
                                unsigned *seen);
bool scene_parser_take_switch(parser *p, const char *what, bool *off);

bool scene_parser_run_directive(parser *p);
bool scene_parser_resolve_file(parser *p, const char *owner, const char *what, const char *given,
                               char out[SCENE_PATH_MAX]);
bool scene_parser_take_pbr(parser *p, scene_material *m);
bool scene_parser_take_opacity(parser *p, float *opacity);
bool scene_parser_take_placement(parser *p, const char *what, scene_object *o, unsigned *seen);
bool scene_parser_parse_model(parser *p);
bool scene_parser_parse_light(parser *p);
bool scene_parser_parse_spot(parser *p);
bool scene_parser_parse_key(parser *p);
void scene_parser_start_keys(parser *p, last_kind last);

#endif
