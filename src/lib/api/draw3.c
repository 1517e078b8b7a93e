/*
 * 3-D sampling (frs.h's frs_sampler3): a 3-D mask over a volume, through
 * frs3.h, its samples given out as the 2-D draws give theirs (store.c);
 * and frs_sampler3_levels.
 */
#define _POSIX_C_SOURCE 200809L
#include "frs.h"

#include <stdlib.h>
#include <string.h>

#include "api/api.h"
#include "base/err.h"
#include "maps/vol.h"

int frs_sampler3_new(frs_sampler3 **sampler, const frs_mask *mask,
    const float *volume, uint32_t width, uint32_t height, uint32_t depth,
    const struct frs_options *opt, frs_error *err)
{
	struct api_values v = { .f = volume, .w = width, .h = height,
	    .depth = depth };

	return api_sampler_make(3, mask, &v, opt, NULL, sampler, err);
}

int frs_sampler3_new_f64(frs_sampler3 **sampler, const frs_mask *mask,
    const double *volume, uint32_t width, uint32_t height, uint32_t depth,
    const struct frs_options *opt, frs_error *err)
{
	struct api_values v = { .d = volume, .w = width, .h = height,
	    .depth = depth };

	return api_sampler_make(3, mask, &v, opt, NULL, sampler, err);
}

void frs_sampler3_free(frs_sampler3 *s)
{
	api_sampler_free(NULL, s);
}

int api_sampler3_prep(const frs_sampler3 *s, const struct frs3_setup *su,
    struct frs3_prep *view)
{
	return api_mask_prep3(s->mask, s->opt.algorithm == FRS_ALG_SORTED ?
	    frs3_block(su) : 0, view);
}

static enum frs_impl algo3(const frs_sampler3 *s)
{
	return s->opt.algorithm == FRS_ALG_NAIVE ? FRS_NAIVE : FRS_SORTED;
}

/* Exact counts: the levels' counts at level 0's tau, added. */
struct xcount3 {
	const frs_sampler3 *s;
	struct api_lev3 *lv;
};

static int xcount3_fn(void *ctx, double tau, uint64_t *count)
{
	struct xcount3 *x = ctx;
	struct frs_xtau xt = { .n = 1, .steps = { x->lv->su[0].n },
	    .tau = { tau } };

	*count = 0;
	api_lev3_exact(x->lv, &xt);
	for (unsigned i = 0; i < x->lv->n; i++) {
		struct frs3_setup *su = &x->lv->su[i];
		struct frs3_prep view;
		struct frs3_result r;
		if (api_sampler3_prep(x->s, su, &view) < 0 ||
		    frs3_sample(su, &x->lv->vol, &view, algo3(x->s), &su->n, 1,
		    1, &r) < 0)
			return -1;
		*count += r.count;
		frs3_result_free(&r);
	}
	return 0;
}

static int exact3(const frs_sampler3 *s, const uint64_t *steps,
    unsigned nsteps, struct api_lev3 *lv)
{
	struct xcount3 x = { s, lv };
	struct frs_xtau xt;
	double tau0[16];
	unsigned passes;

	if (frs_steps_check(steps, nsteps) < 0)
		return -1;
	for (unsigned k = 0; k < nsteps; k++)
		tau0[k] = frs3_tau(&lv->base, steps[k]);
	if (frs_exact_taus(steps, nsteps, tau0, api_lev3_most(lv), xcount3_fn,
	    &x, &xt, &passes) < 0)
		return -1;
	api_lev3_exact(lv, &xt);
	return 0;
}

int api_setup3(const frs_sampler3 *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, int exact, struct api_lev3 *lv)
{
	struct frs3_setup su;

	memset(lv, 0, sizeof *lv);
	if (frs3_setup(&su, &s->vol, &s->mask->m, steps[nsteps - 1],
	    s->opt.sigma, seed) < 0)
		return -1;
	API_MODES(&su, &s->opt);
	if (api_lev3_make(&s->opt, &su, &s->vol, (struct api_plan *)&s->plan,
	    lv) < 0)
		return -1;
	if (exact && s->opt.rule == FRS_RULE_EXACT &&
	    exact3(s, steps, nsteps, lv) < 0) {
		api_lev3_free(lv);
		return -1;
	}
	return 0;
}

