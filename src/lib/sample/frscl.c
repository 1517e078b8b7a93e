#define _POSIX_C_SOURCE 200809L
#include "sample/frscl.h"
#include "base/err.h"
#include "base/progress.h"

#include "../../../cl/defs.cl"

#include <stdlib.h>
#include <string.h>

static struct {
	cl_context ctx;
	cl_program prog;
} cache;

static struct frscl_times last;


void frscl_last_times(struct frscl_times *t)
{
	*t = last;
}

void frscl_release(struct ocl *o)
{
	if (cache.prog != NULL && cache.ctx == o->ctx) {
		clReleaseProgram(cache.prog);
		cache.prog = NULL;
		cache.ctx = NULL;
	}
}

static int program(struct ocl *o, cl_program *prog)
{
	if (cache.prog == NULL || cache.ctx != o->ctx) {
		if (cache.prog != NULL)
			clReleaseProgram(cache.prog);
		cache.prog = NULL;
		cache.ctx = NULL;
		if (ocl_program(o, "frs", NULL, &cache.prog) < 0)
			return -1;
		cache.ctx = o->ctx;
	}
	*prog = cache.prog;
	return 0;
}

/* What one call holds on the device. */
struct clrun {
	struct ocl *o;
	cl_program prog;
	cl_mem setup, thr, mat, loff, sval, sidx, soff, cnt, off, out, ca, cb,
	    ccnt;
	cl_kernel k, k2, k3;
	uint64_t nact;
	double t;	/* start of the current phase */
};

static void rel(cl_mem *m)
{
	if (*m != NULL)
		clReleaseMemObject(*m);
	*m = NULL;
}

static void clrun_free(struct clrun *c)
{
	cl_mem *all[] = { &c->setup, &c->thr, &c->mat, &c->loff, &c->sval,
	    &c->sidx, &c->soff, &c->cnt, &c->off, &c->out, &c->ca, &c->cb,
	    &c->ccnt };
	for (size_t i = 0; i < sizeof all / sizeof all[0]; i++)
		rel(all[i]);
	if (c->k)
		clReleaseKernel(c->k);
	if (c->k2)
		clReleaseKernel(c->k2);
	if (c->k3)
		clReleaseKernel(c->k3);
}

static void phase(struct clrun *c, double *acc)
{
	double now = progress_now();
	*acc += now - c->t;
	c->t = now;
}

/* A buffer of size bytes, copied from host or filled with zeros.  A
 * zero-filled one is made whole words long, at least one (the fill writes
 * words, and an empty buffer is still bound to a kernel argument). */
static int buffer(struct clrun *c, size_t size, const void *host, cl_mem *b)
{
	size_t words = size ? (size + 3) / 4 * 4 : 4;

	if (host != NULL)
		return ocl_buffer(c->o, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
		    size, host, b);
	if (ocl_buffer(c->o, CL_MEM_READ_WRITE, words, NULL, b) < 0)
		return -1;
	return ocl_fill32(c->o, *b, words, 0);
}

/* The matrix and its lists, read-only and alive for the whole run: the
 * device may use the host's memory as it is (a CPU device such as PoCL
 * then copies nothing; a GPU driver copies once, as it would anyway). */
static int shared_buffer(struct clrun *c, size_t size, const void *host,
    cl_mem *b)
{
	if (size == 0)
		return buffer(c, size, host, b);
	return ocl_buffer(c->o, CL_MEM_READ_ONLY | CL_MEM_USE_HOST_PTR, size,
	    host, b);
}

static int alloc_fail(void)
{
	return frs_fail("out of memory for the samples");
}

/* Counts (64-bit or 32-bit) to offsets; the total in *total.  Counts are
 * read back, offsets written to off (made here). */
static int scan(struct clrun *c, cl_mem cnt, uint64_t n, int wide,
    cl_mem *off, uint64_t *total)
{
	uint64_t *o = malloc((n ? n : 1) * sizeof *o), sum = 0;
	int rc = -1;

	if (o == NULL)
		return alloc_fail();
	if (wide) {
		if (ocl_read(c->o, cnt, n * sizeof *o, o) < 0)
			goto out;
		for (uint64_t i = 0; i < n; i++) {
			uint64_t v = o[i];
			o[i] = sum;
			sum += v;
		}
	} else {
		uint32_t *w = malloc((n ? n : 1) * sizeof *w);
		if (w == NULL) {
			rc = alloc_fail();
			goto out;
		}
		if (ocl_read(c->o, cnt, n * sizeof *w, w) < 0) {
			free(w);
			goto out;
		}
		for (uint64_t i = 0; i < n; i++) {
			o[i] = sum;
			sum += w[i];
		}
		free(w);
	}
	*total = sum;
	rel(off);
	rc = buffer(c, n * sizeof *o, o, off);
out:
	free(o);
	return rc;
}

