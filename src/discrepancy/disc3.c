/*
 * Star discrepancy of 3-D point sets (disc.h): Warnock's closed form for
 * D2 in any dimension, the exact Dinf over the critical boxes, and the
 * grid of s^3 anchored boxes.
 *
 * Every parallel loop cuts its work into chunks of a fixed size, each
 * chunk writes its own partial result, and the partials are combined in
 * chunk order: the same bits for any thread count, and with par = 0.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "discrepancy/disc.h"
#include "discrepancy/discint.h"
#include "cli/cli.h"
#include "discrepancy/geom.h"

#define L2_ROWS 32		/* rows of the pair sum per chunk */
#define DINF_SWEEPS 256	/* x positions of the exact Dinf per chunk */
#define QBLOCK 8		/* z ranks per block of the exact Dinf */
#define TILE 16			/* rows of its coarse bound */
#define GRID_PLANES 8		/* grid planes per chunk */

/* ---- D2: Warnock's closed form in k dimensions ---------------------- */

/*
 * D2^2 = 3^-k - 2^(1-k)/n sum_i prod_d (1 - x_id^2)
 *        + 1/n^2 sum_i sum_j prod_d (1 - max(x_id, x_jd)).
 * With u = 1 - x (rounding is monotone, so 1 - max(a, b) rounds to
 * min(1 - a, 1 - b)), the pair sum is 2 sum_{i<j} prod min(u_id, u_jd)
 * plus the diagonal.  The three terms are O(1) and cancel to O(1/n): a
 * row is summed with TwoSum on four independent lanes (the error of each
 * add kept), rows and chunks in double-double.
 */
struct l2job {
	const double *u;	/* k arrays of n values, 1 - x */
	size_t n;
	unsigned k;
	struct dd *part;	/* per chunk */
};

/* prod_d min(u_id, u_jd) for j = i+1 .. n-1 into t[0 ..]. */
static void row_terms(const struct l2job *c, size_t i, double *t)
{
	size_t n = c->n, m = n - i - 1;

	for (unsigned d = 0; d < c->k; d++) {
		const double *u = c->u + (size_t)d * n + i + 1;
		double ui = c->u[(size_t)d * n + i];
		if (d == 0)
			for (size_t j = 0; j < m; j++)
				t[j] = u[j] < ui ? u[j] : ui;
		else
			for (size_t j = 0; j < m; j++)
				t[j] *= u[j] < ui ? u[j] : ui;
	}
}

/* Sum of t[0..m-1] as a double-double: TwoSum on four lanes. */
static struct dd lane_sum(const double *t, size_t m)
{
	double s[4] = { 0, 0, 0, 0 }, e[4] = { 0, 0, 0, 0 };
	struct dd r = dd_from(0.0);
	size_t j = 0;

	for (; j + 4 <= m; j += 4)
		for (int l = 0; l < 4; l++) {
			double a = s[l] + t[j + (size_t)l];
			double bb = a - s[l];
			e[l] += (s[l] - (a - bb)) + (t[j + (size_t)l] - bb);
			s[l] = a;
		}
	for (; j < m; j++)
		r = dd_add_d(r, t[j]);
	for (int l = 0; l < 4; l++)
		r = dd_add(r, dd_two_sum(s[l], e[l]));
	return r;
}

static int l2_chunk(void *ctx, uint64_t b, uint64_t e)
{
	struct l2job *c = ctx;
	double *t = malloc(c->n * sizeof *t);
	struct dd acc = dd_from(0.0);

	if (t == NULL)
		return cli_fail("no memory for %zu points", c->n);
	for (size_t i = (size_t)b; i < (size_t)e; i++) {
		double diag = 1.0;
		for (unsigned d = 0; d < c->k; d++)
			diag *= c->u[(size_t)d * c->n + i];
		row_terms(c, i, t);
		acc = dd_add(acc, dd_mul_d(lane_sum(t, c->n - i - 1), 2.0));
		acc = dd_add_d(acc, diag);
	}
	c->part[b / L2_ROWS] = acc;
	free(t);
	return 0;
}

/* ---- D2 in 3-D: the pair sum by divide and conquer ------------------ */

