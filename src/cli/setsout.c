#define _POSIX_C_SOURCE 200809L
#include <string.h>

#include "base/err.h"
#include "cli/setsout.h"

int sets_writer_begin(struct sets_writer *s, FILE *fp, const char *name,
    unsigned dims, unsigned extra, const char *const *names, uint64_t sets,
    uint64_t count, int text)
{
	const char *all[PTS_MAXCOLS];
	unsigned k = extra;

	s->sets = sets;
	s->set = 0;
	s->ncol = dims + extra;
	if (dims + extra + (sets > 1) > PTS_MAXCOLS)
		return frs_fail("%s: %u coordinates, %u extra values and the "
		    "set per point are not supported", name, dims, extra);
	if (extra > 0)
		memcpy(all, names, extra * sizeof *all);
	if (sets > 1)
		all[k++] = PTS_COL_SET;
	return pts_writer_begin(&s->w, fp, name, dims, k, all, count, text);
}

/* n records of the caller's pts (stride apart) and columns col (its
 * extra ones), the set's column after them when there are sets. */
static int put_apart(struct sets_writer *s, const double *pts,
    size_t stride, const struct pts_col *col, size_t n)
{
	struct pts_col all[PTS_MAXCOLS];
	unsigned extra = s->ncol - s->w.dims;
	double set = (double)s->set;

	if (s->sets <= 1)
		return pts_writer_put_cols(&s->w, pts, stride, col, n);
	if (extra > 0)
		memcpy(all, col, extra * sizeof *all);
	all[extra] = (struct pts_col){ &set, 0 };
	return pts_writer_put_cols(&s->w, pts, stride, all, n);
}

int sets_writer_put(struct sets_writer *s, const double *rec, size_t n)
{
	struct pts_col col[PTS_MAXCOLS];
	unsigned dims = s->w.dims;

	for (unsigned j = 0; j < s->ncol - dims; j++)
		col[j] = (struct pts_col){ rec + dims + j, s->ncol };
	return put_apart(s, rec, s->ncol, col, n);
}

int sets_writer_put_cols(struct sets_writer *s, const double *pts,
    const double *const *col, size_t n)
{
	struct pts_col c[PTS_MAXCOLS];

	for (unsigned j = 0; j < s->ncol - s->w.dims; j++)
		c[j] = (struct pts_col){ col[j], 1 };
	return put_apart(s, pts, s->w.dims, c, n);
}

int sets_writer_end(struct sets_writer *s)
{
	return pts_writer_end(&s->w);
}
