/* model_file.c - see model_file.h. */
#define _XOPEN_SOURCE 700 /* realpath */
#include "model_file.h"

#include "data_dir.h"

#include <assimp/cfileio.h>
#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <limits.h>
#include <sys/stat.h>

bool model_fail(char *why, size_t n, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(why, n, fmt, ap);
    va_end(ap);
    return false;
}

/* ---- limits and formats ------------------------------------------------------------------------ */

static bool env_limit(const char *name, long long hi, long long *value, char *why, size_t n)
{
    const char *text = getenv(name);
    if (!text || !*text)
        return true;
    char *end;
    errno = 0;
    long long v = strtoll(text, &end, 10);
    if (errno || *end || v < 1 || v > hi)
        return model_fail(why, n, "%s='%.40s': expected a whole number from 1 to %lld", name, text, hi);
    *value = v;
    return true;
}

bool model_limits_get(model_limits *lim, char *why, size_t n)
{
    /* The upper ends keep every count inside mesh_data's int arithmetic (3 vertices a triangle,
     * 6 floats a vertex) and every file inside what one read can hold. */
    long long bytes = MODEL_MAX_BYTES_DEFAULT, vertices = MODEL_MAX_VERTICES_DEFAULT, faces = MODEL_MAX_FACES_DEFAULT,
              megabytes = MODEL_MAX_MB_DEFAULT;
    if (!env_limit("COURSE_MODEL_MAX_BYTES", 1LL << 32, &bytes, why, n) ||
        !env_limit("COURSE_MODEL_MAX_VERTICES", 100000000, &vertices, why, n) ||
        !env_limit("COURSE_MODEL_MAX_FACES", 100000000, &faces, why, n) ||
        !env_limit("COURSE_MODEL_MAX_MB", 1LL << 20, &megabytes, why, n))
        return false;
    *lim = (model_limits){
        .bytes = bytes, .vertices = (long)vertices, .faces = (long)faces, .memory = megabytes << 20};
    return true;
}

const char *model_format_of(const char *path)
{
    static const char *const formats[] = {"obj", "ply", "off", "stl", "gltf", "glb"};
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    if (!dot || (slash && dot < slash))
        return NULL;
    for (size_t i = 0; i < sizeof formats / sizeof formats[0]; i++)
        if (strcasecmp(dot + 1, formats[i]) == 0)
            return formats[i];
    return NULL;
}

void model_quote(const char *text, char *out, size_t n)
{
    size_t k = 0;
    for (const unsigned char *p = (const unsigned char *)text; *p && *p != '\n' && *p != '\r' && k + 4 < n; p++) {
        if (k == MODEL_QUOTE_MAX) {
            memcpy(out + k, "...", 3), k += 3;
            break;
        }
        out[k++] = *p >= 0x20 && *p < 0x7f ? (char)*p : '?';
    }
    out[n ? k : 0] = '\0';
}

bool model_uri_decode(const char *uri, char *out, size_t n)
{
    size_t k = 0;
    for (const char *c = uri; *c; c++) {
        unsigned v;
        if (k + 1 >= n)
            return false;
        if (*c != '%')
            out[k++] = *c;
        else if (!c[1] || !c[2] || sscanf(c + 1, "%2x", &v) != 1 || v == 0)
            return false;
        else
            out[k++] = (char)v, c += 2;
    }
    out[k] = '\0';
    return true;
}

bool model_path_inside(const char *model, const char *path, char *resolved, long long *size, char *why, size_t n)
{
    char folder[PATH_MAX], target[PATH_MAX], dir[PATH_MAX];
    const char *slash = strrchr(model, '/');
    int length = !slash ? 1 : slash == model ? 1 : (int)(slash - model);
    snprintf(dir, sizeof dir, "%.*s", length, slash ? model : ".");
    struct stat st;
    if (!realpath(dir, folder))
        return model_fail(why, n, "the model's folder cannot be resolved (%s)", strerror(errno));
    if (!realpath(path, target))
        return model_fail(why, n, "no such file");
    size_t k = strlen(folder);
    if (strcmp(folder, "/") != 0 && (strncmp(target, folder, k) != 0 || target[k] != '/'))
        return model_fail(why, n, "it lies outside the model's folder (files are read from the model's folder "
                          "and below)");
    if (stat(target, &st) != 0 || !S_ISREG(st.st_mode))
        return model_fail(why, n, "not a regular file");
    *size = (long long)st.st_size;
    if (resolved)
        snprintf(resolved, MODEL_PATH_MAX, "%s", target);
    return true;
}

