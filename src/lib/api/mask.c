/*
 * Masks (frs.h's threshold matrices): loading a .frd with its prepared
 * twin or a .frp, wrapping the caller's values, and the parts made on
 * first use (minmap, sorted lists in 2-D and 3-D) under the mask's lock.
 */
#define _POSIX_C_SOURCE 200809L
#include "frs.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/api.h"
#include "base/datadir.h"
#include "base/err.h"
#include "base/io.h"
#include "base/num.h"
#include "formats/frdio.h"
#include "sample/frpio.h"

/* Forget the prepared file (and close it). */
static void drop_frp(frs_mask *mk)
{
	if (mk->frp_fp != NULL)
		fclose(mk->frp_fp);
	mk->frp_fp = NULL;
	free(mk->frp);
	mk->frp = NULL;
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
	drop_frp(mk);
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

/* A .frp from fp (its first npre bytes in pre): the matrix and its
 * minmap now, its sorted lists when asked (from fp, kept open, when a
 * regular file). */
static int load_frp(frs_mask *mk, FILE *fp, const char *path,
    const unsigned char *pre, size_t npre)
{
	struct frs_prep p;

	if (frp_read_pre(fp, path, pre, npre, &mk->m, &p, 0) < 0)
		return -1;
	take_minmap(mk, &p);
	frs_prep_free(&p);
	if ((mk->frp = strdup(path)) == NULL)
		return frs_fail("%s: out of memory", path);
	if (io_file_size(fp) >= 0)
		mk->frp_fp = fp;
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

/* The prepared twin beside the 2-D .frd at path, when it was made from
 * its matrix: opened and read whole once, a stale or damaged one noted
 * and ignored. */
static void load_twin(frs_mask *mk, const char *path)
{
	char *sib = sibling_frp(path);
	struct frs_prep tp;
	int rc = sib == NULL || strcmp(sib, path) == 0 ? 1 :
	    frp_read_twin(sib, &mk->m, &tp, &mk->frp_fp);

	if (rc == 2)
		snprintf(mk->note, sizeof mk->note, "%s is stale (made from "
		    "another matrix than %s); ignored", sib, path);
	if (rc < 0) {
		snprintf(mk->note, sizeof mk->note, "%s; ignored", frs_errmsg());
		frs_clearerr();
	}
	if (rc != 0) {
		free(sib);
		return;
	}
	take_minmap(mk, &tp);
	frs_prep_free(&tp);
	mk->frp = sib;
	mk->twin = 1;
}

/* The matrix at path, opened once: a .frp (a named file that starts
 * with its magic) or a .frd, whose values one pass checks, a
 * permutation required (frd_read_pre's message names the stream as
 * name).  *dims: what a .frd header says, also when the rest fails. */
static int read_matrix(frs_mask *mk, FILE *fp, const char *name,
    const char *path, unsigned *dims)
{
	unsigned char h[FRD_HEADER];
	size_t got = fread(h, 1, sizeof h, fp);

	if (got == sizeof h && memcmp(h, FRD_MAGIC, 8) == 0)
		*dims = io_get_u32(h + 12);
	if (fp != stdin && got >= 8 && memcmp(h, FRP_MAGIC, 8) == 0)
		return load_frp(mk, fp, path, h, got);
	return frd_read_pre(fp, name, h, got, &mk->m, FRD_PERM_NEED);
}

int frs_mask_load_dims(frs_mask **mask, const char *path, unsigned *dims,
    frs_error *err)
{
	const char *name;
	unsigned got = 0;
	frs_mask *mk;
	FILE *fp;
	int rc;

	if (dims != NULL)
		*dims = 0;
	if (mask == NULL || path == NULL)
		return api_arg_err(err, "frs_mask_load: NULL argument");
	*mask = NULL;
	if ((fp = io_open_in(path, &name)) == NULL)
		return api_lib_err(err, FRS_E_IO);
	if ((mk = mask_new()) == NULL || (mk->name = strdup(path)) == NULL) {
		io_close_in(fp);
		frs_mask_free(mk);
		return api_nomem(err);
	}
	rc = read_matrix(mk, fp, name, path, &got);
	if (fp != mk->frp_fp)
		io_close_in(fp);
	if (dims != NULL)
		*dims = got;
	if (rc == 0 && mk->frp == NULL && mk->m.dims == 2)
		load_twin(mk, path);	/* prepared files are 2-D */
	if (rc < 0) {
		int code = api_lib_err(err, FRS_E_FORMAT);
		frs_mask_free(mk);
		return code;
	}
	if (mk->nlev == 0) {
		mk->nlev = 1;
		mk->lev[0] = mk->m.v;
	}
	*mask = mk;
	return api_ok(err);
}

int frs_mask_load(frs_mask **mask, const char *path, frs_error *err)
{
	return frs_mask_load_dims(mask, path, NULL, err);
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
		return api_arg_err(err, "frs_default_matrix: dims is not 2 or 3");
	if (path != NULL && cap == 0)
		return api_arg_err(err, "frs_default_matrix: cap is 0");
	if (path != NULL)
		path[0] = '\0';
	if (api_default_matrix(dims, found, sizeof found) < 0) {
		char msg[sizeof err->message];

		snprintf(msg, sizeof msg, "no default %smatrix (%s)",
		    dims == 3 ? "3-D " : "", frs_errmsg());
		return api_set_err(err, FRS_E_IO, msg);
	}
	if (path != NULL) {
		if ((len = strlen(found)) >= cap) {
			char msg[sizeof err->message];

			snprintf(msg, sizeof msg, "%.400s: needs %zu bytes, "
			    "cap is %zu", found, len + 1, cap);
			return api_set_err(err, FRS_E_BUFFER, msg);
		}
		memcpy(path, found, len + 1);
	}
	if (mask != NULL)
		return frs_mask_load(mask, found, err);
	return api_ok(err);
}

int frs_mask_wrap(frs_mask **mask, const uint32_t *values, uint32_t width,
    uint32_t height, frs_error *err)
{
	frs_mask *mk;

	if (mask == NULL || values == NULL)
		return api_arg_err(err, "frs_mask_wrap: NULL argument");
	*mask = NULL;
	if (!num_is_pow2(width) || !num_is_pow2(height) ||
	    (uint64_t)width * height > FRD_MAX_ELEMS / 2)
		return api_arg_err(err, "frs_mask_wrap: the sides must be powers of "
		    "two, below 2^31 elements in all");
	if ((mk = mask_new()) == NULL)
		return api_nomem(err);
	mk->wrapped = 1;
	mk->m = (struct frs_matrix){ .dims = 2, .w = width, .h = height,
	    .d = 1, .n = (size_t)width * height, .v = (uint32_t *)values };
	if (frd_check_permutation(&mk->m, "frs_mask_wrap") < 0) {
		frs_mask_free(mk);
		return api_lib_err(err, FRS_E_ARG);
	}
	mk->m.perm = 1;		/* the values stay as they are (frs.h) */
	mk->nlev = 1;
	mk->lev[0] = mk->m.v;
	*mask = mk;
	return api_ok(err);
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
	unsigned l = num_log2_ceil(b);
	struct frs_prep p;

	if (mk->frp != NULL && api_lists_from_frp(&mk->m, below)) {
		struct frs_matrix tm;
		if (frp_read_known(mk->frp_fp, mk->frp, &mk->m, &tm, &p,
		    b) == 0) {
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
			drop_frp(mk);
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
	const struct frs_prep *have = block ? &mk->lists[num_log2_ceil(block)] : NULL;
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

int api_lists_from_frp(const struct frs_matrix *m, uint64_t below)
{
	return below >= m->n / 2;
}

/* The 3-D sorted lists of block size b (0: none), made on first use and
 * kept in the mask. */
int api_mask_prep3(const frs_mask *cmk, uint32_t b, struct frs3_prep *view)
{
	frs_mask *mk = (frs_mask *)cmk;	/* only the lazy parts change */
	unsigned l = num_log2_ceil(b);
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
	else if (mk->name != NULL)
		frs_fail_context(mk->name);
	pthread_mutex_unlock(&mk->lock);
	return rc;
}

int frs_matrix_read(struct frs_matrix *m, const char *path, frs_error *err)
{
	if (m != NULL)
		*m = (struct frs_matrix){ 0 };
	if (m == NULL || path == NULL)
		return api_arg_err(err, "frs_matrix_read: NULL argument");
	if (frd_read_perm(path, m) < 0)
		return api_lib_err(err, FRS_E_FORMAT);
	return api_ok(err);
}

int frs_matrix_write(const struct frs_matrix *m, FILE *fp, const char *name,
    frs_error *err)
{
	if (m == NULL || fp == NULL || m->params == NULL ||
	    (m->v == NULL && m->n > 0))
		return api_arg_err(err, "frs_matrix_write: NULL argument");
	if (frd_write(fp, name != NULL ? name : "matrix", m) < 0)
		return api_lib_err(err, strlen(m->params) > FRD_MAX_PARAMS ?
		    FRS_E_ARG : FRS_E_IO);
	return api_ok(err);
}

uint32_t frs_mask_made(const frs_mask *mk, const char **file)
{
	if (file != NULL)
		*file = mk == NULL ? NULL : mk->frp != NULL ? mk->frp : mk->name;
	return mk != NULL ? mk->made : 0;
}

void frs_matrix_free(struct frs_matrix *m)
{
	if (m != NULL)
		frd_free(m);
}
