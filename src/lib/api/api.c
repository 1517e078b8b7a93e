/*
 * The public API (src/lib/frs.h, libfrs(3)) over the library's own
 * modules.  The internal functions report through the per-thread message
 * of err.c; here it becomes a code and the caller's frs_error.
 */
#define _POSIX_C_SOURCE 200809L
#include "frs.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/api.h"
#include "api/version.h"
#include "base/datadir.h"
#include "base/err.h"
#include "sample/frscore.h"
#include "sample/frpio.h"
#include "sample/hsw.h"
#include "base/io.h"
#include "base/par.h"
#include "base/progress.h"
#include "maps/vol.h"
#include "maps/mapload.h"
#include "maps/spec.h"

/* ---- errors ---------------------------------------------------------- */

static const char *const code_names[] = {
	"FRS_OK", "FRS_E_ARG", "FRS_E_MAP", "FRS_E_BUFFER", "FRS_E_NOMEM",
	"FRS_E_IO", "FRS_E_FORMAT", "FRS_E_LIMIT", "FRS_E_CALLBACK"
};

const char *frs_code_name(int code)
{
	if (code < 0 || code >= (int)(sizeof code_names / sizeof code_names[0]))
		return "FRS_E_UNKNOWN";
	return code_names[code];
}

const char *frs_library_version(void)
{
	return FRS_VERSION;
}

/* frs_progress_fn and progress.h's progress_fn are the same type. */
void frs_set_progress(frs_progress_fn fn, void *ctx)
{
	progress_set(fn, ctx);
}

static int set_err(frs_error *err, enum frs_code code, const char *msg)
{
	if (err != NULL) {
		err->code = code;
		snprintf(err->message, sizeof err->message, "%s", msg);
	}
	return (int)code;
}

/* An argument error with a message of our own. */
static int arg_err(frs_error *err, const char *what)
{
	return set_err(err, FRS_E_ARG, what);
}

/* The library's last message as code (NOMEM when the memory ceiling or
 * an allocation failed, whatever code the caller expected else). */
static int lib_err(frs_error *err, enum frs_code code)
{
	if (frs_errkind() == FRS_ERRKIND_MEM)
		code = FRS_E_NOMEM;
	else if (frs_errkind() == FRS_ERRKIND_MAP)
		code = FRS_E_MAP;
	return set_err(err, code, frs_errmsg());
}

static int ok(frs_error *err)
{
	return set_err(err, FRS_OK, "");
}

/* FRS_E_IO when path cannot be opened for reading, else FRS_OK. */
static int readable(const char *path, frs_error *err)
{
	const char *name;
	FILE *fp = io_open_in(path, &name);

	if (fp == NULL)
		return lib_err(err, FRS_E_IO);
	io_close_in(fp);
	return FRS_OK;
}

/* ---- masks ----------------------------------------------------------- */

static int is_pow2(uint32_t v)
{
	return v != 0 && (v & (v - 1)) == 0;
}

static unsigned log2u(uint32_t v)
{
	unsigned l = 0;

	while ((1u << l) < v)
		l++;
	return l;
}

static void mask_free_parts(frs_mask *mk)
{
	for (unsigned l = 1; l < mk->nlev; l++)
		free(mk->lev[l]);
	for (unsigned b = 0; b < 32; b++) {
		frs_prep_free(&mk->lists[b]);
		frs3_prep_free(&mk->p3[b]);
	}
	while (mk->old != NULL) {
		struct old_lists *o = mk->old;
		mk->old = o->next;
		frs_prep_free(&o->p);
		free(o);
	}
	if (!mk->wrapped)
		frd_free(&mk->m);
	free(mk->frp);
	free(mk->name);
}

void frs_mask_free(frs_mask *mk)
{
	if (mk == NULL)
		return;
	mask_free_parts(mk);
	pthread_mutex_destroy(&mk->lock);
	free(mk);
}

static frs_mask *mask_new(void)
{
	frs_mask *mk = calloc(1, sizeof *mk);

	if (mk != NULL && pthread_mutex_init(&mk->lock, NULL) != 0) {
		free(mk);
		return NULL;
	}
	return mk;
}

/* Take the minmap levels of a prepared matrix read from a .frp. */
static void take_minmap(frs_mask *mk, struct frs_prep *p)
{
	mk->nlev = p->nlev;
	mk->lev[0] = mk->m.v;
	for (unsigned l = 1; l < p->nlev; l++) {
		mk->lev[l] = p->lev[l];
		p->lev[l] = NULL;
	}
	p->nlev = 1;
}

/* A .frp: the matrix and its minmap now, its sorted lists when asked. */
static int load_frp(frs_mask *mk, const char *path)
{
	struct frs_prep p;

	if (frp_read(path, &mk->m, &p, 0) < 0)
		return -1;
	take_minmap(mk, &p);
	frs_prep_free(&p);
	if ((mk->frp = strdup(path)) == NULL)
		return frs_fail("%s: out of memory", path);
	return 0;
}

/* NAME.frp for NAME.frd (the last dot after the last slash). */
static char *sibling_frp(const char *path)
{
	const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
	size_t len = dot && (!slash || dot > slash) ? (size_t)(dot - path) :
	    strlen(path);
	char *s = malloc(len + 5);

	if (s != NULL) {
		memcpy(s, path, len);
		strcpy(s + len, ".frp");
	}
	return s;
}

