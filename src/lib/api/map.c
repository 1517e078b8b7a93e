/*
 * Importance maps and volumes: frs_map_load, and the caller's values as
 * the library's (doubles, validated) in new samplers, 2-D and 3-D, and
 * in HSW's quadtree.
 */
#define _POSIX_C_SOURCE 200809L
#include "frs.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/api.h"
#include "base/err.h"
#include "maps/imap.h"
#include "maps/mapload.h"
#include "maps/spec.h"
#include "maps/vol.h"

/*
 * The loads of frs_map_load and frs_imap_load (fn names it): their
 * arguments, then src as the programs load it.  A failure's code: a
 * spec's is the argument's (bad parameters, a size too large, a volume's
 * spec), a file's its format's, but for a file that does not open or
 * read (IO, by the failure's kind: one open), the memory (NOMEM) and the
 * values (MAP).  A spec is a name that some spec has and no file has, as
 * for frs_source_read.
 */
static int load_map(const char *fn, int args, const char *src, uint32_t w,
    uint32_t h, int flags, struct frs_imap *m, frs_error *err)
{
	char msg[80];
	int spec;

	if (!args) {
		snprintf(msg, sizeof msg, "%s: NULL argument", fn);
		return api_arg_err(err, msg);
	}
	if ((w == 0) != (h == 0)) {
		snprintf(msg, sizeof msg, "%s: width and height are both 0 or "
		    "both set", fn);
		return api_arg_err(err, msg);
	}
	if (source_read(src, 2, (const uint32_t[3]){ w, h, 0 }, flags, m, NULL,
	    NULL, &spec) < 0)
		return api_lib_err(err, spec ? FRS_E_ARG : FRS_E_FORMAT);
	return FRS_OK;
}

int frs_map_load(const char *src, uint32_t width, uint32_t height,
    float **map, uint32_t *width_out, uint32_t *height_out, frs_error *err)
{
	struct frs_imap m;
	float *f;
	int rc;

	if (map != NULL)
		*map = NULL;
	/* Negative values (lossy EXR) become zero, as in frs-sample(1). */
	rc = load_map("frs_map_load", src != NULL && map != NULL &&
	    width_out != NULL && height_out != NULL, src, width, height, 0, &m,
	    err);
	if (rc != FRS_OK)
		return rc;
	f = malloc((size_t)m.w * m.h * sizeof *f);
	if (f == NULL) {
		imap_free(&m);
		return api_nomem(err);
	}
	for (size_t i = 0; i < (size_t)m.w * m.h; i++)
		f[i] = (float)m.v[i];
	*map = f;
	*width_out = m.w;
	*height_out = m.h;
	imap_free(&m);
	return api_ok(err);
}

void frs_map_free(float *map)
{
	free(map);
}

int frs_imap_load(struct frs_imap *map, const char *src, uint32_t width,
    uint32_t height, int flags, frs_error *err)
{
	int rc;

	if (map != NULL)
		*map = (struct frs_imap){ 0 };
	rc = load_map("frs_imap_load", src != NULL && map != NULL, src, width,
	    height, flags, map, err);
	return rc != FRS_OK ? rc : api_ok(err);
}

void frs_imap_free(struct frs_imap *map)
{
	if (map != NULL)
		imap_free(map);
}

/* Row j of the map, rows stride elements apart (0: width), times
 * imap_equirect_weight: for maps of floats and of doubles. */
#define EQUIRECT_ROWS(type, map, width, height, stride) do {		\
	size_t st_ = (stride) ? (stride) : (width);			\
	for (uint32_t j_ = 0; (map) != NULL && j_ < (height); j_++) {	\
		double w_ = imap_equirect_weight(j_, (height));		\
		for (uint32_t i_ = 0; i_ < (width); i_++)		\
			(map)[j_ * st_ + i_] = (type)((map)[j_ * st_ + i_] *	\
			    w_);					\
	}								\
} while (0)

void frs_map_equirect(float *map, uint32_t width, uint32_t height,
    size_t stride)
{
	EQUIRECT_ROWS(float, map, width, height, stride);
}

void frs_map_equirect_f64(double *map, uint32_t width, uint32_t height,
    size_t stride)
{
	EQUIRECT_ROWS(double, map, width, height, stride);
}

/* The caller's map as the library's (doubles, validated: no NaN, no
 * infinity, no negative value, not all zero).  map NULL: constant 1. */
int api_copy_map(struct frs_imap *m, const float *f, const double *d,
    uint32_t w, uint32_t h, size_t stride, int flags,
    struct frs_imap_stats *st, frs_error *err)
{
	if (w == 0 || h == 0)
		return api_arg_err(err, "map: width and height must not be 0");
	if (stride == 0)
		stride = w;
	if (stride < w)
		return api_arg_err(err, "map: stride is less than the width");
	if (imap_alloc(m, w, h) < 0)
		return api_lib_err(err, FRS_E_LIMIT);
	for (uint32_t y = 0; y < h; y++)
		for (uint32_t x = 0; x < w; x++)
			m->v[(size_t)y * w + x] = f ? (double)f[y * stride + x] :
			    d ? d[y * stride + x] : 1.0;
	if (imap_validate_stats(m, "map", flags, st) < 0) {
		imap_free(m);
		return api_lib_err(err, FRS_E_MAP);
	}
	return FRS_OK;
}

