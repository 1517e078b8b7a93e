#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>

#include "hsw-sample/hswrun.h"
#include "cli/cli.h"

/* Points per round of handing out the device's points (their
 * densities, 512 KiB, made a round at a time); frs_hsw_draw_each's
 * batches on the CPU are as large. */
#define ROUND ((uint64_t)1 << 16)

int hsw_run_open(struct hsw_run *r, const char *src, uint32_t w,
    uint32_t h, int flags, int cl, int cl_index)
{
	struct frs_imap map;
	frs_error err;
	double t0;
	int rc, bad = -1;	/* -2 when it is the device that fails */

	memset(r, 0, sizeof *r);
	r->cl = cl;
	if (cl)	/* one that does not open ends the program */
		r->dev = cli_device_open(cl_index, 1);
	if (frs_imap_load(&map, src, w, h, flags, NULL) != FRS_OK)
		goto fail;
	t0 = cli_now();
	rc = frs_hsw_new_f64(&r->hw, map.v, map.w, map.h, 0, &err);
	frs_imap_free(&map);
	if (rc == FRS_OK)
		rc = frs_hsw_info(r->hw, &r->info, &err);
	if (rc != FRS_OK) {
		cli_fail("%s", err.message);
		cli_fail_context(src);
		goto fail;
	}
	if (cl && hswcl_init(&r->hc, r->dev, &r->info) < 0) {
		bad = -2;
		goto fail;
	}
	r->t_tree = cli_now() - t0;
	return 0;
fail:
	frs_hsw_free(r->hw);
	cli_device_close(r->dev);
	return bad;
}

void hsw_run_close(struct hsw_run *r)
{
	if (r->cl) {
		hswcl_free(&r->hc);
		cli_device_close(r->dev);
	}
	frs_hsw_free(r->hw);
}

/* Handing the library's batches to the caller's fn, and the warping's
 * share of the time. */
struct hand {
	struct hsw_run *r;
	hsw_rec_fn fn;
	void *ctx;
	double t0;		/* when the warping of this batch began */
	int stopped;		/* fn said stop */
};

/* k points xy and, when not NULL, their densities to fn. */
static int hand_over(void *ctx, const double *xy, const double *pdf,
    const uint32_t *step, size_t k, uint64_t total)
{
	struct hand *u = ctx;

	(void)step, (void)total;
	u->r->t_warp += cli_now() - u->t0;
	u->stopped = u->fn(u->ctx, xy, pdf, k) != 0;
	u->t0 = cli_now();
	return u->stopped;
}

/* The device's points pts, warped beforehand, in rounds with their
 * densities. */
static int hand_device(struct hand *u, const double *pts, uint64_t n,
    int want_pdf)
{
	double *pdf = NULL;
	frs_error err;
	int rc = 0;

	if (want_pdf)
		pdf = cli_calloc("output buffer", ROUND, sizeof *pdf);
	for (uint64_t b = 0; rc == 0 && b < n; b += ROUND) {
		size_t m = (size_t)(n - b < ROUND ? n - b : ROUND);
		if (pdf != NULL && frs_hsw_pdf(u->r->hw, pts + 2 * b, pdf, m,
		    &err) != FRS_OK)
			rc = cli_fail("%s", err.message);
		else if (hand_over(u, pts + 2 * b, pdf, NULL, m, n) != 0)
			rc = -1;
	}
	free(pdf);
	return rc;
}

/*
 * A point depends only on its index, so the records are the same for
 * any thread count, round or chunk size.  The device is handed all the
 * points at once.
 */
int hsw_run_each(struct hsw_run *r, enum frs_hsw_input input, double *pts,
    uint64_t n, uint64_t seed, int pdf, hsw_rec_fn fn, void *ctx)
{
	struct hand u = { r, fn, ctx, cli_now(), 0 };
	frs_error err;
	int rc = 0;

	if (r->cl && pts == NULL)
		return cli_fail("hsw_run_each: the device needs the points");
	if (r->cl)
		rc = hswcl_warp_points(&r->hc, pts, pts, n) < 0 ? -1 :
		    hand_device(&u, pts, n, pdf);
	else if (frs_hsw_draw_each(r->hw, input, pts, n, seed, pdf,
	    cli_threads(), hand_over, &u, &err) != FRS_OK)
		rc = u.stopped ? -1 : cli_fail("%s", err.message);
	return rc;
}
