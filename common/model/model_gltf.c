/* model_gltf.c - model_gltf_check (model_file.h): a glTF 2.0 file (.gltf, or .glb's chunks) read
 * with cJSON and checked before Assimp sees it. Assimp 5.2's glTF reader trusts what the JSON says:
 * it recurses without a limit, checks an accessor's end as offset + 4 x count whatever the element
 * size, and opens whatever file a URI names. Everything it would trust is checked here, in 64-bit
 * arithmetic on whole numbers below 2^53, and Assimp then reads the JSON this file checked, written
 * out again by cJSON (numbers as it read them, no duplicate keys), so the two readers cannot
 * disagree on what the file says. */
#include "model_gltf_internal.h"

#include "data_dir.h"

#include <cjson/cJSON.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- the container: a .glb's header and chunks --------------------------------------------- */

static bool glb_chunks(gltf *g, const char *data, size_t size, const char **json, size_t *json_size)
{
    const unsigned char *d = (const unsigned char *)data;
    if (size < 20 || memcmp(d, "glTF", 4) != 0)
        return model_fail(g->why, g->n, "not a binary glTF: it does not start with 'glTF' and a chunk");
    if (gltf_le32(d + 4) != 2)
        return model_fail(g->why, g->n, "a binary glTF of version %u (the course reads 2 only)",
                          gltf_le32(d + 4));
    if (gltf_le32(d + 8) != size)
        return model_fail(g->why, g->n, "a bad .glb header: it says %u bytes, the file has %zu",
                          gltf_le32(d + 8), size);
    uint32_t length = gltf_le32(d + 12);
    if (memcmp(d + 16, "JSON", 4) != 0)
        return model_fail(g->why, g->n, "a bad .glb chunk: the first chunk is not JSON");
    if (length > size - 20)
        return model_fail(g->why, g->n, "a bad .glb chunk: the JSON chunk says %u bytes, %zu follow it",
                          length, size - 20);
    *json = data + 20, *json_size = length;
    size_t at = 20 + (size_t)length;
    if (at == size)
        return true;
    if (size - at < 8)
        return model_fail(g->why, g->n, "a bad .glb chunk: %zu stray bytes after the JSON chunk", size - at);
    uint32_t bin = gltf_le32(d + at);
    if (memcmp(d + at + 4, "BIN\0", 4) != 0)
        return model_fail(g->why, g->n, "a bad .glb chunk: the second chunk is not BIN");
    if (bin > size - at - 8)
        return model_fail(g->why, g->n, "a bad .glb chunk: the BIN chunk says %u bytes, %zu follow it", bin,
                          size - at - 8);
    g->bin = d + at + 8, g->bin_size = bin, g->has_bin = true;
    return true;
}

/* ---- the JSON: its depth before it is parsed, its keys after ------------------------------- */

/* Brackets counted outside strings: a document nested deeper is refused before cJSON (whose own
 * limit is 1,000 levels of recursion) or Assimp (no limit) descends into it. */
static bool json_depth_ok(gltf *g, const char *p, size_t size)
{
    int depth = 0;
    bool in_string = false;
    for (size_t i = 0; i < size; i++) {
        char c = p[i];
        if (in_string) {
            if (c == '\\')
                i++;
            else if (c == '"')
                in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > MODEL_JSON_DEPTH_MAX)
                return model_fail(g->why, g->n, "its JSON is nested more than %d levels deep",
                                  MODEL_JSON_DEPTH_MAX);
        } else if (c == ']' || c == '}') {
            depth--;
        }
    }
    return true;
}

/* A NUL byte, or the escape that makes one: a C reader's string would end there, a C++ one's not. */
static bool holds_nul(const char *p, size_t size)
{
    for (size_t i = 0; i < size; i++)
        if (p[i] == '\0' || (p[i] == '\\' && size - i >= 6 && memcmp(p + i, "\\u0000", 6) == 0))
            return true;
    return false;
}

/* The byte where `p` stops being UTF-8 (glTF's JSON must be), or `size`: no overlong forms, no
 * surrogates, nothing past U+10FFFF. */
