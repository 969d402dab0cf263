/* input_script.c - see input_script.h. */
#include "input_script.h"

#include "data_dir.h"
#include "image.h"

#include "input.h"
#include "keys.h"
#include "log.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define SCRIPT_LINE_MAX 1024
#define SCRIPT_BYTES_MAX (64L << 20) /* a file larger than this is no hand-written script */

static const char *const kind_names[] = {
    [SCRIPT_KEY] = "key",         [SCRIPT_DOWN] = "down",       [SCRIPT_UP] = "up",
    [SCRIPT_MOVE] = "move",       [SCRIPT_PRESS] = "press",     [SCRIPT_RELEASE] = "release",
    [SCRIPT_SCROLL] = "scroll",   [SCRIPT_SCREENSHOT] = "screenshot", [SCRIPT_OVERLAY] = "overlay",
    [SCRIPT_OBJECTS_MARK] = "objects", [SCRIPT_QUIT] = "quit",
};

#define SCRIPT_PATH_MAX 255

/* One line's event, before its frame range is expanded. */
typedef struct parsed {
    long first, last;
    script_event ev;
    char path[SCRIPT_PATH_MAX + 1];
} parsed;

/* The whole of `text` as a number in [lo, hi] (the command line's rules; cli.c reads scripts, so
 * this file does not include it). */
static bool parse_number(const char *text, double lo, double hi, bool whole, double *out)
{
    char *end;
    errno = 0;
    double v = whole ? (double)strtol(text, &end, 10) : strtod(text, &end);
    if (errno || end == text || *end || !isfinite(v) || v < lo || v > hi)
        return false;
    *out = v;
    return true;
}

static bool parse_frames(const char *word, long *first, long *last)
{
    char head[32];
    const char *dash = strchr(word, '-');
    size_t n = dash ? (size_t)(dash - word) : strlen(word);
    if (n == 0 || n >= sizeof head)
        return false;
    memcpy(head, word, n), head[n] = '\0';
    double a = 0, b = 0;
    if (!parse_number(head, 0, SCRIPT_FRAME_MAX, true, &a) || (dash && !parse_number(dash + 1, a, SCRIPT_FRAME_MAX, true, &b)))
        return false;
    *first = (long)a, *last = dash ? (long)b : (long)a;
    return true;
}

static bool parse_button(const char *word, int *button)
{
    *button = word && strcmp(word, "left") == 0 ? INPUT_BUTTON_LEFT : word && strcmp(word, "right") == 0 ? INPUT_BUTTON_RIGHT : -1;
    return *button >= 0;
}

/* The arguments of `kind` from the words after it; false with *why set when they are wrong. */
static bool parse_args(parsed *line, char **w, int n, const char **why)
{
    script_event *ev = &line->ev;
    double x = 0.0, y = 0.0;
    switch (ev->kind) {
    case SCRIPT_KEY:
    case SCRIPT_DOWN:
    case SCRIPT_UP:
        *why = "expected a key of the key table (W, Space, Home, F1, PgUp, +, ...)";
        return n == 1 && (ev->code = keys_code(w[0])) != 0;
    case SCRIPT_MOVE:
        *why = "expected X Y, framebuffer pixels";
        if (n != 2 || !parse_number(w[0], -1e6, 1e6, false, &x) || !parse_number(w[1], -1e6, 1e6, false, &y))
            return false;
        ev->x = x, ev->y = y;
        return true;
    case SCRIPT_PRESS:
    case SCRIPT_RELEASE: *why = "expected left or right"; return n == 1 && parse_button(w[0], &ev->code);
    case SCRIPT_SCROLL:
        *why = "expected wheel steps";
        return n == 1 && parse_number(w[0], -1e3, 1e3, false, &ev->y);
    case SCRIPT_SCREENSHOT:
        *why = "expected a file name ending in .png, .bmp, .tga or .jpg";
        if (n != 1 || strlen(w[0]) > SCRIPT_PATH_MAX || image_format_of(w[0]) == IMAGE_UNKNOWN)
            return false;
        strcpy(line->path, w[0]);
        return true;
    case SCRIPT_OBJECTS_MARK:
        *why = "expected mark or check";
        if (n == 1 && strcmp(w[0], "check") == 0)
            ev->kind = SCRIPT_OBJECTS_CHECK;
        return n == 1 && (strcmp(w[0], "mark") == 0 || strcmp(w[0], "check") == 0);
    default: *why = "expected nothing after it"; return n == 0;
    }
}

