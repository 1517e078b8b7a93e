#define _POSIX_C_SOURCE 200809L
#include "sample/frs3.h"
#include "base/err.h"
#include "base/mem.h"
#include "base/num.h"
#include "base/par.h"
#include "base/rng.h"
#include "sample/tile.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static uint32_t min3(uint32_t a, uint32_t b, uint32_t c)
{
	uint32_t m = a < b ? a : b;
	return m < c ? m : c;
}

/* ---- setup ---------------------------------------------------------- */

int frs3_setup(struct frs3_setup *s, const struct frs_vol *vol,
    const struct frs_matrix *mat, uint64_t n, double sigma, uint64_t seed)
{
	const uint32_t side[3] = { vol->w, vol->h, vol->d };
	struct frs_imap cells = vol_as_map(vol);
	struct frs_window w;
	uint64_t *size[3] = { &s->sw, &s->sh, &s->sd };
	uint64_t *off[3] = { &s->wx, &s->wy, &s->wz };

	memset(s, 0, sizeof *s);
	if (frs_window_setup(&w, 3, side, &cells, NULL, mat, n, sigma, seed) < 0)
		return -1;
	/* Element ids (z S_H + y) S_W + x must fit 64 bits. */
	if ((double)w.size[0] * (double)w.size[1] * (double)w.size[2] >= 0x1p63)
		return frs_fail("%llu samples: the window of %llux%llux%llu "
		    "elements is too large", (unsigned long long)n,
		    (unsigned long long)w.size[0], (unsigned long long)w.size[1],
		    (unsigned long long)w.size[2]);
	s->iw = vol->w;
	s->ih = vol->h;
	s->id = vol->d;
	s->mw = mat->w;
	s->mh = mat->h;
	s->md = mat->d;
	FRS_SETUP_TAKE(s, w, n, sigma, seed);
	for (int i = 0; i < 3; i++) {
		*size[i] = w.size[i];
		*off[i] = w.off[i];
	}
	s->lfac = 1.0;
	s->sw0 = s->sw;
	s->sh0 = s->sh;
	s->sd0 = s->sd;
	s->tau = frs3_tau(s, n);
	return 0;
}

double frs3_tau(const struct frs3_setup *s, uint64_t n)
{
	return s->lfac * frs_xtau_get(&s->exact, n, (double)n * ((double)s->mw *
	    s->mh * s->md) / ((double)s->sw0 * (double)s->sh0 * (double)s->sd0 *
	    s->imean));
}

void frs3_level_setup(struct frs3_setup *s, const struct frs3_setup *s0,
    unsigned l, double max)
{
	*s = *s0;
	FRS_LEVEL_TAKE(s, l, 3, max);
	s->sw = (uint64_t)s->ns * s->iw;
	s->sh = (uint64_t)s->ns * s->ih;
	s->sd = (uint64_t)s->ns * s->id;
	s->wx = frs_window_offset(s->seed, 0, s->ns, s->mw);
	s->wy = frs_window_offset(s->seed, 1, s->ns, s->mh);
	s->wz = frs_window_offset(s->seed, 2, s->ns, s->md);
	s->tau = frs3_tau(s, s->n);
}

double frs3_unique(const struct frs3_setup *s)
{
	return (double)s->mw * s->mh * s->md / (s->sigma * s->sigma * s->sigma);
}

uint32_t frs3_block(const struct frs3_setup *s)
{
	uint32_t m = min3(s->mw, s->mh, s->md);

	if (s->tiles == FRS_TILES_SHUFFLE)
		m = min3((uint32_t)frs_tile_step(s->mw),
		    (uint32_t)frs_tile_step(s->mh), (uint32_t)frs_tile_step(s->md));
	return s->ns < m ? s->ns : m;
}

/* ---- preparation ---------------------------------------------------- */

void frs3_prep_free(struct frs3_prep *p)
{
	free(p->sval);
	free(p->sidx);
	memset(p, 0, sizeof *p);
}

