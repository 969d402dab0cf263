/* app_embed.c - see app_embed.h. */
#include "app_embed.h"

#include "app_internal.h"
#include "exit_code.h"
#include "gbuffer.h"
#include "gl_program.h"
#include "gl_util.h"
#include "log.h"

#include <stdlib.h>
#include <string.h>

enum { EMBED_ARGS_MAX = 32, EMBED_OPEN_MAX = 32 };

struct app_embed {
    const app_desc *desc;
    const char *renderers_plus[APP_RENDERERS_MAX];
    cli_desc cli;
    cli_options opt;
    char *argv[EMBED_ARGS_MAX + 1]; /* the arguments the options point into */
    app a;
    fbo linear_target; /* RGBA32F + depth: a frame drawn with linear output */
    bool have_init;
    bool no_linear; /* a frame with linear output was asked for and not drawn: do not ask again */
    const gbuffer_layout *saved_layout; /* the default layout before a metallic-roughness scene changed it */
    bool saved_emissive;                /* whether the default G-buffer had RT2 (emissive) before */
    char saved_defines[512];            /* the scene defines programs got before (gl_program.h) */
};

/* The chapters open now: each keeps its passes in file-static state. */
static const app_desc *open_chapters[EMBED_OPEN_MAX];

static bool mark_open(const app_desc *desc, bool open)
{
    for (int i = 0; i < EMBED_OPEN_MAX; i++)
        if (open_chapters[i] == (open ? NULL : desc)) {
            open_chapters[i] = open ? desc : NULL;
            return true;
        }
    return false;
}

static bool is_open(const app_desc *desc)
{
    for (int i = 0; i < EMBED_OPEN_MAX; i++)
        if (open_chapters[i] == desc)
            return true;
    return false;
}

static void free_args(char **argv)
{
    for (int i = 0; argv[i]; i++)
        free(argv[i]);
    memset(argv, 0, (EMBED_ARGS_MAX + 1) * sizeof *argv);
}

/* args parsed with the chapter's command line into opt; argv keeps the strings opt points into. */
static bool parse_args(app_embed *e, const char *const *args, char **argv, cli_options *opt)
{
    int argc = 0;
    argv[argc++] = strdup(e->cli.program);
    for (int i = 0; args && args[i]; i++) {
        if (argc == EMBED_ARGS_MAX) {
            log_error("%s: more than %d embedded arguments", e->cli.program, EMBED_ARGS_MAX - 1);
            return false;
        }
        argv[argc++] = strdup(args[i]);
    }
    for (int i = 0; i < argc; i++)
        if (!argv[i]) {
            log_error("out of memory for %s's arguments", e->cli.program);
            return false;
        }
    return cli_parse(argc, argv, &e->cli, opt) == EXIT_CODE_OK;
}

bool app_embed_open(const app_desc *desc, const char *const *args, const gpu_scene *gs, app_embed **out)
{
    *out = NULL;
    if (is_open(desc)) {
        log_error("%s is embedded already: a chapter is open once at a time", desc->cli->program);
        return false;
    }
    app_embed *e = calloc(1, sizeof *e);
    if (!e || !mark_open(desc, true)) {
        log_error("cannot embed %s: out of memory or too many chapters open", desc->cli->program);
        free(e);
        return false;
    }
    e->desc = desc;
    e->saved_emissive = gbuffer_default_emissive();
    /* the caller's scene defines come back on close */
    snprintf(e->saved_defines, sizeof e->saved_defines, "%s", gl_program_scene_defines());
    e->cli = app_cli_of(desc, e->renderers_plus);
    app *a = &e->a;
    bool ok = parse_args(e, args, e->argv, &e->opt);
    if (ok) {
        app_init(a, &e->cli, &e->opt);
        a->width = gs->view.width, a->height = gs->view.height;
        a->scene = *gs->src; /* a view of the caller's scene: never destroyed here */
        a->gs = *gs;
        ok = app_scene_features(a); /* the scene's features for the chapter's programs */
        a->query = gl_query_create();
        /* --gbuffer as the runner takes it; a scene with metallic-roughness materials is drawn with a
         * layout that holds them. The layout before is restored on close. */
        const gbuffer_layout *asked = e->opt.gbuffer ? gbuffer_layout_find(e->opt.gbuffer) : NULL;
        const gbuffer_layout *layout = gbuffer_layout_for_chapter(asked, gs->src, desc->prefers_reversed_z);
        ok = ok && layout != NULL;
        /* An emissive scene's G-buffers get RT2; restored on close, as the layout is. */
        gbuffer_set_default_emissive(gbuffer_scene_emits(gs->src));
        if (ok && layout != gbuffer_default_layout()) {
            e->saved_layout = gbuffer_default_layout();
            ok = gbuffer_set_default_layout(layout);
        }
        ok = ok && (!desc->accepts_scene || desc->accepts_scene(a)) && app_target_make(a) &&
             (!desc->init || (e->have_init = desc->init(a)));
    }
    if (!ok) {
        app_embed_close(e);
        return false;
    }
    *out = e;
    return true;
}

