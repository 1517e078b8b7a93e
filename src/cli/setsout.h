/*
 * M point sets into one points file, one after another, as the samplers'
 * --sets M write them (frs-sample, hsw-sample, ref-sample; pts(5)): the
 * caller makes set i with seed S + i and hands its records over; with
 * M > 1 each record is followed by its set i, in a last extra column
 * named set, by which the analysis programs split the file (ptsets.h).
 */
#ifndef FRS_SETSOUT_H
#define FRS_SETSOUT_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "cli/ptsio.h"

/* The most points of all the sets of one file: 2^56 records of up to 17
 * columns stay far inside a 64-bit file offset. */
#define SETS_MAX_POINTS ((uint64_t)1 << 56)

struct sets_writer {
	struct pts_writer w;
	uint64_t sets;		/* M */
	uint64_t set;		/* the set being written, from 0: the caller's */
	unsigned ncol;		/* values of a caller's record */
};

/* Begin the file: records of dims coordinates and extra columns named
 * names, the set column added after them when sets > 1; count: the points
 * of all the sets, or 0 when not known beforehand (pts_writer_begin). */
int sets_writer_begin(struct sets_writer *s, FILE *fp, const char *name,
    unsigned dims, unsigned extra, const char *const *names, uint64_t sets,
    uint64_t count, int text);
/* n records of set s->set, dims + extra values each. */
int sets_writer_put(struct sets_writer *s, const double *rec, size_t n);
/* The same from columns: n points of dims coordinates packed in pts, and
 * the extra columns col[0..extra-1], n values each (the library's draws
 * hand their points and densities so: no records made to write them). */
int sets_writer_put_cols(struct sets_writer *s, const double *pts,
    const double *const *col, size_t n);
int sets_writer_end(struct sets_writer *s);

#endif
