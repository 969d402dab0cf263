/* ray_scene.h - the exact ray caster behind the tests' and the benchmark's references: a scene's
 * triangles in world space, in double precision, each object under a bounding-volume hierarchy, so a
 * reference can trace every pixel of a scene of 300,000 triangles (the teapots) in seconds. The hits
 * are those of testing every triangle: the hierarchy only skips triangles whose boxes the ray misses.
 *
 *   ray_scene_build(rs, s, time)       the scene's objects at `time`; false on a mesh error
 *   ray_scene_trace(rs, o, d, tmin, tmax, filter, tri)
 *                                      the nearest hit along o + t d with t in (tmin, tmax): its t
 *                                      (and *tri, 9 doubles, when tri is not NULL), or -1;
 *                                      RAY_ANY stops at the first hit (a shadow ray), RAY_CASTERS
 *                                      also skips `cast off` objects
 *   ray_scene_destroy(rs)
 */
#ifndef TOOLS_RAY_SCENE_H
#define TOOLS_RAY_SCENE_H

#include "scene.h"

#include <stdbool.h>

enum { RAY_NEAREST = 0, RAY_ANY = 1, RAY_CASTERS = 2 };

typedef struct ray_node {
    double lo[3], hi[3];
    int first, count; /* a leaf: triangles [first, first + count); an inner node: count 0, children first, first + 1 */
} ray_node;

typedef struct ray_object {
    double *v; /* 9 doubles per triangle: world space, in the hierarchy's order */
    int count;
    double lo[3], hi[3];
    bool casts;
    ray_node *nodes;
    int node_count;
} ray_object;

typedef struct ray_scene {
    ray_object *objects;
    int object_count;
} ray_scene;

bool ray_scene_build(ray_scene *rs, const scene *s, float time);
double ray_scene_trace(const ray_scene *rs, const double o[3], const double d[3], double tmin, double tmax, int filter,
                       const double **tri);
void ray_scene_destroy(ray_scene *rs);

#endif
