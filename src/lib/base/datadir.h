/*
 * Where the shipped data lie (default.frd, default3.frd, sunset.exr):
 * the directories that frs_default_matrix and, through src/cli's
 * cli_data_file, frs-sample and mc-error look through, wherever the
 * programs or the library were installed.
 */
#ifndef FRS_DATADIR_H
#define FRS_DATADIR_H

#include <stddef.h>

#define DATA_DIRS_MAX 4
#define DATA_PATH_MAX 4096

struct data_dirs {
	size_t n;
	int env;			/* 1: the one directory of $FRS_DATA */
	char dir[DATA_DIRS_MAX][DATA_PATH_MAX];
};

/*
 * The directories to look in, in order: $FRS_DATA alone when it is set
 * and not empty; else PREFIX/share/frs beside the shared library
 * (LIBDIR/..) when the code runs from libfrs.so, the same beside the
 * program (BINDIR/..), the source tree's data/ (uninstalled builds; not
 * when built with SRCDATA empty) and the share/frs of the PREFIX the
 * library was built for.  Each directory once.
 */
void data_dirs(struct data_dirs *d);

/*
 * The path of NAME in the first of those directories that holds it
 * readable, into path (cap bytes): 0.  Else -1 with the message
 * "looked for D1/NAME, D2/NAME and D3/NAME", or "looked for
 * D/NAME; FRS_DATA is set".
 */
int data_find(const char *name, char *path, size_t cap);

#endif