/*
 * P = sum_{i,j} prod_d min(u_id, u_jd) in O(n log^2 n) (CDQ divide and
 * conquer; the quadratic loop above stays for k other than 3 and as the
 * tests' second opinion).  With the points in x order, u_x falls, so for
 * i before j the x factor is u_jx and
 *   P = diag + 2 sum_j u_jx Q_j,
 *   Q_j = sum_{i before j} min(u_iy, u_jy) min(u_iz, u_jz).
 * Bottom up over blocks of x positions: blocks of CDQ_BASE points take
 * their pairs directly; then, level by level, the later half R of each
 * block of 2w positions takes its pairs with the earlier half L.  Both
 * halves are kept sorted by u_y and by u_z (merged as the levels rise).
 * A merge by z gives each j of R the number c_j of L with u_iz <= u_jz
 * and their sum of u_iz; a merge by y inserts the points of L with
 * u_iy <= u_jy (the set A) into a Fenwick tree over their z positions
 * before j is met, holding u_iy u_iz, u_iy, u_iz and 1.  Then, with
 * prefix sums up to c_j,
 *   Q_j(L) = sum_{A, z<=} u_iy u_iz + u_jz sum_{A, z>} u_iy
 *          + u_jy sum_{not A, z<=} u_iz + u_jy u_jz #{not A, z>},
 * the last two as the whole of L less A.  Ties are where they belong:
 * an equal u is the min either way, and the merges send equal values of
 * L first, to the <= side.
 * D2^2 is O(1/n) from terms of O(1), so everything is summed in
 * double-double (the terms u_iy u_iz are rounded products, as in the
 * quadratic sum).  Blocks of one level are independent: they run on
 * the thread team, each writes its own partial, and the partials are
 * added in block order, so the bits do not depend on the threads.
 */
#define CDQ_BASE 32		/* points per block taken directly */
#define CDQ_WORK 8192		/* positions per chunk of the team, at least */

struct cdq {
	size_t n;
	double *u;		/* u_x, u_y, u_z of x position p at 3p */
	uint32_t *ys, *zs;	/* positions, sorted by u_y / u_z per block */
	uint32_t *zpos;		/* of L: place among L by u_z */
	uint32_t *zc;		/* of R: c_j */
	struct dd *zsum;	/* of R: sum of u_iz over those c_j */
	struct dd *part;	/* per block of the level */
	size_t w;		/* the half width of the level */
};

struct fen3 {
	struct dd yz, y, z;	/* sums of u_iy u_iz, u_iy, u_iz */
	double c;		/* count, exact */
};

/* Stable insertion sort of positions a[0..m-1] by coordinate c of u. */
static void cdq_isort(const double *u, uint32_t *a, size_t m, int c)
{
	for (size_t i = 1; i < m; i++) {
		uint32_t t = a[i];
		double v = u[3 * (size_t)t + (size_t)c];
		size_t j = i;
		for (; j > 0 && u[3 * (size_t)a[j - 1] + (size_t)c] > v; j--)
			a[j] = a[j - 1];
		a[j] = t;
	}
}

/* Blocks b .. e-1 of CDQ_BASE positions: their own pairs (i < j, the x
 * factor u_jx), and their lists by y and z. */
static int cdq_base(void *ctx, uint64_t b, uint64_t e)
{
	struct cdq *c = ctx;

	for (uint64_t k = b; k < e; k++) {
		size_t lo = (size_t)k * CDQ_BASE, hi = lo + CDQ_BASE;
		struct dd acc = dd_from(0.0);
		hi = hi < c->n ? hi : c->n;
		for (size_t j = lo; j < hi; j++) {
			const double *q = c->u + 3 * j;
			double s = 0.0, e2 = 0.0;
			for (size_t i = lo; i < j; i++) {
				const double *p = c->u + 3 * i;
				double t = q[0] * (p[1] < q[1] ? p[1] : q[1]) *
				    (p[2] < q[2] ? p[2] : q[2]);
				struct dd r = dd_two_sum(s, t);
				s = r.hi, e2 += r.lo;
			}
			acc = dd_add(acc, dd_two_sum(s, e2));
			c->ys[j] = c->zs[j] = (uint32_t)j;
		}
		cdq_isort(c->u, c->ys + lo, hi - lo, 1);
		cdq_isort(c->u, c->zs + lo, hi - lo, 2);
		c->part[k] = acc;
	}
	return 0;
}

/* The merge by z of block [lo, hi), L = [lo, mid): zpos of L, c_j and
 * the sums of R; zs of the block merged through tmp. */
static void cdq_zmerge(struct cdq *c, size_t lo, size_t mid, size_t hi,
    uint32_t *tmp)
{
	const double *u = c->u;
	size_t i = lo, o = 0;
	uint32_t cnt = 0;
	struct dd s = dd_from(0.0);

	for (size_t r = mid; r < hi; r++) {
		uint32_t j = c->zs[r];
		double v = u[3 * (size_t)j + 2];
		for (; i < mid && u[3 * (size_t)c->zs[i] + 2] <= v; i++) {
			uint32_t p = c->zs[i];
			c->zpos[p] = cnt++;
			s = dd_add_d(s, u[3 * (size_t)p + 2]);
			tmp[o++] = p;
		}
		c->zc[j] = cnt;
		c->zsum[j] = s;
		tmp[o++] = j;
	}
	for (; i < mid; i++) {
		c->zpos[c->zs[i]] = cnt++;
		tmp[o++] = c->zs[i];
	}
	memcpy(c->zs + lo, tmp, (hi - lo) * sizeof *tmp);
}

