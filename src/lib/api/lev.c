/*
 * The levels of a run (sample/levels.h): from level 0's setup, the
 * setup and the masked map of every level that has cells, 2-D and 3-D,
 * and the block of a level's sorted lists.  Below the draws (draw.c,
 * draw3.c), which set runs up and report their levels
 * (frs_sampler_levels): no module of api/ calls back into one above it
 * (t_layout).
 */
#define _POSIX_C_SOURCE 200809L
#include "frs.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/api.h"
#include "base/err.h"
#include "base/mem.h"
#include "base/num.h"
#include "base/par.h"

void api_lev2_free(struct api_lev2 *lv)
{
	frs_levels_free(&lv->plan);
	memset(lv, 0, sizeof *lv);
}

void api_lev3_free(struct api_lev3 *lv)
{
	frs_levels_free(&lv->plan);
	memset(lv, 0, sizeof *lv);
}

int api_plan_init(struct api_plan *c)
{
	memset(c, 0, sizeof *c);
	if (pthread_mutex_init(&c->lock, NULL) != 0)
		return frs_fail("cannot make a lock");
	return 0;
}

void api_plan_free(struct api_plan *c)
{
	frs_levels_free(&c->plan);
	pthread_mutex_destroy(&c->lock);
}

/* A copy of the plan a (its levels' array made anew) into b. */
static int plan_copy(struct frs_levels *b, const struct frs_levels *a)
{
	uint64_t n = (uint64_t)a->side[0] * a->side[1] * a->side[2];

	*b = *a;
	if (a->lev == NULL)
		return 0;
	if ((b->lev = mem_calloc("levels", n, 1)) == NULL)
		return -1;
	memcpy(b->lev, a->lev, n);
	return 0;
}

/* The plan of key (t0, ns) from the cache into L and max: 1 when it was
 * there, 0 when not, -1 after frs_fail. */
static int cache_get(struct api_plan *c, double t0, uint32_t ns,
    struct frs_levels *L)
{
	int rc = 0;

	if (c == NULL)
		return 0;
	pthread_mutex_lock(&c->lock);
	if (c->valid && c->t0 == t0 && c->ns == ns) {
		rc = plan_copy(L, &c->plan) < 0 ? -1 : 1;
	}
	pthread_mutex_unlock(&c->lock);
	return rc;
}

/* Keep a copy of the plan L of key (t0, ns) in the cache (when there is
 * no room, it is only not kept). */
static void cache_put(struct api_plan *c, double t0, uint32_t ns,
    const struct frs_levels *L)
{
	struct frs_levels copy;

	if (c == NULL || plan_copy(&copy, L) < 0) {
		frs_clearerr();
		return;
	}
	pthread_mutex_lock(&c->lock);
	if (c->valid)	/* the plan of another key */
		frs_levels_free(&c->plan);
	c->plan = copy;
	c->t0 = t0;
	c->ns = ns;
	c->valid = 1;
	pthread_mutex_unlock(&c->lock);
}

/*
 * The plan of the cells v (sides side, dims of them) for level 0's
 * threshold scale t0, n_s, matrix elements nm and sigma under the
 * options o, into L (from the cache when it has it).  The number of
 * levels that have cells; 0
 * for one level (no levels asked, or every cell at level 0), with
 * nothing kept; -1 after frs_fail.
 */
/*
 * The coarsest level a run needs: the finest at which the window of the
 * whole map (volume) fits the matrix (msize) on every axis, so that no
 * level repeats the matrix; top (one element a cell) when the map is
 * larger than the matrix.  Coarser levels would only add seams: at this
 * one a dark region takes the matrix's first values over one tile, a
 * prefix of the matrix, which is blue noise.  0: the thesis's window
 * repeats nothing, and one level is all.
 */
