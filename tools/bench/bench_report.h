/* bench_report.h - the benchmark's result files: every row as CSV for tools, and a Markdown page
 * with the targets, the crossover and one table per question for people (docs/compare.md shows
 * one). Every file is written to NAME.tmp and renamed into place, so a reader never sees half a file.
 *
 *   bench_report_write_csv(st)             OUT/bench.csv: one row per (case, renderer), NA where a
 *                                          value was not measured; the columns are stable
 *   bench_report_write_md(st)              OUT/bench.md
 *   bench_report_write_part_md(st, name, title, write_section)
 *                                          OUT/NAME: a part run alone (--gbuffer-sweep only,
 *                                          --storage only) writes its section into a page of its own,
 *                                          the machine on top, so it never replaces the sweep's bench.md
 *   bench_report_write_pbr(f, st)          the "## Metallic-roughness scenes" section of bench.md (the
 *                                          PBR rows; bench_report_pbr.c); nothing when there are none
 *   bench_report_time_cell(f, r)           one table cell: r's median ms, marked when extrapolated or
 *                                          from fewer frames; "–" when r is NULL
 *   bench_report_open_tmp(dir, name, tmp, size)
 *                                          DIR/NAME.tmp opened for writing, its path in tmp; NULL
 *                                          on failure (logged)
 *   bench_report_close_tmp(f, tmp, dir, name)
 *                                          close f and rename tmp to DIR/NAME; on any failure
 *                                          (logged) tmp is removed and false returned
 */
#ifndef TOOLS_BENCH_REPORT_H
#define TOOLS_BENCH_REPORT_H

#include "bench_state.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

bool bench_report_write_csv(const bench_state *st);
bool bench_report_write_md(const bench_state *st);
bool bench_report_write_part_md(const bench_state *st, const char *name, const char *title,
                                void (*write_section)(FILE *f, const bench_state *st));
void bench_report_write_pbr(FILE *f, const bench_state *st);
void bench_report_time_cell(FILE *f, const bench_row *r);
FILE *bench_report_open_tmp(const char *dir, const char *name, char *tmp, size_t size);
bool bench_report_close_tmp(FILE *f, const char *tmp, const char *dir, const char *name);

#endif