/* The merge by y: the pairs of R with L, as in the comment above. */
static struct dd cdq_ymerge(struct cdq *c, size_t lo, size_t mid,
    size_t hi, uint32_t *tmp, struct fen3 *f)
{
	const double *u = c->u;
	size_t i = lo, o = 0, nl = mid - lo;
	struct dd acc = dd_from(0.0), ty = dd_from(0.0);
	double tc = 0.0;

	memset(f, 0, (nl + 1) * sizeof *f);
	for (size_t r = mid; r < hi; r++) {
		uint32_t j = c->ys[r];
		const double *q = u + 3 * (size_t)j;
		struct fen3 a = { { 0, 0 }, { 0, 0 }, { 0, 0 }, 0 };
		struct dd t;
		for (; i < mid && u[3 * (size_t)c->ys[i] + 1] <= q[1]; i++) {
			uint32_t p = c->ys[i];
			double py = u[3 * (size_t)p + 1], pz = u[3 * (size_t)p + 2];
			double pyz = py * pz;
			for (size_t x = (size_t)c->zpos[p] + 1; x <= nl;
			    x += x & (~x + 1)) {
				f[x].yz = dd_add_d(f[x].yz, pyz);
				f[x].y = dd_add_d(f[x].y, py);
				f[x].z = dd_add_d(f[x].z, pz);
				f[x].c += 1.0;
			}
			ty = dd_add_d(ty, py);
			tc += 1.0;
			tmp[o++] = p;
		}
		for (size_t x = c->zc[j]; x > 0; x &= x - 1) {
			a.yz = dd_add(a.yz, f[x].yz);
			a.y = dd_add(a.y, f[x].y);
			a.z = dd_add(a.z, f[x].z);
			a.c += f[x].c;
		}
		t = dd_add(a.yz, dd_mul_d(dd_add(ty, dd_mul_d(a.y, -1.0)),
		    q[2]));
		t = dd_add(t, dd_mul_d(dd_add(c->zsum[j], dd_mul_d(a.z, -1.0)),
		    q[1]));
		t = dd_add(t, dd_mul_d(dd_prod(q[1], q[2]),
		    ((double)nl - c->zc[j]) - (tc - a.c)));
		acc = dd_add(acc, dd_mul_d(t, q[0]));
		tmp[o++] = j;
	}
	for (; i < mid; i++)
		tmp[o++] = c->ys[i];
	memcpy(c->ys + lo, tmp, (hi - lo) * sizeof *tmp);
	return acc;
}

/* Blocks b .. e-1 of 2w positions at the level of c->w. */
static int cdq_level(void *ctx, uint64_t b, uint64_t e)
{
	struct cdq *c = ctx;
	size_t w = c->w;
	uint32_t *tmp = malloc(2 * w * sizeof *tmp);
	struct fen3 *f = malloc((w + 1) * sizeof *f);

	if (tmp == NULL || f == NULL) {
		free(tmp), free(f);
		return cli_fail("no memory for %zu points", c->n);
	}
	for (uint64_t k = b; k < e; k++) {
		size_t lo = 2 * w * (size_t)k, mid = lo + w, hi = mid + w;
		hi = hi < c->n ? hi : c->n;
		c->part[k] = dd_from(0.0);
		if (mid >= hi)
			continue;	/* no later half: the lists stand */
		cdq_zmerge(c, lo, mid, hi, tmp);
		c->part[k] = cdq_ymerge(c, lo, mid, hi, tmp, f);
	}
	free(tmp), free(f);
	return 0;
}

/* Chunks of blocks of width bw on the team or in order, and the sum of
 * the partials of the nb blocks, in order. */
static int cdq_pass(struct cdq *c, size_t nb, size_t bw,
    int (*fn)(void *, uint64_t, uint64_t), int par, struct dd *sum)
{
	size_t per = bw >= CDQ_WORK ? 1 : CDQ_WORK / bw;
	int rc = par ? cli_parallel(nb, per, fn, c, NULL) :
	    fn(c, 0, nb);

	for (size_t k = 0; rc == 0 && k < nb; k++)
		*sum = dd_add(*sum, c->part[k]);
	return rc;
}