/* One non-empty line; false with the reason logged as name:line. */
static bool parse_line(char *line, const char *name, int number, parsed *out)
{
    char *w[8];
    int n = 0;
    for (char *t = strtok(line, " \t\r\n"); t && n < 8; t = strtok(NULL, " \t\r\n"))
        w[n++] = t;
    if (n < 2 || !parse_frames(w[0], &out->first, &out->last)) {
        log_error("%s:%d: expected FRAME[-LAST] ACTION [ARGS] (frames 0..%ld)", name, number, SCRIPT_FRAME_MAX);
        return false;
    }
    memset(&out->ev, 0, sizeof out->ev);
    out->ev.line = number;
    size_t k = 0;
    while (k < sizeof kind_names / sizeof kind_names[0] && !(kind_names[k] && strcmp(kind_names[k], w[1]) == 0))
        k++;
    if (k == sizeof kind_names / sizeof kind_names[0]) {
        log_error("%s:%d: unknown action '%s' (key, down, up, move, press, release, scroll, screenshot, overlay, "
                  "objects, quit)", name, number, w[1]);
        return false;
    }
    out->ev.kind = (script_kind)k;
    const char *why = "";
    if (!parse_args(out, w + 2, n - 2, &why)) {
        log_error("%s:%d: %s: %s", name, number, w[1], why);
        return false;
    }
    return true;
}

static bool append(input_script *s, parsed *p, int *cap)
{
    if (p->ev.kind == SCRIPT_SCREENSHOT) { /* one copy of the file name for the whole range */
        char found[4400], why[9200];
        if (!data_dir_find_output(p->path, found, sizeof found, why, sizeof why)) {
            log_error("%s:%d: screenshot: cannot write %s: %s", s->name, p->ev.line, p->path, why);
            return false;
        }
        char **grown = realloc(s->paths, (size_t)(s->path_count + 1) * sizeof *grown);
        char *copy = grown ? strdup(found) : NULL;
        if (grown)
            s->paths = grown;
        if (!copy) {
            log_error("%s:%d: out of memory", s->name, p->ev.line);
            return false;
        }
        s->paths[s->path_count++] = copy;
        p->ev.path = copy;
    }
    for (long f = p->first; f <= p->last; f++) {
        if (s->count == *cap) {
            /* The limit is checked before the allocation and holds exactly: the last growth
             * stops at SCRIPT_EVENTS_MAX rather than doubling past it. */
            if (*cap == SCRIPT_EVENTS_MAX) {
                log_error("%s:%d: more than %d events (a FRAME-LAST range counts one event per frame)", s->name,
                          p->ev.line, SCRIPT_EVENTS_MAX);
                return false;
            }
            int grown_cap = *cap ? (*cap > SCRIPT_EVENTS_MAX / 2 ? SCRIPT_EVENTS_MAX : *cap * 2) : 64;
            script_event *grown = realloc(s->events, (size_t)grown_cap * sizeof *grown);
            if (!grown) {
                log_error("%s:%d: out of memory for %d events", s->name, p->ev.line, grown_cap);
                return false;
            }
            s->events = grown, *cap = grown_cap;
        }
        s->events[s->count] = p->ev;
        s->events[s->count++].frame = f;
    }
    return true;
}

/* By frame, then by line: a stable order without relying on qsort's stability. */
static int by_frame(const void *x, const void *y)
{
    const script_event *a = x, *b = y;
    if (a->frame != b->frame)
        return a->frame < b->frame ? -1 : 1;
    return (a->line > b->line) - (a->line < b->line);
}

