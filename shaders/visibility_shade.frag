#version 330 core
// visibility_shade.frag - chapter 16's shading pass: one full-screen triangle. Each pixel reads its
// id, fetches the triangle's three vertices (vis_meshes: positions and normals, object space), puts
// them in the world with the object's matrices, intersects the pixel's ray from the eye with the
// triangle (Moller-Trumbore: the barycentrics of the hit, perspective-correct by construction),
// interpolates position, normal, texture coordinate and tangent as the rasterizer would have (the
// coordinate's screen derivatives from the rays through the next pixels: a material's images are read
// at the mip level forward reads them), and shades with chapter 11's cluster lists. u_show_ids: a colour per id instead (hashed). The background (id 0) is discarded:
// the chapter clears the picture to it first, so the pass's GL_SAMPLES_PASSED counts the pixels
// that fetch a triangle.
// VIS_SAMPLES N (--samples N): the ids hold N samples a pixel. Drawn twice: u_pass VIS_PASS_PIXELS
// shades the pixels whose samples all hold one id, once, as above; VIS_PASS_EDGES the others, each
// sample's triangle where the pixel centre's ray meets its plane (where forward MSAA runs a
// primitive's fragment: its attributes extrapolated to the centre), the samples' radiance averaged
// before the display encoding (chapter 13's resolve). Each pass discards the other's pixels.
// SHADOWS (--shadows N): the cluster loop reads chapter 14's atlas (shade_light_index).
// variants: - | VIS_SAMPLES 4 | SHADOWS 1 | VIS_SAMPLES 4, SHADOWS 1
#include "shading.glsl"
#include "heat.glsl"
#include "clusters.glsl"
#define MATERIAL_MAPS_GRAD 1 // the maps read with textureGrad: the derivatives come from the triangle
#include "material_maps.glsl"

#ifdef VIS_SAMPLES
#define VIS_PASS_PIXELS 0
#define VIS_PASS_EDGES 1
uniform usampler2DMS u_ids;          // R32UI, VIS_SAMPLES samples: (object + 1) << bits | triangle
uniform int u_pass;
#else
uniform usampler2D u_ids;            // R32UI: (object + 1) << SHADER_VIS_TRIANGLE_BITS | triangle
#endif
uniform samplerBuffer u_objects;     // forward.vert's object texels (common/base/shader_layout.h)
uniform samplerBuffer u_vertices;    // R32F: position xyz, normal xyz per vertex, every mesh
uniform usamplerBuffer u_indices;    // R32UI: every mesh's indices, each relative to its mesh
uniform isamplerBuffer u_object_meshes; // per object: its mesh's first index, first vertex
uniform mat4 u_inv_view_proj;
uniform vec2 u_viewport_size;
uniform vec3 u_eye;
uniform bool u_show_ids;
uniform int u_view_mode;      // set by clusters_use: SHADER_VIEW_LIT, or the linear picture's
uniform bool u_output_linear; // linear radiance for a float target (the benchmark)

out vec4 o_color;

struct vertex {
    vec3 position, normal; // object space
};

// Where corner `corner` of the object's triangle lies in u_vertices (SHADER_MESH_VERTEX_FLOATS each).
int vertex_first_float(int object, int triangle, int corner)
{
    ivec2 mesh = texelFetch(u_object_meshes, object).xy;
    return SHADER_MESH_VERTEX_FLOATS * (mesh.y + int(texelFetch(u_indices, mesh.x + 3 * triangle + corner).r));
}

vertex vertex_fetch(int f)
{
    vertex v;
    v.position = vec3(texelFetch(u_vertices, f).r, texelFetch(u_vertices, f + 1).r, texelFetch(u_vertices, f + 2).r);
    v.normal = vec3(texelFetch(u_vertices, f + 3).r, texelFetch(u_vertices, f + 4).r, texelFetch(u_vertices, f + 5).r);
    return v;
}

// The texture coordinate and the tangent (object space, w the handedness): common/scene/mesh_data.h.
vec2 vertex_uv(int f) { return vec2(texelFetch(u_vertices, f + 6).r, texelFetch(u_vertices, f + 7).r); }

