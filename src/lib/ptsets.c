#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>

#include "err.h"
#include "ptsets.h"
#include "ptsio.h"

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

/* The first extra column into an array of its own, and the dims
 * coordinates of each point packed. */
static double *split(struct frs_points *p)
{
	size_t d = p->dims, stride = d + p->extra;
	double *w = NULL;

	if (p->extra && (w = malloc(p->n * sizeof *w)) == NULL)
		return NULL;
	for (size_t i = 0; p->extra && i < p->n; i++) {
		w[i] = p->x[stride * i + d];
		/* forward: the target never overtakes the source */
		memmove(&p->x[d * i], &p->x[stride * i], d * sizeof *p->x);
	}
	return w;
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
	double *w;
	size_t k;

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
	if (per && p.n % per != 0) {
		size_t cnt = p.n;
		pts_free(&p);
		return frs_fail("%s: %zu points are not a whole number of sets "
		    "of %zu", path, cnt, per);
	}
	w = split(&p);
	k = per ? p.n / per : 1;
	per = per ? per : p.n;
	ns = realloc(s->set, (s->n + k) * sizeof *ns);
	if (ns != NULL)
		s->set = ns;
	if (ns == NULL || (p.extra && w == NULL) || keep(s, p.x) < 0) {
		free(w);
		pts_free(&p);
		return frs_fail("no memory for %zu sets", s->n + k);
	}
	if (w != NULL && keep(s, w) < 0) {
		free(w);
		return frs_fail("no memory for %zu sets", s->n + k);
	}
	s->dims = p.dims;
	for (size_t i = 0; i < k; i++) {
		struct pt_set *t = &s->set[s->n++];
		t->xy = p.x + (size_t)p.dims * per * i;
		t->w = w ? w + per * i : NULL;
		t->n = per;
		t->dims = p.dims;
		t->file = path;
	}
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
	case PT_GROUP_FILE: return a->file == b->file;
	default: return 1;
	}
}
