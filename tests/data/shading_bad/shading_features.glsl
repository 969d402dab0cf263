// A registry as it must not be: chapter 17's file brought in without its define, so every program
// compiles it.
#include "ambient_occlusion.glsl"
#ifdef SHADOWS
#include "shadows.glsl"
#endif