struct sort_job {
	struct frs3_prep *p;
	uint32_t bw, bh;	/* blocks per row and column */
};

/* Sort blocks [b0, b1); any thread may take any blocks. */
static int sort_blocks(void *ctx, uint64_t b0, uint64_t b1)
{
	struct sort_job *j = ctx;
	const struct frs_matrix *m = j->p->m;
	uint32_t b = j->p->block;
	size_t bb = (size_t)b * b * b;
	struct num_vi *tmp = malloc(bb * sizeof *tmp);

	if (tmp == NULL)
		return frs_fail("out of memory for the sorted lists");
	for (uint64_t blk = b0; blk < b1; blk++) {
		uint64_t bx = blk % j->bw, by = blk / j->bw % j->bh;
		uint64_t bz = blk / j->bw / j->bh;
		for (uint32_t k = 0; k < bb; k++) {
			uint64_t x = bx * b + k % b, y = by * b + k / b % b;
			uint64_t z = bz * b + k / b / b;
			tmp[k] = (struct num_vi){ m->v[(z * m->h + y) * m->w + x], k };
		}
		qsort(tmp, bb, sizeof *tmp, num_vi_cmp);
		for (size_t k = 0; k < bb; k++) {
			j->p->sval[blk * bb + k] = tmp[k].v;
			j->p->sidx[blk * bb + k] = tmp[k].i;
		}
	}
	free(tmp);
	return 0;
}

int frs3_prepare(struct frs3_prep *p, const struct frs_matrix *m, uint32_t b)
{
	struct sort_job job;

	memset(p, 0, sizeof *p);
	p->m = m;
	if (b == 0)
		return 0;
	if (!num_is_pow2(m->w) || !num_is_pow2(m->h) || !num_is_pow2(m->d))
		return frs_fail("the matrix is %ux%ux%u: the sorted implementation "
		    "needs power-of-two sides (naive does not)", m->w, m->h, m->d);
	if (!num_is_pow2(b) || b > min3(m->w, m->h, m->d))
		return frs_fail("sorted blocks of %u do not fit the %ux%ux%u "
		    "matrix", b, m->w, m->h, m->d);
	p->block = b;
	p->sval = mem_calloc("the sorted lists", m->n, sizeof *p->sval);
	p->sidx = mem_calloc("the sorted lists", m->n, sizeof *p->sidx);
	job.p = p;
	job.bw = m->w / b;
	job.bh = m->h / b;
	if (p->sval == NULL || p->sidx == NULL ||
	    frs_parallel((uint64_t)job.bw * job.bh * (m->d / b), 1, sort_blocks,
	    &job, NULL) < 0) {
		frs3_prep_free(p);
		return -1;
	}
	return 0;
}

/* ---- thresholding ---------------------------------------------------- */

struct run {
	const struct frs3_setup *s;
	const struct frs_vol *vol;
	const struct frs3_prep *p;
	enum frs_impl algo;
	const double *tau;
	unsigned nsteps;
	int count_only;
};

struct vox {
	const struct run *run;
	struct frs3_chunk *c;
	uint64_t thr[32];	/* frs_thr_words', two a step */
	uint64_t lim;
	uint64_t x0, y0, z0;	/* the voxel's first window element */
	uint64_t tile[3];	/* the last tile met and its transform */
	int tvalid;
	struct frs_tile t;
};

static uint64_t elem_id(const struct frs3_setup *s, uint64_t x, uint64_t y,
    uint64_t z)
{
	return (z * s->sh + y) * s->sw + x;
}

static int grow(struct frs3_chunk *c, uint64_t k)
{
	c->e = frs_elems_grow(c->e, sizeof *c->e, c->n + k, &c->cap,
	    &c->failed);
	return c->failed ? -1 : 0;
}

/* Test value v of element (x, y, z) against every step; keep it with the
 * first step it passes. */
