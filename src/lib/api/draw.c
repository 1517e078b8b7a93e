/*
 * 2-D sampling (frs.h's frs_sampler): the setup of a run, the mask
 * prepared for it, the thresholding on the CPU or an OpenCL device, and
 * Sorted's direct path for one step, which converts each chunk where it
 * was made.
 */
#define _POSIX_C_SOURCE 200809L
#include "frs.h"

#include <stdlib.h>

#include "api/api.h"
#include "base/err.h"
#include "base/par.h"
#include "maps/imap.h"
#include "sample/frscl.h"

int frs_sampler_new(frs_sampler **sampler, const frs_mask *mask,
    const float *map, uint32_t width, uint32_t height, size_t stride,
    const struct frs_options *opt, frs_error *err)
{
	struct api_values v = { map, NULL, width, height, 0, stride };

	return api_sampler_make(2, mask, &v, opt, sampler, NULL, err);
}

int frs_sampler_new_f64(frs_sampler **sampler, const frs_mask *mask,
    const double *map, uint32_t width, uint32_t height, size_t stride,
    const struct frs_options *opt, frs_error *err)
{
	struct api_values v = { NULL, map, width, height, 0, stride };

	return api_sampler_make(2, mask, &v, opt, sampler, NULL, err);
}

void frs_sampler_free(frs_sampler *s)
{
	api_sampler_free(s, NULL);
}

void api_sampler_device(frs_sampler *s, struct ocl *ocl, int alg)
{
	s->ocl = ocl;
	s->algo = api_algo(alg);
}

int api_setup(const frs_sampler *s, uint64_t n, uint64_t seed,
    struct frs_setup *su)
{
	if (frs_setup(su, &s->map, &s->mask->m, n, s->opt.sigma, seed) < 0)
		return -1;
	su->rule = api_rule(&s->opt);
	su->jitter = api_jitter(&s->opt);
	su->tiles = api_tiling(&s->opt, frs_tiles_auto(su));
	return 0;
}

/* The exact counts' passes: Sorted's count of the window at any tau,
 * with lists for a little more than the largest tau asked so far (the
 * passes around one tau need one list making). */
struct xcount {
	const frs_sampler *s;
	struct frs_setup su;
	int minmap, have;
	uint32_t block;
	struct frs_prep view;
};

static int xcount_fn(void *ctx, double tau, uint64_t *count)
{
	struct xcount *x = ctx;
	struct frs_result r;

	if (!x->have || x->view.below < frs_lim_most(&x->su, tau)) {
		if (api_mask_prep(x->s->mask, x->minmap, x->block,
		    frs_lim_most(&x->su, tau * 1.0625), &x->view) < 0)
			return -1;
		x->have = 1;
	}
	x->su.exact = (struct frs_xtau){ .n = 1, .steps = { x->su.n },
	    .tau = { tau } };
	if (frs_sample(&x->su, &x->s->map, &x->view, FRS_SORTED, &x->su.n, 1,
	    1, &r) < 0)
		return -1;
	*count = r.count;
	frs_result_free(&r);
	return 0;
}

int api_exact(const frs_sampler *s, const uint64_t *steps, unsigned nsteps,
    struct frs_setup *su)
{
	struct xcount x = { s, *su, api_sorted_minmap(su), 0,
	    api_sorted_block(su), { 0 } };
	double tau0[16];
	unsigned passes;

	if (frs_steps_check(steps, nsteps) < 0)
		return -1;
	for (unsigned k = 0; k < nsteps; k++)
		tau0[k] = frs_tau(su, steps[k]);
	if (frs_exact_taus(steps, nsteps, tau0, frs_exact_most(s->map.v,
	    (uint64_t)s->map.w * s->map.h, su->ns, 2), xcount_fn, &x,
	    &su->exact, &passes) < 0)
		return -1;
	su->tau = frs_tau(su, su->n);
	return 0;
}

int api_setup_steps(const frs_sampler *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, struct frs_setup *su)
{
	if (api_setup(s, steps[nsteps - 1], seed, su) < 0)
		return -1;
	if (s->opt.rule == FRS_RULE_EXACT)
		return api_exact(s, steps, nsteps, su);
	return 0;
}

/* Stack, Level 1, Level 2 and Flat 1 walk the minmap; Sorted takes its
 * lists, and the minmap too when its blocks are smaller than a pixel. */
int api_sampler_prep(const frs_sampler *s, const struct frs_setup *su,
    const uint64_t *steps, unsigned nsteps, struct frs_prep *view)
{
	int sorted = s->algo == FRS_SORTED;
	int minmap = sorted ? api_sorted_minmap(su) : s->algo != FRS_NAIVE;

	return api_mask_prep(s->mask, minmap, sorted ? api_sorted_block(su) : 0,
	    sorted ? api_lists_below(su, steps, nsteps) : 0, view);
}

