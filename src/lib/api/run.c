/*
 * The run of a sampler (frs.h's frs_run_*, since 2.2): the setup that
 * frs_draw_each makes for some steps and a seed, held so that a caller
 * can look at it (the window, its levels and their cells, the threshold
 * scales, the tiles) and find, for a sample, its level and the matrix
 * element it shows: what frs-sample -v reports and --level-column writes.
 */
#define _POSIX_C_SOURCE 200809L
#include "frs.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/api.h"
#include "base/err.h"

struct frs_run {
	unsigned dims;
	const frs_sampler *s;
	const frs_sampler3 *s3;
	uint64_t steps[16];
	unsigned nsteps;
	struct api_lev2 lv;
	struct api_lev3 lv3;
	double tau_plain;	/* level 0's tau without the count passes */
};

static int run_new(const char *fn, frs_run **rp, const frs_sampler *s,
    const frs_sampler3 *s3, const uint64_t *steps, unsigned nsteps,
    uint64_t seed, int flags, frs_error *err)
{
	const struct frs_options *o = s != NULL ? &s->opt : s3 != NULL ?
	    &s3->opt : NULL;	/* NULL: refused below */
	char msg[64];
	frs_run *r;
	int rc;

	if (rp != NULL)
		*rp = NULL;
	if (rp == NULL || (s == NULL && s3 == NULL) ||
	    (flags & ~FRS_RUN_EXACT)) {
		snprintf(msg, sizeof msg, "%s: NULL argument or unknown flags",
		    fn);
		return api_arg_err(err, msg);
	}
	if ((rc = api_run_begin(1, o->threads, steps, nsteps, err)) != FRS_OK)
		return rc;
	if ((r = calloc(1, sizeof *r)) == NULL)
		return api_nomem(err);
	*r = (struct frs_run){ .dims = s != NULL ? 2 : 3, .s = s, .s3 = s3,
	    .nsteps = nsteps };
	memcpy(r->steps, steps, nsteps * sizeof *steps);
	if (s != NULL ? api_setup_steps(s, steps, nsteps, seed,
	    flags & FRS_RUN_EXACT, &r->lv) < 0 : api_setup3(s3, steps, nsteps,
	    seed, flags & FRS_RUN_EXACT, &r->lv3) < 0) {
		free(r);
		return api_lib_err(err, FRS_E_LIMIT);
	}
	if (s != NULL) {
		struct frs_setup plain = r->lv.base;
		plain.exact.n = 0;
		r->tau_plain = frs_tau(&plain, plain.n);
	} else {
		struct frs3_setup plain = r->lv3.base;
		plain.exact.n = 0;
		r->tau_plain = frs3_tau(&plain, plain.n);
	}
	*rp = r;
	return api_ok(err);
}

int frs_run_new(frs_run **run, const frs_sampler *sampler,
    const uint64_t *steps, unsigned nsteps, uint64_t seed, int flags,
    frs_error *err)
{
	return run_new("frs_run_new", run, sampler, NULL, steps, nsteps, seed,
	    flags, err);
}

int frs_run3_new(frs_run **run, const frs_sampler3 *sampler,
    const uint64_t *steps, unsigned nsteps, uint64_t seed, int flags,
    frs_error *err)
{
	return run_new("frs_run3_new", run, NULL, sampler, steps, nsteps, seed,
	    flags, err);
}

void frs_run_free(frs_run *r)
{
	if (r == NULL)
		return;
	api_lev2_free(&r->lv);
	api_lev3_free(&r->lv3);
	free(r);
}

int frs_run_prepare(const frs_run *r, frs_error *err)
{
	if (r == NULL)
		return api_arg_err(err, "frs_run_prepare: NULL argument");
	for (unsigned i = 0; r->dims == 2 && i < r->lv.n; i++) {
		struct frs_prep view;
		if (api_sampler_prep(r->s, &r->lv, i, r->steps, r->nsteps,
		    &view) < 0)
			return api_lib_err(err, FRS_E_FORMAT);
	}
	for (unsigned i = 0; r->dims == 3 && i < r->lv3.n; i++) {
		struct frs3_prep view;
		if (api_sampler3_prep(r->s3, &r->lv3.su[i], &view) < 0)
			return api_lib_err(err, FRS_E_FORMAT);
	}
	return api_ok(err);
}

/* The plan of r's levels: lev NULL when the run has one level. */
static const struct frs_levels *plan_of(const frs_run *r)
{
	return r->dims == 2 ? &r->lv.plan : &r->lv3.plan;
}

