/* scene.c - the text scene parser's line loop and the scene's public functions (scene.h); the
 * format itself is described in docs/scene-format.md.
 *
 * The parser works one line at a time: check the bytes (length, NUL, control bytes, UTF-8),
 * copy the line into a buffer, cut it into tokens, and hand the tokens to the function for
 * the line's directive (scene_directives.c, reading them with scene_parser.c). Every error is
 * reported once, as "PATH:LINE: message", at the place where it is detected; the partly built
 * scene is then freed and the caller's left zeroed.
 */
#include "scene.h"

#include "data_dir.h"
#include "log.h"
#include "scene_internal.h"

#include <assert.h>
#include <errno.h>
#include <limits.h>
#include <locale.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SCENE_FILE_MAX (1L << 30) /* refuse scene files above 1 GiB */

/* Default camera when the file has no camera line; a camera line starts from it too. */
static const scene_camera DEFAULT_CAMERA = {
    .eye = {0.0f, 2.0f, 6.0f},
    .target = {0.0f, 0.0f, 0.0f},
    .up = {0.0f, 1.0f, 0.0f},
    .fovy_deg = 60.0f,
    .near_plane = 0.1f,
    .far_plane = 100.0f,
};

/* ---- lines ------------------------------------------------------------------------------- */

/* Rejects what a text file should not hold, so that tokens are printable UTF-8. */
static bool check_bytes(parser *p, const unsigned char *s, size_t n)
{
    for (size_t i = 0; i < n;) {
        unsigned c = s[i];
        if (c == 0)
            return scene_parser_fail(p, "NUL byte at column %zu (is this a binary file?)", i + 1);
        if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7F)
            return scene_parser_fail(p, "control byte 0x%02X at column %zu", c, i + 1);
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
            return scene_parser_fail(p, "invalid UTF-8 byte 0x%02X at column %zu", c, i + 1);
        if (n - i < len || s[i + 1] < lo || s[i + 1] > hi)
            return scene_parser_fail(p, "invalid UTF-8 sequence at column %zu", i + 1);
        for (size_t k = 2; k < len; k++)
            if ((s[i + k] & 0xC0) != 0x80)
                return scene_parser_fail(p, "invalid UTF-8 sequence at column %zu", i + 1);
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

static bool parse_line(parser *p)
{
    tokenize(p);
    if (p->count == 0)
        return true;
    return scene_parser_run_directive(p);
}

static bool parse_text(parser *p, const char *text, size_t len)
{
    size_t at = 0;
    if (len >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0)
        at = 3; /* a UTF-8 byte order mark some editors write */
    while (at < len) {
        if (p->line == INT_MAX)
            return scene_parser_fail(p, "too many lines");
        p->line++;
        const char *start = text + at;
        const char *newline = memchr(start, '\n', len - at);
        size_t n = newline ? (size_t)(newline - start) : len - at;
        at += n + (newline ? 1 : 0);
        if (n > 0 && start[n - 1] == '\r')
            n--; /* CRLF line ends */
        if (n > SCENE_LINE_MAX)
            return scene_parser_fail(p, "line is longer than %d characters", SCENE_LINE_MAX);
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
    const char *why;
    FILE *f = data_dir_open_input(path, &why); /* a named pipe is refused, not waited on */
    if (!f) {
        log_error("%s: cannot open scene: %s", path, why);
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
    for (int i = 0; i < s->texture_count; i++)
        free(s->textures[i].data);
    free(s->textures);
    free(s->probes);
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
    if (o->has_base)
        glm_mat4_mul(out, (vec4 *)o->base, out);
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
    if (!s->lights || s->light_count >= s->light_capacity) {
        /* doubling: one light at a time made --lights 65536 copy the array 65,536 times */
        int cap = s->light_count < 8 ? 8 : s->light_count <= INT_MAX / 2 ? 2 * s->light_count : INT_MAX;
        scene_light *grown = realloc(s->lights, (size_t)cap * sizeof *grown);
        if (!grown) {
            free(keys);
            log_error("scene_add_light: out of memory for %d lights", cap);
            return false;
        }
        s->lights = grown;
        s->light_capacity = cap;
    }
    s->lights[s->light_count] = copy;
    s->lights[s->light_count].keys = keys;
    s->lights[s->light_count].key_count = keys ? copy.key_count : 0;
    s->light_count++;
    return true;
}
