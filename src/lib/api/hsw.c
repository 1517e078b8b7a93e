/*
 * Hierarchical Sample Warping (frs.h's frs_hsw_*): the warping quadtree
 * of a map, and points warped through it.
 */
#define _POSIX_C_SOURCE 200809L
#include "frs.h"

#include <stdio.h>
#include <stdlib.h>

#include "api/api.h"
#include "base/err.h"
#include "base/par.h"
#include "maps/imap.h"
#include "sample/hsw.h"

static int hsw_new(frs_hsw **hp, const float *f, const double *d,
    uint32_t w, uint32_t h, size_t stride, frs_error *err)
{
	struct frs_imap_stats st;
	frs_hsw *hw;
	int rc;

	if (hp == NULL)
		return api_arg_err(err, "frs_hsw_new: NULL argument");
	*hp = NULL;
	if ((hw = calloc(1, sizeof *hw)) == NULL)
		return api_nomem(err);
	/* Negative values count as zero, as in the quadtree itself. */
	if ((rc = api_copy_map(&hw->map, f, d, w, h, stride, 0, &st,
	    err)) != FRS_OK) {
		free(hw);
		return rc;
	}
	if (hsw_build(&hw->t, &hw->map) < 0) {
		rc = api_lib_err(err, FRS_E_LIMIT);
		imap_free(&hw->map);
		free(hw);
		return rc;
	}
	*hp = hw;
	return api_ok(err);
}

int frs_hsw_new(frs_hsw **hsw, const float *map, uint32_t width,
    uint32_t height, size_t stride, frs_error *err)
{
	return hsw_new(hsw, map, NULL, width, height, stride, err);
}

int frs_hsw_new_f64(frs_hsw **hsw, const double *map, uint32_t width,
    uint32_t height, size_t stride, frs_error *err)
{
	return hsw_new(hsw, NULL, map, width, height, stride, err);
}

void frs_hsw_free(frs_hsw *hw)
{
	if (hw == NULL)
		return;
	hsw_free(&hw->t);
	imap_free(&hw->map);
	free(hw);
}

/* One vocabulary: the public input sets are the warper's. */
_Static_assert((int)FRS_HSW_RANDOM == (int)HSW_RANDOM &&
    (int)FRS_HSW_REGULAR == (int)HSW_REGULAR &&
    (int)FRS_HSW_JITTERED == (int)HSW_JITTERED &&
    (int)FRS_HSW_HALTON == (int)HSW_HALTON &&
    (int)FRS_HSW_HAMMERSLEY == (int)HSW_HAMMERSLEY,
    "enum frs_hsw_input is enum hsw_input");

/* The caller's n points in (NULL: none) in [0,1)^2. */
static int in_square(const char *fn, const double *in, uint64_t n,
    frs_error *err)
{
	char msg[96];

	for (uint64_t i = 0; in != NULL && i < 2 * n; i++)
		if (!(in[i] >= 0.0 && in[i] < 1.0)) {
			snprintf(msg, sizeof msg, "%s: a point lies outside "
			    "[0,1)^2", fn);
			return api_arg_err(err, msg);
		}
	return FRS_OK;
}

/* The checks the draws share: the input set (unless the caller's points
 * in are warped instead, which must lie in [0,1)^2) and threads. */
static int draw_args(const char *fn, enum frs_hsw_input input,
    const double *in, uint64_t n, int threads, frs_error *err)
{
	char msg[96];
	int rc;

	if (in == NULL && (unsigned)input > FRS_HSW_HAMMERSLEY) {
		snprintf(msg, sizeof msg, "%s: unknown input set", fn);
		return api_arg_err(err, msg);
	}
	if (threads < 0 || threads > 1024) {
		snprintf(msg, sizeof msg, "%s: threads must lie in 0 .. 1024", fn);
		return api_arg_err(err, msg);
	}
	if ((rc = in_square(fn, in, n, err)) != FRS_OK)
		return rc;
	frs_set_threads(threads > 0 ? threads : 1);
	return FRS_OK;
}

int frs_hsw_warp(const frs_hsw *hw, const double *in, double *out,
    double *pdf, size_t n, int threads, frs_error *err)
{
	struct hsw_source src = { HSW_HALTON, n, 0, in };
	int rc;

	if (hw == NULL || ((in == NULL || out == NULL) && n > 0))
		return api_arg_err(err, "frs_hsw_warp: NULL argument");
	if ((rc = draw_args("frs_hsw_warp", FRS_HSW_HALTON, in, n, threads,
	    err)) != FRS_OK)
		return rc;
	/* The caller's points, warped as the sets are, densities with them. */
	if (hsw_sample(&hw->t, &src, &hw->map, 0, n, out, pdf) < 0)
		return api_lib_err(err, FRS_E_LIMIT);
	return api_ok(err);
}

