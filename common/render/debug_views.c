/* debug_views.c - see debug_views.h. */
#include "debug_views.h"

#include "frame_timer.h"
#include "gl_program.h"
#include "light_volumes.h"

#include <string.h>

/* The volumes' lines: both faces (a sphere is a cage), tested against the scene's depth, written
 * nowhere but the colour. */
static const gl_pass_state wire_pass = {.depth_func = GL_LESS};

bool debug_views_create(debug_views *dv)
{
    memset(dv, 0, sizeof *dv);
    dv->wire_program = gl_program_load("volume_wire.vert", "volume_wire.frag", NULL);
    if (!dv->wire_program || !present_pass_create(&dv->present) ||
        !light_volumes_mesh_create(&dv->sphere, &dv->mesh_scale)) {
        debug_views_destroy(dv);
        return false;
    }
    dv->u_view_proj = glGetUniformLocation(dv->wire_program, "u_view_proj");
    dv->u_mesh_scale = glGetUniformLocation(dv->wire_program, "u_mesh_scale");
    dv->u_fixed_radius = glGetUniformLocation(dv->wire_program, "u_fixed_radius");
    return gl_check("debug_views_create");
}

void debug_views_destroy(debug_views *dv)
{
    gl_program_destroy(&dv->wire_program);
    present_pass_destroy(&dv->present);
    mesh_destroy(&dv->sphere);
    fbo_destroy(&dv->counts);
    memset(dv, 0, sizeof *dv);
}

/* The count target follows the G-buffer's size and depth texture (recreated after a resize). */
static bool follow_gbuffer(debug_views *dv, const gbuffer *g)
{
    return gbuffer_follow_target(g, &dv->counts, GL_R32F, "overdraw count");
}

bool debug_views_begin_overdraw(debug_views *dv, const gbuffer *g, const gl_pass_state *pass,
                                gl_pass_state *count_pass)
{
    if (!follow_gbuffer(dv, g))
        return false;
    frame_timer_mark("lighting");
    glBindFramebuffer(GL_FRAMEBUFFER, dv->counts.id);
    glViewport(0, 0, dv->counts.width, dv->counts.height);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    /* The chapter's faces, depth test and clamp, so the same fragments run; each adds its count. */
    *count_pass = *pass;
    count_pass->blend[0] = GL_ONE;
    count_pass->blend[1] = GL_ONE;
    return true;
}

bool debug_views_end_overdraw(const debug_views *dv, GLuint target)
{
    frame_timer_mark("present");
    present_pass_draw(&dv->present, dv->counts.color[0], target, dv->counts.width, dv->counts.height,
                      &(present_pass_options){.view = SHADER_VIEW_OVERDRAW});
    return gl_check("debug_views_end_overdraw");
}

bool debug_views_draw_volumes(const debug_views *dv, const gbuffer *g, const gpu_scene *gs, GLuint target,
                              const debug_views_volumes *volumes)
{
    const debug_views_volumes solved = {0};
    if (!volumes)
        volumes = &solved;
    frame_timer_mark("volumes view");
    /* The deferred chapters write no depth into the target: copy the scene's from the G-buffer so
     * that surfaces hide the lines (a depth blit needs equal formats: both DEPTH_COMPONENT32F; a
     * G-buffer with a stencil keeps its depth's copy in that format). */
    int w = g->fbo.width, h = g->fbo.height;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, g->desc.stencil ? g->depth_copy.id : g->fbo.id);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
    glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, w, h);
    if (gs->light_count > 0) {
        glUseProgram(dv->wire_program);
        gpu_scene_bind_lights(gs, dv->wire_program, SHADER_UNIT_LIGHTS);
        glUniformMatrix4fv(dv->u_view_proj, 1, GL_FALSE, (const float *)gs->view.view_proj);
        glUniform1f(dv->u_mesh_scale, volumes->unscaled ? 1.0f : dv->mesh_scale);
        glUniform1f(dv->u_fixed_radius, volumes->fixed_radius);
        gl_pass_state_apply(&wire_pass);
        /* The triangles' edges only; the polygon mode is not part of gl_pass_state: undone below. */
        glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
        mesh_draw_instanced(&dv->sphere, gs->light_count);
        glBindVertexArray(0);
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        gl_pass_state_reset();
    }
    return gl_check("debug_views_draw_volumes");
}
