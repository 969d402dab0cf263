#version 330 core
// volume_wire.vert - the volumes view (common/render/debug_views.c): instance i is light i's volume mesh,
// placed and scaled as light_volume.vert places it (the light's solved radius, or chapter 04's fixed
// one, times the mesh scale), drawn as lines. A light with an infinite radius has no sphere to show:
// its vertices go outside the clip volume, so nothing of it is drawn.
// CONE_VOLUME (chapter 09): the cone template, instance i the spot u_light_index[u_first_instance + i],
// placed by cone_volume.glsl as light_volume.vert places it.
#include "shading.glsl"
#include "cone_volume.glsl"

layout(location = 0) in vec3 a_position;

uniform mat4 u_view_proj;
uniform float u_mesh_scale;   // 1 / inradius (the mesh contains the sphere), or 1 (chapter 04's --scale none)
uniform float u_fixed_radius; // > 0: every volume has this radius (chapter 04); 0: each light's own

#ifdef CONE_VOLUME
uniform isamplerBuffer u_light_index;
uniform int u_first_instance;
#endif

flat out vec3 v_color;

void main()
{
#ifdef CONE_VOLUME
    int light = texelFetch(u_light_index, u_first_instance + gl_InstanceID).r;
#else
    int light = gl_InstanceID;
#endif
    light_data L = light_fetch(light);
    float radius = u_fixed_radius > 0.0 ? u_fixed_radius : L.radius;
    // The light's colour at full brightness, as the ring view draws it.
    v_color = L.radiance / max(max(L.radiance.r, L.radiance.g), max(L.radiance.b, 1e-6));
#ifdef CONE_VOLUME
    vec3 world = cone_volume_position(L.position, radius, light_fetch_cone(light), a_position);
#else
    vec3 world = L.position + a_position * (radius * u_mesh_scale);
#endif
    if (radius < 1e30)
        gl_Position = u_view_proj * vec4(world, 1.0);
    else
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
}
