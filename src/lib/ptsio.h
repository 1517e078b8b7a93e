/*
 * Point files, the .pts format (see pts(5)).
 *
 * Binary, little-endian:
 *   offset  size  field
 *   0       8     magic "\211PTS\r\n\032\n"
 *   8       4     format version (1)
 *   12      4     k, coordinates per point (1..16), each in [0, 1)
 *   16      4     e, extra values per point after the coordinates (0..16),
 *                 e.g. the sample density written by frs-sample --pdf
 *   20      4     reserved, 0
 *   24      8     point count; 0 means "unknown, read to the end"
 *   32            count records of k + e float64
 *
 * Text: one point per line, values separated by blanks (written in the
 * shortest form that reads back exactly, see dtoa.h), '#' starts a
 * comment line; an optional first line "#pts dims=K extra=E count=N"
 * gives the layout (without it every column is a coordinate).
 * Readers detect the form by the magic.
 */
#ifndef FRS_PTSIO_H
#define FRS_PTSIO_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define PTS_MAGIC "\211PTS\r\n\032\n"
#define PTS_VERSION 1
#define PTS_HEADER 32
#define PTS_MAXCOLS 16

struct frs_points {
	unsigned dims, extra;
	size_t n;
	double *x;	/* n records of dims + extra values */
};

void pts_free(struct frs_points *p);
/* Read a whole point file (binary or text, "-" for standard input). */
int pts_read(const char *path, struct frs_points *p);

/* Streaming reader. */
struct pts_reader {
	FILE *fp;
	const char *name;
	int text;
	unsigned dims, extra;
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
	uint64_t count, written;
};

int pts_writer_begin(struct pts_writer *w, FILE *fp, const char *name,
    unsigned dims, unsigned extra, uint64_t count, int text);
int pts_writer_put(struct pts_writer *w, const double *rec);
/* n records at once (n * (dims + extra) values): one check pass and one
 * write; the fast path of the samplers. */
int pts_writer_put_n(struct pts_writer *w, const double *recs, size_t n);
int pts_writer_end(struct pts_writer *w);

/* Write a whole set. */
int pts_write(FILE *fp, const char *name, const struct frs_points *p,
    int text);

#endif