/* The pair sum P of the 3-D points x, diagonal included. */
static int cdq_pairs(const double *x, size_t n, int par, struct dd *out)
{
	struct cdq c = { .n = n };
	size_t nb = (n + CDQ_BASE - 1) / CDQ_BASE;
	uint32_t *ord = cli_try_calloc("the exact D2", (uint64_t)n, 5 *
	    sizeof *ord);
	struct dd off = dd_from(0.0), diag = dd_from(0.0);
	int rc = -1;

	c.u = cli_try_calloc("the exact D2", (uint64_t)n, 3 * sizeof *c.u);
	c.zsum = cli_try_calloc("the exact D2", (uint64_t)n, sizeof *c.zsum);
	c.part = calloc(nb, sizeof *c.part);
	if (ord == NULL || c.u == NULL || c.zsum == NULL || c.part == NULL) {
		if (c.part == NULL)
			cli_fail("no memory for %zu points", n);
		goto out;
	}
	c.ys = ord + n, c.zs = ord + 2 * n;
	c.zpos = ord + 3 * n, c.zc = ord + 4 * n;
	if (disc_order(x, n, 3, ord) < 0)
		goto out;
	for (size_t p = 0; p < n; p++) {
		const double *q = x + 3 * (size_t)ord[p];
		double *v = c.u + 3 * p;
		v[0] = 1.0 - q[0], v[1] = 1.0 - q[1], v[2] = 1.0 - q[2];
		diag = dd_add_d(diag, v[0] * v[1] * v[2]);
	}
	if (cdq_pass(&c, nb, CDQ_BASE, cdq_base, par, &off) < 0)
		goto out;
	for (c.w = CDQ_BASE; c.w < n; c.w *= 2)
		if (cdq_pass(&c, (n + 2 * c.w - 1) / (2 * c.w), 2 * c.w,
		    cdq_level, par, &off) < 0)
			goto out;
	*out = dd_add(dd_mul_d(off, 2.0), diag);
	rc = 0;
out:
	free(ord), free(c.u), free(c.zsum), free(c.part);
	return rc;
}

double disc_star_l2_exact_k(const double *x, size_t n, unsigned k, int par)
{
	size_t nch = (n + L2_ROWS - 1) / L2_ROWS;
	double *u = cli_try_calloc("the exact D2", (uint64_t)n * k, sizeof *u);
	struct l2job c = { u, n, k, calloc(nch ? nch : 1, sizeof(struct dd)) };
	struct dd single = dd_from(0.0), pairs = dd_from(0.0), t;
	double v;

	if (u == NULL || c.part == NULL) {
		if (u != NULL)
			cli_fail("no memory for %zu points", n);
		free(u), free(c.part);
		return -1.0;
	}
	for (size_t i = 0; i < n; i++) {
		double p = 1.0;
		for (unsigned d = 0; d < k; d++) {
			double xd = x[(size_t)k * i + d];
			u[(size_t)d * n + i] = 1.0 - xd;
			p *= 1.0 - xd * xd;
		}
		single = dd_add_d(single, p);
	}
	if (k == 3) {
		free(u), free(c.part);
		if (cdq_pairs(x, n, par, &pairs) < 0)
			return -1.0;
	} else {
		if (disc_run_chunks(n, L2_ROWS, l2_chunk, &c, par) < 0) {
			free(u), free(c.part);
			return -1.0;
		}
		for (size_t q = 0; q < nch; q++)
			pairs = dd_add(pairs, c.part[q]);
		free(u), free(c.part);
	}
	t = dd_div_d(dd_div_d(pairs, (double)n), (double)n);
	t = dd_add(t, dd_mul_d(dd_div_d(single, (double)n),
	    -ldexp(1.0, 1 - (int)k)));
	t = dd_add(t, dd_div_d(dd_from(1.0), pow(3.0, (double)k)));
	v = dd_value(t);
	return v > 0.0 ? sqrt(v) : 0.0;
}

/* ---- Dinf over the critical boxes ----------------------------------- */

/*
 * The corners (a, b, c): a from the distinct x coordinates and 1, b, c
 * likewise.  Ranks: value p of an axis is V[p], p = 1..m, V[m+1] = 1; a
 * point of rank r has coordinate V[r].  P[p][q] counts the swept points
 * (x below or at the current a) of y rank <= p and z rank <= q, so the
 * closed box up to (V_y[p], V_z[q]) holds P[p][q] of them and the open
 * one P[p-1][q-1].  At each a the deficit is read before the points of
 * that x are added (open in x), the excess after (closed in x).
 */
struct axis {
	double *v;		/* v[0] = 0 (unused), v[1..m], v[m+1] = 1 */
	uint32_t m;
};

struct dinf3 {
	const double *xyz;
	size_t n;
	struct axis ax[3];
	uint32_t *rank;		/* 3 per point, 1-based */
	uint32_t *order;	/* points by x rank */
	uint32_t *xstart;	/* points of x rank r: order[xstart[r-1] ..
				 * xstart[r] - 1] */
	double *frac;		/* frac[c] = c / n, c = 0..n: a load instead
				 * of a division, the same bits */
	double *zlo, *zhi;	/* z at both ends of each block of z ranks */
	size_t nb;		/* blocks, covering q = 1..m_z + 1 */
	double *best;		/* per chunk */
};

struct vkey {
	double v;
	uint32_t i;
};

static int vkey_cmp(const void *a, const void *b)
{
	const struct vkey *p = a, *q = b;

	return p->v != q->v ? NUM_CMP(p->v, q->v) : NUM_CMP(p->i, q->i);
}

