/* forward.c - see forward.h. */
#include "forward.h"

#include "frame_timer.h"
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
    f->shaded_pixels = -1;
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
bool forward_build_light_lists(forward *f, const gpu_scene *gs)
{
    frame_timer_mark("light lists");
    int objects = gs->src->object_count;
    size_t n = 2 * (size_t)objects;
    if (!list_reserve(f, n + 1))
        return false;
    for (int i = 0; i < objects; i++) {
        const float *b = gs->bounds[i];
        size_t first = n;
        for (int k = 0; k < gs->light_count; k++) {
            const gpu_light *l = &gs->lights[k];
            float reach = l->radius + b[3];
            if (glm_vec3_distance2((float *)l->position, (float *)b) > reach * reach)
                continue;
            if (!list_reserve(f, n + 1))
                return false;
            f->list[n++] = k;
        }
        f->list[2 * i] = (int)first;
        f->list[2 * i + 1] = (int)(n - first);
    }
    f->list_entries = (long)(n - 2 * (size_t)objects);
    gl_texture_buffer_upload(f->list_buffer, f->list_texture, GL_R32I, f->list, (n ? n : 1) * sizeof(int));
    return true;
}

void forward_draw_depth(const forward *f, const gpu_scene *gs)
{
    frame_timer_mark("depth pre-pass");
    glUseProgram(f->depth_program);
    gpu_scene_bind_objects(gs, f->depth_program, SHADER_UNIT_OBJECTS);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    gpu_scene_draw(gs, f->depth_program);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

/* The linear program is built on first use: only the benchmark and the tests ask for it. */
static GLuint shading_program(forward *f, bool linear)
{
    if (linear && !f->linear_program)
        f->linear_program = gl_program_load("forward.vert", "forward.frag", "OUTPUT_LINEAR 1");
    return linear ? f->linear_program : f->program;
}

bool forward_draw_shaded(forward *f, const gpu_scene *gs, forward_options options)
{
    GLuint program = shading_program(f, options.linear_output);
    if (!program)
        return false;
    frame_timer_mark("shading");
    glUseProgram(program);
    gpu_scene_bind_lights(gs, program, SHADER_UNIT_LIGHTS);
    gpu_scene_bind_objects(gs, program, SHADER_UNIT_OBJECTS);
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_LIGHT_LIST);
    glBindTexture(GL_TEXTURE_BUFFER, f->list_texture);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(glGetUniformLocation(program, "u_light_list"), SHADER_UNIT_LIGHT_LIST);
    glUniform3fv(glGetUniformLocation(program, "u_eye"), 1, gs->view.eye);
    glUniform1i(glGetUniformLocation(program, "u_use_list"), options.light_lists);
    gl_samples_begin(f->query, options.count_pixels);
    gpu_scene_draw(gs, program);
    f->shaded_pixels = gl_samples_end(f->query, options.count_pixels);
    return true;
}

bool forward_render(forward *f, const gpu_scene *gs, GLuint target, forward_options options)
{
    if (options.light_lists && !forward_build_light_lists(f, gs))
        return false;
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, gs->view.width, gs->view.height);
    /* LEQUAL everywhere (the depth-tie rule in forward.h); after a pre-pass, EQUAL without writes */
    gl_pass_state depth = {.cull = GL_BACK, .depth_func = GL_LEQUAL, .depth_write = true};
    gl_pass_state_apply(&depth);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (options.prepass) {
        forward_draw_depth(f, gs);
        depth.depth_func = GL_EQUAL, depth.depth_write = false;
        gl_pass_state_apply(&depth);
    }
    bool ok = forward_draw_shaded(f, gs, options);
    gl_pass_state_reset();
    return ok;
}

long forward_shaded_pixels(const forward *f) { return f->shaded_pixels; }
