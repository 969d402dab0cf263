/* forward.c - see forward.h. */
#include "forward.h"

#include "frame_timer.h"
#include "gl_program.h"
#include "gl_util.h"
#include "log.h"

#include <stdlib.h>
#include <string.h>

/* Chapter 12's glass passes: blended over what lies behind (straight alpha: A * source +
 * (1 - A) * destination), tested against the opaque depth, never writing it; an object's far side
 * (back faces) first, then its near side. */
const gl_pass_state forward_glass_back_pass = {
    .blend = {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA}, .cull = GL_FRONT, .depth_func = GL_LEQUAL};
const gl_pass_state forward_glass_front_pass = {
    .blend = {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA}, .cull = GL_BACK, .depth_func = GL_LEQUAL};
const gl_pass_state *const forward_glass_passes[2] = {&forward_glass_back_pass, &forward_glass_front_pass};

const forward_variant forward_variants[FORWARD_VARIANT_COUNT] = {
    {"forward", {.prepass = true, .light_lists = true}}, /* chapter 00's default */
    {"forward-naive", {0}},                            /* every object with every light, one pass */
    {"forward-prepass", {.prepass = true}},
    {"forward-lists", {.light_lists = true}},
};

const forward_options *forward_variant_find(const char *name)
{
    for (int i = 0; name && i < FORWARD_VARIANT_COUNT; i++)
        if (strcmp(forward_variants[i].name, name) == 0)
            return &forward_variants[i].options;
    return NULL;
}

/* One of the shading programs with the extra as it is now (built on first use, then kept). */
static GLuint shading_program(forward *f, forward_program which)
{
    static const char *const defines[FORWARD_PROGRAM_COUNT] = {NULL, "OUTPUT_LINEAR 1", "TRANSPARENT 1"};
    return gl_program_variant(&f->shading[which], "forward.vert", "forward.frag", defines[which], &f->extra);
}

void forward_set_extra(forward *f, const gl_program_extra *extra)
{
    f->extra = extra ? *extra : (gl_program_extra){0};
}

bool forward_create(forward *f)
{
    return forward_create_with(f, NULL);
}

bool forward_create_with(forward *f, const gl_program_extra *extra)
{
    memset(f, 0, sizeof *f);
    if (extra)
        f->extra = *extra;
    f->depth_program = gl_program_load("forward.vert", "depth_only.frag", NULL);
    if (!shading_program(f, FORWARD_PROGRAM_LIT) || !f->depth_program) {
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
    for (int i = 0; i < FORWARD_PROGRAM_COUNT; i++)
        gl_program_variants_destroy(&f->shading[i]);
    gl_program_destroy(&f->depth_program);
    present_pass_destroy(&f->present);
    fbo_destroy(&f->hdr);
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

/* What both shading programs read: the lights, the objects, the light lists, the eye. */
static void bind_shading(const forward *f, const gpu_scene *gs, GLuint program, bool light_lists)
{
    glUseProgram(program);
    gpu_scene_bind_lights(gs, program, SHADER_UNIT_LIGHTS);
    gpu_scene_bind_objects(gs, program, SHADER_UNIT_OBJECTS);
    glActiveTexture(GL_TEXTURE0 + SHADER_UNIT_LIGHT_LIST);
    glBindTexture(GL_TEXTURE_BUFFER, f->list_texture);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(glGetUniformLocation(program, "u_light_list"), SHADER_UNIT_LIGHT_LIST);
    glUniform3fv(glGetUniformLocation(program, "u_eye"), 1, gs->view.eye);
    glUniform1i(glGetUniformLocation(program, "u_use_list"), light_lists);
    gl_program_extra_bind(&f->extra, program);
}

/* The opaque objects, with the caller's depth state (chapter 00's pass 3). */
static bool draw_opaque(forward *f, const gpu_scene *gs, forward_options options)
{
    GLuint program = shading_program(f, options.linear_output ? FORWARD_PROGRAM_LINEAR : FORWARD_PROGRAM_LIT);
    if (!program)
        return false;
    frame_timer_mark("shading");
    bind_shading(f, gs, program, options.light_lists);
    gl_samples_begin(f->query, options.count_pixels);
    gpu_scene_draw(gs, program);
    f->shaded_pixels = gl_samples_end(f->query, options.count_pixels);
    return true;
}

bool forward_draw_transparent(forward *f, const gpu_scene *gs, const forward_glass *glass)
{
    GLuint program = shading_program(f, FORWARD_PROGRAM_GLASS);
    if (!program)
        return false;
    frame_timer_mark("transparent");
    bind_shading(f, gs, program, glass->light_lists);
    glUniform1i(glGetUniformLocation(program, "u_view"),
                glass->overdraw ? SHADER_VIEW_OVERDRAW : SHADER_VIEW_LIT);
    const gl_pass_state *const *passes = glass->passes ? glass->passes : forward_glass_passes;
    int pass_count = glass->passes ? glass->pass_count : 2;
    gl_samples_begin(f->query, glass->count_pixels);
    gpu_scene_draw_transparent(gs, program, glass->order, passes, pass_count);
    f->shaded_pixels = gl_samples_end(f->query, glass->count_pixels);
    gl_pass_state_reset();
    return true;
}

/* The opaque objects, then the glass over them, into the (float) framebuffer bound. */
static bool draw_opaque_then_glass(forward *f, const gpu_scene *gs, forward_options options)
{
    if (!draw_opaque(f, gs, options))
        return false;
    long opaque = f->shaded_pixels;
    const forward_glass glass = {.light_lists = options.light_lists, .count_pixels = options.count_pixels};
    if (!forward_draw_transparent(f, gs, &glass))
        return false;
    if (options.count_pixels)
        f->shaded_pixels += opaque;
    return true;
}

/* Depth from one framebuffer to another (both GL_DEPTH_COMPONENT32F), whatever the depth mask. */
static void copy_depth(GLuint from, GLuint to, int width, int height)
{
    GLboolean mask;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &mask);
    glDepthMask(GL_TRUE);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, from);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, to);
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    glDepthMask(mask);
}