char *model_read_file(const char *path, const model_limits *lim, size_t *size, char *why, size_t n)
{
    struct stat st;
    const char *reason = NULL;
    FILE *f = data_dir_open_input(path, &reason); /* a regular file, or refused without waiting on it */
    if (!f || fstat(fileno(f), &st) != 0) {
        model_fail(why, n, "%s", f ? strerror(errno) : reason);
        if (f)
            fclose(f);
        return NULL;
    }
    if (st.st_size > lim->bytes) {
        model_fail(why, n, "%lld bytes, more than the limit of %lld (COURSE_MODEL_MAX_BYTES)", (long long)st.st_size,
                   lim->bytes);
        fclose(f);
        return NULL;
    }
    *size = (size_t)st.st_size;
    char *data = malloc(*size ? *size : 1);
    if (!data || fread(data, 1, *size, f) != *size) {
        model_fail(why, n, "cannot read its %zu bytes", *size);
        free(data);
        data = NULL;
    }
    fclose(f);
    return data;
}

/* ---- Assimp's files: the model from memory, the files it names from disk, within limits --------- */

typedef struct io_state {
    const char *name, *data;
    size_t size;
    bool siblings;
    long long budget, used; /* bytes of the named files read so far */
    bool over;
    bool guessing; /* Assimp turned to guessing the format from the content: every open fails */
    bool outside;  /* a file it names lies outside the model's folder, or is no regular file */
    struct io_file *open; /* files Assimp has not closed: it throws past its closes on some errors */
} io_state;

typedef struct io_file {
    struct aiFile file;
    io_state *io;
    const char *data; /* the model, or a named file once read */
    char *owned;
    FILE *disk;
    size_t size, pos;
    struct io_file *next; /* in io_state.open */
} io_file;

static io_file *io_of(struct aiFile *f) { return (io_file *)(void *)f->UserData; }

/* A named file is read whole on its first read, so its bytes count once, when they are used
 * (Assimp also opens files only to ask whether they exist). */
static bool io_fill(io_file *f)
{
    if (f->data || !f->disk)
        return f->data != NULL;
    f->io->used += (long long)f->size;
    if (f->io->used > f->io->budget) {
        f->io->over = true;
        return false;
    }
    f->owned = malloc(f->size ? f->size : 1);
    if (!f->owned || fread(f->owned, 1, f->size, f->disk) != f->size)
        return false;
    f->data = f->owned;
    return true;
}

static size_t io_read(struct aiFile *file, char *buffer, size_t size, size_t count)
{
    io_file *f = io_of(file);
    if (size == 0 || !io_fill(f))
        return 0;
    size_t items = (f->size - f->pos) / size;
    if (items > count)
        items = count;
    memcpy(buffer, f->data + f->pos, items * size);
    f->pos += items * size;
    return items;
}

static size_t io_write(struct aiFile *file, const char *buffer, size_t size, size_t count)
{
    (void)file, (void)buffer, (void)size, (void)count;
    return 0;
}

static size_t io_tell(struct aiFile *file) { return io_of(file)->pos; }
static size_t io_size(struct aiFile *file) { return io_of(file)->size; }
static void io_flush(struct aiFile *file) { (void)file; }

static enum aiReturn io_seek(struct aiFile *file, size_t offset, enum aiOrigin origin)
{
    io_file *f = io_of(file);
    size_t base = origin == aiOrigin_SET ? 0 : origin == aiOrigin_CUR ? f->pos : f->size;
    if (offset > f->size || base > f->size - offset)
        return aiReturn_FAILURE;
    f->pos = base + offset;
    return aiReturn_SUCCESS;
}

static struct aiFile *io_open(struct aiFileIO *fio, const char *name, const char *mode)
{
    io_state *io = (io_state *)(void *)fio->UserData;
    if (strpbrk(mode, "wa+") || io->guessing)
        return NULL;
    FILE *disk = NULL;
    struct stat st;
    bool model = strcmp(name, io->name) == 0;
    if (!model) {
        char reason[160];
        long long bytes;
        if (!io->siblings)
            return NULL;
        if (!model_path_inside(io->name, name, NULL, &bytes, reason, sizeof reason)) {
            io->outside |= strstr(reason, "outside") != NULL;
            return NULL;
        }
        const char *refused;
        if (!(disk = data_dir_open_input(name, &refused)) || fstat(fileno(disk), &st) != 0) {
            if (disk)
                fclose(disk);
            return NULL;
        }
        if (st.st_size > io->budget) { /* never one Assimp could read */
            io->over = true;
            fclose(disk);
            return NULL;
        }
    }
    io_file *f = calloc(1, sizeof *f);
    if (!f) {
        if (disk)
            fclose(disk);
        return NULL;
    }
    f->file = (struct aiFile){io_read, io_write, io_tell, io_size, io_seek, io_flush, (aiUserData)(void *)f};
    f->io = io;
    f->disk = disk;
    f->data = model ? io->data : NULL;
    f->size = model ? io->size : (size_t)st.st_size;
    f->next = io->open;
    io->open = f;
    return &f->file;
}