static size_t utf8_end(const unsigned char *p, size_t size)
{
    for (size_t i = 0; i < size;) {
        unsigned c = p[i];
        size_t more = c < 0x80             ? 0
                      : (c & 0xe0) == 0xc0 ? 1
                      : (c & 0xf0) == 0xe0 ? 2
                      : (c & 0xf8) == 0xf0 ? 3
                                           : 4;
        if (more == 4 || i + more >= size) /* a byte no character starts with, or one cut short */
            return i;
        unsigned long code = more == 0 ? c : c & (0x3fu >> more);
        for (size_t k = 1; k <= more; k++) {
            if ((p[i + k] & 0xc0) != 0x80)
                return i;
            code = code << 6 | (p[i + k] & 0x3fu);
        }
        static const unsigned long least[4] = {0, 0x80, 0x800, 0x10000};
        if (code < least[more] || code > 0x10ffff || (code >= 0xd800 && code <= 0xdfff))
            return i;
        i += more + 1;
    }
    return size;
}

static int compare_keys(const void *a, const void *b)
{
    return strcmp((*(cJSON *const *)a)->string, (*(cJSON *const *)b)->string);
}

/* A key twice in one object is refused: cJSON keeps the first, another reader may keep the last. */
static bool keys_unique(gltf *g, const cJSON *item)
{
    long long count = 0;
    for (const cJSON *c = item->child; c; c = c->next)
        count++;
    if (cJSON_IsObject(item) && count > 1) {
        cJSON **keys = malloc((size_t)count * sizeof *keys);
        if (!keys)
            return model_fail(g->why, g->n, "out of memory");
        long long k = 0;
        for (cJSON *c = item->child; c; c = c->next)
            keys[k++] = c;
        qsort(keys, (size_t)count, sizeof *keys, compare_keys);
        const char *twice = NULL;
        for (k = 1; k < count && !twice; k++)
            if (strcmp(keys[k - 1]->string, keys[k]->string) == 0)
                twice = keys[k]->string;
        char quoted[MODEL_QUOTE_MAX + 8];
        if (twice)
            model_quote(twice, quoted, sizeof quoted);
        free(keys);
        if (twice)
            return model_fail(g->why, g->n, "its JSON has the key '%s' twice in one object", quoted);
    }
    for (const cJSON *c = item->child; c; c = c->next)
        if (!keys_unique(g, c)) /* depth is at most MODEL_JSON_DEPTH_MAX (json_depth_ok) */
            return false;
    return true;
}

/* ---- fields ---------------------------------------------------------------------------------- */

/* The index a JSON value holds: a whole number from 0 to count - 1, or -1. The range is checked on
 * the double before it is converted (a conversion out of range is undefined). */
long long gltf_index_of(const cJSON *v, long long count)
{
    double d = v && cJSON_IsNumber(v) ? v->valuedouble : -1.0;
    if (!(d >= 0.0 && d < (double)count) || d != (double)(long long)d)
        return -1;
    return (long long)d;
}

/* A whole number from 0 to hi; `fallback` when the key is absent (-1: it must be there). */
bool gltf_field_whole(gltf *g, const cJSON *obj, const char *key, long long fallback, long long hi,
                      long long *out, const char *what, long long index)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (!v && fallback >= 0)
        return *out = fallback, true;
    double d = v && cJSON_IsNumber(v) ? v->valuedouble : -1.0;
    if (!(d >= 0.0 && d <= (double)GLTF_WHOLE_MAX) || d != (double)(long long)d || (long long)d > hi)
        return model_fail(g->why, g->n, "%s %lld: '%s' %s a whole number from 0 to %lld", what, index, key,
                          v ? "is not" : "is missing; it must be", hi);
    *out = (long long)d;
    return true;
}

/* An index into `list`, or -1 when the key is absent and may be. */
bool gltf_field_index(gltf *g, const cJSON *obj, const char *key, bool required, const gltf_list *list,
                      long long *out, const char *what, long long index)
{
    *out = -1;
    if (!cJSON_GetObjectItemCaseSensitive(obj, key) && !required)
        return true;
    long long k;
    if (!gltf_field_whole(g, obj, key, -1, GLTF_WHOLE_MAX, &k, what, index))
        return false;
    if (k >= list->count)
        return model_fail(g->why, g->n, "%s %lld: '%s' is %lld, and there are %lld", what, index, key, k,
                          list->count);
    return *out = k, true;
}

bool gltf_numbers(gltf *g, const cJSON *obj, const char *key, int count, const char *what, long long index)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (!v)
        return true;
    int k = 0;
    const cJSON *c;
    cJSON_ArrayForEach(c, v)
    {
        if (!cJSON_IsNumber(c) || c->valuedouble * 0.0 != 0.0)
            k = count + 1;
        k++;
    }
    if (!cJSON_IsArray(v) || k != count)
        return model_fail(g->why, g->n, "%s %lld: '%s' is not %d finite numbers", what, index, key, count);
    return true;
}