/* Distinct values of coordinate c, and the rank of every point. */
static int axis_make(struct dinf3 *d, int c, struct vkey *k)
{
	struct axis *a = &d->ax[c];
	size_t n = d->n;
	uint32_t m = 0;

	for (size_t i = 0; i < n; i++)
		k[i].v = d->xyz[3 * i + (size_t)c], k[i].i = (uint32_t)i;
	qsort(k, n, sizeof *k, vkey_cmp);
	if ((a->v = malloc((n + 2) * sizeof *a->v)) == NULL)
		return cli_fail("no memory for %zu points", n);
	a->v[0] = 0.0;
	for (size_t i = 0; i < n; i++) {
		if (i == 0 || k[i].v != k[i - 1].v)
			a->v[++m] = k[i].v;
		d->rank[3 * (size_t)k[i].i + (size_t)c] = m;
		if (c == 0)
			d->order[i] = k[i].i;
	}
	a->m = m;
	a->v[m + 1] = 1.0;
	return 0;
}

static void dinf3_free(struct dinf3 *d)
{
	for (int c = 0; c < 3; c++)
		free(d->ax[c].v);
	free(d->rank), free(d->order), free(d->xstart), free(d->best);
	free(d->frac), free(d->zlo);
}

/* The last z rank of block k (see struct table), w = m_z + 2. */
static size_t block_last(size_t w, size_t k)
{
	size_t l = QBLOCK * (k + 1);
	return l < w - 1 ? l : w - 1;
}

/* The blocks of z ranks and the z at their ends. */
static int blocks_init(struct dinf3 *d)
{
	size_t w = (size_t)d->ax[2].m + 2;

	d->nb = (w - 2) / QBLOCK + 1;	/* q = 1..w-1 */
	if ((d->zlo = malloc(2 * d->nb * sizeof *d->zlo)) == NULL)
		return cli_fail("no memory for %zu points", d->n);
	d->zhi = d->zlo + d->nb;
	for (size_t k = 0; k < d->nb; k++) {
		d->zlo[k] = d->ax[2].v[1 + QBLOCK * k];
		d->zhi[k] = d->ax[2].v[block_last(w, k)];
	}
	return 0;
}

static int dinf3_init(struct dinf3 *d, const double *xyz, size_t n)
{
	struct vkey *k = malloc(n * sizeof *k);

	memset(d, 0, sizeof *d);
	d->xyz = xyz, d->n = n;
	d->rank = malloc(3 * n * sizeof *d->rank);
	d->order = malloc(n * sizeof *d->order);
	d->xstart = calloc(n + 1, sizeof *d->xstart);
	d->frac = malloc((n + 1) * sizeof *d->frac);
	if (k == NULL || d->rank == NULL || d->order == NULL ||
	    d->xstart == NULL || d->frac == NULL) {
		free(k);
		return cli_fail("no memory for %zu points", n);
	}
	for (size_t c = 0; c <= n; c++)
		d->frac[c] = (double)c / (double)n;
	for (int c = 0; c < 3; c++)
		if (axis_make(d, c, k) < 0) {
			free(k);
			return -1;
		}
	free(k);
	for (size_t i = 0; i < n; i++)
		d->xstart[d->rank[3 * (size_t)d->order[i]]]++;
	for (uint32_t r = 0; r < d->ax[0].m; r++)
		d->xstart[r + 1] += d->xstart[r];
	return blocks_init(d);
}

/*
 * The counts of one chunk.  B, exact at all times: per row p = 0..h-1
 * (h = m_y + 2) a 0 and the count of the closed box up to the last
 * column of each block of QBLOCK z ranks (block k: q = 1 + QBLOCK k ..
 * L(k) = min(QBLOCK (k + 1), w - 1), w = m_z + 2), nb + 1 per row.  The
 * bounds read only B.  P, the count of every (p, q), is rebuilt only now
 * and then (a flush); the points swept since are kept in a short pending
 * list, and the rare blocks the bounds do not rule out add them up.
 * A point costs (h - p)(nb - k) increments of B, 1/QBLOCK of P's.
 * Counts are 16-bit (n <= DISC3_MAX_EXACT_N): half the memory to sweep.
 */
#if DISC3_MAX_EXACT_N > 65535
#error "16-bit counts"
#endif
#define PENDING 128		/* points swept between two flushes, at most */

struct table {
	uint16_t *P, *B;
	size_t w, h, nb;
	uint32_t *pend;		/* y, z ranks of the points since the flush */
	size_t npend;
	uint64_t work;		/* pending points looked at since */
};

