/* app_text.c - the words the window shows: its title, the overlay's lines and F1's key list, each
 * as long as it needs to be (open_memstream). (app.c and app_window.c only: app_internal.h) */
#include "app_internal.h"

#include "keys.h"
#include "log.h"
#include "platform.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- shared by the title and the overlay ------------------------------------------------------ */

/* "geometry 3.10, lighting 8.20": each pass's time over n frames, compare mode's passes left out
 * (they are not the chapter's). */
static void put_passes(const frame_times *t, int n, const char *separator, FILE *out)
{
    for (int k = 0, shown = 0; k < t->count; k++)
        if (strcmp(t->names[k], APP_COMPARE_PASS) != 0 && strcmp(t->names[k], APP_COMPOSE_PASS) != 0)
            fprintf(out, "%s%s %.2f", shown++ ? separator : "", t->names[k], t->ms[k] / n);
}

static const char *renderer_name(const app *a)
{
    return a->cli->renderers ? a->cli->renderers[a->renderer] : "forward";
}

/* " | view lit" when the frame drew the view chosen; when it could not (a forward renderer has no
 * G-buffer to show), the view it drew and, in the overlay's longer words (`explain`), why. */
static void put_view(const app *a, bool explain, FILE *out)
{
    if (!a->cli->views)
        return;
    const char *chosen = a->cli->views[a->view], *drawn = a->view_drawn ? a->view_drawn : chosen;
    fprintf(out, " | view %s", drawn);
    if (strcmp(drawn, chosen) != 0 && explain)
        fprintf(out, " (%s has no %s view: R)", renderer_name(a), chosen);
    else if (strcmp(drawn, chosen) != 0)
        fprintf(out, " (not %s)", chosen);
}

/* ---- the title ---------------------------------------------------------------------------------- */

/* The title shows the renderer and the view drawn, the frame time the timer measured (never CPU
 * submission time alone), its passes and the clock, then forward's frame in compare mode (from frames
 * that drew it); --verbose logs it too. As long as it needs to be (open_memstream). */
void app_text_title(const app *a, const frame_times *sum, int n, bool paused)
{
    char *title = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&title, &size);
    if (!f)
        return;
    const app_frame_split split = app_frame_split_of(sum);
    double ms = split.own_ms / n;
    fprintf(f, "%s | %s", a->cli->program, renderer_name(a));
    put_view(a, false, f);
    fprintf(f, " | %d lights (%d culled) | %dx%d | %.2f ms (%.0f fps; ", a->scene.light_count,
            a->gs.culled_count, a->width, a->height, ms, ms > 0 ? 1000.0 / ms : 0.0);
    put_passes(sum, n, ", ", f);
    fprintf(f, ") [%s]", frame_timer_clock(&a->timer));
    if (split.forward_timed)
        fprintf(f, " | compare: forward %.2f ms", split.forward_ms / n);
    fprintf(f, " | cut-off %.4g%s%s", a->cutoff, a->cutoff == 0 ? " (exact)" : "", paused ? " | paused" : "");
    if (fclose(f) == 0 && title) {
        platform_set_title(title);
        log_debug("window: %s", title);
    }
    free(title);
}

/* ---- the overlay and F1's list
 * ------------------------------------------------------------------------------- */

static const char *gl_name(GLenum e)
{
    switch (e) {
    case GL_FRONT: return "front";
    case GL_BACK: return "back";
    case GL_LESS: return "LESS";
    case GL_LEQUAL: return "LEQUAL";
    case GL_GREATER: return "GREATER";
    case GL_GEQUAL: return "GEQUAL";
    case GL_EQUAL: return "EQUAL";
    case GL_ALWAYS: return "ALWAYS";
    case GL_NOTEQUAL: return "NOTEQUAL";
    case GL_ONE: return "ONE";
    case GL_ZERO: return "ZERO";
    case GL_SRC_ALPHA: return "SRC_ALPHA";
    case GL_ONE_MINUS_SRC_ALPHA: return "ONE_MINUS_SRC_ALPHA";
    default: return "?";
    }
}

/* "cull front, depth GREATER (no writes), clamp, blend ONE+ONE[, stencil NOTEQUAL 0]" */
static int describe_pass(const gl_pass_state *s, char *out, size_t size)
{
    return snprintf(out, size, "cull %s, depth %s%s%s, blend %s%s%s%s%s%s",
                    s->cull ? gl_name(s->cull) : "none", s->depth_func ? gl_name(s->depth_func) : "off",
                    s->depth_write ? "" : " (no writes)", s->depth_clamp ? ", clamp" : "",
                    s->blend[0] ? gl_name(s->blend[0]) : "off", s->blend[0] ? "+" : "",
                    s->blend[0] ? gl_name(s->blend[1]) : "", s->stencil_func ? ", stencil " : "",
                    s->stencil_func ? gl_name(s->stencil_func) : "", s->stencil_func ? " 0" : "");
}

