/* cluster_assign_gpu.c - see cluster_assign_gpu.h. */
#include "cluster_assign_gpu.h"

#include "gl_program.h"
#include "gl_util.h"
#include "log.h"

#include <stdlib.h>
#include <string.h>

enum { GROUP_SIZE = 64 }; /* invocations per workgroup of the count and fill passes */

bool cluster_assign_gpu_create(cluster_assign_gpu *a)
{
    memset(a, 0, sizeof *a);
    GLuint *buffers[] = {&a->sphere_buffer, &a->candidate_buffer, &a->row_buffer,
                         &a->box_buffer,    &a->cursor_buffer,    &a->hit_buffer};
    for (int i = 0; i < 6; i++)
        *buffers[i] = gl_buffer_create();
    return gl_check("cluster_assign_gpu_create");
}

void cluster_assign_gpu_destroy(cluster_assign_gpu *a)
{
    for (int i = 0; i < CLUSTER_ASSIGN_PASSES; i++)
        gl_program_destroy(&a->programs[i]);
    GLuint *buffers[] = {&a->sphere_buffer, &a->candidate_buffer, &a->row_buffer,
                         &a->box_buffer,    &a->cursor_buffer,    &a->hit_buffer};
    for (int i = 0; i < 6; i++)
        gl_buffer_destroy(buffers[i]);
    free(a->spheres), free(a->records), free(a->candidates), free(a->row_first), free(a->boxes);
    memset(a, 0, sizeof *a);
}

/* realloc to hold `need` elements of `size` bytes; false (logged) when out of memory. */
static bool grow(void **p, int *cap, long need, size_t size)
{
    if (need <= *cap)
        return true;
    long n = *cap > 0 ? *cap : 1024;
    while (n < need)
        n *= 2;
    void *q = realloc(*p, (size_t)n * size);
    if (!q) {
        log_error("out of memory for the cluster assignment");
        return false;
    }
    *p = q, *cap = (int)n;
    return true;
}

static void upload(GLuint buffer, const void *data, size_t bytes)
{
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
    glBufferData(GL_SHADER_STORAGE_BUFFER, (GLsizeiptr)(bytes > 0 ? bytes : 16), data, GL_STREAM_DRAW);
}

/* Every cluster's box, from cluster_grid_box itself, so that the shader compares with the very
 * floats the CPU's test does: x depends on the tile column and the slice only, y on the row and the
 * slice, z on the slice. Made again only when the grid changes. */
static bool box_table(cluster_assign_gpu *a, const cluster_grid *g)
{
    if (a->box_cap > 0 && memcmp(&a->box_grid, g, sizeof *g) == 0)
        return true;
    long n = 2L * g->slices * (g->tiles_x + g->tiles_y + 1);
    if (!grow((void **)&a->boxes, &a->box_cap, n, sizeof(float)))
        return false;
    float lo[3], hi[3], *x = a->boxes, *y = x + 2 * g->slices * g->tiles_x,
                        *z = y + 2 * g->slices * g->tiles_y;
    for (int k = 0; k < g->slices; k++) {
        for (int t = 0; t < g->tiles_x; t++) {
            cluster_grid_box(g, t, 0, k, lo, hi);
            x[2 * (k * g->tiles_x + t)] = lo[0], x[2 * (k * g->tiles_x + t) + 1] = hi[0];
            z[2 * k] = lo[2], z[2 * k + 1] = hi[2];
        }
        for (int t = 0; t < g->tiles_y; t++) {
            cluster_grid_box(g, 0, t, k, lo, hi);
            y[2 * (k * g->tiles_y + t)] = lo[1], y[2 * (k * g->tiles_y + t) + 1] = hi[1];
        }
    }
    a->box_grid = *g;
    upload(a->box_buffer, a->boxes, (size_t)n * sizeof(float));
    return true;
}

/* Per light, the slices it may reach and the tiles of each (cluster_grid_sphere_slices and _tiles,
 * as cluster_lists_assign takes them), as records (light, slice, tile columns, tile rows); then
 * sorted into one bucket per (slice, tile row) that they cover, each bucket in light order: counted,
 * then placed. Beside each bucket's first candidate, its first word of hit bits: one bit per
 * (cluster, candidate) pair it tests, each bucket's bits starting on a word of their own. Returns the
 * (cluster, light) pairs to test, an upper bound on the entries; -1 when out of memory. */
