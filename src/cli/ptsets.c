#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/err.h"
#include "cli/ptsets.h"
#include "cli/ptsio.h"

/* Keep buffer b (owned from now on); -1 without freeing it. */
static int keep(struct pt_sets *s, double *b)
{
	double **nb = realloc(s->buf, (s->nbuf + 1) * sizeof *nb);

	if (nb == NULL)
		return -1;
	s->buf = nb;
	s->buf[s->nbuf++] = b;
	return 0;
}

/* The pdf column (col, -1 for none) into an array of its own, and the
 * dims coordinates of each point packed; *fail set when out of memory. */
static double *split(struct frs_points *p, int col, int *fail)
{
	size_t d = p->dims, stride = d + p->extra;
	double *w = NULL;

	*fail = 0;
	if (col >= 0 && (w = malloc(p->n * sizeof *w)) == NULL) {
		*fail = 1;
		return NULL;
	}
	for (size_t i = 0; p->extra && i < p->n; i++) {
		if (w != NULL)
			w[i] = p->x[stride * i + (size_t)col];
		/* forward: the target never overtakes the source */
		memmove(&p->x[d * i], &p->x[stride * i], d * sizeof *p->x);
	}
	return w;
}

/* The set of record i: a whole number from 0 below 2^53. */
static int set_of(const struct frs_points *p, const char *path, int col,
    size_t i, uint64_t *id)
{
	double v = p->x[i * (p->dims + p->extra) + (size_t)col];

	if (!(v >= 0 && v < 9007199254740992.0) || v != floor(v))
		return frs_fail("%s: point %zu: set %.17g is not a whole number "
		    "from 0", path, i, v);
	*id = (uint64_t)v;
	return 0;
}

/* What a split by per does that the user may not expect: a file without
 * a set column cut into blocks in file order (sets only if the file was
 * written set after set: one sampler's single set comes out in strips),
 * or a set column whose sets are not per points (they win). */
static void warn_split(const char *path, size_t per, int column,
    const struct pt_range *r, size_t k)
{
	size_t lo = SIZE_MAX, hi = 0;

	if (per == 0)
		return;
	if (!column) {
		if (k > 1)
			frs_warn("%s: no set column: cut in file order into %zu "
			    "sets of %zu points, which are sets of their own only "
			    "if the file holds such sets one after another (a set "
			    "column marks them, as frs-sample, hsw-sample and "
			    "ref-sample write it for several sets)", path, k, per);
		return;
	}
	for (size_t i = 0; i < k; i++) {
		lo = r[i].n < lo ? r[i].n : lo;
		hi = r[i].n > hi ? r[i].n : hi;
	}
	if (k == 0 || (lo == per && hi == per))
		return;
	if (lo == hi)
		frs_warn("%s: the sets of its set column have %zu points, not "
		    "%zu; they are taken as they are", path, lo, per);
	else
		frs_warn("%s: the sets of its set column have %zu to %zu points, "
		    "not %zu; they are taken as they are", path, lo, hi, per);
}

int pt_split(const struct frs_points *p, const char *path, size_t per,
    struct pt_range **out, size_t *k)
{
	int col = pts_column(p, PTS_COL_SET);
	struct pt_range *r = NULL;
	size_t n = 0, cap = 0;

	*out = NULL, *k = 0;
	if (col < 0 && per && p->n % per != 0)
		return frs_fail("%s: %zu points are not a whole number of sets "
		    "of %zu, and there is no set column to split them by", path,
		    p->n, per);
	for (size_t i = 0; i < p->n;) {
		struct pt_range t = { i, 0, n };
		if (col >= 0) {
			uint64_t id = 0, next = 0;
			if (set_of(p, path, col, i, &id) < 0)
				goto fail;
			if (n > 0 && id <= r[n - 1].id) {
				frs_fail("%s: point %zu: set %llu after set %llu; "
				    "the points of a set must be together, the "
				    "sets in increasing order", path, i,
				    (unsigned long long)id,
				    (unsigned long long)r[n - 1].id);
				goto fail;
			}
			t.id = id;
			while (i < p->n) {
				if (set_of(p, path, col, i, &next) < 0)
					goto fail;
				if (next != id)
					break;
				i++;
			}
			t.n = i - t.first;
		} else {
			t.n = per ? per : p->n;
			i += t.n;
		}
		if (n == cap) {
			size_t ncap = cap ? 2 * cap : 16;
			struct pt_range *nr = realloc(r, ncap * sizeof *r);
			if (nr == NULL) {
				frs_fail("%s: no memory for %zu sets", path, ncap);
				goto fail;
			}
			r = nr, cap = ncap;
		}
		r[n++] = t;
	}
	*out = r, *k = n;
	warn_split(path, per, col >= 0, r, n);
	return 0;
fail:
	free(r);
	return -1;
}

