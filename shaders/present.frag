#version 330 core
// present.frag - copies a colour texture to the screen, texel for pixel.

uniform sampler2D u_image;

out vec4 o_color;

void main()
{
    o_color = texelFetch(u_image, ivec2(gl_FragCoord.xy), 0);
}
