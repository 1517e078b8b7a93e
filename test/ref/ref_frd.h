/*
 * The brute-force FRD reference (Listing 3.1 of the thesis, written from
 * the definition): every free cell sorted by (force, tie key) at every
 * step, the K-th taken, the force added to every cell within the radius
 * (double field: the documented radius and taper; int32: the authors'
 * integer table, written here from its description, at every cell).
 * O(N^2 log N); the oracle of test_frdgen and the baseline of the
 * frd-gen benchmark (ref_frd).
 */
#ifndef FRS_REF_FRD_H
#define FRS_REF_FRD_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "frd-gen/frdgen.h"
#include "base/num.h"

static uint32_t tdist(uint32_t a, uint32_t b, uint32_t n)
{
	uint32_t d = a > b ? a - b : b - a;
	return n - d < d ? n - d : d;
}

/* The radius after `inserted` values, from the rule in frdgen.h:
 * reach times the spacing, at least the neglect radius, at most cap times
 * the shortest side (but never below the neglect radius). */
static double ref_radius(const struct frdgen_params *pr, uint64_t inserted)
{
	double rtol = pr->tol <= 0 ? INFINITY : pr->force == FRDGEN_FORCE_POWER ?
	    pr->s * (pow(pr->tol, -1 / pr->q) - 1) :
	    pr->s * pow(log(1 / pr->tol), 1 / pr->q);
	double vol = (double)pr->w * pr->h * pr->d, sp, r = rtol;
	double side = fmin(pr->w, pr->dims == 3 ? fmin(pr->h, pr->d) : pr->h);
	if (pr->reach > 0) {
		sp = pr->dims == 2 ?
		    sqrt(2 * vol / (sqrt(3.0) * (double)inserted)) :
		    cbrt(sqrt(2.0) * vol / (double)inserted);
		r = fmax(r, pr->reach * sp);
	}
	if (pr->cap > 0 && r > pr->cap * side)
		r = fmax(pr->cap * side, rtol);
	return r;
}

/* The thesis authors' integer force (UTK's ForcedRandomDithering):
 * (int)(scale exp(-sqrt(2 r))), scale = min(INT_MAX / 20, 1 / f(S/2)), S
 * the shortest side. */
static double ref_int_force(const struct frdgen_params *pr, double r)
{
	uint32_t side = pr->w < pr->h ? pr->w : pr->h;
	double scale;
	if (pr->dims == 3 && pr->d < side)
		side = pr->d;
	scale = fmin(2147483647 / 20, 1.0 / exp(-sqrt(2.0 * (side / 2))));
	return (double)(int)(scale * exp(-sqrt(2.0 * r)));
}

/* (1 + r/s)^-q or exp(-(r/s)^q). */
static double ref_force(const struct frdgen_params *pr, double r)
{
	if (pr->force == FRDGEN_FORCE_POWER)
		return pow(1 + r / pr->s, -pr->q);
	return exp(-pow(r / pr->s, pr->q));
}

/* The force that the cell at squared distance d2 gets from an insertion
 * of radius r: int32 everywhere (0 where the table is); double within r,
 * less f(r) under the taper unless r reaches past the torus. */
static double ref_add(const struct frdgen_params *pr, double d2, double r,
    double rmax)
{
	double f, cut;
	if (pr->field == FRDGEN_FIELD_INT32)
		return ref_int_force(pr, sqrt(d2));
	if (!(d2 <= r * r) && r < rmax)
		return 0.0;
	f = ref_force(pr, sqrt(d2));
	cut = pr->taper && r < rmax ? ref_force(pr, r) : 0.0;
	return f - cut > 0.0 ? f - cut : 0.0;
}

struct cand {
	double f;
	uint64_t key;
	uint32_t c;
};

static int cand_cmp(const void *a, const void *b)
{
	const struct cand *x = a, *y = b;

	return x->f != y->f ? NUM_CMP(x->f, y->f) :
	    x->key != y->key ? NUM_CMP(x->key, y->key) : NUM_CMP(x->c, y->c);
}

/* Sort every free cell by (force, tie key), take the K-th, add
 * exp(-(r/s)^q) to every cell within the radius. */
static void reference(const struct frdgen_params *pr, uint32_t *out)
{
	size_t n = (size_t)pr->w * pr->h * pr->d;
	double *f = calloc(n, sizeof *f);
	unsigned char *taken = calloc(n, 1);
	struct cand *cs = malloc(n * sizeof *cs);
	double hw = pr->w / 2, hh = pr->h / 2, hd = pr->d / 2;
	double rmax = sqrt(hw * hw + hh * hh + hd * hd);

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
		if (cs[k - 1].f == 0.0) {
			/* Rank k among the cells no force has reached: the
			 * r-th of them in the documented order. */
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
			f[i] += ref_add(pr, dx * dx + dy * dy + dz * dz, r, rmax);
		}
	}
	free(f);
	free(taken);
	free(cs);
}

#endif
