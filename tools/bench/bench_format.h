/* bench_format.h - numbers as the benchmark's reports print them, where printf's own flags are not
 * enough: a difference keeps its one sign ("+57", "-157"), never "+-157", which a "+%.0f" gives a
 * negative number.
 *
 *   bench_format_change(v, decimals, out, size)
 *                                          v with `decimals` decimals and its sign: "+57.0",
 *                                          "-157.0"; "0.0" when it rounds to zero (no sign); "–"
 *                                          when v is NaN (not measured). Returns out
 */
#ifndef TOOLS_BENCH_FORMAT_H
#define TOOLS_BENCH_FORMAT_H

#include <stddef.h>

const char *bench_format_change(double v, int decimals, char *out, size_t size);

#endif
