/* mesh_data.c - see mesh_data.h. */
#include "mesh_data.h"

#include "log.h"
#include "model_file.h"
#include "model_import.h"

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static bool mesh_alloc(mesh_data *m, int vertices, int indices)
{
    memset(m, 0, sizeof *m);
    m->vertices = calloc((size_t)vertices * MESH_VERTEX_FLOATS, sizeof(float));
    m->indices = calloc((size_t)indices, sizeof(uint32_t));
    if (!m->vertices || !m->indices) {
        log_error("out of memory for a mesh of %d vertices", vertices);
        mesh_data_destroy(m);
        return false;
    }
    m->vertex_count = vertices;
    m->index_count = indices;
    return true;
}

void mesh_data_put_vertex(mesh_data *m, int i, const float pos[3], const float normal[3], const float uv[2],
                          const float tangent[4])
{
    float *v = m->vertices + (size_t)i * MESH_VERTEX_FLOATS;
    memcpy(v + MESH_VERTEX_POSITION, pos, 3 * sizeof(float));
    memcpy(v + MESH_VERTEX_NORMAL, normal, 3 * sizeof(float));
    v[MESH_VERTEX_UV] = uv ? uv[0] : 0.0f;
    v[MESH_VERTEX_UV + 1] = uv ? uv[1] : 0.0f;
    /* No tangent: w = 0 asks mesh_data_generate_tangents for one. */
    for (int k = 0; k < 4; k++)
        v[MESH_VERTEX_TANGENT + k] = tangent ? tangent[k] : 0.0f;
}

/* The built-in shapes: a position, a normal and a texture coordinate; tangents are generated. */
static void set_vertex(mesh_data *m, int i, float px, float py, float pz, float nx, float ny, float nz, float u,
                       float v)
{
    mesh_data_put_vertex(m, i, (const float[3]){px, py, pz}, (const float[3]){nx, ny, nz}, (const float[2]){u, v},
                         NULL);
}

