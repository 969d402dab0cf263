#version 330 core
// shadow_debug.frag - chapter 14's two debug views (shadow_debug.vert says what each item is), in one
// colour scale: a light's tier, the size its tiles got this frame (docs/14_shadows.md): red tier 0
// (1024 texels), yellow tier 1 (512), cyan tier 2 (256), blue tier 3 (128); grey: a light without a
// shadow. The tier, not the importance it started from: the plan moves the least important lights
// down a tier until the atlas holds them all, and the views show what it decided.
//   --view atlas       each tile's depth, near the light bright, far dark, cleared (nothing) black,
//                      times its light's colour
//   --view importance  a disc with a dark rim at each light

uniform sampler2D u_atlas_depth; // read with texelFetch, its comparison switched off while drawn
uniform int u_mode;

in vec2 v_local;
flat in vec4 v_item;
flat in vec4 v_more;
out vec4 o_color;

const float near_plane = 0.05; // SHADOW_NEAR (common/shadows/shadow_plan.h)

vec3 tier_color(float tier)
{
    const vec3 colors[4] = vec3[4](vec3(1.0, 0.15, 0.1), vec3(1.0, 0.9, 0.1), vec3(0.0, 0.85, 0.9),
                                   vec3(0.15, 0.25, 1.0));
    return colors[clamp(int(tier + 0.5), 0, 3)];
}

void main()
{
    vec3 tint = v_more.y > 0.5 ? tier_color(v_item.w) : vec3(0.55);
    if (u_mode == 0) {
        ivec2 texel = ivec2(v_item.xy + min(v_local * v_item.z, vec2(v_item.z - 1.0)));
        float d = texelFetch(u_atlas_depth, texel, 0).r;
        float far_plane = v_more.x;
        float z = near_plane * far_plane / (far_plane - d * (far_plane - near_plane)); // the depth's distance
        o_color = vec4(tint * (0.2 + 0.8 * clamp(1.0 - z / far_plane, 0.0, 1.0)), 1.0);
        return;
    }
    float r = length(v_local * 2.0 - 1.0);
    if (r > 1.0)
        discard;
    o_color = vec4(r > 0.7 ? tint * 0.25 : tint, 1.0);
}
