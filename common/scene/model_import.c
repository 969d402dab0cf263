/* model_import.c - see model_import.h. The file goes through model_file.c (limits, validation,
 * Assimp's messages as one line); what is here turns Assimp's scene into the course's: meshes by
 * index, materials and their images, the node tree flattened into objects, and the lights.
 */
#include "model_import.h"

#include "log.h"
#include "model_file.h"
#include "model_image.h"

#include <assimp/GltfMaterial.h>
#include <assimp/cimport.h>
#include <assimp/light.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* Assimp's steps after the validated import: triangles, welded vertices, normals where the file has
 * none, and tangents where it has UVs but no tangents. Every import of a model uses these, so a
 * mesh's index (scene_mesh.part) means the same mesh at parse time and when the mesh is built. */
#define IMPORT_STEPS                                                                                         \
    (aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_GenSmoothNormals |                  \
     aiProcess_FindDegenerates | aiProcess_SortByPType | aiProcess_FindInvalidData |                         \
     aiProcess_CalcTangentSpace)

/* ---- the kept import ------------------------------------------------------------------------ */

static struct {
    char path[SCENE_PATH_MAX];
    off_t size;
    struct timespec mtime;
    const struct aiScene *sc;
} kept;

void model_import_release(void)
{
    if (kept.sc)
        aiReleaseImport(kept.sc);
    memset(&kept, 0, sizeof kept);
}

static bool is_gltf2(const struct aiScene *sc)
{
    const struct aiMetadata *meta = sc->mMetaData;
    for (unsigned i = 0; meta && i < meta->mNumProperties; i++)
        if (strcmp(meta->mKeys[i].data, "SourceAsset_Format") == 0 && meta->mValues[i].mType == AI_AISTRING)
            return strcmp(((const struct aiString *)meta->mValues[i].mData)->data, "glTF2 Importer") == 0;
    return false;
}

/* What the course cannot draw is refused here, once for the parse and the meshes alike. */
static bool check_supported(const struct aiScene *sc, char *why, size_t n)
{
    char name[MODEL_QUOTE_MAX + 8];
    if (!is_gltf2(sc))
        return model_fail(why, n, "not a glTF 2.0 file (glTF 1.0? the course reads 2.0 only)");
    for (unsigned i = 0; i < sc->mNumMeshes; i++) {
        const struct aiMesh *mesh = sc->mMeshes[i];
        model_quote(mesh->mName.data, name, sizeof name);
        if (mesh->mNumBones > 0)
            return model_fail(why, n, "mesh %u ('%s') is skinned: skins are not supported", i, name);
        if (mesh->mNumAnimMeshes > 0)
            return model_fail(why, n, "mesh %u ('%s') has morph targets: they are not supported", i, name);
        if (mesh->mMaterialIndex >= sc->mNumMaterials)
            return model_fail(why, n, "mesh %u ('%s') names material %u of %u", i, name, mesh->mMaterialIndex,
                              sc->mNumMaterials);
    }
    return true;
}

const struct aiScene *model_import_cached(const char *path, char *why, size_t n)
{
    struct stat st;
    if (kept.sc && strcmp(kept.path, path) == 0 && stat(path, &st) == 0 && st.st_size == kept.size &&
        st.st_mtim.tv_sec == kept.mtime.tv_sec && st.st_mtim.tv_nsec == kept.mtime.tv_nsec)
        return kept.sc;
    model_import_release();
    model_limits lim;
    if (!model_limits_get(&lim, why, n))
        return NULL;
    const char *format = model_format_of(path);
    if (!format || (strcmp(format, "gltf") != 0 && strcmp(format, "glb") != 0)) {
        model_fail(why, n,
                   "the model directive reads glTF 2.0 files (.gltf, .glb): for other formats use "
                   "'mesh NAME file PATH'");
        return NULL;
    }
    if (strlen(path) >= sizeof kept.path) {
        model_fail(why, n, "its path is longer than %zu characters", sizeof kept.path - 1);
        return NULL;
    }
    size_t size;
    char *data = model_read_file(path, &lim, &size, why, n);
    if (!data)
        return NULL;
    const struct aiScene *sc = NULL;
    if (model_prescan(data, size, format, &lim, why, n))
        sc = model_import(path, data, size, true, &lim, IMPORT_STEPS, why, n);
    free(data);
    if (!sc)
        return NULL;
    if (!check_supported(sc, why, n) || stat(path, &st) != 0) {
        aiReleaseImport(sc);
        return NULL;
    }
    snprintf(kept.path, sizeof kept.path, "%s", path);
    kept.size = st.st_size;
    kept.mtime = st.st_mtim;
    kept.sc = sc;
    return sc;
}