/* Read the samples into the chunk that out_buffer made c->out over. */
static int take(struct clrun *c, uint64_t total, struct frs_result *r)
{
	struct frs_chunk *ch = &r->chunk[0];

	if (total > 0 &&
	    ocl_read(c->o, c->out, total * sizeof *ch->e, ch->e) < 0)
		return -1;
	ch->n = total;
	return 0;
}

/* c->out for total samples over the result's one chunk, zeroed: a device
 * that can use host memory (PoCL) writes the samples in place, and the
 * read back copies nothing. */
static int out_buffer(struct clrun *c, uint64_t total, struct frs_result *r)
{
	struct frs_chunk *ch = &r->chunk[0];

	if (total > SIZE_MAX / sizeof *ch->e)
		return alloc_fail();
	free(ch->e);
	ch->e = calloc(total ? total : 1, sizeof *ch->e);
	if (ch->e == NULL)
		return alloc_fail();
	ch->cap = total;
	rel(&c->out);
	if (ocl_buffer(c->o, CL_MEM_READ_WRITE | CL_MEM_USE_HOST_PTR,
	    (size_t)total * sizeof *ch->e, ch->e, &c->out) < 0)
		return -1;
	phase(c, &last.download);
	return 0;
}

/* A kernel argument, for ocl_args: its size and where it is. */
#define ARG(x) sizeof(x), &(x)

static int kernel(struct clrun *c, const char *name, cl_kernel *k)
{
	return ocl_kernel(c->prog, name, k);
}

/* Run kernel k on n work-items: the kernel phase. */
static int launch(struct clrun *c, cl_kernel k, uint64_t n)
{
	if (ocl_run(c->o, k, (size_t)n, 0) < 0)
		return -1;
	phase(c, &last.kernel);
	return 0;
}

/* A fresh *buf for total records of 12 bytes. */
static int grow(struct clrun *c, uint64_t total, cl_mem *buf)
{
	if (total > SIZE_MAX / 12)
		return alloc_fail();
	rel(buf);
	if (buffer(c, (size_t)total * 12, NULL, buf) < 0)
		return -1;
	phase(c, &last.download);
	return 0;
}

/* Offsets (to c->off) from the n counts in cnt and a fresh *buf for the
 * records counted; their number in *total. */
static int make_room(struct clrun *c, cl_mem cnt, uint64_t n, int wide,
    cl_mem *buf, uint64_t *total)
{
	if (scan(c, cnt, n, wide, &c->off, total) < 0)
		return -1;
	return grow(c, *total, buf);
}

/* make_room for the samples (c->out): the count goes to r; with
 * count_only nothing more is done and the result is 1. */
static int make_out(struct clrun *c, cl_mem cnt, uint64_t n, int wide,
    int count_only, struct frs_result *r, uint64_t *total)
{
	if (scan(c, cnt, n, wide, &c->off, total) < 0)
		return -1;
	r->count = *total;
	if (count_only) {
		phase(c, &last.download);
		return 1;
	}
	return out_buffer(c, *total, r);
}

/* Read the total samples back: the download phase. */
static int finish(struct clrun *c, uint64_t total, struct frs_result *r)
{
	if (take(c, total, r) < 0)
		return -1;
	phase(c, &last.download);
	return 0;
}

/* Naive, Stack, Level N, Sorted: count, offsets, write. */
static int per_pixel(struct clrun *c, int algo, int count_only,
    struct frs_result *r)
{
	uint64_t total;
	int wr = 0, rc;
	cl_mem m1, m2;

	if (kernel(c, algo == FRS_NAIVE ? "frs_naive" : algo == FRS_SORTED ?
	    "frs_sorted" : "frs_minmap", &c->k) < 0)
		return -1;
	if (buffer(c, c->nact * sizeof(uint64_t), NULL, &c->cnt) < 0 ||
	    buffer(c, sizeof(uint64_t), NULL, &c->off) < 0 ||
	    buffer(c, 12, NULL, &c->out) < 0)
		return -1;
	m1 = algo == FRS_SORTED ? c->sval : c->mat;
	m2 = algo == FRS_SORTED ? c->sidx : c->loff;
	phase(c, &last.upload);
	for (;;) {
		if (algo == FRS_NAIVE ? ocl_args(c->k, 7, ARG(c->setup),
		    ARG(c->thr), ARG(m1), ARG(c->cnt), ARG(c->off), ARG(c->out),
		    ARG(wr)) :
		    algo == FRS_SORTED ? ocl_args(c->k, 9, ARG(c->setup),
		    ARG(c->thr), ARG(m1), ARG(m2), ARG(c->soff), ARG(c->cnt),
		    ARG(c->off), ARG(c->out), ARG(wr)) :
		    ocl_args(c->k, 8, ARG(c->setup), ARG(c->thr), ARG(m1),
		    ARG(m2), ARG(c->cnt), ARG(c->off), ARG(c->out), ARG(wr)))
			return -1;
		if (launch(c, c->k, c->nact) < 0)
			return -1;
		if (wr)
			break;
		rc = make_out(c, c->cnt, c->nact, 1, count_only, r, &total);
		if (rc != 0)
			return rc < 0 ? -1 : 0;
		wr = 1;
	}
	return finish(c, total, r);
}

