/* shader_log.c - see shader_log.h. */
#include "shader_log.h"

#include <stdio.h>
#include <string.h>

/* sscanf reads past n otherwise: the log's lines are not NUL-terminated one by one. */
static bool copy_line(const char *line, int n, char *buf, int size)
{
    if (n < 0 || n >= size)
        return false;
    memcpy(buf, line, (size_t)n);
    buf[n] = '\0';
    return true;
}

bool shader_log_parse(const char *line, int n, shader_log_line *out)
{
    char buf[1024];
    int used = 0;
    if (!copy_line(line, n, buf, sizeof buf))
        return false;
    *out = (shader_log_line){.severity = ""};
    if (sscanf(buf, "%d:%d(%d): %n", &out->source, &out->line, &out->column, &used) == 3 && used > 0) {
        /* Mesa */
    } else if (sscanf(buf, "%d(%d) : %n", &out->source, &out->line, &used) == 2 && used > 0) {
        out->column = 0; /* NVIDIA */
    } else if (sscanf(buf, "ERROR: %d:%d: %n", &out->source, &out->line, &used) == 2 && used > 0) {
        out->column = 0, out->severity = "error"; /* AMD */
    } else if (sscanf(buf, "WARNING: %d:%d: %n", &out->source, &out->line, &used) == 2 && used > 0) {
        out->column = 0, out->severity = "warning";
    } else {
        return false;
    }
    out->message = line + used;
    out->message_len = n - used;
    return out->source >= 0 && out->line >= 0;
}