int frs_run_info(const frs_run *r, struct frs_run_info *info,
    frs_error *err)
{
	if (r == NULL || info == NULL)
		return api_arg_err(err, "frs_run_info: NULL argument");
	if (r->dims == 2) {
		const struct frs_setup *b = &r->lv.base;
		*info = (struct frs_run_info){ 2, { b->mw, b->mh, 1 }, b->n, b->ns,
		    { b->sw, b->sh, 1 },
		    { b->wx, b->wy, 0 }, b->tau, r->tau_plain, b->exact.passes,
		    b->level0, b->mean, b->max, frs_unique(b),
		    { frs_tiles_axis(b->wx, b->sw, b->mw),
		    frs_tiles_axis(b->wy, b->sh, b->mh), 1 },
		    b->tiles == FRS_TILES_SHUFFLE, r->lv.n,
		    r->lv.plan.lev != NULL, r->lv.plan.blur };
	} else {
		const struct frs3_setup *b = &r->lv3.base;
		*info = (struct frs_run_info){ 3, { b->mw, b->mh, b->md }, b->n,
		    b->ns,
		    { b->sw, b->sh, b->sd }, { b->wx, b->wy, b->wz }, b->tau,
		    r->tau_plain, b->exact.passes, 0, b->mean, b->max,
		    frs3_unique(b), { frs_tiles_axis(b->wx, b->sw, b->mw),
		    frs_tiles_axis(b->wy, b->sh, b->mh),
		    frs_tiles_axis(b->wz, b->sd, b->md) },
		    b->tiles == FRS_TILES_SHUFFLE, r->lv3.n,
		    r->lv3.plan.lev != NULL, r->lv3.plan.blur };
	}
	return api_ok(err);
}

int frs_run_level(const frs_run *r, unsigned i, struct frs_run_level *lvl,
    frs_error *err)
{
	const struct frs_levels *L;
	unsigned n, l;

	if (r == NULL || lvl == NULL)
		return api_arg_err(err, "frs_run_level: NULL argument");
	n = r->dims == 2 ? r->lv.n : r->lv3.n;
	if (i >= n)
		return api_arg_err(err, "frs_run_level: no such level");
	L = plan_of(r);
	if (r->dims == 2) {
		const struct frs_setup *su = &r->lv.su[i];
		l = su->level;
		lvl->info = (struct frs_level_info){ l, su->ns,
		    { su->sw, su->sh, 1 }, { su->wx, su->wy, 0 },
		    L->lev != NULL ? L->cells[l] : frs_exact_most(r->lv.map.v,
		    (uint64_t)su->iw * su->ih, 1, 2), su->tau };
		lvl->map[0] = su->iw, lvl->map[1] = su->ih, lvl->map[2] = 1;
	} else {
		const struct frs3_setup *su = &r->lv3.su[i];
		l = su->level;
		lvl->info = (struct frs_level_info){ l, su->ns,
		    { su->sw, su->sh, su->sd }, { su->wx, su->wy, su->wz },
		    L->lev != NULL ? L->cells[l] : frs_exact_most(r->lv3.vol.v,
		    (uint64_t)su->iw * su->ih * su->id, 1, 3), su->tau };
		lvl->map[0] = su->iw, lvl->map[1] = su->ih, lvl->map[2] = su->id;
	}
	/* Without a plan every pixel is the level's: the box is the map. */
	for (unsigned a = 0; a < 3; a++) {
		lvl->lo[a] = L->lev != NULL ? L->lo[l][a] : 0;
		lvl->hi[a] = L->lev != NULL ? L->hi[l][a] : lvl->map[a] - 1;
		lvl->side[a] = L->lev != NULL ? L->side[a] : lvl->map[a];
	}
	return api_ok(err);
}

/* The cell of the plan that point p lies in, row-major. */
static uint64_t cell_of(const struct frs_levels *L, unsigned dims,
    const double *p)
{
	uint64_t c = 0;

	for (unsigned a = dims; a-- > 0;) {
		uint64_t k = (uint64_t)(p[a] * (double)L->side[a]);
		c = c * L->side[a] + (k < L->side[a] ? k : L->side[a] - 1);
	}
	return c;
}

unsigned frs_run_level_of(const frs_run *r, const double *p)
{
	const struct frs_levels *L = plan_of(r);
	unsigned n = r->dims == 2 ? r->lv.n : r->lv3.n, l;

	if (L->lev == NULL)
		return 0;
	l = L->lev[cell_of(L, r->dims, p)];
	for (unsigned i = 0; i < n; i++)
		if ((r->dims == 2 ? r->lv.su[i].level : r->lv3.su[i].level) == l)
			return i;
	return 0;
}

uint64_t frs_run_element(const frs_run *r, unsigned i, const double *p)
{
	const struct frs_setup *s;

	if (r->dims != 2 || i >= r->lv.n)
		return UINT64_MAX;
	s = &r->lv.su[i];
	return frs_matrix_index(s, (uint64_t)(p[0] * (double)s->sw),
	    (uint64_t)(p[1] * (double)s->sh));
}

size_t frs_draw_bytes(unsigned dims)
{
	return dims == 3 ? sizeof(struct frs3_elem) : dims == 2 ?
	    sizeof(struct frs_elem) : 0;
}
