/* gen_format.h - numbers as gen_scenes writes them: short, and the same on every run.
 *
 *   gen_format_number(v, decimals, buf)     shortest decimal with at most `decimals` digits:
 *                                           "1.5", "0", "-0.25" (never "-0")
 *   gen_format_count(n, buf)                with thousands separators: "18,529"
 *   gen_format_write_vec3(v, decimals, f)   three gen_format_number values, space-separated
 *
 * Both formatters return buf, so a call can stand as a printf argument.
 */
#ifndef TOOLS_GEN_SCENES_GEN_FORMAT_H
#define TOOLS_GEN_SCENES_GEN_FORMAT_H

#include <stdio.h>

const char *gen_format_number(double v, int decimals, char buf[32]);
const char *gen_format_count(long n, char buf[32]);
void gen_format_write_vec3(const double v[3], int decimals, FILE *f);

#endif
