#version 330 core
// volume_wire.vert - the volumes view (common/debug_views.c): instance i is light i's volume mesh,
// placed and scaled as light_volume.vert places it (the light's solved radius, or chapter 04's fixed
// one, times the mesh scale), drawn as lines. A light with an infinite radius has no sphere to show:
// its vertices go outside the clip volume, so nothing of it is drawn.
#include "shading.glsl"

layout(location = 0) in vec3 a_position;

uniform mat4 u_view_proj;
uniform float u_mesh_scale;   // 1 / inradius (the mesh contains the sphere), or 1 (chapter 04's --scale none)
uniform float u_fixed_radius; // > 0: every volume has this radius (chapter 04); 0: each light's own

flat out vec3 v_color;

void main()
{
    light_data L = light_fetch(gl_InstanceID);
    float radius = u_fixed_radius > 0.0 ? u_fixed_radius : L.radius;
    // The light's colour at full brightness, as the ring view draws it.
    v_color = L.radiance / max(max(L.radiance.r, L.radiance.g), max(L.radiance.b, 1e-6));
    if (radius < 1e30)
        gl_Position = u_view_proj * vec4(L.position + a_position * (radius * u_mesh_scale), 1.0);
    else
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
}
