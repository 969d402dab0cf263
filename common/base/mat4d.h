/* mat4d.h - 4x4 matrices in double, without GL (cglm has no double type): for the results that a
 * float inverse would spoil with its own rounding.
 *
 *   mat4d_from_float(m, out)  16 floats to 16 doubles, the same column-major order
 *   mat4d_invert(m, out)      the inverse by cofactors (the adjugate over the determinant); false
 *                             when m is singular (out then holds infinities or NaN)
 *
 * Matrices are 16 numbers, column-major, as cglm and GL store them.
 */
#ifndef COMMON_MAT4D_H
#define COMMON_MAT4D_H

#include <stdbool.h>

void mat4d_from_float(const float m[16], double out[16]);
bool mat4d_invert(const double m[16], double out[16]);

#endif
