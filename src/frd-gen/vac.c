/*
 * Void-and-cluster threshold matrices; see vac.h for the algorithm, the
 * integer energies and the tie rule.
 */
#define _POSIX_C_SOURCE 200809L
#include "frd-gen/vac.h"
#include "frd-gen/frdgen.h"
#include "cli/cli.h"
#include "frs.h"	/* frs_rand64, struct frs_rng */

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Random streams of this module, far from the FRS_STREAM_* numbers
 * (cl/defs.cl) so that no other consumer of a seed shares them. */
#define VAC_STREAM_INIT 0x56414331u	/* "VAC1": the initial pattern */
#define VAC_STREAM_TIE 0x56414332u	/* "VAC2": tie keys */

#define NONE UINT32_MAX

/* The kernel's extent on the torus, shared by vac_memory and the run. */
struct reach {
	double r2max;		/* squared truncation radius, INFINITY: none */
	int bits;		/* S */
	uint32_t ex, ey, ez;	/* largest |offset| per axis with K_q > 0 */
};

struct vac {
	const struct vac_params *pr;
	uint32_t w, h, d;
	size_t n;		/* cells */
	size_t p;		/* leaves of the trees: a power of two >= n */
	int64_t *e;		/* energies, in units of 2^-S */
	uint32_t *key;		/* tie keys */
	unsigned char *bit;	/* the binary pattern */
	/* Tournament trees over the cells, node k's children 2k and 2k+1,
	 * leaf of cell c at p + c: the tightest cluster (1 of highest
	 * energy) and the largest void (0 of lowest energy) below each
	 * node, NONE where there is none. */
	uint32_t *one, *zero;
	struct reach rc;
	int64_t *tab;		/* K_q by |dx|, |dy|, |dz| */
	int32_t *xext;		/* per (|dy|, |dz|): largest |dx| with K_q > 0 */
	int tree;		/* 0 while many flips come before a rebuild */
};

/* ---- parameters --------------------------------------------------- */

void vac_defaults(struct vac_params *pr)
{
	memset(pr, 0, sizeof *pr);
	pr->dims = 2;
	pr->sigma = VAC_DEFAULT_SIGMA;
	pr->tol = VAC_DEFAULT_TOL;
	pr->seed = 1;
}

int vac_check(const struct vac_params *pr)
{
	if (frdgen_check_size(pr->dims, pr->w, pr->h, pr->d) < 0)
		return -1;
	if (!(pr->sigma > 0.0 && isfinite(pr->sigma)))
		return cli_fail("the void-and-cluster sigma %g is not a positive number",
		    pr->sigma);
	if (!(pr->tol >= 0.0 && pr->tol < 1.0))
		return cli_fail("the filter tolerance %g is outside [0, 1)", pr->tol);
	return 0;
}

double vac_radius(const struct vac_params *pr)
{
	if (pr->tol <= 0.0)
		return INFINITY;
	return sqrt(2.0 * pr->sigma * pr->sigma * log(1.0 / pr->tol));
}

int vac_scale_bits(const struct vac_params *pr)
{
	/* sum K over the torus is the product of the sums along the axes
	 * (K is separable), each below 1 + sqrt(2 pi) sigma and below the
	 * side; with 2^S times it under 2^61 the rounding of up to 2^32
	 * terms cannot overflow either. */
	double a = 1.0 + sqrt(2.0 * NUM_PI) * pr->sigma;
	double b = fmin((double)pr->w, a) * fmin((double)pr->h, a);
	int e;

	if (pr->dims == 3)
		b *= fmin((double)pr->d, a);
	frexp(b, &e);
	return 61 - e;
}

uint64_t vac_ones(uint64_t n)
{
	uint64_t m = (n + 9) / 10;
	return m > 0 ? m : 1;
}

uint32_t vac_tiekey(const struct vac_params *pr, uint32_t c)
{
	return (uint32_t)(frs_rand64(pr->seed, VAC_STREAM_TIE, c) >> 32);
}

void vac_initial_cells(const struct vac_params *pr, uint32_t *perm)
{
	uint64_t n = (uint64_t)pr->w * pr->h * pr->d, m = vac_ones(n);
	struct frs_rng r;

	for (uint64_t i = 0; i < n; i++)
		perm[i] = (uint32_t)i;
	/* The first m steps of a Fisher-Yates shuffle: m distinct cells,
	 * uniformly. */
	frs_rng_init(&r, pr->seed, VAC_STREAM_INIT);
	for (uint64_t i = 0; i < m; i++) {
		uint64_t j = i + frs_rng_below(&r, n - i);
		uint32_t t = perm[i];
		perm[i] = perm[j];
		perm[j] = t;
	}
}