static void io_close(struct aiFileIO *fio, struct aiFile *file)
{
    io_state *io = (io_state *)(void *)fio->UserData;
    io_file *f = io_of(file);
    for (io_file **p = &io->open; *p; p = &(*p)->next)
        if (*p == f) {
            *p = f->next;
            break;
        }
    if (f->disk)
        fclose(f->disk);
    free(f->owned);
    free(f);
}

/* Assimp's first warning that it left part of the file out, during the checking import. Its other
 * warnings (a material it could not find, 3D texture coordinates that are 2D) do not change the
 * geometry the course reads, so they pass. */
static char assimp_warning[MODEL_QUOTE_MAX + 8];
static io_state *importing; /* the import under way, for the log stream; NULL between imports */

static void keep_warning(const char *message, char *user)
{
    (void)user;
    if (!importing)
        return;
    /* When the readers of a file's extension all refuse it (a .glb that is not glTF), Assimp asks
     * every other reader whether the content is theirs, and the course would read a format it
     * never checked: from this line on the file cannot be opened, so none can. */
    if (strstr(message, "File extension not known, trying signature-based detection"))
        importing->guessing = true;
    static const char *const dropping[] = {"dropped", "out of range", "out-of-range", "Ignoring"};
    if (assimp_warning[0] || (strncmp(message, "Warn", 4) != 0 && strncmp(message, "Error", 5) != 0))
        return;
    for (size_t i = 0; i < sizeof dropping / sizeof dropping[0]; i++)
        if (strstr(message, dropping[i])) {
            const char *colon = strstr(message, ": "); /* after Assimp's "Warn,  T0: " */
            model_quote(colon ? colon + 2 : message, assimp_warning, sizeof assimp_warning);
            return;
        }
}

static bool finite3(const struct aiVector3D *v) { return isfinite(v->x) && isfinite(v->y) && isfinite(v->z); }

/* Each mesh's faces must be what its primitive types say: Assimp's triangulation asserts (and
 * aborts) when a loader marked a mesh as holding polygons that it does not hold. */
static bool check_faces(const struct aiScene *sc, char *why, size_t n)
{
    for (unsigned i = 0; i < sc->mNumMeshes; i++) {
        const struct aiMesh *mesh = sc->mMeshes[i];
        unsigned types = 0;
        for (unsigned f = 0; f < mesh->mNumFaces; f++) {
            unsigned k = mesh->mFaces[f].mNumIndices;
            if (k == 0)
                return model_fail(why, n, "mesh %u face %u has no corners", i, f);
            types |= k == 1 ? aiPrimitiveType_POINT : k == 2 ? aiPrimitiveType_LINE
                     : k == 3 ? aiPrimitiveType_TRIANGLE : aiPrimitiveType_POLYGON;
        }
        unsigned said = mesh->mPrimitiveTypes & (aiPrimitiveType_POINT | aiPrimitiveType_LINE |
                                                 aiPrimitiveType_TRIANGLE | aiPrimitiveType_POLYGON);
        if (said != types)
            return model_fail(why, n, "mesh %u: its faces do not match the primitive types Assimp read for it "
                        "(0x%x, faces 0x%x): a malformed file", i, said, types);
    }
    return true;
}

/* Positions and the normals the file gives (none are made yet) must be finite. A zero-length
 * normal passes: the loader replaces it by +Y (docs/hard-cases.md, case 9). */
static bool check_vertices(const struct aiScene *sc, char *why, size_t n)
{
    for (unsigned i = 0; i < sc->mNumMeshes; i++) {
        const struct aiMesh *mesh = sc->mMeshes[i];
        for (unsigned v = 0; v < mesh->mNumVertices; v++) {
            if (!finite3(&mesh->mVertices[v]))
                return model_fail(why, n, "mesh %u vertex %u: a position that is not a finite number", i, v);
            if (mesh->mNormals && !finite3(&mesh->mNormals[v]))
                return model_fail(why, n, "mesh %u vertex %u: a normal that is not a finite number", i, v);
        }
    }
    return true;
}

/* One aiImportFileEx; what Assimp left open (it throws past its own closes on some short files)
 * is closed after it. */
static const struct aiScene *import_with(const char *name, unsigned flags, struct aiFileIO *fio, io_state *io)
{
    importing = io;
    const struct aiScene *sc = aiImportFileEx(name, flags, fio);
    importing = NULL;
    while (io->open)
        io_close(fio, &io->open->file);
    return sc;
}

