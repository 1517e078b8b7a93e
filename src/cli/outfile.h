/*
 * Atomic output.  A result goes to a temporary file beside its target
 * and is renamed over it only when it is complete, so an error, SIGINT or
 * SIGTERM never leaves a partial file.  "-" or NULL streams to standard
 * output; a target that exists and is not a regular file (a device such as
 * /dev/null or /dev/full, a FIFO) is written in place.
 */
#ifndef FRS_OUTFILE_H
#define FRS_OUTFILE_H

#include <stdio.h>

struct outfile {
	FILE *fp;
	const char *name;	/* for messages: the path or "<stdout>" */
	char *path;		/* target, NULL for standard output */
	char *tmp;		/* temporary file, NULL when writing in place */
};

/* binary != 0 refuses to write to a terminal. */
int outfile_open(struct outfile *o, const char *path, int binary);
/* Flush, check for write errors, rename into place.  On failure the
 * temporary file is removed and -1 returned. */
int outfile_commit(struct outfile *o);
/* Drop the output: remove the temporary file. */
void outfile_abort(struct outfile *o);
/* Remove every temporary file still open (called at exit and from the
 * signal handler, which outfile_open installs). */
void outfile_cleanup_all(void);

#endif
