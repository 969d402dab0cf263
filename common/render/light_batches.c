/* light_batches.c - see light_batches.h. */
#include "light_batches.h"

#include "log.h"

#include <stdlib.h>
#include <string.h>

void light_batches_rect(const frame_view *view, const float position[3], float radius, int rect[4])
{
    const int size[2] = {view->width, view->height};
    rect[0] = rect[1] = 0, rect[2] = view->width - 1, rect[3] = view->height - 1;
    vec4 c, clip;
    glm_mat4_mulv((vec4 *)view->view, (vec4){position[0], position[1], position[2], 1.0f}, c);
    float lo[2] = {1e30f, 1e30f}, hi[2] = {-1e30f, -1e30f};
    for (int corner = 0; corner < 8; corner++) {
        float r = radius;
        vec4 p = {c[0] + (corner & 1 ? r : -r), c[1] + (corner & 2 ? r : -r), c[2] + (corner & 4 ? r : -r),
                  1.0f};
        glm_mat4_mulv((vec4 *)view->proj, p, clip);
        if (!(clip[3] > 1e-6f)) /* behind the eye, or NaN: the whole view */
            return;
        for (int k = 0; k < 2; k++)
            lo[k] = glm_min(lo[k], clip[k] / clip[3]), hi[k] = glm_max(hi[k], clip[k] / clip[3]);
    }
    /* NDC to the pixels whose centres can be inside, widened by one pixel. */
    for (int k = 0; k < 2; k++) {
        float last = (float)(size[k] - 1);
        rect[k] = (int)glm_clamp(floorf((lo[k] + 1.0f) * 0.5f * (float)size[k]) - 1.0f, 0.0f, last);
        rect[k + 2] = (int)glm_clamp(ceilf((hi[k] + 1.0f) * 0.5f * (float)size[k]) + 1.0f, 0.0f, last);
    }
}

static bool overlap(const int a[4], const int b[4])
{
    return a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3];
}

static long area(const int r[4])
{
    return (long)(r[2] - r[0] + 1) * (r[3] - r[1] + 1);
}

/* qsort has no context argument: the rectangles being sorted. */
static const int (*sorting)[4];

static int by_area(const void *x, const void *y)
{
    int i = *(const int *)x, j = *(const int *)y;
    long a = area(sorting[i]), b = area(sorting[j]);
    return a != b ? (a < b) - (a > b) : i - j; /* larger first; ties in list order */
}

static bool grow(void *array, size_t size, int n)
{
    void *p = realloc(*(void **)array, size * (size_t)n);
    if (p)
        *(void **)array = p;
    return p != NULL;
}

static bool reserve(light_batches *lb, int n)
{
    if (n <= lb->capacity)
        return true;
    if (!grow(&lb->rects, sizeof *lb->rects, n) || !grow(&lb->order, sizeof(int), n) ||
        !grow(&lb->next, sizeof(int), n) || !grow(&lb->head, sizeof(int), n) ||
        !grow(&lb->batches, sizeof(light_batch), n)) {
        log_error("out of memory for the batches of %d lights", n);
        return false;
    }
    lb->capacity = n;
    return true;
}

/* The first batch none of whose rectangles overlaps rect; lb->count when there is none. */
static int first_fit(const light_batches *lb, const int rect[4])
{
    for (int b = 0; b < lb->count; b++) {
        int j = lb->head[b];
        while (j >= 0 && !overlap(rect, lb->rects[j]))
            j = lb->next[j];
        if (j < 0)
            return b;
    }
    return lb->count;
}

bool light_batches_make(light_batches *lb, light_volumes *lv, const gpu_scene *gs, bool one_per_light)
{
    int n = lv->finite_count, *lights = lv->indices;
    lb->count = 0;
    if (!reserve(lb, n + 1))
        return false;
    for (int i = 0; i < n; i++) {
        const gpu_light *l = &gs->lights[lights[i]];
        light_batches_rect(&gs->view, l->position, l->radius * lv->mesh_scale, lb->rects[i]);
        lb->order[i] = i;
    }
    sorting = (const int(*)[4])lb->rects;
    qsort(lb->order, (size_t)n, sizeof(int), by_area);
    for (int k = 0; k < n; k++) {
        int i = lb->order[k], b = one_per_light ? lb->count : first_fit(lb, lb->rects[i]);
        if (b == lb->count)
            lb->head[lb->count++] = -1;
        lb->next[i] = lb->head[b], lb->head[b] = i;
    }
    /* The light list, batch by batch, into order[] (no longer needed), then over lv's. */
    for (int b = 0, at = 0; b < lb->count; b++) {
        lb->batches[b].first = at;
        for (int j = lb->head[b]; j >= 0; j = lb->next[j])
            lb->order[at++] = lights[j];
        lb->batches[b].count = at - lb->batches[b].first;
    }
    if (n > 0)
        memcpy(lights, lb->order, (size_t)n * sizeof(int));
    gl_texture_buffer_upload(lv->index_buffer, lv->index_texture, GL_R32I, lights,
                             (size_t)(gs->light_count > 0 ? gs->light_count : 1) * sizeof(int));
    return true;
}

void light_batches_destroy(light_batches *lb)
{
    free(lb->batches), free(lb->rects), free(lb->order), free(lb->next), free(lb->head);
    memset(lb, 0, sizeof *lb);
}
