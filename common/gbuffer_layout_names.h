/* gbuffer_layout_names.h - the G-buffer layouts by id and name, and nothing else: no GL, so that the
 * command line (cli.c) offers the same names that common/gbuffer.h gives formats to.
 *
 *   GBUFFER_LAYOUT_LIST(X)   X(ID, "name") once per layout: the one list of them
 *   gbuffer_layout_id        GBUFFER_LAYOUT_<ID> for each, in that order, then GBUFFER_LAYOUT_COUNT
 *   GBUFFER_LAYOUT_NAMES     the names in that order as an initialiser, NULL-terminated
 */
#ifndef COMMON_GBUFFER_LAYOUT_NAMES_H
#define COMMON_GBUFFER_LAYOUT_NAMES_H

#include <stddef.h>

#define GBUFFER_LAYOUT_LIST(X)                                                                               \
    X(REFERENCE, "reference")                                                                                \
    X(COMPACT, "compact")                                                                                    \
    X(COMPACT_D24S8, "compact-d24s8")                                                                        \
    X(REVERSED_Z, "reversed-z")                                                                              \
    X(LINEAR_ALBEDO, "linear-albedo")                                                                        \
    X(OCT8, "oct8")                                                                                          \
    X(OCT16, "oct16")

#define GBUFFER_LAYOUT_ID_(id, name) GBUFFER_LAYOUT_##id,
typedef enum gbuffer_layout_id {
    GBUFFER_LAYOUT_LIST(GBUFFER_LAYOUT_ID_) GBUFFER_LAYOUT_COUNT
} gbuffer_layout_id;
#undef GBUFFER_LAYOUT_ID_

#define GBUFFER_LAYOUT_NAME_(id, name) name,
#define GBUFFER_LAYOUT_NAMES                                                                                 \
    {                                                                                                        \
        GBUFFER_LAYOUT_LIST(GBUFFER_LAYOUT_NAME_) NULL                                                       \
    }

#endif
