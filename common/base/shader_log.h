/* shader_log.h - a driver's shader info log, line by line, mapped back to the course's files.
 *
 *   shader_log_parse(line, n, out)   false when the first n characters of `line` name no place
 *
 * The GL drivers write the place of a message three ways (source string S, line L, column C):
 *   Mesa     S:L(C): error: message
 *   NVIDIA   S(L) : error C0502: message
 *   AMD      ERROR: S:L: message
 * gl_program.c gives every #included file its own source string (#line L S), so S names the file.
 */
#ifndef COMMON_SHADER_LOG_H
#define COMMON_SHADER_LOG_H

#include <stdbool.h>

typedef struct shader_log_line {
    int source, line;
    int column;           /* 0 when the driver gives none */
    const char *severity; /* "error" or "warning" where the format puts it before the place, else "" */
    const char *message;  /* the rest of the line after the place (not NUL-terminated at n) */
    int message_len;
} shader_log_line;

bool shader_log_parse(const char *line, int n, shader_log_line *out);

#endif
