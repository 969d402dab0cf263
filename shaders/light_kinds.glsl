// light_kinds.glsl - the light kinds a program is built for (scene_features.glsl): a spot's cone
// where the scene has spots (chapter 09, light_spot.glsl); otherwise every light is a point light,
// and a light's cone is NO_CONE, read from nowhere, its factor 1. Included by shading.glsl.
#ifdef LIGHT_SPOT
#include "light_spot.glsl"
#else
struct light_cone {
    vec3 direction;
    float cos_outer;
    float cos_inner;
};

const light_cone NO_CONE = light_cone(vec3(0.0), -1.0, -1.0);

light_cone light_fetch_cone(int i)
{
    return NO_CONE;
}

float light_cone_factor(light_cone C, vec3 l)
{
    return 1.0;
}
#endif