vec4 vertex_tangent(int f)
{
    return vec4(texelFetch(u_vertices, f + 8).r, texelFetch(u_vertices, f + 9).r, texelFetch(u_vertices, f + 10).r,
                texelFetch(u_vertices, f + 11).r);
}

// The hit of the ray o + t d with triangle (a, b, c): its barycentrics (1 - u - v, u, v). A triangle
// seen edge-on (det near 0) has no stable answer; its few pixels take the clamped values. inside:
// clamped to the triangle; else the plane's point, as the rasterizer extrapolates (MSAA edges).
vec3 ray_barycentrics(vec3 o, vec3 d, vec3 a, vec3 b, vec3 c, bool inside)
{
    vec3 e1 = b - a, e2 = c - a;
    vec3 p = cross(d, e2);
    float det = dot(e1, p);
    if (abs(det) < 1e-12)
        return vec3(1.0 / 3.0);
    vec3 s = o - a;
    float u = dot(s, p) / det;
    float v = dot(d, cross(s, e1)) / det;
    if (!inside)
        return vec3(1.0 - u - v, u, v);
    vec2 uv = clamp(vec2(u, v), 0.0, 1.0);
    uv /= max(1.0, uv.x + uv.y);
    return vec3(1.0 - uv.x - uv.y, uv);
}

// A colour per id (a 32-bit integer hash, lowbias32).
vec3 id_colour(uint id)
{
    id ^= id >> 16; id *= 0x7feb352du; id ^= id >> 15; id *= 0x846ca68bu; id ^= id >> 16;
    return vec3(uvec3(id, id >> 8, id >> 16) & 255u) / 255.0;
}

// The ray from the eye through window point `frag` (its far-plane point, unprojected).
vec3 pixel_ray(vec2 frag)
{
    vec4 far_point = u_inv_view_proj * vec4((frag / u_viewport_size) * 2.0 - 1.0, 1.0, 1.0);
    return far_point.xyz / far_point.w - u_eye;
}

