/* probe_readback.h - what split_sum_reference.h measures, read back from one of chapter 19's probes
 * (chapters/ibl_probes.h): its capture, every prefiltered level and the split-sum table, as floats.
 *
 *   probe_readback(b, index, out)   probe `index` of b; false (GL's error logged) when a read fails
 *   probe_readback_free(p)
 */
#ifndef TOOLS_PROBE_READBACK_H
#define TOOLS_PROBE_READBACK_H

#include "ibl_probes.h"
#include "split_sum_reference.h"

#include <stdbool.h>

bool probe_readback(const ibl *b, int index, split_sum_probe *out);
void probe_readback_free(split_sum_probe *p);

#endif
