/* gbuffer.h - the G-buffer: what the lighting passes need to know about each visible pixel.
 *
 *   gbuffer_create(g, width, height)     textures + framebuffer + the geometry-pass program, in the
 *                                        default layout
 *   gbuffer_create_with(g, width, height, desc)
 *                                        the same with options (desc may be NULL: the defaults)
 *   gbuffer_create_pass(g, desc)         the geometry-pass program and the options only: the caller
 *                                        makes g->fbo itself (chapter 02 shows what MRT takes) with
 *                                        the layout's formats, colour 0 and 1 drawn, and a depth texture
 *   gbuffer_attach_stencil(g, framebuffer)
 *                                        attach g's stencil to `framebuffer` (one that borrows g's
 *                                        depth texture, like the light accumulation buffer), so a
 *                                        pass drawing there tests the stencil; g made with .stencil
 *   gbuffer_follow_target(g, target, format, name)
 *                                        a target of one `format` colour texture on g's depth
 *                                        texture, at g's size (a lighting pass's sum, a count), so
 *                                        that a pass drawing there depth-tests against the scene;
 *                                        made when `target` has none, remade only when g's depth or
 *                                        size changed since (a changed format: destroy it first)
 *   gbuffer_resize(g, width, height)     recreate the textures (window resize)
 *   gbuffer_destroy(g)
 *   gbuffer_render(g, gs)                geometry pass into g's own framebuffer: every object once,
 *                                        depth test on; leaves framebuffer 0 bound and
 *                                        gl_pass_state_reset()'s state
 *   gbuffer_bind_textures(g, gs, program, first_unit)
 *                                        u_gbuffer_albedo, u_gbuffer_normal, u_gbuffer_depth on units
 *                                        first_unit..first_unit+2, plus the layout's decoding
 *                                        (u_gbuffer_normal_encoding, u_gbuffer_reversed_z),
 *                                        u_inv_view_proj and u_eye (with a stencil: the depth's copy)
 *   gbuffer_bytes_per_pixel()            the default layout's size without stencil (a naive layout
 *                                        is GBUFFER_NAIVE_BYTES), plus RT2's where the default
 *                                        G-buffer has one (gbuffer_set_default_emissive)
 *   gbuffer_pixel_bytes(g)               g's bytes per pixel and sample: its layout's, plus RT2's
 *   gbuffer_memory_bytes(g)              g's targets in bytes: gbuffer_pixel_bytes x samples x width x
 *                                        height (without the stencil's depth copy)
 *   gbuffer_scene_emits(s)               whether a material of s gives off light (a non-zero emissive
 *                                        or an emissive map, on a metallic-roughness material)
 *   gbuffer_set_default_emissive(on)     whether G-buffers made from now on without desc.emissive have
 *                                        RT2 (the runner's: on for a scene that emits)
 *   gbuffer_default_emissive()
 *
 *   gbuffer_layout_find(name)            the layout called name (--gbuffer), NULL when none is
 *   gbuffer_layout_name(layout)          its name (gbuffer_layout_names[])
 *   gbuffer_layout_bytes(layout, stencil)
 *                                        bytes per pixel: the bits its formats hold, / 8
 *   gbuffer_layout_depth_format(layout, stencil)
 *   gbuffer_layout_available(layout)     false, with one line logged, where the context cannot draw
 *                                        it (reversed-Z without glClipControl); needs a context
 *   gbuffer_set_default_layout(layout)   the layout gbuffer_create uses from now on (the runner's
 *                                        --gbuffer); false, logged, when not available
 *   gbuffer_default_layout()
 *   gbuffer_layout_holds_pbr(layout)     whether the layout keeps metallic-roughness materials (a
 *                                        half-float RT1: reference; a 16-bit one: oct16)
 *   gbuffer_layout_for_scene(layout, s)  the layout to draw s with: `layout` (NULL: the default), or
 *                                        for a scene with metallic-roughness materials and no layout
 *                                        asked for, oct16; NULL, logged, when the one asked for
 *                                        cannot hold them
 *   gbuffer_layout_for_chapter(layout, s, prefers_reversed_z)
 *                                        as gbuffer_layout_for_scene; with nothing asked, a chapter
 *                                        that prefers reversed-Z (17, 19) gets reversed-z where the
 *                                        default is compact, the scene has no metallic-roughness
 *                                        material and the context has glClipControl
 *   gbuffer_layout_fits_pass(layout, pass)
 *                                        false, with one line logged, for a reversed-Z layout and a
 *                                        lighting pass written for standard depth (see below)
 *
 *   gbuffer_depth_test_begin(g, gs, view, state)
 *   gbuffer_depth_test_end(g)            around a pass that depth-tests against g's depth: with a
 *                                        reversed-Z layout they set glClipControl's [0,1] depth (clear 0),
 *                                        put the reversed projection in view->view.view_proj (view is
 *                                        a copy of gs) and mirror state->depth_func (GREATER <-> LESS,
 *                                        GEQUAL <-> LEQUAL); with the others they only copy
 *   gbuffer_layout_depth_begin(layout, gs, view, state)
 *   gbuffer_layout_depth_end(layout)     the same for a target of the layout's depth that is not a
 *                                        G-buffer (chapter 17's depth-normal pre-pass); reversed, the
 *                                        clear depth is 0 (far) between them, 1 again after
 *   gbuffer_layout_bind_depth(layout, gs, program)
 *                                        u_inv_view_proj and u_gbuffer_reversed_z for gbuffer_read.glsl
 *                                        on the program in use (reversed: the inverse of the reversed
 *                                        projection, in double); gbuffer_bind_textures calls it
 *
 * Layouts (gbuffer_layouts[]; docs/02_mrt_gbuffer.md has what each loses, measured):
 *   RT0  albedo.rgb: GL_SRGB8_ALPHA8 (sRGB-encoded: 8 bits spent where the eye sees them) or
 *        GL_RGBA8 (linear); alpha: specular S in 8 bits (within 1/510; above 1 clamps), except in
 *        `reference`, whose alpha is unused
 *   RT1  the octahedral normal (shaders/octahedral.glsl), and the material RT0 has no room for:
 *          SHADER_GBUFFER_NORMAL_HALF    GL_RGBA16F  x, y half floats (best of 4), S, P   8 bytes
 *          SHADER_GBUFFER_NORMAL_SHORTS  GL_RGBA16   x, y 16-bit codes, -, P             8 bytes
 *                                        (metallic-roughness: x, y, 0.5 + 0.5 occlusion, roughness)
 *          SHADER_GBUFFER_NORMAL_PACKED  GL_RGBA8    x, y 12-bit codes over r, g, b; P   4 bytes
 *          SHADER_GBUFFER_NORMAL_BYTES   GL_RGBA8    x, y 8-bit codes, -, P              4 bytes
 *        an n-bit code q is (q - m) / m, m = 2^(n-1) - 1, so 0 and +-1 are exact, and the encoder
 *        keeps the best of the four code pairs around the exact value (max error 0.64, 0.040,
 *        0.0025 degrees for 8, 12, 16 bits; half floats 0.040: tests/unit/test_octahedral.c);
 *        shininess in a fixed-point channel is P = 1 + 255 c: the integers 1..256 exactly
 *   depth GL_DEPTH_COMPONENT32F, GL_DEPTH24_STENCIL8, or GL_DEPTH_COMPONENT32F reversed (near 1,
 *        far 0, cleared to 0, GL_GEQUAL, drawn with glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE):
 *        float's precision spread evenly over distance; refused without clip control). Position
 *        is rebuilt from it with the inverse view-projection. With desc.stencil a float depth
 *        becomes GL_DEPTH32F_STENCIL8 (the same depth values to the bit); D24S8 has its stencil
 *        already. gbuffer_render clears the stencil to 0, then copies the depth
 *        (glBlitFramebuffer), and the shaders read the copy: a pass that writes the stencil must
 *        not sample the texture it writes (a feedback loop, undefined in GL; llvmpipe finishes all
 *        queued drawing before each such draw)
 *   name           RT0            RT1             depth          bytes (with stencil: D32F_S8 is
 *                                                                       40 bits, 64 on most GPUs)
 *   reference      SRGB8_ALPHA8   RGBA16F HALF    D32F           16 (17)
 *   compact        SRGB8_ALPHA8   RGBA8 PACKED    D32F           12 (13)   <- the default
 *   compact-d24s8  SRGB8_ALPHA8   RGBA8 PACKED    D24S8          12 (12)
 *   reversed-z     SRGB8_ALPHA8   RGBA8 PACKED    D32F reversed  12 (13)
 *   linear-albedo  RGBA8          RGBA8 PACKED    D32F           12 (13)
 *   oct8           SRGB8_ALPHA8   RGBA8 BYTES     D32F           12 (13)
 *   oct16          SRGB8_ALPHA8   RGBA16 SHORTS   D32F           16 (17)
 *   RT2  emissive (chapter 18): GL_RGBA16F, 8 bytes (R11F_G11F_B10F left 0.19 % of a test scene
 *        over 1/255 from forward), the light the surface gives off itself (linear radiance,
 *        factor times map), added once per pixel where the ambient is; made only
 *        for a scene that has it (desc.emissive, or gbuffer_set_default_emissive), so every other
 *        scene keeps two targets and its bytes. Its reader, gbuffer_read.glsl, reads it where
 *        u_gbuffer_has_emissive says it is there; the geometry pass writes it when built with
 *        GBUFFER_EMISSIVE. docs/18_pbr_materials.md has its precision, measured.
 * The default keeps a float depth: with D24S8 chapters 07 and 08 leave the course's 1/255 bound
 * against forward on the city (docs/02_mrt_gbuffer.md). shaders/gbuffer_read.glsl decodes a pixel
 * of any layout (uniforms from gbuffer_bind_textures): gbuffer_read(ivec2 pixel) -> surface.
 *
 * Multisampling (chapter 13): desc.samples > 1 makes every target a multisampled texture with that
 * many samples (0 or 1: the plain textures every other chapter uses). gbuffer_render is unchanged:
 * without sample shading gbuffer.frag runs once per pixel per primitive, at the pixel centre, and
 * writes its values to the samples the primitive covers; the depth is per sample. The shaders that
 * read it are built with the define GBUFFER_MULTISAMPLE, which makes gbuffer_read.glsl's samplers
 * sampler2DMS; gbuffer_read_sample(pixel, sample, position) reads one sample.
 *
 * Reversed-Z flips every depth comparison against the G-buffer and needs the reversed projection
 * wherever something is depth-tested against it: gbuffer_depth_test_begin/end. The lighting passes
 * of chapters 04 on are written for standard depth (their pass state, and light_volume.frag's
 * `depth >= 1.0`), so the runner refuses reversed-z wherever a chapter sets a lighting pass state
 * (gbuffer_layout_fits_pass); chapters 02 and 03 read depth through gbuffer_read.glsl only and
 * take it, as do 11, 17 and 19, whose one full-screen shading pass tests nothing (app_desc's
 * takes_reversed_z).
 */
