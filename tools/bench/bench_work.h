/* bench_work.h - the old name of bench_error.h, kept only until tools/bench/bench_gbuffer.c includes
 * bench_error.h and calls bench_error_measure_hdr; then delete this file. */
#include "bench_error.h"

#define bench_work_hdr_error bench_error_measure_hdr