void vac_describe(const struct vac_params *pr, char *buf, size_t n)
{
	snprintf(buf, n, "generator=frd-gen\nmethod=vac\nk=%u\nsize=%ux%ux%u\n"
	    "sigma=%.17g\ntol=%.17g\nseed=%llu\n", pr->dims, pr->w, pr->h,
	    pr->d, pr->sigma, pr->tol, (unsigned long long)pr->seed);
}

/* ---- the kernel --------------------------------------------------- */

static int64_t kernel_q(const struct vac_params *pr, const struct reach *rc,
    double r2)
{
	if (r2 > rc->r2max)
		return 0;
	return llround(ldexp(exp(-r2 / (2.0 * pr->sigma * pr->sigma)),
	    rc->bits));
}

/* Largest offset a <= size/2 along one axis where K_q > 0: K falls with
 * the distance, so nothing further out is applied. */
static uint32_t axis_reach(const struct vac_params *pr,
    const struct reach *rc, uint32_t size)
{
	uint32_t a = 0;

	while (a < size / 2 && kernel_q(pr, rc, (double)(a + 1) * (a + 1)) > 0)
		a++;
	return a;
}

static void get_reach(const struct vac_params *pr, struct reach *rc)
{
	rc->r2max = pr->tol > 0.0 ? 2.0 * pr->sigma * pr->sigma *
	    log(1.0 / pr->tol) : INFINITY;
	rc->bits = vac_scale_bits(pr);
	rc->ex = axis_reach(pr, rc, pr->w);
	rc->ey = axis_reach(pr, rc, pr->h);
	rc->ez = pr->dims == 3 ? axis_reach(pr, rc, pr->d) : 0;
}

static uint64_t pow2_at_least(uint64_t n)
{
	uint64_t p = 1;
	while (p < n)
		p *= 2;
	return p;
}

uint64_t vac_memory(const struct vac_params *pr)
{
	uint64_t n = (uint64_t)pr->w * pr->h * pr->d, p = pow2_at_least(n);
	uint64_t rows, tab;
	struct reach rc;

	get_reach(pr, &rc);
	rows = ((uint64_t)rc.ey + 1) * (rc.ez + 1);
	tab = rows * (rc.ex + 1);
	/* energies, keys, pattern, output, two trees, tables */
	return n * (8 + 4 + 1 + 4) + 2 * (2 * p) * 4 + tab * 8 + rows * 4 +
	    (1 << 20);
}

/* K_q by |offset| and the x reach of each row; the largest distance
 * applied goes to *radius. */
static int make_table(struct vac *g, double *radius)
{
	const struct reach *rc = &g->rc;
	size_t nx = rc->ex + 1, ny = rc->ey + 1, nz = rc->ez + 1;

	g->tab = malloc(nx * ny * nz * sizeof *g->tab);
	g->xext = malloc(ny * nz * sizeof *g->xext);
	if (g->tab == NULL || g->xext == NULL)
		return cli_fail("out of memory for the void-and-cluster kernel");
	*radius = 0.0;
	for (size_t z = 0; z < nz; z++)
		for (size_t y = 0; y < ny; y++) {
			int64_t *t = g->tab + (z * ny + y) * nx;
			int32_t last = -1;
			for (size_t x = 0; x < nx; x++) {
				double r2 = (double)(x * x + y * y + z * z);
				t[x] = kernel_q(g->pr, rc, r2);
				if (t[x] > 0) {
					last = (int32_t)x;
					*radius = fmax(*radius, sqrt(r2));
				}
			}
			g->xext[z * ny + y] = last;
		}
	return 0;
}

static void vac_free(struct vac *g)
{
	free(g->e), free(g->key), free(g->bit), free(g->one);
	free(g->zero), free(g->tab), free(g->xext);
}

static int vac_init(struct vac *g, const struct vac_params *pr,
    double *radius)
{
	memset(g, 0, sizeof *g);
	g->pr = pr;
	g->w = pr->w;
	g->h = pr->h;
	g->d = pr->d;
	g->n = (size_t)pr->w * pr->h * pr->d;
	g->p = (size_t)pow2_at_least(g->n);
	get_reach(pr, &g->rc);
	g->e = calloc(g->n, sizeof *g->e);
	g->key = malloc(g->n * sizeof *g->key);
	g->bit = calloc(g->n, 1);
	g->one = malloc(2 * g->p * sizeof *g->one);
	g->zero = malloc(2 * g->p * sizeof *g->zero);
	if (!g->e || !g->key || !g->bit || !g->one || !g->zero)
		return cli_fail("out of memory for a %zu-cell void-and-cluster "
		    "matrix", g->n);
	for (size_t c = 0; c < g->n; c++)
		g->key[c] = vac_tiekey(pr, (uint32_t)c);
	return make_table(g, radius);
}