static void emit(struct vox *vx, uint64_t x, uint64_t y, uint64_t z,
    uint32_t v)
{
	const struct run *run = vx->run;
	const struct frs3_setup *s = run->s;
	unsigned k = frs_thr_step(vx->thr, run->nsteps, v, s->seed,
	    elem_id(s, x, y, z));

	if (k == run->nsteps)
		return;
	vx->c->count++;
	if (run->count_only || grow(vx->c, 1) < 0)
		return;
	vx->c->e[vx->c->n++] = (struct frs3_elem){ (uint32_t)x, (uint32_t)y,
	    (uint32_t)z, k };
}

/* The transform of the tile of window element e[] (cached in vx), and
 * the element's place in the tile in l[]. */
static const struct frs_tile *tile_at(struct vox *vx, const uint64_t *e,
    uint64_t *l)
{
	const struct frs3_setup *s = vx->run->s;
	uint64_t m[3] = { s->mw, s->mh, s->md }, w[3] = { s->wx, s->wy, s->wz };
	uint64_t t[3];

	for (int i = 0; i < 3; i++) {
		t[i] = (w[i] + e[i]) / m[i];
		l[i] = w[i] + e[i] - t[i] * m[i];
	}
	if (!vx->tvalid || t[0] != vx->tile[0] || t[1] != vx->tile[1] ||
	    t[2] != vx->tile[2]) {
		if (s->tiles != FRS_TILES_SHUFFLE)
			frs_tile_plain(&vx->t);
		else
			frs_tile_make(&vx->t, s->seed, 3, m, t[0], t[1], t[2]);
		memcpy(vx->tile, t, sizeof t);
		vx->tvalid = 1;
	}
	return &vx->t;
}

/* The index of the matrix block of side 2^lb that shows the window block
 * (of that side) whose first element is e[]. */
static uint64_t block_index(struct vox *vx, unsigned lb, const uint64_t *e)
{
	const struct frs3_setup *s = vx->run->s;
	uint64_t m[3] = { s->mw, s->mh, s->md }, l[3], u[3], v[3];
	const struct frs_tile *t = tile_at(vx, e, l);

	for (int i = 0; i < 3; i++)
		u[i] = l[i] >> lb;
	frs_tile_block(t, 3, m, lb, u, v);
	return (v[2] * (s->mh >> lb) + v[1]) * (s->mw >> lb) + v[0];
}

static void vox_naive(struct vox *vx)
{
	const struct frs3_setup *s = vx->run->s;
	const uint32_t *mv = vx->run->p->m->v;
	uint32_t ns = s->ns;

	for (uint64_t k = 0; k < (uint64_t)ns * ns * ns; k++) {
		uint64_t e[3] = { vx->x0 + k % ns, vx->y0 + k / ns % ns,
		    vx->z0 + k / ns / ns };
		uint32_t v = mv[block_index(vx, 0, e)];
		if (v < vx->lim)
			emit(vx, e[0], e[1], e[2], v);
	}
}

/* The window element e[] of in-block index k of a sorted block of side
 * b whose first element is at o[]. */
static void inblock(const struct vox *vx, uint32_t b, uint32_t k,
    const uint64_t *o, uint64_t *e)
{
	uint64_t w[3] = { k % b, k / b % b, k / b / b }, u[3];

	frs_tile_inblock(&vx->t, 3, b, w, u);
	for (int i = 0; i < 3; i++)
		e[i] = o[i] + u[i];
}

/* One step: the first k sorted values of a block pass but perhaps the
 * last, which alone can sit at floor(T) (the values are distinct) and
 * needs its coin; the rest pass without a test, and counting costs no
 * more than the bisection. */
