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

int sets_writer_put(struct sets_writer *s, const double *rec, size_t n)
{
	double buf[4096];
	size_t per = sizeof buf / sizeof *buf / (s->ncol + 1);

	if (s->sets <= 1)
		return pts_writer_put_n(&s->w, rec, n);
	/* The records in pieces, each with its set after it. */
	for (size_t b = 0; b < n; b += per) {
		size_t m = n - b < per ? n - b : per;
		for (size_t i = 0; i < m; i++) {
			double *r = buf + i * (s->ncol + 1);
			memcpy(r, rec + (b + i) * s->ncol, s->ncol * sizeof *r);
			r[s->ncol] = (double)s->set;
		}
		if (pts_writer_put_n(&s->w, buf, m) < 0)
			return -1;
	}
	return 0;
}

int sets_writer_end(struct sets_writer *s)
{
	return pts_writer_end(&s->w);
}