/* The setup and prepared matrix of a run for steps with this seed, and
 * the sampler's thread count set.  A code. */
static int begin_run(const frs_sampler *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, struct frs_setup *su,
    struct frs_prep *view, frs_error *err)
{
	int rc = api_run_begin(s != NULL, s != NULL ? s->opt.threads : 0, steps,
	    nsteps, err);

	if (rc != FRS_OK)
		return rc;
	if (api_setup_steps(s, steps, nsteps, seed, su) < 0)
		return api_lib_err(err, FRS_E_LIMIT);
	if (api_sampler_prep(s, su, steps, nsteps, view) < 0)
		return api_lib_err(err, FRS_E_FORMAT);
	return FRS_OK;
}

/* Threshold the window for steps with this seed, on the sampler's device
 * or the CPU, into st.  A code. */
static int run(const void *vs, const uint64_t *steps, unsigned nsteps,
    uint64_t seed, int count_only, struct api_store *st, frs_error *err)
{
	const frs_sampler *s = vs;
	struct frs_setup *su = &st->u.d2.su;
	struct frs_result *r = &st->u.d2.r;
	struct frs_prep view;
	int rc = begin_run(s, steps, nsteps, seed, su, &view, err);

	if (rc != FRS_OK)
		return rc;
	if ((s->ocl != NULL ? frs_sample_cl(s->ocl, su, &s->map, &view,
	    s->algo, steps, nsteps, count_only, r) : frs_sample(su, &s->map,
	    &view, (enum frs_impl)s->algo, steps, nsteps, count_only, r)) < 0)
		return api_lib_err(err, FRS_E_LIMIT);
	st->u.d2.map = &s->map;
	api_store_set(st, 2, nsteps);
	return FRS_OK;
}

/*
 * Sorted, one step: the samples go straight from the thresholding to
 * their place, each chunk converted by the thread that made it, with no
 * store of the whole run.  A count first (Sorted counts a block by one
 * bisection, a few milliseconds for 2^24 samples) places every chunk.
 */
struct direct {
	const struct frs_setup *su;
	const struct frs_imap *map;
	const uint64_t *at;	/* chunk c's first sample */
	uint64_t base;		/* the sample at xy[0] */
	double *xy, *pdf;
};

static int direct_chunk(void *ctx, uint64_t ci, const struct frs_chunk *c)
{
	const struct direct *d = ctx;
	uint64_t o = d->at[ci] - d->base, want = d->at[ci + 1] - d->at[ci];

	if (c->n != want)
		return frs_fail("internal error: chunk %llu has %llu samples, "
		    "its count said %llu", (unsigned long long)ci,
		    (unsigned long long)c->n, (unsigned long long)want);
	if (c->n == 0 || c->xy != NULL)	/* none, or made in place */
		return 0;
	frs_points(d->su, c->e, (size_t)c->n, d->xy + 2 * o);
	for (uint64_t i = 0; d->pdf != NULL && i < c->n; i++)
		d->pdf[o + i] = api_pdf(d->su, d->map, &c->e[i]);
	return 0;
}

static int direct_ok(const frs_sampler *s, const uint64_t *steps,
    unsigned nsteps)
{
	return s != NULL && steps != NULL && nsteps == 1 &&
	    s->algo == FRS_SORTED && s->ocl == NULL;
}

/* The count of every chunk: at[c] the first sample of chunk c, at[nchunk]
 * the total.  A code; *at is the caller's to free. */
static int chunk_starts(const frs_sampler *s, const struct frs_setup *su,
    const struct frs_prep *view, uint64_t **at, frs_error *err)
{
	struct frs_result r;
	uint64_t nc = frs_nchunks(su);

	if ((*at = malloc((nc + 1) * sizeof **at)) == NULL)
		return api_nomem(err);
	if (frs_sample(su, &s->map, view, FRS_SORTED, &su->n, 1, 1, &r) < 0) {
		free(*at);
		*at = NULL;
		return api_lib_err(err, FRS_E_LIMIT);
	}
	(*at)[0] = 0;
	for (uint64_t c = 0; c < nc; c++)
		(*at)[c + 1] = (*at)[c] + r.chunk[c].count;
	frs_result_free(&r);
	return FRS_OK;
}

/* Samples per wave of the direct path: the chunks thresholded in
 * parallel, into one store that every wave reuses (api.h). */
uint64_t api_wave = (uint64_t)1 << 17;