static void take_all(struct vox *vx, const uint32_t *val, const uint32_t *idx,
    uint32_t b, uint64_t k, const uint64_t *o)
{
	const struct frs3_setup *s = vx->run->s;
	struct frs3_chunk *c = vx->c;
	uint64_t e[3];

	if (k > 0) {
		inblock(vx, b, idx[k - 1], o, e);
		if (frs_thr_step(vx->thr, 1, val[k - 1], s->seed,
		    elem_id(s, e[0], e[1], e[2])) != 0)
			k--;
	}
	c->count += k;
	if (vx->run->count_only || k == 0 || grow(c, k) < 0)
		return;
	for (uint64_t j = 0; j < k; j++) {
		inblock(vx, b, idx[j], o, e);
		c->e[c->n + j] = (struct frs3_elem){ (uint32_t)e[0],
		    (uint32_t)e[1], (uint32_t)e[2], 0 };
	}
	c->n += k;
}

/* One block of the sorted lists, its first element at window (x, y, z):
 * the values below lim by bisection, then each through emit. */
static void take_block(struct vox *vx, const uint32_t *val,
    const uint32_t *idx, uint32_t b, const uint64_t *o)
{
	uint64_t lo = 0, hi = (uint64_t)b * b * b;

	while (lo < hi) {
		uint64_t mid = lo + (hi - lo) / 2;
		if (val[mid] < vx->lim)
			lo = mid + 1;
		else
			hi = mid;
	}
	if (vx->run->nsteps > 1) {
		for (uint64_t k = 0; k < lo; k++) {
			uint64_t e[3];
			inblock(vx, b, idx[k], o, e);
			emit(vx, e[0], e[1], e[2], val[k]);
		}
		return;
	}
	take_all(vx, val, idx, b, lo, o);
}

static void vox_sorted(struct vox *vx)
{
	const struct frs3_setup *s = vx->run->s;
	const struct frs3_prep *p = vx->run->p;
	uint32_t b = p->block;
	uint64_t nb = s->ns / b, bb = (uint64_t)b * b * b;
	unsigned lb = 0;

	while ((1u << lb) < b)
		lb++;
	for (uint64_t k = 0; k < nb * nb * nb; k++) {
		uint64_t o[3] = { vx->x0 + k % nb * b, vx->y0 + k / nb % nb * b,
		    vx->z0 + k / nb / nb * b };
		uint64_t blk = block_index(vx, lb, o);
		take_block(vx, p->sval + blk * bb, p->sidx + blk * bb, b, o);
	}
}

/* Slices [z0, z1) of voxels, each its own chunk. */
static int slices_task(void *ctx, void *chunk, uint64_t z0, uint64_t z1)
{
	const struct run *run = ctx;
	const struct frs3_setup *s = run->s;
	struct frs3_chunk *c = chunk;
	struct vox vx;

	vx.run = run;
	vx.tvalid = 0;
	for (uint64_t vz = z0; vz < z1; vz++) {
		uint64_t i0 = vz * s->ih * s->iw, i1 = i0 + s->ih * s->iw;
		vx.c = &c[vz];
		if (s->lev != NULL) {	/* the level's voxels only */
			i0 = i0 > s->cell0 ? i0 : s->cell0;
			i1 = i1 < s->cell1 ? i1 : s->cell1;
		}
		for (uint64_t i = i0; i < i1; i++) {
			double imp = run->vol->v[i];
			if (!(imp > 0.0) || !frs_cell_here(s->lev, s->level, i))
				continue;	/* zero importance costs nothing */
			vx.lim = frs_thr_words(vx.thr, run->tau, run->nsteps,
			    imp * s->iscale, s->rule);
			if (vx.lim == 0)
				continue;
			vx.x0 = i % s->iw * s->ns;
			vx.y0 = i / s->iw % s->ih * s->ns;
			vx.z0 = vz * s->ns;
			if (run->algo == FRS_NAIVE)
				vox_naive(&vx);
			else
				vox_sorted(&vx);
		}
		if (vx.c->failed)
			return frs_fail("out of memory for the samples");
	}
	return 0;
}

/* Past these, a run would take hours: naive visits every window
 * element, sorted every block of every voxel (a bisection each), and a
 * count far beyond the matrix's own S_M / sigma^3 makes the blocks many. */
