/* clusters.c - see clusters.h. */
#include "clusters.h"

#include "frame_timer.h"
#include "gl_program.h"
#include "gl_util.h"
#include "log.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>

/* The views of shaders/clusters.glsl beside SHADER_VIEW_LIT and SHADER_VIEW_OVERDRAW. */
enum { VIEW_CLUSTERS = 3, VIEW_COUNT = 4 };

bool clusters_create(clusters *c, const clusters_desc *desc)
{
    memset(c, 0, sizeof *c);
    if (desc)
        c->desc = *desc;
    if (c->desc.tile_size <= 0)
        c->desc.tile_size = CLUSTERS_TILE_SIZE;
    c->range_buffer = gl_buffer_create();
    c->list_buffer = gl_buffer_create();
    c->range_texture = gl_texture_create();
    c->list_texture = gl_texture_create();
    c->evaluations = c->covered = -1;
    return cluster_assign_gpu_create(&c->gpu) && gl_check("clusters_create");
}

void clusters_destroy(clusters *c)
{
    for (int i = 0; i < CLUSTERS_PROGRAM_COUNT; i++)
        gl_program_variants_destroy(&c->programs[i]);
    gl_buffer_destroy(&c->range_buffer);
    gl_buffer_destroy(&c->list_buffer);
    gl_texture_destroy(&c->range_texture);
    gl_texture_destroy(&c->list_texture);
    fbo_destroy(&c->count_target);
    cluster_lists_destroy(&c->lists);
    cluster_lists_destroy(&c->readback);
    cluster_assign_gpu_destroy(&c->gpu);
    free(c->spheres);
    free(c->count_pixels);
    memset(c, 0, sizeof *c);
}

bool clusters_light_spheres(clusters *c, const gpu_scene *gs)
{
    const frame_view *v = &gs->view;
    /* Row 2 of the view matrix (cglm is column-major): the view depth of p is -dot(row, (p, 1)). */
    const mat4 *m = (const mat4 *)v->view;
    for (int i = 0; i < 4; i++)
        c->depth_row[i] = (*m)[i][2];
    if (gs->light_count > c->sphere_cap) {
        float(*s)[4] = realloc(c->spheres, (size_t)gs->light_count * sizeof *s);
        if (!s) {
            log_error("out of memory for the light spheres");
            return false;
        }
        c->spheres = s, c->sphere_cap = gs->light_count;
    }
    for (int i = 0; i < gs->light_count; i++) {
        const gpu_light *l = &gs->lights[i];
        float s[4];
        cluster_light_bounds(l->position, l->direction, l->radius, l->cos_outer, s);
        vec4 view;
        glm_mat4_mulv((vec4 *)v->view, (vec4){s[0], s[1], s[2], 1.0f}, view);
        c->spheres[i][0] = view[0], c->spheres[i][1] = view[1], c->spheres[i][2] = view[2];
        c->spheres[i][3] = s[3] >= CLUSTER_INFINITE_RADIUS ? CLUSTER_INFINITE_RADIUS : s[3];
    }
    return true;
}

void clusters_upload_lists(clusters *c)
{
    gl_texture_buffer_upload(c->range_buffer, c->range_texture, GL_RG32I, c->lists.ranges,
                             (size_t)cluster_grid_count(&c->grid) * 2 * sizeof(int));
    gl_texture_buffer_upload(c->list_buffer, c->list_texture, GL_R32I, c->lists.indices,
                             (size_t)(c->lists.entries + 1) * sizeof(int));
}

/* desc.check: the compute lists are the CPU's, or the first cluster where they are not, logged. */
static bool lists_same(const clusters *c)
{
    int at = cluster_lists_first_difference(&c->lists, &c->readback);
    if (at < 0)
        return true;
    const int *a = &c->lists.ranges[2 * at], *b = &c->readback.ranges[2 * at];
    int k = at / (c->grid.tiles_x * c->grid.tiles_y), t = at % (c->grid.tiles_x * c->grid.tiles_y);
    log_error("cluster %d (tile %d, %d, slice %d): the CPU's list (first %d, count %d) and the compute "
              "passes' (first %d, count %d) differ",
              at, t % c->grid.tiles_x, t / c->grid.tiles_x, k, a[0], a[1], b[0], b[1]);
    return false;
}

bool clusters_check(clusters *c, int lights, int limit)
{
    const cluster_assign_buffers out = {c->range_buffer, c->range_texture, c->list_buffer, c->list_texture};
    return cluster_lists_assign(&c->lists, &c->grid, (const float(*)[4])c->spheres, lights, limit) &&
           cluster_assign_gpu_read(&out, cluster_grid_count(&c->grid), &c->readback) && lists_same(c);
}

void clusters_bind(const clusters *c, GLuint program, int first_unit)
{
    const cluster_grid *g = &c->grid;
    glUseProgram(program);
    gl_texture_buffer_bind(program, "u_cluster_ranges", first_unit, c->range_texture);
    gl_texture_buffer_bind(program, "u_cluster_lights", first_unit + 1, c->list_texture);
    glUniform3i(glGetUniformLocation(program, "u_cluster_grid"), g->tiles_x, g->tiles_y, g->slices);
    glUniform1i(glGetUniformLocation(program, "u_cluster_tile"), g->tile_size);
    glUniform2f(glGetUniformLocation(program, "u_cluster_slicing"), g->near_plane, g->log_scale);
    glUniform4fv(glGetUniformLocation(program, "u_cluster_depth_row"), 1, c->depth_row);
}

