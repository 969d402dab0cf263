/* app_options.c - what the runner makes of the shared command line beyond common/platform/cli.c (app.c
 * only; declared in app_internal.h): the GL context's size limits and --gl-info, a --camera pose
 * laid over the scene's camera, and Forward+ offered wherever a chapter offers forward. */
#include "app_internal.h"

#include "log.h"
#include "platform.h"

#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

static int min_int(int x, int y) { return x < y ? x : y; }

/* The largest target this context can make: textures, renderbuffers and the viewport all limit it. */
typedef struct size_limits {
    GLint max_tex, max_rb, max_vp[2];
    int width, height;
} size_limits;

static size_limits query_size_limits(void)
{
    size_limits l = {0};
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &l.max_tex);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &l.max_rb);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, l.max_vp);
    l.width = min_int(min_int(l.max_tex, l.max_rb), l.max_vp[0]);
    l.height = min_int(min_int(l.max_tex, l.max_rb), l.max_vp[1]);
    return l;
}

/* --gl-info: key=value lines, so that scripts (the size tests) can ask the context; no scene. */
int app_print_gl_info(const cli_options *opt, const char *program)
{
    const platform_desc pd = {.backend = opt->backend, .width = 16, .height = 16, .title = program};
    int rc = platform_create(&pd);
    if (rc != EXIT_CODE_OK)
        return rc;
    size_limits l = query_size_limits();
    GLint draw_buffers = 0, samples = 0;
    glGetIntegerv(GL_MAX_DRAW_BUFFERS, &draw_buffers);
    glGetIntegerv(GL_MAX_SAMPLES, &samples);
    printf("gl: backend=%s max_width=%d max_height=%d max_texture_size=%d max_renderbuffer_size=%d "
           "max_viewport=%dx%d max_draw_buffers=%d max_samples=%d\n",
           platform_backend_name(), l.width, l.height, l.max_tex, l.max_rb, l.max_vp[0], l.max_vp[1],
           draw_buffers, samples);
    printf("gl: renderer=%s\n", (const char *)glGetString(GL_RENDERER));
    printf("gl: version=%s\n", (const char *)glGetString(GL_VERSION));
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    printf("gl: context=%d.%d core (the newest the driver gave, asking for 4.6 down to 3.3)\n", major, minor);
    printf("gl: compute=%s (compute shaders: core since 4.3)\n", GLAD_GL_VERSION_4_3 ? "yes" : "no");
    platform_destroy();
    return EXIT_CODE_OK;
}

bool app_check_size_limits(int width, int height)
{
    const size_limits l = query_size_limits();
    const GLint max_tex = l.max_tex, max_rb = l.max_rb, *max_vp = l.max_vp;
    const int limit_w = l.width, limit_h = l.height;
    if (width > limit_w || height > limit_h) {
        log_error("--size %dx%d is larger than this GL allows (%dx%d: GL_MAX_TEXTURE_SIZE %d, "
                  "GL_MAX_RENDERBUFFER_SIZE %d, GL_MAX_VIEWPORT_DIMS %dx%d)",
                  width, height, limit_w, limit_h, max_tex, max_rb, max_vp[0], max_vp[1]);
        return false;
    }
    return true;
}

/* The bytes a software rasteriser can still take, and where that bound comes from: the memory the
 * system has available (MemAvailable + SwapFree), or what is left of this process's address-space
 * limit (ulimit -v), whichever is smaller; 0 when neither can be read (not Linux). */
static double memory_left(const char **source)
{
    double left = 0, kb, avail = -1, swap = 0;
    char line[160];
    FILE *f = fopen("/proc/meminfo", "r");
    for (; f && fgets(line, sizeof line, f);)
        if (sscanf(line, "MemAvailable: %lf kB", &kb) == 1)
            avail = kb * 1024;
        else if (sscanf(line, "SwapFree: %lf kB", &kb) == 1)
            swap = kb * 1024;
    if (f)
        fclose(f);
    if (avail >= 0)
        left = avail + swap, *source = "memory the system has available";
    struct rlimit lim;
    double pages = 0;
    if (getrlimit(RLIMIT_AS, &lim) == 0 && lim.rlim_cur != RLIM_INFINITY && (f = fopen("/proc/self/statm", "r"))) {
        if (fscanf(f, "%lf", &pages) != 1)
            pages = 0;
        fclose(f);
        double as_left = (double)lim.rlim_cur - pages * (double)sysconf(_SC_PAGESIZE);
        if (left == 0 || as_left < left)
            left = as_left > 1 ? as_left : 1, *source = "address space left under this process's limit (ulimit -v)";
    }
    return left;
}