/* A .frd, and the prepared twin beside it when it was made from it. */
static int load_frd(frs_mask *mk, const char *path)
{
	char *sib;
	uint32_t w, h;
	uint64_t sum;
	struct frs_matrix tm;
	struct frs_prep tp;

	if (frd_read(path, &mk->m) < 0)
		return -1;
	if (mk->m.dims != 2)
		return 0;	/* prepared files are 2-D */
	sib = sibling_frp(path);
	if (sib == NULL || strcmp(sib, path) == 0 || frp_is(sib) != 1 ||
	    frp_info(sib, &w, &h, &sum) < 0) {
		free(sib);
		frs_clearerr();
		return 0;
	}
	if (sum != frd_checksum(&mk->m)) {
		snprintf(mk->note, sizeof mk->note, "%s is stale (made from "
		    "another matrix than %s); ignored", sib, path);
		free(sib);
		return 0;
	}
	/* Read it whole once: a damaged twin is noted and ignored. */
	if (frp_read(sib, &tm, &tp, 0) < 0) {
		snprintf(mk->note, sizeof mk->note, "%s; ignored", frs_errmsg());
		frs_clearerr();
		free(sib);
		return 0;
	}
	take_minmap(mk, &tp);
	mk->lev[0] = mk->m.v;
	frs_prep_free(&tp);
	frd_free(&tm);
	mk->frp = sib;
	mk->twin = 1;
	return 0;
}

int frs_mask_load(frs_mask **mask, const char *path, frs_error *err)
{
	frs_mask *mk;
	int rc;

	if (mask == NULL || path == NULL)
		return arg_err(err, "frs_mask_load: NULL argument");
	*mask = NULL;
	if (readable(path, err) != FRS_OK)
		return err ? (int)err->code : FRS_E_IO;
	if ((mk = mask_new()) == NULL)
		return set_err(err, FRS_E_NOMEM, "out of memory");
	if ((mk->name = strdup(path)) == NULL) {
		frs_mask_free(mk);
		return set_err(err, FRS_E_NOMEM, "out of memory");
	}
	rc = frp_is(path) == 1 ? load_frp(mk, path) : load_frd(mk, path);
	if (rc == 0 && frd_check_permutation(&mk->m, path) < 0)
		rc = -1;
	if (rc < 0) {
		int code = lib_err(err, FRS_E_FORMAT);
		frs_mask_free(mk);
		return code;
	}
	if (mk->nlev == 0) {
		mk->nlev = 1;
		mk->lev[0] = mk->m.v;
	}
	*mask = mk;
	return ok(err);
}

int api_default_matrix(unsigned dims, char *path, size_t cap)
{
	const char *env = getenv(dims == 3 ? "FRS_MATRIX3" : "FRS_MATRIX");
	int len;

	if (env == NULL || *env == '\0')
		return data_find(dims == 3 ? "default3.frd" : "default.frd",
		    path, cap);
	len = snprintf(path, cap, "%s", env);
	if (len < 0 || (size_t)len >= cap)
		return frs_fail("%s: %s: path too long for %zu bytes",
		    dims == 3 ? "FRS_MATRIX3" : "FRS_MATRIX", env, cap);
	return 0;
}

int frs_default_matrix(frs_mask **mask, unsigned dims, char *path,
    size_t cap, frs_error *err)
{
	char found[DATA_PATH_MAX];
	size_t len;

	if (mask != NULL)
		*mask = NULL;
	if (dims != 2 && dims != 3)
		return arg_err(err, "frs_default_matrix: dims is not 2 or 3");
	if (path != NULL && cap == 0)
		return arg_err(err, "frs_default_matrix: cap is 0");
	if (path != NULL)
		path[0] = '\0';
	if (api_default_matrix(dims, found, sizeof found) < 0) {
		char msg[sizeof err->message];

		snprintf(msg, sizeof msg, "no default %smatrix (%s)",
		    dims == 3 ? "3-D " : "", frs_errmsg());
		return set_err(err, FRS_E_IO, msg);
	}
	if (path != NULL) {
		if ((len = strlen(found)) >= cap) {
			char msg[sizeof err->message];

			snprintf(msg, sizeof msg, "%.400s: needs %zu bytes, "
			    "cap is %zu", found, len + 1, cap);
			return set_err(err, FRS_E_BUFFER, msg);
		}
		memcpy(path, found, len + 1);
	}
	if (mask != NULL)
		return frs_mask_load(mask, found, err);
	return ok(err);
}

int frs_mask_wrap(frs_mask **mask, const uint32_t *values, uint32_t width,
    uint32_t height, frs_error *err)
{
	frs_mask *mk;

	if (mask == NULL || values == NULL)
		return arg_err(err, "frs_mask_wrap: NULL argument");
	*mask = NULL;
	if (!is_pow2(width) || !is_pow2(height) ||
	    (uint64_t)width * height > FRD_MAX_ELEMS / 2)
		return arg_err(err, "frs_mask_wrap: the sides must be powers of "
		    "two, below 2^31 elements in all");
	if ((mk = mask_new()) == NULL)
		return set_err(err, FRS_E_NOMEM, "out of memory");
	mk->wrapped = 1;
	mk->m = (struct frs_matrix){ 2, width, height, 1,
	    (size_t)width * height, NULL, (uint32_t *)values };
	if (frd_check_permutation(&mk->m, "frs_mask_wrap") < 0) {
		frs_mask_free(mk);
		return lib_err(err, FRS_E_ARG);
	}
	mk->nlev = 1;
	mk->lev[0] = mk->m.v;
	*mask = mk;
	return ok(err);
}

unsigned frs_mask_dims(const frs_mask *mk)
{
	return mk != NULL ? mk->m.dims : 0;
}

void frs_mask_size3(const frs_mask *mk, uint32_t *width, uint32_t *height,
    uint32_t *depth)
{
	frs_mask_size(mk, width, height);
	if (depth != NULL)
		*depth = mk ? mk->m.d : 0;
}

void frs_mask_size(const frs_mask *mk, uint32_t *width, uint32_t *height)
{
	if (width != NULL)
		*width = mk ? mk->m.w : 0;
	if (height != NULL)
		*height = mk ? mk->m.h : 0;
}