#ifndef COMMON_GBUFFER_H
#define COMMON_GBUFFER_H

#include "fbo.h"
#include "gbuffer_layout_names.h"
#include "gl_util.h"
#include "gpu_scene.h"

/* position RGBA16F (8) + normal RGBA16F (8) + albedo RGBA8 (4) + depth 32 bit (4) */
#define GBUFFER_NAIVE_BYTES 24

typedef enum gbuffer_depth {
    GBUFFER_DEPTH_D24S8,
    GBUFFER_DEPTH_D32F,
    GBUFFER_DEPTH_D32F_REVERSED,
} gbuffer_depth;

/* gbuffer_layouts[] holds one per gbuffer_layout_id (gbuffer_layout_names.h, whose one list of
 * names the command line offers too). */
typedef struct gbuffer_layout {
    GLenum albedo_format; /* RT0 */
    GLenum normal_format; /* RT1 */
    int normal_encoding;  /* SHADER_GBUFFER_NORMAL_* */
    gbuffer_depth depth;
    const char *loses;    /* against the geometry pass's exact floats, in a few words */
} gbuffer_layout;

#define GBUFFER_LAYOUT_DEFAULT GBUFFER_LAYOUT_COMPACT

extern const gbuffer_layout gbuffer_layouts[GBUFFER_LAYOUT_COUNT];