int frs_hsw_draw(const frs_hsw *hw, enum frs_hsw_input input, uint64_t n,
    uint64_t seed, double *xy, double *pdf, int threads, frs_error *err)
{
	struct hsw_source src = { (enum hsw_input)input, n, seed, NULL };
	int rc;

	if (hw == NULL || (xy == NULL && n > 0))
		return api_arg_err(err, "frs_hsw_draw: NULL argument");
	if ((rc = draw_args("frs_hsw_draw", input, NULL, n, threads,
	    err)) != FRS_OK)
		return rc;
	/* The set made and warped chunk by chunk, as frs_hsw_warp would
	 * warp it. */
	if (hsw_sample(&hw->t, &src, &hw->map, 0, n, xy, pdf) < 0)
		return api_lib_err(err, FRS_E_LIMIT);
	return api_ok(err);
}

/* Points a batch of frs_hsw_draw_each: 1 MiB of pairs (and 0.5 MiB of
 * densities), warped by all threads, then handed over at once. */
#define HSW_BATCH ((uint64_t)1 << 16)

int frs_hsw_draw_each(const frs_hsw *hw, enum frs_hsw_input input,
    const double *in, uint64_t n, uint64_t seed, int want_pdf, int threads,
    frs_point_fn fn, void *ctx, frs_error *err)
{
	struct hsw_source src = { (enum hsw_input)input, n, seed, in };
	uint64_t cap = n < HSW_BATCH ? n : HSW_BATCH;
	double *xy, *pdf = NULL;
	int rc;

	if (hw == NULL || fn == NULL)
		return api_arg_err(err, "frs_hsw_draw_each: NULL argument");
	if ((rc = draw_args("frs_hsw_draw_each", input, in, n, threads,
	    err)) != FRS_OK)
		return rc;
	if (n == 0)
		return api_ok(err);
	xy = malloc((size_t)cap * 2 * sizeof *xy);
	if (want_pdf)
		pdf = malloc((size_t)cap * sizeof *pdf);
	if (xy == NULL || (want_pdf && pdf == NULL)) {
		free(xy);
		free(pdf);
		return api_nomem(err);
	}
	rc = FRS_OK;
	/* A point depends only on its index: the same batches for any
	 * thread count. */
	for (uint64_t b = 0; rc == FRS_OK && b < n; b += HSW_BATCH) {
		uint64_t m = n - b < HSW_BATCH ? n - b : HSW_BATCH;
		if (hsw_sample(&hw->t, &src, &hw->map, b, b + m, xy, pdf) < 0)
			rc = api_lib_err(err, FRS_E_LIMIT);
		if (rc == FRS_OK && fn(ctx, xy, pdf, NULL, (size_t)m, n) != 0)
			rc = api_set_err(err, FRS_E_CALLBACK,
			    "stopped by the callback");
	}
	free(xy);
	free(pdf);
	return rc == FRS_OK ? api_ok(err) : rc;
}

int frs_hsw_input(enum frs_hsw_input input, uint64_t n, uint64_t seed,
    double *xy, frs_error *err)
{
	if (xy == NULL && n > 0)
		return api_arg_err(err, "frs_hsw_input: NULL argument");
	if ((unsigned)input > FRS_HSW_HAMMERSLEY)
		return api_arg_err(err, "frs_hsw_input: unknown input set");
	hsw_input_make((enum hsw_input)input, n, seed, xy);
	return api_ok(err);
}

int frs_hsw_pdf(const frs_hsw *hw, const double *xy, double *pdf, size_t n,
    frs_error *err)
{
	double mean;
	int rc;

	if (hw == NULL || ((xy == NULL || pdf == NULL) && n > 0))
		return api_arg_err(err, "frs_hsw_pdf: NULL argument");
	if ((rc = in_square("frs_hsw_pdf", xy, n, err)) != FRS_OK)
		return rc;
	mean = hsw_mean(&hw->t, &hw->map);
	for (size_t i = 0; i < n; i++)
		pdf[i] = hsw_pdf_at(&hw->map, mean, xy[2 * i], xy[2 * i + 1]);
	return api_ok(err);
}

int frs_hsw_info(const frs_hsw *hw, struct frs_hsw_info *info,
    frs_error *err)
{
	if (hw == NULL || info == NULL)
		return api_arg_err(err, "frs_hsw_info: NULL argument");
	*info = (struct frs_hsw_info){ hw->map.w, hw->map.h, hw->t.size,
	    hw->t.levels, hw->t.total, hsw_mean(&hw->t, &hw->map), hw->t.sum };
	return api_ok(err);
}
