/* deferred_volumes.h - deferred lighting with light volumes whose light is ADDED into a
 * floating-point accumulation buffer, then tone mapped once (chapter 06); chapter 07 passes its
 * depth-tested pass state, and the benchmark and the tests use chapter 07's (renderers.c).
 *
 *   deferred_volumes_create(dv, g, accum_format)  the light volumes, an accumulation buffer of
 *                                                 `accum_format` sharing g's depth texture, the
 *                                                 present program
 *   deferred_volumes_destroy(dv)
 *   deferred_volumes_resize(dv, g)                after gbuffer_resize: follow g's size and depth
 *   deferred_volumes_render(dv, g, gs, target, frame)
 *        from the G-buffer g (filled by gbuffer_render): clear the accumulation buffer, ambient,
 *        every light's volume with frame->volume_state (its blending adds the lights up), then the
 *        present pass (tone map, display encoding) into the framebuffer `target`; follows g's size
 *        and depth and frame->accum_format when they changed; leaves gl_pass_state_reset()'s state.
 *        With frame->view LIGHT_VOLUMES_VIEW_OVERDRAW: no ambient, the buffer adds up one count per
 *        lighting fragment, and the present pass shows the counts as a heat map (shaders/heat.glsl;
 *        an rgba8 buffer clamps at 1, i.e. at SHADER_OVERDRAW_SCALE counts)
 *   deferred_volumes_shaded_pixels(dv)            lighting fragments kept in the last frame
 *                                                 (GL_SAMPLES_PASSED) when counted, else -1
 *   deferred_volumes_present(dv, target, frame)   the present pass alone (frame->tonemap, exposure,
 *                                                 view), for a chapter that fills the accumulation
 *                                                 buffer itself (chapter 08: per batch of lights)
 */
#ifndef COMMON_DEFERRED_VOLUMES_H
#define COMMON_DEFERRED_VOLUMES_H

#include "fbo.h"
#include "light_volumes.h"
#include "present_pass.h"

typedef enum deferred_volumes_tonemap {
    DEFERRED_VOLUMES_TONEMAP_NONE = SHADER_TONEMAP_NONE,         /* clamp at 1: forward's transform */
    DEFERRED_VOLUMES_TONEMAP_EXPOSURE = SHADER_TONEMAP_EXPOSURE, /* scale by the exposure, then clamp */
    DEFERRED_VOLUMES_TONEMAP_REINHARD = SHADER_TONEMAP_REINHARD, /* x / (1 + x) after it: never clips */
} deferred_volumes_tonemap;

typedef struct deferred_volumes_frame {
    const gl_pass_state *volume_state; /* how the volumes are drawn: blending, faces, depth test */
    GLenum accum_format;               /* 0: keep the current one */
    deferred_volumes_tonemap tonemap;
    float exposure; /* 0 means 1 */
    light_volumes_view view;
    bool count_pixels;
} deferred_volumes_frame;

typedef struct deferred_volumes {
    light_volumes lv;
    fbo accum; /* colour: the sum of the lights; depth: the G-buffer's */
    GLenum accum_format;
    present_pass present; /* accum_present.frag */
    GLuint query;
    long shaded_pixels;
} deferred_volumes;

bool deferred_volumes_create(deferred_volumes *dv, const gbuffer *g, GLenum accum_format);
void deferred_volumes_destroy(deferred_volumes *dv);
bool deferred_volumes_resize(deferred_volumes *dv, const gbuffer *g);
bool deferred_volumes_render(deferred_volumes *dv, const gbuffer *g, const gpu_scene *gs, GLuint target,
                             const deferred_volumes_frame *frame);
long deferred_volumes_shaded_pixels(const deferred_volumes *dv);
void deferred_volumes_present(const deferred_volumes *dv, GLuint target, const deferred_volumes_frame *frame);

#endif