const char *frs_mask_note(const frs_mask *mk)
{
	return mk != NULL && mk->note[0] ? mk->note : NULL;
}

/* Keep the lists p in slot l; the lists there before (too short for
 * this run) stay until the mask is freed. */
static int keep_lists(frs_mask *mk, unsigned l, struct frs_prep *p)
{
	if (mk->lists[l].sval != NULL) {
		struct old_lists *o = malloc(sizeof *o);
		if (o == NULL) {
			frs_prep_free(p);
			return frs_fail("out of memory");
		}
		o->p = mk->lists[l];
		o->next = mk->old;
		mk->old = o;
	}
	mk->lists[l] = *p;
	mk->lists[l].m = &mk->m;
	mk->lists[l].nlev = 0;
	mk->lists[l].lev[0] = NULL;
	return 0;
}

/* Sorted lists of block size b holding the values below `below`: from
 * the .frp when it has them and the run needs half the values or more
 * (reading and checking complete lists costs more than making the few a
 * smaller run needs), made here otherwise.  Damaged lists are an error
 * in a .frp loaded as such; in the twin of a .frd they are noted and the
 * twin is dropped.  Called with the lock held.  0; -1 with a message, 1
 * with one that names the .frp already. */
static int make_lists(frs_mask *mk, uint32_t b, uint64_t below)
{
	unsigned l = log2u(b);
	struct frs_prep p;

	if (mk->frp != NULL && api_lists_from_frp(&mk->m, below)) {
		struct frs_matrix tm;
		if (frp_read(mk->frp, &tm, &p, b) == 0) {
			frd_free(&tm);
			if (p.block == b) {
				for (unsigned k = 1; k < p.nlev; k++)
					free(p.lev[k]);
				return keep_lists(mk, l, &p);
			}
			frs_prep_free(&p);
			mk->made = b;
		} else if (!mk->twin) {
			return 1;	/* the message names the .frp */
		} else {
			snprintf(mk->note, sizeof mk->note, "%s; ignored",
			    frs_errmsg());
			free(mk->frp);
			mk->frp = NULL;
		}
		frs_clearerr();		/* make them instead */
	}
	if (frs_prepare_below(&p, &mk->m, 0, b, below) < 0)
		return -1;
	return keep_lists(mk, l, &p);
}

static int make_minmap(frs_mask *mk)
{
	struct frs_prep p;

	if (frs_prepare(&p, &mk->m, 1, 0) < 0)
		return -1;
	take_minmap(mk, &p);
	frs_prep_free(&p);
	return 0;
}

int api_mask_prep(const frs_mask *cmk, int minmap, uint32_t block,
    uint64_t below, struct frs_prep *view)
{
	frs_mask *mk = (frs_mask *)cmk;	/* only the lazy parts change */
	const struct frs_prep *have = block ? &mk->lists[log2u(block)] : NULL;
	int rc = 0;

	pthread_mutex_lock(&mk->lock);
	if (minmap && mk->nlev <= 1)
		rc = make_minmap(mk);
	if (rc == 0 && block && (have->sval == NULL || have->below < below))
		rc = make_lists(mk, block, below);
	/* Every message names the matrix, once (a .frp's own do). */
	if (rc < 0 && mk->name != NULL)
		frs_fail_context(mk->name);
	if (rc != 0)
		rc = -1;
	memset(view, 0, sizeof *view);
	view->m = &mk->m;
	view->nlev = minmap ? mk->nlev : 1;
	for (unsigned l = 0; l < view->nlev; l++)
		view->lev[l] = mk->lev[l];
	if (block && rc == 0) {
		view->block = block;
		view->sval = have->sval;
		view->sidx = have->sidx;
		view->soff = have->soff;
		view->below = have->below;
	}
	pthread_mutex_unlock(&mk->lock);
	return rc;
}

const struct frs_matrix *api_mask_matrix(const frs_mask *mk)
{
	return &mk->m;
}

/* ---- maps ------------------------------------------------------------ */

int frs_map_load(const char *src, uint32_t width, uint32_t height,
    float **map, uint32_t *width_out, uint32_t *height_out, frs_error *err)
{
	struct frs_imap m;
	float *f;

	if (src == NULL || map == NULL || width_out == NULL ||
	    height_out == NULL)
		return arg_err(err, "frs_map_load: NULL argument");
	*map = NULL;
	if ((width == 0) != (height == 0))
		return arg_err(err, "frs_map_load: width and height are both "
		    "0 or both set");
	if (!imap_is_spec(src) && readable(src, err) != FRS_OK)
		return err ? (int)err->code : FRS_E_IO;
	/* Negative values (lossy EXR) become zero, as in frs-sample(1). */
	if (imap_load(src, width, height, 0, &m) < 0)
		return lib_err(err, imap_is_spec(src) ? FRS_E_ARG :
		    FRS_E_FORMAT);
	f = malloc((size_t)m.w * m.h * sizeof *f);
	if (f == NULL) {
		imap_free(&m);
		return set_err(err, FRS_E_NOMEM, "out of memory");
	}
	for (size_t i = 0; i < (size_t)m.w * m.h; i++)
		f[i] = (float)m.v[i];
	*map = f;
	*width_out = m.w;
	*height_out = m.h;
	imap_free(&m);
	return ok(err);
}

void frs_map_free(float *map)
{
	free(map);
}

/* The caller's map as the library's (doubles, validated: no NaN, no
 * infinity, no negative value, not all zero).  map NULL: constant 1. */
