/*
 * The programs' output step: a file opened (outfile.h: written beside
 * its target and renamed into place), written, and committed, or on any
 * failure removed, the program ending with the library's message.
 */
#ifndef FRS_CLI_OUTPUT_H
#define FRS_CLI_OUTPUT_H

#include "base/outfile.h"

/* path NULL or "-": standard output, which binary output refuses when it
 * is a terminal. */
void cli_out_open(struct outfile *of, const char *path, int binary);
/* rc: what writing of->fp gave (-1 after frs_fail: the file removed). */
void cli_out_commit(struct outfile *of, int rc);

#endif