/* The caller's volume, x fastest, validated like a map; NULL: constant. */
static int copy_vol(struct frs_vol *v, const float *f, const double *d,
    uint32_t w, uint32_t h, uint32_t dd, frs_error *err)
{
	if (w == 0 || h == 0 || dd == 0)
		return api_arg_err(err, "volume: width, height and depth must not "
		    "be 0");
	if (vol_alloc(v, w, h, dd) < 0)
		return api_lib_err(err, FRS_E_LIMIT);
	for (uint64_t i = 0; i < (uint64_t)w * h * dd; i++)
		v->v[i] = f ? (double)f[i] : d ? d[i] : 1.0;
	if (vol_validate(v, "volume", FRS_MAP_STRICT) < 0) {
		vol_free(v);
		return api_lib_err(err, FRS_E_MAP);
	}
	return FRS_OK;
}

/* The checks of frs_sampler_new (dims 2) and frs_sampler3_new (3): a
 * place for the sampler (have_sp), a mask of dims, options opt that fit
 * it, into o.  A code. */
static int sampler_check(int have_sp, const frs_mask *mask, unsigned dims,
    const struct frs_options *opt, struct frs_options *o, frs_error *err)
{
	int rc;

	if (!have_sp || mask == NULL)
		return api_arg_err(err, dims == 2 ? "frs_sampler_new: NULL "
		    "argument" : "frs_sampler3_new: NULL argument");
	if (mask->m.dims != dims)
		return api_arg_err(err, dims == 2 ? "frs_sampler_new: a 3-D mask "
		    "samples volumes (frs_sampler3_new)" : "frs_sampler3_new: a "
		    "2-D mask samples maps (frs_sampler_new)");
	if ((rc = api_options(o, opt, err)) != FRS_OK)
		return rc;
	if (dims == 3 && o->algorithm != FRS_ALG_SORTED &&
	    o->algorithm != FRS_ALG_NAIVE)
		return api_arg_err(err, "options: 3-D sampling has the naive and "
		    "sorted algorithms");
	return FRS_OK;
}

void api_sampler_free(frs_sampler *s2, frs_sampler3 *s3)
{
	if (s2 != NULL) {
		imap_free(&s2->map);
		api_plan_free(&s2->plan);
	}
	if (s3 != NULL) {
		vol_free(&s3->vol);
		api_plan_free(&s3->plan);
	}
	free(s2);
	free(s3);
}

int api_sampler_make(unsigned dims, const frs_mask *mask,
    const struct api_values *v, const struct frs_options *opt,
    frs_sampler **s2, frs_sampler3 **s3, frs_error *err)
{
	struct frs_imap map = { 0 };
	struct frs_imap_stats st;
	const struct frs_imap_stats *known = &st;
	struct frs_vol vol = { 0 };
	struct frs_options o;
	int rc;

	if (s2 != NULL)
		*s2 = NULL;
	if (s3 != NULL)
		*s3 = NULL;
	rc = sampler_check(dims == 2 ? s2 != NULL : s3 != NULL, mask, dims, opt,
	    &o, err);
	if (rc == FRS_OK && dims == 2 && v->own != NULL) {
		map = *v->own;
		known = v->own_stats;
		memset(v->own, 0, sizeof *v->own);
	} else if (rc == FRS_OK)
		rc = dims == 2 ? api_copy_map(&map, v->f, v->d, v->w, v->h,
		    v->stride, FRS_MAP_STRICT, &st, err) : copy_vol(&vol, v->f,
		    v->d, v->w, v->h, v->depth, err);
	if (rc != FRS_OK)
		return rc;
	if (dims == 2 && (*s2 = malloc(sizeof **s2)) != NULL) {
		**s2 = (struct frs_sampler){ .mask = mask, .map = map, .opt = o,
		    .algo = (int)o.algorithm };
		/* A map that fails them fails each setup, which says why. */
		(*s2)->have_cells = frs_cell_stats(&map, known,
		    &(*s2)->cells) == 0;
		if (!(*s2)->have_cells)
			frs_clearerr();
		if (api_plan_init(&(*s2)->plan) == 0)
			return api_ok(err);
		free(*s2);
		*s2 = NULL;
	} else if (dims == 3 && (*s3 = malloc(sizeof **s3)) != NULL) {
		**s3 = (struct frs_sampler3){ .mask = mask, .vol = vol, .opt = o };
		if (api_plan_init(&(*s3)->plan) == 0)
			return api_ok(err);
		free(*s3);
		*s3 = NULL;
	}
	imap_free(&map);
	vol_free(&vol);
	return api_nomem(err);
}

int frs_sampler_take(frs_sampler **s, const frs_mask *mask,
    struct frs_imap *map, const struct frs_imap_stats *st,
    const struct frs_options *opt, frs_error *err)
{
	struct frs_imap_stats own;
	int rc;

	if (s != NULL)
		*s = NULL;
	if (map == NULL)
		return api_arg_err(err, "frs_sampler_take: NULL argument");
	if (st == NULL && imap_validate_stats(map, "map", FRS_MAP_STRICT,
	    &own) < 0) {
		imap_free(map);
		return api_lib_err(err, FRS_E_MAP);
	}
	rc = api_sampler_make(2, mask, &(struct api_values){ .own = map,
	    .own_stats = st != NULL ? st : &own }, opt, s, NULL, err);
	if (rc != FRS_OK)
		imap_free(map);	/* refused before it was taken: released */
	return rc;
}
