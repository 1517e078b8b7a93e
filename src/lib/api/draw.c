/*
 * 2-D sampling (frs.h's frs_sampler): the setup of a run, the mask
 * prepared for it, the thresholding on the CPU or an OpenCL device, and
 * Sorted's direct path for one step, which converts each chunk where it
 * was made; and frs_sampler_levels, the levels such a run would use.
 */
#define _POSIX_C_SOURCE 200809L
#include "frs.h"

#include <stdlib.h>
#include <string.h>

#include "api/api.h"
#include "base/err.h"
#include "base/par.h"
#include "maps/imap.h"

int frs_sampler_new(frs_sampler **sampler, const frs_mask *mask,
    const float *map, uint32_t width, uint32_t height, size_t stride,
    const struct frs_options *opt, frs_error *err)
{
	struct api_values v = { .f = map, .w = width, .h = height,
	    .stride = stride };

	return api_sampler_make(2, mask, &v, opt, sampler, NULL, err);
}

int frs_sampler_new_f64(frs_sampler **sampler, const frs_mask *mask,
    const double *map, uint32_t width, uint32_t height, size_t stride,
    const struct frs_options *opt, frs_error *err)
{
	struct api_values v = { .d = map, .w = width, .h = height,
	    .stride = stride };

	return api_sampler_make(2, mask, &v, opt, sampler, NULL, err);
}

void frs_sampler_free(frs_sampler *s)
{
	api_sampler_free(s, NULL);
}

int api_setup(const frs_sampler *s, uint64_t n, uint64_t seed,
    struct frs_setup *su)
{
	if (frs_setup_known(su, &s->map, s->have_cells ? &s->cells : NULL,
	    &s->mask->m, n, s->opt.sigma, seed) < 0)
		return -1;
	API_MODES(su, &s->opt);
	return 0;
}

/* The exact counts' passes: Sorted's count of the window at any tau
 * (level 0's: each level's is 4^l of it), the levels' counts added, with
 * lists for a little more than the largest tau asked so far (the passes
 * around one tau need one list making per level). */
struct xcount {
	const frs_sampler *s;
	struct api_lev2 *lv;
	int have[FRS_LEVELS_MAX];
	struct frs_prep view[FRS_LEVELS_MAX];
};

static int xcount_fn(void *ctx, double tau, uint64_t *count)
{
	struct xcount *x = ctx;
	struct frs_xtau xt = { .n = 1, .steps = { x->lv->su[0].n },
	    .tau = { tau } };

	*count = 0;
	api_lev2_exact(x->lv, &xt);
	for (unsigned i = 0; i < x->lv->n; i++) {
		struct frs_setup *su = &x->lv->su[i];
		struct frs_result r;
		uint32_t b = api_lev2_block(x->lv, i);
		if (!x->have[i] || (b && x->view[i].below <
		    api_lev2_below(x->lv, &su->n, 1, 1.0))) {
			if (api_mask_prep(x->s->mask, b == 0 || b < su->ns, b,
			    b ? api_lev2_below(x->lv, &su->n, 1, 1.0625) : 0,
			    &x->view[i]) < 0)
				return -1;
			x->have[i] = 1;
		}
		if (frs_sample(su, &x->lv->map, &x->view[i], FRS_SORTED,
		    &su->n, 1, 1, &r) < 0)
			return -1;
		*count += r.count;
		frs_result_free(&r);
	}
	return 0;
}

int api_exact(const frs_sampler *s, const uint64_t *steps, unsigned nsteps,
    struct api_lev2 *lv)
{
	struct xcount x = { .s = s, .lv = lv };
	struct frs_setup *s0 = &lv->su[0];
	struct frs_xtau xt;
	double tau0[16];
	unsigned passes;

	if (frs_steps_check(steps, nsteps) < 0)
		return -1;
	for (unsigned k = 0; k < nsteps; k++)
		tau0[k] = frs_tau(s0, steps[k]) / s0->lfac;
	if (frs_exact_taus(steps, nsteps, tau0, api_lev2_most(lv), xcount_fn,
	    &x, &xt, &passes) < 0)
		return -1;
	api_lev2_exact(lv, &xt);
	return 0;
}

