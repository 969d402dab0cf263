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
    gl_program_destroy(&c->depth_program);
    gl_program_destroy(&c->forward_program);
    gl_program_destroy(&c->deferred_program);
    gl_program_destroy(&c->glass_program);
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

bool clusters_assign(clusters *c, const gpu_scene *gs)
{
    frame_timer_mark("light assignment");
    const frame_view *v = &gs->view;
    cluster_grid_init(&c->grid, v->width, v->height, c->desc.tile_size, c->desc.slices,
                      (const float *)v->proj, v->near_plane, v->far_plane);
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
    /* Each light's bounding sphere, taken to view space (an infinite one stays infinite). */
    for (int i = 0; i < gs->light_count; i++) {
        const gpu_light *l = &gs->lights[i];
        float s[4];
        cluster_light_bounds(l->position, l->direction, l->radius, l->cos_outer, s);
        vec4 view;
        glm_mat4_mulv((vec4 *)v->view, (vec4){s[0], s[1], s[2], 1.0f}, view);
        c->spheres[i][0] = view[0], c->spheres[i][1] = view[1], c->spheres[i][2] = view[2];
        c->spheres[i][3] = s[3] >= CLUSTER_INFINITE_RADIUS ? CLUSTER_INFINITE_RADIUS : s[3];
    }
    /* A cluster's list may hold no more than the texture buffer can address for every cluster. */
    GLint max_texels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &max_texels);
    int count = cluster_grid_count(&c->grid);
    int limit = max_texels / count;
    if (c->desc.cluster_limit > 0 && c->desc.cluster_limit < limit)
        limit = c->desc.cluster_limit;
    limit = limit > 0 ? limit : 1;
    const float(*spheres)[4] = (const float(*)[4])c->spheres;
    if (c->desc.compute) {
        const cluster_assign_buffers out = {c->range_buffer, c->range_texture, c->list_buffer,
                                            c->list_texture};
        return cluster_assign_gpu_run(&c->gpu, &c->grid, spheres, gs->light_count, limit, &out) &&
               (!c->desc.check ||
                (cluster_lists_assign(&c->lists, &c->grid, spheres, gs->light_count, limit) &&
                 cluster_assign_gpu_read(&out, count, &c->readback) && lists_same(c)));
    }
    if (!cluster_lists_assign(&c->lists, &c->grid, spheres, gs->light_count, limit))
        return false;
    gl_texture_buffer_upload(c->range_buffer, c->range_texture, GL_RG32I, c->lists.ranges,
                             (size_t)count * 2 * sizeof(int));
    gl_texture_buffer_upload(c->list_buffer, c->list_texture, GL_R32I, c->lists.indices,
                             (size_t)(c->lists.entries + 1) * sizeof(int));
    return gl_check("clusters_assign");
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

static GLuint program_once(GLuint *p, const char *vert, const char *frag, const char *defines)
{
    if (!*p)
        *p = gl_program_load(vert, frag, defines);
    return *p;
}

static int view_mode(clusters_view view)
{
    return view == CLUSTERS_VIEW_OVERDRAW   ? SHADER_VIEW_OVERDRAW
           : view == CLUSTERS_VIEW_CLUSTERS ? VIEW_CLUSTERS
                                            : SHADER_VIEW_LIT;
}

bool clusters_draw_depth(clusters *c, const gpu_scene *gs)
{
    GLuint p = program_once(&c->depth_program, "forward.vert", "depth_only.frag", NULL);
    if (!p)
        return false;
    glUseProgram(p);
    gpu_scene_bind_objects(gs, p, SHADER_UNIT_OBJECTS);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    gpu_scene_draw(gs, p);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    return true;
}

/* Forward+'s shading with a u_view_mode (also the count pass's). */
static bool shade_forward(clusters *c, const gpu_scene *gs, const gl_pass_state *pass, int mode, bool linear)
{
    GLuint p = program_once(&c->forward_program, "forward.vert", "forward_plus.frag", NULL);
    if (!p)
        return false;
    gl_pass_state_apply(pass);
    glUseProgram(p);
    gpu_scene_bind_lights(gs, p, SHADER_UNIT_LIGHTS);
    gpu_scene_bind_objects(gs, p, SHADER_UNIT_OBJECTS);
    clusters_bind(c, p, SHADER_UNIT_LIGHT_INDEX); /* and the unit after it */
    glUniform3fv(glGetUniformLocation(p, "u_eye"), 1, gs->view.eye);
    glUniform1i(glGetUniformLocation(p, "u_view_mode"), mode);
    glUniform1i(glGetUniformLocation(p, "u_output_linear"), linear);
    gpu_scene_draw(gs, p);
    return gl_check("clusters: Forward+ shading");
}

bool clusters_shade_forward(clusters *c, const gpu_scene *gs, const gl_pass_state *pass, clusters_view view)
{
    frame_timer_mark("shading");
    return shade_forward(c, gs, pass, view_mode(view), view == CLUSTERS_VIEW_LINEAR);
}

