// light_kinds.glsl - the light kinds a program is built for (scene_features.glsl). Every light has a
// cone: a spot's (chapter 09, light_spot.glsl, in programs built for a scene with spots: LIGHT_SPOT),
// or a point light's NO_CONE (direction 0, both cosines -1), which lights every direction. Built for a
// scene of point lights only, a light's cone is NO_CONE, read from nowhere, and its factor 1.
// Included by shading.glsl.

// A light's cone: its unit axis and the cosines of its half-angles.
struct light_cone {
    vec3 direction;
    float cos_outer;
    float cos_inner;
};

const light_cone NO_CONE = light_cone(vec3(0.0), -1.0, -1.0);

#ifdef LIGHT_SPOT
#include "light_spot.glsl"
#else
light_cone light_fetch_cone(int i)
{
    return NO_CONE;
}

float light_cone_factor(light_cone C, vec3 l)
{
    return 1.0;
}
#endif