/* The chunks from c0 whose samples fit a wave (api_wave a thread: each
 * thread's share stays in its cache, and threads start once a wave), and
 * with more than one thread at least two a thread: a peaked map puts most
 * samples in a few chunks, and a wave of one would leave the other
 * threads idle. */
static uint64_t wave_end(const uint64_t *at, uint64_t c0, uint64_t nc)
{
	uint64_t c1 = c0 + 1, t = (uint64_t)frs_threads();
	uint64_t least = t > 1 ? 2 * t : 1;

	while (c1 < nc && (c1 - c0 < least ||
	    at[c1 + 1] - at[c0] <= api_wave * t))
		c1++;
	return c1;
}

/* The most samples of a wave. */
static uint64_t wave_most(const uint64_t *at, uint64_t nc)
{
	uint64_t most = 0;

	for (uint64_t c0 = 0, c1; c0 < nc; c0 = c1) {
		c1 = wave_end(at, c0, nc);
		most = at[c1] - at[c0] > most ? at[c1] - at[c0] : most;
	}
	return most;
}

/*
 * Threshold wave after wave, the elements of a wave in one store (its
 * pages touched once for the run, not once per chunk), each chunk turned
 * into points by direct_chunk where d says; after each wave, out(octx,
 * first sample, samples) if out is not NULL.  d->base follows the wave
 * when wave_base (a buffer of one wave), else stays (the whole run's).
 */
static int direct_waves(const frs_sampler *s, const struct frs_setup *su,
    const struct frs_prep *view, const uint64_t *at, struct direct *d,
    int wave_base, int (*out)(void *, uint64_t, uint64_t), void *octx,
    frs_error *err)
{
	uint64_t nc = frs_nchunks(su), most = wave_most(at, nc);
	struct frs_elem *store = malloc((size_t)(most + 1) * sizeof *store);
	uint64_t *rel = malloc((size_t)(nc + 1) * sizeof *rel);
	int rc = FRS_OK, team = 0;

	if (store == NULL || rel == NULL)
		rc = api_nomem(err);
	/* One team of threads for all the waves: starting threads for each
	 * wave took a third of the thresholding at 2^24 on two threads. */
	else if (frs_team_start() < 0)
		rc = api_lib_err(err, FRS_E_NOMEM);
	else
		team = 1;
	for (uint64_t c0 = 0, c1, o; rc == FRS_OK && c0 < nc; c0 = c1) {
		c1 = wave_end(at, c0, nc);
		for (uint64_t c = c0; c <= c1; c++)
			rel[c - c0] = at[c] - at[c0];
		if (wave_base)
			d->base = at[c0];
		o = at[c0] - d->base;
		if (frs_sample_each(su, &s->map, view, FRS_SORTED, c0, c1, rel,
		    store, d->xy != NULL ? d->xy + 2 * o : NULL,
		    d->pdf != NULL ? d->pdf + o : NULL,
		    direct_chunk, d) < 0)
			rc = api_lib_err(err, FRS_E_LIMIT);
		else if (out != NULL && out(octx, at[c0], at[c1] - at[c0]) != 0)
			rc = api_set_err(err, FRS_E_CALLBACK, "stopped by the callback");
	}
	if (team)
		frs_team_stop();
	free(store);
	free(rel);
	return rc;
}

static int draw_direct(const frs_sampler *s, uint64_t n, uint64_t seed,
    double *xy, double *pdf, size_t bufcap, size_t *count, frs_error *err)
{
	struct frs_setup su;
	struct frs_prep view;
	struct direct d;
	uint64_t *at, nc;
	int rc = begin_run(s, &n, 1, seed, &su, &view, err);

	if (rc != FRS_OK || (rc = chunk_starts(s, &su, &view, &at, err)) != FRS_OK)
		return rc;
	nc = frs_nchunks(&su);
	*count = (size_t)at[nc];
	if (at[nc] > bufcap) {
		free(at);
		return api_too_small("frs_draw", err);
	}
	d = (struct direct){ &su, &s->map, at, 0, xy, pdf };
	rc = direct_waves(s, &su, &view, at, &d, 0, NULL, NULL, err);
	free(at);
	return rc != FRS_OK ? rc : api_ok(err);
}

uint32_t api_sorted_block(const struct frs_setup *su)
{
	uint32_t b = su->ns < su->mw ? su->ns : su->mw, t = frs_tile_max_block(su);
	b = b < su->mh ? b : su->mh;
	return b < t ? b : t;
}

int api_sorted_minmap(const struct frs_setup *su)
{
	return api_sorted_block(su) < su->ns;
}

uint64_t api_lists_below(const struct frs_setup *su, const uint64_t *steps,
    unsigned nsteps)
{
	return frs_lim_most(su, frs_tau(su, steps[nsteps - 1]));
}

