/* light_work.h - the least lighting work a frame needs: how many (pixel, light) pairs a perfect
 * light volume would shade. The benchmark reports every renderer's work against it, and the
 * window's overlay the chapter's. No GL here: it works on a read-back depth buffer.
 *
 *   light_work_positions(depth, w, h, view_proj, out)   world position of every pixel's visible
 *                                          surface (x, y, z, 1) or (0, 0, 0, 0) for background,
 *                                          unprojected in double with the inverse of view_proj
 *   light_work_ideal_pairs(pos, w, h, view_proj, lights, count)
 *                                          (pixel, light) pairs whose surface point lies within the
 *                                          light's radius; each light only looks at the pixels of
 *                                          its sphere's rectangle on screen
 *
 * depth is window depth in [0,1] as fbo_read_depth (glReadPixels of GL_DEPTH_COMPONENT) returns it
 * (bottom row first); view_proj is 16 floats, column-major, as cglm and GL store it.
 */
#ifndef COMMON_LIGHT_WORK_H
#define COMMON_LIGHT_WORK_H

typedef struct gpu_light gpu_light; /* common/gl/gpu_scene.h */

void light_work_positions(const float *depth, int width, int height, const float *view_proj, double *out);
long long light_work_ideal_pairs(const double *pos, int width, int height, const float *view_proj,
                                 const gpu_light *lights, int count);

#endif