bool app_check_size_memory(int width, int height, bool screenshot)
{
    /* Only where GL's textures live in this process: a GPU's memory is its own, and GL does not say
     * how much of it is free. */
    const char *renderer = (const char *)glGetString(GL_RENDERER);
    if (!renderer || !(strstr(renderer, "llvmpipe") || strstr(renderer, "softpipe") || strstr(renderer, "swrast")))
        return true;
    /* A floor, so that no run that could succeed is refused: the runner's own target (RGBA8 and a
     * 32-bit depth) and the --screenshot read-back; every chapter's targets come on top (chapter 03
     * with the default G-buffer: 20 bytes a pixel in all, docs/hard-cases.md case 12). */
    const int per_pixel = 8 + (screenshot ? 4 : 0);
    const double mib = 1024.0 * 1024.0, need = (double)width * height * per_pixel;
    const char *source = "";
    const double left = memory_left(&source);
    if (left <= 0 || need <= left)
        return true;
    log_error("--size %dx%d needs at least %.0f MiB (%d bytes a pixel for the runner's own target%s, before the "
              "chapter's), more than the %.0f MiB of %s: try a smaller --size",
              width, height, need / mib, per_pixel, screenshot ? " and the screenshot" : "", left / mib, source);
    return false;
}

/* A chapter that offers `forward` offers the strongest forward too: Forward+ (chapter 11) joins its
 * list right after it, so --renderer and the R key reach it everywhere. */
const char *const *app_with_forward_plus(const char *const *list, const char **out, int capacity)
{
    int n = 0, forward_at = -1;
    for (; list && list[n]; n++)
        if (strcmp(list[n], "forward-plus") == 0)
            return list;
        else if (strcmp(list[n], "forward") == 0)
            forward_at = n;
    if (forward_at < 0 || n + 2 > capacity)
        return list;
    for (int i = 0, k = 0; i <= n; i++) {
        out[k++] = list[i];
        if (i == forward_at)
            out[k++] = "forward-plus";
    }
    return out;
}

/* True when `word` is one of the whitespace-separated tokens of `text`. */
static bool has_token(const char *text, const char *word)
{
    size_t n = strlen(word);
    for (const char *p = strstr(text, word); p; p = strstr(p + 1, word))
        if ((p == text || p[-1] == ' ' || p[-1] == '\t') && (p[n] == '\0' || p[n] == ' ' || p[n] == '\t'))
            return true;
    return false;
}

/* --camera: a camera line made of the given attributes and the scene's for the others, checked by
 * the scene parser exactly as a scene file's camera line is. */
bool app_apply_camera(scene *s, const char *given)
{
    const scene_camera *c = &s->camera;
    char line[1024];
    int n = snprintf(line, sizeof line, "camera %s", given);
    const struct {
        const char *name;
        int count;
        const float *v;
    } attrs[] = {{"eye", 3, c->eye},         {"target", 3, c->target},        {"up", 3, c->up},
                 {"fovy", 1, &c->fovy_deg}, {"near", 1, &c->near_plane}, {"far", 1, &c->far_plane}};
    for (size_t k = 0; k < sizeof attrs / sizeof attrs[0] && n > 0 && n < (int)sizeof line - 64; k++) {
        if (has_token(given, attrs[k].name))
            continue;
        n += snprintf(line + n, sizeof line - (size_t)n, " %s", attrs[k].name);
        for (int j = 0; j < attrs[k].count; j++) /* %.9g: a float survives the text exactly */
            n += snprintf(line + n, sizeof line - (size_t)n, " %.9g", (double)attrs[k].v[j]);
    }
    scene tmp;
    if (n <= 0 || n >= (int)sizeof line || !scene_parse_string(line, "--camera", "", &tmp))
        return false;
    s->camera = tmp.camera;
    scene_destroy(&tmp);
    return true;
}
