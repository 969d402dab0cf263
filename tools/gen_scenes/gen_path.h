/* gen_path.h - the file-system side of gen_scenes: folders, the scenes' relative model paths,
 * and output files that report their own errors.
 *
 *   gen_path_make_dir(dir)                    create dir unless it exists (not its parents)
 *   gen_path_relative(from, to, size, out)    the path from directory `from` to directory `to`
 *                                             ("../models"), both resolved first; "." when equal
 *   gen_path_join(dir, name, out)             "dir/name"
 *   gen_path_open_file(path)                  fopen(path, "w")
 *   gen_path_close_file(f, path)              fclose, true only when every write succeeded
 *
 * Each logs its own error and returns false (or NULL); callers do not log it again.
 */
#ifndef TOOLS_GEN_SCENES_GEN_PATH_H
#define TOOLS_GEN_SCENES_GEN_PATH_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#define GEN_PATH_MAX 4096

bool gen_path_make_dir(const char *dir);
bool gen_path_relative(const char *from, const char *to, size_t size, char *out);
bool gen_path_join(const char *dir, const char *name, char out[GEN_PATH_MAX]);
FILE *gen_path_open_file(const char *path);
bool gen_path_close_file(FILE *f, const char *path);

#endif
