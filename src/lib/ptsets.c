#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>

#include "err.h"
#include "ptsets.h"
#include "ptsio.h"

int pt_sets_add(struct pt_sets *s, const char *path, size_t per)
{
	struct frs_points p;
	struct pt_set *ns;
	double **nb;
	size_t k, stride;

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
	stride = 2 + p.extra;
	for (size_t i = 0; p.extra && i < p.n; i++)
		p.x[2 * i] = p.x[stride * i],
		p.x[2 * i + 1] = p.x[stride * i + 1];
	k = per ? p.n / per : 1;
	per = per ? per : p.n;
	ns = realloc(s->set, (s->n + k) * sizeof *ns);
	if (ns != NULL)
		s->set = ns;
	nb = realloc(s->buf, (s->nbuf + 1) * sizeof *nb);
	if (nb != NULL)
		s->buf = nb;
	if (ns == NULL || nb == NULL) {
		pts_free(&p);
		return frs_fail("no memory for %zu sets", s->n + k);
	}
	s->buf[s->nbuf++] = p.x;
	for (size_t i = 0; i < k; i++) {
		struct pt_set *t = &s->set[s->n++];
		t->xy = p.x + 2 * per * i;
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
