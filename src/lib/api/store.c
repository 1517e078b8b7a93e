/*
 * A run's stored samples to the caller, 2-D and 3-D alike: into the
 * buffers of frs_draw_progressive, or in batches to frs_draw_each's
 * callback.  The order is the output order: the steps in turn, each in
 * chunk order (rows of pixels, slices of voxels), with each sample's
 * density where asked (api_pdf).
 */
#define _POSIX_C_SOURCE 200809L
#include "frs.h"

#include <stdio.h>
#include <stdlib.h>

#include "api/api.h"
#include "base/err.h"

void api_store_set(struct api_store *st, unsigned dims, unsigned nsteps,
    unsigned nparts)
{
	st->dims = dims;
	st->nsteps = nsteps;
	st->nparts = nparts;
	st->count = 0;
	for (unsigned i = 0; i < nparts; i++)
		st->count += dims == 2 ? st->r[i].count : st->r3[i].count;
}

void api_store_free(struct api_store *st)
{
	for (unsigned i = 0; i < st->nparts; i++)
		if (st->dims == 2)
			frs_result_free(&st->r[i]);
		else
			frs3_result_free(&st->r3[i]);
	if (st->lv != NULL)
		api_lev2_free(st->lv);
	if (st->lv3 != NULL)
		api_lev3_free(st->lv3);
	free(st->lv);
	free(st->lv3);
	st->lv = NULL;
	st->lv3 = NULL;
	st->nparts = 0;
}

double api_pdf(const struct frs_setup *su, const struct frs_imap *map,
    const struct frs_elem *e)
{
	return map->v[(uint64_t)(e->y / su->ns) * su->iw + e->x / su->ns] /
	    su->mean;
}

static uint64_t nchunks(const struct api_store *st, unsigned part)
{
	return st->dims == 2 ? st->r[part].nchunk : st->r3[part].nchunk;
}

static uint64_t chunk_size(const struct api_store *st, unsigned part,
    uint64_t c)
{
	return st->dims == 2 ? st->r[part].chunk[c].n :
	    st->r3[part].chunk[c].n;
}

static uint32_t elem_step(const struct api_store *st, unsigned part,
    uint64_t c, uint64_t i)
{
	return st->dims == 2 ? st->r[part].chunk[c].e[i].step :
	    st->r3[part].chunk[c].e[i].step;
}

/* The points of k elements of chunk c of level part from i, dims
 * coordinates each, and their densities when pdf is not NULL. */
static void points(const struct api_store *st, unsigned part, uint64_t c,
    uint64_t i, size_t k, double *p, double *pdf)
{
	if (st->dims == 2) {
		const struct frs_setup *su = &st->lv->su[part];
		const struct frs_elem *e = st->r[part].chunk[c].e + i;
		frs_points(su, e, k, p);
		for (size_t j = 0; pdf != NULL && j < k; j++)
			pdf[j] = api_pdf(su, &st->lv->map, &e[j]);
		return;
	}
	for (size_t j = 0; j < k; j++) {
		const struct frs3_setup *su = &st->lv3->su[part];
		const struct frs3_elem *e = st->r3[part].chunk[c].e + i + j;
		frs3_point(su, e, p + 3 * j);
		if (pdf != NULL)
			pdf[j] = frs3_pdf(su, &st->lv3->vol, e);
	}
}

static uint64_t stored(const struct api_store *st)
{
	uint64_t n = 0;

	for (unsigned part = 0; part < st->nparts; part++)
		for (uint64_t c = 0; c < nchunks(st, part); c++)
			n += chunk_size(st, part, c);
	return n;
}

/* Visit the elements in output order, as runs of neighbours in one
 * chunk and step: fn(ctx, level, chunk, first, count, step), which
 * returns non-zero to stop.  The order: the steps in turn, each level by
 * level, each level's chunks in order. */
static int each_span(const struct api_store *st, int (*fn)(void *, unsigned,
    uint64_t, uint64_t, uint64_t, uint32_t), void *ctx)
{
	for (uint32_t s = 0; s < st->nsteps; s++)
		for (unsigned part = 0; part < st->nparts; part++)
			for (uint64_t c = 0; c < nchunks(st, part); c++) {
				uint64_t n = chunk_size(st, part, c), i = 0, j;
				while (i < n) {
					if (st->nsteps > 1 &&
					    elem_step(st, part, c, i) != s) {
						i++;
						continue;
					}
					j = st->nsteps == 1 ? n : i + 1;
					while (j < n && elem_step(st, part, c, j) == s)
						j++;
					if (fn(ctx, part, c, i, j - i, s) != 0)
						return -1;
					i = j;
				}
			}
	return 0;
}

/* frs_draw_progressive's buffers, filled k samples on. */
struct put {
	const struct api_store *st;
	double *p, *pdf;
	uint32_t *step;
	size_t k;
};

