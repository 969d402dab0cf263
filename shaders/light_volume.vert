#version 330 core
// light_volume.vert - one instance per light: the icosphere moved to the light and scaled so it
// contains the light's sphere of influence, or (u_fullscreen) a triangle covering the viewport for
// a light that reaches everything. The light's data goes to the fragments as flat values, fetched
// once per vertex instead of once per pixel.
// FIXED_RADIUS (chapter 04): instance i is light i and every volume has radius u_fixed_radius.
// Otherwise (chapter 05 on): instance i is light u_light_index[u_first_instance + i], its volume
// the light's own solved radius.
// CONE_VOLUME (chapter 09): the mesh is the cone template and each instance a spot, placed by
// cone_volume.glsl instead of scaled as a sphere.
#include "shading.glsl"
#include "fullscreen.glsl"
#include "cone_volume.glsl"

layout(location = 0) in vec3 a_position;

uniform mat4 u_view_proj;
uniform float u_mesh_scale; // 1 / inradius: the inscribed mesh grown to contain the unit sphere
#ifdef FIXED_RADIUS
uniform float u_fixed_radius;
#else
uniform isamplerBuffer u_light_index; // instance -> light, finite volumes first
uniform int u_first_instance;
uniform bool u_fullscreen;
#endif

flat out vec3 v_light_position;
flat out float v_light_radius;  // where shade_light() stops (the solved radius)
flat out vec3 v_light_radiance;
flat out vec3 v_light_attenuation;
flat out vec3 v_light_direction; // the spot's cone (shading.glsl's light_cone; NO_CONE for a point)
flat out vec2 v_light_cos;       // cos(outer), cos(inner)
flat out float v_volume_radius; // where the volume stops (the solved or the fixed radius)

void main()
{
#ifdef FIXED_RADIUS
    int light = gl_InstanceID;
    light_data L = light_fetch(light);
    v_volume_radius = u_fixed_radius;
    bool fullscreen = false;
#else
    int light = texelFetch(u_light_index, u_first_instance + gl_InstanceID).r;
    light_data L = light_fetch(light);
    v_volume_radius = L.radius;
    bool fullscreen = u_fullscreen;
#endif
    light_cone C = light_fetch_cone(light);
    v_light_direction = C.direction;
    v_light_cos = vec2(C.cos_outer, C.cos_inner);
    v_light_position = L.position;
    v_light_radius = L.radius;
    v_light_radiance = L.radiance;
    v_light_attenuation = L.attenuation;
    if (fullscreen) {
        gl_Position = fullscreen_position(gl_VertexID);
    } else {
#ifdef CONE_VOLUME
        gl_Position = u_view_proj * vec4(cone_volume_position(L.position, v_volume_radius, C, a_position), 1.0);
#else
        gl_Position = u_view_proj * vec4(L.position + a_position * (v_volume_radius * u_mesh_scale), 1.0);
#endif
    }
}