/* ---- the tournament trees ------------------------------------------ */

/* Among equal energies: the lower tie key, then the lower index. */
static uint32_t tie(const struct vac *g, uint32_t a, uint32_t b)
{
	if (g->key[a] != g->key[b])
		return g->key[a] < g->key[b] ? a : b;
	return a < b ? a : b;
}

static uint32_t cluster_of(const struct vac *g, uint32_t a, uint32_t b)
{
	if (a == NONE || b == NONE)
		return a == NONE ? b : a;
	if (g->e[a] != g->e[b])
		return g->e[a] > g->e[b] ? a : b;
	return tie(g, a, b);
}

static uint32_t void_of(const struct vac *g, uint32_t a, uint32_t b)
{
	if (a == NONE || b == NONE)
		return a == NONE ? b : a;
	if (g->e[a] != g->e[b])
		return g->e[a] < g->e[b] ? a : b;
	return tie(g, a, b);
}

static void set_leaf(struct vac *g, size_t c)
{
	g->one[g->p + c] = g->bit[c] ? (uint32_t)c : NONE;
	g->zero[g->p + c] = g->bit[c] ? NONE : (uint32_t)c;
}

static void set_node(struct vac *g, size_t k)
{
	g->one[k] = cluster_of(g, g->one[2 * k], g->one[2 * k + 1]);
	g->zero[k] = void_of(g, g->zero[2 * k], g->zero[2 * k + 1]);
}

static void tree_build(struct vac *g)
{
	for (size_t c = 0; c < g->p; c++)
		if (c < g->n)
			set_leaf(g, c);
		else
			g->one[g->p + c] = g->zero[g->p + c] = NONE;
	for (size_t k = g->p - 1; k >= 1; k--)
		set_node(g, k);
	g->tree = 1;
}

/* Cells a .. b changed: their leaves and every node above them.  A row of
 * the window is one run, so the nodes above it merge within a few
 * levels and each costs O(run + log N). */
static void tree_run(struct vac *g, size_t a, size_t b)
{
	if (!g->tree)
		return;
	for (size_t c = a; c <= b; c++)
		set_leaf(g, c);
	for (a = (g->p + a) / 2, b = (g->p + b) / 2; a >= 1; a /= 2, b /= 2)
		for (size_t k = a; k <= b; k++)
			set_node(g, k);
}

/* ---- flips ---------------------------------------------------------- */

static uint32_t umin(uint32_t a, uint32_t b)
{
	return a < b ? a : b;
}

/* Add sgn * K_q(|dx|) to cells x = cx + dx of one row, dx from -e to e
 * but each cell of the torus once, then update the trees. */
static void flip_row(struct vac *g, uint32_t cx, size_t row,
    const int64_t *t, uint32_t e, int64_t sgn)
{
	int64_t lo = -(int64_t)umin(e, (g->w - 1) / 2);
	int64_t hi = umin(e, g->w / 2);
	int64_t *er = g->e + row;
	uint32_t x0 = (uint32_t)(((int64_t)cx + lo + g->w) % g->w);
	uint32_t len = (uint32_t)(hi - lo + 1);
	uint32_t first = umin(len, g->w - x0);	/* cells before the seam */
	int64_t dx = lo;

	for (uint32_t i = 0; i < len; i++, dx++)
		er[(x0 + i) % g->w] += sgn * t[dx < 0 ? -dx : dx];
	tree_run(g, row + x0, row + x0 + first - 1);
	if (first < len)
		tree_run(g, row, row + (len - first) - 1);
}

/* Turn cell c on (1) or off (0): its kernel added to or taken from the
 * energies around it. */