/* A top-level array as an array of pointers (cJSON's lists are linked: indexing them is linear). */
bool gltf_list_of(gltf *g, const cJSON *parent, const char *key, long long max, gltf_list *out)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(parent, key);
    if (!v)
        return true;
    if (!cJSON_IsArray(v))
        return model_fail(g->why, g->n, "'%s' is not an array", key);
    long long count = 0;
    for (const cJSON *c = v->child; c; c = c->next)
        if (++count > max)
            return model_fail(g->why, g->n, "'%s' has more than %lld entries", key, max);
    if (count && !(out->at = malloc((size_t)count * sizeof *out->at)))
        return model_fail(g->why, g->n, "out of memory");
    out->count = 0;
    for (cJSON *c = v->child; c; c = c->next) {
        if (!cJSON_IsObject(c))
            return model_fail(g->why, g->n, "%s %lld is not an object", key, out->count);
        out->at[out->count++] = c;
    }
    return true;
}

/* ---- files and data URIs --------------------------------------------------------------------- */

/* The bytes a data URI holds: base64 (4 characters for 3 bytes, '=' padding) or plain. */
static long long data_uri_bytes(const char *uri)
{
    const char *comma = strchr(uri, ',');
    if (!comma)
        return -1;
    long long length = (long long)strlen(comma + 1);
    bool base64 = comma - uri >= 7 && memcmp(comma - 7, ";base64", 7) == 0;
    return base64 ? length / 4 * 3 + (length % 4 ? length % 4 - 1 : 0) : length;
}

/* A file a URI names, beside the model: relative, inside the model's folder once `..` and links
 * are resolved, a regular file of at most lim->bytes, all of them together too. */
bool gltf_uri_file(gltf *g, const char *uri, const char *what, long long index, char *path, size_t pn,
                   long long *size)
{
    char quoted[MODEL_QUOTE_MAX + 8], rel[MODEL_PATH_MAX], reason[256];
    model_quote(uri, quoted, sizeof quoted);
    const char *colon = strchr(uri, ':'), *slash = strchr(uri, '/');
    if (!g->siblings)
        return model_fail(g->why, g->n,
                          "%s %lld names the file '%s', and this model is read without the files "
                          "beside it",
                          what, index, quoted);
    if (uri[0] == '/' || uri[0] == '\\' || (colon && (!slash || colon < slash)) ||
        !model_uri_decode(uri, rel, sizeof rel))
        return model_fail(g->why, g->n,
                          "%s %lld: '%s' is not a relative path (files are read from the model's "
                          "folder)",
                          what, index, quoted);
    const char *cut = strrchr(g->name, '/');
    int dir = cut ? (int)(cut - g->name) + 1 : 0;
    if (snprintf(path, pn, "%.*s%s", dir, g->name, rel) >= (int)pn)
        return model_fail(g->why, g->n, "%s %lld: '%s': its path is too long", what, index, quoted);
    if (!model_path_inside(g->name, path, NULL, size, reason, sizeof reason))
        return model_fail(g->why, g->n, "%s %lld: '%s': %s", what, index, quoted, reason);
    g->named_bytes += *size;
    if (*size > g->lim->bytes || g->named_bytes > g->lim->bytes)
        return model_fail(g->why, g->n,
                          "%s %lld: '%s': the files it names hold more than %lld bytes "
                          "(COURSE_MODEL_MAX_BYTES)",
                          what, index, quoted, g->lim->bytes);
    return true;
}

static bool check_buffers(gltf *g)
{
    for (long long i = 0; i < g->buffers.count; i++) {
        const cJSON *b = g->buffers.at[i], *uri = cJSON_GetObjectItemCaseSensitive(b, "uri");
        long long length, have;
        char path[MODEL_PATH_MAX];
        if (!gltf_field_whole(g, b, "byteLength", -1, g->lim->bytes, &length, "buffer", i))
            return false;
        if (uri && !cJSON_IsString(uri))
            return model_fail(g->why, g->n, "buffer %lld: 'uri' is not a string", i);
        if (!uri) {
            if (i != 0 || !g->has_bin)
                return model_fail(g->why, g->n, "buffer %lld has no 'uri' and is not a .glb's BIN chunk", i);
            have = g->bin_size;
        } else if (gltf_is_data_uri(uri->valuestring)) {
            have = data_uri_bytes(uri->valuestring);
        } else if (!gltf_uri_file(g, uri->valuestring, "buffer", i, path, sizeof path, &have)) {
            return false;
        } else if (!(g->files[i] = strdup(path))) {
            return model_fail(g->why, g->n, "out of memory");
        }
        if (have < length)
            return model_fail(g->why, g->n, "buffer %lld says %lld bytes, and its data holds %lld", i, length,
                              have < 0 ? 0 : have);
    }
    return true;
}