/* The choices a learner switches at run time; the chapter's own options must stay as opened. */
bool app_embed_choose(app_embed *e, const char *const *args)
{
    char *argv[EMBED_ARGS_MAX + 1] = {0};
    cli_options opt;
    bool ok = parse_args(e, args, argv, &opt);
    for (int i = 0; ok && i < CLI_MAX_EXTRAS && e->cli.extras[i].name; i++) {
        const char *now = e->opt.extra_values[i], *asked = opt.extra_values[i];
        if ((now || asked) && (!now || !asked || strcmp(now, asked) != 0)) {
            log_error("%s: --%s is read when the chapter opens: open it again to change it", e->cli.program,
                      e->cli.extras[i].name);
            ok = false;
        }
    }
    if (!ok) {
        free_args(argv);
        return false;
    }
    free_args(e->argv);
    memcpy(e->argv, argv, sizeof argv);
    e->opt = opt;
    e->no_linear = false;
    e->a.renderer = e->cli.renderers ? cli_choice_index(e->cli.renderers, opt.renderer) : 0;
    e->a.view = e->cli.views ? cli_choice_index(e->cli.views, opt.view) : 0;
    return true;
}

/* The caller's frame, at its size, with --falloff over the scene's model. */
static bool follow_scene(app_embed *e, const gpu_scene *gs)
{
    app *a = &e->a;
    a->scene = *gs->src; /* the caller may change scenes between frames */
    a->gs = *gs;
    if (e->opt.falloff)
        a->gs.falloff = strcmp(e->opt.falloff, "windowed") == 0 ? SHADER_FALLOFF_WINDOWED : SHADER_FALLOFF_HARD;
    if (a->width == gs->view.width && a->height == gs->view.height)
        return true;
    a->width = gs->view.width, a->height = gs->view.height;
    return app_target_make(a) && (!e->desc->resize || e->desc->resize(a));
}

static bool draw(app_embed *e, const gpu_scene *gs, bool count, bool linear)
{
    app *a = &e->a;
    if (!follow_scene(e, gs))
        return false;
    e->opt.bench = count; /* an embedded frame counts as a --bench frame does (app_render_forward) */
    a->count_pixels = count;
    a->shaded_pixels = -1;
    a->lights_per_pixel = 1.0;
    a->linear_output = linear;
    a->linear_written = false;
    a->linear = NULL;
    bool ok = e->desc->frame(a);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    a->frame_index++;
    return ok;
}

bool app_embed_frame(app_embed *e, const gpu_scene *gs, bool count, app_embed_work *work)
{
    bool ok = draw(e, gs, count, false);
    if (work)
        *work = (app_embed_work){e->a.shaded_pixels, e->a.lights_per_pixel};
    return ok;
}

const fbo *app_embed_target(const app_embed *e) { return &e->a.target; }

/* One frame with linear output, into linear_target in place of the target. */
static bool draw_linear(app_embed *e, const gpu_scene *gs)
{
    app *a = &e->a;
    const fbo_desc d = {.color_formats = {GL_RGBA32F}, .color_count = 1, .depth_format = GL_DEPTH_COMPONENT32F,
                        .name = "linear target"};
    if ((e->linear_target.width != gs->view.width || e->linear_target.height != gs->view.height) &&
        (fbo_destroy(&e->linear_target), !fbo_create(&e->linear_target, &d, gs->view.width, gs->view.height)))
        return false;
    fbo target = a->target;
    a->target = e->linear_target;
    bool ok = draw(e, gs, false, true) && a->linear_written;
    a->target = target;
    return ok;
}

bool app_embed_read_linear(app_embed *e, const gpu_scene *gs, float *rgba)
{
    const fbo *src = e->a.linear;
    if (!src && (e->no_linear || !draw_linear(e, gs))) {
        e->no_linear = true;
        return false;
    }
    return fbo_read_float(src ? src : &e->linear_target, 0, rgba);
}

void app_embed_close(app_embed *e)
{
    if (!e)
        return;
    if (e->have_init && e->desc->cleanup)
        e->desc->cleanup(&e->a);
    app_forward_destroy(&e->a.forward);
    fbo_destroy(&e->linear_target);
    fbo_destroy(&e->a.target);
    gl_query_destroy(&e->a.query);
    free_args(e->argv);
    if (e->saved_layout)
        gbuffer_set_default_layout(e->saved_layout);
    gbuffer_set_default_emissive(e->saved_emissive);
    gl_program_set_scene_defines(e->saved_defines);
    mark_open(e->desc, false);
    free(e);
}
