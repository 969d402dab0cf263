/* fuzz_model.c - libFuzzer target for the model path (mesh_data_load_memory: the pre-scan, Assimp's
 * validated import and post-processing, the copy into a mesh).
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

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const names[] = {"fuzz.obj", "fuzz.ply", "fuzz.off", "fuzz.stl", "fuzz.gltf", "fuzz.glb"};
    if (size < 1)
        return 0;
    mesh_data m;
    if (!mesh_data_load_memory(&m, names[data[0] % 6], data + 1, size - 1, "fuzz"))
        return 0;
    /* What the renderer trusts once the loader said yes: whole triangles, indices that name a
     * vertex, finite positions and unit normals. */
    if (m.vertex_count < 1 || m.index_count < 3 || m.index_count % 3 != 0 || !m.vertices || !m.indices)
        abort();
    for (int i = 0; i < m.index_count; i++)
        if (m.indices[i] >= (uint32_t)m.vertex_count)
            abort();
    for (int v = 0; v < m.vertex_count; v++) {
        const float *p = m.vertices + (size_t)v * MESH_VERTEX_FLOATS;
        float len = sqrtf(p[3] * p[3] + p[4] * p[4] + p[5] * p[5]);
        if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]) || !(fabsf(len - 1.0f) < 1e-3f))
            abort();
    }
    mesh_data_destroy(&m);
    return 0;
}
