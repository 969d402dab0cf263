#version 330 core
// fullscreen.vert - one triangle that covers the viewport, from gl_VertexID alone (no buffers).

out vec2 v_uv;

void main()
{
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2); // (0,0) (2,0) (0,2)
    v_uv = p;
    gl_Position = vec4(2.0 * p - 1.0, 0.0, 1.0);
}