double api_pdf(const struct frs_setup *su, const struct frs_imap *map,
    const struct frs_elem *e)
{
	return map->v[(uint64_t)(e->y / su->ns) * su->iw + e->x / su->ns] /
	    su->mean;
}

int frs_draw_progressive(const frs_sampler *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, double *xy, double *pdf,
    uint32_t *step, size_t cap, size_t *count, frs_error *err)
{
	int rc = api_draw_args("frs_draw", xy, cap, count, err);

	if (rc != FRS_OK)
		return rc;
	if (direct_ok(s, steps, nsteps))
		return draw_direct(s, steps[0], seed, xy, pdf, cap, count, err);
	return api_draw(run, s, "frs_draw", steps, nsteps, seed, xy, pdf,
	    step, cap, count, err);
}

int frs_count(const frs_sampler *s, uint64_t n, uint64_t seed,
    uint64_t *count, frs_error *err)
{
	return api_count(run, s, "frs_count", n, seed, count, err);
}

int frs_draw(const frs_sampler *s, uint64_t n, uint64_t seed, double *xy,
    double *pdf, size_t cap, size_t *count, frs_error *err)
{
	return frs_draw_progressive(s, &n, 1, seed, xy, pdf, NULL, cap, count,
	    err);
}

struct wave_cb {
	frs_point_fn fn;
	void *ctx;
	uint64_t total;
	const double *xy, *pdf;
};

static int wave_out(void *ctx, uint64_t first, uint64_t n)
{
	const struct wave_cb *w = ctx;

	(void)first;
	for (uint64_t i = 0; i < n; i += API_BATCH) {
		size_t k = n - i < API_BATCH ? (size_t)(n - i) : API_BATCH;
		if (w->fn(w->ctx, w->xy + 2 * i, w->pdf != NULL ? w->pdf + i :
		    NULL, NULL, k, w->total) != 0)
			return -1;
	}
	return 0;
}

static int each_direct(const frs_sampler *s, uint64_t n, uint64_t seed,
    int want_pdf, frs_point_fn fn, void *ctx, frs_error *err)
{
	struct frs_setup su;
	struct frs_prep view;
	struct direct d;
	struct wave_cb w;
	uint64_t *at = NULL, most;
	double *xy = NULL, *pdf = NULL;
	int rc = begin_run(s, &n, 1, seed, &su, &view, err);

	if (rc != FRS_OK || (rc = chunk_starts(s, &su, &view, &at, err)) != FRS_OK)
		return rc;
	most = wave_most(at, frs_nchunks(&su));
	xy = malloc((size_t)(2 * most + 1) * sizeof *xy);
	pdf = want_pdf ? malloc((size_t)(most + 1) * sizeof *pdf) : NULL;
	if (xy == NULL || (want_pdf && pdf == NULL))
		rc = api_nomem(err);
	d = (struct direct){ &su, &s->map, at, 0, xy, pdf };
	w = (struct wave_cb){ fn, ctx, at[frs_nchunks(&su)], xy, pdf };
	if (rc == FRS_OK)
		rc = direct_waves(s, &su, &view, at, &d, 1, wave_out, &w, err);
	free(xy);
	free(pdf);
	free(at);
	return rc != FRS_OK ? rc : api_ok(err);
}

int frs_draw_each(const frs_sampler *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, int want_pdf, frs_point_fn fn,
    void *ctx, frs_error *err)
{
	if (fn == NULL)
		return api_arg_err(err, "frs_draw_each: NULL callback");
	if (direct_ok(s, steps, nsteps))
		return each_direct(s, steps[0], seed, want_pdf, fn, ctx, err);
	return api_each(run, s, "frs_draw_each", steps, nsteps, seed, want_pdf,
	    fn, ctx, err);
}

int frs_sampler_info(const frs_sampler *s, uint64_t n, uint64_t seed,
    struct frs_info *info, frs_error *err)
{
	struct frs_setup su;

	if (s == NULL || info == NULL)
		return api_arg_err(err, "frs_sampler_info: NULL argument");
	if (n == 0)
		return api_arg_err(err, "frs_sampler_info: n must not be 0");
	if (n > API_MAX_N)
		return api_set_err(err, FRS_E_LIMIT, "n: more than 2^40 samples");
	frs_set_threads(s->opt.threads > 0 ? s->opt.threads : 1);
	if (api_setup_steps(s, &n, 1, seed, &su) < 0)
		return api_lib_err(err, FRS_E_LIMIT);
	*info = (struct frs_info){ su.ns, su.sw, su.sh, su.wx, su.wy, su.tau,
	    su.mean, su.max, frs_unique(&su) };
	return api_ok(err);
}