/* Point i swept: B now, P at the next flush. */
static void counts_add(const struct dinf3 *d, struct table *t, uint32_t i)
{
	size_t ry = d->rank[3 * (size_t)i + 1], rz = d->rank[3 * (size_t)i + 2];
	size_t nb = t->nb, k0 = (rz - 1) / QBLOCK + 1;

	for (size_t p = ry; p < t->h; p++) {
		uint16_t *brow = t->B + p * (nb + 1);
		size_t k = k0;
		/* eight at a time: the compiler makes one vector add of it */
		for (; k + 8 <= nb + 1; k += 8) {
			uint16_t *v = brow + k;
			v[0]++, v[1]++, v[2]++, v[3]++;
			v[4]++, v[5]++, v[6]++, v[7]++;
		}
		for (; k <= nb; k++)
			brow[k]++;
	}
	t->pend[2 * t->npend] = (uint32_t)ry;
	t->pend[2 * t->npend + 1] = (uint32_t)rz;
	t->npend++;
}

/* P and B of the points of x rank below r, from scratch: histogram,
 * prefix sums; nothing pending. */
static void counts_init(const struct dinf3 *d, struct table *t, uint32_t r)
{
	uint16_t *P = t->P;
	size_t w = t->w, nb = t->nb;

	memset(P, 0, t->w * t->h * sizeof *P);
	for (uint32_t s = 0; r > 0 && s < d->xstart[r - 1]; s++) {
		uint32_t i = d->order[s];
		P[d->rank[3 * (size_t)i + 1] * w + d->rank[3 * (size_t)i + 2]]++;
	}
	for (size_t p = 0; p < t->h; p++)
		for (size_t q = 1; q < w; q++)
			P[p * w + q] = (uint16_t)(P[p * w + q] + P[p * w + q - 1]);
	for (size_t p = 1; p < t->h; p++)
		for (size_t q = 0; q < w; q++)
			P[p * w + q] = (uint16_t)(P[p * w + q] +
			    P[(p - 1) * w + q]);
	for (size_t p = 0; p < t->h; p++) {
		t->B[p * (nb + 1)] = 0;
		for (size_t k = 0; k < nb; k++)
			t->B[p * (nb + 1) + k + 1] = P[p * w + block_last(w, k)];
	}
	t->npend = 0;
	t->work = 0;
}

/* c[q - q0] = the exact closed count up to (row, q), q = q0..q1
 * (q1 - q0 < QBLOCK): P plus the pending points below and left. */
static void block_counts(struct table *t, size_t row, size_t q0,
    size_t q1, uint32_t *c)
{
	uint32_t add[QBLOCK + 1] = { 0 }, run = 0;

	t->work += t->npend;
	for (size_t j = 0; j < t->npend; j++) {
		size_t ry = t->pend[2 * j], rz = t->pend[2 * j + 1];
		if (ry <= row && rz <= q1)
			add[rz > q0 ? rz - q0 : 0]++;
	}
	for (size_t q = q0; q <= q1; q++) {
		run += add[q - q0];
		c[q - q0] = t->P[row * t->w + q] + run;
	}
}

/*
 * Counts grow with p and q, and so do the volumes: the values of a block
 * (one row, QBLOCK columns) or a tile (TILE rows of a block) are bounded
 * by the largest volume less the smallest count (deficit), or the
 * largest count less the smallest volume (excess).  Rounding is
 * monotone, so the bound computed in floating point bounds the values
 * computed.  What does not beat the best so far cannot change the
 * maximum and is skipped: almost everything for random sets, most for
 * sets of low discrepancy, whose best is small.
 * zlo[k], zhi[k]: z at the first and the last column of block k.
 */

/* Deficit of the corners (a, y_p, z_q), q in block k: open boxes, the
 * counts of row p - 1 at columns q - 1. */
static double deficit_block(const struct dinf3 *d, struct table *t,
    size_t p, size_t k, double ay, double best)
{
	const double *z = d->ax[2].v, *f = d->frac;
	size_t q0 = 1 + QBLOCK * k, q1 = block_last(t->w, k);
	uint32_t c[QBLOCK];

	block_counts(t, p - 1, q0 - 1, q1 - 1, c);
	for (size_t q = q0; q <= q1; q++) {
		double v = ay * z[q] - f[c[q - q0]];
		best = v > best ? v : best;
	}
	return best;
}

/* max(best, a y_p z_q - open(p, q)/n), p, q = 1..m+1. */
static double deficit(const struct dinf3 *d, struct table *t,
    double a, double best)
{
	const double *y = d->ax[1].v, *f = d->frac, *zhi = d->zhi;
	size_t nb = t->nb;

	for (size_t p0 = 1; p0 < t->h; p0 += TILE) {
		size_t p1 = p0 + TILE - 1 < t->h - 1 ? p0 + TILE - 1 : t->h - 1;
		const uint16_t *blo = t->B + (p0 - 1) * (nb + 1);
		double ahi = a * y[p1];
		for (size_t k = 0; k < nb; k++) {
			if (ahi * zhi[k] - f[blo[k]] <= best)
				continue;
			for (size_t p = p0; p <= p1; p++) {
				double ay = a * y[p];
				if (ay * zhi[k] - f[t->B[(p - 1) * (nb + 1) + k]] >
				    best)
					best = deficit_block(d, t, p, k, ay, best);
			}
		}
	}
	return best;
}

