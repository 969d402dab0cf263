/* fuzz_model.c - libFuzzer target for the model path (mesh_data_load_memory: the pre-scan, Assimp's
 * validated import and post-processing, the copy into a mesh) and, for glTF, the model directive's
 * import (model_import_scene: materials, images, nodes, lights, and each mesh built alone).
 *
 *   LLVMFuzzerTestOneInput(data, size)   the first byte picks the format (obj, ply, off, stl, gltf,
 *                                        glb: every one the course reads), the rest is the file;
 *                                        a mesh it accepts must be one the renderer can draw
 *
 * Whatever the bytes, loading must return true or false without crashing, aborting inside Assimp,
 * leaking or running out of memory (run_fuzz.sh caps the process at -rss_limit_mb). A seed file is
 * its format byte followed by a model file: see tests/fuzz/corpus_model/.
 */
#include "mesh_data.h"
#include "model_import.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* What the renderer trusts once the loader said yes: whole triangles, indices that name a vertex,
 * finite positions and unit normals. */
static void check_mesh(const mesh_data *m)
{
    if (m->vertex_count < 1 || m->index_count < 3 || m->index_count % 3 != 0 || !m->vertices || !m->indices)
        abort();
    for (int i = 0; i < m->index_count; i++)
        if (m->indices[i] >= (uint32_t)m->vertex_count)
            abort();
    for (int v = 0; v < m->vertex_count; v++) {
        const float *p = m->vertices + (size_t)v * MESH_VERTEX_FLOATS;
        float len = sqrtf(p[3] * p[3] + p[4] * p[4] + p[5] * p[5]);
        if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]) || !(fabsf(len - 1.0f) < 1e-3f))
            abort();
    }
}

/* The model directive reads a file from disk (with the files it names beside it): the bytes go to
 * a file of a folder made once, and every mesh of what it accepts is built. */
static char dir[512];

/* The folder goes when the run ends (each file in it is removed after its input). */
static void remove_dir(void) { rmdir(dir); }

static void import_gltf(const char *name, const uint8_t *data, size_t size)
{
    if (!dir[0]) {
        const char *tmp = getenv("TMPDIR"); /* fuzz.replay.model_cleans_up points it at an empty folder */
        if (snprintf(dir, sizeof dir, "%s/fuzz_model_XXXXXX", tmp && *tmp ? tmp : "/tmp") >= (int)sizeof dir ||
            !mkdtemp(dir))
            abort();
        atexit(remove_dir);
    }
    char path[sizeof dir + 16];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(data, 1, size, f) != size || fclose(f) != 0)
        abort();
    model_import_release(); /* a file written within the same clock tick could look unchanged */
    scene part;
    char why[512];
    if (model_import_scene(path, "fuzz", &part, why, sizeof why)) {
        for (int i = 0; i < part.object_count; i++)
            if (part.objects[i].mesh < 0 || part.objects[i].mesh >= part.mesh_count ||
                part.objects[i].material < 0 || part.objects[i].material >= part.material_count)
                abort();
        for (int i = 0; i < part.mesh_count; i++) {
            mesh_data m;
            if (!mesh_data_from_scene(&m, &part, &part.meshes[i]))
                continue;
            check_mesh(&m);
            mesh_data_destroy(&m);
        }
        model_import_free(&part);
    }
    model_import_release();
    unlink(path);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const names[] = {"fuzz.obj", "fuzz.ply", "fuzz.off", "fuzz.stl", "fuzz.gltf", "fuzz.glb"};
    if (size < 1)
        return 0;
    const char *name = names[data[0] % 6];
    if (data[0] % 6 >= 4)
        import_gltf(name, data + 1, size - 1);
    mesh_data m;
    if (!mesh_data_load_memory(&m, name, data + 1, size - 1, "fuzz"))
        return 0;
    check_mesh(&m);
    mesh_data_destroy(&m);
    return 0;
}