static int copy_map(struct frs_imap *m, const float *f, const double *d,
    uint32_t w, uint32_t h, size_t stride, int flags, frs_error *err)
{
	if (w == 0 || h == 0)
		return arg_err(err, "map: width and height must not be 0");
	if (stride == 0)
		stride = w;
	if (stride < w)
		return arg_err(err, "map: stride is less than the width");
	if (imap_alloc(m, w, h) < 0)
		return lib_err(err, FRS_E_LIMIT);
	for (uint32_t y = 0; y < h; y++)
		for (uint32_t x = 0; x < w; x++)
			m->v[(size_t)y * w + x] = f ? (double)f[y * stride + x] :
			    d ? d[y * stride + x] : 1.0;
	if (imap_validate(m, "map", flags) < 0) {
		imap_free(m);
		return lib_err(err, FRS_E_MAP);
	}
	return FRS_OK;
}

/* ---- samplers -------------------------------------------------------- */

void frs_options_init(struct frs_options *opt)
{
	opt->sigma = 8.0;
	opt->algorithm = FRS_ALG_SORTED;
	opt->jitter = FRS_JIT_NONE;
	opt->rule = FRS_RULE_UNBIASED;
	opt->threads = 1;
	opt->tiling = FRS_TILING_PLAIN;
}

static int check_options(const struct frs_options *o, frs_error *err)
{
	if (!(o->sigma >= 1.0 && o->sigma <= 1e6))
		return arg_err(err, "options: sigma must lie in [1, 1e6]");
	if ((unsigned)o->algorithm > FRS_ALG_LEVEL2)
		return arg_err(err, "options: unknown algorithm");
	if ((unsigned)o->jitter > FRS_JIT_RANDOM)
		return arg_err(err, "options: unknown jitter");
	if ((unsigned)o->rule > FRS_RULE_EXACT)
		return arg_err(err, "options: unknown rule");
	if ((unsigned)o->tiling > FRS_TILING_PLAIN)
		return arg_err(err, "options: unknown tiling");
	if (o->threads < 0 || o->threads > 1024)
		return arg_err(err, "options: threads must lie in 0 .. 1024");
	return FRS_OK;
}

static int sampler_new(frs_sampler **sp, const frs_mask *mask,
    const float *f, const double *d, uint32_t w, uint32_t h, size_t stride,
    const struct frs_options *opt, frs_error *err)
{
	frs_sampler *s;
	int rc;

	if (sp == NULL || mask == NULL)
		return arg_err(err, "frs_sampler_new: NULL argument");
	*sp = NULL;
	if (mask->m.dims != 2)
		return arg_err(err, "frs_sampler_new: a 3-D mask samples "
		    "volumes (frs_sampler3_new)");
	if ((s = calloc(1, sizeof *s)) == NULL)
		return set_err(err, FRS_E_NOMEM, "out of memory");
	if (opt != NULL)
		s->opt = *opt;
	else
		frs_options_init(&s->opt);
	if ((rc = check_options(&s->opt, err)) != FRS_OK ||
	    (rc = copy_map(&s->map, f, d, w, h, stride, IMAP_STRICT,
	    err)) != FRS_OK) {
		free(s);
		return rc;
	}
	s->mask = mask;
	*sp = s;
	return ok(err);
}

int frs_sampler_new(frs_sampler **sampler, const frs_mask *mask,
    const float *map, uint32_t width, uint32_t height, size_t stride,
    const struct frs_options *opt, frs_error *err)
{
	return sampler_new(sampler, mask, map, NULL, width, height, stride,
	    opt, err);
}

int frs_sampler_new_f64(frs_sampler **sampler, const frs_mask *mask,
    const double *map, uint32_t width, uint32_t height, size_t stride,
    const struct frs_options *opt, frs_error *err)
{
	return sampler_new(sampler, mask, NULL, map, width, height, stride,
	    opt, err);
}

void frs_sampler_free(frs_sampler *s)
{
	if (s == NULL)
		return;
	imap_free(&s->map);
	free(s);
}

static const enum frs_algo algos[] = {
	FRS_SORTED, FRS_NAIVE, FRS_STACK, FRS_LEVEL1, FRS_LEVEL2
};

/* FRS_RULE_EXACT is the unbiased rule with its taus moved. */
static enum frs_rule rule_of(const struct frs_options *o)
{
	return o->rule == FRS_RULE_THESIS ? FRS_THESIS : FRS_UNBIASED;
}

static enum frs_jitter jitter_of(const struct frs_options *o)
{
	return o->jitter == FRS_JIT_HALTON ? FRS_JITTER_HALTON :
	    o->jitter == FRS_JIT_RANDOM ? FRS_JITTER_RANDOM : FRS_JITTER_NONE;
}

int api_setup(const frs_sampler *s, uint64_t n, uint64_t seed,
    struct frs_setup *su)
{
	if (frs_setup(su, &s->map, &s->mask->m, n, s->opt.sigma, seed) < 0)
		return -1;
	su->rule = rule_of(&s->opt);
	su->jitter = jitter_of(&s->opt);
	su->tiles = s->opt.tiling == FRS_TILING_PLAIN ? FRS_TILES_PLAIN :
	    s->opt.tiling == FRS_TILING_SHUFFLED ? FRS_TILES_SHUFFLE :
	    frs_tiles_auto(su);
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

/* The most samples one call makes, as frs-sample -n allows: past it
 * the window alone would take hours to threshold. */
#define MAX_N ((uint64_t)1 << 40)

static int check_steps(const uint64_t *steps, unsigned nsteps,
    frs_error *err)
{
	if (steps == NULL || nsteps == 0 || nsteps > 16)
		return arg_err(err, "steps: 1 to 16 counts");
	for (unsigned k = 0; k < nsteps; k++)
		if (steps[k] == 0 || (k > 0 && steps[k] <= steps[k - 1]))
			return arg_err(err, "steps: counts must be positive "
			    "and increase");
	if (steps[nsteps - 1] > MAX_N)
		return set_err(err, FRS_E_LIMIT, "n: more than 2^40 samples");
	return FRS_OK;
}

/* The setup and prepared matrix of a run for steps with this seed, and
 * the sampler's thread count set.  A code. */
static int begin_run(const frs_sampler *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, struct frs_setup *su,
    struct frs_prep *view, frs_error *err)
{
	enum frs_algo a;
	int minmap, rc;
	uint32_t block = 0;