static unsigned fit_level(unsigned dims, const uint32_t *side,
    const uint32_t *msize, uint32_t ns)
{
	unsigned l = 0, top = num_log2_ceil(ns);

	for (; l < top; l++) {
		int fits = 1;
		for (unsigned a = 0; a < dims; a++)
			fits &= (uint64_t)(ns >> l) * side[a] <= msize[a];
		if (fits)
			break;
	}
	return l;
}

/* The smoothing of the levels in cells, or -1 without levels (plain or
 * shuffled tiles): the options', or an eighth of the longest side of the
 * map or volume, so that the levels do not depend on its resolution. */
static double blur_of(const struct frs_options *o, uint32_t longest)
{
	return o->tiling != FRS_TILING_LEVELS ? -1.0 :
	    o->level_blur > 0.0 ? o->level_blur : (double)longest / 8.0;
}

static int plan_levels(const struct frs_options *o, unsigned dims,
    const uint32_t *side, const uint32_t *msize, const double *v,
    double t0, uint32_t ns, double sigma, struct api_plan *cache,
    struct frs_levels *L)
{
	uint32_t longest = side[0];
	unsigned top = fit_level(dims, side, msize, ns);
	double blur, nm = (double)msize[0] * msize[1] * (dims == 3 ? msize[2] : 1);
	int rc;

	for (unsigned a = 1; a < dims; a++)
		longest = side[a] > longest ? side[a] : longest;
	blur = blur_of(o, longest);
	if (blur < 0.0 || top == 0)
		return 0;
	if ((rc = cache_get(cache, t0, ns, L)) < 0)
		return -1;
	if (rc == 0) {
		if (frs_levels_plan(L, dims, side, v, t0, top, nm, sigma,
		    blur) < 0)
			return -1;
		cache_put(cache, t0, ns, L);
	}
	/* One level, level 0's: the thesis's window, no plan (lev NULL). */
	if (frs_levels_used(L) == 0 || (frs_levels_used(L) == 1 &&
	    L->cells[0] > 0)) {
		frs_levels_free(L);
		return 0;
	}
	return (int)frs_levels_used(L);
}

/*
 * Sorted's lists for the levels of a multi-level run: one block size b
 * for all the levels that read lists (made once, a read of the matrix,
 * then read by every level whose n_s b divides), chosen with the levels
 * that read them to cost least by this model, in nanoseconds measured on
 * a 2-core x86-64 (forest.exr, 2^16 and 2^20 samples):
 *   making lists:   1.5 a matrix element and 5 a value they hold
 *                   (the largest threshold of the levels reading them);
 *   reading lists:  25 a block of every pixel, 2 a sample;
 *   scanning:       0.5 an element (n_s up to FRS_SCAN_NS);
 *   walking:        5 a start block (8 x 8), 130 a sample.
 * A level's samples: each level-0 element of a cell of value v expects
 * t0 v / S_M of them, n_s0^2 elements a cell.
 */
static double walk_cost(double ns, double cells, double samples)
{
	return ns <= FRS_SCAN_NS ? 0.5 * cells * ns * ns :
	    5.0 * cells * (ns / 8.0) * (ns / 8.0) + 130.0 * samples;
}

static double read_cost(double ns, double b, double cells, double samples)
{
	return 25.0 * cells * (ns / b) * (ns / b) + 2.0 * samples;
}

/* The cost of the run with lists of block b (0: none) into *cost, and
 * the levels that read them into use. */
static void cost_of(const struct api_lev2 *lv, uint32_t b, double *cost,
    int *use)
{
	const struct frs_setup *b0 = &lv->base;
	double nm = (double)b0->mw * b0->mh, ns0 = b0->ns, below = 0.0;
	int any = 0;

	*cost = 0.0;
	for (unsigned i = 0; i < lv->n; i++) {
		const struct frs_setup *su = &lv->su[i];
		double cells = (double)lv->plan.cells[su->level], ns = su->ns;
		double samples = b0->tau * b0->iscale * ns0 * ns0 *
		    lv->plan.sum[su->level] / nm;
		double w = walk_cost(ns, cells, samples), r;
		use[i] = b != 0 && su->ns >= b &&
		    (r = read_cost(ns, b, cells, samples)) < w;
		*cost += use[i] ? r : w;
		if (use[i]) {
			double lim = (double)frs_lim_most(su, su->tau);
			below = lim > below ? lim : below;
			any = 1;
		}
	}
	if (any)
		*cost += 1.5 * nm + 5.0 * (below < nm ? below : nm);
}

