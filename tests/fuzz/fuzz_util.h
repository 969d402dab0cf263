/* fuzz_util.h - what the fuzz targets share. Header-only, since each target is built on its own
 * (tests/fuzz/fuzz.cmake, run_fuzz.sh) from its one fuzz_NAME.c.
 *
 *   fuzz_text(data, size)   a malloc'd copy of the input bytes with a NUL after them, for parsers
 *                           that take a C string; NULL when out of memory. The caller frees it.
 */
#ifndef TESTS_FUZZ_UTIL_H
#define TESTS_FUZZ_UTIL_H

#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static inline char *fuzz_text(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text)
        return NULL;
    memcpy(text, data, size);
    text[size] = '\0';
    return text;
}

#endif
