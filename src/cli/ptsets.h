/*
 * Point sets for the analysis programs (discrepancy, dda, mc-error,
 * pts-render): 2-D or 3-D point files read whole, each file one set, cut
 * into sets by its set column, or cut into sets of a fixed size.
 */
#ifndef FRS_PTSETS_H
#define FRS_PTSETS_H

#include <stddef.h>
#include <stdio.h>
#include <stdint.h>

struct frs_points;

/* A set within a file's records. */
struct pt_range {
	size_t first, n;	/* records first .. first + n - 1 */
	uint64_t id;		/* the set column's value, else the index */
};

/*
 * The sets of p, read from path: with a column named "set" (pts(5)), the
 * runs of equal values (whole numbers from 0, never decreasing; an empty
 * set simply has no points); else with per > 0 blocks of per records
 * (the count must be a multiple); else the whole file.  With per, a
 * warning naming path when the file is cut into more than one block, or
 * when its set column has sets of another size than per (the column's
 * sets are kept).  *r (malloc'd, *k ranges; p->n = 0 gives none) or -1
 * with a message naming path.
 */
int pt_split(const struct frs_points *p, const char *path, size_t per,
    struct pt_range **r, size_t *k);

struct pt_set {
	const double *xy;	/* n points, dims coordinates each, packed
				 * (x y, or x y z) */
	const double *w;	/* the first extra value of each point (the
				 * density of frs-sample --pdf), or NULL */
	size_t n;
	unsigned dims;		/* 2 or 3 */
	const char *file;	/* the name given, for messages and tables */
	size_t first;		/* its first point's index in the file */
};

struct pt_sets {
	struct pt_set *set;
	size_t n;
	double **buf;		/* one per file, owning the coordinates */
	size_t nbuf;
	unsigned max_dims;	/* set by the caller before the first add:
				 * 3 accepts 2-D and 3-D files; 0 or 2 (the
				 * default of a zeroed struct) 2-D only */
	unsigned dims;		/* of every set so far; 0 before the first */
};

/* Read path ("-": standard input), points of 2 (or, with max_dims 3, 3)
 * coordinates, and append its sets (pt_split).  Of the extra values only
 * the pdf is kept (as w): the column named pdf, or in a file of version 1
 * (unnamed columns) the first extra one.  All files of one pt_sets have
 * the same dimension: a file that differs from those before is an error
 * naming it.  An empty file is an error. */
int pt_sets_add(struct pt_sets *s, const char *path, size_t per);
void pt_sets_free(struct pt_sets *s);

/* --group (discrepancy, mc-error): which sets one table row sums up.
 * The default, PT_GROUP_NFILE, has no name: the sets of one count in one
 * file, so that several files are never merged unless asked. */
enum pt_group { PT_GROUP_N, PT_GROUP_FILE, PT_GROUP_ALL, PT_GROUP_NFILE };
/* "n", "file" or "all"; -1 for anything else. */
int pt_group_parse(const char *s);
/* Sets a and b go in one row: the same count (n), the same file, always
 * (all), or the same count in the same file (the default). */
int pt_same_group(enum pt_group g, const struct pt_set *a,
    const struct pt_set *b);
/* Whether the rows of g carry a file column: g is file, or the default
 * with sets from more than one file (nfiles). */
int pt_group_files(enum pt_group g, size_t nfiles);
/* A file name as a table's last cell: tabs and newlines as '?'. */
void pt_put_name(FILE *fp, const char *name);

#endif