#define FRS3_MAX_NAIVE ((double)((uint64_t)1 << 36))
#define FRS3_MAX_BLOCKS ((double)((uint64_t)1 << 33))

static int check_work(const struct frs3_setup *s, const struct frs3_prep *p,
    enum frs_impl algo)
{
	double vox = (double)s->iw * s->ih * s->id, ns = s->ns;

	if (algo == FRS_NAIVE && vox * ns * ns * ns > FRS3_MAX_NAIVE)
		return frs_fail("naive: %llu samples would visit %.3g window "
		    "elements (above 2^36, hours); sorted would not",
		    (unsigned long long)s->n, vox * ns * ns * ns);
	if (algo == FRS_SORTED) {
		double nb = ns / p->block, work = vox * nb * nb * nb;
		if (work > FRS3_MAX_BLOCKS)
			return frs_fail("%llu samples would visit %.3g blocks of the "
			    "%ux%ux%u matrix (above 2^33, hours): %.6g samples "
			    "repeat it %.3g times; use a larger matrix or fewer "
			    "samples", (unsigned long long)s->n, work, s->mw, s->mh,
			    s->md, frs3_unique(s), (double)s->n / frs3_unique(s));
	}
	return 0;
}

static int check(const struct frs3_setup *s, const struct frs3_prep *p,
    enum frs_impl algo, const uint64_t *steps, unsigned nsteps,
    int count_only, double *tau)
{
	if (frs_steps_check(steps, nsteps) < 0)
		return -1;
	for (unsigned k = 0; k < nsteps; k++)
		tau[k] = frs3_tau(s, steps[k]);
	if (!count_only && (s->sw > UINT32_MAX || s->sh > UINT32_MAX ||
	    s->sd > UINT32_MAX))
		return frs_fail("the window of %llux%llux%llu elements is too large "
		    "to store samples (a count-only run counts them)",
		    (unsigned long long)s->sw, (unsigned long long)s->sh,
		    (unsigned long long)s->sd);
	if (algo != FRS_NAIVE && algo != FRS_SORTED)
		return frs_fail("%s: 3-D sampling has naive and sorted",
		    frs_impl_name(algo));
	if (algo == FRS_SORTED && (p->block == 0 || s->ns % p->block ||
	    p->block > min3(s->mw, s->mh, s->md) ||
	    (s->tiles == FRS_TILES_SHUFFLE && p->block > frs3_block(s))))
		return frs_fail("sorted: lists of blocks of %u do not fit "
		    "n_s = %u", p->block, s->ns);
	return check_work(s, p, algo);
}

static const struct frs_chunk_kind chunk_kind =
    FRS_CHUNK_KIND(struct frs3_chunk);

int frs3_sample(const struct frs3_setup *s, const struct frs_vol *vol,
    const struct frs3_prep *p, enum frs_impl algo, const uint64_t *steps,
    unsigned nsteps, int count_only, struct frs3_result *r)
{
	double tau[16];
	struct run run = { s, vol, p, algo, tau, nsteps, count_only };

	memset(r, 0, sizeof *r);
	if (check(s, p, algo, steps, nsteps, count_only, tau) < 0)
		return -1;
	r->chunk = frs_chunks_run(&chunk_kind, s->id, slices_task, &run,
	    &r->count);
	r->nchunk = r->chunk != NULL ? s->id : 0;
	return r->chunk != NULL ? 0 : -1;
}

void frs3_result_free(struct frs3_result *r)
{
	frs_chunks_free(&chunk_kind, r->chunk, r->nchunk);
	memset(r, 0, sizeof *r);
}

int frs3_each(const struct frs3_result *r, unsigned nsteps,
    int (*fn)(void *ctx, const struct frs3_elem *e), void *ctx)
{
	for (uint32_t st = 0; st < nsteps; st++)
		for (uint64_t c = 0; c < r->nchunk; c++)
			for (uint64_t i = 0; i < r->chunk[c].n; i++) {
				int rc;
				if (r->chunk[c].e[i].step != st)
					continue;
				if ((rc = fn(ctx, &r->chunk[c].e[i])) != 0)
					return rc;
			}
	return 0;
}

