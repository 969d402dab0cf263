/* forward.h - chapter 00's forward renderer, shared so every chapter can switch to it.
 *
 *   forward_create(f)                       compile the shaders
 *   forward_create_with(f, extra)           the same with a later chapter's additions to every
 *                                           shading program (gl_program.h; chapter 14's shadows)
 *   forward_set_extra(f, extra)             the additions from the next draw on (NULL: none): each
 *                                           variant's programs are built once, on first use, and
 *                                           kept (chapter 14: its shadows' programs only while a
 *                                           light is shadowed)
 *   forward_destroy(f)
 *   forward_render(f, gs, target, options)  draw gs into the framebuffer `target` (cleared here):
 *                                           the three passes below with the state they need;
 *                                           leaves gl_pass_state_reset()'s state
 *   forward_build_light_lists(f, gs)        per object, the lights that reach it, uploaded
 *   forward_draw_depth(f, gs)               every object into the depth buffer only
 *   forward_draw_shaded(f, gs, options)     every opaque object shaded (lists when options.light_lists),
 *                                           with whatever depth state the caller set; then, if the
 *                                           scene has transparent objects, those (see below)
 *   forward_draw_transparent(f, gs, glass)  the transparent objects alone into the framebuffer bound
 *                                           (a float one): forward-shaded in linear radiance and
 *                                           blended over what it holds, object by object in
 *                                           glass->order, each with every state of glass->passes;
 *                                           leaves gl_pass_state_reset()'s state (chapter 12)
 *   forward_draw_linear(f, gs, draw, user)  a frame with glass for the display-encoded framebuffer
 *                                           bound: draw(user, gs) draws it in linear radiance into
 *                                           f->hdr, which holds the bound framebuffer's depth; then
 *                                           the present pass encodes it into the bound framebuffer,
 *                                           whose depth gets f->hdr's back (below; Forward+ too)
 *   forward_variant_find(name)              chapter 00's forward renderer called name ("forward",
 *                                           "forward-naive", "forward-prepass", "forward-lists"):
 *                                           its optimisations; NULL when name is none of them
 *   forward_lights_per_pixel(f, gs, lists)  the lights each shaded fragment of the last frame looped
 *                                           over: with the lists, their mean length per object
 *   forward_shaded_pixels(f)                fragments that passed the depth test in the last
 *                                           shading pass (GL_SAMPLES_PASSED), when counting is on:
 *                                           the opaque objects' plus the transparent ones'
 *
 * Objects are drawn in batches (gpu_scene_draw): one instanced draw per run of objects sharing a mesh.
 *
 * Transparent objects (material opacity A < 1; docs/12_transparency.md) are in no depth pre-pass and
 * no batch: after the opaque ones, each is drawn on its own, back to front (gpu_scene sorts them),
 * with forward_glass_back_pass (its far side) then forward_glass_front_pass (its near side), blended
 * final = A * shaded + (1 - A) * behind in LINEAR radiance, tested against the opaque depth and not
 * writing it. So that the blend sees linear radiance, as chapter 12's deferred frame blends into its
 * float accumulation buffer, forward_draw_shaded on such a scene draws the frame into f->hdr (RGBA32F)
 * instead of the display-encoded framebuffer bound: the bound framebuffer's depth (cleared, or the
 * pre-pass's; it must be GL_DEPTH_COMPONENT32F) is copied in, the opaque objects are shaded in linear
 * radiance, the glass blended over them, and the sum display-encoded once into the bound framebuffer
 * (accum_present.frag, the deferred chapters' present pass), whose depth gets the opaque depth back.
 * With options.linear_output the bound framebuffer is float already: the glass is blended there.
 * A scene without transparent objects draws exactly as before, straight into the bound framebuffer.
 * Depth ties: every pass that draws the scene uses GL_LEQUAL, so where two surfaces have exactly
 * the same depth the one drawn last wins, with or without a pre-pass and in the G-buffer alike.
 *
 * Options are the honest optimisations a forward renderer turns on:
 *   prepass      depth-only pass first, then shade with GL_EQUAL: each pixel shaded once
 *   light_lists  per object, only the lights whose sphere reaches the object's bounding sphere
 * and one that changes the output, not the speed:
 *   linear_output  write linear radiance, unclamped and not display-encoded, for a float target
 *                  (the benchmark's HDR error); a second program built with OUTPUT_LINEAR
 */
