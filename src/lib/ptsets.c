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

/* The first extra column into an array of its own, and x y packed. */
static double *split(struct frs_points *p)
{
	size_t stride = 2 + p->extra;
	double *w = NULL;

	if (p->extra && (w = malloc(p->n * sizeof *w)) == NULL)
		return NULL;
	for (size_t i = 0; p->extra && i < p->n; i++) {
		w[i] = p->x[stride * i + 2];
		p->x[2 * i] = p->x[stride * i],
		p->x[2 * i + 1] = p->x[stride * i + 1];
	}
	return w;
}

int pt_sets_add(struct pt_sets *s, const char *path, size_t per)
{
	struct frs_points p;
	struct pt_set *ns;
	double *w;
	size_t k;

	if (pts_read(path, &p) < 0)
		return -1;
	if (p.dims != 2) {
		unsigned dims = p.dims;
		pts_free(&p);
		return frs_fail("%s: %u-dimensional points; 2 are needed", path,
		    dims);
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
	for (size_t i = 0; i < k; i++) {
		struct pt_set *t = &s->set[s->n++];
		t->xy = p.x + 2 * per * i;
		t->w = w ? w + per * i : NULL;
		t->n = per;
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
