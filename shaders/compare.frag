#version 330 core
// compare.frag - forward and the chapter's picture side by side, or their difference as a heat map.
// Both inputs are the display-encoded 8-bit pictures the window would show: texelFetch, no filtering.

#include "heat.glsl"

uniform sampler2D u_forward;
uniform sampler2D u_picture;
uniform bool u_difference;
uniform int u_divider;       // split: first column of the right-hand (chapter) side
uniform int u_divider_width; // white columns left of it
uniform int u_tolerance;     // levels

out vec4 o_color;

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 f = texelFetch(u_forward, pixel, 0).rgb;
    vec3 p = texelFetch(u_picture, pixel, 0).rgb;
    if (u_difference) {
        // In 8-bit levels; up to u_tolerance levels apart is the course's "same picture": black.
        vec3 levels = round(abs(f - p) * 255.0);
        float worst = max(max(levels.r, levels.g), levels.b);
        // Beyond it, the overdraw views' colour map: 1 level dark purple ... 16 and more pale yellow.
        o_color = vec4(worst > float(u_tolerance) ? heat(int(worst)) : vec3(0.0), 1.0);
        return;
    }
    if (pixel.x >= u_divider - u_divider_width && pixel.x < u_divider)
        o_color = vec4(1.0);
    else
        o_color = vec4(pixel.x < u_divider ? f : p, 1.0);
}
