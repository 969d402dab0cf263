/* test_scene_programs.c - every program a chapter builds is built for its scene (common/gl/
 * shader_features.h): on a Blinn-Phong scene without images (the default scene), no program of any
 * chapter, in any of its renderers, declares a material image's sampler (sampler2DArray, material_maps.glsl)
 * and the scene's defines name neither chapter 18's model nor its maps; on a scene whose metallic-
 * roughness materials sample images (pbr_teapots), the same check finds those samplers, so it can fail.
 *
 *   test_scene_programs BLINN_PHONG_SCENE MAPS_SCENE
 *
 * Exit 0 when every check holds, 1 when one fails, 77 when no GL context can be made.
 */
#include "app_embed.h"
#include "chapters.h"
#include "gl_program.h"
#include "hard_util.h"

#include <stdio.h>
#include <string.h>

#define W 96
#define H 72

static const app_desc *const chapters[] = {&chapter_00, &chapter_01, &chapter_02, &chapter_03, &chapter_04,
                                           &chapter_05, &chapter_06, &chapter_07, &chapter_08, &chapter_09,
                                           &chapter_10, &chapter_11, &chapter_12, &chapter_13, &chapter_14,
                                           &chapter_15, &chapter_16, &chapter_17, &chapter_18, &chapter_19};

/* The material-image samplers among the active uniforms of the live programs the chapter built. */
static int map_samplers(char *where, size_t size)
{
    const gl_program_info *list;
    int n = gl_program_compiled(&list), found = 0;
    for (int i = 0; i < n; i++) {
        if (!list[i].program)
            continue;
        GLint uniforms = 0;
        glGetProgramiv(list[i].program, GL_ACTIVE_UNIFORMS, &uniforms);
        for (GLint u = 0; u < uniforms; u++) {
            char name[128];
            GLint count;
            GLenum type;
            glGetActiveUniform(list[i].program, (GLuint)u, sizeof name, NULL, &count, &type, name);
            if (type == GL_SAMPLER_2D_ARRAY && found++ == 0)
                snprintf(where, size, "%s in %s", name, list[i].name);
        }
    }
    return found;
}

/* Chapter c on gs, one frame in each renderer it offers: the map samplers its programs declare. */
static int chapter_map_samplers(const app_desc *c, const gpu_scene *gs, char *where, size_t size)
{
    int found = 0;
    for (int r = 0; c->cli->renderers && c->cli->renderers[r]; r++) {
        const char *args[] = {"--renderer", c->cli->renderers[r], NULL};
        app_embed *e = NULL;
        bool ok = app_embed_open(c, args, gs, &e) && app_embed_frame(e, gs, false, NULL);
        hard_expect(ok, "%s --renderer %s: a frame", c->cli->program, c->cli->renderers[r]);
        found += ok ? map_samplers(where, size) : 0;
        app_embed_close(e);
    }
    return found;
}

static bool load(const char *path, scene *s, gpu_scene *gs)
{
    return hard_expect(scene_load(path, s) && gpu_scene_create(s, gs) &&
                           gpu_scene_update(gs, 0.0f, 5.0 / 256.0, W, H),
                       "load %s", path);
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: %s BLINN_PHONG_SCENE MAPS_SCENE\n", argv[0]);
        return 2;
    }
    hard_context_create(W, H);
    app_forward_set_plus(&chapter_11_forward_plus); /* every chapter's forward-plus, as their main() */
    scene s;
    gpu_scene gs;
    if (load(argv[1], &s, &gs)) {
        for (size_t i = 0; i < sizeof chapters / sizeof *chapters; i++) {
            char where[256] = "";
            int n = chapter_map_samplers(chapters[i], &gs, where, sizeof where);
            hard_expect(n == 0, "%s on %s: %d material-image sampler(s) in its programs%s%s",
                        chapters[i]->cli->program, argv[1], n, n ? ", first " : "", where);
        }
        const app_desc *c = &chapter_11;
        app_embed *e = NULL;
        const char *defines = "";
        if (app_embed_open(c, NULL, &gs, &e))
            defines = gl_program_scene_defines();
        hard_expect(e && strstr(defines, "MATERIAL_BLINN_PHONG") && !strstr(defines, "MATERIAL_PBR") &&
                        !strstr(defines, "MATERIAL_MAPS") && !strstr(defines, "LIGHT_SPOT"),
                    "the default scene's defines: Blinn-Phong only, no maps, no spot ('%s')", defines);
        app_embed_close(e);
        gpu_scene_destroy(&gs);
        scene_destroy(&s);
    }
    if (load(argv[2], &s, &gs)) {
        char where[256] = "";
        int n = chapter_map_samplers(&chapter_18, &gs, where, sizeof where);
        hard_expect(n > 0, "chapter 18 on %s: %d material-image sampler(s) (first %s): the check sees them",
                    argv[2], n, where);
        gpu_scene_destroy(&gs);
        scene_destroy(&s);
    }
    return hard_finish();
}