/* Excess of the corners (a, y_p, z_q), q in block k up to m_z: closed
 * boxes, the counts of row p. */
static double excess_block(const struct dinf3 *d, struct table *t,
    size_t p, size_t k, double ay, double best)
{
	const double *z = d->ax[2].v, *f = d->frac;
	size_t q0 = 1 + QBLOCK * k, q1 = block_last(t->w, k);
	uint32_t c[QBLOCK];

	q1 = q1 < t->w - 2 ? q1 : t->w - 2;
	block_counts(t, p, q0, q1, c);
	for (size_t q = q0; q <= q1; q++) {
		double v = f[c[q - q0]] - ay * z[q];
		best = v > best ? v : best;
	}
	return best;
}

/* max(best, closed(p, q)/n - a y_p z_q), p, q = 1..m.  Count m+1 of a row
 * equals count m: B bounds the last block, cut at m, too. */
static double excess(const struct dinf3 *d, struct table *t,
    double a, double best)
{
	const double *y = d->ax[1].v, *f = d->frac, *zlo = d->zlo;
	size_t nb = t->nb, my = t->h - 2;
	size_t nbe = (t->w - 2 + QBLOCK - 1) / QBLOCK;

	for (size_t p0 = 1; p0 <= my; p0 += TILE) {
		size_t p1 = p0 + TILE - 1 < my ? p0 + TILE - 1 : my;
		const uint16_t *bhi = t->B + p1 * (nb + 1) + 1;
		double alo = a * y[p0];
		for (size_t k = 0; k < nbe; k++) {
			if (f[bhi[k]] - alo * zlo[k] <= best)
				continue;
			for (size_t p = p0; p <= p1; p++) {
				double ay = a * y[p];
				if (f[t->B[p * (nb + 1) + 1 + k]] - ay * zlo[k] >
				    best)
					best = excess_block(d, t, p, k, ay, best);
			}
		}
	}
	return best;
}

/* Sweeps r = b+1 .. e over the x ranks (r = m+1: a = 1). */
static int dinf3_chunk(void *ctx, uint64_t b, uint64_t e)
{
	struct dinf3 *d = ctx;
	struct table t = { .w = (size_t)d->ax[2].m + 2,
	    .h = (size_t)d->ax[1].m + 2, .nb = d->nb };
	double best = 0.0;

	t.P = cli_try_calloc("the exact 3-D Dinf", (uint64_t)t.w * t.h +
	    (uint64_t)(t.nb + 1) * t.h, sizeof *t.P);
	t.pend = malloc(2 * d->n * sizeof *t.pend);
	if (t.P == NULL || t.pend == NULL) {
		if (t.P != NULL)
			cli_fail("no memory for %zu points", d->n);
		free(t.P), free(t.pend);
		return -1;
	}
	t.B = t.P + t.w * t.h;
	counts_init(d, &t, (uint32_t)b + 1);
	for (uint32_t r = (uint32_t)b + 1; r <= (uint32_t)e; r++) {
		double a = d->ax[0].v[r];
		best = deficit(d, &t, a, best);
		if (r > d->ax[0].m)
			break;
		for (uint32_t s = d->xstart[r - 1]; s < d->xstart[r]; s++)
			counts_add(d, &t, d->order[s]);
		/* Ranks up to r swept: a flush, when the pending list grows
		 * long or the blocks have spent on it what a flush costs
		 * (sets of low discrepancy leave many blocks to look at). */
		if (t.npend > PENDING || t.work > (uint64_t)t.w * t.h)
			counts_init(d, &t, r + 1);
		best = excess(d, &t, a, best);
	}
	d->best[b / DINF_SWEEPS] = best;
	free(t.P), free(t.pend);
	return 0;
}

int disc3_star_dinf_exact(const double *xyz, size_t n, int par,
    double *dinf)
{
	struct dinf3 d;
	size_t sweeps, nch;
	int rc;

	if (n > DISC3_MAX_EXACT_N)
		return cli_fail("%zu points: the exact 3-D Dinf takes O(n^3) "
		    "time and is limited to %d points (Dinf on a grid is not)",
		    n, DISC3_MAX_EXACT_N);
	if (dinf3_init(&d, xyz, n) < 0) {
		dinf3_free(&d);
		return -1;
	}
	sweeps = (size_t)d.ax[0].m + 1;
	nch = (sweeps + DINF_SWEEPS - 1) / DINF_SWEEPS;
	if ((d.best = calloc(nch, sizeof *d.best)) == NULL) {
		dinf3_free(&d);
		return cli_fail("no memory for %zu points", n);
	}
	rc = disc_run_chunks(sweeps, DINF_SWEEPS, dinf3_chunk, &d, par);
	if (rc == 0) {
		*dinf = 0.0;
		for (size_t q = 0; q < nch; q++)
			*dinf = d.best[q] > *dinf ? d.best[q] : *dinf;
	}
	dinf3_free(&d);
	return rc;
}

