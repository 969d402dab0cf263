/* debug_views.h - the two debug views that chapters 03-09 show on V (chapter 12 the first of them):
 * `overdraw`, how many lighting fragments ran at each pixel as a heat map, and `volumes`, every
 * light's volume as lines over the lit picture. Read docs/07_face_culling.md, "Debug views".
 *
 *   debug_views_create(dv)              the line and count programs, the volume mesh
 *   debug_views_destroy(dv)
 *   debug_views_begin_overdraw(dv, g, pass, count_pass)
 *        bind a float count target the size of g, sharing g's depth (a depth-tested pass tests the
 *        scene as it does when it lights), and clear it to 0; *count_pass = *pass plus additive
 *        blending, so every fragment the chapter's volume pass draws with it, with the view
 *        LIGHT_VOLUMES_VIEW_OVERDRAW, adds one count (faces, depth test and clamp stay the chapter's)
 *   debug_views_end_overdraw(dv, target)
 *        the counts as a heat map (shaders/heat.glsl, through accum_present.frag) into `target`
 *   debug_views_draw_volumes(dv, g, gs, target, volumes)
 *        copy g's depth (or, with a stencil, its depth's copy) into `target`'s (both
 *        GL_DEPTH_COMPONENT32F: the deferred chapters never write the target's depth), then every light's volume mesh, placed and scaled as the volume
 *        chapters draw it (`volumes`; NULL: each light's solved radius, the scaled mesh), as lines in
 *        the light's colour, hidden where the scene is in front; leaves gl_pass_state_reset()'s state
 *        and GL_FILL
 *
 * Chapter 03 has no volumes to count: its overdraw view is its own loop's count
 * (deferred_fullscreen.frag, VIEW_OVERDRAW); chapters 06-07 count in their accumulation buffer
 * (deferred_volumes.h). tools/heat_count reads a heat-map screenshot back into counts.
 */
#ifndef COMMON_DEBUG_VIEWS_H
#define COMMON_DEBUG_VIEWS_H

#include "gbuffer.h"
#include "gl_util.h"
#include "gpu_scene.h"
#include "mesh.h"
#include "present_pass.h"

/* How the volumes view sizes the volumes; zero is chapters 05-07's. */
typedef struct debug_views_volumes {
    float fixed_radius; /* > 0: every volume this radius (chapter 04); 0: each light's solved radius */
    bool unscaled;      /* the mesh at the radius, not scaled by 1 / inradius (chapter 04's --scale none) */
} debug_views_volumes;

typedef struct debug_views {
    GLuint wire_program;
    present_pass present; /* the counts as the heat map (accum_present.frag) */
    GLint u_view_proj, u_mesh_scale, u_fixed_radius; /* wire_program's */
    mesh sphere;
    float mesh_scale; /* 1 / inradius */
    fbo counts;       /* R32F: the overdraw count; depth: the G-buffer's */
} debug_views;

bool debug_views_create(debug_views *dv);
void debug_views_destroy(debug_views *dv);
bool debug_views_begin_overdraw(debug_views *dv, const gbuffer *g, const gl_pass_state *pass,
                                gl_pass_state *count_pass);
bool debug_views_end_overdraw(const debug_views *dv, GLuint target);
bool debug_views_draw_volumes(const debug_views *dv, const gbuffer *g, const gpu_scene *gs, GLuint target,
                              const debug_views_volumes *volumes);

#endif