	if (s == NULL)
		return arg_err(err, "NULL sampler");
	a = algos[s->opt.algorithm];
	minmap = a == FRS_STACK || a == FRS_LEVEL1 || a == FRS_LEVEL2;
	if ((rc = check_steps(steps, nsteps, err)) != FRS_OK)
		return rc;
	frs_set_threads(s->opt.threads > 0 ? s->opt.threads : 1);
	if (api_setup_steps(s, steps, nsteps, seed, su) < 0)
		return lib_err(err, FRS_E_LIMIT);
	if (a == FRS_SORTED && api_sorted_minmap(su))
		minmap = 1;
	if (a == FRS_SORTED)
		block = api_sorted_block(su);
	if (api_mask_prep(s->mask, minmap, block, a == FRS_SORTED ?
	    api_lists_below(su, steps, nsteps) : 0, view) < 0)
		return lib_err(err, FRS_E_FORMAT);
	return FRS_OK;
}

/* Threshold the window for steps with this seed; r and su for the
 * caller.  A code. */
static int run(const frs_sampler *s, const uint64_t *steps, unsigned nsteps,
    uint64_t seed, int count_only, struct frs_setup *su,
    struct frs_result *r, frs_error *err)
{
	struct frs_prep view;
	int rc = begin_run(s, steps, nsteps, seed, su, &view, err);

