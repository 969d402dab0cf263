/* shadow_atlas.h - chapter 14's depth atlas: the shadow plan (shadow_plan.h) made real each frame.
 * Written in common/ because chapters 15 to 19 cast the same shadows (their --shadows N).
 *
 *   shadow_atlas_create(s, desc, format, slope_bias)
 *                                   the atlas texture (GL_DEPTH_COMPONENT32F or 16), compared with
 *                                   GL_LEQUAL and read with GL_LINEAR (bilinear PCF), its framebuffer, the depth
 *                                   program and the two tables; false (logged) when the context cannot
 *                                   make it
 *   shadow_atlas_destroy(s)
 *   shadow_atlas_update(s, gs)      plan this frame for gs's lights and objects, draw the tiles the
 *                                   plan says changed (each cleared in its own square, then its
 *                                   casters, depth only, with glPolygonOffset(slope_bias, 0)), and
 *                                   upload the tables; with s->enabled false, every light unshadowed
 *                                   and nothing drawn. Leaves framebuffer 0 bound and
 *                                   gl_pass_state_reset()'s state
 *   shadow_atlas_bind(program, s)   the atlas and the tables on their units (SHADER_UNIT_SHADOW_*), and
 *                                   the samplers of `program` (in use) set to them: the bind of the
 *                                   gl_program_extra that chapters 14 to 19 hand to forward and the clusters
 *   shadow_atlas_programs(s, with, without)
 *                                   after the update, the additions the frame's shading programs are
 *                                   built with: `with` (shadow_atlas_extra's, and the chapter's own)
 *                                   while the plan shadows a light, `without` (the chapter's own alone,
 *                                   or NULL) otherwise, so shadows that are off cost nothing (each
 *                                   variant built once: gl_program_variant); one line says each change.
 *                                   No atlas made (s zeroed): `without`, nothing said
 *   shadow_atlas_bytes(s)           the atlas's memory
 *   shadow_atlas_extra(s)           that gl_program_extra: "SHADOWS 1", SHADOW_PCF (the taps a side, so
 *                                   the lookup's loop is known when the program is built: one tap
 *                                   for PCF 1) and shadow_atlas_bind
 */
#ifndef COMMON_SHADOW_ATLAS_H
#define COMMON_SHADOW_ATLAS_H

#include "fbo.h"
#include "gl_program.h"
#include "gpu_scene.h"
#include "shadow_plan.h"

typedef struct shadow_atlas {
    shadow_plan plan;
    fbo target; /* depth only */
    GLenum format;
    float slope_bias;
    bool enabled;
    char defines[40]; /* shadow_atlas_extra's: SHADOWS and SHADOW_PCF */
    int programs_said; /* the programs last said to be drawing with it: 1 with SHADOWS, 0 without, -1 none yet */
    GLuint depth_program;
    GLuint light_buffer, light_texture, tile_buffer, tile_texture;
    float *light_texels, *tile_texels;
    int light_texel_cap, tile_texel_cap;
    shadow_light *lights;
    shadow_caster *casters;
    int light_cap, caster_cap;
    long frames, tiles_drawn_total; /* since create: the mean tiles drawn per frame */
} shadow_atlas;

bool shadow_atlas_create(shadow_atlas *s, const shadow_plan_desc *desc, GLenum format, float slope_bias);
void shadow_atlas_destroy(shadow_atlas *s);
bool shadow_atlas_update(shadow_atlas *s, const gpu_scene *gs);
void shadow_atlas_bind(GLuint program, const void *s);
double shadow_atlas_bytes(const shadow_atlas *s);
gl_program_extra shadow_atlas_extra(const shadow_atlas *s);
const gl_program_extra *shadow_atlas_programs(shadow_atlas *s, const gl_program_extra *with,
                                              const gl_program_extra *without);

#endif