/* The block of each level's lists into lv->block: the cheapest of none
 * and the powers of two from 8 to the matrix's side. */
static void choose_blocks(struct api_lev2 *lv)
{
	uint32_t m = lv->base.mw < lv->base.mh ? lv->base.mw : lv->base.mh;
	int use[FRS_LEVELS_MAX], best_use[FRS_LEVELS_MAX];
	double cost, best;
	uint32_t bb = 0;

	cost_of(lv, 0, &best, best_use);
	for (uint32_t b = 8; b <= m; b *= 2) {
		cost_of(lv, b, &cost, use);
		if (cost < best) {
			best = cost;
			bb = b;
			memcpy(best_use, use, sizeof use);
		}
	}
	for (unsigned i = 0; i < lv->n; i++)
		lv->block[i] = best_use[i] ? bb : 0;
}

/*
 * The setups of the levels of plan L that have cells, into lv->su, of
 * level 0's s0 (2-D and 3-D alike, level_setup their maker): s0 alone
 * without a plan (one level); else level 0 is s0 with the largest value
 * of its cells, and each level reads the cells of its level, within the
 * slices (rows of pixels, planes of voxels) of axis ax that its cells
 * span, slice cells apart.  A macro, as the setups are of two types
 * (type).
 */
#define LEVEL_SETUPS(lv, s0, type, level_setup, ax, slice) do {	\
	if ((lv)->plan.lev == NULL) {					\
		(lv)->su[0] = *(s0);					\
		(lv)->n = 1;						\
		break;							\
	}								\
	for (unsigned l_ = 0; l_ <= (lv)->plan.top; l_++) {		\
		type *su_ = &(lv)->su[(lv)->n];				\
		if ((lv)->plan.cells[l_] == 0)				\
			continue;					\
		if (l_ == 0) {						\
			*su_ = *(s0);					\
			su_->max = (lv)->plan.max[0];			\
		} else {						\
			level_setup(su_, (s0), l_, (lv)->plan.max[l_]);	\
		}							\
		su_->lev = (lv)->plan.lev;				\
		su_->cell0 = (uint64_t)(lv)->plan.lo[l_][ax] * (slice);	\
		su_->cell1 = (uint64_t)((lv)->plan.hi[l_][ax] + 1) *	\
		    (slice);						\
		(lv)->n++;						\
	}								\
} while (0)

int api_lev2_make(const struct frs_options *o, const struct frs_setup *s0,
    const struct frs_imap *map, struct api_plan *cache, struct api_lev2 *lv)
{
	const uint32_t side[2] = { map->w, map->h }, msize[2] = { s0->mw, s0->mh };

	memset(lv, 0, sizeof *lv);
	lv->base = *s0;
	lv->map = *map;
	if (plan_levels(o, 2, side, msize, map->v, s0->tau * s0->iscale,
	    s0->ns, s0->sigma, cache, &lv->plan) < 0)
		return -1;
	LEVEL_SETUPS(lv, s0, struct frs_setup, frs_level_setup, 1, map->w);
	if (lv->plan.lev != NULL)
		choose_blocks(lv);
	return 0;
}

