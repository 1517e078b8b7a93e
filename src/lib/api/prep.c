/*
 * Preparing matrices (since 2.2), what frd-prep(1) does: matrices made
 * and checked, PNG dither masks read, .frd told from .frp, .frp written
 * and checked, and the plan of levels whose lists a .frp should hold.
 * The work is formats/frdio's, sample/frpio's and lev.c's; here are the
 * public checks and codes.
 */
#define _POSIX_C_SOURCE 200809L
#include "frs.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "api/api.h"
#include "base/err.h"
#include "base/io.h"
#include "formats/frdio.h"
#include "maps/imap.h"
#include "maps/pngio.h"
#include "sample/frpio.h"

int frs_matrix_alloc(struct frs_matrix *m, unsigned dims, uint32_t w,
    uint32_t h, uint32_t d, const char *params, frs_error *err)
{
	if (m == NULL)
		return api_arg_err(err, "frs_matrix_alloc: NULL argument");
	if (frd_alloc(m, dims, w, h, d, params) == 0)
		return api_ok(err);
	/* frd_alloc's own order of checks, its message kept. */
	if (dims < 2 || dims > 3 || w == 0 || h == 0 || d == 0 ||
	    (dims == 2 && d != 1))
		return api_lib_err(err, FRS_E_ARG);
	if ((uint64_t)w * h * d > FRD_MAX_ELEMS)
		return api_lib_err(err, FRS_E_LIMIT);
	return api_lib_err(err, FRS_E_NOMEM);
}

/* A matrix whose values can be read: its sizes agree with n. */
static int matrix_ok(const struct frs_matrix *m)
{
	return m != NULL && (m->dims == 2 || m->dims == 3) &&
	    (uint64_t)m->w * m->h * m->d == m->n && (m->v != NULL || m->n == 0);
}

int frs_matrix_check(const struct frs_matrix *m, const char *name,
    frs_error *err)
{
	if (!matrix_ok(m))
		return api_arg_err(err, "frs_matrix_check: not a matrix");
	if (frd_check_permutation(m, name != NULL ? name : "matrix") < 0)
		return api_lib_err(err, FRS_E_FORMAT);
	return api_ok(err);
}

int frs_matrix_rank(struct frs_matrix *m, frs_error *err)
{
	if (!matrix_ok(m) || m->n > FRD_MAX_ELEMS)
		return api_arg_err(err, "frs_matrix_rank: not a matrix");
	if (frd_rank(m) < 0)
		return api_lib_err(err, FRS_E_NOMEM);
	return api_ok(err);
}

uint64_t frs_matrix_checksum(const struct frs_matrix *m)
{
	return m != NULL ? frd_checksum(m) : 0;
}

int frs_matrix_read_png(struct frs_matrix *m, const char *path,
    frs_error *err)
{
	const char *name;
	unsigned char *buf;
	size_t len;
	struct frs_imap img;

	if (m != NULL)
		*m = (struct frs_matrix){ 0 };
	if (m == NULL || path == NULL)
		return api_arg_err(err, "frs_matrix_read_png: NULL argument");
	if (io_slurp_path(path, &name, &buf, &len) < 0)
		return api_lib_err(err, FRS_E_IO);
	if (imap_read_png_mem(buf, len, name, 0, &img) < 0) {
		free(buf);
		return api_lib_err(err, FRS_E_FORMAT);
	}
	free(buf);
	if (frd_alloc(m, 2, img.w, img.h, 1, "imported=png\n") < 0) {
		imap_free(&img);
		frs_fail_context(name);
		return api_lib_err(err, FRS_E_NOMEM);
	}
	/* Grey levels of a 16-bit (or 8-bit) mask, exactly, as integers:
	 * the decoder scales g to g / 65535 (g / 255), which times 65535
	 * rounds back to g (257 g). */
	for (size_t i = 0; i < m->n; i++)
		m->v[i] = (uint32_t)llround(img.v[i] * 65535.0);
	imap_free(&img);
	if (frd_rank(m) < 0) {
		frd_free(m);
		return api_lib_err(err, FRS_E_NOMEM);
	}
	return api_ok(err);
}

/* frp_check_fp's summary as the caller's. */
static void file_info(struct frs_file_info *info, const struct frp_summary *s)
{
	info->checked = 1;
	info->w = s->w;
	info->h = s->h;
	info->checksum = s->sum;
	info->minmap = s->minmap;
	info->nblocks = s->nblocks;
	memcpy(info->blocks, s->blocks, sizeof info->blocks);
}

/* The file open as fp, its first bytes read to tell a .frd from a .frp:
 * 0, or -1 after frs_fail with *code the failure's. */
static int read_file(FILE *fp, const char *name, int flags,
    struct frs_matrix *m, struct frs_file_info *info, enum frs_code *code)
{
	unsigned char pre[8];
	size_t npre = fread(pre, 1, sizeof pre, fp);
	struct frp_summary s;

