/* gbuffer_layout_names.c - see gbuffer_layout_names.h. */
#include "gbuffer_layout_names.h"

#include <stddef.h>

const char *const gbuffer_layout_names[GBUFFER_LAYOUT_COUNT + 1] = {
    [GBUFFER_LAYOUT_REFERENCE] = "reference",         [GBUFFER_LAYOUT_COMPACT] = "compact",
    [GBUFFER_LAYOUT_COMPACT_D24S8] = "compact-d24s8", [GBUFFER_LAYOUT_REVERSED_Z] = "reversed-z",
    [GBUFFER_LAYOUT_LINEAR_ALBEDO] = "linear-albedo", [GBUFFER_LAYOUT_OCT8] = "oct8",
    [GBUFFER_LAYOUT_OCT16] = "oct16",                 [GBUFFER_LAYOUT_COUNT] = NULL,
};