/* The dimension of a file against what the caller and the files before
 * allow. */
static int check_dims(const struct pt_sets *s, const char *path,
    unsigned dims)
{
	unsigned max = s->max_dims == 3 ? 3 : 2;

	if (dims < 2 || dims > max)
		return max == 2 ?
		    frs_fail("%s: %u-dimensional points; 2 are needed", path,
		    dims) :
		    frs_fail("%s: %u-dimensional points; 2 or 3 are needed",
		    path, dims);
	if (s->dims != 0 && dims != s->dims)
		return frs_fail("%s: %u-dimensional points after %u-dimensional "
		    "ones; one run takes sets of one dimension", path, dims,
		    s->dims);
	return 0;
}

int pt_sets_add(struct pt_sets *s, const char *path, size_t per)
{
	struct frs_points p;
	struct pt_set *ns;
	struct pt_range *rg;
	double *w;
	size_t k;
	int pdf, fail;

	if (pts_read(path, &p) < 0)
		return -1;
	if (check_dims(s, path, p.dims) < 0) {
		pts_free(&p);
		return -1;
	}
	if (p.n == 0) {
		pts_free(&p);
		return frs_fail("%s: no points", path);
	}
	if (pt_split(&p, path, per, &rg, &k) < 0) {
		pts_free(&p);
		return -1;
	}
	pdf = pts_column(&p, PTS_COL_PDF);
	if (pdf < 0 && p.version < 2 && p.extra > 0)
		pdf = (int)p.dims;	/* unnamed: the first extra value */
	w = split(&p, pdf, &fail);
	ns = realloc(s->set, (s->n + k) * sizeof *ns);
	if (ns != NULL)
		s->set = ns;
	if (ns == NULL || fail || keep(s, p.x) < 0) {
		free(w);
		free(rg);
		pts_free(&p);
		return frs_fail("no memory for %zu sets", s->n + k);
	}
	if (w != NULL && keep(s, w) < 0) {
		free(w);
		free(rg);
		return frs_fail("no memory for %zu sets", s->n + k);
	}
	s->dims = p.dims;
	for (size_t i = 0; i < k; i++) {
		struct pt_set *t = &s->set[s->n++];
		t->xy = p.x + (size_t)p.dims * rg[i].first;
		t->w = w ? w + rg[i].first : NULL;
		t->n = rg[i].n;
		t->dims = p.dims;
		t->file = path;
		t->first = rg[i].first;
	}
	free(rg);
	return 0;
}

void pt_sets_free(struct pt_sets *s)
{
	for (size_t i = 0; i < s->nbuf; i++)
		free(s->buf[i]);
	free(s->buf);
	free(s->set);
	s->buf = NULL, s->set = NULL;
	s->n = s->nbuf = 0;
	s->dims = 0;
}

int pt_group_parse(const char *s)
{
	static const char *const name[] = { "n", "file", "all" };

	for (int g = PT_GROUP_N; g <= PT_GROUP_ALL; g++)
		if (strcmp(s, name[g]) == 0)
			return g;
	return -1;
}

int pt_same_group(enum pt_group g, const struct pt_set *a,
    const struct pt_set *b)
{
	switch (g) {
	case PT_GROUP_N: return a->n == b->n;
	case PT_GROUP_NFILE: return a->n == b->n && a->file == b->file;
	case PT_GROUP_FILE: return a->file == b->file;
	default: return 1;
	}
}

int pt_group_files(enum pt_group g, size_t nfiles)
{
	return g == PT_GROUP_FILE || (g == PT_GROUP_NFILE && nfiles > 1);
}

void pt_put_name(FILE *fp, const char *name)
{
	for (; *name; name++)
		fputc(*name == '\t' || *name == '\n' ? '?' : *name, fp);
}
