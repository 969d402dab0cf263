/* hard_util.h - what the hard-case test programs share.
 *
 *   hard_context_create(width, height)    headless EGL context with KHR_debug on; exits 77 (skip)
 *                                         when no context can be made
 *   hard_program_create(vert, frag)       a program from source text; a line `#include "shading.glsl"`
 *                                         pulls in the course's one shading model from the shader dir
 *   hard_expect(ok, fmt, ...)             print "ok"/"FAIL" and the message; failures are counted
 *   hard_failures()                       how many hard_expect calls failed
 *   hard_finish()                         GL errors count as failures; returns the exit code
 *   hard_encode(linear)                   display_encode() of shaders/shading.glsl, in double, 0..255
 *
 * Each program prints a table of what it measured, so the numbers in docs/hard-cases.md can be
 * re-checked by running it.
 */
#ifndef HARD_UTIL_H
#define HARD_UTIL_H

#include "log.h"

#include <glad/gl.h>
#include <stdbool.h>

void hard_context_create(int width, int height);
GLuint hard_program_create(const char *vert, const char *frag);
bool hard_expect(bool ok, const char *fmt, ...) LOG_PRINTF(2, 3);
int hard_failures(void);
int hard_finish(void);
double hard_encode(double linear);

#endif
