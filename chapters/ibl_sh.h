/* ibl_sh.h - chapter 19's arithmetic without GL: cube-map texel directions and solid angles, the
 * irradiance as 9 spherical-harmonics coefficients, the probes picked each frame and their weight
 * at a point, and the Blinn-Phong shininess as a GGX roughness (docs/19_image_based_light.md).
 *
 *   ibl_cube_direction(face, size, x, y, dir)  the unit direction through texel coordinates (x, y)
 *                                              of a cube face (GL's face order and orientation;
 *                                              a texel's centre is (i + 0.5, j + 0.5))
 *   ibl_cube_solid_angle(size, i, j)           the solid angle texel (i, j) of any face covers
 *   ibl_sh_project(faces, size, sh)            radiance (6 faces of size x size RGB floats, row j =
 *                                              t, GL's glGetTexImage order) onto bands 0-2, double
 *   ibl_sh_irradiance(sh, n, out)              E(n) / pi: what a white Lambertian surface of normal n
 *                                              reflects, from those coefficients (the same formula as
 *                                              shaders/ibl.glsl)
 *   ibl_probe_importance(probe, eye)           how much a probe matters to this frame: its radius
 *                                              over its distance to the eye, 1 inside it
 *   ibl_probes_pick_indices(probes, count, eye, out) the indices of the IBL_MAX_PICKED most important
 *                                              (ties: the scene's order); returns how many
 *   ibl_probe_weight(probe, p)                 (1 - (d / R)^2)^2 inside the radius, 0 outside
 *   ibl_shininess_roughness(s)                 (2 / (s + 2))^(1/4): Blinn-Phong's exponent as the
 *                                              GGX roughness whose lobe is as wide
 */
#ifndef CHAPTERS_IBL_SH_H
#define CHAPTERS_IBL_SH_H

#include "scene.h"

void ibl_cube_direction(int face, int size, double x, double y, double dir[3]);
double ibl_cube_solid_angle(int size, int i, int j);
void ibl_sh_project(const float *const faces[6], int size, double sh[SHADER_IBL_SH_COEFFS][3]);
void ibl_sh_irradiance(const double sh[SHADER_IBL_SH_COEFFS][3], const double n[3], double out[3]);
double ibl_probe_importance(const scene_probe *probe, const float eye[3]);
int ibl_probes_pick_indices(const scene_probe *probes, int count, const float eye[3], int out[SHADER_IBL_MAX_PICKED]);
double ibl_probe_weight(const scene_probe *probe, const double p[3]);
double ibl_shininess_roughness(double shininess);

#endif