/* ---- building the scene --------------------------------------------------------------------- */

typedef struct build {
    const struct aiScene *sc;
    const char *path; /* the model file */
    scene *out;
    int texture_cap, object_cap, light_cap;
    long long texels; /* of the images kept so far */
    long long bytes;  /* the most an image file may hold (COURSE_MODEL_MAX_BYTES) */
    int nodes;        /* visited so far */
    int directional;  /* lights left out */
    int *slot;        /* per mesh of the file: its index in out->meshes, -1 for points and lines */
    int lines;        /* meshes of points or lines, left out */
    char *why;
    size_t n;
} build;

/* Append `element` to an array that grows by doubling; false (with *why) when it cannot. */
static bool push(build *b, void **array, int *count, int *cap, const void *element, size_t size)
{
    if (*count == *cap) {
        int grown_cap = *cap ? *cap * 2 : 8;
        void *grown = grown_cap < *cap ? NULL : realloc(*array, (size_t)grown_cap * size);
        if (!grown)
            return model_fail(b->why, b->n, "out of memory");
        *array = grown;
        *cap = grown_cap;
    }
    memcpy((char *)*array + (size_t)*count * size, element, size);
    (*count)++;
    return true;
}

/* "BoxTextured.glb#mesh0": a name no `mesh` or `material` line can declare ('#' starts a comment). */
static void part_name(const char *path, const char *kind, unsigned index, char out[SCENE_NAME_MAX])
{
    const char *slash = strrchr(path, '/');
    snprintf(out, SCENE_NAME_MAX, "%.40s#%s%u", slash ? slash + 1 : path, kind, index);
}

/* The meshes of triangles; points and lines (a file's, or degenerate triangles that Assimp turns
 * into them) are left out. */
static bool add_meshes(build *b)
{
    int cap = 0;
    if (!(b->slot = malloc(((size_t)b->sc->mNumMeshes + 1) * sizeof *b->slot)))
        return model_fail(b->why, b->n, "out of memory");
    for (unsigned i = 0; i < b->sc->mNumMeshes; i++) {
        b->slot[i] = -1;
        if (b->sc->mMeshes[i]->mPrimitiveTypes != aiPrimitiveType_TRIANGLE) {
            b->lines++;
            continue;
        }
        scene_mesh m = {.kind = SCENE_MESH_FILE, .part = (int)i};
        part_name(b->path, "mesh", i, m.name);
        snprintf(m.path, sizeof m.path, "%s", b->path);
        if (!push(b, (void **)&b->out->meshes, &b->out->mesh_count, &cap, &m, sizeof m))
            return false;
        b->slot[i] = b->out->mesh_count - 1;
    }
    return true;
}

/* ---- images --------------------------------------------------------------------------------- */

/* The image a material names (model_image.c checks it), once per image and colour space; its texels
 * count towards MODEL_TEXELS_MAX. *index: its slot in out->textures. */
static bool add_texture(build *b, const char *given, bool srgb, int *index)
{
    model_image image;
    if (!model_image_check(b->sc, b->path, given, b->bytes, &image, b->why, b->n))
        return false;
    for (int i = 0; i < b->out->texture_count; i++)
        if (b->out->textures[i].srgb == srgb && strcmp(b->out->textures[i].path, image.path) == 0)
            return *index = i, true;
    b->texels += (long long)image.width * image.height;
    if (b->texels > MODEL_TEXELS_MAX)
        return model_fail(b->why, b->n, "its images hold more than %lld texels", MODEL_TEXELS_MAX);
    scene_texture t = {.srgb = srgb};
    memcpy(t.path, image.path, sizeof t.path);
    if (image.bytes) {
        if (!(t.data = malloc(image.size)))
            return model_fail(b->why, b->n, "out of memory");
        memcpy(t.data, image.bytes, image.size);
        t.size = image.size;
    }
    if (!push(b, (void **)&b->out->textures, &b->out->texture_count, &b->texture_cap, &t, sizeof t)) {
        free(t.data);
        return false;
    }
    *index = b->out->texture_count - 1;
    return true;
}

