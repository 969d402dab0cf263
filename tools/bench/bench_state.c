/* bench_state.c - see bench_state.h. */
#include "bench_state.h"

#include "log.h"
#include "platform.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void read_cpu_info(bench_state *st)
{
    snprintf(st->cpu, sizeof st->cpu, "unknown CPU");
    st->cores = 0;
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (!f)
        return;
    char line[512];
    bool have_name = false;
    while (fgets(line, sizeof line, f)) {
        if (strncmp(line, "processor", 9) == 0)
            st->cores++;
        if (!have_name && strncmp(line, "model name", 10) == 0) {
            const char *colon = strchr(line, ':');
            if (colon) {
                snprintf(st->cpu, sizeof st->cpu, "%s", colon + 1 + (colon[1] == ' '));
                st->cpu[strcspn(st->cpu, "\n")] = '\0';
                have_name = true;
            }
        }
    }
    fclose(f);
}

const char *const bench_pass_names[BENCH_PASSES] = {"light lists", "depth pre-pass", "shading",
                                                    "geometry",    "lighting",       "present"};

void bench_state_read_machine(bench_state *st)
{
    read_cpu_info(st);
    snprintf(st->gl_renderer, sizeof st->gl_renderer, "%s", (const char *)glGetString(GL_RENDERER));
    snprintf(st->gl_version, sizeof st->gl_version, "%s", (const char *)glGetString(GL_VERSION));
}

bench_row *bench_state_add_row(bench_state *st)
{
    if (st->row_count == st->row_cap) {
        int cap = st->row_cap ? 2 * st->row_cap : 64;
        bench_row *rows = realloc(st->rows, (size_t)cap * sizeof *rows);
        if (!rows) {
            log_error("out of memory for %d result rows", cap);
            return NULL;
        }
        st->rows = rows, st->row_cap = cap;
    }
    bench_row *row = &st->rows[st->row_count++];
    memset(row, 0, sizeof *row);
    return row;
}

const bench_row *bench_state_find_row(const bench_state *st, const char *sweep, const char *scene_name,
                                      int renderer, bool own, int lights, double cutoff)
{
    for (int i = 0; i < st->row_count; i++) {
        const bench_row *r = &st->rows[i];
        if (strcmp(r->sweep, sweep) == 0 && strcmp(r->scene, scene_name) == 0 && r->renderer == renderer &&
            r->own_lights == own && (own || r->lights == lights) && (cutoff < 0 || r->cutoff == cutoff))
            return r;
    }
    return NULL;
}

void bench_state_destroy(bench_state *st)
{
    free(st->rows);
    st->rows = NULL;
    st->row_count = st->row_cap = 0;
}
