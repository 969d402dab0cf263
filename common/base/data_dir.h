/* data_dir.h - where the course's shaders and assets are, wherever a program runs from.
 *
 *   data_dir_set(dir)                    --data-dir: this folder (it holds shaders/ and assets/)
 *   data_dir()                           the folder: --data-dir, else $COURSE_DATA_DIR, else
 *                                        share/deferred_course of an installed prefix (beside the
 *                                        executable's bin/), else the source tree it was built from
 *   data_dir_path(relative, out, size)   data_dir()/relative; false when it does not fit
 *   data_dir_origin()                    which of the four gave data_dir(), for messages
 *   data_dir_find(given, first, out, size, tried, tried_size)
 *                                        an input file named on a command line or in a scene: an
 *                                        absolute `given` as it is; a relative one in the folder
 *                                        `first` (NULL: the current folder), then in data_dir().
 *                                        False when neither exists (or the path does not fit), with
 *                                        `tried` listing where it looked; *out is then the first place
 *   data_dir_find_output(given, out, size, why, why_size)
 *                                        a file to write (a screenshot): its folder found as
 *                                        data_dir_find finds an input, the file's name kept; false
 *                                        when there is no such folder or the name is a folder, with
 *                                        `why` saying so and where it looked
 *   data_dir_open_input(path, &why)      a file found above, opened to read ("rb") only when it is a
 *                                        regular file: a named pipe or a device is refused without
 *                                        waiting on it (opened non-blocking, then fstat'ed, so that no
 *                                        file swapped in between is read). NULL with *why, a static
 *                                        string ("not a regular file", strerror's), otherwise
 */
#ifndef COMMON_DATA_DIR_H
#define COMMON_DATA_DIR_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

void data_dir_set(const char *dir);
const char *data_dir(void);
bool data_dir_path(const char *relative, char *out, size_t size);
const char *data_dir_origin(void);
bool data_dir_find(const char *given, const char *first, char *out, size_t size, char *tried, size_t tried_size);
bool data_dir_find_output(const char *given, char *out, size_t size, char *why, size_t why_size);
FILE *data_dir_open_input(const char *path, const char **why);

#endif