/* Flat 1, first launch: the candidate blocks at the start level (c->ca). */
static int flat_init(struct clrun *c, uint64_t *ncand)
{
	for (int wr = 0; wr < 2; wr++) {
		if (ocl_args(c->k, 8, ARG(c->setup), ARG(c->thr), ARG(c->mat),
		    ARG(c->loff), ARG(c->cnt), ARG(c->off), ARG(c->ca),
		    ARG(wr)) < 0 || launch(c, c->k, c->nact) < 0)
			return -1;
		if (!wr && make_room(c, c->cnt, c->nact, 1, &c->ca, ncand) < 0)
			return -1;
	}
	return 0;
}

/* Flat 1, one level: the ncand blocks of c->ca refined to level l - 1. */
static int flat_refine(struct clrun *c, unsigned l, uint64_t *ncand)
{
	uint64_t next = 0;

	rel(&c->ccnt);
	rel(&c->cb);
	if (buffer(c, (size_t)*ncand * 4, NULL, &c->ccnt) < 0 ||
	    buffer(c, 12, NULL, &c->cb) < 0)
		return -1;
	for (int wr = 0; wr < 2; wr++) {
		if (ocl_args(c->k2, 11, ARG(c->setup), ARG(c->thr), ARG(c->mat),
		    ARG(c->loff), ARG(c->ca), ARG(*ncand), ARG(l), ARG(c->ccnt),
		    ARG(c->off), ARG(c->cb), ARG(wr)) < 0 ||
		    launch(c, c->k2, *ncand) < 0)
			return -1;
		if (!wr && make_room(c, c->ccnt, *ncand, 0, &c->cb, &next) < 0)
			return -1;
	}
	rel(&c->ca);
	c->ca = c->cb;
	c->cb = NULL;
	*ncand = next;
	return 0;
}

/* Flat 1: the start blocks, a launch per level, the elements. */
static int flat1(struct clrun *c, unsigned L, int count_only,
    struct frs_result *r)
{
	uint64_t ncand = 0, total;
	int rc;

	if (kernel(c, "frs_flat_init", &c->k) < 0 ||
	    kernel(c, "frs_flat_refine", &c->k2) < 0 ||
	    kernel(c, "frs_flat_final", &c->k3) < 0)
		return -1;
	if (buffer(c, c->nact * sizeof(uint64_t), NULL, &c->cnt) < 0 ||
	    buffer(c, sizeof(uint64_t), NULL, &c->off) < 0 ||
	    buffer(c, 12, NULL, &c->ca) < 0)
		return -1;
	phase(c, &last.upload);
	if (flat_init(c, &ncand) < 0)
		return -1;
	for (unsigned l = L; l >= 1; l--)
		if (flat_refine(c, l, &ncand) < 0)
			return -1;
	rel(&c->ccnt);
	if (buffer(c, (size_t)ncand * 4, NULL, &c->ccnt) < 0 ||
	    buffer(c, 12, NULL, &c->out) < 0)
		return -1;
	for (int wr = 0; wr < 2; wr++) {
		if (ocl_args(c->k3, 9, ARG(c->setup), ARG(c->thr), ARG(c->mat),
		    ARG(c->ca), ARG(ncand), ARG(c->ccnt), ARG(c->off),
		    ARG(c->out), ARG(wr)) < 0 ||
		    launch(c, c->k3, ncand) < 0)
			return -1;
		if (wr)
			break;
		rc = make_out(c, c->ccnt, ncand, 0, count_only, r, &total);
		if (rc != 0)
			return rc < 0 ? -1 : 0;
	}
	return finish(c, total, r);
}

/* The minmap levels in one buffer, level l from offset loff[l]. */
static int upload_minmap(struct clrun *c, const struct frs_prep *p)
{
	uint64_t loff[32] = { 0 }, n = 0;
	uint32_t *all;
	int rc;

	for (unsigned l = 0; l < p->nlev; l++) {
		loff[l] = n;
		n += (uint64_t)(p->m->w >> l) * (p->m->h >> l);
	}
	all = malloc(n * sizeof *all);
	if (all == NULL)
		return frs_fail("out of memory for the minmap");
	for (unsigned l = 0; l < p->nlev; l++)
		memcpy(all + loff[l], p->lev[l], (size_t)(p->m->w >> l) *
		    (p->m->h >> l) * sizeof *all);
	rc = buffer(c, n * sizeof *all, all, &c->mat);
	free(all);
	if (rc == 0)
		rc = buffer(c, sizeof loff, loff, &c->loff);
	return rc;
}