/* ---- materials ------------------------------------------------------------------------------ */

/* A factor in [0, 1] (key: "$mat.metallicFactor", the string of AI_MATKEY_METALLIC_FACTOR). */
static float factor(const struct aiMaterial *mat, const char *key, float fallback)
{
    ai_real v;
    unsigned one = 1;
    if (aiGetMaterialFloatArray(mat, key, 0, 0, &v, &one) != aiReturn_SUCCESS || one != 1 || !isfinite(v))
        return fallback;
    return fminf(fmaxf((float)v, 0.0f), 1.0f);
}

/* One map: the first texture of the first type that has one. */
static bool add_map(build *b, unsigned index, const struct aiMaterial *mat, scene_map map, scene_material *m)
{
    static const char *const names[SCENE_MAP_COUNT] = {"base colour", "metallic-roughness", "normal",
                                                       "occlusion", "emissive"};
    enum aiTextureType types[2] = {aiTextureType_NONE, aiTextureType_NONE};
    switch (map) {
    case SCENE_MAP_BASE: types[0] = aiTextureType_BASE_COLOR, types[1] = aiTextureType_DIFFUSE; break;
    case SCENE_MAP_METAL_ROUGH: types[0] = aiTextureType_UNKNOWN; break; /* AI_MATKEY_GLTF_PBR... */
    case SCENE_MAP_NORMAL: types[0] = aiTextureType_NORMALS; break;
    case SCENE_MAP_OCCLUSION: types[0] = aiTextureType_LIGHTMAP; break;
    case SCENE_MAP_EMISSIVE: types[0] = aiTextureType_EMISSIVE; break;
    case SCENE_MAP_COUNT: return false;
    }
    for (int k = 0; k < 2 && types[k] != aiTextureType_NONE; k++) {
        if (aiGetMaterialTextureCount(mat, types[k]) == 0)
            continue;
        struct aiString file;
        unsigned uv = 0;
        if (aiGetMaterialTexture(mat, types[k], 0, &file, NULL, &uv, NULL, NULL, NULL, NULL) !=
            aiReturn_SUCCESS)
            return model_fail(b->why, b->n, "material %u: its %s texture cannot be read", index, names[map]);
        if (uv != 0)
            return model_fail(b->why, b->n,
                              "material %u: its %s texture reads UV set %u (the course reads set "
                              "0 only)",
                              index, names[map], uv);
        struct aiUVTransform t;
        if (aiGetMaterialUVTransform(mat, _AI_MATKEY_UVTRANSFORM_BASE, types[k], 0, &t) == aiReturn_SUCCESS &&
            (t.mTranslation.x != 0 || t.mTranslation.y != 0 || t.mScaling.x != 1 || t.mScaling.y != 1 ||
             t.mRotation != 0))
            return model_fail(b->why, b->n,
                              "material %u: its %s texture has a texture transform "
                              "(KHR_texture_transform is not supported)",
                              index, names[map]);
        return add_texture(b, file.data, map == SCENE_MAP_BASE || map == SCENE_MAP_EMISSIVE, &m->maps[map]);
    }
    return true;
}

