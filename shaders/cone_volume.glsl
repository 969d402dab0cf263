// cone_volume.glsl - where chapter 09's cone mesh (common/render/light_volumes.h, light_volumes_cone_*) puts
// a vertex for a spot, so that the mesh CONTAINS the spot's cone cut by its sphere of influence
// (docs/09_spot_lights.md). Include after "shading.glsl". light_volumes_cone_point() in
// common/render/light_volumes.c is the same computation in C: tests/spot/test_cone_mesh.c checks it.
//
// The template's vertices are not positions: the apex is (0, 0, -1); a cap vertex is
// (cos a, sin a, t), azimuth a, t from 0 at the tip to 1 at the rim. A cap vertex goes to polar
// angle t * theta_s on a sphere of radius u_cone_cap_scale (units of the light's radius), with
// tan(theta_s) = u_cone_side_scale * tan(outer): the pyramid's faces then touch the cone instead of
// cutting it, and the cap's faces lie outside the unit sphere.

uniform float u_cone_side_scale; // 1 / cos(pi / segments); 1: the faces cut the cone (--scale none)
uniform float u_cone_cap_scale;  // the cap's 1 / inradius at the widest cone; 1: they cut the sphere

// The template vertex a for a cone of cos(outer) = cos_outer, apex at 0, axis +Z, radius 1.
vec3 cone_volume_local(vec3 a, float cos_outer)
{
    if (a.z < 0.0)
        return vec3(0.0);
    float sin_outer = sqrt(max(1.0 - cos_outer * cos_outer, 0.0));
    float polar = a.z * atan(u_cone_side_scale * sin_outer, cos_outer);
    return u_cone_cap_scale * vec3(sin(polar) * a.xy, cos(polar));
}

// A right-handed orthonormal frame whose third axis is the unit vector d (Duff et al., "Building an
// orthonormal basis, revisited", 2017): no division by zero for any d, so any direction works.
mat3 cone_volume_frame(vec3 d)
{
    float s = d.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + d.z);
    float b = d.x * d.y * a;
    return mat3(vec3(1.0 + s * d.x * d.x * a, s * b, -s * d.x), vec3(b, s + d.y * d.y * a, -d.y), d);
}

// World position of template vertex a for a spot at `position` reaching `radius` along C.direction.
vec3 cone_volume_position(vec3 position, float radius, light_cone C, vec3 a)
{
    return position + radius * (cone_volume_frame(C.direction) * cone_volume_local(a, C.cos_outer));
}