static bool shade_deferred(clusters *c, const gbuffer *g, const gpu_scene *gs, const gl_pass_state *pass,
                           int mode, bool linear)
{
    GLuint p = program_once(&c->deferred_program, "fullscreen.vert", "clustered_deferred.frag", NULL);
    if (!p)
        return false;
    gl_pass_state_apply(pass);
    glUseProgram(p);
    gpu_scene_bind_lights(gs, p, SHADER_UNIT_LIGHTS);
    gbuffer_bind_textures(g, gs, p, SHADER_UNIT_GBUFFER);
    clusters_bind(c, p, SHADER_UNIT_LIGHT_INDEX); /* and the unit after it */
    glUniform1i(glGetUniformLocation(p, "u_view_mode"), mode);
    glUniform1i(glGetUniformLocation(p, "u_output_linear"), linear);
    gl_draw_fullscreen();
    return gl_check("clusters: clustered deferred shading");
}

bool clusters_shade_deferred(clusters *c, const gbuffer *g, const gpu_scene *gs, const gl_pass_state *pass,
                             clusters_view view)
{
    frame_timer_mark("lighting");
    return shade_deferred(c, g, gs, pass, view_mode(view), view == CLUSTERS_VIEW_LINEAR);
}

bool clusters_shade_glass(clusters *c, const gpu_scene *gs, const gl_pass_state *const passes[], int pass_count,
                          gpu_scene_order order, clusters_view view)
{
    GLuint p = program_once(&c->glass_program, "forward.vert", "forward_plus.frag", "TRANSPARENT 1");
    if (!p)
        return false;
    frame_timer_mark("transparent");
    glUseProgram(p);
    gpu_scene_bind_lights(gs, p, SHADER_UNIT_LIGHTS);
    gpu_scene_bind_objects(gs, p, SHADER_UNIT_OBJECTS); /* and with them each object's opacity */
    clusters_bind(c, p, SHADER_UNIT_LIGHT_INDEX);       /* and the unit after it */
    glUniform3fv(glGetUniformLocation(p, "u_eye"), 1, gs->view.eye);
    glUniform1i(glGetUniformLocation(p, "u_view_mode"), view_mode(view));
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

bool clusters_count(clusters *c, const gbuffer *g, const gpu_scene *gs)
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
    bool ok;
    if (g) {
        ok = shade_deferred(c, g, gs, &(gl_pass_state){0}, VIEW_COUNT, false);
    } else { /* Forward+'s own two passes: the same vertex path, so the same visible fragments */
        ok = clusters_draw_depth(c, gs) &&
             shade_forward(c, gs, &(gl_pass_state){.cull = GL_BACK, .depth_func = GL_EQUAL}, VIEW_COUNT,
                           false);
    }
    gl_pass_state_reset();
    if (!ok)
        return false;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!fbo_read_float(&c->count_target, 0, c->count_pixels))
        return false;
    long covered = 0, evaluations = 0;
    for (long i = 0; i < (long)w * h; i++) {
        covered += (long)c->count_pixels[4 * i];
        evaluations += (long)c->count_pixels[4 * i + 1];
    }
    c->covered = covered, c->evaluations = evaluations;
    return gl_check("clusters_count");
}

const gl_pass_state clusters_prepass = {.cull = GL_BACK, .depth_func = GL_LEQUAL, .depth_write = true};
const gl_pass_state clusters_shade_after_prepass = {.cull = GL_BACK, .depth_func = GL_EQUAL};

/* The opaque frame in linear radiance, then the glass over it with the same lists (chapter 12). */
static bool shade_forward_plus_linear(void *user, const gpu_scene *gs)
{
    clusters *c = user;
    return clusters_shade_forward(c, gs, &clusters_shade_after_prepass, CLUSTERS_VIEW_LINEAR) &&
           clusters_shade_glass(c, gs, forward_glass_passes, 2, GPU_SCENE_BACK_TO_FRONT, CLUSTERS_VIEW_LINEAR);
}

/* The shading after the pre-pass; glass is blended in linear radiance, as forward does. */
static bool shade_forward_plus(clusters *c, forward *fwd, const gpu_scene *gs, clusters_view view)
{
    if (!fwd || gs->transparent_count == 0)
        return clusters_shade_forward(c, gs, &clusters_shade_after_prepass, view);
    if (view == CLUSTERS_VIEW_LINEAR)
        return shade_forward_plus_linear(c, gs);
    return forward_draw_linear(fwd, gs, shade_forward_plus_linear, c);
}

bool clusters_render_forward_plus(clusters *c, forward *fwd, const gpu_scene *gs, GLuint target, clusters_view view)
{
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, gs->view.width, gs->view.height);
    gl_pass_state_apply(&clusters_prepass);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    frame_timer_mark("depth pre-pass");
    bool ok = clusters_draw_depth(c, gs) && clusters_assign(c, gs) && shade_forward_plus(c, fwd, gs, view);
    gl_pass_state_reset();
    return ok;
}