static int put_span(void *ctx, unsigned part, uint64_t c, uint64_t i,
    uint64_t n, uint32_t s)
{
	struct put *p = ctx;

	points(p->st, part, c, i, (size_t)n, p->p + p->st->dims * p->k,
	    p->pdf != NULL ? p->pdf + p->k : NULL);
	for (uint64_t j = 0; p->step != NULL && j < n; j++)
		p->step[p->k + j] = s;
	p->k += (size_t)n;
	return 0;
}

/* Batches for frs_draw_each. */
struct batch {
	const struct api_store *st;
	double p[3 * API_BATCH], pdf[API_BATCH];
	uint32_t step[API_BATCH];
	size_t k;
	int want_pdf;
	frs_point_fn fn;
	void *ctx;
	uint64_t total;
};

static int flush(struct batch *b)
{
	int rc = b->k ? b->fn(b->ctx, b->p, b->want_pdf ? b->pdf : NULL,
	    b->st->nsteps > 1 ? b->step : NULL, b->k, b->total) : 0;

	b->k = 0;
	return rc;
}

static int batch_span(void *ctx, unsigned part, uint64_t c, uint64_t i,
    uint64_t n, uint32_t s)
{
	struct batch *b = ctx;

	while (n > 0) {
		size_t k = API_BATCH - b->k;
		k = n < k ? (size_t)n : k;
		points(b->st, part, c, i, k, b->p + b->st->dims * b->k,
		    b->want_pdf ? b->pdf + b->k : NULL);
		for (size_t j = 0; j < k; j++)
			b->step[b->k + j] = s;
		b->k += k;
		i += k;
		n -= k;
		if (b->k == API_BATCH && flush(b) != 0)
			return -1;
	}
	return 0;
}

int api_draw_args(const char *fn, const double *p, size_t cap,
    size_t *count, frs_error *err)
{
	char msg[64];

	if (count == NULL || (p == NULL && cap > 0)) {
		snprintf(msg, sizeof msg, "%s: NULL argument", fn);
		return api_arg_err(err, msg);
	}
	*count = 0;
	return FRS_OK;
}

int api_too_small(const char *fn, frs_error *err)
{
	char msg[128];

	snprintf(msg, sizeof msg, "%s: the buffer is too small; *count says "
	    "how many samples there are", fn);
	return api_set_err(err, FRS_E_BUFFER, msg);
}

int api_draw(api_run_fn run, const void *s, const char *fn,
    const uint64_t *steps, unsigned nsteps, uint64_t seed, double *p,
    double *pdf, uint32_t *step, size_t cap, size_t *count, frs_error *err)
{
	struct api_store st;
	struct put put;
	uint64_t n;
	int rc;

	if ((rc = api_draw_args(fn, p, cap, count, err)) != FRS_OK ||
	    (rc = run(s, steps, nsteps, seed, 0, &st, err)) != FRS_OK)
		return rc;
	n = stored(&st);
	*count = (size_t)n;
	if (n > cap) {
		api_store_free(&st);
		return api_too_small(fn, err);
	}
	put = (struct put){ &st, p, pdf, step, 0 };
	each_span(&st, put_span, &put);
	api_store_free(&st);
	return api_ok(err);
}

int api_count(api_run_fn run, const void *s, const char *fn, uint64_t n,
    uint64_t seed, uint64_t *count, frs_error *err)
{
	struct api_store st;
	char msg[64];
	int rc;

	if (count == NULL) {
		snprintf(msg, sizeof msg, "%s: NULL argument", fn);
		return api_arg_err(err, msg);
	}
	*count = 0;
	if ((rc = run(s, &n, 1, seed, 1, &st, err)) != FRS_OK)
		return rc;
	*count = st.count;
	api_store_free(&st);
	return api_ok(err);
}

int api_each(api_run_fn run, const void *s, const char *fn,
    const uint64_t *steps, unsigned nsteps, uint64_t seed, int want_pdf,
    frs_point_fn cb, void *ctx, frs_error *err)
{
	struct api_store st;
	struct batch *b;
	char msg[64];
	int rc, stop;

	if (cb == NULL) {
		snprintf(msg, sizeof msg, "%s: NULL callback", fn);
		return api_arg_err(err, msg);
	}
	if ((rc = run(s, steps, nsteps, seed, 0, &st, err)) != FRS_OK)
		return rc;
	if ((b = malloc(sizeof *b)) == NULL) {
		api_store_free(&st);
		return api_nomem(err);
	}
	*b = (struct batch){ .st = &st, .want_pdf = want_pdf, .fn = cb,
	    .ctx = ctx, .total = stored(&st) };
	stop = each_span(&st, batch_span, b) < 0 || flush(b) != 0;
	free(b);
	api_store_free(&st);
	if (stop)
		return api_set_err(err, FRS_E_CALLBACK, "stopped by the callback");
	return api_ok(err);
}