GLuint clusters_program(clusters *c, clusters_program_id which)
{
    static const char *const files[CLUSTERS_PROGRAM_COUNT][3] = {
        [CLUSTERS_PROGRAM_DEPTH] = {"forward.vert", "depth_only.frag", NULL},
        [CLUSTERS_PROGRAM_FORWARD] = {"forward.vert", "forward_plus.frag", NULL},
        [CLUSTERS_PROGRAM_DEFERRED] = {"fullscreen.vert", "clustered_deferred.frag", NULL},
        [CLUSTERS_PROGRAM_GLASS] = {"forward.vert", "forward_plus.frag", "TRANSPARENT 1"},
    };
    return gl_program_variant(&c->programs[which], files[which][0], files[which][1], files[which][2], &c->desc.extra);
}

void clusters_set_extra(clusters *c, const gl_program_extra *extra)
{
    c->desc.extra = extra ? *extra : (gl_program_extra){0};
}

static int view_mode(clusters_view view)
{
    switch (view) {
    case CLUSTERS_VIEW_OVERDRAW: return SHADER_VIEW_OVERDRAW;
    case CLUSTERS_VIEW_CLUSTERS: return VIEW_CLUSTERS;
    case CLUSTERS_VIEW_COUNT: return VIEW_COUNT;
    default: return SHADER_VIEW_LIT;
    }
}

void clusters_use(const clusters *c, const gpu_scene *gs, GLuint program, clusters_view view)
{
    glUseProgram(program);
    gpu_scene_bind_lights(gs, program, SHADER_UNIT_LIGHTS);
    clusters_bind(c, program, SHADER_UNIT_LIGHT_INDEX); /* and the unit after it */
    glUniform3fv(glGetUniformLocation(program, "u_eye"), 1, gs->view.eye);
    glUniform1i(glGetUniformLocation(program, "u_view_mode"), view_mode(view));
    glUniform1i(glGetUniformLocation(program, "u_output_linear"), view == CLUSTERS_VIEW_LINEAR);
    gl_program_extra_bind(&c->desc.extra, program);
}

bool clusters_draw_depth(clusters *c, const gpu_scene *gs)
{
    GLuint p = clusters_program(c, CLUSTERS_PROGRAM_DEPTH);
    if (!p)
        return false;
    glUseProgram(p);
    gpu_scene_bind_objects(gs, p, SHADER_UNIT_OBJECTS);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    gpu_scene_draw(gs, p);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    return true;
}

bool clusters_shade_glass(clusters *c, const gpu_scene *gs, const gl_pass_state *const passes[], int pass_count,
                          gpu_scene_order order, clusters_view view)
{
    GLuint p = clusters_program(c, CLUSTERS_PROGRAM_GLASS);
    if (!p)
        return false;
    frame_timer_mark("transparent");
    clusters_use(c, gs, p, view == CLUSTERS_VIEW_OVERDRAW ? view : CLUSTERS_VIEW_LIT);
    gpu_scene_bind_objects(gs, p, SHADER_UNIT_OBJECTS); /* and with them each object's opacity */
    gpu_scene_draw_transparent(gs, p, order, passes, pass_count);
    gl_pass_state_reset();
    return gl_check("clusters: glass");
}

/* The count pass's target at the view's size: RGBA32F (covered, loop length) and a float depth. */
static bool count_target_follow(clusters *c, int w, int h)
{
    if (c->count_target.id && c->count_target.width == w && c->count_target.height == h)
        return true;
    fbo_destroy(&c->count_target);
    free(c->count_pixels);
    c->count_pixels = malloc((size_t)w * (size_t)h * 4 * sizeof(float));
    const fbo_desc desc = {.color_formats = {GL_RGBA32F},
                           .color_count = 1,
                           .depth_format = GL_DEPTH_COMPONENT32F,
                           .name = "cluster counts"};
    return c->count_pixels && fbo_create(&c->count_target, &desc, w, h);
}

bool clusters_count_begin(clusters *c, const gpu_scene *gs)
{
    int w = gs->view.width, h = gs->view.height;
    c->evaluations = c->covered = -1;
    if (!count_target_follow(c, w, h))
        return false;
    frame_timer_mark("count");
    glBindFramebuffer(GL_FRAMEBUFFER, c->count_target.id);
    glViewport(0, 0, w, h);
    gl_pass_state_apply(&(gl_pass_state){.cull = GL_BACK, .depth_func = GL_LEQUAL, .depth_write = true});
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    return true;
}

bool clusters_count_end(clusters *c, bool drawn)
{
    gl_pass_state_reset();
    if (!drawn)
        return false;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!fbo_read_float(&c->count_target, 0, c->count_pixels))
        return false;
    long covered = 0, evaluations = 0, n = (long)c->count_target.width * c->count_target.height;
    for (long i = 0; i < n; i++) {
        covered += (long)c->count_pixels[4 * i];
        evaluations += (long)c->count_pixels[4 * i + 1];
    }
    c->covered = covered, c->evaluations = evaluations;
    return gl_check("clusters_count");
}
