/* log.h - the one place the course prints diagnostics.
 *
 *   log_error(fmt, ...)   one line on stderr, always
 *   log_warn(fmt, ...)    one line on stderr, always
 *   log_info(fmt, ...)    one line on stderr unless log_set_quiet(true)
 *   log_debug(fmt, ...)   one line on stderr only after log_set_verbose(true)
 *
 * Library code logs an error once, where it is detected, and returns
 * false/0/NULL; callers do not log it again. Input errors are formatted by
 * the caller as "file:line: message".
 */
#ifndef COMMON_LOG_H
#define COMMON_LOG_H

#include <stdbool.h>

#if defined(__GNUC__)
#define LOG_PRINTF(a, b) __attribute__((format(printf, a, b)))
#else
#define LOG_PRINTF(a, b)
#endif

void log_set_verbose(bool verbose);
void log_set_quiet(bool quiet);
void log_error(const char *fmt, ...) LOG_PRINTF(1, 2);
void log_warn(const char *fmt, ...) LOG_PRINTF(1, 2);
void log_info(const char *fmt, ...) LOG_PRINTF(1, 2);
void log_debug(const char *fmt, ...) LOG_PRINTF(1, 2);

#endif