/* ---- the grid ------------------------------------------------------- */

/*
 * Corners (i/s, j/s, l/s), i, j, l = 1..s.  A point of bins (kx, ky, kz)
 * (grid lines at or below each coordinate, disc_star_bin) lies in the
 * boxes with i > kx, j > ky, l > kz.  Plane i: H counts the points with
 * kx < i by (ky, kz); a running sum over the rows turns it into the
 * box counts of the plane, O(s^2) per plane.
 */
struct grid3 {
	const uint32_t *bin;	/* 3 per point */
	struct disc_rows rows;	/* points by kx */
	const double *g;	/* g[i] = i/s */
	uint32_t s;
	double n;
	double *sq, *best;	/* per chunk */
};

/* Sum of d^2 (Neumaier) and max |d| over the boxes of plane i. */
static void grid3_plane(const struct grid3 *c, const uint32_t *H,
    uint32_t *acc, uint32_t i, struct num_sum *sq, double *best)
{
	uint32_t s = c->s;

	memset(acc, 0, (size_t)s * sizeof *acc);
	for (uint32_t j = 1; j <= s; j++) {
		const uint32_t *row = H + (size_t)(j - 1) * s;
		double gij = c->g[i] * c->g[j];
		uint32_t run = 0;
		for (uint32_t l = 1; l <= s; l++) {
			double d;
			run += row[l - 1];
			acc[l - 1] += run;
			d = (double)acc[l - 1] / c->n - gij * c->g[l];
			num_add(sq, d * d);
			d = fabs(d);
			*best = d > *best ? d : *best;
		}
	}
}

/* Planes i = b+1 .. e. */
static int grid3_chunk(void *ctx, uint64_t b, uint64_t e)
{
	struct grid3 *c = ctx;
	size_t s = c->s;
	uint32_t *H = cli_try_calloc("the 3-D grid", (uint64_t)s * s + s,
	    sizeof *H);
	struct num_sum sq = { 0.0, 0.0 };
	double best = 0.0;

	if (H == NULL)
		return -1;
	for (uint32_t q = 0; q < c->rows.start[b]; q++) {
		const uint32_t *k = c->bin + 3 * (size_t)c->rows.idx[q];
		H[k[1] * s + k[2]]++;
	}
	for (uint64_t p = b; p < e; p++) {
		for (uint32_t q = c->rows.start[p]; q < c->rows.start[p + 1];
		    q++) {
			const uint32_t *k = c->bin + 3 * (size_t)c->rows.idx[q];
			H[k[1] * s + k[2]]++;
		}
		grid3_plane(c, H, H + s * s, (uint32_t)p + 1, &sq, &best);
	}
	c->sq[b / GRID_PLANES] = num_total(&sq);
	c->best[b / GRID_PLANES] = best;
	free(H);
	return 0;
}

int disc3_star_grid(const double *xyz, size_t n, uint32_t s, int par,
    struct disc_result *r)
{
	struct grid3 c = { .s = s, .n = (double)n };
	size_t nch = (s + GRID_PLANES - 1) / GRID_PLANES;
	uint32_t *bin = malloc(3 * n * sizeof *bin), *kx = malloc(n * sizeof *kx);
	double *g = malloc(((size_t)s + 1) * sizeof *g), ds = (double)s;
	int rc = -1;

	c.sq = calloc(2 * nch, sizeof *c.sq);
	if (s < 1 || s > DISC3_MAX_GRID) {
		free(bin), free(kx), free(g), free(c.sq);
		return cli_fail("3-D grid %u: 1 to %d allowed", s,
		    DISC3_MAX_GRID);
	}
	if (bin == NULL || kx == NULL || g == NULL || c.sq == NULL) {
		free(bin), free(kx), free(g), free(c.sq);
		return cli_fail("no memory for a %u^3 grid", s);
	}
	c.best = c.sq + nch;
	for (size_t i = 0; i < 3 * n; i++)
		bin[i] = disc_star_bin(xyz[i], s);
	for (size_t i = 0; i < n; i++)
		kx[i] = bin[3 * i];
	for (uint32_t i = 0; i <= s; i++)
		g[i] = disc_star_line(i, s);
	c.bin = bin, c.g = g;
	if (disc_rows_make(&c.rows, kx, n, s) == 0) {
		rc = disc_run_chunks(s, GRID_PLANES, grid3_chunk, &c, par);
		disc_rows_free(&c.rows);
	}
	if (rc == 0) {
		r->d2 = sqrt(num_sum(c.sq, nch) / (ds * ds * ds));
		r->dinf = 0.0;
		for (size_t q = 0; q < nch; q++)
			r->dinf = c.best[q] > r->dinf ? c.best[q] : r->dinf;
	}
	free(bin), free(kx), free(g), free(c.sq);
	return rc;
}