	*code = FRS_E_FORMAT;
	if (ferror(fp)) {
		*code = FRS_E_IO;
		return frs_fail_errno("%s: read error", name);
	}
	if (npre == sizeof pre && memcmp(pre, FRP_MAGIC, 8) == 0) {
		info->frp = 1;
		if (!(flags & FRS_READ_CHECK_FRP))
			return 0;
		if (frp_check_fp(fp, name, pre, npre, &s) < 0)
			return -1;
		file_info(info, &s);
		return 0;
	}
	return frd_read_pre(fp, name, pre, npre, m, flags & FRS_READ_ANY_VALUES ?
	    FRD_PERM_NO : FRD_PERM_NEED);
}

int frs_matrix_read_file(struct frs_matrix *m, const char *path, int flags,
    struct frs_file_info *info, frs_error *err)
{
	const char *name;
	FILE *fp;
	enum frs_code code;
	int rc;

	if (m != NULL)
		*m = (struct frs_matrix){ 0 };
	if (info != NULL)
		*info = (struct frs_file_info){ 0 };
	if (m == NULL || path == NULL || info == NULL)
		return api_arg_err(err, "frs_matrix_read_file: NULL argument");
	if ((fp = io_open_in(path, &name)) == NULL)
		return api_lib_err(err, FRS_E_IO);
	rc = read_file(fp, name, flags, m, info, &code);
	io_close_in(fp);
	return rc < 0 ? api_lib_err(err, code) : api_ok(err);
}

int frs_prepared_write(const struct frs_matrix *m, FILE *fp,
    const char *name, const char *src, int minmap, const uint32_t *blocks,
    unsigned nblocks, frs_error *err)
{
	if (!matrix_ok(m) || fp == NULL || (blocks == NULL && nblocks > 0))
		return api_arg_err(err, "frs_prepared_write: NULL argument");
	if (nblocks > 32)
		return api_arg_err(err, "frs_prepared_write: more than 32 block "
		    "sizes");
	if (frp_write(fp, name != NULL ? name : "prepared matrix",
	    src != NULL ? src : "matrix", m, minmap, blocks, nblocks) == 0)
		return api_ok(err);
	/* Not written: the matrix or the blocks (frp_write's checks, their
	 * messages kept), the memory, or the stream. */
	if (m->dims != 2 || ((minmap || nblocks) && ((m->w & (m->w - 1)) ||
	    (m->h & (m->h - 1)))))
		return api_lib_err(err, FRS_E_ARG);
	for (unsigned b = 0; b < nblocks; b++)
		if (blocks[b] == 0 || (blocks[b] & (blocks[b] - 1)) ||
		    blocks[b] > m->w || blocks[b] > m->h)
			return api_lib_err(err, FRS_E_ARG);
	return api_lib_err(err, FRS_E_IO);
}

/* The levels of lv as the caller's. */
static void plan_levels(const struct frs_matrix *m, const struct api_lev2 *lv,
    uint64_t n, struct frs_prepared_level *levels, unsigned cap)
{
	for (unsigned l = 0; l < lv->n && l < cap; l++) {
		const struct frs_setup *t = &lv->su[l];
		uint32_t b = api_lev2_block(lv, l);
		uint64_t vals = b ? api_lists_below(t, &n, 1) : 0;
		vals = vals < m->n ? vals : m->n;
		levels[l] = (struct frs_prepared_level){ .level = t->level,
		    .ns = t->ns, .window_w = t->sw, .window_h = t->sh,
		    .block = b, .minmap = b == 0 || b < t->ns, .values = vals,
		    .from_frp = b && api_lists_from_frp(m, vals) };
	}
}

int frs_prepared_plan(const struct frs_matrix *m, const struct frs_imap *map,
    uint64_t n, const struct frs_options *opt,
    struct frs_prepared_level *levels, unsigned cap, unsigned *count,
    frs_error *err)
{
	struct frs_options o;
	struct frs_setup su;
	struct api_lev2 lv;
	int rc;

	if (count != NULL)
		*count = 0;
	if (!matrix_ok(m) || map == NULL || map->v == NULL || map->w == 0 ||
	    map->h == 0 || count == NULL || (levels == NULL && cap > 0))
		return api_arg_err(err, "frs_prepared_plan: NULL argument");
	if (n == 0)
		return api_arg_err(err, "frs_prepared_plan: n must not be 0");
	if (n > API_MAX_N)
		return api_set_err(err, FRS_E_LIMIT, "n: more than 2^40 samples");
	if ((rc = api_options(&o, opt, err)) != FRS_OK)
		return rc;
	/* The setup of a sampler's run (api_setup: seed 1, the window's
	 * sizes do not depend on it), and its levels. */
	if (frs_setup(&su, map, m, n, o.sigma, 1) < 0)
		return api_lib_err(err, m->dims != 2 ? FRS_E_ARG : FRS_E_LIMIT);
	API_MODES(&su, &o);
	if (api_lev2_make(&o, &su, map, NULL, &lv) < 0)
		return api_lib_err(err, FRS_E_LIMIT);
	plan_levels(m, &lv, n, levels, cap);
	*count = lv.n;
	api_lev2_free(&lv);
	return api_ok(err);
}
