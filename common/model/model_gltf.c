/* model_gltf.c - model_gltf_check (model_file.h): a glTF 2.0 file (.gltf, or .glb's chunks) read
 * with cJSON and checked before Assimp sees it. Assimp 5.2's glTF reader trusts what the JSON says:
 * it recurses without a limit, checks an accessor's end as offset + 4 x count whatever the element
 * size, and opens whatever file a URI names. Everything it would trust is checked here, in 64-bit
 * arithmetic on whole numbers below 2^53, and Assimp then reads the JSON this file checked, written
 * out again by cJSON (numbers as it read them, no duplicate keys), so the two readers cannot
 * disagree on what the file says. */
#include "model_file.h"

#include "data_dir.h"

#include <cjson/cJSON.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define GLTF_ITEMS_MAX 65536      /* entries of any one top-level array (buffers, accessors, ...) */
#define GLTF_PRIMITIVES_MAX 65536 /* primitives of all meshes together */
#define GLTF_WHOLE_MAX 9007199254740991LL /* 2^53 - 1: every whole number a double holds exactly */

typedef struct gltf_list {
    cJSON **at;
    long long count;
} gltf_list;

typedef struct gltf {
    const char *name;                 /* the model file */
    bool siblings;                    /* files it names may be read */
    const model_limits *lim;
    const unsigned char *bin;         /* a .glb's BIN chunk */
    long long bin_size;
    bool has_bin;
    gltf_list buffers, views, accessors, meshes, nodes, images, textures, skins, lights, scenes,
        animations, materials, samplers, cameras;
    unsigned char **data;            /* per buffer, decoded when a sparse accessor's indices are read */
    char **files;                    /* per buffer, the file its URI names, resolved by check_buffers */
    long long named_bytes;           /* of the files it names, together */
    long long vertices, faces, memory;
    char *why;
    size_t n;
} gltf;

/* ---- the container: a .glb's header and chunks --------------------------------------------- */

static uint32_t le32(const unsigned char *p) { return p[0] | p[1] << 8 | p[2] << 16 | (uint32_t)p[3] << 24; }

