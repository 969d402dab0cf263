/* camera.c - see camera.h. */
#include "camera.h"

#include <cglm/cglm.h>
#include <math.h>
#include <stdio.h>

#define POLE_MARGIN 0.035f /* radians (2 degrees) kept between a view direction and the up axis */
#define ZOOM_BASE 0.85f

/* Turns v about `up` by yaw, then towards `up` by pitch, keeping its length and never closer
 * to the up axis than POLE_MARGIN (past the pole the view would flip). */
static void turn(vec3 v, const vec3 up_in, float yaw, float pitch)
{
    vec3 up, axis;
    glm_vec3_normalize_to((float *)up_in, up);
    float len = glm_vec3_norm(v);
    if (len <= 0.0f)
        return;
    glm_vec3_rotate(v, yaw, up);
    float theta = acosf(glm_clamp(glm_vec3_dot(v, up) / len, -1.0f, 1.0f));
    float wanted = glm_clamp(theta - pitch, POLE_MARGIN, GLM_PIf - POLE_MARGIN);
    glm_vec3_cross(up, v, axis);
    if (glm_vec3_norm(axis) > 1e-6f * len) {
        glm_vec3_normalize(axis);
        glm_vec3_rotate(v, wanted - theta, axis); /* about up x v, a positive angle moves away from up */
    }
}

void camera_orbit(scene_camera *c, float yaw, float pitch)
{
    vec3 offset;
    glm_vec3_sub(c->eye, c->target, offset);
    turn(offset, c->up, yaw, pitch);
    glm_vec3_add(c->target, offset, c->eye);
}

void camera_look(scene_camera *c, float yaw, float pitch)
{
    vec3 dir;
    glm_vec3_sub(c->target, c->eye, dir);
    turn(dir, c->up, yaw, pitch);
    glm_vec3_add(c->eye, dir, c->target);
}

void camera_fly(scene_camera *c, float forward, float right)
{
    vec3 dir, side, move;
    glm_vec3_sub(c->target, c->eye, dir);
    glm_vec3_normalize(dir);
    glm_vec3_cross(dir, c->up, side);
    glm_vec3_normalize(side);
    glm_vec3_scale(dir, forward, move);
    glm_vec3_muladds(side, right, move);
    glm_vec3_add(c->eye, move, c->eye);
    glm_vec3_add(c->target, move, c->target);
}

void camera_zoom(scene_camera *c, float steps)
{
    vec3 offset;
    glm_vec3_sub(c->eye, c->target, offset);
    float len = glm_vec3_norm(offset);
    if (len <= 0.0f)
        return;
    float wanted = fmaxf(len * powf(ZOOM_BASE, steps), 2.0f * c->near_plane);
    glm_vec3_scale(offset, wanted / len, offset);
    glm_vec3_add(c->target, offset, c->eye);
}

void camera_frame(scene_camera *c, const float lo[3], const float hi[3], float aspect)
{
    vec3 centre, dir;
    for (int k = 0; k < 3; k++)
        centre[k] = 0.5f * (lo[k] + hi[k]);
    float radius = 0.5f * glm_vec3_distance((float *)lo, (float *)hi);
    glm_vec3_sub(c->eye, c->target, dir);
    if (glm_vec3_norm(dir) <= 0.0f)
        glm_vec3_copy((vec3){0.0f, 0.0f, 1.0f}, dir);
    glm_vec3_normalize(dir);
    /* The narrower of the two angles of view decides. */
    float half_v = glm_rad(c->fovy_deg) * 0.5f;
    float half_h = atanf(tanf(half_v) * (aspect > 0.0f ? aspect : 1.0f));
    float distance = radius / sinf(fminf(half_v, half_h));
    glm_vec3_copy(centre, c->target);
    glm_vec3_scale(dir, distance, dir);
    glm_vec3_add(centre, dir, c->eye);
    c->far_plane = fmaxf(c->far_plane, 1.1f * (distance + radius));
}

int camera_format(const scene_camera *c, char *out, size_t size)
{
    return snprintf(out, size,
                    "camera eye %.9g %.9g %.9g target %.9g %.9g %.9g up %.9g %.9g %.9g fovy %.9g near %.9g far %.9g",
                    (double)c->eye[0], (double)c->eye[1], (double)c->eye[2], (double)c->target[0],
                    (double)c->target[1], (double)c->target[2], (double)c->up[0], (double)c->up[1],
                    (double)c->up[2], (double)c->fovy_deg, (double)c->near_plane, (double)c->far_plane);
}