static bool add_materials(build *b)
{
    int cap = 0;
    for (unsigned i = 0; i < b->sc->mNumMaterials; i++) {
        const struct aiMaterial *mat = b->sc->mMaterials[i];
        scene_material m = {
            .specular = 0.0f, .shininess = 32.0f, .opacity = 1.0f, .pbr = true, .maps = {-1, -1, -1, -1, -1}};
        part_name(b->path, "material", i, m.name);
        ai_real unused;
        if (aiGetMaterialFloatArray(mat, "$mat.glossinessFactor", 0, 0, &unused, NULL) == aiReturn_SUCCESS)
            return model_fail(b->why, b->n,
                              "material %u is specular-glossiness (KHR_materials_pbrSpecular"
                              "Glossiness): the course reads metallic-roughness only",
                              i);
        struct aiColor4D base = {1, 1, 1, 1}, emissive = {0, 0, 0, 1};
        if (aiGetMaterialColor(mat, AI_MATKEY_BASE_COLOR, &base) != aiReturn_SUCCESS)
            aiGetMaterialColor(mat, AI_MATKEY_COLOR_DIFFUSE, &base);
        aiGetMaterialColor(mat, AI_MATKEY_COLOR_EMISSIVE, &emissive);
        ai_real strength = 1;
        aiGetMaterialFloatArray(mat, AI_MATKEY_EMISSIVE_INTENSITY, &strength, NULL);
        const float rgb[2][3] = {{base.r, base.g, base.b}, {emissive.r, emissive.g, emissive.b}};
        for (int k = 0; k < 3; k++) {
            m.albedo[k] = fminf(fmaxf(rgb[0][k], 0.0f), 1.0f);
            m.emissive[k] = fmaxf(rgb[1][k] * (float)strength, 0.0f);
            if (!isfinite(m.albedo[k]) || !isfinite(m.emissive[k]))
                return model_fail(b->why, b->n, "material %u: a colour that is not a finite number", i);
        }
        m.metallic = factor(mat, "$mat.metallicFactor", 1.0f);   /* AI_MATKEY_METALLIC_FACTOR */
        m.roughness = factor(mat, "$mat.roughnessFactor", 1.0f); /* AI_MATKEY_ROUGHNESS_FACTOR */
        /* BLEND is the course's glass (scene_material.opacity > 0); MASK has no cut-out here: opaque. */
        struct aiString mode;
        if (aiGetMaterialString(mat, AI_MATKEY_GLTF_ALPHAMODE, &mode) == aiReturn_SUCCESS &&
            strcmp(mode.data, "BLEND") == 0)
            m.opacity = isfinite(base.a) ? fminf(fmaxf(base.a, 1.0f / 255.0f), 1.0f) : 1.0f;
        for (int map = 0; map < SCENE_MAP_COUNT; map++)
            if (!add_map(b, i, mat, (scene_map)map, &m))
                return false;
        if (!push(b, (void **)&b->out->materials, &b->out->material_count, &cap, &m, sizeof m))
            return false;
    }
    return true;
}

/* ---- nodes: objects and lights -------------------------------------------------------------- */

/* Assimp's matrices are row-major (a1..a4 the first row); cglm's are columns. */
static bool to_mat4(const struct aiMatrix4x4 *a, mat4 out)
{
    const float rows[4][4] = {{a->a1, a->a2, a->a3, a->a4},
                              {a->b1, a->b2, a->b3, a->b4},
                              {a->c1, a->c2, a->c3, a->c4},
                              {a->d1, a->d2, a->d3, a->d4}};
    bool finite = true;
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++)
            finite = finite && isfinite(out[c][r] = rows[r][c]);
    return finite;
}

/* A KHR_lights_punctual light: colour * intensity (candela) becomes the course's colour (largest
 * component 1) and intensity, its inverse square law 1 / (MODEL_LIGHT_KC + d^2). */
static bool add_light(build *b, const struct aiLight *l, mat4 world)
{
    if (l->mType != aiLightSource_POINT && l->mType != aiLightSource_SPOT) {
        b->directional++;
        return true;
    }
    scene_light out = {.kc = MODEL_LIGHT_KC, .kl = 0.0f, .kq = 1.0f, .color = {1, 1, 1}};
    vec4 local = {l->mPosition.x, l->mPosition.y, l->mPosition.z, 1.0f}, placed;
    glm_mat4_mulv(world, local, placed);
    glm_vec3_copy(placed, out.position);
    float rgb[3] = {l->mColorDiffuse.r, l->mColorDiffuse.g, l->mColorDiffuse.b};
    float peak = fmaxf(rgb[0], fmaxf(rgb[1], rgb[2]));
    if (!isfinite(peak) || !(fminf(rgb[0], fminf(rgb[1], rgb[2])) >= 0.0f))
        return model_fail(b->why, b->n,
                          "light '%.60s': a colour or intensity that is not a finite, non-negative "
                          "number",
                          l->mName.data);
    out.intensity = peak;
    for (int k = 0; k < 3 && peak > 0.0f; k++)
        out.color[k] = rgb[k] / peak;
    if (l->mType == aiLightSource_SPOT) {
        /* glTF's cone angles are half-angles in radians, 0 <= inner < outer <= pi/2; the course's
         * cone is 0 < inner <= outer < 90 degrees. */
        mat3 turn;
        glm_mat4_pick3(world, turn);
        vec3 axis = {l->mDirection.x, l->mDirection.y, l->mDirection.z};
        glm_mat3_mulv(turn, axis, out.direction);
        out.spot = true;
        out.outer_deg = fminf(glm_deg(l->mAngleOuterCone), 89.0f);
        out.inner_deg = fminf(fmaxf(glm_deg(l->mAngleInnerCone), 0.01f), out.outer_deg);
        double x = out.direction[0], y = out.direction[1], z = out.direction[2];
        if (!(x * x + y * y + z * z > 0.0) || !isfinite(x + y + z) || !(out.outer_deg > 0.0f))
            return model_fail(b->why, b->n, "spot light '%.60s': no direction or no cone", l->mName.data);
    }
    return push(b, (void **)&b->out->lights, &b->out->light_count, &b->light_cap, &out, sizeof out);
}

