/* tile_cull.c - see tile_cull.h. */
#include "tile_cull.h"

#include <math.h>

void tile_sphere(const gpu_light *l, const frame_view *view, vec4 out)
{
    /* A spot (cone half-angle a, radius r): the sphere of radius r / (2 cos a) on the axis at that
     * distance from the apex up to 45 degrees (through the apex and the rim), r sin a at r cos a beyond
     * (through the rim). A point light, or a cone of 90 degrees and more: the light's own sphere. */
    float r = l->radius, c = l->cos_outer;
    bool point = c <= 0.0f || r > 1e30f, narrow = c >= 0.70710678f;
    float along = point ? 0.0f : narrow ? r / (2.0f * c) : r * c;
    vec4 world = {l->position[0], l->position[1], l->position[2], 1.0f};
    glm_vec3_muladds((float *)l->direction, along, world);
    glm_mat4_mulv((vec4 *)view->view, world, out);
    out[3] = point ? r : narrow ? along : r * sqrtf(1.0f - c * c);
    out[3] += 1e-4f * (out[3] + glm_vec3_norm(out)); /* float rounding never cuts a light */
}

/* Side plane k is +-(row axis - bound * row 3) of the projection (x_clip >= x0 w_clip, ...); the box
 * holds the corner rays (scaled to z = -1) at both depths. */
void tile_frustum_make(const frame_view *v, int x, int y, int size, const float depth[2], tile_frustum *f)
{
    /* the tile's pixel rectangle, cut at the view's edge, in NDC */
    float rect[4] = {(float)x, (float)y, glm_min(x + size, v->width), glm_min(y + size, v->height)};
    for (int k = 0; k < 4; k++)
        rect[k] = rect[k] / (float)(k % 2 ? v->height : v->width) * 2.0f - 1.0f;
    glm_vec3_broadcast(3.0e38f, f->lo);
    glm_vec3_broadcast(-3.0e38f, f->hi);
    for (int k = 0; k < 4; k++) { /* x >= x0, x <= x1, y >= y0, y <= y1 */
        float sign = k % 2 ? -1.0f : 1.0f, bound = rect[k / 2 + 2 * (k % 2)];
        for (int j = 0; j < 4; j++)
            f->side[k][j] = sign * (v->proj[j][k / 2] - bound * v->proj[j][3]);
        glm_vec4_scale(f->side[k], 1.0f / glm_vec3_norm(f->side[k]), f->side[k]);
        vec4 p;
        glm_mat4_mulv((vec4 *)v->inv_proj, (vec4){rect[k % 2 ? 2 : 0], rect[k < 2 ? 1 : 3], 0.0f, 1.0f}, p);
        for (int j = 0; j < 3; j++) {
            float ray = p[j] / -p[2];
            f->lo[j] = glm_min(f->lo[j], glm_min(ray * depth[0], ray * depth[1]));
            f->hi[j] = glm_max(f->hi[j], glm_max(ray * depth[0], ray * depth[1]));
        }
    }
    f->depth[0] = depth[0], f->depth[1] = depth[1];
}

bool tile_sphere_visible(const tile_frustum *f, const vec4 s)
{
    if (-s[2] + s[3] < f->depth[0] || -s[2] - s[3] > f->depth[1])
        return false;
    for (int k = 0; k < 4; k++)
        if (glm_vec3_dot((float *)f->side[k], (float *)s) + f->side[k][3] < -s[3])
            return false;
    float outside2 = 0.0f; /* squared distance from the centre to the box */
    for (int j = 0; j < 3; j++) {
        float d = glm_max(glm_max(f->lo[j] - s[j], s[j] - f->hi[j]), 0.0f);
        outside2 += d * d;
    }
    return outside2 <= s[3] * s[3];
}

void tile_bind_view(GLuint p, const frame_view *v)
{
    glUniformMatrix4fv(glGetUniformLocation(p, "u_view_matrix"), 1, GL_FALSE, (const float *)v->view);
    glUniformMatrix4fv(glGetUniformLocation(p, "u_proj"), 1, GL_FALSE, (const float *)v->proj);
    glUniformMatrix4fv(glGetUniformLocation(p, "u_inv_proj"), 1, GL_FALSE, (const float *)v->inv_proj);
}