/* ---- points ---------------------------------------------------------- */

void frs3_point(const struct frs3_setup *s, const struct frs3_elem *e,
    double p[3])
{
	static const unsigned base[3] = { 2, 3, 5 };
	const uint64_t c[3] = { e->x, e->y, e->z };
	const uint64_t side[3] = { s->sw, s->sh, s->sd };
	uint64_t id = elem_id(s, e->x, e->y, e->z);
	unsigned l = s->level;

	/* A level-l element (l > 0) stands for 8^l elements of level 0 in
	 * one voxel, whose importance is constant: its sample goes to one of
	 * them, drawn from (level seed, element), with the jitter of the
	 * level-l element.  Every level's samples then lie on level 0's grid
	 * of n_s a voxel side: at the centres of their own elements, those
	 * of a coarse level form a coarse grid that shows in every
	 * projection of the volume (64 columns over shell3's 32^3 voxels at
	 * 4096 samples, against 256 at level 0). */
	for (unsigned a = 0; a < 3; a++) {
		double j = 0.5;
		uint64_t ca = c[a] << l | (l > 0 ? frs_level_place(s->seed, l, id,
		    a) : 0);
		if (s->jitter == FRS_PLACE_RANDOM) {
			j = frs_rand01(s->seed, FRS_STREAM_JITTER, 3 * id + a);
		} else if (s->jitter == FRS_PLACE_HALTON) {
			/* Halton (2, 3, 5) by element, rotated by the seed. */
			j = num_radical_inverse(id + 1, base[a]) +
			    frs_rand01(s->seed, FRS_STREAM_JITTER, UINT64_MAX - a);
			j -= floor(j);
		}
		p[a] = frs_below_one(((double)ca + j) / (double)(side[a] << l));
	}
}

double frs3_pdf(const struct frs3_setup *s, const struct frs_vol *vol,
    const struct frs3_elem *e)
{
	uint64_t x = e->x / s->ns, y = e->y / s->ns, z = e->z / s->ns;
	return vol->v[(z * vol->h + y) * vol->w + x] / s->mean;
}

/* ---- exact counts ------------------------------------------------- */

struct xcount3 {
	struct frs3_setup s;
	const struct frs_vol *vol;
	const struct frs3_prep *p;
};

static int xcount3_fn(void *ctx, double tau, uint64_t *count)
{
	struct xcount3 *x = ctx;
	struct frs3_result r;

	x->s.exact = (struct frs_xtau){ .n = 1, .steps = { x->s.n },
	    .tau = { tau } };
	if (frs3_sample(&x->s, x->vol, x->p, x->p->block ? FRS_SORTED :
	    FRS_NAIVE, &x->s.n, 1, 1, &r) < 0)
		return -1;
	*count = r.count;
	frs3_result_free(&r);
	return 0;
}

int frs3_exact(struct frs3_setup *s, const struct frs_vol *vol,
    const struct frs3_prep *p, const uint64_t *steps, unsigned nsteps)
{
	struct xcount3 x = { *s, vol, p };
	double tau0[16];
	unsigned passes;

	if (s->rule == FRS_THESIS)
		return frs_fail("exact counts need the unbiased threshold rule");
	if (frs_steps_check(steps, nsteps) < 0)
		return -1;
	for (unsigned k = 0; k < nsteps; k++)
		tau0[k] = frs3_tau(s, steps[k]);
	if (frs_exact_taus(steps, nsteps, tau0, frs_exact_most(vol->v,
	    (uint64_t)vol->w * vol->h * vol->d, s->ns, 3), xcount3_fn, &x,
	    &s->exact, &passes) < 0)
		return -1;
	s->tau = frs3_tau(s, s->n);
	return 0;
}
