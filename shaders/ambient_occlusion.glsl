// ambient_occlusion.glsl - chapter 17's occlusion (docs/17_ssao.md): the share of the ambient light
// that reaches this pixel's surface (SSAO, blurred), in the picture's own pixel grid. It scales the
// ambient term only: the lights' direct terms already know where they come from. Fragment shaders
// only; included through shading_features.glsl in programs built with AMBIENT_OCCLUSION.
uniform sampler2D u_ao;
uniform bool u_ao_on;

float ambient_occlusion()
{
    if (u_ao_on)
        return texelFetch(u_ao, ivec2(gl_FragCoord.xy), 0).r;
    return 1.0;
}
