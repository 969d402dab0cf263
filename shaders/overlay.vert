#version 330 core
// overlay.vert - stb_easy_font's quads: font units from the top-left corner, times u_scale pixels.
layout(location = 0) in vec2 a_position;
layout(location = 1) in vec4 a_color;

uniform vec2 u_viewport; // pixels
uniform float u_scale;

out vec4 v_color;

void main()
{
    vec2 pixel = a_position * u_scale;
    gl_Position = vec4(pixel.x / u_viewport.x * 2.0 - 1.0, 1.0 - pixel.y / u_viewport.y * 2.0, 0.0, 1.0);
    v_color = a_color;
}