static bool check_views(gltf *g)
{
    for (long long i = 0; i < g->views.count; i++) {
        const cJSON *v = g->views.at[i];
        long long buffer, offset, length, stride, size;
        if (!gltf_field_index(g, v, "buffer", true, &g->buffers, &buffer, "bufferView", i) ||
            !gltf_field_whole(g, v, "byteOffset", 0, GLTF_WHOLE_MAX, &offset, "bufferView", i) ||
            !gltf_field_whole(g, v, "byteLength", -1, GLTF_WHOLE_MAX, &length, "bufferView", i) ||
            !gltf_field_whole(g, v, "byteStride", 4, 252, &stride, "bufferView", i) ||
            !gltf_field_whole(g, g->buffers.at[buffer], "byteLength", -1, GLTF_WHOLE_MAX, &size, "buffer",
                              buffer))
            return false;
        if (stride < 4 || stride % 4)
            return model_fail(g->why, g->n,
                              "bufferView %lld: 'byteStride' %lld is not 4 to 252 in steps of 4", i, stride);
        if (length < 1 || offset > size || length > size - offset)
            return model_fail(g->why, g->n,
                              "bufferView %lld: bytes %lld to %lld, past the end of buffer %lld "
                              "(%lld bytes)",
                              i, offset, offset + length, buffer, size);
    }
    return true;
}

/* ---- the whole document ------------------------------------------------------------------------ */

static bool check_document(gltf *g, const cJSON *root)
{
    const cJSON *asset = cJSON_GetObjectItemCaseSensitive(root, "asset"),
                *version = cJSON_GetObjectItemCaseSensitive(asset, "version"),
                *ext = cJSON_GetObjectItemCaseSensitive(root, "extensions"),
                *punctual = cJSON_GetObjectItemCaseSensitive(ext, "KHR_lights_punctual");
    char quoted[MODEL_QUOTE_MAX + 8];
    model_quote(cJSON_IsString(version) ? version->valuestring : "none", quoted, sizeof quoted);
    if (!cJSON_IsObject(root) || !cJSON_IsString(version) || strncmp(version->valuestring, "2.", 2) != 0)
        return model_fail(g->why, g->n, "not a glTF 2.0 file (asset.version '%s'; the course reads 2.0 only)",
                          quoted);
    const struct {
        const char *key;
        gltf_list *list;
        long long max;
    } lists[] = {{"buffers", &g->buffers, GLTF_ITEMS_MAX},     {"bufferViews", &g->views, GLTF_ITEMS_MAX},
                 {"accessors", &g->accessors, GLTF_ITEMS_MAX}, {"meshes", &g->meshes, GLTF_ITEMS_MAX},
                 {"nodes", &g->nodes, MODEL_NODES_MAX},        {"images", &g->images, GLTF_ITEMS_MAX},
                 {"textures", &g->textures, GLTF_ITEMS_MAX},   {"skins", &g->skins, GLTF_ITEMS_MAX},
                 {"scenes", &g->scenes, GLTF_ITEMS_MAX},       {"animations", &g->animations, GLTF_ITEMS_MAX},
                 {"materials", &g->materials, GLTF_ITEMS_MAX}, {"samplers", &g->samplers, GLTF_ITEMS_MAX},
                 {"cameras", &g->cameras, GLTF_ITEMS_MAX}};
    for (size_t i = 0; i < sizeof lists / sizeof lists[0]; i++)
        if (!gltf_list_of(g, root, lists[i].key, lists[i].max, lists[i].list))
            return false;
    if (!gltf_list_of(g, punctual, "lights", MODEL_LIGHTS_MAX, &g->lights))
        return false;
    if (g->buffers.count && (!(g->data = calloc((size_t)g->buffers.count, sizeof *g->data)) ||
                             !(g->files = calloc((size_t)g->buffers.count, sizeof *g->files))))
        return model_fail(g->why, g->n, "out of memory");
    const cJSON *scene = cJSON_GetObjectItemCaseSensitive(root, "scene");
    if (scene && gltf_index_of(scene, g->scenes.count) < 0)
        return model_fail(g->why, g->n, "'scene' is not the index of one of its %lld scenes",
                          g->scenes.count);
    bool ok = check_buffers(g) && check_views(g) && gltf_check_accessors(g) && gltf_check_meshes(g) &&
              gltf_check_nodes(g) && gltf_check_skins_scenes(g) && gltf_check_images(g) &&
              gltf_check_lights(g) && gltf_check_animations(g);
    for (long long i = 0; ok && i < g->materials.count; i++)
        ok = gltf_check_material_textures(g, g->materials.at[i], i);
    if (ok && g->memory > g->lim->memory)
        ok = model_fail(g->why, g->n,
                        "importing it would take about %lld MB, more than the budget of %lld MB "
                        "(COURSE_MODEL_MAX_MB)",
                        g->memory >> 20, g->lim->memory >> 20);
    return ok;
}

