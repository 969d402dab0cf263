/* forward.c - see forward.h. */
#include "forward.h"

#include "gl_util.h"
#include "log.h"

#include <stdlib.h>
#include <string.h>

bool forward_create(forward *f)
{
    memset(f, 0, sizeof *f);
    f->program = gl_program_load("forward.vert", "forward.frag", NULL);
    f->depth_program = gl_program_load("forward.vert", "depth_only.frag", NULL);
    if (!f->program || !f->depth_program) {
        forward_destroy(f);
        return false;
    }
    f->list_buffer = gl_buffer_create();
    f->list_texture = gl_texture_create();
    f->query = gl_query_create();
    return gl_check("forward_create");
}

void forward_destroy(forward *f)
{
    gl_program_destroy(&f->program);
    gl_program_destroy(&f->depth_program);
    gl_program_destroy(&f->linear_program);
    gl_buffer_destroy(&f->list_buffer);
    gl_texture_destroy(&f->list_texture);
    gl_query_destroy(&f->query);
    free(f->list);
    memset(f, 0, sizeof *f);
}

static bool list_reserve(forward *f, size_t n)
{
    if (n <= f->list_cap)
        return true;
    size_t cap = f->list_cap ? f->list_cap : 4096;
    while (cap < n)
        cap *= 2;
    int *list = realloc(f->list, cap * sizeof *list);
    if (!list) {
        log_error("out of memory for light lists");
        return false;
    }
    f->list = list;
    f->list_cap = cap;
    return true;
}

/* Per object, the lights whose sphere of influence touches the object's bounding sphere.
 * Layout: (first, count) for each object, then the indices; forward.frag reads it the same way. */
static bool build_light_lists(forward *f, const gpu_scene *gs)
{
    int objects = gs->src->object_count;
    size_t n = 2 * (size_t)objects;
    if (!list_reserve(f, n + 1))
        return false;
    for (int i = 0; i < objects; i++) {
        const float *b = gs->bounds[i];
        size_t first = n;
        for (int k = 0; k < gs->light_count; k++) {
            const gpu_light *l = &gs->lights[k];
            float dx = l->position[0] - b[0], dy = l->position[1] - b[1], dz = l->position[2] - b[2];
            float reach = l->radius + b[3];
            if (dx * dx + dy * dy + dz * dz > reach * reach)
                continue;
            if (!list_reserve(f, n + 1))
                return false;
            f->list[n++] = k;
        }
        f->list[2 * i] = (int)first;
        f->list[2 * i + 1] = (int)(n - first);
    }
    f->list_entries = (long)(n - 2 * (size_t)objects);
    glBindBuffer(GL_TEXTURE_BUFFER, f->list_buffer);
    glBufferData(GL_TEXTURE_BUFFER, (GLsizeiptr)((n ? n : 1) * sizeof(int)), f->list, GL_STREAM_DRAW);
    glBindTexture(GL_TEXTURE_BUFFER, f->list_texture);
    glTexBuffer(GL_TEXTURE_BUFFER, GL_R32I, f->list_buffer);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    return true;
}

/* The linear program is built on first use: only the benchmark and the tests ask for it. */
static bool load_linear_program(forward *f)
{
    if (!f->linear_program)
        f->linear_program = gl_program_load("forward.vert", "forward.frag", "OUTPUT_LINEAR 1");
    return f->linear_program != 0;
}

bool forward_render(forward *f, const gpu_scene *gs, forward_options options)
{
    if (options.light_lists && !build_light_lists(f, gs))
        return false;
    if (options.linear_output && !load_linear_program(f))
        return false;
    GLuint program = options.linear_output ? f->linear_program : f->program;

    glViewport(0, 0, gs->view.width, gs->view.height);
    glClearColor(0, 0, 0, 1);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE); /* planes are single-sided */
    glCullFace(GL_BACK);
    glDisable(GL_BLEND);
    glDepthFunc(GL_LEQUAL);

    if (options.prepass) {
        glUseProgram(f->depth_program);
        gpu_scene_bind_objects(gs, f->depth_program, 2);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        gpu_scene_draw(gs, f->depth_program);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDepthFunc(GL_EQUAL);
        glDepthMask(GL_FALSE);
    }

    glUseProgram(program);
    gpu_scene_bind_lights(gs, program, 0);
    gpu_scene_bind_objects(gs, program, 2);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_BUFFER, f->list_texture);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(glGetUniformLocation(program, "u_light_list"), 1);
    glUniform3fv(glGetUniformLocation(program, "u_eye"), 1, gs->view.eye);
    glUniform1i(glGetUniformLocation(program, "u_use_list"), options.light_lists);
    if (options.count_pixels)
        glBeginQuery(GL_SAMPLES_PASSED, f->query);
    gpu_scene_draw(gs, program);
    if (options.count_pixels) {
        glEndQuery(GL_SAMPLES_PASSED);
        GLuint samples = 0;
        glGetQueryObjectuiv(f->query, GL_QUERY_RESULT, &samples);
        f->shaded_pixels = (long)samples;
    }
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    return true;
}

long forward_shaded_pixels(const forward *f) { return f->shaded_pixels; }
