/* scene_check.c - parse scene files and print one summary line each; the quick way to find a typo.
 *
 *   scene_check [--help] SCENE...
 *
 * Each scene's meshes are built too (model files loaded through Assimp), and their triangle counts
 * printed, so a model that does not load is found here rather than at render time.
 * Exit status: 0 when every scene and its models load, 2 on a usage error or when any fails (the
 * parser or the loader has already printed "file:line: message" for it).
 */
#include "log.h"
#include "mesh_data.h"
#include "model_import.h"
#include "scene.h"

#include <stdio.h>
#include <string.h>

static void print_usage(FILE *to)
{
    fputs("usage: scene_check [--help] SCENE...\n"
          "Parse each scene file, build its meshes (loading model files), and print a summary.\n"
          "Exit status 0 when all scenes are valid, 2 otherwise; errors are printed as FILE:LINE: message.\n",
          to);
}

/* One line per mesh: its triangles, from the built shape or the loaded model. */
static bool check_meshes(const scene *s)
{
    bool ok = true;
    for (int i = 0; i < s->mesh_count; i++) {
        const scene_mesh *decl = &s->meshes[i];
        mesh_data m;
        if (!mesh_data_from_scene(&m, s, decl)) {
            ok = false;
            continue;
        }
        printf("  mesh %s: %d triangles, %d vertices%s%s\n", decl->name, m.index_count / 3, m.vertex_count,
               decl->kind == SCENE_MESH_FILE ? " from " : "", decl->kind == SCENE_MESH_FILE ? decl->path : "");
        mesh_data_destroy(&m);
    }
    model_import_release(); /* the model files' meshes are built */
    return ok;
}

static void print_summary(const scene *s)
{
    const scene_camera *c = &s->camera;
    printf("%s: %d objects, %d lights, %d meshes, %d materials, %d textures; camera eye (%g, %g, %g) target (%g, %g, "
           "%g) fovy %g near %g far %g\n",
           s->path, s->object_count, s->light_count, s->mesh_count, s->material_count, s->texture_count, c->eye[0], c->eye[1],
           c->eye[2], c->target[0], c->target[1], c->target[2], c->fovy_deg, c->near_plane, c->far_plane);
}

int main(int argc, char **argv)
{
    /* Options first; "--" ends them so that a scene may be named "-x.scene". */
    int first = 1;
    for (; first < argc && argv[first][0] == '-' && argv[first][1] != '\0'; first++) {
        if (strcmp(argv[first], "--") == 0) {
            first++;
            break;
        }
        if (strcmp(argv[first], "--help") == 0 || strcmp(argv[first], "-h") == 0) {
            print_usage(stdout);
            return 0;
        }
        log_error("scene_check: unknown option '%s'", argv[first]);
        print_usage(stderr);
        return 2;
    }
    if (first >= argc) {
        log_error("scene_check: no scene file given");
        print_usage(stderr);
        return 2;
    }
    int status = 0;
    for (int i = first; i < argc; i++) {
        scene s;
        if (!scene_load(argv[i], &s)) {
            status = 2;
            continue;
        }
        print_summary(&s);
        if (!check_meshes(&s))
            status = 2;
        scene_destroy(&s);
    }
    return status;
}
