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
    GLuint p = f->program;
    f->loc.object.model = glGetUniformLocation(p, "u_model");
    f->loc.object.normal_matrix = glGetUniformLocation(p, "u_normal_matrix");
    f->loc.view_proj = glGetUniformLocation(p, "u_view_proj");
    f->loc.eye = glGetUniformLocation(p, "u_eye");
    f->loc.albedo = glGetUniformLocation(p, "u_albedo");
    f->loc.specular = glGetUniformLocation(p, "u_specular");
    f->loc.shininess = glGetUniformLocation(p, "u_shininess");
    f->loc.use_list = glGetUniformLocation(p, "u_use_list");
    f->loc.light_list = glGetUniformLocation(p, "u_light_list");
    f->loc.list_offset = glGetUniformLocation(p, "u_list_offset");
    f->loc.list_count = glGetUniformLocation(p, "u_list_count");
    f->loc.depth_object.model = glGetUniformLocation(f->depth_program, "u_model");
    f->loc.depth_object.normal_matrix = glGetUniformLocation(f->depth_program, "u_normal_matrix");
    f->loc.depth_view_proj = glGetUniformLocation(f->depth_program, "u_view_proj");
    f->list_buffer = gl_buffer_create();
    f->list_texture = gl_texture_create();
    glGenQueries(1, &f->query);
    return gl_check("forward_create");
}

void forward_destroy(forward *f)
{
    gl_program_destroy(&f->program);
    gl_program_destroy(&f->depth_program);
    gl_program_destroy(&f->linear_program);
    gl_buffer_destroy(&f->list_buffer);
    gl_texture_destroy(&f->list_texture);
    if (f->query)
        glDeleteQueries(1, &f->query);
    free(f->list);
    free(f->offsets);
    free(f->counts);
    memset(f, 0, sizeof *f);
}

/* Per object, the lights whose sphere of influence touches the object's bounding sphere. */
static bool build_light_lists(forward *f, const gpu_scene *gs)
{
    int objects = gs->src->object_count;
    if (objects > f->object_cap) {
        int *o = realloc(f->offsets, (size_t)objects * sizeof *o);
        int *c = realloc(f->counts, (size_t)objects * sizeof *c);
        if (o)
            f->offsets = o;
        if (c)
            f->counts = c;
        if (!o || !c) {
            log_error("out of memory for light lists");
            return false;
        }
        f->object_cap = objects;
    }
    size_t n = 0;
    for (int i = 0; i < objects; i++) {
        const float *b = gs->bounds[i];
        f->offsets[i] = (int)n;
        for (int k = 0; k < gs->light_count; k++) {
            const gpu_light *l = &gs->lights[k];
            float dx = l->position[0] - b[0], dy = l->position[1] - b[1], dz = l->position[2] - b[2];
            float reach = l->radius + b[3];
            if (dx * dx + dy * dy + dz * dz > reach * reach)
                continue;
            if (n == f->list_cap) {
                size_t cap = f->list_cap ? 2 * f->list_cap : 4096;
                int *list = realloc(f->list, cap * sizeof *list);
                if (!list) {
                    log_error("out of memory for light lists");
                    return false;
                }
                f->list = list;
                f->list_cap = cap;
            }
            f->list[n++] = k;
        }
        f->counts[i] = (int)n - f->offsets[i];
    }
    f->list_entries = (long)n;
    static const int zero = 0;
    glBindBuffer(GL_TEXTURE_BUFFER, f->list_buffer);
    glBufferData(GL_TEXTURE_BUFFER, n ? (GLsizeiptr)(n * sizeof(int)) : (GLsizeiptr)sizeof zero,
                 n ? (const void *)f->list : &zero, GL_STREAM_DRAW);
    glBindTexture(GL_TEXTURE_BUFFER, f->list_texture);
    glTexBuffer(GL_TEXTURE_BUFFER, GL_R32I, f->list_buffer);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    return true;
}

