/* gen_format.c - number formatting for the scene and model writers. */
#include "gen_format.h"

#include <string.h>

/* Trailing zeros would make the files longer and the diffs between generator versions noisier. */
const char *gen_format_number(double v, int decimals, char buf[32])
{
    snprintf(buf, 32, "%.*f", decimals, v);
    char *dot = strchr(buf, '.');
    if (dot) {
        char *end = buf + strlen(buf) - 1;
        while (end > dot && *end == '0') {
            *end-- = '\0';
        }
        if (end == dot) {
            *end = '\0';
        }
    }
    if (strcmp(buf, "-0") == 0) {
        strcpy(buf, "0");
    }
    return buf;
}

/* As the published tables print counts, so a scene's comment block reads like them. */
const char *gen_format_count(long n, char buf[32])
{
    char digits[32];
    int len = snprintf(digits, sizeof digits, "%ld", n), k = 0;
    for (int i = 0; i < len; i++) {
        if (i > 0 && digits[i - 1] != '-' && (len - i) % 3 == 0) {
            buf[k++] = ',';
        }
        buf[k++] = digits[i];
    }
    buf[k] = '\0';
    return buf;
}

void gen_format_write_vec3(const double v[3], int decimals, FILE *f)
{
    char a[32], b[32], c[32];
    fprintf(f, "%s %s %s", gen_format_number(v[0], decimals, a), gen_format_number(v[1], decimals, b),
            gen_format_number(v[2], decimals, c));
}