// Triangle `id` at the pixel centre: its linear radiance (lit view), its cluster and view depth.
vec3 shade_id(uint id, bool inside, out ivec2 range, out float depth)
{
    int object = int(id >> SHADER_VIS_TRIANGLE_BITS) - 1;
    int triangle = int(id & ((1u << SHADER_VIS_TRIANGLE_BITS) - 1u));
    int t = SHADER_OBJECT_TEXELS * object;
    mat4 model = mat4(texelFetch(u_objects, t), texelFetch(u_objects, t + 1), texelFetch(u_objects, t + 2),
                      texelFetch(u_objects, t + 3));
    int n = t + SHADER_OBJECT_TEXEL_NORMAL;
    mat3 normal_matrix = mat3(texelFetch(u_objects, n).xyz, texelFetch(u_objects, n + 1).xyz,
                              texelFetch(u_objects, n + 2).xyz);
    vec4 material = texelFetch(u_objects, t + SHADER_OBJECT_TEXEL_MATERIAL);
    float shininess = texelFetch(u_objects, t + SHADER_OBJECT_TEXEL_SHININESS).r;

    ivec3 f = ivec3(vertex_first_float(object, triangle, 0), vertex_first_float(object, triangle, 1),
                    vertex_first_float(object, triangle, 2));
    vertex v0 = vertex_fetch(f.x), v1 = vertex_fetch(f.y), v2 = vertex_fetch(f.z);
    vec3 a = (model * vec4(v0.position, 1.0)).xyz, b = (model * vec4(v1.position, 1.0)).xyz,
         c = (model * vec4(v2.position, 1.0)).xyz;
    vec3 w = ray_barycentrics(u_eye, pixel_ray(gl_FragCoord.xy), a, b, c, inside);
    vec3 p = w.x * a + w.y * b + w.z * c;
    vec3 normal = safe_normalize(normal_matrix * (w.x * v0.normal + w.y * v1.normal + w.z * v2.normal),
                                 vec3(0.0, 1.0, 0.0));
    // A material's images (chapter 18), only where it has some: the texture coordinate, and its screen
    // derivatives as the rasterizer takes them: across the 2 x 2 quad the pixel lies in, from its first
    // pixel to the next right and up, each where that pixel's ray meets this triangle's plane
    // (unclamped: a neighbour on another triangle is extrapolated, as the rasterizer's helper pixels are).
    // The emissive (rgb, its map's layer) is added once, beside the ambient, as forward.frag adds it.
    vec4 maps = texelFetch(u_objects, t + SHADER_OBJECT_TEXEL_MAPS);
    vec4 emissive_texel = texelFetch(u_objects, t + SHADER_OBJECT_TEXEL_EMISSIVE);
    vec3 emissive = emissive_texel.rgb;
    float occlusion = 1.0;
    if (material_is_pbr(shininess) && (any(greaterThanEqual(maps, vec4(0.0))) || emissive_texel.w >= 0.0)) {
        mat3x2 uvs = mat3x2(vertex_uv(f.x), vertex_uv(f.y), vertex_uv(f.z));
        vec2 quad = floor(gl_FragCoord.xy * 0.5) * 2.0 + 0.5;
        vec3 wc = ray_barycentrics(u_eye, pixel_ray(quad), a, b, c, false);
        vec3 wx = ray_barycentrics(u_eye, pixel_ray(quad + vec2(1.0, 0.0)), a, b, c, false);
        vec3 wy = ray_barycentrics(u_eye, pixel_ray(quad + vec2(0.0, 1.0)), a, b, c, false);
        g_map_dx = uvs * (wx - wc);
        g_map_dy = uvs * (wy - wc);
        vec4 t0 = vertex_tangent(f.x), t1 = vertex_tangent(f.y), t2 = vertex_tangent(f.z);
        vec4 tangent = vec4(mat3(model) * (w.x * t0.xyz + w.y * t1.xyz + w.z * t2.xyz), t0.w);
        material_apply_maps_at(uvs * w, tangent, maps, material.rgb, material.a, shininess, normal, occlusion);
        emissive = material_emissive_at(uvs * w, emissive_texel);
    }

    depth = cluster_view_depth(p);
    range = cluster_range(cluster_index(gl_FragCoord.xy, depth));
    if (u_view_mode != SHADER_VIEW_LIT)
        return vec3(0.0);
    vec3 view = safe_normalize(u_eye - p, normal);
    return cluster_shade(range, p, normal, view, material.rgb, material.a, shininess, occlusion) + emissive;
}

#ifdef VIS_SAMPLES
void main()
{
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    uint ids[VIS_SAMPLES];
    bool one = true, any = false;
    for (int s = 0; s < VIS_SAMPLES; s++) {
        ids[s] = texelFetch(u_ids, pixel, s).r;
        one = one && ids[s] == ids[0];
        any = any || ids[s] != 0u;
    }
    if (!any || one != (u_pass == VIS_PASS_PIXELS))
        discard; // the background, or the other pass's pixel
    ivec2 range = ivec2(0);
    float depth = 0.0;
    vec3 sum = vec3(0.0), last = vec3(0.0);
    for (int s = 0; s < VIS_SAMPLES; s++) {
        if (ids[s] == 0u)
            continue; // forward's clear colour, black
        if (s == 0 || ids[s] != ids[s - 1])
            last = u_show_ids ? id_colour(ids[s]) : shade_id(ids[s], one, range, depth);
        sum += last;
    }
    o_color = u_show_ids ? vec4(sum / float(VIS_SAMPLES), 1.0) // the ids view: their colours averaged
                         : cluster_output(u_view_mode, u_output_linear, range, depth, sum / float(VIS_SAMPLES));
}
#else
void main()
{
    uint id = texelFetch(u_ids, ivec2(gl_FragCoord.xy), 0).r;
    if (id == 0u)
        discard; // the background: the picture is cleared to forward's clear colour
    if (u_show_ids) {
        o_color = vec4(id_colour(id), 1.0);
        return;
    }
    ivec2 range;
    float depth;
    vec3 col = shade_id(id, true, range, depth);
    o_color = cluster_output(u_view_mode, u_output_linear, range, depth, col);
}
#endif
