/* model_gltf_parts.c - the glTF pre-scan's checks of a document's parts (model_gltf_internal.h):
 * accessors (their bytes, sparse indices), meshes (what Assimp will make of them), nodes, scenes,
 * skins, images, textures, materials, lights and animations. */
#include "model_gltf_internal.h"

#include "data_dir.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- accessors ------------------------------------------------------------------------------- */

static int component_size(long long type)
{
    switch (type) {
    case 5120:
    case 5121: return 1;
    case 5122:
    case 5123: return 2;
    case 5125:
    case 5126: return 4;
    default: return 0;
    }
}

/* Bytes of one element, matrix columns padded to 4 bytes as the specification lays them out. */
static long long element_size(const char *type, int component)
{
    static const struct {
        const char *name;
        int rows, columns;
    } types[] = {{"SCALAR", 1, 1}, {"VEC2", 2, 1}, {"VEC3", 3, 1}, {"VEC4", 4, 1},
                 {"MAT2", 2, 2},   {"MAT3", 3, 3}, {"MAT4", 4, 4}};
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
    gltf_field_whole(g, g->buffers.at[i], "byteLength", -1, GLTF_WHOLE_MAX, &length, "buffer", i);
    unsigned char *out = g->data[i] = calloc((size_t)length, 1);
    if (!out)
        return model_fail(g->why, g->n, "out of memory"), NULL;
    const char *s = uri->valuestring;
    if (gltf_is_data_uri(s)) {
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
    gltf_field_whole(g, g->views.at[view], "byteLength", -1, GLTF_WHOLE_MAX, &length, "bufferView", view);
    /* count <= 2^28 and stride <= 252 (check_accessors): the product cannot overflow */
    long long end = offset + stride * (count - 1) + size;
    if (end > length)
        return model_fail(g->why, g->n,
                          "%s %lld: %lld items of %lld bytes, %lld apart from byte %lld, end at "
                          "byte %lld of bufferView %lld's %lld",
                          what, index, count, size, stride, offset, end, view, length);
    return true;
}

static bool check_sparse(gltf *g, const cJSON *sparse, long long i, long long count, long long size)
{
    const cJSON *ix = cJSON_GetObjectItemCaseSensitive(sparse, "indices"),
                *values = cJSON_GetObjectItemCaseSensitive(sparse, "values");
    long long k, iview, ioffset, itype, vview, voffset, start, vstride;
    if (!cJSON_IsObject(ix) || !cJSON_IsObject(values))
        return model_fail(g->why, g->n, "accessor %lld: a sparse part without 'indices' and 'values'", i);
    if (!gltf_field_whole(g, sparse, "count", -1, count, &k, "accessor (sparse)", i) ||
        !gltf_field_index(g, ix, "bufferView", true, &g->views, &iview, "accessor (sparse indices)", i) ||
        !gltf_field_whole(g, ix, "byteOffset", 0, GLTF_WHOLE_MAX, &ioffset, "accessor (sparse indices)", i) ||
        !gltf_field_whole(g, ix, "componentType", -1, 5125, &itype, "accessor (sparse indices)", i) ||
        !gltf_field_index(g, values, "bufferView", true, &g->views, &vview, "accessor (sparse values)", i) ||
        !gltf_field_whole(g, values, "byteOffset", 0, GLTF_WHOLE_MAX, &voffset, "accessor (sparse values)",
                          i) ||
        !gltf_field_whole(g, g->views.at[iview], "byteOffset", 0, GLTF_WHOLE_MAX, &start, "bufferView",
                          iview) ||
        !gltf_field_whole(g, g->views.at[vview], "byteStride", size, 252, &vstride, "bufferView", vview))
        return false;
    int isize = itype == 5121 || itype == 5123 || itype == 5125 ? component_size(itype) : 0;
    if (k < 1 || !isize)
        return model_fail(g->why, g->n,
                          "accessor %lld: a sparse part of no entries or of indices that are not "
                          "unsigned",
                          i);
    if (!view_holds(g, iview, ioffset, k, isize, isize, "accessor (sparse indices)", i) ||
        !view_holds(g, vview, voffset, k, size, vstride, "accessor (sparse values)", i))
        return false;
    long long buffer;
    gltf_field_whole(g, g->views.at[iview], "buffer", -1, GLTF_WHOLE_MAX, &buffer, "bufferView", iview);
    const unsigned char *d = buffer_data(g, buffer);
    if (!d)
        return false;
    /* Each index names an element of the accessor: where Assimp writes that value. */
    for (long long e = 0; e < k; e++) {
        const unsigned char *p = d + start + ioffset + e * isize;
        long long at = isize == 1 ? p[0] : isize == 2 ? (p[0] | p[1] << 8) : (long long)gltf_le32(p);
        if (at >= count)
            return model_fail(g->why, g->n,
                              "accessor %lld: sparse index %lld is %lld, past its %lld elements", i, e, at,
                              count);
    }
    return true;
}

bool gltf_check_accessors(gltf *g)
{
    long long count_max = 3 * (g->lim->faces > g->lim->vertices ? g->lim->faces : g->lim->vertices);
    if (count_max > (1LL << 26) * 4)
        count_max = (1LL << 26) * 4;
    for (long long i = 0; i < g->accessors.count; i++) {
        const cJSON *a = g->accessors.at[i], *type = cJSON_GetObjectItemCaseSensitive(a, "type"),
                    *sparse = cJSON_GetObjectItemCaseSensitive(a, "sparse");
        long long ctype, count, view, offset, stride;
        if (!gltf_field_whole(g, a, "componentType", -1, 5126, &ctype, "accessor", i) ||
            !gltf_field_whole(g, a, "count", -1, count_max, &count, "accessor", i) ||
            !gltf_field_index(g, a, "bufferView", false, &g->views, &view, "accessor", i) ||
            !gltf_field_whole(g, a, "byteOffset", 0, GLTF_WHOLE_MAX, &offset, "accessor", i))
            return false;
        long long size = element_size(cJSON_IsString(type) ? type->valuestring : "", component_size(ctype));
        if (!size || count < 1)
            return model_fail(g->why, g->n,
                              "accessor %lld: no elements, or a 'type' or 'componentType' that glTF "
                              "2.0 does not have",
                              i);
        if (view < 0 && count * size > g->lim->bytes)
            return model_fail(g->why, g->n,
                              "accessor %lld: %lld elements of %lld bytes, more than %lld bytes "
                              "(COURSE_MODEL_MAX_BYTES)",
                              i, count, size, g->lim->bytes);
        if (view >= 0) {
            if (!gltf_field_whole(g, g->views.at[view], "byteStride", size, 252, &stride, "bufferView", view))
                return false;
            if (stride < size)
                return model_fail(g->why, g->n,
                                  "accessor %lld: elements of %lld bytes, %lld apart in bufferView "
                                  "%lld",
                                  i, size, stride, view);
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
        long long k = gltf_index_of(a, g->accessors.count);
        if (k < 0)
            return model_fail(g->why, g->n, "mesh %lld: attribute '%.40s' names no accessor", mesh,
                              a->string);
        long long count;
        gltf_field_whole(g, g->accessors.at[k], "count", -1, GLTF_WHOLE_MAX, &count, "accessor", k);
        if (*vertices && count != *vertices)
            return model_fail(g->why, g->n, "mesh %lld: its attributes have different counts (%lld, %lld)",
                              mesh, *vertices, count);
        *vertices = count;
    }
    return true;
}

static bool check_primitive(gltf *g, const cJSON *p, long long mesh)
{
    long long vertices, indices, mode, count;
    if (!check_attributes(g, cJSON_GetObjectItemCaseSensitive(p, "attributes"), mesh, &vertices) ||
        !gltf_field_index(g, p, "indices", false, &g->accessors, &indices, "mesh", mesh) ||
        !gltf_field_whole(g, p, "mode", 4, 6, &mode, "mesh", mesh) ||
        !gltf_field_index(g, p, "material", false, &g->materials, &count, "mesh", mesh))
        return false;
    const cJSON *targets = cJSON_GetObjectItemCaseSensitive(p, "targets"), *t;
    cJSON_ArrayForEach(t, targets)
    {
        long long target_vertices;
        if (!check_attributes(g, t, mesh, &target_vertices))
            return false;
        if (target_vertices && target_vertices != vertices)
            return model_fail(g->why, g->n,
                              "mesh %lld: a morph target of %lld vertices, the primitive has %lld", mesh,
                              target_vertices, vertices);
        g->memory += vertices * MODEL_BYTES_PER_VERTEX;
    }
    count = vertices;
    if (indices >= 0) {
        const cJSON *a = g->accessors.at[indices], *type = cJSON_GetObjectItemCaseSensitive(a, "type");
        long long ctype;
        gltf_field_whole(g, a, "componentType", -1, GLTF_WHOLE_MAX, &ctype, "accessor", indices);
        if (!cJSON_IsString(type) || strcmp(type->valuestring, "SCALAR") != 0 ||
            (ctype != 5121 && ctype != 5123 && ctype != 5125))
            return model_fail(g->why, g->n, "mesh %lld: its indices (accessor %lld) are not unsigned scalars",
                              mesh, indices);
        gltf_field_whole(g, a, "count", -1, GLTF_WHOLE_MAX, &count, "accessor", indices);
    }
    long long faces = mode == 4 ? count / 3 : mode >= 5 ? (count > 2 ? count - 2 : 0) : count;
    g->vertices += vertices, g->faces += faces;
    g->memory += vertices * MODEL_BYTES_PER_VERTEX + faces * MODEL_BYTES_PER_FACE;
    return true;
}

bool gltf_check_meshes(gltf *g)
{
    long long primitives = 0;
    for (long long i = 0; i < g->meshes.count; i++) {
        const cJSON *list = cJSON_GetObjectItemCaseSensitive(g->meshes.at[i], "primitives"), *p;
        if (!cJSON_IsArray(list) || !list->child)
            return model_fail(g->why, g->n, "mesh %lld has no 'primitives' array", i);
        cJSON_ArrayForEach(p, list)
        {
            if (++primitives > GLTF_PRIMITIVES_MAX)
                return model_fail(g->why, g->n, "its meshes hold more than %d primitives",
                                  GLTF_PRIMITIVES_MAX);
            if (!cJSON_IsObject(p) || !check_primitive(g, p, i))
                return cJSON_IsObject(p) ? false
                                         : model_fail(g->why, g->n,
                                                      "mesh %lld: a primitive that is not "
                                                      "an object",
                                                      i);
        }
    }
    if (g->vertices > g->lim->vertices || g->faces > g->lim->faces)
        return model_fail(g->why, g->n,
                          "its meshes declare %lld vertices and %lld faces, more than the limits of "
                          "%ld and %ld (COURSE_MODEL_MAX_VERTICES, COURSE_MODEL_MAX_FACES)",
                          g->vertices, g->faces, g->lim->vertices, g->lim->faces);
    return true;
}

/* ---- nodes, scenes and skins ------------------------------------------------------------------- */

static bool check_node(gltf *g, long long i, long long *parent)
{
    const cJSON *node = g->nodes.at[i], *children = cJSON_GetObjectItemCaseSensitive(node, "children"), *c;
    const cJSON *ext = cJSON_GetObjectItemCaseSensitive(node, "extensions");
    const cJSON *light = cJSON_GetObjectItemCaseSensitive(ext, "KHR_lights_punctual");
    long long k;
    if (!gltf_field_index(g, node, "mesh", false, &g->meshes, &k, "node", i) ||
        !gltf_field_index(g, node, "skin", false, &g->skins, &k, "node", i) ||
        !gltf_field_index(g, node, "camera", false, &g->cameras, &k, "node", i) ||
        (light && !gltf_field_index(g, light, "light", true, &g->lights, &k, "node", i)) ||
        !gltf_numbers(g, node, "matrix", 16, "node", i) ||
        !gltf_numbers(g, node, "translation", 3, "node", i) ||
        !gltf_numbers(g, node, "rotation", 4, "node", i) || !gltf_numbers(g, node, "scale", 3, "node", i))
        return false;
    if (children && !cJSON_IsArray(children))
        return model_fail(g->why, g->n, "node %lld: 'children' is not an array", i);
    cJSON_ArrayForEach(c, children)
    {
        k = gltf_index_of(c, g->nodes.count);
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
bool gltf_check_nodes(gltf *g)
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
        long long k = gltf_index_of(c, list->count);
        if (k < 0)
            return model_fail(g->why, g->n, "%s %lld: '%s' holds an index that names nothing", what, i, key);
        (*count)++;
    }
    return true;
}

bool gltf_check_skins_scenes(gltf *g)
{
    long long k, joints, matrices;
    for (long long i = 0; i < g->skins.count; i++) {
        const cJSON *s = g->skins.at[i];
        if (!index_array(g, s, "joints", &g->nodes, "skin", i, &joints) ||
            !gltf_field_index(g, s, "skeleton", false, &g->nodes, &k, "skin", i) ||
            !gltf_field_index(g, s, "inverseBindMatrices", false, &g->accessors, &k, "skin", i))
            return false;
        if (k < 0) /* optional in glTF, but Assimp 5.2 reads them through a null pointer when absent */
            return model_fail(g->why, g->n,
                              "skin %lld has no inverseBindMatrices (Assimp 5.2 cannot read a skin "
                              "without them)",
                              i);
        const cJSON *a = g->accessors.at[k], *type = cJSON_GetObjectItemCaseSensitive(a, "type");
        long long ctype;
        gltf_field_whole(g, a, "componentType", -1, GLTF_WHOLE_MAX, &ctype, "accessor", k);
        gltf_field_whole(g, a, "count", -1, GLTF_WHOLE_MAX, &matrices, "accessor", k);
        if (!cJSON_IsString(type) || strcmp(type->valuestring, "MAT4") != 0 || ctype != 5126 ||
            matrices < joints)
            return model_fail(g->why, g->n,
                              "skin %lld: its inverseBindMatrices (accessor %lld) are not %lld float "
                              "4x4 matrices",
                              i, k, joints);
    }
    for (long long i = 0; i < g->scenes.count; i++)
        if (!index_array(g, g->scenes.at[i], "nodes", &g->nodes, "scene", i, &k))
            return false;
    return true;
}

/* ---- images, textures, materials, lights, animations ------------------------------------------ */

bool gltf_check_images(gltf *g)
{
    for (long long i = 0; i < g->images.count; i++) {
        const cJSON *im = g->images.at[i], *uri = cJSON_GetObjectItemCaseSensitive(im, "uri");
        long long view, size;
        char path[MODEL_PATH_MAX];
        if (!gltf_field_index(g, im, "bufferView", false, &g->views, &view, "image", i))
            return false;
        if ((uri != NULL) == (view >= 0) || (uri && !cJSON_IsString(uri)))
            return model_fail(g->why, g->n, "image %lld has not exactly one of 'uri' and 'bufferView'", i);
        if (uri && !gltf_is_data_uri(uri->valuestring) &&
            !gltf_uri_file(g, uri->valuestring, "image", i, path, sizeof path, &size))
            return false;
        /* Assimp 5.2 reads the part after the '/' of an embedded image's type without looking for
         * the '/' (a null pointer plus one, found by fuzzing); glTF allows these two. */
        const cJSON *mime = cJSON_GetObjectItemCaseSensitive(im, "mimeType");
        char quoted[MODEL_QUOTE_MAX + 8];
        model_quote(cJSON_IsString(mime) ? mime->valuestring : "", quoted, sizeof quoted);
        if (mime && strcmp(quoted, "image/png") != 0 && strcmp(quoted, "image/jpeg") != 0)
            return model_fail(g->why, g->n,
                              "image %lld: mimeType '%s' (glTF 2.0's images are image/png or "
                              "image/jpeg)",
                              i, quoted);
    }
    for (long long i = 0, k; i < g->textures.count; i++)
        if (!gltf_field_index(g, g->textures.at[i], "source", false, &g->images, &k, "texture", i) ||
            !gltf_field_index(g, g->textures.at[i], "sampler", false, &g->samplers, &k, "texture", i))
            return false;
    return true;
}

/* Every texture a material names, in any object under a key ending in "Texture" (its core maps and
 * the extensions' alike). */
bool gltf_check_material_textures(gltf *g, const cJSON *obj, long long i)
{
    const cJSON *c;
    cJSON_ArrayForEach(c, obj)
    {
        size_t len = c->string ? strlen(c->string) : 0;
        long long k;
        if (cJSON_IsObject(c) && len >= 7 && strcmp(c->string + len - 7, "Texture") == 0 &&
            (!gltf_field_index(g, c, "index", true, &g->textures, &k, "material", i) ||
             !gltf_field_whole(g, c, "texCoord", 0, 7, &k, "material", i)))
            return false;
        if ((cJSON_IsObject(c) || cJSON_IsArray(c)) && !gltf_check_material_textures(g, c, i))
            return false;
    }
    return true;
}

bool gltf_check_lights(gltf *g)
{
    for (long long i = 0; i < g->lights.count; i++) {
        const cJSON *l = g->lights.at[i], *type = cJSON_GetObjectItemCaseSensitive(l, "type");
        char quoted[MODEL_QUOTE_MAX + 8];
        model_quote(cJSON_IsString(type) ? type->valuestring : "", quoted, sizeof quoted);
        if (strcmp(quoted, "point") != 0 && strcmp(quoted, "spot") != 0 && strcmp(quoted, "directional") != 0)
            return model_fail(g->why, g->n,
                              "light %lld is of type '%s': the course reads KHR_lights_punctual's "
                              "point, spot and directional lights",
                              i, quoted);
        if (strcmp(quoted, "spot") == 0 && !cJSON_IsObject(cJSON_GetObjectItemCaseSensitive(l, "spot")))
            return model_fail(g->why, g->n, "spot light %lld has no 'spot' object (its cone)", i);
        if (!gltf_numbers(g, l, "color", 3, "light", i))
            return false;
    }
    return true;
}

bool gltf_check_animations(gltf *g)
{
    for (long long i = 0; i < g->animations.count; i++) {
        gltf_list samplers = {0}, channels = {0};
        long long k;
        bool ok = gltf_list_of(g, g->animations.at[i], "samplers", GLTF_ITEMS_MAX, &samplers) &&
                  gltf_list_of(g, g->animations.at[i], "channels", GLTF_ITEMS_MAX, &channels);
        for (long long s = 0; ok && s < samplers.count; s++)
            ok = gltf_field_index(g, samplers.at[s], "input", true, &g->accessors, &k, "animation sampler",
                                  s) &&
                 gltf_field_index(g, samplers.at[s], "output", true, &g->accessors, &k, "animation sampler",
                                  s);
        for (long long c = 0; ok && c < channels.count; c++) {
            const cJSON *target = cJSON_GetObjectItemCaseSensitive(channels.at[c], "target");
            ok =
                gltf_field_index(g, channels.at[c], "sampler", true, &samplers, &k, "animation channel", c) &&
                (cJSON_IsObject(target)
                     ? gltf_field_index(g, target, "node", false, &g->nodes, &k, "animation channel", c)
                     : model_fail(g->why, g->n, "animation channel %lld has no target", c));
        }
        free(samplers.at);
        free(channels.at);
        if (!ok)
            return false;
    }
    return true;
}
