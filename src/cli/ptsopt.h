/*
 * The options and inputs of the programs that read point sets (dda,
 * discrepancy, mc-error, pts-render; ptsets.h): --sets N, --group G and
 * the point files named after the options; and --sets M of those that
 * write them (frs-sample, hsw-sample, ref-sample; setsout.h).
 */
#ifndef FRS_CLI_PTSOPT_H
#define FRS_CLI_PTSOPT_H

#include <stddef.h>
#include <stdint.h>

#include "formats/ptsets.h"

/* --sets N: every file split into sets of N points. */
size_t cli_sets(const char *arg);
/* --sets M of a sampler: M sets one after another. */
uint64_t cli_sets_m(const char *arg);
/* M sets of n points each (n: the most a set can have) fit one file and
 * their seeds, from -S on, stay within 2^64 - 1; else a usage error. */
void cli_sets_check(uint64_t m, uint64_t n);
/* --group G: n, file or all. */
enum pt_group cli_group(const char *arg);
/* The files after the options: at least one, else a usage error. */
void cli_need_files(int argc);
/* Each file after the options read into s (pt_sets_add with per), then
 * handed to each (when not NULL) with its number among the files and its
 * first set; a failure of either ends the program with its message. */
void cli_read_sets(struct pt_sets *s, int argc, char **argv, size_t per,
    int (*each)(void *ctx, const struct pt_sets *s, size_t file,
    size_t first), void *ctx);

#endif