int api_setup_steps(const frs_sampler *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, int taus, struct api_lev2 *lv)
{
	struct frs_setup su;

	memset(lv, 0, sizeof *lv);
	if (api_setup(s, steps[nsteps - 1], seed, &su) < 0 ||
	    api_lev2_make(&s->opt, &su, &s->map, (struct api_plan *)&s->plan,
	    lv) < 0)
		return -1;
	if (taus && s->opt.rule == FRS_RULE_EXACT &&
	    api_exact(s, steps, nsteps, lv) < 0) {
		api_lev2_free(lv);
		return -1;
	}
	return 0;
}

/* Stack, Level 1, Level 2 and Flat 1 walk the minmap; Sorted takes its
 * lists (api_lev2_block), and the minmap too when its blocks are smaller
 * than a pixel or it has none. */
int api_sampler_prep(const frs_sampler *s, const struct api_lev2 *lv,
    unsigned i, const uint64_t *steps, unsigned nsteps,
    struct frs_prep *view)
{
	const struct frs_setup *su = &lv->su[i];
	uint32_t b = s->algo == FRS_SORTED ? api_lev2_block(lv, i) : 0;
	int minmap = s->algo == FRS_SORTED ? b == 0 || b < su->ns :
	    s->algo != FRS_NAIVE;

	return api_mask_prep(s->mask, minmap, b, b ? api_lev2_below(lv, steps,
	    nsteps, 1.0) : 0, view);
}

/* The levels and the prepared matrix of each for a run of steps with
 * this seed, and the sampler's thread count set.  A code. */
static int begin_run(const frs_sampler *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, struct api_lev2 *lv,
    struct frs_prep *view, frs_error *err)
{
	int rc = api_run_begin(s != NULL, s != NULL ? s->opt.threads : 0, steps,
	    nsteps, err);

	if (rc != FRS_OK)
		return rc;
	if (api_setup_steps(s, steps, nsteps, seed, 1, lv) < 0)
		return api_lib_err(err, FRS_E_LIMIT);
	for (unsigned i = 0; i < lv->n; i++)
		if (api_sampler_prep(s, lv, i, steps, nsteps, &view[i]) < 0) {
			api_lev2_free(lv);
			return api_lib_err(err, FRS_E_FORMAT);
		}
	return FRS_OK;
}

/* Threshold the window of every level for steps with this seed, on the
 * sampler's device or the CPU, into st.  A code. */
static int run(const void *vs, const uint64_t *steps, unsigned nsteps,
    uint64_t seed, int count_only, struct api_store *st, frs_error *err)
{
	const frs_sampler *s = vs;
	struct frs_prep view[FRS_LEVELS_MAX];
	struct api_lev2 *lv = malloc(sizeof *lv);
	int rc;

	memset(st, 0, sizeof *st);
	if (lv == NULL)
		return api_nomem(err);
	if ((rc = begin_run(s, steps, nsteps, seed, lv, view, err)) != FRS_OK) {
		free(lv);
		return rc;
	}
	st->lv = lv;
	for (unsigned i = 0; i < lv->n; i++) {
		const struct frs_setup *su = &lv->su[i];
		if ((s->dev != NULL ? api_sample_cl(s, su, &lv->map, &view[i],
		    steps, nsteps, count_only, &st->r[i]) :
		    frs_sample(su, &lv->map, &view[i], (enum frs_impl)s->algo,
		    steps, nsteps, count_only, &st->r[i])) < 0) {
			rc = api_lib_err(err, FRS_E_LIMIT);
			api_store_set(st, 2, nsteps, i);
			api_store_free(st);
			return rc;
		}
	}
	api_store_set(st, 2, nsteps, lv->n);
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
	    s->algo == FRS_SORTED && s->dev == NULL;
}

/* One level of a direct run: its setup, map and prepared matrix, and
 * at[c] the first sample of its chunk c (at[nc] its count).  A level
 * whose Sorted walks the minmap (no lists) is thresholded once, its
 * elements kept in r: a count would cost a second walk. */
struct dlev {
	const struct frs_setup *su;
	const struct frs_imap *map;
	const struct frs_prep *view;
	uint64_t *at, nc;
	struct frs_result r;
};

/* A direct run: the levels, and the samples of all and of the largest
 * wave. */