/* Options; zero is the default. */
typedef struct gbuffer_desc {
    bool stencil; /* a depth-stencil target (D24S8, or D32F_S8 for a float depth) */
    const gbuffer_layout *layout; /* NULL: gbuffer_default_layout() */
    int samples;  /* > 1: multisampled targets (chapter 13); 0, 1: plain textures */
    bool emissive; /* RT2, emissive (also made when gbuffer_default_emissive() is on) */
} gbuffer_desc;

#define GBUFFER_EMISSIVE_FORMAT GL_RGBA16F

typedef struct gbuffer {
    fbo fbo;        /* color[0] albedo, color[1] normal/material, [color[2] emissive], depth (and stencil) */
    GLuint program; /* geometry pass */
    gbuffer_desc desc; /* desc.layout is never NULL once created */
    fbo depth_copy; /* with desc.stencil: the depth, copied after the geometry pass, for the shaders */
} gbuffer;

bool gbuffer_create(gbuffer *g, int width, int height);
bool gbuffer_create_with(gbuffer *g, int width, int height, const gbuffer_desc *desc);
bool gbuffer_create_pass(gbuffer *g, const gbuffer_desc *desc);
void gbuffer_attach_stencil(const gbuffer *g, GLuint framebuffer);
bool gbuffer_follow_target(const gbuffer *g, fbo *target, GLenum format, const char *name);
bool gbuffer_resize(gbuffer *g, int width, int height);
void gbuffer_destroy(gbuffer *g);
bool gbuffer_render(gbuffer *g, const gpu_scene *gs);
void gbuffer_bind_textures(const gbuffer *g, const gpu_scene *gs, GLuint program, int first_unit);
int gbuffer_bytes_per_pixel(void);
int gbuffer_pixel_bytes(const gbuffer *g);
double gbuffer_memory_bytes(const gbuffer *g);
bool gbuffer_scene_emits(const scene *s);
void gbuffer_set_default_emissive(bool on);
bool gbuffer_default_emissive(void);

