/* fuzz_scene.c - libFuzzer target for the scene parser (scene_parse_string).
 *
 *   LLVMFuzzerTestOneInput(data, size)   parse the bytes as a scene; on success, evaluate every
 *                                        object and light at a few times and free the scene
 *
 * Whatever the bytes, the parser must return true or false without reading out of bounds, leaking,
 * overflowing a signed integer or leaving half a scene behind. Model paths resolve against folders
 * that do not exist (the scene's and the data folder), so a "mesh NAME file PATH" line only ever
 * probes a missing file (or an absolute path).
 */
#include "data_dir.h"
#include "model_import.h"
#include "scene.h"

#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_util.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    /* scene_parse_string takes a C string: a NUL inside the input just ends it early. */
    char *text = fuzz_text(data, size);
    if (!text)
        return 0;

    data_dir_set("/nonexistent-fuzz-data"); /* a model path is looked for in the data folder too */
    scene s;
    if (scene_parse_string(text, "fuzz.scene", "/nonexistent-fuzz-dir", &s)) {
        const float times[] = {-1.0f, 0.0f, 0.5f, 3.0f, 1e9f};
        for (size_t t = 0; t < sizeof times / sizeof times[0]; t++) {
            for (int i = 0; i < s.object_count; i++) {
                mat4 world;
                scene_object_world_at(&s, i, times[t], world);
            }
            for (int i = 0; i < s.light_count; i++) {
                vec3 position;
                scene_light_position_at(&s, i, times[t], position);
            }
        }
        /* Appending a light copies its keys; the copy must be owned by the scene. The light is
         * copied first: scene_add_light may move the array it points into. */
        if (s.light_count > 0) {
            scene_light first = s.lights[0];
            scene_add_light(&s, &first);
        }
        scene_destroy(&s);
    }
    model_import_release(); /* a model line's file, kept for its meshes (none are built here) */
    free(text);
    return 0;
}
