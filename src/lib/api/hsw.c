/*
 * Hierarchical Sample Warping (frs.h's frs_hsw_*): the warping quadtree
 * of a map, and points warped through it.
 */
#define _POSIX_C_SOURCE 200809L
#include "frs.h"

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

void api_hsw_pdf(const struct hsw_tree *t, const struct frs_imap *map,
    const double *xy, double *pdf, size_t n)
{
	double mean = hsw_mean(t, map);

	for (size_t i = 0; i < n; i++)
		pdf[i] = hsw_pdf_at(map, mean, xy[2 * i], xy[2 * i + 1]);
}

int frs_hsw_warp(const frs_hsw *hw, const double *in, double *out,
    double *pdf, size_t n, int threads, frs_error *err)
{
	if (hw == NULL || ((in == NULL || out == NULL) && n > 0))
		return api_arg_err(err, "frs_hsw_warp: NULL argument");
	if (threads < 0 || threads > 1024)
		return api_arg_err(err, "frs_hsw_warp: threads must lie in 0 .. "
		    "1024");
	for (size_t i = 0; i < 2 * n; i++)
		if (!(in[i] >= 0.0 && in[i] < 1.0))
			return api_arg_err(err, "frs_hsw_warp: a point lies outside "
			    "[0,1)^2");
	frs_set_threads(threads > 0 ? threads : 1);
	if (hsw_warp_points(&hw->t, in, out, n) < 0)
		return api_lib_err(err, FRS_E_LIMIT);
	if (pdf != NULL)
		api_hsw_pdf(&hw->t, &hw->map, out, pdf, n);
	return api_ok(err);
}

int frs_hsw_draw(const frs_hsw *hw, enum frs_hsw_input input, uint64_t n,
    uint64_t seed, double *xy, double *pdf, int threads, frs_error *err)
{
	static const enum hsw_input kinds[] = {
		HSW_RANDOM, HSW_REGULAR, HSW_JITTERED, HSW_HALTON, HSW_HAMMERSLEY
	};
	struct hsw_source src = { HSW_HALTON, n, seed, NULL };

	if (hw == NULL || (xy == NULL && n > 0))
		return api_arg_err(err, "frs_hsw_draw: NULL argument");
	if ((unsigned)input > FRS_HSW_HAMMERSLEY)
		return api_arg_err(err, "frs_hsw_draw: unknown input set");
	if (threads < 0 || threads > 1024)
		return api_arg_err(err, "frs_hsw_draw: threads must lie in 0 .. "
		    "1024");
	/* The set made and warped chunk by chunk, as frs_hsw_warp would
	 * warp it. */
	src.kind = kinds[input];
	frs_set_threads(threads > 0 ? threads : 1);
	if (hsw_sample(&hw->t, &src, NULL, 0, n, xy) < 0)
		return api_lib_err(err, FRS_E_LIMIT);
	if (pdf != NULL)
		api_hsw_pdf(&hw->t, &hw->map, xy, pdf, (size_t)n);
	return api_ok(err);
}