static void flip(struct vac *g, uint32_t c, int on)
{
	const struct reach *rc = &g->rc;
	uint32_t cx = c % g->w, cy = c / g->w % g->h, cz = c / g->w / g->h;
	int64_t ylo = -(int64_t)umin(rc->ey, (g->h - 1) / 2), yhi = umin(rc->ey,
	    g->h / 2);
	int64_t zlo = -(int64_t)umin(rc->ez, (g->d - 1) / 2), zhi = umin(rc->ez,
	    g->d / 2);
	size_t nx = rc->ex + 1, ny = rc->ey + 1;

	g->bit[c] = (unsigned char)on;
	for (int64_t dz = zlo; dz <= zhi; dz++)
		for (int64_t dy = ylo; dy <= yhi; dy++) {
			size_t az = (size_t)(dz < 0 ? -dz : dz);
			size_t ay = (size_t)(dy < 0 ? -dy : dy);
			int32_t e = g->xext[az * ny + ay];
			size_t y = (size_t)(((int64_t)cy + dy + g->h) % g->h);
			size_t z = (size_t)(((int64_t)cz + dz + g->d) % g->d);
			if (e >= 0)
				flip_row(g, cx, (z * g->h + y) * g->w,
				    g->tab + (az * ny + ay) * nx, (uint32_t)e,
				    on ? 1 : -1);
		}
}

/* ---- the phases ----------------------------------------------------- */

/* Phase 0: move the tightest cluster to the largest void until it would
 * go back where it came from.  Returns the number of moves. */
static uint64_t relax(struct vac *g)
{
	uint64_t moves;

	/* Each move lowers the total pair energy, or keeps it in a tie; the
	 * cap only guards against ties cycling, never seen. */
	for (moves = 0; moves < g->n; moves++) {
		uint32_t t = g->one[1], v;
		flip(g, t, 0);
		v = g->zero[1];
		if (v == t) {
			flip(g, t, 1);
			break;
		}
		flip(g, v, 1);
	}
	return moves;
}

static void progress_at(struct cli_task *task, uint64_t done)
{
	if (task != NULL && (done & 4095) == 0)
		cli_task_update(task, done);
}

/* Phase 1: remove the tightest clusters of the initial pattern, ranks
 * ones - 1 down to 0. */
static void remove_clusters(struct vac *g, uint32_t *rank, uint64_t ones,
    struct cli_task *task)
{
	for (uint64_t r = ones; r-- > 0;) {
		uint32_t t = g->one[1];
		rank[t] = (uint32_t)r;
		flip(g, t, 0);
		progress_at(task, ones - r);
	}
}

/* Phases 2 and 3: fill the largest voids, ranks ones .. N-1 (see vac.h:
 * the zero energy's maximum is the energy's minimum over the 0s). */
static void fill_voids(struct vac *g, uint32_t *rank, uint64_t ones,
    struct cli_task *task)
{
	for (uint64_t r = ones; r < g->n; r++) {
		uint32_t v = g->zero[1];
		rank[v] = (uint32_t)r;
		flip(g, v, 1);
		progress_at(task, r + 1);
	}
}

/* Set the given cells, then rebuild the trees once: cheaper than keeping
 * them current through thousands of flips. */
static void set_pattern(struct vac *g, const uint32_t *cells, uint64_t m)
{
	g->tree = 0;
	for (uint64_t i = 0; i < m; i++)
		flip(g, cells[i], 1);
	tree_build(g);
}

int vac_run(const struct vac_params *pr, struct frs_matrix *out,
    struct cli_task *task, struct vac_stats *st)
{
	char params[512];
	frs_error err;
	struct vac g;
	uint64_t ones, moves, k = 0;
	double radius = 0.0;

	memset(out, 0, sizeof *out);
	memset(&g, 0, sizeof g);
	if (vac_check(pr) < 0)
		return -1;
	/* The memory ceiling is the caller's, for everything together
	 * before anything exists (frd-gen's check of vac_memory). */
	vac_describe(pr, params, sizeof params);
	if (frs_matrix_alloc(out, pr->dims, pr->w, pr->h, pr->d, params,
	    &err) != FRS_OK)
		return cli_fail("%s", err.message);
	if (vac_init(&g, pr, &radius) < 0) {
		vac_free(&g);
		frs_matrix_free(out);
		return -1;
	}
	ones = vac_ones(g.n);
	/* The output holds the initial cells first, the ranks after. */
	vac_initial_cells(pr, out->v);
	set_pattern(&g, out->v, ones);
	moves = relax(&g);
	for (size_t c = 0; c < g.n; c++)
		out->v[c] = NONE;
	remove_clusters(&g, out->v, ones, task);
	/* Back to the relaxed pattern: the cells of ranks below ones.  The
	 * energies are all exactly 0 again (integer sums). */
	for (size_t c = 0; c < g.n; c++)
		if (out->v[c] != NONE)
			g.one[k++] = (uint32_t)c;	/* scratch, rebuilt below */
	set_pattern(&g, g.one, k);
	fill_voids(&g, out->v, ones, task);
	if (st != NULL) {
		st->ones = ones;
		st->moves = moves;
		st->radius = radius;
	}
	vac_free(&g);
	return 0;
}