#ifndef COMMON_FORWARD_H
#define COMMON_FORWARD_H

#include "fbo.h"
#include "gl_program.h"
#include "gpu_scene.h"
#include "present_pass.h"

typedef struct forward_options {
    bool prepass;
    bool light_lists;
    bool count_pixels;
    bool linear_output;
} forward_options;

/* Chapter 00's four forward renderers, by the optimisations each turns on (forward_variant_find). */
typedef struct forward_variant {
    const char *name;
    forward_options options;
} forward_variant;

#define FORWARD_VARIANT_COUNT 4
extern const forward_variant forward_variants[FORWARD_VARIANT_COUNT];

/* How forward_draw_transparent draws the glass; zero is what forward_draw_shaded draws. */
typedef struct forward_glass {
    const gl_pass_state *const *passes; /* per object, in turn; NULL: forward_glass_passes */
    int pass_count;
    gpu_scene_order order;              /* GPU_SCENE_BACK_TO_FRONT, or the scene's order (a bug) */
    bool light_lists;                   /* forward_build_light_lists ran this frame: use them */
    bool count_pixels;
    bool overdraw; /* each fragment adds 1 / SHADER_OVERDRAW_SCALE instead of its colour (passes
                      that blend GL_ONE, GL_ONE: the overdraw view's count) */
} forward_glass;

/* Chapter 12's two literals (chapters/12_transparency.c), kept here for every forward frame. */
extern const gl_pass_state forward_glass_back_pass, forward_glass_front_pass;
extern const gl_pass_state *const forward_glass_passes[2];

/* The shading programs: lit, linear (OUTPUT_LINEAR: the benchmark, the tests, scenes with glass) and
 * glass (TRANSPARENT: scenes with transparent objects); each but lit built on first use. */
typedef enum forward_program { FORWARD_PROGRAM_LIT, FORWARD_PROGRAM_LINEAR, FORWARD_PROGRAM_GLASS, FORWARD_PROGRAM_COUNT } forward_program;

typedef struct forward {
    gl_program_variants shading[FORWARD_PROGRAM_COUNT]; /* each with the extra as it was when drawn */
    GLuint depth_program;
    present_pass present;                       /* the same */
    fbo hdr;                               /* such a scene's frame in linear radiance (RGBA32F) */
    GLuint list_buffer, list_texture;
    GLuint query;
    int *list;         /* per object (first, count), then the light indices, object after object */
    size_t list_cap;
    long list_entries; /* sum of list lengths in the last frame */
    long shaded_pixels;
    gl_program_extra extra; /* forward_create_with's, or forward_set_extra's */
} forward;

bool forward_create(forward *f);
bool forward_create_with(forward *f, const gl_program_extra *extra);
void forward_set_extra(forward *f, const gl_program_extra *extra);
void forward_destroy(forward *f);
bool forward_render(forward *f, const gpu_scene *gs, GLuint target, forward_options options);
bool forward_build_light_lists(forward *f, const gpu_scene *gs);
void forward_draw_depth(const forward *f, const gpu_scene *gs);
bool forward_draw_shaded(forward *f, const gpu_scene *gs, forward_options options);
bool forward_draw_transparent(forward *f, const gpu_scene *gs, const forward_glass *glass);
bool forward_draw_linear(forward *f, const gpu_scene *gs, bool (*draw)(void *user, const gpu_scene *gs), void *user);
const forward_options *forward_variant_find(const char *name);
double forward_lights_per_pixel(const forward *f, const gpu_scene *gs, bool light_lists);
long forward_shaded_pixels(const forward *f);

#endif