	if (rc != FRS_OK)
		return rc;
	if (frs_sample(su, &s->map, &view, algos[s->opt.algorithm], steps,
	    nsteps, count_only, r) < 0)
		return lib_err(err, FRS_E_LIMIT);
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
	    algos[s->opt.algorithm] == FRS_SORTED;
}

/* The count of every chunk: at[c] the first sample of chunk c, at[nchunk]
 * the total.  A code; *at is the caller's to free. */
static int chunk_starts(const frs_sampler *s, const struct frs_setup *su,
    const struct frs_prep *view, uint64_t **at, frs_error *err)
{
	struct frs_result r;
	uint64_t nc = frs_nchunks(su);

	if ((*at = malloc((nc + 1) * sizeof **at)) == NULL)
		return set_err(err, FRS_E_NOMEM, "out of memory");
	if (frs_sample(su, &s->map, view, FRS_SORTED, &su->n, 1, 1, &r) < 0) {
		free(*at);
		*at = NULL;
		return lib_err(err, FRS_E_LIMIT);
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
		rc = set_err(err, FRS_E_NOMEM, "out of memory");
	/* One team of threads for all the waves: starting threads for each
	 * wave took a third of the thresholding at 2^24 on two threads. */
	else if (frs_team_start() < 0)
		rc = lib_err(err, FRS_E_NOMEM);
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
			rc = lib_err(err, FRS_E_LIMIT);
		else if (out != NULL && out(octx, at[c0], at[c1] - at[c0]) != 0)
			rc = set_err(err, FRS_E_CALLBACK, "stopped by the callback");
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
		return set_err(err, FRS_E_BUFFER, "frs_draw: the buffer is "
		    "too small; *count says how many samples there are");
	}
	d = (struct direct){ &su, &s->map, at, 0, xy, pdf };
	rc = direct_waves(s, &su, &view, at, &d, 0, NULL, NULL, err);
	free(at);
	return rc != FRS_OK ? rc : ok(err);
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

int api_lists_from_frp(const struct frs_matrix *m, uint64_t below)
{
	return below >= m->n / 2;
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

/* Visit the elements in output order: the steps in turn, each in row
 * order; fn returns non-zero to stop. */
static int each_elem(const struct frs_result *r, unsigned nsteps,
    int (*fn)(void *, const struct frs_elem *), void *ctx)
{
	for (uint32_t step = 0; step < nsteps; step++)
		for (uint64_t c = 0; c < r->nchunk; c++)
			for (uint64_t i = 0; i < r->chunk[c].n; i++) {
				const struct frs_elem *e = &r->chunk[c].e[i];
				if ((nsteps == 1 || e->step == step) &&
				    fn(ctx, e) != 0)
					return -1;
			}
	return 0;
}

struct put {
	const struct frs_setup *su;
	const struct frs_imap *map;
	double *xy, *pdf;
	uint32_t *step;
	size_t k;
};

static int put_one(void *ctx, const struct frs_elem *e)
{
	struct put *p = ctx;

	frs_point(p->su, e, &p->xy[2 * p->k], &p->xy[2 * p->k + 1]);
	if (p->pdf != NULL)
		p->pdf[p->k] = api_pdf(p->su, p->map, e);
	if (p->step != NULL)
		p->step[p->k] = e->step;
	p->k++;
	return 0;
}

static uint64_t stored(const struct frs_result *r)
{
	uint64_t n = 0;

	for (uint64_t c = 0; c < r->nchunk; c++)
		n += r->chunk[c].n;
	return n;
}

int frs_draw_progressive(const frs_sampler *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, double *xy, double *pdf,
    uint32_t *step, size_t cap, size_t *count, frs_error *err)
{
	struct frs_setup su;
	struct frs_result r;
	struct put p;
	uint64_t n;
	int rc;

	if (count == NULL || (xy == NULL && cap > 0))
		return arg_err(err, "frs_draw: NULL argument");
	*count = 0;
	if (direct_ok(s, steps, nsteps))
		return draw_direct(s, steps[0], seed, xy, pdf, cap, count, err);
	if ((rc = run(s, steps, nsteps, seed, 0, &su, &r, err)) != FRS_OK)
		return rc;
	n = stored(&r);
	*count = (size_t)n;
	if (n > cap) {
		frs_result_free(&r);
		return set_err(err, FRS_E_BUFFER, "frs_draw: the buffer is "
		    "too small; *count says how many samples there are");
	}
	p = (struct put){ &su, &s->map, xy, pdf, step, 0 };
	each_elem(&r, nsteps, put_one, &p);
	frs_result_free(&r);
	return ok(err);
}

int frs_draw(const frs_sampler *s, uint64_t n, uint64_t seed, double *xy,
    double *pdf, size_t cap, size_t *count, frs_error *err)
{
	return frs_draw_progressive(s, &n, 1, seed, xy, pdf, NULL, cap, count,
	    err);
}

int frs_count(const frs_sampler *s, uint64_t n, uint64_t seed,
    uint64_t *count, frs_error *err)
{
	struct frs_setup su;
	struct frs_result r;
	int rc;

	if (count == NULL)
		return arg_err(err, "frs_count: NULL argument");
	*count = 0;
	if ((rc = run(s, &n, 1, seed, 1, &su, &r, err)) != FRS_OK)
		return rc;
	*count = r.count;
	frs_result_free(&r);
	return ok(err);
}

/* Batches for frs_draw_each. */
#define BATCH 4096
struct batch {
	struct put p;
	double xy[2 * BATCH], pdf[BATCH];
	uint32_t step[BATCH];
	frs_point_fn fn;
	void *ctx;
	uint64_t total;
};

static int flush(struct batch *b)
{
	int rc = b->p.k ? b->fn(b->ctx, b->xy, b->p.pdf, b->p.step, b->p.k,
	    b->total) : 0;

	b->p.k = 0;
	return rc;
}

static int batch_one(void *ctx, const struct frs_elem *e)
{
	struct batch *b = ctx;

	put_one(&b->p, e);
	return b->p.k == BATCH ? flush(b) : 0;
}

/* One step: the chunks' elements converted a batch at a time. */
static int each_run(struct batch *b, const struct frs_result *r)
{
	for (uint64_t c = 0; c < r->nchunk; c++) {
		const struct frs_elem *e = r->chunk[c].e;
		uint64_t left = r->chunk[c].n;
		while (left > 0) {
			size_t k = BATCH - b->p.k;
			k = left < k ? (size_t)left : k;
			frs_points(b->p.su, e, k, b->xy + 2 * b->p.k);
			for (size_t i = 0; b->p.pdf != NULL && i < k; i++)
				b->pdf[b->p.k + i] = api_pdf(b->p.su, b->p.map, &e[i]);
			b->p.k += k;
			e += k;
			left -= k;
			if (b->p.k == BATCH && flush(b) != 0)
				return -1;
		}
	}
	return 0;
}

/* A wave's samples (from xy[0], pdf[0]) to the callback, BATCH at a
 * time. */
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
	for (uint64_t i = 0; i < n; i += BATCH) {
		size_t k = n - i < BATCH ? (size_t)(n - i) : BATCH;
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
		rc = set_err(err, FRS_E_NOMEM, "out of memory");
	d = (struct direct){ &su, &s->map, at, 0, xy, pdf };
	w = (struct wave_cb){ fn, ctx, at[frs_nchunks(&su)], xy, pdf };
	if (rc == FRS_OK)
		rc = direct_waves(s, &su, &view, at, &d, 1, wave_out, &w, err);
	free(xy);
	free(pdf);
	free(at);
	return rc != FRS_OK ? rc : ok(err);
}

int api_result_each(const struct frs_setup *su, const struct frs_imap *map,
    const struct frs_result *r, unsigned nsteps, int want_pdf,
    frs_point_fn fn, void *ctx)
{
	struct batch *b = malloc(sizeof *b);
	int stop;

	if (b == NULL)
		return FRS_E_NOMEM;
	b->p = (struct put){ su, map, b->xy, want_pdf ? b->pdf : NULL,
	    nsteps > 1 ? b->step : NULL, 0 };
	b->fn = fn;
	b->ctx = ctx;
	b->total = stored(r);
	if (nsteps == 1)
		stop = each_run(b, r) < 0 || flush(b) != 0;
	else
		stop = each_elem(r, nsteps, batch_one, b) < 0 || flush(b) != 0;
	free(b);
	return stop ? FRS_E_CALLBACK : FRS_OK;
}

int frs_draw_each(const frs_sampler *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, int want_pdf, frs_point_fn fn,
    void *ctx, frs_error *err)
{
	struct frs_setup su;
	struct frs_result r;
	int rc;

	if (fn == NULL)
		return arg_err(err, "frs_draw_each: NULL callback");
	if (direct_ok(s, steps, nsteps))
		return each_direct(s, steps[0], seed, want_pdf, fn, ctx, err);
	if ((rc = run(s, steps, nsteps, seed, 0, &su, &r, err)) != FRS_OK)
		return rc;
	rc = api_result_each(&su, &s->map, &r, nsteps, want_pdf, fn, ctx);
	frs_result_free(&r);
	if (rc == FRS_E_NOMEM)
		return set_err(err, (enum frs_code)rc, "out of memory");
	if (rc == FRS_E_CALLBACK)
		return set_err(err, (enum frs_code)rc, "stopped by the callback");
	return ok(err);
}

int frs_sampler_info(const frs_sampler *s, uint64_t n, uint64_t seed,
    struct frs_info *info, frs_error *err)
{
	struct frs_setup su;

	if (s == NULL || info == NULL)
		return arg_err(err, "frs_sampler_info: NULL argument");
	if (n == 0)
		return arg_err(err, "frs_sampler_info: n must not be 0");
	if (n > MAX_N)
		return set_err(err, FRS_E_LIMIT, "n: more than 2^40 samples");
	frs_set_threads(s->opt.threads > 0 ? s->opt.threads : 1);
	if (api_setup_steps(s, &n, 1, seed, &su) < 0)
		return lib_err(err, FRS_E_LIMIT);
	*info = (struct frs_info){ su.ns, su.sw, su.sh, su.wx, su.wy, su.tau,
	    su.mean, su.max, frs_unique(&su) };
	return ok(err);
}

/* ---- three dimensions ------------------------------------------------ */

/* The caller's volume, x fastest, validated like a map; NULL: constant. */
static int copy_vol(struct frs_vol *v, const float *f, const double *d,
    uint32_t w, uint32_t h, uint32_t dd, frs_error *err)
{
	if (w == 0 || h == 0 || dd == 0)
		return arg_err(err, "volume: width, height and depth must not "
		    "be 0");
	if (vol_alloc(v, w, h, dd) < 0)
		return lib_err(err, FRS_E_LIMIT);
	for (uint64_t i = 0; i < (uint64_t)w * h * dd; i++)
		v->v[i] = f ? (double)f[i] : d ? d[i] : 1.0;
	if (vol_validate(v, "volume", IMAP_STRICT) < 0) {
		vol_free(v);
		return lib_err(err, FRS_E_MAP);
	}
	return FRS_OK;
}

static int sampler3_new(frs_sampler3 **sp, const frs_mask *mask,
    const float *f, const double *d, uint32_t w, uint32_t h, uint32_t dd,
    const struct frs_options *opt, frs_error *err)
{
	frs_sampler3 *s;
	int rc;

	if (sp == NULL || mask == NULL)
		return arg_err(err, "frs_sampler3_new: NULL argument");
	*sp = NULL;
	if (mask->m.dims != 3)
		return arg_err(err, "frs_sampler3_new: a 2-D mask samples maps "
		    "(frs_sampler_new)");
	if ((s = calloc(1, sizeof *s)) == NULL)
		return set_err(err, FRS_E_NOMEM, "out of memory");
	if (opt != NULL)
		s->opt = *opt;
	else
		frs_options_init(&s->opt);
	rc = check_options(&s->opt, err);
	if (rc == FRS_OK && s->opt.algorithm != FRS_ALG_SORTED &&
	    s->opt.algorithm != FRS_ALG_NAIVE)
		rc = arg_err(err, "options: 3-D sampling has the naive and "
		    "sorted algorithms");
	if (rc != FRS_OK ||
	    (rc = copy_vol(&s->vol, f, d, w, h, dd, err)) != FRS_OK) {
		free(s);
		return rc;
	}
	s->mask = mask;
	*sp = s;
	return ok(err);
}

int frs_sampler3_new(frs_sampler3 **sampler, const frs_mask *mask,
    const float *volume, uint32_t width, uint32_t height, uint32_t depth,
    const struct frs_options *opt, frs_error *err)
{
	return sampler3_new(sampler, mask, volume, NULL, width, height, depth,
	    opt, err);
}

int frs_sampler3_new_f64(frs_sampler3 **sampler, const frs_mask *mask,
    const double *volume, uint32_t width, uint32_t height, uint32_t depth,
    const struct frs_options *opt, frs_error *err)
{
	return sampler3_new(sampler, mask, NULL, volume, width, height, depth,
	    opt, err);
}

void frs_sampler3_free(frs_sampler3 *s)
{
	if (s == NULL)
		return;
	vol_free(&s->vol);
	free(s);
}

/* The 3-D sorted lists of block size b (0: none), made on first use and
 * kept in the mask. */
static int mask_prep3(const frs_mask *cmk, uint32_t b, struct frs3_prep *view)
{
	frs_mask *mk = (frs_mask *)cmk;	/* only the lazy parts change */
	unsigned l = log2u(b);
	int rc = 0;

	memset(view, 0, sizeof *view);
	view->m = &mk->m;
	if (b == 0)
		return 0;
	pthread_mutex_lock(&mk->lock);
	if (mk->p3[l].block == 0)
		rc = frs3_prepare(&mk->p3[l], &mk->m, b);
	if (rc == 0)
		*view = mk->p3[l];
	pthread_mutex_unlock(&mk->lock);
	return rc;
}

static int run3(const frs_sampler3 *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, int count_only, struct frs3_setup *su,
    struct frs3_result *r, frs_error *err)
{
	enum frs_algo a;
	struct frs3_prep view;
	int rc;

	if (s == NULL)
		return arg_err(err, "NULL sampler");
	a = s->opt.algorithm == FRS_ALG_NAIVE ? FRS_NAIVE : FRS_SORTED;
	if ((rc = check_steps(steps, nsteps, err)) != FRS_OK)
		return rc;
	frs_set_threads(s->opt.threads > 0 ? s->opt.threads : 1);
	if (frs3_setup(su, &s->vol, &s->mask->m, steps[nsteps - 1],
	    s->opt.sigma, seed) < 0)
		return lib_err(err, FRS_E_LIMIT);
	su->rule = rule_of(&s->opt);
	su->jitter = jitter_of(&s->opt);
	su->tiles = s->opt.tiling == FRS_TILING_PLAIN ? FRS_TILES_PLAIN :
	    s->opt.tiling == FRS_TILING_SHUFFLED ? FRS_TILES_SHUFFLE :
	    frs3_tiles_auto(su);
	if (mask_prep3(s->mask, a == FRS_SORTED ? frs3_block(su) : 0,
	    &view) < 0)
		return lib_err(err, FRS_E_FORMAT);
	if (s->opt.rule == FRS_RULE_EXACT &&
	    frs3_exact(su, &s->vol, &view, steps, nsteps) < 0)
		return lib_err(err, FRS_E_LIMIT);
	if (frs3_sample(su, &s->vol, &view, a, steps, nsteps, count_only, r) < 0)
		return lib_err(err, FRS_E_LIMIT);
	return FRS_OK;
}

/* frs_draw3's output, one element at a time. */
struct put3 {
	const struct frs3_setup *su;
	const struct frs_vol *vol;
	double *xyz, *pdf;
	uint32_t *step;
	size_t k;
};

static int put3_one(void *ctx, const struct frs3_elem *e)
{
	struct put3 *p = ctx;

	frs3_point(p->su, e, &p->xyz[3 * p->k]);
	if (p->pdf != NULL)
		p->pdf[p->k] = frs3_pdf(p->su, p->vol, e);
	if (p->step != NULL)
		p->step[p->k] = e->step;
	p->k++;
	return 0;
}

int frs_draw3_progressive(const frs_sampler3 *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, double *xyz, double *pdf,
    uint32_t *step, size_t cap, size_t *count, frs_error *err)
{
	struct frs3_setup su;
	struct frs3_result r;
	struct put3 p;
	uint64_t n = 0;
	int rc;

	if (count == NULL || (xyz == NULL && cap > 0))
		return arg_err(err, "frs_draw3: NULL argument");
	*count = 0;
	if ((rc = run3(s, steps, nsteps, seed, 0, &su, &r, err)) != FRS_OK)
		return rc;
	for (uint64_t c = 0; c < r.nchunk; c++)
		n += r.chunk[c].n;
	*count = (size_t)n;
	if (n > cap) {
		frs3_result_free(&r);
		return set_err(err, FRS_E_BUFFER, "frs_draw3: the buffer is "
		    "too small; *count says how many samples there are");
	}
	p = (struct put3){ &su, &s->vol, xyz, pdf, step, 0 };
	frs3_each(&r, nsteps, put3_one, &p);
	frs3_result_free(&r);
	return ok(err);
}

int frs_draw3(const frs_sampler3 *s, uint64_t n, uint64_t seed, double *xyz,
    double *pdf, size_t cap, size_t *count, frs_error *err)
{
	return frs_draw3_progressive(s, &n, 1, seed, xyz, pdf, NULL, cap, count,
	    err);
}

int frs_count3(const frs_sampler3 *s, uint64_t n, uint64_t seed,
    uint64_t *count, frs_error *err)
{
	struct frs3_setup su;
	struct frs3_result r;
	int rc;

	if (count == NULL)
		return arg_err(err, "frs_count3: NULL argument");
	*count = 0;
	if ((rc = run3(s, &n, 1, seed, 1, &su, &r, err)) != FRS_OK)
		return rc;
	*count = r.count;
	frs3_result_free(&r);
	return ok(err);
}

/* ---- HSW ------------------------------------------------------------- */

static int hsw_new(frs_hsw **hp, const float *f, const double *d,
    uint32_t w, uint32_t h, size_t stride, frs_error *err)
{
	frs_hsw *hw;
	int rc;

	if (hp == NULL)
		return arg_err(err, "frs_hsw_new: NULL argument");
	*hp = NULL;
	if ((hw = calloc(1, sizeof *hw)) == NULL)
		return set_err(err, FRS_E_NOMEM, "out of memory");
	/* Negative values count as zero, as in the quadtree itself. */
	if ((rc = copy_map(&hw->map, f, d, w, h, stride, 0, err)) != FRS_OK) {
		free(hw);
		return rc;
	}
	if (hsw_build(&hw->t, &hw->map) < 0) {
		rc = lib_err(err, FRS_E_LIMIT);
		imap_free(&hw->map);
		free(hw);
		return rc;
	}
	*hp = hw;
	return ok(err);
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
		return arg_err(err, "frs_hsw_warp: NULL argument");
	if (threads < 0 || threads > 1024)
		return arg_err(err, "frs_hsw_warp: threads must lie in 0 .. "
		    "1024");
	for (size_t i = 0; i < 2 * n; i++)
		if (!(in[i] >= 0.0 && in[i] < 1.0))
			return arg_err(err, "frs_hsw_warp: a point lies outside "
			    "[0,1)^2");
	frs_set_threads(threads > 0 ? threads : 1);
	if (hsw_warp_points(&hw->t, in, out, n) < 0)
		return lib_err(err, FRS_E_LIMIT);
	if (pdf != NULL)
		api_hsw_pdf(&hw->t, &hw->map, out, pdf, n);
	return ok(err);
}

int frs_hsw_draw(const frs_hsw *hw, enum frs_hsw_input input, uint64_t n,
    uint64_t seed, double *xy, double *pdf, int threads, frs_error *err)
{
	static const enum hsw_input kinds[] = {
		HSW_RANDOM, HSW_REGULAR, HSW_JITTERED, HSW_HALTON, HSW_HAMMERSLEY
	};
	struct hsw_source src = { HSW_HALTON, n, seed, NULL };

	if (hw == NULL || (xy == NULL && n > 0))
		return arg_err(err, "frs_hsw_draw: NULL argument");
	if ((unsigned)input > FRS_HSW_HAMMERSLEY)
		return arg_err(err, "frs_hsw_draw: unknown input set");
	if (threads < 0 || threads > 1024)
		return arg_err(err, "frs_hsw_draw: threads must lie in 0 .. "
		    "1024");
	/* The set made and warped chunk by chunk, as frs_hsw_warp would
	 * warp it. */
	src.kind = kinds[input];
	frs_set_threads(threads > 0 ? threads : 1);
	if (hsw_sample(&hw->t, &src, NULL, 0, n, xy) < 0)
		return lib_err(err, FRS_E_LIMIT);
	if (pdf != NULL)
		api_hsw_pdf(&hw->t, &hw->map, xy, pdf, (size_t)n);
	return ok(err);
}