struct drun {
	struct api_lev2 lv;
	struct frs_prep view[FRS_LEVELS_MAX];
	struct dlev l[FRS_LEVELS_MAX];
	uint64_t total, most;
};

/* The count of every chunk of level dl into dl->at (with the elements
 * kept in dl->r when it has no lists).  A code. */
static int chunk_starts(struct dlev *dl, frs_error *err)
{
	struct frs_result r;
	uint64_t nc = frs_nchunks(dl->su);
	int keep = dl->view->block == 0;

	dl->nc = nc;
	if ((dl->at = malloc((nc + 1) * sizeof *dl->at)) == NULL)
		return api_nomem(err);
	if (frs_sample(dl->su, dl->map, dl->view, FRS_SORTED, &dl->su->n, 1,
	    !keep, &r) < 0)
		return api_lib_err(err, FRS_E_LIMIT);
	dl->at[0] = 0;
	for (uint64_t c = 0; c < nc; c++)
		dl->at[c + 1] = dl->at[c] + r.chunk[c].count;
	if (keep)
		dl->r = r;
	else
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

static void drun_end(struct drun *d)
{
	for (unsigned i = 0; i < d->lv.n; i++) {
		free(d->l[i].at);
		frs_result_free(&d->l[i].r);
	}
	api_lev2_free(&d->lv);
	free(d);
}

/* The levels of n samples with this seed, each counted chunk by chunk.
 * A code; *dp NULL on failure. */
static int drun_begin(const frs_sampler *s, uint64_t n, uint64_t seed,
    struct drun **dp, frs_error *err)
{
	struct drun *d = calloc(1, sizeof *d);
	int rc;

	if ((*dp = d) == NULL)
		return api_nomem(err);
	if ((rc = begin_run(s, &n, 1, seed, &d->lv, d->view, err)) != FRS_OK) {
		free(d);
		*dp = NULL;
		return rc;
	}
	for (unsigned i = 0; i < d->lv.n; i++) {
		struct dlev *dl = &d->l[i];
		uint64_t m;
		*dl = (struct dlev){ &d->lv.su[i], &d->lv.map, &d->view[i],
		    NULL, 0, { 0 } };
		if ((rc = chunk_starts(dl, err)) != FRS_OK) {
			drun_end(d);
			*dp = NULL;
			return rc;
		}
		d->total += dl->at[dl->nc];
		m = wave_most(dl->at, dl->nc);
		d->most = m > d->most ? m : d->most;
	}
	return FRS_OK;
}

/* direct_waves for a level whose elements dl->r holds: each chunk
 * converted in turn. */
static int kept_waves(const struct dlev *dl, struct direct *d,
    int wave_base, int (*out)(void *, uint64_t), void *octx,
    frs_error *err)
{
	for (uint64_t c0 = 0, c1; c0 < dl->nc; c0 = c1) {
		c1 = wave_end(dl->at, c0, dl->nc);
		if (wave_base)
			d->base = dl->at[c0];
		for (uint64_t c = c0; c < c1; c++)
			if (direct_chunk(d, c, &dl->r.chunk[c]) < 0)
				return api_lib_err(err, FRS_E_LIMIT);
		if (out != NULL && out(octx, dl->at[c1] - dl->at[c0]) != 0)
			return api_set_err(err, FRS_E_CALLBACK,
			    "stopped by the callback");
	}
	return FRS_OK;
}

/*
 * Threshold level dl wave after wave, the elements of a wave in one store
 * (its pages touched once for the run, not once per chunk), each chunk
 * turned into points by direct_chunk where d says; after each wave,
 * out(octx, samples) if out is not NULL.  d->base follows the wave when
 * wave_base (a buffer of one wave), else stays (the level's first).
 */
static int direct_waves(const struct dlev *dl, struct direct *d,
    int wave_base, int (*out)(void *, uint64_t), void *octx,
    frs_error *err)
{
	uint64_t nc = dl->nc, most = wave_most(dl->at, nc);

	if (dl->r.chunk != NULL)
		return kept_waves(dl, d, wave_base, out, octx, err);
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
		c1 = wave_end(dl->at, c0, nc);
		for (uint64_t c = c0; c <= c1; c++)
			rel[c - c0] = dl->at[c] - dl->at[c0];
		if (wave_base)
			d->base = dl->at[c0];
		o = dl->at[c0] - d->base;
		if (frs_sample_each(dl->su, dl->map, dl->view, FRS_SORTED, c0, c1,
		    rel, store, d->xy != NULL ? d->xy + 2 * o : NULL,
		    d->pdf != NULL ? d->pdf + o : NULL, direct_chunk, d) < 0)
			rc = api_lib_err(err, FRS_E_LIMIT);
		else if (out != NULL && out(octx, dl->at[c1] - dl->at[c0]) != 0)
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
	struct drun *d;
	uint64_t first = 0;
	int rc = drun_begin(s, n, seed, &d, err);

	if (rc != FRS_OK)
		return rc;
	*count = (size_t)d->total;
	if (d->total > bufcap) {
		drun_end(d);
		return api_too_small("frs_draw", err);
	}
	for (unsigned i = 0; rc == FRS_OK && i < d->lv.n; i++) {
		const struct dlev *dl = &d->l[i];
		struct direct dd = { dl->su, dl->map, dl->at, 0, xy + 2 * first,
		    pdf != NULL ? pdf + first : NULL };
		rc = direct_waves(dl, &dd, 0, NULL, NULL, err);
		first += dl->at[dl->nc];
	}
	drun_end(d);
	return rc != FRS_OK ? rc : api_ok(err);
}

int frs_sampler_levels(const frs_sampler *s, uint64_t n, uint64_t seed,
    struct frs_level_info *levels, unsigned cap, unsigned *count,
    frs_error *err)
{
	struct api_lev2 lv;
	int rc;

	if (count != NULL)
		*count = 0;
	if ((rc = api_query_args("frs_sampler_levels", s != NULL &&
	    count != NULL && (levels != NULL || cap == 0), n, s ? s->opt.threads :
	    0, err)) != FRS_OK)
		return rc;
	if (api_setup_steps(s, &n, 1, seed, 1, &lv) < 0)
		return api_lib_err(err, FRS_E_LIMIT);
	for (unsigned i = 0; i < lv.n && i < cap; i++) {
		const struct frs_setup *su = &lv.su[i];
		levels[i] = (struct frs_level_info){ su->level, su->ns,
		    { su->sw, su->sh, 1 }, { su->wx, su->wy, 0 },
		    lv.plan.lev != NULL ? lv.plan.cells[su->level] :
		    frs_exact_most(lv.map.v, (uint64_t)su->iw * su->ih, 1, 2),
		    su->tau };
	}
	*count = lv.n;
	api_lev2_free(&lv);
	return api_ok(err);
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

static int wave_out(void *ctx, uint64_t n)
{
	const struct wave_cb *w = ctx;

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
	struct drun *d;
	struct wave_cb w;
	double *xy = NULL, *pdf = NULL;
	int rc = drun_begin(s, n, seed, &d, err);

	if (rc != FRS_OK)
		return rc;
	xy = malloc((size_t)(2 * d->most + 1) * sizeof *xy);
	pdf = want_pdf ? malloc((size_t)(d->most + 1) * sizeof *pdf) : NULL;
	if (xy == NULL || (want_pdf && pdf == NULL))
		rc = api_nomem(err);
	w = (struct wave_cb){ fn, ctx, d->total, xy, pdf };
	for (unsigned i = 0; rc == FRS_OK && i < d->lv.n; i++) {
		const struct dlev *dl = &d->l[i];
		struct direct dd = { dl->su, dl->map, dl->at, 0, xy, pdf };
		rc = direct_waves(dl, &dd, 1, wave_out, &w, err);
	}
	free(xy);
	free(pdf);
	drun_end(d);
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
	struct api_lev2 lv;
	const struct frs_setup *su = &lv.base;
	int rc = api_query_args("frs_sampler_info", s != NULL && info != NULL, n,
	    s != NULL ? s->opt.threads : 0, err);

	if (rc != FRS_OK)
		return rc;
	if (api_setup_steps(s, &n, 1, seed, 1, &lv) < 0)
		return api_lib_err(err, FRS_E_LIMIT);
	*info = (struct frs_info){ su->ns, su->sw, su->sh, su->wx, su->wy,
	    su->tau, su->mean, su->max, frs_unique(su) };
	api_lev2_free(&lv);
	return api_ok(err);
}