static void compute_bounds(mesh_data *m)
{
    for (int k = 0; k < 3; k++) {
        m->bounds_min[k] = m->vertex_count ? INFINITY : 0.0f;
        m->bounds_max[k] = m->vertex_count ? -INFINITY : 0.0f;
    }
    m->bound_radius = 0.0f;
    for (int i = 0; i < m->vertex_count; i++) {
        const float *p = m->vertices + (size_t)i * MESH_VERTEX_FLOATS;
        for (int k = 0; k < 3; k++) {
            m->bounds_min[k] = fminf(m->bounds_min[k], p[k]);
            m->bounds_max[k] = fmaxf(m->bounds_max[k], p[k]);
        }
        m->bound_radius = fmaxf(m->bound_radius, sqrtf(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
    }
}

bool mesh_data_cube(mesh_data *m)
{
    if (!mesh_alloc(m, 24, 36))
        return false;
    /* One face per axis direction; u x v = n so the winding is counter-clockwise seen from outside. */
    static const float faces[6][3][3] = {
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},  {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},   {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
    };
    static const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int f = 0; f < 6; f++) {
        const float *n = faces[f][0], *u = faces[f][1], *v = faces[f][2];
        for (int c = 0; c < 4; c++) {
            float p[3];
            for (int k = 0; k < 3; k++)
                p[k] = 0.5f * (n[k] + corners[c][0] * u[k] + corners[c][1] * v[k]);
            /* The face's u axis is the texture's s, its v axis t: the image upright on every side face. */
            set_vertex(m, f * 4 + c, p[0], p[1], p[2], n[0], n[1], n[2], 0.5f * (corners[c][0] + 1.0f),
                       0.5f * (corners[c][1] + 1.0f));
        }
        static const int quad[6] = {0, 1, 2, 0, 2, 3};
        for (int i = 0; i < 6; i++)
            m->indices[f * 6 + i] = (uint32_t)(f * 4 + quad[i]);
    }
    compute_bounds(m);
    mesh_data_generate_tangents(m);
    return true;
}

bool mesh_data_plane(mesh_data *m)
{
    if (!mesh_alloc(m, 4, 6))
        return false;
    /* s along +X, t along -Z: seen from above, the image upright. */
    set_vertex(m, 0, -0.5f, 0, 0.5f, 0, 1, 0, 0, 0);
    set_vertex(m, 1, 0.5f, 0, 0.5f, 0, 1, 0, 1, 0);
    set_vertex(m, 2, 0.5f, 0, -0.5f, 0, 1, 0, 1, 1);
    set_vertex(m, 3, -0.5f, 0, -0.5f, 0, 1, 0, 0, 1);
    static const uint32_t idx[6] = {0, 1, 2, 0, 2, 3};
    memcpy(m->indices, idx, sizeof idx);
    compute_bounds(m);
    mesh_data_generate_tangents(m);
    return true;
}

bool mesh_data_sphere(mesh_data *m, int slices, int stacks)
{
    if (slices < 3 || stacks < 2) {
        log_error("sphere needs at least 3 slices and 2 stacks (got %d, %d)", slices, stacks);
        return false;
    }
    int cols = slices + 1;
    /* Pole rows are one triangle per slice: 2*slices*(stacks-1) triangles in all. */
    if (!mesh_alloc(m, cols * (stacks + 1), 6 * slices * (stacks - 1)))
        return false;
    const double pi = 3.14159265358979323846;
    for (int j = 0; j <= stacks; j++) {
        double theta = pi * j / stacks; /* from +Y down */
        for (int i = 0; i <= slices; i++) {
            double phi = 2.0 * pi * (i % slices) / slices;
            float x = (float)(sin(theta) * cos(phi)), y = (float)cos(theta), z = (float)(-sin(theta) * sin(phi));
            if (j == 0 || j == stacks)
                x = 0.0f, z = 0.0f, y = j == 0 ? 1.0f : -1.0f;
            /* s round the equator (the seam column i = slices repeats i = 0 with s = 1), t pole to pole. */
            set_vertex(m, j * cols + i, x, y, z, x, y, z, (float)i / (float)slices, 1.0f - (float)j / (float)stacks);
        }
    }
    int k = 0;
    for (int j = 0; j < stacks; j++) {
        for (int i = 0; i < slices; i++) {
            uint32_t a = (uint32_t)(j * cols + i), b = a + 1, c = a + (uint32_t)cols, d = c + 1;
            if (j != 0) {
                m->indices[k++] = a, m->indices[k++] = c, m->indices[k++] = b;
            }
            if (j != stacks - 1) {
                m->indices[k++] = b, m->indices[k++] = c, m->indices[k++] = d;
            }
        }
    }
    m->index_count = k;
    compute_bounds(m);
    mesh_data_generate_tangents(m);
    return true;
}

/* ---- icosphere ---------------------------------------------------------------------------- */

typedef struct edge_key {
    uint32_t a, b, mid;
} edge_key;

static uint32_t midpoint(float *pos, int *count, edge_key *edges, int *edge_count, uint32_t a, uint32_t b)
{
    if (a > b) {
        uint32_t t = a;
        a = b;
        b = t;
    }
    for (int i = 0; i < *edge_count; i++)
        if (edges[i].a == a && edges[i].b == b)
            return edges[i].mid;
    float *pa = pos + 3 * a, *pb = pos + 3 * b, *p = pos + 3 * *count;
    double x = pa[0] + pb[0], y = pa[1] + pb[1], z = pa[2] + pb[2], l = sqrt(x * x + y * y + z * z);
    p[0] = (float)(x / l), p[1] = (float)(y / l), p[2] = (float)(z / l);
    edges[*edge_count] = (edge_key){a, b, (uint32_t)*count};
    ++*edge_count;
    return (uint32_t)(*count)++;
}

bool mesh_data_icosphere(mesh_data *m, int subdivisions)
{
    if (subdivisions < 0 || subdivisions > 4) {
        log_error("icosphere subdivisions must be 0..4 (got %d)", subdivisions);
        return false;
    }
    int tris = 20, verts = 12;
    for (int s = 0; s < subdivisions; s++) {
        verts += tris * 3 / 2;
        tris *= 4;
    }
    float *pos = malloc((size_t)verts * 3 * sizeof(float));
    uint32_t *idx = malloc((size_t)tris * 3 * sizeof(uint32_t));
    uint32_t *next = malloc((size_t)tris * 3 * sizeof(uint32_t));
    edge_key *edges = malloc((size_t)tris * 3 * sizeof(edge_key));
    bool ok = pos && idx && next && edges;
    if (ok) {
        const double t = (1.0 + sqrt(5.0)) / 2.0, l = sqrt(1.0 + t * t);
        const double base[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                     {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
        for (int i = 0; i < 12; i++)
            for (int k = 0; k < 3; k++)
                pos[3 * i + k] = (float)(base[i][k] / l);
        static const uint32_t faces[60] = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                                           4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                                           6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
        memcpy(idx, faces, sizeof faces);
        int count = 12, cur = 20;
        for (int s = 0; s < subdivisions; s++) {
            int edge_count = 0;
            for (int f = 0; f < cur; f++) {
                uint32_t a = idx[3 * f], b = idx[3 * f + 1], c = idx[3 * f + 2];
                uint32_t ab = midpoint(pos, &count, edges, &edge_count, a, b);
                uint32_t bc = midpoint(pos, &count, edges, &edge_count, b, c);
                uint32_t ca = midpoint(pos, &count, edges, &edge_count, c, a);
                const uint32_t quad[12] = {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca};
                memcpy(next + 12 * f, quad, sizeof quad);
            }
            cur *= 4;
            memcpy(idx, next, (size_t)cur * 3 * sizeof(uint32_t));
        }
        ok = mesh_alloc(m, verts, tris * 3);
        if (ok) {
            for (int i = 0; i < verts; i++)
                mesh_data_put_vertex(m, i, pos + 3 * i, pos + 3 * i, NULL, NULL); /* a light volume: no texture */
            memcpy(m->indices, idx, (size_t)tris * 3 * sizeof(uint32_t));
            compute_bounds(m);
            mesh_data_generate_tangents(m);
        }
    } else {
        log_error("out of memory for an icosphere");
    }
    free(pos);
    free(idx);
    free(next);
    free(edges);
    return ok;
}

double mesh_data_inradius(const mesh_data *m)
{
    double r = INFINITY;
    for (int t = 0; t + 2 < m->index_count; t += 3) {
        const float *a = m->vertices + (size_t)m->indices[t] * MESH_VERTEX_FLOATS;
        const float *b = m->vertices + (size_t)m->indices[t + 1] * MESH_VERTEX_FLOATS;
        const float *c = m->vertices + (size_t)m->indices[t + 2] * MESH_VERTEX_FLOATS;
        double u[3], v[3], n[3];
        for (int k = 0; k < 3; k++)
            u[k] = (double)b[k] - a[k], v[k] = (double)c[k] - a[k];
        n[0] = u[1] * v[2] - u[2] * v[1];
        n[1] = u[2] * v[0] - u[0] * v[2];
        n[2] = u[0] * v[1] - u[1] * v[0];
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (len == 0.0)
            continue;
        double d = fabs(n[0] * a[0] + n[1] * a[1] + n[2] * a[2]) / len;
        r = fmin(r, d);
    }
    return r;
}

/* ---- model files through Assimp -------------------------------------------------------------- */

static void count_node(const struct aiScene *sc, const struct aiNode *node, int *verts, int *idx)
{
    for (unsigned i = 0; i < node->mNumMeshes; i++) {
        const struct aiMesh *mesh = sc->mMeshes[node->mMeshes[i]];
        if (!(mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE))
            continue;
        *verts += (int)mesh->mNumVertices;
        for (unsigned f = 0; f < mesh->mNumFaces; f++)
            if (mesh->mFaces[f].mNumIndices == 3)
                *idx += 3;
    }
    for (unsigned c = 0; c < node->mNumChildren; c++)
        count_node(sc, node->mChildren[c], verts, idx);
}

/* A normal of unit length; degenerate input (zero-length or NaN) gives +Y rather than NaN pixels. */
static struct aiVector3D unit_normal(struct aiVector3D n)
{
    float len = sqrtf(n.x * n.x + n.y * n.y + n.z * n.z);
    if (!(len > 1e-20f) || !isfinite(len))
        return (struct aiVector3D){0, 1, 0};
    return (struct aiVector3D){n.x / len, n.y / len, n.z / len};
}

/* A model's vertex: its first texture coordinate set when it has one, and Assimp's tangent when that is
 * usable (finite, not along the normal); else w = 0, for mesh_data_generate_tangents. */
static void put_model_vertex(mesh_data *m, int i, const struct aiMesh *mesh, unsigned v,
                             const struct aiMatrix4x4 *world, struct aiVector3D p, struct aiVector3D n)
{
    const float pos[3] = {p.x, p.y, p.z}, normal[3] = {n.x, n.y, n.z};
    float uv[2] = {0.0f, 0.0f}, tangent[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    if (mesh->mTextureCoords[0] && isfinite(mesh->mTextureCoords[0][v].x) && isfinite(mesh->mTextureCoords[0][v].y)) {
        uv[0] = mesh->mTextureCoords[0][v].x;
        uv[1] = mesh->mTextureCoords[0][v].y;
    }
    if (mesh->mTextureCoords[0] && mesh->mTangents && mesh->mBitangents) {
        struct aiMatrix3x3 linear;
        aiMatrix3FromMatrix4(&linear, world);
        struct aiVector3D t = mesh->mTangents[v], b = mesh->mBitangents[v];
        aiTransformVecByMatrix3(&t, &linear);
        aiTransformVecByMatrix3(&b, &linear);
        float tn = t.x * n.x + t.y * n.y + t.z * n.z;
        t = (struct aiVector3D){t.x - tn * n.x, t.y - tn * n.y, t.z - tn * n.z};
        float len = sqrtf(t.x * t.x + t.y * t.y + t.z * t.z);
        if (len > 1e-12f && isfinite(len)) {
            /* Handedness: whether the bitangent runs along n x t or against it (a mirrored UV layout). */
            float c[3] = {n.y * t.z - n.z * t.y, n.z * t.x - n.x * t.z, n.x * t.y - n.y * t.x};
            float w = c[0] * b.x + c[1] * b.y + c[2] * b.z < 0.0f ? -1.0f : 1.0f;
            tangent[0] = t.x / len, tangent[1] = t.y / len, tangent[2] = t.z / len, tangent[3] = w;
        }
    }
    mesh_data_put_vertex(m, i, pos, normal, uv, tangent[3] != 0.0f ? tangent : NULL);
}

static void copy_node(const struct aiScene *sc, const struct aiNode *node, struct aiMatrix4x4 parent,
                      mesh_data *m, int *vbase, int *ibase)
{
    struct aiMatrix4x4 world = parent;
    aiMultiplyMatrix4(&world, &node->mTransformation);
    struct aiMatrix3x3 normal_matrix;
    aiMatrix3FromMatrix4(&normal_matrix, &world);
    aiMatrix3Inverse(&normal_matrix);
    aiTransposeMatrix3(&normal_matrix);
    for (unsigned i = 0; i < node->mNumMeshes; i++) {
        const struct aiMesh *mesh = sc->mMeshes[node->mMeshes[i]];
        if (!(mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE))
            continue;
        for (unsigned v = 0; v < mesh->mNumVertices; v++) {
            struct aiVector3D p = mesh->mVertices[v];
            struct aiVector3D n = mesh->mNormals ? mesh->mNormals[v] : (struct aiVector3D){0, 0, 0};
            aiTransformVecByMatrix4(&p, &world);
            aiTransformVecByMatrix3(&n, &normal_matrix);
            put_model_vertex(m, *vbase + (int)v, mesh, v, &world, p, unit_normal(n));
        }
        for (unsigned f = 0; f < mesh->mNumFaces; f++) {
            const struct aiFace *face = &mesh->mFaces[f];
            if (face->mNumIndices != 3)
                continue;
            for (int k = 0; k < 3; k++)
                m->indices[(*ibase)++] = (uint32_t)(*vbase) + face->mIndices[k];
        }
        *vbase += (int)mesh->mNumVertices;
    }
    for (unsigned c = 0; c < node->mNumChildren; c++)
        copy_node(sc, node->mChildren[c], world, m, vbase, ibase);
}

/* Bounds, tangents where the file gave none, and every coordinate finite; false (the mesh freed) when
 * one is not. */
static bool finish(mesh_data *m, const char *path, const char *pre)
{
    compute_bounds(m);
    mesh_data_generate_tangents(m);
    for (int i = 0; i < m->vertex_count * MESH_VERTEX_FLOATS; i++)
        if (!isfinite(m->vertices[i])) {
            log_error("%s: model '%s' has a non-finite vertex coordinate", pre, path);
            mesh_data_destroy(m);
            return false;
        }
    return true;
}

/* The steps after the validated import (model_file.c): triangles and welded vertices with normals, and
 * tangents where the mesh has texture coordinates (Assimp computes none without). */
#define MESH_POST_STEPS                                                                                        \
    (aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_GenSmoothNormals |                    \
     aiProcess_FindDegenerates | aiProcess_SortByPType | aiProcess_FindInvalidData | aiProcess_CalcTangentSpace)

static bool load_bytes(mesh_data *m, const char *path, const char *data, size_t size, bool siblings,
                       const model_limits *lim, const char *pre)
{
    char why[512];
    const char *format = model_format_of(path);
    const struct aiScene *sc = NULL;
    if (!model_prescan(data, size, format, lim, why, sizeof why) ||
        !(sc = model_import(path, data, size, siblings, lim, MESH_POST_STEPS, why, sizeof why))) {
        log_error("%s: cannot load model '%s': %s", pre, path, why);
        return false;
    }
    int verts = 0, idx = 0;
    count_node(sc, sc->mRootNode, &verts, &idx);
    if (idx == 0) {
        log_error("%s: model '%s' holds no triangles", pre, path);
        aiReleaseImport(sc);
        return false;
    }
    bool ok = mesh_alloc(m, verts, idx);
    if (ok) {
        struct aiMatrix4x4 identity;
        aiIdentityMatrix4(&identity);
        int vbase = 0, ibase = 0;
        copy_node(sc, sc->mRootNode, identity, m, &vbase, &ibase);
        m->index_count = ibase;
        ok = finish(m, path, pre);
    }
    aiReleaseImport(sc);
    return ok;
}

/* The limits, and a file name the course reads (by its extension); false with the error logged. */
static bool load_check(const char *path, const char *pre, model_limits *lim)
{
    char why[256];
    if (!model_limits_get(lim, why, sizeof why)) {
        log_error("%s: cannot load model '%s': %s", pre, path, why);
        return false;
    }
    if (!model_format_of(path)) {
        log_error("%s: cannot load model '%s': not a format the course reads (.obj, .ply, .off, .stl, .gltf, .glb)",
                  pre, path);
        return false;
    }
    return true;
}

bool mesh_data_load(mesh_data *m, const char *path, const char *origin)
{
    memset(m, 0, sizeof *m);
    const char *pre = origin ? origin : path;
    model_limits lim;
    if (!load_check(path, pre, &lim))
        return false;
    /* The whole file is read here, within the limit, so what was checked is what Assimp reads. */
    char why[256];
    size_t size;
    char *data = model_read_file(path, &lim, &size, why, sizeof why);
    if (!data) {
        log_error("%s: cannot load model '%s': %s", pre, path, why);
        return false;
    }
    bool ok = load_bytes(m, path, data, size, true, &lim, pre);
    free(data);
    return ok;
}

bool mesh_data_load_memory(mesh_data *m, const char *name, const void *data, size_t size, const char *origin)
{
    memset(m, 0, sizeof *m);
    const char *pre = origin ? origin : name;
    model_limits lim;
    return load_check(name, pre, &lim) && load_bytes(m, name, data, size, false, &lim, pre);
}

void mesh_data_destroy(mesh_data *m)
{
    free(m->vertices);
    free(m->indices);
    memset(m, 0, sizeof *m);
}

/* Mesh `part` of a model file alone: its vertices as the file has them, with UVs and tangents. */
static bool load_part(mesh_data *m, const char *path, int part, const char *pre)
{
    memset(m, 0, sizeof *m);
    char why[512];
    const struct aiScene *sc = model_import_cached(path, why, sizeof why);
    if (!sc) {
        log_error("%s: cannot load model '%s': %s", pre, path, why);
        return false;
    }
    const struct aiMesh *mesh = (unsigned)part < sc->mNumMeshes ? sc->mMeshes[part] : NULL;
    int triangles = 0;
    for (unsigned f = 0; mesh && f < mesh->mNumFaces; f++)
        triangles += mesh->mFaces[f].mNumIndices == 3;
    if (triangles == 0) {
        log_error("%s: cannot load model '%s': it has no mesh %d with triangles (did the file change?)", pre, path,
                  part);
        return false;
    }
    if (!mesh_alloc(m, (int)mesh->mNumVertices, 3 * triangles))
        return false;
    struct aiMatrix4x4 identity; /* the part in the file's own space: the node's matrix is the object's */
    aiIdentityMatrix4(&identity);
    for (unsigned v = 0; v < mesh->mNumVertices; v++) {
        struct aiVector3D n = mesh->mNormals ? mesh->mNormals[v] : (struct aiVector3D){0, 0, 0};
        put_model_vertex(m, (int)v, mesh, v, &identity, mesh->mVertices[v], unit_normal(n));
    }
    int k = 0;
    for (unsigned f = 0; f < mesh->mNumFaces; f++)
        for (unsigned c = 0; mesh->mFaces[f].mNumIndices == 3 && c < 3; c++)
            m->indices[k++] = mesh->mFaces[f].mIndices[c];
    return finish(m, path, pre);
}

bool mesh_data_from_scene(mesh_data *m, const scene *s, const scene_mesh *decl)
{
    char origin[SCENE_PATH_MAX + 32];
    snprintf(origin, sizeof origin, "%s:%d", s->path, decl->line);
    switch (decl->kind) {
    case SCENE_MESH_CUBE: return mesh_data_cube(m);
    case SCENE_MESH_PLANE: return mesh_data_plane(m);
    case SCENE_MESH_SPHERE: return mesh_data_sphere(m, decl->slices, decl->stacks);
    case SCENE_MESH_FILE:
        return decl->part < 0 ? mesh_data_load(m, decl->path, origin) : load_part(m, decl->path, decl->part, origin);
    }
    return false;
}
