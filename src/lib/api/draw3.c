/*
 * 3-D sampling (frs.h's frs_sampler3): a 3-D mask over a volume, through
 * frs3.h, its samples given out as the 2-D draws give theirs (store.c).
 */
#define _POSIX_C_SOURCE 200809L
#include "frs.h"

#include "api/api.h"
#include "base/err.h"
#include "maps/vol.h"

int frs_sampler3_new(frs_sampler3 **sampler, const frs_mask *mask,
    const float *volume, uint32_t width, uint32_t height, uint32_t depth,
    const struct frs_options *opt, frs_error *err)
{
	struct api_values v = { volume, NULL, width, height, depth, 0 };

	return api_sampler_make(3, mask, &v, opt, NULL, sampler, err);
}

int frs_sampler3_new_f64(frs_sampler3 **sampler, const frs_mask *mask,
    const double *volume, uint32_t width, uint32_t height, uint32_t depth,
    const struct frs_options *opt, frs_error *err)
{
	struct api_values v = { NULL, volume, width, height, depth, 0 };

	return api_sampler_make(3, mask, &v, opt, NULL, sampler, err);
}

void frs_sampler3_free(frs_sampler3 *s)
{
	api_sampler_free(NULL, s);
}

int api_setup3(const frs_sampler3 *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, const struct frs3_prep *view,
    struct frs3_setup *su)
{
	if (frs3_setup(su, &s->vol, &s->mask->m, steps[nsteps - 1],
	    s->opt.sigma, seed) < 0)
		return -1;
	su->rule = api_rule(&s->opt);
	su->jitter = api_jitter(&s->opt);
	su->tiles = api_tiling(&s->opt, frs3_tiles_auto(su));
	if (view != NULL && s->opt.rule == FRS_RULE_EXACT)
		return frs3_exact(su, &s->vol, view, steps, nsteps);
	return 0;
}

int api_sampler3_prep(const frs_sampler3 *s, const struct frs3_setup *su,
    struct frs3_prep *view)
{
	return api_mask_prep3(s->mask, s->opt.algorithm == FRS_ALG_SORTED ?
	    frs3_block(su) : 0, view);
}

static int run3(const void *vs, const uint64_t *steps, unsigned nsteps,
    uint64_t seed, int count_only, struct api_store *st, frs_error *err)
{
	const frs_sampler3 *s = vs;
	struct frs3_setup *su = &st->u.d3.su;
	struct frs3_prep view;
	int rc;

	if ((rc = api_run_begin(s != NULL, s != NULL ? s->opt.threads : 0,
	    steps, nsteps, err)) != FRS_OK)
		return rc;
	if (api_setup3(s, steps, nsteps, seed, NULL, su) < 0)
		return api_lib_err(err, FRS_E_LIMIT);
	if (api_sampler3_prep(s, su, &view) < 0)
		return api_lib_err(err, FRS_E_FORMAT);
	if (s->opt.rule == FRS_RULE_EXACT &&
	    frs3_exact(su, &s->vol, &view, steps, nsteps) < 0)
		return api_lib_err(err, FRS_E_LIMIT);
	if (frs3_sample(su, &s->vol, &view, s->opt.algorithm == FRS_ALG_NAIVE ?
	    FRS_NAIVE : FRS_SORTED, steps, nsteps, count_only,
	    &st->u.d3.r) < 0)
		return api_lib_err(err, FRS_E_LIMIT);
	st->u.d3.vol = &s->vol;
	api_store_set(st, 3, nsteps);
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

int api_draw3_each(const frs_sampler3 *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, int want_pdf, frs_point_fn fn,
    void *ctx, frs_error *err)
{
	return api_each(run3, s, "frs_draw3_each", steps, nsteps, seed,
	    want_pdf, fn, ctx, err);
}