int api_lev3_make(const struct frs_options *o, const struct frs3_setup *s0,
    const struct frs_vol *vol, struct api_plan *cache, struct api_lev3 *lv)
{
	const uint32_t side[3] = { vol->w, vol->h, vol->d };
	const uint32_t msize[3] = { s0->mw, s0->mh, s0->md };

	memset(lv, 0, sizeof *lv);
	lv->base = *s0;
	lv->vol = *vol;
	if (plan_levels(o, 3, side, msize, vol->v, s0->tau * s0->iscale,
	    s0->ns, s0->sigma, cache, &lv->plan) < 0)
		return -1;
	LEVEL_SETUPS(lv, s0, struct frs3_setup, frs3_level_setup, 2,
	    (uint64_t)vol->w * vol->h);
	return 0;
}

/* most and the window elements of the cells of level l of plan L, n_s
 * a cell side in dims dimensions: at most UINT64_MAX. */
static uint64_t add_most(uint64_t most, const struct frs_levels *L,
    unsigned l, uint64_t ns, unsigned dims)
{
	uint64_t e = L->cells[l] * ns * ns * (dims == 3 ? ns : 1);

	return e > UINT64_MAX - most ? UINT64_MAX : most + e;
}

uint64_t api_lev2_most(const struct api_lev2 *lv)
{
	uint64_t most = 0;

	if (lv->plan.lev == NULL)
		return frs_exact_most(lv->map.v, (uint64_t)lv->map.w *
		    lv->map.h, lv->su[0].ns, 2);
	for (unsigned i = 0; i < lv->n; i++)
		most = add_most(most, &lv->plan, lv->su[i].level, lv->su[i].ns, 2);
	return most;
}

uint64_t api_lev3_most(const struct api_lev3 *lv)
{
	uint64_t most = 0;

	if (lv->plan.lev == NULL)
		return frs_exact_most(lv->vol.v, (uint64_t)lv->vol.w *
		    lv->vol.h * lv->vol.d, lv->su[0].ns, 3);
	for (unsigned i = 0; i < lv->n; i++)
		most = add_most(most, &lv->plan, lv->su[i].level, lv->su[i].ns, 3);
	return most;
}

/* The exact count's taus x into level 0's setup and every level's
 * (tau_of: frs_tau or frs3_tau). */
#define LEVEL_EXACT(lv, x, tau_of) do {				\
	(lv)->base.exact = *(x);					\
	(lv)->base.tau = tau_of(&(lv)->base, (lv)->base.n);		\
	for (unsigned i_ = 0; i_ < (lv)->n; i_++) {			\
		(lv)->su[i_].exact = *(x);				\
		(lv)->su[i_].tau = tau_of(&(lv)->su[i_], (lv)->su[i_].n);	\
	}								\
} while (0)

void api_lev3_exact(struct api_lev3 *lv, const struct frs_xtau *x)
{
	LEVEL_EXACT(lv, x, frs3_tau);
}

uint32_t api_sorted_block(const struct frs_setup *su)
{
	uint32_t b = su->ns < su->mw ? su->ns : su->mw, t = frs_tile_max_block(su);
	b = b < su->mh ? b : su->mh;
	return b < t ? b : t;
}

uint64_t api_lists_below(const struct frs_setup *su, const uint64_t *steps,
    unsigned nsteps)
{
	return frs_lim_most(su, frs_tau(su, steps[nsteps - 1]));
}

uint32_t api_lev2_block(const struct api_lev2 *lv, unsigned i)
{
	return lv->plan.lev == NULL ? api_sorted_block(&lv->su[i]) :
	    lv->block[i];
}

uint64_t api_lev2_below(const struct api_lev2 *lv, const uint64_t *steps,
    unsigned nsteps, double margin)
{
	uint64_t most = 0;

	for (unsigned i = 0; i < lv->n; i++) {
		const struct frs_setup *su = &lv->su[i];
		uint64_t b;
		if (api_lev2_block(lv, i) == 0)
			continue;
		b = frs_lim_most(su, margin * frs_tau(su, steps[nsteps - 1]));
		most = b > most ? b : most;
	}
	return most;
}

void api_lev2_exact(struct api_lev2 *lv, const struct frs_xtau *x)
{
	LEVEL_EXACT(lv, x, frs_tau);
}