/* The linear program is built on first use: only the benchmark asks for it. */
static bool load_linear_program(forward *f)
{
    if (f->linear_program)
        return true;
    GLuint p = gl_program_load("forward.vert", "forward.frag", "OUTPUT_LINEAR 1");
    if (!p)
        return false;
    f->linear_program = p;
    f->linear_loc.object.model = glGetUniformLocation(p, "u_model");
    f->linear_loc.object.normal_matrix = glGetUniformLocation(p, "u_normal_matrix");
    f->linear_loc.view_proj = glGetUniformLocation(p, "u_view_proj");
    f->linear_loc.eye = glGetUniformLocation(p, "u_eye");
    f->linear_loc.albedo = glGetUniformLocation(p, "u_albedo");
    f->linear_loc.specular = glGetUniformLocation(p, "u_specular");
    f->linear_loc.shininess = glGetUniformLocation(p, "u_shininess");
    f->linear_loc.use_list = glGetUniformLocation(p, "u_use_list");
    f->linear_loc.light_list = glGetUniformLocation(p, "u_light_list");
    f->linear_loc.list_offset = glGetUniformLocation(p, "u_list_offset");
    f->linear_loc.list_count = glGetUniformLocation(p, "u_list_count");
    return true;
}

bool forward_render(forward *f, const gpu_scene *gs, forward_options options)
{
    const scene *s = gs->src;
    if (options.light_lists && !build_light_lists(f, gs))
        return false;
    if (options.linear_output && !load_linear_program(f))
        return false;
    GLuint program = f->program;
    forward_locations loc = {.object = f->loc.object,
                             .view_proj = f->loc.view_proj,
                             .eye = f->loc.eye,
                             .albedo = f->loc.albedo,
                             .specular = f->loc.specular,
                             .shininess = f->loc.shininess,
                             .use_list = f->loc.use_list,
                             .light_list = f->loc.light_list,
                             .list_offset = f->loc.list_offset,
                             .list_count = f->loc.list_count};
    if (options.linear_output)
        program = f->linear_program, loc = f->linear_loc;

    glViewport(0, 0, gs->view.width, gs->view.height);
    glClearColor(0, 0, 0, 1);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE); /* planes are single-sided */
    glCullFace(GL_BACK);
    glDisable(GL_BLEND);

    if (options.prepass) {
        glUseProgram(f->depth_program);
        glUniformMatrix4fv(f->loc.depth_view_proj, 1, GL_FALSE, (const float *)gs->view.view_proj);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glDepthFunc(GL_LESS);
        for (int i = 0; i < s->object_count; i++)
            gpu_scene_draw_object(gs, i, f->loc.depth_object);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDepthFunc(GL_EQUAL);
        glDepthMask(GL_FALSE);
    } else {
        glDepthFunc(GL_LESS);
    }

    glUseProgram(program);
    gpu_scene_bind_lights(gs, program, 0);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_BUFFER, f->list_texture);
    glUniform1i(loc.light_list, 1);
    glActiveTexture(GL_TEXTURE0);
    glUniformMatrix4fv(loc.view_proj, 1, GL_FALSE, (const float *)gs->view.view_proj);
    glUniform3fv(loc.eye, 1, gs->view.eye);
    glUniform1i(loc.use_list, options.light_lists);
    if (options.count_pixels)
        glBeginQuery(GL_SAMPLES_PASSED, f->query);
    for (int i = 0; i < s->object_count; i++) {
        if (options.light_lists) {
            glUniform1i(loc.list_offset, f->offsets[i]);
            glUniform1i(loc.list_count, f->counts[i]);
        }
        const scene_material *m = &s->materials[s->objects[i].material];
        glUniform3fv(loc.albedo, 1, m->albedo);
        glUniform1f(loc.specular, m->specular);
        glUniform1f(loc.shininess, m->shininess);
        gpu_scene_draw_object(gs, i, loc.object);
    }
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
