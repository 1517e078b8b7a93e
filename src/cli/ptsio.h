/*
 * Point files, the .pts format (see pts(5)).
 *
 * Binary, little-endian:
 *   offset  size  field
 *   0       8     magic "\211PTS\r\n\032\n"
 *   8       4     format version (2; 1 is read too)
 *   12      4     k, coordinates per point (1..16), each in [0, 1)
 *   16      4     e, extra values per point after the coordinates (0..16),
 *                 e.g. the sample density written by frs-sample --pdf
 *   20      4     L, bytes of column names after the header (version 2;
 *                 reserved, 0, in version 1): 0 when e is 0, else the e
 *                 names of the extra columns, each ended by a NUL, then
 *                 NULs up to a multiple of 8
 *   24      8     point count; 0 means "unknown, read to the end"
 *   32 + L        count records of k + e float64
 *
 * Text: one point per line, values separated by blanks (written in the
 * shortest form that reads back exactly, see base/dtoa.h), '#' starts a
 * comment line; an optional first line
 * "#pts dims=K extra=E count=N version=2 names=A,B" gives the layout
 * (without it every column is a coordinate; without names the extra
 * columns are unnamed, as in version 1).  Readers detect the form by the
 * magic.
 */
#ifndef FRS_PTSIO_H
#define FRS_PTSIO_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define PTS_MAGIC "\211PTS\r\n\032\n"
#define PTS_VERSION 2
#define PTS_HEADER 32
#define PTS_MAXCOLS 16
/* A column name: 1 to PTS_NAMELEN - 1 of [A-Za-z0-9_], not starting with
 * a digit. */
#define PTS_NAMELEN 32
#define PTS_MAXNAMES (PTS_MAXCOLS * PTS_NAMELEN)

/* The extra columns that the programs write and look for. */
#define PTS_COL_PDF "pdf"	/* the sample's density, frs-sample --pdf */
#define PTS_COL_STEP "step"	/* its progressive step, from 1 */
#define PTS_COL_SET "set"	/* its set, from 0 (--sets) */
#define PTS_COL_LEVEL "level"	/* its level of the multi-level window,
				 * frs-sample --level-column */

struct frs_points {
	unsigned dims, extra;
	size_t n;
	double *x;	/* n records of dims + extra values */
	/* The names of the extra columns, "" for an unnamed one (version 1
	 * files); a writer needs them all. */
	char names[PTS_MAXCOLS][PTS_NAMELEN];
	unsigned version;	/* of the file read */
};

void pts_free(struct frs_points *p);
/* Read a whole point file (binary or text, "-" for standard input). */
int pts_read(const char *path, struct frs_points *p);
/* The column (dims + j) of the extra column named name, -1 if none. */
int pts_column(const struct frs_points *p, const char *name);
/* Whether s is a valid column name. */
int pts_name_ok(const char *s);

/* Streaming reader. */
struct pts_reader {
	FILE *fp;
	const char *name;
	int text;
	unsigned dims, extra;
	unsigned version;	/* 1 or 2 (text: 2 with a version field) */
	char names[PTS_MAXCOLS][PTS_NAMELEN];	/* of the extra columns */
	uint64_t count;		/* from the header, 0 if unknown */
	uint64_t got;
	unsigned long line;
	unsigned char pre[PTS_HEADER];	/* bytes read while detecting */
	size_t npre, ppre;
	char *buf;		/* text line buffer */
	size_t cap;
	int have_line;		/* buf holds a first data line already */
};

int pts_reader_open(struct pts_reader *r, const char *path);
/* 1 and a record in rec (dims + extra values), 0 at the end, -1 on error. */
int pts_reader_next(struct pts_reader *r, double *rec);
void pts_reader_close(struct pts_reader *r);

/* Streaming writer.  count 0 writes "unknown" and, when the stream can
 * seek, the true count is patched in by pts_writer_end. */
struct pts_writer {
	FILE *fp;
	const char *name;
	int text;
	unsigned dims, extra;
	uint32_t namelen;	/* L, the bytes of names after the header */
	uint64_t count, written;
};

/* Always version 2: names holds the extra columns' names (NULL when
 * extra is 0), each valid and distinct. */
int pts_writer_begin(struct pts_writer *w, FILE *fp, const char *name,
    unsigned dims, unsigned extra, const char *const *names, uint64_t count,
    int text);
int pts_writer_put(struct pts_writer *w, const double *rec);
/* n records at once (n * (dims + extra) values): one check pass and one
 * write; the fast path of the samplers. */
int pts_writer_put_n(struct pts_writer *w, const double *recs, size_t n);
/* A column of n records apart from the rest: v[i * stride] is record
 * i's value (stride 0: v[0] is every record's). */
struct pts_col {
	const double *v;
	size_t stride;
};
/* n records whose values lie apart: record i's coordinates at
 * pts + i * stride (stride dims: packed), then its value of each of the
 * w->extra columns col[j].  The bytes pts_writer_put_n writes of the
 * records side by side, without the caller making them. */
int pts_writer_put_cols(struct pts_writer *w, const double *pts,
    size_t stride, const struct pts_col *col, size_t n);
int pts_writer_end(struct pts_writer *w);

/* Write a whole set (p->names names its extra columns). */
int pts_write(FILE *fp, const char *name, const struct frs_points *p,
    int text);

#endif
