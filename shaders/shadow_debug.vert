#version 330 core
// shadow_debug.vert - chapter 14's two debug views (chapters/shadow_views.c): one quad per item, from
// gl_VertexID and gl_InstanceID alone (no vertex buffers). Each item is two texels of u_items:
//   --view atlas       a tile: (x, y, size in atlas texels, tier), (far plane, 1, 0, 0); the
//                      quad is the tile's square inside the atlas's square u_rect (NDC x, y of its
//                      corner, its width and height), whose side is u_atlas_size texels
//   --view importance  a light: (NDC x, y, 0, tier), (0, 1 if shadowed, 0, 0); the quad is a
//                      square of half-side u_radius (NDC) round the light's projection

uniform samplerBuffer u_items;
uniform int u_mode; // 0: atlas tiles, 1: light circles
uniform vec4 u_rect;
uniform float u_atlas_size;
uniform vec2 u_radius;

out vec2 v_local; // 0..1 across the quad
flat out vec4 v_item;
flat out vec4 v_more;

void main()
{
    const vec2 corners[6] = vec2[6](vec2(0.0, 0.0), vec2(1.0, 0.0), vec2(1.0, 1.0), vec2(0.0, 0.0), vec2(1.0, 1.0),
                                    vec2(0.0, 1.0));
    vec2 corner = corners[gl_VertexID];
    v_item = texelFetch(u_items, 2 * gl_InstanceID);
    v_more = texelFetch(u_items, 2 * gl_InstanceID + 1);
    v_local = corner;
    vec2 p = u_mode == 0 ? u_rect.xy + (v_item.xy + corner * v_item.z) / u_atlas_size * u_rect.zw
                         : v_item.xy + (corner * 2.0 - 1.0) * u_radius;
    gl_Position = vec4(p, 0.0, 1.0);
}
