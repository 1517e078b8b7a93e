#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>

#include "hsw-sample/hswrun.h"
#include "cli/cli.h"

/* Points per round of warping and handing out: the record buffer
 * (1.5 MiB with the density), filled by all threads, then given to the
 * caller at once. */
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
	if (rc != FRS_OK) {
		cli_fail("%s", err.message);
		cli_fail_context(src);
		goto fail;
	}
	if (cl && hswcl_init(&r->hc, r->dev, &r->hw->t) < 0) {
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

/* Round b .. b + m - 1 into rec: warped here, or, warped on the device
 * beforehand, copied with the density added. */
static int round_recs(struct hsw_run *r, const struct hsw_source *src,
    double *pts, int pdf, uint64_t b, uint64_t m, double *rec)
{
	const struct frs_imap *map = pdf ? &r->hw->map : NULL;
	double mean = hsw_mean(&r->hw->t, &r->hw->map);
	unsigned stride = pdf ? 3 : 2;

	if (!r->cl)
		return hsw_sample(&r->hw->t, src, map, b, b + m, rec);
	for (uint64_t q = 0; q < m; q++) {
		double *x = rec + q * stride;
		x[0] = pts[2 * (b + q)];
		x[1] = pts[2 * (b + q) + 1];
		if (map != NULL)
			x[2] = hsw_pdf_at(map, mean, x[0], x[1]);
	}
	return 0;
}

/*
 * A point depends only on its index, so the records are the same for
 * any thread count, round or chunk size.  The device is handed all the
 * points at once.
 */
int hsw_run_each(struct hsw_run *r, enum hsw_input kind, double *pts,
    uint64_t n, uint64_t seed, int pdf, hsw_rec_fn fn, void *ctx)
{
	struct hsw_source src = { kind, n, seed, pts };
	uint64_t cap = n < ROUND ? n : ROUND;
	double *rec, t0 = cli_now();
	int rc = -1;

	if (r->cl && pts == NULL)
		return cli_fail("hsw_run_each: the device needs the points");
	rec = cli_calloc("output buffer", cap, (pdf ? 3 : 2) * sizeof *rec);
	if (r->cl && hswcl_warp_points(&r->hc, pts, pts, n) < 0)
		goto out;
	for (uint64_t b = 0; b < n; b += ROUND) {
		uint64_t m = n - b < ROUND ? n - b : ROUND;

		if (round_recs(r, &src, pts, pdf, b, m, rec) < 0)
			goto out;
		r->t_warp += cli_now() - t0;
		if (fn(ctx, rec, (size_t)m) != 0)
			goto out;
		t0 = cli_now();
	}
	rc = 0;
out:
	free(rec);
	return rc;
}

void hsw_run_shape(const struct hsw_run *r, uint32_t *w, uint32_t *h,
    uint32_t *side, unsigned *levels, double *mean)
{
	*w = r->hw->map.w;
	*h = r->hw->map.h;
	*side = r->hw->t.size;
	*levels = r->hw->t.levels;
	*mean = hsw_mean(&r->hw->t, &r->hw->map);
}
