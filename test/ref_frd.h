/*
 * The brute-force FRD reference (Listing 3.1 of the thesis, written from
 * the definition): every free cell sorted by (force, tie key) at every
 * step, the K-th taken, the force added to every cell within the radius.
 * O(N^2 log N); the oracle of test_frdgen and the baseline of the
 * frd-gen benchmark (ref_frd).
 */
#ifndef FRS_REF_FRD_H
#define FRS_REF_FRD_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "frdgen.h"

static uint32_t tdist(uint32_t a, uint32_t b, uint32_t n)
{
	uint32_t d = a > b ? a - b : b - a;
	return n - d < d ? n - d : d;
}

/* The radius after `inserted` values, from the rule in frdgen.h. */
static double ref_radius(const struct frdgen_params *pr, uint64_t inserted)
{
	double r = pr->tol > 0 ? pr->s * pow(log(1 / pr->tol), 1 / pr->q) :
	    INFINITY;
	double vol = (double)pr->w * pr->h * pr->d, sp;
	if (pr->reach > 0) {
		sp = pr->dims == 2 ? sqrt(2 * vol / (sqrt(3.0) * inserted)) :
		    cbrt(sqrt(2.0) * vol / inserted);
		r = fmax(r, pr->reach * sp);
	}
	return r;
}

struct cand {
	double f;
	uint64_t key;
	uint32_t c;
};

static int cand_cmp(const void *a, const void *b)
{
	const struct cand *x = a, *y = b;
	if (x->f != y->f)
		return x->f < y->f ? -1 : 1;
	if (x->key != y->key)
		return x->key < y->key ? -1 : 1;
	return x->c < y->c ? -1 : x->c > y->c;
}

/* Sort every free cell by (force, tie key), take the K-th, add
 * exp(-(r/s)^q) to every cell within the radius. */
static void reference(const struct frdgen_params *pr, uint32_t *out)
{
	size_t n = (size_t)pr->w * pr->h * pr->d;
	double *f = calloc(n, sizeof *f);
	unsigned char *taken = calloc(n, 1);
	struct cand *cs = malloc(n * sizeof *cs);

	for (uint64_t step = 0; step < n; step++) {
		size_t nc = 0;
		uint64_t k = frdgen_rank(pr, step, n - step);
		uint32_t c, cx, cy, cz;
		double r;
		for (uint32_t i = 0; i < n; i++)
			if (!taken[i])
				cs[nc++] = (struct cand){ f[i],
				    frdgen_tiekey(pr, step, i), i };
		qsort(cs, nc, sizeof *cs, cand_cmp);
		c = cs[k - 1].c;
		if (cs[0].f == 0.0) {
			/* Cells no force has reached: the r-th of them in the
			 * documented order. */
			uint64_t z = 0, zr;
			for (size_t i = 0; i < nc && cs[i].f == 0.0; i++)
				z++;
			zr = frdgen_zerorank(pr, step, z);
			for (size_t i = 0; i < z; i++)
				cs[i].key = frdgen_cellorder(pr, cs[i].c);
			qsort(cs, z, sizeof *cs, cand_cmp);
			c = cs[zr].c;
		}
		out[c] = (uint32_t)step;
		taken[c] = 1;
		cx = c % pr->w;
		cy = c / pr->w % pr->h;
		cz = c / pr->w / pr->h;
		r = ref_radius(pr, step + 1);
		for (uint32_t i = 0; i < n; i++) {
			double dx = tdist(i % pr->w, cx, pr->w);
			double dy = tdist(i / pr->w % pr->h, cy, pr->h);
			double dz = tdist(i / pr->w / pr->h, cz, pr->d);
			double d2 = dx * dx + dy * dy + dz * dz;
			if (d2 <= r * r)
				f[i] += exp(-pow(sqrt(d2) / pr->s, pr->q));
		}
	}
	free(f);
	free(taken);
	free(cs);
}

#endif