static long candidates_make(cluster_assign_gpu *a, const cluster_grid *g, const float (*spheres)[4],
                            int count)
{
    int buckets = g->slices * g->tiles_y, records = 0, *first, *words;
    if (!grow((void **)&a->spheres, &a->sphere_cap, count > 0 ? count : 1, sizeof *a->spheres) ||
        !grow((void **)&a->row_first, &a->row_cap, 2L * (buckets + 1), sizeof(int)))
        return -1;
    first = a->row_first, words = first + buckets + 1;
    memset(first, 0, 2 * (size_t)(buckets + 1) * sizeof(int));
    long pairs = 0, entries = 0;
    for (int i = 0; i < count; i++) {
        const float *s = spheres[i];
        bool infinite = s[3] >= CLUSTER_INFINITE_RADIUS;
        float r = CLUSTER_INFINITE_RADIUS;
        int span[2] = {0, g->slices - 1};
        if (!infinite && !cluster_grid_sphere_slices(g, s, &r, span))
            continue;
        a->spheres[i][0] = s[0], a->spheres[i][1] = s[1], a->spheres[i][2] = s[2], a->spheres[i][3] = r;
        if (!grow((void **)&a->records, &a->record_cap, records + span[1] - span[0] + 1L, sizeof *a->records))
            return -1;
        for (int k = span[0]; k <= span[1]; k++) {
            int tx[2] = {0, g->tiles_x - 1}, ty[2] = {0, g->tiles_y - 1};
            if (!infinite)
                cluster_grid_sphere_tiles(g, s, r, k, tx, ty);
            int *rec = a->records[records++];
            rec[0] = i, rec[1] = k, rec[2] = tx[0] | tx[1] << 16, rec[3] = ty[0] | ty[1] << 16;
            for (int y = ty[0]; y <= ty[1]; y++)
                first[k * g->tiles_y + y + 1]++, words[k * g->tiles_y + y + 1] += tx[1] - tx[0] + 1;
            entries += ty[1] - ty[0] + 1;
            pairs += (long)(tx[1] - tx[0] + 1) * (ty[1] - ty[0] + 1);
        }
    }
    for (int b = 0; b < buckets; b++) /* counts to starts; pairs to words, 32 bits each */
        first[b + 1] += first[b], words[b + 1] = words[b] + (words[b + 1] + 31) / 32;
    if (!grow((void **)&a->candidates, &a->candidate_cap, entries + 1, sizeof *a->candidates))
        return -1;
    for (int n = 0; n < records; n++) { /* place; first[b] ends as bucket b + 1's start */
        const int *rec = a->records[n];
        for (int y = rec[3] & 0xffff; y <= rec[3] >> 16; y++) {
            int *c = a->candidates[first[rec[1] * g->tiles_y + y]++];
            c[0] = rec[0], c[1] = rec[2];
        }
    }
    memmove(first + 1, first, (size_t)buckets * sizeof(int)); /* back to starts */
    first[0] = 0;
    return pairs;
}

static GLuint program(cluster_assign_gpu *a, cluster_assign_pass pass)
{
    static const char *const defines[CLUSTER_ASSIGN_PASSES] = {"PASS_COUNT 1", "PASS_SCAN 1", "PASS_FILL 1"};
    if (!a->programs[pass])
        a->programs[pass] = gl_compute_program_load("cluster_assign.comp", defines[pass]);
    return a->programs[pass];
}

bool cluster_assign_gpu_prepare(cluster_assign_gpu *a, const cluster_grid *g, const float (*spheres)[4],
                                int count, int cluster_limit, const cluster_assign_buffers *out)
{
    int clusters = cluster_grid_count(g);
    long pairs = candidates_make(a, g, spheres, count);
    if (pairs < 0 || !box_table(a, g) || !program(a, CLUSTER_ASSIGN_COUNT) || !program(a, CLUSTER_ASSIGN_SCAN) ||
        !program(a, CLUSTER_ASSIGN_FILL))
        return false;
    /* No list is longer than the limit: the entries are at most min(pairs, clusters x limit). */
    long most = (long)clusters * cluster_limit < pairs ? (long)clusters * cluster_limit : pairs;
    upload(a->sphere_buffer, a->spheres, (size_t)(count > 0 ? count : 1) * sizeof *a->spheres);
    upload(a->candidate_buffer, a->candidates,
           (size_t)(a->row_first[g->slices * g->tiles_y] + 1) * sizeof *a->candidates);
    int buckets = g->slices * g->tiles_y;
    upload(a->row_buffer, a->row_first, 2 * (size_t)(buckets + 1) * sizeof(int));
    upload(a->hit_buffer, NULL, (size_t)a->row_first[2 * buckets + 1] * sizeof(GLuint));
    gl_texture_buffer_upload(out->range_buffer, out->range_texture, GL_RG32I, NULL,
                             (size_t)clusters * 2 * sizeof(int));
    gl_texture_buffer_upload(out->list_buffer, out->list_texture, GL_R32I, NULL,
                             (size_t)(most + 1) * sizeof(int));
    upload(a->cursor_buffer, NULL, (size_t)(clusters + buckets) * sizeof(int));
    GLuint bound[] = {a->sphere_buffer,  a->candidate_buffer, a->row_buffer,    a->box_buffer,
                      out->range_buffer, out->list_buffer,    a->cursor_buffer, a->hit_buffer};
    for (GLuint i = 0; i < 8; i++)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, i, bound[i]);
    a->groups = (GLuint)((buckets + GROUP_SIZE - 1) / GROUP_SIZE);
    a->grid = *g, a->limit = cluster_limit;
    return gl_check("cluster_assign_gpu_prepare");
}

void cluster_assign_gpu_use(cluster_assign_gpu *a, cluster_assign_pass pass)
{
    GLuint p = a->programs[pass];
    glUseProgram(p);
    glUniform3i(glGetUniformLocation(p, "u_grid"), a->grid.tiles_x, a->grid.tiles_y, a->grid.slices);
    glUniform1i(glGetUniformLocation(p, "u_limit"), a->limit);
}

void cluster_assign_gpu_finish(void)
{
    for (GLuint i = 0; i < 8; i++)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, i, 0);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

bool cluster_assign_gpu_read(const cluster_assign_buffers *out, int clusters, cluster_lists *l)
{
    if (!grow((void **)&l->ranges, &l->range_cap, 2L * clusters, sizeof(int)))
        return false;
    gl_buffer_read(out->range_buffer, (size_t)clusters * 2 * sizeof(int), l->ranges);
    l->clusters = clusters, l->entries = 0;
    for (int c = 0; c < clusters; c++)
        if (l->ranges[2 * c + 1] > 0 && l->ranges[2 * c] + l->ranges[2 * c + 1] > l->entries)
            l->entries = l->ranges[2 * c] + l->ranges[2 * c + 1];
    if (!grow((void **)&l->indices, &l->index_cap, l->entries + 1L, sizeof(int)))
        return false;
    gl_buffer_read(out->list_buffer, (size_t)l->entries * sizeof(int), l->indices);
    return gl_check("cluster_assign_gpu_read");
}