/* The frame's time split into the chapter's side and compare mode's passes. Compare mode's figure comes
 * from frames that drew forward: the half-second average while it holds them, else the last frame; a
 * frame without forward's pass (M pressed since, or the timer's queries one frame behind) says so,
 * never "forward 0.00 ms". */
static void put_times(const app_window *w, const app *a, FILE *out)
{
    /* the half-second average; the last frame's times until there is one (a single headless frame) */
    const frame_times *t = w->times.count > 0 ? &w->times : &a->timer.last;
    if (w->compare != COMPARE_OFF && !app_frame_split_of(t).forward_timed)
        t = &a->timer.last;
    const app_frame_split split = app_frame_split_of(t);
    fprintf(out, "passes (ms): ");
    put_passes(t, 1, ", ", out);
    fprintf(out, "\nframe %.2f ms = %.0f fps (clock: %s)\n", split.own_ms,
            split.own_ms > 0 ? 1000.0 / split.own_ms : 0.0, frame_timer_clock(&a->timer));
    if (w->compare == COMPARE_OFF)
        return;
    const char *renderer = renderer_name(a);
    if (split.forward_timed)
        fprintf(out, "compare %s: forward %.2f ms (left) | %s %.2f ms (right)\n",
                compare_mode_name(w->compare), split.forward_ms, renderer, split.own_ms);
    else
        fprintf(out, "compare %s: forward not timed yet (left) | %s %.2f ms (right)\n",
                compare_mode_name(w->compare), renderer, split.own_ms);
}

/* The overlay's lines, written to out. */
static void write_overlay(const app_window *w, const app *a, bool paused, FILE *out)
{
    fprintf(out, "%s | renderer %s", a->cli->program, renderer_name(a));
    put_view(a, true, out);
    fprintf(out, " | %dx%d\n", a->width, a->height);
    if (a->note)
        fprintf(out, "note: %s\n", a->note);
    fprintf(out, "lights %d active, %d culled (cut-off %.4g%s, %s falloff)\n", a->gs.light_count,
            a->gs.culled_count, a->cutoff, a->cutoff == 0 ? ": exact" : "",
            a->gs.falloff == SHADER_FALLOFF_WINDOWED ? "windowed" : "hard");
    put_times(w, a, out);
    const char *work = a->work_name ? a->work_name : "lighting fragments";
    if (a->shaded_pixels >= 0 && w->ideal > 0 && paused)
        fprintf(out, "%s %ld = %.2f x the ideal %lld (pixel, light) pairs\n", work, a->shaded_pixels,
                (double)a->shaded_pixels / (double)w->ideal, w->ideal);
    else if (a->shaded_pixels >= 0)
        fprintf(out, "%s %ld = %.2f per pixel (Space: pause to count the ideal)\n", work, a->shaded_pixels,
                (double)a->shaded_pixels / ((double)a->width * a->height));
    if (a->pass_state && !app_renderer_is_forward(a)) { /* the chapter's own renderer */
        char pass[160];
        describe_pass(a->pass_state, pass, sizeof pass); /* bounded: GL names and fixed words */
        fprintf(out, "lighting pass: %s\n", pass);
    }
    if (a->overlay_lines[0]) /* the chapter's own */
        fprintf(out, "%s\n", a->overlay_lines);
    const scene_camera *c = &a->scene.camera;
    fprintf(out, "eye %.2f %.2f %.2f  target %.2f %.2f %.2f\n", (double)c->eye[0], (double)c->eye[1],
            (double)c->eye[2], (double)c->target[0], (double)c->target[1], (double)c->target[2]);
    fprintf(out, "%sH hides this, F1 lists the keys", paused ? "PAUSED (Space resumes) | " : "");
}

/* What write_text(out) writes, as a string to free, as long as it is (open_memstream): no buffer of
 * a fixed size can cut it. NULL when out of memory (logged). */
static char *text_of(const app_window *w, const app *a, bool paused,
                     void (*write_text)(const app_window *w, const app *a, bool paused, FILE *out))
{
    char *text = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&text, &size);
    if (f) {
        write_text(w, a, paused, f);
        if (fclose(f) != 0)
            free(text), text = NULL;
    }
    if (!text)
        log_error("window: out of memory for the overlay's text");
    return text;
}

char *app_text_overlay(const app_window *w, const app *a, bool paused)
{
    return text_of(w, a, paused, write_overlay);
}

/* F1's list: the chapter's keys as --help lists them, without the blank line that starts it there. */
static void write_key_list(const app_window *w, const app *a, bool paused, FILE *out)
{
    (void)w, (void)paused;
    char *list = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&list, &size);
    if (!f)
        return;
    keys_print_help(f, a->cli->program, a->cli->views != NULL);
    if (fclose(f) == 0 && list)
        fputs(list[0] == '\n' ? list + 1 : list, out);
    free(list);
}

char *app_text_key_list(const app *a)
{
    return text_of(NULL, a, false, write_key_list);
}