static void gltf_free(gltf *g)
{
    gltf_list *lists[] = {&g->buffers,    &g->views,     &g->accessors, &g->meshes, &g->nodes,
                          &g->images,     &g->textures,  &g->skins,     &g->lights, &g->scenes,
                          &g->animations, &g->materials, &g->samplers,  &g->cameras};
    for (size_t i = 0; i < sizeof lists / sizeof lists[0]; i++)
        free(lists[i]->at);
    for (long long i = 0; i < g->buffers.count; i++) {
        free(g->data ? g->data[i] : NULL);
        free(g->files ? g->files[i] : NULL);
    }
    free(g->data);
    free(g->files);
}

/* The checked document as Assimp will read it: the JSON written again, in the .glb's chunks when
 * the file is one (its BIN chunk copied). */
static char *rewrite(const cJSON *root, const gltf *g, bool glb, size_t *size)
{
    char *json = cJSON_PrintUnformatted(root);
    if (!json || !glb) {
        *size = json ? strlen(json) : 0;
        return json;
    }
    size_t length = strlen(json), padded = (length + 3) / 4 * 4;
    size_t bin = g->has_bin ? 8 + ((size_t)g->bin_size + 3) / 4 * 4 : 0;
    *size = 12 + 8 + padded + bin;
    unsigned char *out = calloc(*size, 1);
    if (out) {
        uint32_t words[5] = {0x46546c67u /* glTF */, 2, (uint32_t)*size, (uint32_t)padded,
                             0x4e4f534au /* JSON */};
        for (int w = 0; w < 5; w++)
            for (int b = 0; b < 4; b++)
                out[w * 4 + b] = (unsigned char)(words[w] >> (8 * b));
        memcpy(out + 20, json, length);
        memset(out + 20 + length, ' ', padded - length);
        if (g->has_bin) {
            uint32_t chunk[2] = {(uint32_t)(bin - 8), 0x004e4942u /* BIN */};
            for (int w = 0; w < 2; w++)
                for (int b = 0; b < 4; b++)
                    out[20 + padded + w * 4 + b] = (unsigned char)(chunk[w] >> (8 * b));
            memcpy(out + 28 + padded, g->bin, (size_t)g->bin_size);
        }
    }
    cJSON_free(json);
    return (char *)out;
}

char *model_gltf_check(const char *name, const char *data, size_t size, bool siblings,
                       const model_limits *lim, size_t *out_size, char *why, size_t n)
{
    gltf g = {.name = name, .siblings = siblings, .lim = lim, .why = why, .n = n};
    const char *format = model_format_of(name), *json = data;
    bool glb = format && strcmp(format, "glb") == 0;
    size_t json_size = size;
    if (glb && !glb_chunks(&g, data, size, &json, &json_size))
        return NULL;
    if (!json_depth_ok(&g, json, json_size))
        return NULL;
    if (holds_nul(json, json_size)) {
        model_fail(why, n, "its JSON holds a NUL character");
        return NULL;
    }
    size_t bad = utf8_end((const unsigned char *)json, json_size);
    if (bad < json_size) {
        model_fail(why, n, "its JSON is not UTF-8 (byte %zu of %zu)", bad, json_size);
        return NULL;
    }
    const char *end = NULL;
    cJSON *root = cJSON_ParseWithLengthOpts(json, json_size, &end, false);
    char *out = NULL;
    if (!root)
        model_fail(why, n, "its JSON cannot be read (near byte %td of %zu)", end ? end - json : (ptrdiff_t)0,
                   json_size);
    else if (keys_unique(&g, root) && check_document(&g, root) && !(out = rewrite(root, &g, glb, out_size)))
        model_fail(why, n, "out of memory");
    gltf_free(&g);
    cJSON_Delete(root);
    return out;
}