int frs_sample_cl(struct ocl *o, const struct frs_setup *s,
    const struct frs_imap *map, const struct frs_prep *p, int algo,
    const uint64_t *steps, unsigned nsteps, int count_only,
    struct frs_result *r)
{
	double tau[16];
	uint64_t setup[FRSCL_NSETUP], *thr = NULL;
	uint64_t rec = FRSCL_RECORD((uint64_t)nsteps);
	uint64_t npix = (uint64_t)s->iw * s->ih;
	struct clrun c;
	unsigned L = 0;
	int rc = -1;

	memset(r, 0, sizeof *r);
	memset(&last, 0, sizeof last);
	memset(&c, 0, sizeof c);
	c.o = o;
	c.t = progress_now();
	if (algo < 0 || algo > FRS_FLAT1)
		return frs_fail("no implementation %d", algo);
	if (frs_sample_check(s, p, algo, frs_impl_name((enum frs_impl)algo), steps, nsteps,
	    count_only, tau) < 0)
		return -1;
	/* Sorted without lists visits the pixels as on the CPU. */
	if (algo == FRS_SORTED && p->block == 0)
		algo = (int)frs_sorted_walk(s);
	if (program(o, &c.prog) < 0)
		return -1;
	phase(&c, &last.build);
	r->nchunk = 1;
	r->chunk = calloc(1, sizeof *r->chunk);
	thr = malloc((npix ? npix : 1) * rec * sizeof *thr);
	if (r->chunk == NULL || thr == NULL) {
		rc = frs_fail("out of memory");
		goto out;
	}
	/* The active pixels: importance above 0 and a limit above 0. */
	for (uint64_t i = 0; i < npix; i++) {
		double imp = map->v[i];
		uint64_t *t = thr + c.nact * rec;
		if (!(imp > 0.0) || !frs_cell_here(s->lev, s->level, i))
			continue;
		t[FRSCL_REC_LIM] = frs_thr_words(t + FRSCL_REC_TF(0), tau,
		    nsteps, imp * s->iscale, s->rule);
		if (t[FRSCL_REC_LIM] == 0)
			continue;
		t[FRSCL_REC_PIXEL] = (i % s->iw) | (i / s->iw) << 32;
		c.nact++;
	}
	if (algo == FRS_STACK || algo == FRS_FLAT1)
		L = frs_start_level(s, p, s->level0);
	else if (algo == FRS_LEVEL1)
		L = frs_start_level(s, p, 1);
	else if (algo == FRS_LEVEL2)
		L = frs_start_level(s, p, 2);
	setup[FRSCL_SW] = s->sw;
	setup[FRSCL_NS] = s->ns;
	setup[FRSCL_WX] = s->wx;
	setup[FRSCL_WY] = s->wy;
	setup[FRSCL_MW] = s->mw;
	setup[FRSCL_MH] = s->mh;
	setup[FRSCL_SEED] = s->seed;
	setup[FRSCL_NSTEPS] = nsteps;
	setup[FRSCL_NACT] = c.nact;
	setup[FRSCL_START] = algo == FRS_SORTED ? p->block : L;
	setup[FRSCL_TILES] = s->tiles == FRS_TILES_SHUFFLE;
	if (buffer(&c, sizeof setup, setup, &c.setup) < 0 ||
	    buffer(&c, c.nact * rec * sizeof *thr, thr, &c.thr) < 0)
		goto out;
	if (algo == FRS_NAIVE) {
		if (shared_buffer(&c, p->m->n * sizeof *p->m->v, p->m->v,
		    &c.mat) < 0)
			goto out;
	} else if (algo == FRS_SORTED) {
		uint64_t nblk = p->m->n / ((uint64_t)p->block * p->block);
		uint64_t nl = p->soff[nblk];	/* entries in all lists */
		if (shared_buffer(&c, nl * sizeof *p->sval, p->sval,
		    &c.sval) < 0 || shared_buffer(&c, nl * sizeof *p->sidx,
		    p->sidx, &c.sidx) < 0 || shared_buffer(&c, (nblk + 1) *
		    sizeof *p->soff, p->soff, &c.soff) < 0)
			goto out;
	} else if (upload_minmap(&c, p) < 0) {
		goto out;
	}
	if (c.nact == 0)
		rc = 0;
	else if (algo == FRS_FLAT1)
		rc = flat1(&c, L, count_only, r);
	else
		rc = per_pixel(&c, algo, count_only, r);
	if (rc == 0)
		r->chunk[0].count = r->count;
out:
	free(thr);
	clrun_free(&c);
	if (rc < 0)
		frs_result_free(r);
	return rc;
}
