/* scene_parser.c - the scene parser's messages, growing arrays, name tables and token readers.
 *
 * The readers consume the tokens that scene.c cut from the current line; each one checks what the
 * format asks of its token (docs/scene-format.md) and, when the token does not fit, logs the one
 * "PATH:LINE: message" that the parse reports.
 */
#include "scene_internal.h"

#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- messages ---------------------------------------------------------------------------- */

bool scene_parser_fail(parser *p, const char *fmt, ...)
{
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    log_error("%s:%d: %s", p->name, p->line, msg);
    return false;
}

/* Cut at SCENE_SHOW_MAX bytes on a UTF-8 boundary, so a long token cannot flood the message. */
shown scene_parser_show_token(const char *token)
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

/* Returns the array with `element` added at its end (it doubles when full), or NULL after logging;
 * on NULL the caller's array is untouched and still its to free. */
void *scene_parser_append(parser *p, void *array, int *count, int *capacity, const void *element, size_t size)
{
    if (*count == *capacity) {
        if (*capacity > INT_MAX / 2) {
            scene_parser_fail(p, "too many entries");
            return NULL;
        }
        int cap = *capacity ? *capacity * 2 : 8;
        void *grown = realloc(array, (size_t)cap * size);
        if (!grown) {
            scene_parser_fail(p, "out of memory");
            return NULL;
        }
        *capacity = cap;
        array = grown;
    }
    memcpy((char *)array + (size_t)*count * size, element, size);
    (*count)++;
    return array;
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

const name_slot *scene_parser_find_name(const name_table *t, name_list list, const char *name)
{
    if (t->capacity == 0)
        return NULL;
    uint32_t h = name_hash(name);
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

bool scene_parser_add_name(parser *p, name_table *t, const char *name, int index)
{
    /* Keep the table at most half full so that probe runs stay short. */
    if ((t->count + 1) * 2 > t->capacity) {
        if (t->capacity > INT_MAX / 4)
            return scene_parser_fail(p, "too many names");
        int cap = t->capacity ? t->capacity * 2 : 64;
        name_slot *slots = malloc((size_t)cap * sizeof *slots);
        if (!slots)
            return scene_parser_fail(p, "out of memory");
        for (int i = 0; i < cap; i++)
            slots[i].index = -1;
        for (int i = 0; i < t->capacity; i++)
            if (t->slots[i].index >= 0)
                table_put(slots, cap, t->slots[i]);
        free(t->slots);
        t->slots = slots;
        t->capacity = cap;
    }
    table_put(t->slots, t->capacity, (name_slot){.hash = name_hash(name), .index = index, .line = p->line});
    t->count++;
    return true;
}

/* ---- reading tokens ---------------------------------------------------------------------- */

bool scene_parser_at_end(const parser *p)
{
    return p->pos >= p->count;
}

bool scene_parser_expect_end(parser *p, const char *what)
{
    if (scene_parser_at_end(p))
        return true;
    return scene_parser_fail(p, "%s: unexpected extra token '%s'", what,
                             scene_parser_show_token(p->tok[p->pos]).text);
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

/* For attributes with an optional second form ("scale S" or "scale X Y Z"). */
bool scene_parser_next_is_number(const parser *p)
{
    double unused;
    const char *message;
    return !scene_parser_at_end(p) && number_parse(p->tok[p->pos], &unused, &message);
}

bool scene_parser_take_number(parser *p, const char *what, number_rule rule, float *out)
{
    if (scene_parser_at_end(p))
        return scene_parser_fail(p, "%s: missing number", what);
    const char *token = p->tok[p->pos++];
    double v;
    const char *message;
    if (!number_parse(token, &v, &message))
        return scene_parser_fail(p, "%s: %s, got '%s'", what, message, scene_parser_show_token(token).text);
    if (rule == NUMBER_NON_NEGATIVE && v < 0.0)
        return scene_parser_fail(p, "%s: must be >= 0, got '%s'", what, scene_parser_show_token(token).text);
    if (rule == NUMBER_POSITIVE && !(v > 0.0))
        return scene_parser_fail(p, "%s: must be > 0, got '%s'", what, scene_parser_show_token(token).text);
    *out = (float)v;
    return true;
}

bool scene_parser_take_vec3(parser *p, const char *what, number_rule rule, vec3 out)
{
    for (int i = 0; i < 3; i++) {
        if (scene_parser_at_end(p))
            return scene_parser_fail(p, "%s: expected 3 numbers, got %d", what, i);
        if (!scene_parser_take_number(p, what, rule, &out[i]))
            return false;
    }
    return true;
}

bool scene_parser_take_int(parser *p, const char *what, int min, int max, int *out)
{
    if (scene_parser_at_end(p))
        return scene_parser_fail(p, "%s: missing integer", what);
    const char *token = p->tok[p->pos++];
    char *end;
    errno = 0;
    long v = strtol(token, &end, 10);
    if (end == token || *end != '\0')
        return scene_parser_fail(p, "%s: expected an integer, got '%s'", what,
                                 scene_parser_show_token(token).text);
    if (errno == ERANGE || v < min || v > max)
        return scene_parser_fail(p, "%s: must be between %d and %d, got '%s'", what, min, max,
                                 scene_parser_show_token(token).text);
    *out = (int)v;
    return true;
}

/* Names: letters, digits, '_', '-', '.'; that keeps them printable and free of '#'. */
bool scene_parser_take_name(parser *p, const char *what, char out[SCENE_NAME_MAX])
{
    if (scene_parser_at_end(p))
        return scene_parser_fail(p, "%s: missing name", what);
    const char *token = p->tok[p->pos++];
    size_t n = strlen(token);
    if (n >= SCENE_NAME_MAX)
        return scene_parser_fail(p, "%s: name '%s' is longer than %d characters", what,
                                 scene_parser_show_token(token).text, SCENE_NAME_MAX - 1);
    for (size_t i = 0; i < n; i++) {
        unsigned char c = (unsigned char)token[i];
        bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                  c == '-' || c == '.';
        if (!ok)
            return scene_parser_fail(p, "%s: invalid name '%s' (use letters, digits, '_', '-', '.')", what,
                                     scene_parser_show_token(token).text);
    }
    memcpy(out, token, n + 1);
    return true;
}

/* Reads one of `names` (NULL-terminated; `valid` lists them for the message) and returns its
 * index, or -1 after logging. An attribute may appear once per line: `seen` collects bit 1 << index
 * per attribute read. A number where an attribute should be is one number too many for the
 * attribute before it, and is reported as such rather than as an unknown attribute. */
int scene_parser_take_attribute(parser *p, const char *what, const char *const names[], const char *valid,
                                unsigned *seen)
{
    const char *token = p->tok[p->pos++];
    for (int i = 0; names[i]; i++) {
        if (strcmp(token, names[i]) != 0)
            continue;
        if (*seen & (1u << i)) {
            scene_parser_fail(p, "%s: '%s' given twice", what, token);
            return -1;
        }
        *seen |= 1u << i;
        return i;
    }
    double v;
    const char *message;
    if (number_parse(token, &v, &message))
        scene_parser_fail(p, "%s: unexpected extra token '%s'", what, scene_parser_show_token(token).text);
    else
        scene_parser_fail(p, "%s: unknown attribute '%s' (expected %s)", what,
                          scene_parser_show_token(token).text, valid);
    return -1;
}

bool scene_parser_take_switch(parser *p, const char *what, bool *off)
{
    if (scene_parser_at_end(p))
        return scene_parser_fail(p, "%s: expected on or off", what);
    const char *token = p->tok[p->pos++];
    if (strcmp(token, "on") != 0 && strcmp(token, "off") != 0)
        return scene_parser_fail(p, "%s: expected on or off, got '%s'", what, scene_parser_show_token(token).text);
    *off = strcmp(token, "off") == 0;
    return true;
}
