// A shading.glsl as it must not be (tests/lessons/shading_features.py refuses it): chapter 14's
// lookup called from chapter 00's file.
vec3 shade_light_index(int i, vec3 p, vec3 n)
{
    return shade_light(i, p, n) * shadow_visibility(i, p, n);
}