static const struct aiScene *import_bytes(const char *name, const char *data, size_t size, bool siblings,
                                          const model_limits *lim, unsigned post, char *why, size_t n)
{
    io_state io = {.name = name, .data = data, .size = size, .siblings = siblings, .budget = lim->bytes};
    struct aiFileIO fio = {io_open, io_close, (aiUserData)(void *)&io};
    char quoted[MODEL_QUOTE_MAX + 8];
    /* 1. Import and validate only: a malformed file stops here, before any post-processing step
     * (triangulation, normals) walks arrays that are not there. */
    /* Attached once for the process: detaching the last stream destroys Assimp's logger, and a
     * logger made and destroyed around every import is one more thing to go wrong. */
    static bool attached;
    if (!attached) {
        struct aiLogStream stream = {keep_warning, NULL};
        aiAttachLogStream(&stream);
        attached = true;
    }
    assimp_warning[0] = '\0';
    const struct aiScene *sc = import_with(name, aiProcess_ValidateDataStructure, &fio, &io);
    if (io.outside) {
        if (sc)
            aiReleaseImport(sc);
        model_fail(why, n, "a file it names lies outside the model's folder");
        return NULL;
    }
    if (io.guessing) {
        if (sc)
            aiReleaseImport(sc);
        model_fail(why, n, "its content is not what its extension says (Assimp found no reader for it)");
        return NULL;
    }
    if (sc && !io.over && assimp_warning[0]) {
        aiReleaseImport(sc);
        model_fail(why, n, "%s", assimp_warning);
        return NULL;
    }
    if (!sc || io.over) {
        model_quote(sc ? "" : aiGetErrorString(), quoted, sizeof quoted);
        if (sc)
            aiReleaseImport(sc);
        if (io.over)
            model_fail(why, n, "the files it names hold more than %lld bytes (COURSE_MODEL_MAX_BYTES)", lim->bytes);
        else
            model_fail(why, n, "%s", quoted[0] ? quoted : "Assimp gave no reason");
        return NULL;
    }
    /* 2. What the post-processing will make is bounded by what was read: a polygon of k corners
     * becomes k - 2 triangles. */
    unsigned long long vertices = 0, triangles = 0;
    for (unsigned i = 0; i < sc->mNumMeshes; i++) {
        const struct aiMesh *mesh = sc->mMeshes[i];
        vertices += mesh->mNumVertices;
        for (unsigned f = 0; f < mesh->mNumFaces; f++)
            triangles += mesh->mFaces[f].mNumIndices > 3 ? mesh->mFaces[f].mNumIndices - 2 : 1;
    }
    if (vertices > (unsigned long long)lim->vertices || triangles > (unsigned long long)lim->faces) {
        model_fail(why, n, "it holds %llu vertices and %llu triangles, more than the limits of %ld and %ld "
             "(COURSE_MODEL_MAX_VERTICES, COURSE_MODEL_MAX_FACES)", vertices, triangles, lim->vertices, lim->faces);
        aiReleaseImport(sc);
        return NULL;
    }
    bool usable = sc->mNumMeshes > 0 ? check_faces(sc, why, n) && check_vertices(sc, why, n)
                                      : model_fail(why, n, "it holds no meshes");
    aiReleaseImport(sc);
    if (!usable)
        return NULL;
    /* 3. The post-processing, on data that passed: the file is imported again with the steps.
     * aiApplyPostProcessing on the first import would save the read, but when a step fails
     * (FindInvalidData leaving no mesh) Assimp 5.2 releases the scene through freed memory. */
    io.used = 0;
    const struct aiScene *done = import_with(name, aiProcess_ValidateDataStructure | post, &fio, &io);
    if (!done || io.over || io.outside) {
        model_quote(done ? "" : aiGetErrorString(), quoted, sizeof quoted);
        if (done)
            aiReleaseImport(done);
        model_fail(why, n, "%s", quoted[0] ? quoted : "the files it names changed while it was read");
        return NULL;
    }
    return done;
}

const struct aiScene *model_import(const char *name, const char *data, size_t size, bool siblings,
                                   const model_limits *lim, unsigned post, char *why, size_t n)
{
    const char *format = model_format_of(name);
    if (!format || (strcmp(format, "gltf") != 0 && strcmp(format, "glb") != 0))
        return import_bytes(name, data, size, siblings, lim, post, why, n);
    /* glTF: Assimp reads the document model_gltf_check checked, never the file's own bytes. */
    size_t checked_size;
    char *checked = model_gltf_check(name, data, size, siblings, lim, &checked_size, why, n);
    if (!checked)
        return NULL;
    const struct aiScene *sc = import_bytes(name, checked, checked_size, siblings, lim, post, why, n);
    free(checked);
    return sc;
}