static bool glb_chunks(gltf *g, const char *data, size_t size, const char **json, size_t *json_size)
{
    const unsigned char *d = (const unsigned char *)data;
    if (size < 20 || memcmp(d, "glTF", 4) != 0)
        return model_fail(g->why, g->n, "not a binary glTF: it does not start with 'glTF' and a chunk");
    if (le32(d + 4) != 2)
        return model_fail(g->why, g->n, "a binary glTF of version %u (the course reads 2 only)", le32(d + 4));
    if (le32(d + 8) != size)
        return model_fail(g->why, g->n, "a bad .glb header: it says %u bytes, the file has %zu", le32(d + 8), size);
    uint32_t length = le32(d + 12);
    if (memcmp(d + 16, "JSON", 4) != 0)
        return model_fail(g->why, g->n, "a bad .glb chunk: the first chunk is not JSON");
    if (length > size - 20)
        return model_fail(g->why, g->n, "a bad .glb chunk: the JSON chunk says %u bytes, %zu follow it", length,
                          size - 20);
    *json = data + 20, *json_size = length;
    size_t at = 20 + (size_t)length;
    if (at == size)
        return true;
    if (size - at < 8)
        return model_fail(g->why, g->n, "a bad .glb chunk: %zu stray bytes after the JSON chunk", size - at);
    uint32_t bin = le32(d + at);
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
                return model_fail(g->why, g->n, "its JSON is nested more than %d levels deep", MODEL_JSON_DEPTH_MAX);
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
        size_t more = c < 0x80 ? 0 : (c & 0xe0) == 0xc0 ? 1 : (c & 0xf0) == 0xe0 ? 2 : (c & 0xf8) == 0xf0 ? 3 : 4;
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
static long long index_of(const cJSON *v, long long count)
{
    double d = v && cJSON_IsNumber(v) ? v->valuedouble : -1.0;
    if (!(d >= 0.0 && d < (double)count) || d != (double)(long long)d)
        return -1;
    return (long long)d;
}

/* A whole number from 0 to hi; `fallback` when the key is absent (-1: it must be there). */
static bool field_whole(gltf *g, const cJSON *obj, const char *key, long long fallback, long long hi,
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
static bool field_index(gltf *g, const cJSON *obj, const char *key, bool required, const gltf_list *list,
                        long long *out, const char *what, long long index)
{
    *out = -1;
    if (!cJSON_GetObjectItemCaseSensitive(obj, key) && !required)
        return true;
    long long k;
    if (!field_whole(g, obj, key, -1, GLTF_WHOLE_MAX, &k, what, index))
        return false;
    if (k >= list->count)
        return model_fail(g->why, g->n, "%s %lld: '%s' is %lld, and there are %lld", what, index, key, k,
                          list->count);
    return *out = k, true;
}

static bool numbers(gltf *g, const cJSON *obj, const char *key, int count, const char *what, long long index)
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
static bool list_of(gltf *g, const cJSON *parent, const char *key, long long max, gltf_list *out)
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

static bool is_data_uri(const char *uri) { return strncmp(uri, "data:", 5) == 0; }

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
static bool uri_file(gltf *g, const char *uri, const char *what, long long index, char *path, size_t pn,
                     long long *size)
{
    char quoted[MODEL_QUOTE_MAX + 8], rel[MODEL_PATH_MAX], reason[256];
    model_quote(uri, quoted, sizeof quoted);
    const char *colon = strchr(uri, ':'), *slash = strchr(uri, '/');
    if (!g->siblings)
        return model_fail(g->why, g->n, "%s %lld names the file '%s', and this model is read without the files "
                          "beside it", what, index, quoted);
    if (uri[0] == '/' || uri[0] == '\\' || (colon && (!slash || colon < slash)) || !model_uri_decode(uri, rel, sizeof rel))
        return model_fail(g->why, g->n, "%s %lld: '%s' is not a relative path (files are read from the model's "
                          "folder)", what, index, quoted);
    const char *cut = strrchr(g->name, '/');
    int dir = cut ? (int)(cut - g->name) + 1 : 0;
    if (snprintf(path, pn, "%.*s%s", dir, g->name, rel) >= (int)pn)
        return model_fail(g->why, g->n, "%s %lld: '%s': its path is too long", what, index, quoted);
    if (!model_path_inside(g->name, path, size, reason, sizeof reason))
        return model_fail(g->why, g->n, "%s %lld: '%s': %s", what, index, quoted, reason);
    g->named_bytes += *size;
    if (*size > g->lim->bytes || g->named_bytes > g->lim->bytes)
        return model_fail(g->why, g->n, "%s %lld: '%s': the files it names hold more than %lld bytes "
                          "(COURSE_MODEL_MAX_BYTES)", what, index, quoted, g->lim->bytes);
    return true;
}

static bool check_buffers(gltf *g)
{
    for (long long i = 0; i < g->buffers.count; i++) {
        const cJSON *b = g->buffers.at[i], *uri = cJSON_GetObjectItemCaseSensitive(b, "uri");
        long long length, have;
        char path[MODEL_PATH_MAX];
        if (!field_whole(g, b, "byteLength", -1, g->lim->bytes, &length, "buffer", i))
            return false;
        if (uri && !cJSON_IsString(uri))
            return model_fail(g->why, g->n, "buffer %lld: 'uri' is not a string", i);
        if (!uri) {
            if (i != 0 || !g->has_bin)
                return model_fail(g->why, g->n, "buffer %lld has no 'uri' and is not a .glb's BIN chunk", i);
            have = g->bin_size;
        } else if (is_data_uri(uri->valuestring)) {
            have = data_uri_bytes(uri->valuestring);
        } else if (!uri_file(g, uri->valuestring, "buffer", i, path, sizeof path, &have)) {
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
        if (!field_index(g, v, "buffer", true, &g->buffers, &buffer, "bufferView", i) ||
            !field_whole(g, v, "byteOffset", 0, GLTF_WHOLE_MAX, &offset, "bufferView", i) ||
            !field_whole(g, v, "byteLength", -1, GLTF_WHOLE_MAX, &length, "bufferView", i) ||
            !field_whole(g, v, "byteStride", 4, 252, &stride, "bufferView", i) ||
            !field_whole(g, g->buffers.at[buffer], "byteLength", -1, GLTF_WHOLE_MAX, &size, "buffer", buffer))
            return false;
        if (stride < 4 || stride % 4)
            return model_fail(g->why, g->n, "bufferView %lld: 'byteStride' %lld is not 4 to 252 in steps of 4", i,
                              stride);
        if (length < 1 || offset > size || length > size - offset)
            return model_fail(g->why, g->n, "bufferView %lld: bytes %lld to %lld, past the end of buffer %lld "
                              "(%lld bytes)", i, offset, offset + length, buffer, size);
    }
    return true;
}

/* ---- accessors ------------------------------------------------------------------------------- */

static int component_size(long long type)
{
    switch (type) {
    case 5120: case 5121: return 1;
    case 5122: case 5123: return 2;
    case 5125: case 5126: return 4;
    default: return 0;
    }
}

/* Bytes of one element, matrix columns padded to 4 bytes as the specification lays them out. */
static long long element_size(const char *type, int component)
{
    static const struct { const char *name; int rows, columns; } types[] = {
        {"SCALAR", 1, 1}, {"VEC2", 2, 1}, {"VEC3", 3, 1}, {"VEC4", 4, 1}, {"MAT2", 2, 2}, {"MAT3", 3, 3},
        {"MAT4", 4, 4}};
    for (size_t i = 0; i < sizeof types / sizeof types[0]; i++)
        if (strcmp(type, types[i].name) == 0) {
            long long column = (long long)types[i].rows * component;
            if (types[i].columns > 1)
                column = (column + 3) / 4 * 4;
            return column * types[i].columns;
        }
    return 0;
}

static int base64_value(char c)
{
    const char *alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const char *at = c ? strchr(alphabet, c) : NULL;
    return at ? (int)(at - alphabet) : -1;
}

/* A buffer's bytes, for what must be read to be checked (sparse indices): the BIN chunk, a data
 * URI decoded, or the file read whole; kept until the check ends. NULL with *why. */
static const unsigned char *buffer_data(gltf *g, long long i)
{
    if (g->data[i])
        return g->data[i];
    const cJSON *uri = cJSON_GetObjectItemCaseSensitive(g->buffers.at[i], "uri");
    if (!uri)
        return g->bin;
    long long length;
    field_whole(g, g->buffers.at[i], "byteLength", -1, GLTF_WHOLE_MAX, &length, "buffer", i);
    unsigned char *out = g->data[i] = calloc((size_t)length, 1);
    if (!out)
        return model_fail(g->why, g->n, "out of memory"), NULL;
    const char *s = uri->valuestring;
    if (is_data_uri(s)) {
        const char *comma = strchr(s, ',') + 1;
        bool base64 = comma - s >= 8 && memcmp(comma - 8, ";base64", 7) == 0;
        long long k = 0;
        for (unsigned bits = 0, have = 0; *comma && *comma != '=' && k < length; comma++) {
            int v = base64 ? base64_value(*comma) : (unsigned char)*comma;
            if (v < 0)
                return model_fail(g->why, g->n, "buffer %lld: its data URI is not base64", i), NULL;
            bits = base64 ? (bits << 6 | (unsigned)v) : (unsigned)v, have += base64 ? 6 : 8;
            if (have >= 8)
                out[k++] = (unsigned char)(bits >> (have - 8)), have -= 8;
        }
        return out;
    }
    const char *refused = "cannot be read";
    FILE *f = data_dir_open_input(g->files[i], &refused); /* the file check_buffers resolved and counted */
    if (!f || fread(out, 1, (size_t)length, f) != (size_t)length) {
        if (f)
            fclose(f);
        return model_fail(g->why, g->n, "buffer %lld: its file %s", i, f ? "cannot be read" : refused), NULL;
    }
    fclose(f);
    return out;
}

/* A view's range for `count` items of `size` bytes, `stride` apart, from `offset`: inside it. */
static bool view_holds(gltf *g, long long view, long long offset, long long count, long long size,
                       long long stride, const char *what, long long index)
{
    long long length;
    field_whole(g, g->views.at[view], "byteLength", -1, GLTF_WHOLE_MAX, &length, "bufferView", view);
    /* count <= 2^28 and stride <= 252 (check_accessors): the product cannot overflow */
    long long end = offset + stride * (count - 1) + size;
    if (end > length)
        return model_fail(g->why, g->n, "%s %lld: %lld items of %lld bytes, %lld apart from byte %lld, end at "
                          "byte %lld of bufferView %lld's %lld", what, index, count, size, stride, offset, end,
                          view, length);
    return true;
}

static bool check_sparse(gltf *g, const cJSON *sparse, long long i, long long count, long long size)
{
    const cJSON *ix = cJSON_GetObjectItemCaseSensitive(sparse, "indices"),
                *values = cJSON_GetObjectItemCaseSensitive(sparse, "values");
    long long k, iview, ioffset, itype, vview, voffset, start, vstride;
    if (!cJSON_IsObject(ix) || !cJSON_IsObject(values))
        return model_fail(g->why, g->n, "accessor %lld: a sparse part without 'indices' and 'values'", i);
    if (!field_whole(g, sparse, "count", -1, count, &k, "accessor (sparse)", i) ||
        !field_index(g, ix, "bufferView", true, &g->views, &iview, "accessor (sparse indices)", i) ||
        !field_whole(g, ix, "byteOffset", 0, GLTF_WHOLE_MAX, &ioffset, "accessor (sparse indices)", i) ||
        !field_whole(g, ix, "componentType", -1, 5125, &itype, "accessor (sparse indices)", i) ||
        !field_index(g, values, "bufferView", true, &g->views, &vview, "accessor (sparse values)", i) ||
        !field_whole(g, values, "byteOffset", 0, GLTF_WHOLE_MAX, &voffset, "accessor (sparse values)", i) ||
        !field_whole(g, g->views.at[iview], "byteOffset", 0, GLTF_WHOLE_MAX, &start, "bufferView", iview) ||
        !field_whole(g, g->views.at[vview], "byteStride", size, 252, &vstride, "bufferView", vview))
        return false;
    int isize = itype == 5121 || itype == 5123 || itype == 5125 ? component_size(itype) : 0;
    if (k < 1 || !isize)
        return model_fail(g->why, g->n, "accessor %lld: a sparse part of no entries or of indices that are not "
                          "unsigned", i);
    if (!view_holds(g, iview, ioffset, k, isize, isize, "accessor (sparse indices)", i) ||
        !view_holds(g, vview, voffset, k, size, vstride, "accessor (sparse values)", i))
        return false;
    long long buffer;
    field_whole(g, g->views.at[iview], "buffer", -1, GLTF_WHOLE_MAX, &buffer, "bufferView", iview);
    const unsigned char *d = buffer_data(g, buffer);
    if (!d)
        return false;
    /* Each index names an element of the accessor: where Assimp writes that value. */
    for (long long e = 0; e < k; e++) {
        const unsigned char *p = d + start + ioffset + e * isize;
        long long at = isize == 1 ? p[0] : isize == 2 ? (p[0] | p[1] << 8) : (long long)le32(p);
        if (at >= count)
            return model_fail(g->why, g->n, "accessor %lld: sparse index %lld is %lld, past its %lld elements", i,
                              e, at, count);
    }
    return true;
}

static bool check_accessors(gltf *g)
{
    long long count_max = 3 * (g->lim->faces > g->lim->vertices ? g->lim->faces : g->lim->vertices);
    if (count_max > (1LL << 26) * 4)
        count_max = (1LL << 26) * 4;
    for (long long i = 0; i < g->accessors.count; i++) {
        const cJSON *a = g->accessors.at[i], *type = cJSON_GetObjectItemCaseSensitive(a, "type"),
                    *sparse = cJSON_GetObjectItemCaseSensitive(a, "sparse");
        long long ctype, count, view, offset, stride;
        if (!field_whole(g, a, "componentType", -1, 5126, &ctype, "accessor", i) ||
            !field_whole(g, a, "count", -1, count_max, &count, "accessor", i) ||
            !field_index(g, a, "bufferView", false, &g->views, &view, "accessor", i) ||
            !field_whole(g, a, "byteOffset", 0, GLTF_WHOLE_MAX, &offset, "accessor", i))
            return false;
        long long size = element_size(cJSON_IsString(type) ? type->valuestring : "", component_size(ctype));
        if (!size || count < 1)
            return model_fail(g->why, g->n, "accessor %lld: no elements, or a 'type' or 'componentType' that glTF "
                              "2.0 does not have", i);
        if (view < 0 && count * size > g->lim->bytes)
            return model_fail(g->why, g->n, "accessor %lld: %lld elements of %lld bytes, more than %lld bytes "
                              "(COURSE_MODEL_MAX_BYTES)", i, count, size, g->lim->bytes);
        if (view >= 0) {
            if (!field_whole(g, g->views.at[view], "byteStride", size, 252, &stride, "bufferView", view))
                return false;
            if (stride < size)
                return model_fail(g->why, g->n, "accessor %lld: elements of %lld bytes, %lld apart in bufferView "
                                  "%lld", i, size, stride, view);
            if (!view_holds(g, view, offset, count, size, stride, "accessor", i))
                return false;
        }
        if (sparse && !check_sparse(g, sparse, i, count, size))
            return false;
    }
    return true;
}

/* ---- meshes: what Assimp will make of them ----------------------------------------------------- */

static bool check_attributes(gltf *g, const cJSON *attributes, long long mesh, long long *vertices)
{
    const cJSON *a;
    *vertices = 0;
    if (!cJSON_IsObject(attributes))
        return model_fail(g->why, g->n, "mesh %lld: a primitive without an 'attributes' object", mesh);
    cJSON_ArrayForEach(a, attributes)
    {
        long long k = index_of(a, g->accessors.count);
        if (k < 0)
            return model_fail(g->why, g->n, "mesh %lld: attribute '%.40s' names no accessor", mesh, a->string);
        long long count;
        field_whole(g, g->accessors.at[k], "count", -1, GLTF_WHOLE_MAX, &count, "accessor", k);
        if (*vertices && count != *vertices)
            return model_fail(g->why, g->n, "mesh %lld: its attributes have different counts (%lld, %lld)", mesh,
                              *vertices, count);
        *vertices = count;
    }
    return true;
}

static bool check_primitive(gltf *g, const cJSON *p, long long mesh)
{
    long long vertices, indices, mode, count;
    if (!check_attributes(g, cJSON_GetObjectItemCaseSensitive(p, "attributes"), mesh, &vertices) ||
        !field_index(g, p, "indices", false, &g->accessors, &indices, "mesh", mesh) ||
        !field_whole(g, p, "mode", 4, 6, &mode, "mesh", mesh) ||
        !field_index(g, p, "material", false, &g->materials, &count, "mesh", mesh))
        return false;
    const cJSON *targets = cJSON_GetObjectItemCaseSensitive(p, "targets"), *t;
    cJSON_ArrayForEach(t, targets)
    {
        long long target_vertices;
        if (!check_attributes(g, t, mesh, &target_vertices))
            return false;
        if (target_vertices && target_vertices != vertices)
            return model_fail(g->why, g->n, "mesh %lld: a morph target of %lld vertices, the primitive has %lld",
                              mesh, target_vertices, vertices);
        g->memory += vertices * MODEL_BYTES_PER_VERTEX;
    }
    count = vertices;
    if (indices >= 0) {
        const cJSON *a = g->accessors.at[indices], *type = cJSON_GetObjectItemCaseSensitive(a, "type");
        long long ctype;
        field_whole(g, a, "componentType", -1, GLTF_WHOLE_MAX, &ctype, "accessor", indices);
        if (!cJSON_IsString(type) || strcmp(type->valuestring, "SCALAR") != 0 ||
            (ctype != 5121 && ctype != 5123 && ctype != 5125))
            return model_fail(g->why, g->n, "mesh %lld: its indices (accessor %lld) are not unsigned scalars", mesh,
                              indices);
        field_whole(g, a, "count", -1, GLTF_WHOLE_MAX, &count, "accessor", indices);
    }
    long long faces = mode == 4 ? count / 3 : mode >= 5 ? (count > 2 ? count - 2 : 0) : count;
    g->vertices += vertices, g->faces += faces;
    g->memory += vertices * MODEL_BYTES_PER_VERTEX + faces * MODEL_BYTES_PER_FACE;
    return true;
}

static bool check_meshes(gltf *g)
{
    long long primitives = 0;
    for (long long i = 0; i < g->meshes.count; i++) {
        const cJSON *list = cJSON_GetObjectItemCaseSensitive(g->meshes.at[i], "primitives"), *p;
        if (!cJSON_IsArray(list) || !list->child)
            return model_fail(g->why, g->n, "mesh %lld has no 'primitives' array", i);
        cJSON_ArrayForEach(p, list)
        {
            if (++primitives > GLTF_PRIMITIVES_MAX)
                return model_fail(g->why, g->n, "its meshes hold more than %d primitives", GLTF_PRIMITIVES_MAX);
            if (!cJSON_IsObject(p) || !check_primitive(g, p, i))
                return cJSON_IsObject(p) ? false : model_fail(g->why, g->n, "mesh %lld: a primitive that is not "
                                                              "an object", i);
        }
    }
    if (g->vertices > g->lim->vertices || g->faces > g->lim->faces)
        return model_fail(g->why, g->n, "its meshes declare %lld vertices and %lld faces, more than the limits of "
                          "%ld and %ld (COURSE_MODEL_MAX_VERTICES, COURSE_MODEL_MAX_FACES)", g->vertices, g->faces,
                          g->lim->vertices, g->lim->faces);
    return true;
}

/* ---- nodes, scenes and skins ------------------------------------------------------------------- */

static bool check_node(gltf *g, long long i, long long *parent)
{
    const cJSON *node = g->nodes.at[i], *children = cJSON_GetObjectItemCaseSensitive(node, "children"), *c;
    const cJSON *ext = cJSON_GetObjectItemCaseSensitive(node, "extensions");
    const cJSON *light = cJSON_GetObjectItemCaseSensitive(ext, "KHR_lights_punctual");
    long long k;
    if (!field_index(g, node, "mesh", false, &g->meshes, &k, "node", i) ||
        !field_index(g, node, "skin", false, &g->skins, &k, "node", i) ||
        !field_index(g, node, "camera", false, &g->cameras, &k, "node", i) ||
        (light && !field_index(g, light, "light", true, &g->lights, &k, "node", i)) ||
        !numbers(g, node, "matrix", 16, "node", i) || !numbers(g, node, "translation", 3, "node", i) ||
        !numbers(g, node, "rotation", 4, "node", i) || !numbers(g, node, "scale", 3, "node", i))
        return false;
    if (children && !cJSON_IsArray(children))
        return model_fail(g->why, g->n, "node %lld: 'children' is not an array", i);
    cJSON_ArrayForEach(c, children)
    {
        k = index_of(c, g->nodes.count);
        if (k < 0)
            return model_fail(g->why, g->n, "node %lld: a child that names no node", i);
        if (parent[k] >= 0 || k == i)
            return model_fail(g->why, g->n, "node %lld is a child twice, or its own (nodes form a tree)", k);
        parent[k] = i;
    }
    return true;
}

/* Each node's depth from its parents, walked up: a node deeper than MODEL_DEPTH_MAX, or on a cycle,
 * is refused without recursion (Assimp's own recursion overflows the stack near 17,500 levels). */
static bool check_nodes(gltf *g)
{
    long long *parent = malloc(((size_t)g->nodes.count + 1) * sizeof *parent);
    if (!parent)
        return model_fail(g->why, g->n, "out of memory");
    for (long long i = 0; i < g->nodes.count; i++)
        parent[i] = -1;
    bool ok = true;
    for (long long i = 0; ok && i < g->nodes.count; i++)
        ok = check_node(g, i, parent);
    for (long long i = 0; ok && i < g->nodes.count; i++) {
        long long depth = 0, k = i;
        while (parent[k] >= 0 && depth <= MODEL_DEPTH_MAX)
            k = parent[k], depth++;
        if (depth <= MODEL_DEPTH_MAX)
            continue;
        while (parent[k] >= 0 && depth <= g->nodes.count) /* a chain longer than the nodes is a loop */
            k = parent[k], depth++;
        ok = depth > g->nodes.count
                 ? model_fail(g->why, g->n, "its nodes form a cycle (node %lld is its own ancestor)", k)
                 : model_fail(g->why, g->n, "its nodes are nested more than %d deep", MODEL_DEPTH_MAX);
    }
    free(parent);
    return ok;
}

static bool index_array(gltf *g, const cJSON *obj, const char *key, const gltf_list *list, const char *what,
                        long long i, long long *count)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, key), *c;
    *count = 0;
    if (v && !cJSON_IsArray(v))
        return model_fail(g->why, g->n, "%s %lld: '%s' is not an array", what, i, key);
    cJSON_ArrayForEach(c, v)
    {
        long long k = index_of(c, list->count);
        if (k < 0)
            return model_fail(g->why, g->n, "%s %lld: '%s' holds an index that names nothing", what, i, key);
        (*count)++;
    }
    return true;
}

static bool check_skins_scenes(gltf *g)
{
    long long k, joints, matrices;
    for (long long i = 0; i < g->skins.count; i++) {
        const cJSON *s = g->skins.at[i];
        if (!index_array(g, s, "joints", &g->nodes, "skin", i, &joints) ||
            !field_index(g, s, "skeleton", false, &g->nodes, &k, "skin", i) ||
            !field_index(g, s, "inverseBindMatrices", false, &g->accessors, &k, "skin", i))
            return false;
        if (k < 0) /* optional in glTF, but Assimp 5.2 reads them through a null pointer when absent */
            return model_fail(g->why, g->n, "skin %lld has no inverseBindMatrices (Assimp 5.2 cannot read a skin "
                              "without them)", i);
        const cJSON *a = g->accessors.at[k], *type = cJSON_GetObjectItemCaseSensitive(a, "type");
        long long ctype;
        field_whole(g, a, "componentType", -1, GLTF_WHOLE_MAX, &ctype, "accessor", k);
        field_whole(g, a, "count", -1, GLTF_WHOLE_MAX, &matrices, "accessor", k);
        if (!cJSON_IsString(type) || strcmp(type->valuestring, "MAT4") != 0 || ctype != 5126 || matrices < joints)
            return model_fail(g->why, g->n, "skin %lld: its inverseBindMatrices (accessor %lld) are not %lld float "
                              "4x4 matrices", i, k, joints);
    }
    for (long long i = 0; i < g->scenes.count; i++)
        if (!index_array(g, g->scenes.at[i], "nodes", &g->nodes, "scene", i, &k))
            return false;
    return true;
}

/* ---- images, textures, materials, lights, animations ------------------------------------------ */

static bool check_images(gltf *g)
{
    for (long long i = 0; i < g->images.count; i++) {
        const cJSON *im = g->images.at[i], *uri = cJSON_GetObjectItemCaseSensitive(im, "uri");
        long long view, size;
        char path[MODEL_PATH_MAX];
        if (!field_index(g, im, "bufferView", false, &g->views, &view, "image", i))
            return false;
        if ((uri != NULL) == (view >= 0) || (uri && !cJSON_IsString(uri)))
            return model_fail(g->why, g->n, "image %lld has not exactly one of 'uri' and 'bufferView'", i);
        if (uri && !is_data_uri(uri->valuestring) &&
            !uri_file(g, uri->valuestring, "image", i, path, sizeof path, &size))
            return false;
        /* Assimp 5.2 reads the part after the '/' of an embedded image's type without looking for
         * the '/' (a null pointer plus one, found by fuzzing); glTF allows these two. */
        const cJSON *mime = cJSON_GetObjectItemCaseSensitive(im, "mimeType");
        char quoted[MODEL_QUOTE_MAX + 8];
        model_quote(cJSON_IsString(mime) ? mime->valuestring : "", quoted, sizeof quoted);
        if (mime && strcmp(quoted, "image/png") != 0 && strcmp(quoted, "image/jpeg") != 0)
            return model_fail(g->why, g->n, "image %lld: mimeType '%s' (glTF 2.0's images are image/png or "
                              "image/jpeg)", i, quoted);
    }
    for (long long i = 0, k; i < g->textures.count; i++)
        if (!field_index(g, g->textures.at[i], "source", false, &g->images, &k, "texture", i) ||
            !field_index(g, g->textures.at[i], "sampler", false, &g->samplers, &k, "texture", i))
            return false;
    return true;
}

/* Every texture a material names, in any object under a key ending in "Texture" (its core maps and
 * the extensions' alike). */
static bool check_material_textures(gltf *g, const cJSON *obj, long long i)
{
    const cJSON *c;
    cJSON_ArrayForEach(c, obj)
    {
        size_t len = c->string ? strlen(c->string) : 0;
        long long k;
        if (cJSON_IsObject(c) && len >= 7 && strcmp(c->string + len - 7, "Texture") == 0 &&
            (!field_index(g, c, "index", true, &g->textures, &k, "material", i) ||
             !field_whole(g, c, "texCoord", 0, 7, &k, "material", i)))
            return false;
        if ((cJSON_IsObject(c) || cJSON_IsArray(c)) && !check_material_textures(g, c, i))
            return false;
    }
    return true;
}

static bool check_lights(gltf *g)
{
    for (long long i = 0; i < g->lights.count; i++) {
        const cJSON *l = g->lights.at[i], *type = cJSON_GetObjectItemCaseSensitive(l, "type");
        char quoted[MODEL_QUOTE_MAX + 8];
        model_quote(cJSON_IsString(type) ? type->valuestring : "", quoted, sizeof quoted);
        if (strcmp(quoted, "point") != 0 && strcmp(quoted, "spot") != 0 && strcmp(quoted, "directional") != 0)
            return model_fail(g->why, g->n, "light %lld is of type '%s': the course reads KHR_lights_punctual's "
                              "point, spot and directional lights", i, quoted);
        if (strcmp(quoted, "spot") == 0 && !cJSON_IsObject(cJSON_GetObjectItemCaseSensitive(l, "spot")))
            return model_fail(g->why, g->n, "spot light %lld has no 'spot' object (its cone)", i);
        if (!numbers(g, l, "color", 3, "light", i))
            return false;
    }
    return true;
}

static bool check_animations(gltf *g)
{
    for (long long i = 0; i < g->animations.count; i++) {
        gltf_list samplers = {0}, channels = {0};
        long long k;
        bool ok = list_of(g, g->animations.at[i], "samplers", GLTF_ITEMS_MAX, &samplers) &&
                  list_of(g, g->animations.at[i], "channels", GLTF_ITEMS_MAX, &channels);
        for (long long s = 0; ok && s < samplers.count; s++)
            ok = field_index(g, samplers.at[s], "input", true, &g->accessors, &k, "animation sampler", s) &&
                 field_index(g, samplers.at[s], "output", true, &g->accessors, &k, "animation sampler", s);
        for (long long c = 0; ok && c < channels.count; c++) {
            const cJSON *target = cJSON_GetObjectItemCaseSensitive(channels.at[c], "target");
            ok = field_index(g, channels.at[c], "sampler", true, &samplers, &k, "animation channel", c) &&
                 (cJSON_IsObject(target) ? field_index(g, target, "node", false, &g->nodes, &k, "animation channel", c)
                                         : model_fail(g->why, g->n, "animation channel %lld has no target", c));
        }
        free(samplers.at);
        free(channels.at);
        if (!ok)
            return false;
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
    const struct { const char *key; gltf_list *list; long long max; } lists[] = {
        {"buffers", &g->buffers, GLTF_ITEMS_MAX},     {"bufferViews", &g->views, GLTF_ITEMS_MAX},
        {"accessors", &g->accessors, GLTF_ITEMS_MAX}, {"meshes", &g->meshes, GLTF_ITEMS_MAX},
        {"nodes", &g->nodes, MODEL_NODES_MAX},        {"images", &g->images, GLTF_ITEMS_MAX},
        {"textures", &g->textures, GLTF_ITEMS_MAX},   {"skins", &g->skins, GLTF_ITEMS_MAX},
        {"scenes", &g->scenes, GLTF_ITEMS_MAX},       {"animations", &g->animations, GLTF_ITEMS_MAX},
        {"materials", &g->materials, GLTF_ITEMS_MAX}, {"samplers", &g->samplers, GLTF_ITEMS_MAX},
        {"cameras", &g->cameras, GLTF_ITEMS_MAX}};
    for (size_t i = 0; i < sizeof lists / sizeof lists[0]; i++)
        if (!list_of(g, root, lists[i].key, lists[i].max, lists[i].list))
            return false;
    if (!list_of(g, punctual, "lights", MODEL_LIGHTS_MAX, &g->lights))
        return false;
    if (g->buffers.count && (!(g->data = calloc((size_t)g->buffers.count, sizeof *g->data)) ||
                             !(g->files = calloc((size_t)g->buffers.count, sizeof *g->files))))
        return model_fail(g->why, g->n, "out of memory");
    const cJSON *scene = cJSON_GetObjectItemCaseSensitive(root, "scene");
    if (scene && index_of(scene, g->scenes.count) < 0)
        return model_fail(g->why, g->n, "'scene' is not the index of one of its %lld scenes", g->scenes.count);
    bool ok = check_buffers(g) && check_views(g) && check_accessors(g) && check_meshes(g) && check_nodes(g) &&
              check_skins_scenes(g) && check_images(g) && check_lights(g) && check_animations(g);
    for (long long i = 0; ok && i < g->materials.count; i++)
        ok = check_material_textures(g, g->materials.at[i], i);
    if (ok && g->memory > g->lim->memory)
        ok = model_fail(g->why, g->n, "importing it would take about %lld MB, more than the budget of %lld MB "
                        "(COURSE_MODEL_MAX_MB)", g->memory >> 20, g->lim->memory >> 20);
    return ok;
}

static void gltf_free(gltf *g)
{
    gltf_list *lists[] = {&g->buffers, &g->views, &g->accessors, &g->meshes, &g->nodes, &g->images, &g->textures,
                          &g->skins, &g->lights, &g->scenes, &g->animations, &g->materials, &g->samplers,
                          &g->cameras};
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
        uint32_t words[5] = {0x46546c67u /* glTF */, 2, (uint32_t)*size, (uint32_t)padded, 0x4e4f534au /* JSON */};
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

char *model_gltf_check(const char *name, const char *data, size_t size, bool siblings, const model_limits *lim,
                       size_t *out_size, char *why, size_t n)
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
