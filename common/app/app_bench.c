/* app_bench.c - the runner's one `bench: key=value ...` line of --bench (app_internal.h). */
#include "app_internal.h"

#include "frame_stats.h"
#include "gl_program.h"
#include "gl_util.h"
#include "platform.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* key=value output keeps values free of spaces. */
static void print_token(const char *s)
{
    for (; s && *s; s++)
        putchar(*s == ' ' || *s == '\t' || *s == '=' ? '_' : *s);
}

/* The scene file's name without directory and extension. */
static void print_scene_name(const char *path)
{
    char name[256];
    const char *slash = strrchr(path, '/');
    snprintf(name, sizeof name, "%s", slash ? slash + 1 : path);
    char *dot = strrchr(name, '.');
    if (dot)
        *dot = '\0';
    print_token(name);
}

/* " geometry_ms=3.100 lighting_ms=8.200 ... pass_clock=gpu-timer": each pass's median. */
static void print_passes(const app *a, const double *pass_ms, int n)
{
    double *column = malloc((size_t)n * sizeof *column);
    for (int k = 0; column && k < a->timer.last.count; k++) {
        for (int i = 0; i < n; i++)
            column[i] = pass_ms[i * FRAME_TIMER_MAX_PASSES + k];
        putchar(' ');
        print_token(a->timer.last.names[k]);
        printf("_ms=%.3f", frame_stats_of(column, n).median);
    }
    free(column);
    printf(" pass_clock=%s", frame_timer_clock(&a->timer));
}

/* "programs: compiled=N vert+frag[DEFINES] ...": every program the run built, with its own defines
 * (the scene's are the bench line's features), so a reader sees the variants a scene asked for. */
static void print_programs(void)
{
    const gl_program_info *list;
    int n = gl_program_compiled(&list);
    printf("programs: compiled=%d", gl_program_compiled_total());
    for (int i = 0; i < n; i++) {
        putchar(' ');
        for (const char *c = list[i].name; *c; c++)
            if (*c != ' ')
                putchar(*c);
        /* "SHADOWS 1 GBUFFER_NORMAL 2" as [SHADOWS,GBUFFER_NORMAL:2] */
        char name[96], value[32];
        int used = 0;
        for (const char *d = list[i].defines; sscanf(d, "%95s %31s%n", name, value, &used) == 2; d += used)
            printf("%c%s%s%s", d == list[i].defines ? '[' : ',', name, strcmp(value, "1") ? ":" : "",
                   strcmp(value, "1") ? value : "");
        if (list[i].defines[0])
            putchar(']');
    }
    printf("\n");
}

void app_bench_print(const app *a, double *ms, double *pass_ms, int n)
{
    const frame_stats st = frame_stats_of(ms, n);
    printf("bench: chapter=%s renderer=%s scene=", a->cli->program,
           a->cli->renderers ? a->cli->renderers[a->renderer] : "forward");
    print_scene_name(a->options->scene_path);
    printf(" lights=%d active_lights=%d culled_lights=%d size=%dx%d frames=%d warmup=%d median_ms=%.3f "
           "min_ms=%.3f max_ms=%.3f mean_ms=%.3f fps=%.2f cutoff=%.6g shaded_pixels=%ld clock=glFinish+monotonic "
           "backend=%s gl_renderer=",
           a->scene.light_count, a->gs.light_count, a->gs.culled_count, a->width, a->height, n,
           a->options->warmup, st.median, st.min, st.max, st.mean, st.median > 0 ? 1000.0 / st.median : 0.0, a->cutoff,
           a->shaded_pixels, platform_backend_name());
    print_token((const char *)glGetString(GL_RENDERER));
    print_passes(a, pass_ms, n);
    char features[160];
    shader_features_describe(&a->features, features, sizeof features);
    printf(" features=%s\n", features[0] ? features : "none");
    print_programs();
    fflush(stdout);
}
