// fullscreen.glsl - the one triangle that covers the viewport, from the vertex index alone (no
// buffers): vertices 0, 1, 2 at (0,0), (2,0), (0,2) in [0,1] viewport units, so the visible square
// is its corner. Included by fullscreen.vert and light_volume.vert (full-screen lights).
#ifndef FULLSCREEN_GLSL
#define FULLSCREEN_GLSL

// The vertex in [0,1] viewport units (the triangle reaches 2).
vec2 fullscreen_uv(int vertex_id)
{
    return vec2((vertex_id << 1) & 2, vertex_id & 2);
}

vec4 fullscreen_position(int vertex_id)
{
    return vec4(2.0 * fullscreen_uv(vertex_id) - 1.0, 0.0, 1.0);
}

#endif
