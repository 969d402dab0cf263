/* gbuffer_layout_names.h - the G-buffer layouts by id and name, and nothing else: no GL, so that the
 * command line (cli.c) offers the names that common/render/gbuffer.h gives formats to, from one list.
 *
 *   gbuffer_layout_id        GBUFFER_LAYOUT_<ID> for each layout, then GBUFFER_LAYOUT_COUNT
 *   gbuffer_layout_names[]   what --gbuffer takes, by id, NULL-terminated
 */
#ifndef COMMON_GBUFFER_LAYOUT_NAMES_H
#define COMMON_GBUFFER_LAYOUT_NAMES_H

typedef enum gbuffer_layout_id {
    GBUFFER_LAYOUT_REFERENCE,
    GBUFFER_LAYOUT_COMPACT,
    GBUFFER_LAYOUT_COMPACT_D24S8,
    GBUFFER_LAYOUT_REVERSED_Z,
    GBUFFER_LAYOUT_LINEAR_ALBEDO,
    GBUFFER_LAYOUT_OCT8,
    GBUFFER_LAYOUT_OCT16,
    GBUFFER_LAYOUT_COUNT
} gbuffer_layout_id;

extern const char *const gbuffer_layout_names[GBUFFER_LAYOUT_COUNT + 1];

#endif
