#version 330 core
// fullscreen.vert - one triangle that covers the viewport, from gl_VertexID alone (no buffers).
#include "fullscreen.glsl"

out vec2 v_uv;

void main()
{
    v_uv = fullscreen_uv(gl_VertexID);
    gl_Position = fullscreen_position(gl_VertexID);
}