static bool add_node(build *b, const struct aiNode *node, mat4 parent, int depth)
{
    if (depth > MODEL_DEPTH_MAX)
        return model_fail(b->why, b->n, "its nodes are nested more than %d deep", MODEL_DEPTH_MAX);
    if (++b->nodes > MODEL_NODES_MAX)
        return model_fail(b->why, b->n, "it has more than %d nodes", MODEL_NODES_MAX);
    mat4 local, world;
    if (!to_mat4(&node->mTransformation, local))
        return model_fail(b->why, b->n, "node '%.60s': a transform that is not finite", node->mName.data);
    glm_mat4_mul(parent, local, world);
    for (unsigned i = 0; i < node->mNumMeshes; i++) {
        unsigned k = node->mMeshes[i];
        if (k >= b->sc->mNumMeshes)
            return model_fail(b->why, b->n, "node '%.60s' names mesh %u of %u", node->mName.data, k,
                              b->sc->mNumMeshes);
        if (b->slot[k] < 0)
            continue;
        if (b->out->object_count >= MODEL_OBJECTS_MAX)
            return model_fail(b->why, b->n, "it places more than %d meshes", MODEL_OBJECTS_MAX);
        scene_object o = {.mesh = b->slot[k],
                          .material = (int)b->sc->mMeshes[k]->mMaterialIndex,
                          .scale = {1, 1, 1},
                          .has_base = true};
        glm_mat4_copy(world, o.base);
        if (!push(b, (void **)&b->out->objects, &b->out->object_count, &b->object_cap, &o, sizeof o))
            return false;
    }
    /* Assimp names a light after the node that carries it. */
    for (unsigned i = 0; i < b->sc->mNumLights; i++)
        if (strcmp(b->sc->mLights[i]->mName.data, node->mName.data) == 0 &&
            !add_light(b, b->sc->mLights[i], world))
            return false;
    for (unsigned c = 0; c < node->mNumChildren; c++)
        if (!add_node(b, node->mChildren[c], world, depth + 1))
            return false;
    return true;
}

void model_import_free(scene *out)
{
    for (int i = 0; i < out->texture_count; i++)
        free(out->textures[i].data);
    free(out->textures);
    free(out->meshes);
    free(out->materials);
    free(out->objects);
    free(out->lights);
    memset(out, 0, sizeof *out);
}

bool model_import_scene(const char *path, const char *origin, scene *out, char *why, size_t n)
{
    memset(out, 0, sizeof *out);
    const struct aiScene *sc = model_import_cached(path, why, n);
    if (!sc)
        return false;
    model_limits lim;
    if (!model_limits_get(&lim, why, n))
        return false;
    build b = {.sc = sc, .path = path, .out = out, .bytes = lim.bytes, .why = why, .n = n};
    mat4 identity = GLM_MAT4_IDENTITY_INIT;
    bool ok = add_meshes(&b) && add_materials(&b) && add_node(&b, sc->mRootNode, identity, 0);
    free(b.slot);
    if (ok && out->object_count == 0)
        ok = model_fail(why, n, "its nodes place no mesh of triangles%s",
                        b.lines ? " (points and lines are not drawn)" : "");
    if (!ok) {
        model_import_free(out);
        return false;
    }
    if (b.lines)
        log_warn("%s: model '%s': %d mesh(es) of points or lines left out (the course draws triangles)",
                 origin, path, b.lines);
    if (b.directional)
        log_warn(
            "%s: model '%s': %d directional light(s) left out (the course has point and spot lights only)",
            origin, path, b.directional);
    if (sc->mNumAnimations)
        log_warn("%s: model '%s': %u animation(s) ignored: the scene shows the file's rest pose", origin,
                 path, sc->mNumAnimations);
    return true;
}