static int run3(const void *vs, const uint64_t *steps, unsigned nsteps,
    uint64_t seed, int count_only, struct api_store *st, frs_error *err)
{
	const frs_sampler3 *s = vs;
	struct api_lev3 *lv;
	int rc;

	memset(st, 0, sizeof *st);
	if ((rc = api_run_begin(s != NULL, s != NULL ? s->opt.threads : 0,
	    steps, nsteps, err)) != FRS_OK)
		return rc;
	if ((lv = malloc(sizeof *lv)) == NULL)
		return api_nomem(err);
	if (api_setup3(s, steps, nsteps, seed, 1, lv) < 0) {
		free(lv);
		return api_lib_err(err, FRS_E_LIMIT);
	}
	st->lv3 = lv;
	for (unsigned i = 0; i < lv->n; i++) {
		struct frs3_prep view;
		if (api_sampler3_prep(s, &lv->su[i], &view) < 0)
			rc = api_lib_err(err, FRS_E_FORMAT);
		else if (frs3_sample(&lv->su[i], &lv->vol, &view, algo3(s),
		    steps, nsteps, count_only, &st->r3[i]) < 0)
			rc = api_lib_err(err, FRS_E_LIMIT);
		if (rc != FRS_OK) {
			api_store_set(st, 3, nsteps, i);
			api_store_free(st);
			return rc;
		}
	}
	api_store_set(st, 3, nsteps, lv->n);
	return FRS_OK;
}

int frs_draw3_progressive(const frs_sampler3 *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, double *xyz, double *pdf,
    uint32_t *step, size_t cap, size_t *count, frs_error *err)
{
	return api_draw(run3, s, "frs_draw3", steps, nsteps, seed, xyz, pdf,
	    step, cap, count, err);
}

int frs_draw3(const frs_sampler3 *s, uint64_t n, uint64_t seed, double *xyz,
    double *pdf, size_t cap, size_t *count, frs_error *err)
{
	return frs_draw3_progressive(s, &n, 1, seed, xyz, pdf, NULL, cap, count,
	    err);
}

int frs_count3(const frs_sampler3 *s, uint64_t n, uint64_t seed,
    uint64_t *count, frs_error *err)
{
	return api_count(run3, s, "frs_count3", n, seed, count, err);
}

int frs_draw3_each(const frs_sampler3 *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, int want_pdf, frs_point_fn fn,
    void *ctx, frs_error *err)
{
	return api_each(run3, s, "frs_draw3_each", steps, nsteps, seed,
	    want_pdf, fn, ctx, err);
}

int frs_sampler3_levels(const frs_sampler3 *s, uint64_t n, uint64_t seed,
    struct frs_level_info *levels, unsigned cap, unsigned *count,
    frs_error *err)
{
	struct api_lev3 lv;
	int rc;

	if (count != NULL)
		*count = 0;
	if ((rc = api_query_args("frs_sampler3_levels", s != NULL &&
	    count != NULL && (levels != NULL || cap == 0), n, s ? s->opt.threads :
	    0, err)) != FRS_OK)
		return rc;
	if (api_setup3(s, &n, 1, seed, 1, &lv) < 0)
		return api_lib_err(err, FRS_E_LIMIT);
	for (unsigned i = 0; i < lv.n && i < cap; i++) {
		const struct frs3_setup *su = &lv.su[i];
		levels[i] = (struct frs_level_info){ su->level, su->ns,
		    { su->sw, su->sh, su->sd }, { su->wx, su->wy, su->wz },
		    lv.plan.lev != NULL ? lv.plan.cells[su->level] :
		    frs_exact_most(lv.vol.v, (uint64_t)su->iw * su->ih * su->id,
		    1, 3), su->tau };
	}
	*count = lv.n;
	api_lev3_free(&lv);
	return api_ok(err);
}