/* f->hdr at the view's size, and the present program (scenes with glass only). */
static bool hdr_follow_view(forward *f, int width, int height)
{
    if (!f->present.program && !present_pass_create(&f->present))
        return false;
    if (f->hdr.id && f->hdr.width == width && f->hdr.height == height)
        return true;
    fbo_destroy(&f->hdr);
    const fbo_desc desc = {.color_formats = {GL_RGBA32F},
                           .color_count = 1,
                           .depth_format = GL_DEPTH_COMPONENT32F,
                           .name = "forward linear radiance"};
    return fbo_create(&f->hdr, &desc, width, height);
}

bool forward_draw_linear(forward *f, const gpu_scene *gs, bool (*draw)(void *user, const gpu_scene *gs), void *user)
{
    GLint bound = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
    GLuint target = (GLuint)bound;
    int w = gs->view.width, h = gs->view.height;
    if (!hdr_follow_view(f, w, h))
        return false;
    copy_depth(target, f->hdr.id, w, h); /* cleared, or the pre-pass's */
    glBindFramebuffer(GL_FRAMEBUFFER, f->hdr.id);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    if (!draw(user, gs))
        return false;

    frame_timer_mark("present");
    gl_pass_state_apply(&(gl_pass_state){0}); /* no depth test: the target's depth is copied below */
    present_pass_draw(&f->present, f->hdr.color[0], target, w, h, NULL);
    copy_depth(f->hdr.id, target, w, h);
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    gl_pass_state_reset();
    return true;
}

/* Forward's own frame with glass, through forward_draw_linear. */
typedef struct linear_frame {
    forward *f;
    forward_options options;
} linear_frame;

static bool draw_linear_frame(void *user, const gpu_scene *gs)
{
    linear_frame *l = user;
    return draw_opaque_then_glass(l->f, gs, l->options);
}

bool forward_draw_shaded(forward *f, const gpu_scene *gs, forward_options options)
{
    if (gs->transparent_count == 0)
        return draw_opaque(f, gs, options);
    if (options.linear_output)
        return draw_opaque_then_glass(f, gs, options);
    linear_frame l = {f, options};
    l.options.linear_output = true;
    return forward_draw_linear(f, gs, draw_linear_frame, &l);
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

double forward_lights_per_pixel(const forward *f, const gpu_scene *gs, bool light_lists)
{
    int objects = gs->src->object_count;
    return light_lists && objects > 0 ? (double)f->list_entries / objects : gs->light_count;
}

long forward_shaded_pixels(const forward *f) { return f->shaded_pixels; }