const gbuffer_layout *gbuffer_layout_find(const char *name);
const char *gbuffer_layout_name(const gbuffer_layout *layout);
int gbuffer_layout_bytes(const gbuffer_layout *layout, bool stencil);
GLenum gbuffer_layout_depth_format(const gbuffer_layout *layout, bool stencil);
bool gbuffer_layout_available(const gbuffer_layout *layout);
bool gbuffer_set_default_layout(const gbuffer_layout *layout);
const gbuffer_layout *gbuffer_default_layout(void);
bool gbuffer_layout_holds_pbr(const gbuffer_layout *layout);
const gbuffer_layout *gbuffer_layout_for_scene(const gbuffer_layout *layout, const scene *s);
const gbuffer_layout *gbuffer_layout_for_chapter(const gbuffer_layout *layout, const scene *s,
                                                 bool prefers_reversed_z);
bool gbuffer_layout_fits_pass(const gbuffer_layout *layout, const gl_pass_state *pass);

void gbuffer_layout_depth_begin(const gbuffer_layout *layout, const gpu_scene *gs, gpu_scene *view,
                                gl_pass_state *state);
void gbuffer_layout_depth_end(const gbuffer_layout *layout);
void gbuffer_layout_bind_depth(const gbuffer_layout *layout, const gpu_scene *gs, GLuint program);
void gbuffer_depth_test_begin(const gbuffer *g, const gpu_scene *gs, gpu_scene *view, gl_pass_state *state);
void gbuffer_depth_test_end(const gbuffer *g);

#endif
