/* camera.h - the scene's camera moved by hand (the window's mouse and keys), and its pose as text.
 * Every function changes a scene_camera in place; angles in radians, distances in world units.
 *
 *   camera_orbit(c, yaw, pitch)       the eye turns around the target: yaw about the up axis, pitch
 *                                     towards it, raising the eye (never over the pole); the
 *                                     distance is kept
 *   camera_look(c, yaw, pitch)        the target turns around the eye (fly mode's mouse look);
 *                                     positive yaw turns left, positive pitch looks up
 *   camera_fly(c, forward, right)     eye and target move together along the view direction and
 *                                     its right-hand side
 *   camera_zoom(c, steps)             the eye's distance to the target times 0.85^steps, never
 *                                     closer than twice the near plane
 *   camera_frame(c, lo, hi, aspect)   the target to the box's centre and the eye back along the
 *                                     view direction until the box's bounding sphere fits the view;
 *                                     the far plane grows to keep the box inside it
 *   camera_format(c, out, size)       "camera eye X Y Z target X Y Z up X Y Z fovy F near N far F",
 *                                     a scene-file line (and --camera's argument without "camera");
 *                                     %.9g, so a float survives the text exactly
 */
#ifndef COMMON_CAMERA_H
#define COMMON_CAMERA_H

#include "scene.h"

#include <stddef.h>

void camera_orbit(scene_camera *c, float yaw, float pitch);
void camera_look(scene_camera *c, float yaw, float pitch);
void camera_fly(scene_camera *c, float forward, float right);
void camera_zoom(scene_camera *c, float steps);
void camera_frame(scene_camera *c, const float lo[3], const float hi[3], float aspect);
int camera_format(const scene_camera *c, char *out, size_t size);

#endif
