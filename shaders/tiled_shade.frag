#version 330 core
// tiled_shade.frag - chapter 10's shading pass, the same for both of its paths: one full-screen
// triangle; each pixel reads its surface from the G-buffer once, looks up its tile's light list and
// adds up shade_light() over it, in registers, with ambient first as chapter 03 and forward do; the
// sum is display-encoded and written once: no blending, no accumulation buffer.
// The lists (tiled_cull.comp on the compute path, the CPU on the 3.3 path): per tile (first, count,
// covered pixels, -) in u_tile_ranges, count -1 when the tile had more lights than its list holds
// (then every light); the light indices from `first` on in u_tile_lights, in light order.
// Views (u_view_mode): SHADER_VIEW_LIT; SHADER_VIEW_OVERDRAW, the light-loop iterations of each pixel
// as the heat map (0 on the background, which loops over nothing); VIEW_TILES, each tile's list
// length as the heat map with the tile grid in grey.
#include "tiled.glsl"
#include "shading.glsl"
#include "gbuffer_read.glsl"
#include "heat.glsl"

uniform isamplerBuffer u_tile_ranges; // RGBA32I, one texel per tile, row by row from the bottom left
uniform isamplerBuffer u_tile_lights; // R32I light indices
uniform int u_tiles_x;                // tiles per row
uniform int u_view_mode;

out vec4 o_color;

void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    ivec2 tile = pixel / TILE_SIZE;
    ivec2 range = texelFetch(u_tile_ranges, tile.y * u_tiles_x + tile.x).xy;
    bool every_light = range.y < 0;
    int count = every_light ? u_light_count : range.y;
    if (u_view_mode == VIEW_TILES) {
        bool grid = any(equal(pixel % TILE_SIZE, ivec2(0)));
        o_color = vec4(grid ? vec3(0.35) : heat(count), 1.0);
        return;
    }
    surface s = gbuffer_read(pixel);
    // Nothing drawn here: black, as forward's clear, and no light loop.
    if (s.background) {
        o_color = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    if (u_view_mode == SHADER_VIEW_OVERDRAW) {
        o_color = vec4(heat(count), 1.0);
        return;
    }
    vec3 n = s.normal;
    vec3 v = safe_normalize(u_eye - s.position, n);
    vec3 c = shade_ambient(s.albedo * s.occlusion);
    c += s.emissive; // once per pixel, beside the ambient (0 but for an emissive material)
    for (int k = 0; k < count; k++) {
        int i = every_light ? k : texelFetch(u_tile_lights, range.x + k).r;
        c += shade_light(light_fetch(i), light_fetch_cone(i), s.position, n, v, s.albedo, s.specular, s.shininess);
    }
    o_color = vec4(display_encode(c), 1.0);
}
