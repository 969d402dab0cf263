/* replay_main.c - run a fuzz target once on each file named on the command line, or on each
 * file inside a folder named there.
 *
 * Links with any fuzz target in place of libFuzzer, so the seed corpus and the saved crashes in
 * tests/fuzz/regressions/ are replayed by every compiler (and under the sanitizer build).
 */
#include <dirent.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int replay_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "%s: cannot open\n", path);
        return 1;
    }
    size_t len = 0, cap = 4096;
    unsigned char *buf = malloc(cap);
    for (size_t got; buf && (got = fread(buf + len, 1, cap - len, f)) > 0;) {
        len += got;
        if (len == cap) {
            unsigned char *grown = realloc(buf, cap * 2);
            if (!grown) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = grown;
            cap *= 2;
        }
    }
    fclose(f);
    if (!buf) {
        fprintf(stderr, "%s: out of memory\n", path);
        return 1;
    }
    LLVMFuzzerTestOneInput(buf, len);
    free(buf);
    return 0;
}

/* Files directly inside a folder (hidden ones skipped, so a .gitkeep keeps an empty folder). */
static int replay_folder(const char *path, int *count)
{
    DIR *d = opendir(path);
    if (!d) {
        fprintf(stderr, "%s: cannot open folder\n", path);
        return 1;
    }
    int failed = 0;
    for (struct dirent *e; (e = readdir(d)) != NULL;) {
        if (e->d_name[0] == '.')
            continue;
        char file[4096];
        snprintf(file, sizeof file, "%s/%s", path, e->d_name);
        failed += replay_file(file);
        (*count)++;
    }
    closedir(d);
    return failed;
}

int main(int argc, char **argv)
{
    int failed = 0, count = 0;
    for (int i = 1; i < argc; i++) {
        struct stat st;
        if (stat(argv[i], &st) == 0 && S_ISDIR(st.st_mode)) {
            failed += replay_folder(argv[i], &count);
        } else {
            failed += replay_file(argv[i]);
            count++;
        }
    }
    printf("replayed %d input(s), %d unreadable\n", count - failed, failed);
    return failed || count == 0 ? 1 : 0;
}