bool input_script_parse(const char *text, const char *name, input_script *s)
{
    memset(s, 0, sizeof *s);
    snprintf(s->name, sizeof s->name, "%s", name);
    int cap = 0, number = 0;
    for (const char *p = text; *p;) {
        const char *end = strchr(p, '\n');
        size_t len = end ? (size_t)(end - p) : strlen(p);
        char line[SCRIPT_LINE_MAX];
        number++;
        if (len >= sizeof line) {
            log_error("%s:%d: line longer than %d characters", name, number, SCRIPT_LINE_MAX - 1);
            input_script_destroy(s);
            return false;
        }
        memcpy(line, p, len), line[len] = '\0';
        p += len + (end != NULL);
        char *hash = strchr(line, '#');
        if (hash)
            *hash = '\0';
        if (strspn(line, " \t\r") == strlen(line))
            continue;
        parsed one;
        if (!parse_line(line, name, number, &one) || !append(s, &one, &cap)) {
            input_script_destroy(s);
            return false;
        }
    }
    if (s->count > 0)
        qsort(s->events, (size_t)s->count, sizeof *s->events, by_frame);
    /* A check compares with the count its mark remembered: without a mark before it (an earlier
     * frame, or an earlier line of the same frame) it would compare with nothing. */
    for (int i = 0; i < s->count && s->events[i].kind != SCRIPT_OBJECTS_MARK; i++)
        if (s->events[i].kind == SCRIPT_OBJECTS_CHECK) {
            log_error("%s:%d: objects check: no 'objects mark' before it (at an earlier frame, or earlier in "
                      "frame %ld) to compare with", name, s->events[i].line, s->events[i].frame);
            input_script_destroy(s);
            return false;
        }
    return true;
}

bool input_script_load(const char *path, input_script *s)
{
    memset(s, 0, sizeof *s);
    struct stat st;
    const char *why;
    FILE *f = data_dir_open_input(path, &why); /* checked on the open file: a pipe is never waited on */
    if (!f) {
        bool folder = stat(path, &st) == 0 && S_ISDIR(st.st_mode);
        log_error("%s: cannot open script: %s%s", path, why, folder ? " (a folder)" : "");
        return false;
    }
    if (fstat(fileno(f), &st) == 0 && st.st_size > SCRIPT_BYTES_MAX) {
        log_error("%s: script of %lld bytes: more than the %ld a script may hold", path, (long long)st.st_size,
                  SCRIPT_BYTES_MAX);
        fclose(f);
        return false;
    }
    size_t cap = 1 << 16, len = 0;
    char *text = malloc(cap);
    for (size_t got = 1; text && got > 0;) {
        if (len + 1 == cap) {
            char *grown = cap < (1u << 26) ? realloc(text, cap * 2) : NULL;
            if (!grown) {
                free(text), text = NULL;
                break;
            }
            text = grown, cap *= 2;
        }
        got = fread(text + len, 1, cap - 1 - len, f);
        len += got;
    }
    fclose(f);
    if (!text) {
        log_error("%s: script too large or out of memory", path);
        return false;
    }
    text[len] = '\0';
    bool ok = input_script_parse(text, path, s);
    free(text);
    return ok;
}

void input_script_destroy(input_script *s)
{
    for (int i = 0; i < s->path_count; i++)
        free(s->paths[i]);
    free(s->paths);
    free(s->events);
    s->paths = NULL;
    s->events = NULL;
    s->count = s->path_count = 0;
}

void input_script_range(const input_script *s, long frame, int *first, int *count)
{
    int lo = 0, hi = s->count;
    while (lo < hi) { /* the first event at or after `frame` */
        int mid = (lo + hi) / 2;
        if (s->events[mid].frame < frame)
            lo = mid + 1;
        else
            hi = mid;
    }
    int end = lo;
    while (end < s->count && s->events[end].frame == frame)
        end++;
    *first = lo, *count = end - lo;
}

void input_script_feed(const input_script *s, long frame)
{
    int first, count;
    input_script_range(s, frame, &first, &count);
    for (int i = first; i < first + count; i++) {
        const script_event *e = &s->events[i];
        switch (e->kind) {
        case SCRIPT_KEY: input_key(e->code, true), input_key(e->code, false); break;
        case SCRIPT_DOWN: input_key(e->code, true); break;
        case SCRIPT_UP: input_key(e->code, false); break;
        case SCRIPT_MOVE: input_mouse_move(e->x, e->y); break;
        case SCRIPT_PRESS: input_mouse_button(e->code, true); break;
        case SCRIPT_RELEASE: input_mouse_button(e->code, false); break;
        case SCRIPT_SCROLL: input_scroll(e->y); break;
        default: break; /* the runner's, after the frame */
        }
    }
}

long input_script_last_frame(const input_script *s) { return s->count > 0 ? s->events[s->count - 1].frame : -1; }
