#define _POSIX_C_SOURCE 200809L
#include "sample/levels.h"
#include "base/err.h"
#include "base/mem.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void frs_levels_free(struct frs_levels *L)
{
	free(L->lev);
	memset(L, 0, sizeof *L);
}

static uint64_t ncells(const struct frs_levels *L)
{
	return (uint64_t)L->side[0] * L->side[1] * L->side[2];
}

/* The grid the levels are smoothed on: the cells in blocks of f = 2^lf
 * per side (f^k cells, fewer at the far ends). */
struct grid {
	unsigned dims, lf;
	uint64_t side[3], f;
};

static uint64_t grid_n(const struct grid *g)
{
	return g->side[0] * g->side[1] * g->side[2];
}

/* One box filter of radius r along one line of n contiguous values,
 * truncated at the ends (the sums of the blocks inside the map only):
 * prefix sums in p, n + 1 of them. */
static void box_line(double *a, uint64_t n, uint64_t r, double *p)
{
	p[0] = 0.0;
	for (uint64_t i = 0; i < n; i++)
		p[i + 1] = p[i] + a[i];
	for (uint64_t i = 0; i < n; i++) {
		uint64_t lo = i > r ? i - r : 0, hi = i + r + 1 < n ? i + r + 1 : n;
		a[i] = p[hi] - p[lo];
	}
}

/* The same along n rows of s values each (an axis other than the
 * first): a sliding sum, a row at a time, from the copy src of the rows,
 * so that the inner loops run along memory. */
static void box_rows(double *a, const double *src, uint64_t n, uint64_t s,
    uint64_t r)
{
	for (uint64_t k = 0; k < s; k++)
		a[k] = 0.0;
	for (uint64_t j = 0; j <= r && j < n; j++)
		for (uint64_t k = 0; k < s; k++)
			a[k] += src[j * s + k];
	for (uint64_t i = 1; i < n; i++) {
		double *o = a + i * s;
		const double *prev = a + (i - 1) * s;
		for (uint64_t k = 0; k < s; k++)
			o[k] = prev[k];
		if (i + r < n)
			for (uint64_t k = 0; k < s; k++)
				o[k] += src[(i + r) * s + k];
		if (i > r)
			for (uint64_t k = 0; k < s; k++)
				o[k] -= src[(i - r - 1) * s + k];
	}
}

/* Three box passes along every axis of the grid: about a Gaussian of
 * standard deviation r blocks (each pass of width w = 2r + 1 has
 * variance (w^2 - 1) / 12, and 3 (w^2 - 1) / 12 = r^2 + r).  In place;
 * tmp has room for every block and one more. */
static void blur_all(const struct grid *g, double *a, uint64_t r,
    double *tmp)
{
	uint64_t total = grid_n(g), stride = 1;

	for (unsigned ax = 0; ax < g->dims; stride *= g->side[ax], ax++) {
		uint64_t n = g->side[ax], block = stride * n;
		if (n < 2)
			continue;
		for (int pass = 0; pass < 3; pass++)
			for (uint64_t o = 0; o < total; o += block) {
				if (stride == 1) {
					box_line(a + o, n, r, tmp);
					continue;
				}
				memcpy(tmp, a + o, block * sizeof *tmp);
				box_rows(a + o, tmp, n, stride, r);
			}
	}
}

/* The box radius whose three passes make a Gaussian of standard
 * deviation blur: w = sqrt(4 blur^2 + 1), r = (w - 1) / 2 rounded. */
static uint64_t blur_radius(double blur)
{
	double w = sqrt(4.0 * blur * blur + 1.0);

	return (uint64_t)floor((w - 1.0) / 2.0 + 0.5);
}

/* log2 x for x > 0 to about 1e-7, from the exponent and a series in
 * the mantissa: exact operations only, so the same on every machine
 * (the levels must not depend on the math library). */
static double log2_det(double x)
{
	uint64_t b;
	int e;
	double m, u, u2;

	memcpy(&b, &x, sizeof b);
	if ((b >> 52) != 0) {	/* normal: the exponent and mantissa bits */
		e = (int)(b >> 52) - 1022;
		b = (b & 0xfffffffffffffULL) | 0x3ff0000000000000ULL;
		memcpy(&m, &b, sizeof m);
	} else {
		m = 2.0 * frexp(x, &e);
	}
	u = (m - 1.0) / (m + 1.0);
	u2 = u * u;
	/* ln m = 2 atanh u, |u| <= 1/3 */
	double s = u * (1.0 + u2 * (1.0 / 3.0 + u2 * (1.0 / 5.0 + u2 * (1.0 /
	    7.0 + u2 * (1.0 / 9.0 + u2 * (1.0 / 11.0 + u2 / 13.0))))));

	return (double)(e - 1) + 2.0 * s / 0.69314718055994530942;
}

/* floor(x) clamped to levels 0 .. top (x may be far out of range). */
static unsigned clamp_level(double x, unsigned top)
{
	x = floor(x);
	return x <= 0.0 ? 0 : x >= top ? top : (unsigned)x;
}

/* The first block of the grid in the row of cells (y, z). */
static uint64_t row_block(const struct grid *g, uint32_t y, uint32_t z)
{
	return ((z >> g->lf) * g->side[1] + (y >> g->lf)) * g->side[0];
}

/* The cells of row (y, z) of the values v at their levels, from the
 * level of each block (lev_b): each cell's level, and each level's
 * count, box, largest value and sum, in the order of the cells. */
static void add_row(struct frs_levels *L, const struct grid *g,
    const uint8_t *lev_b, const double *v, uint32_t y, uint32_t z)
{
	uint64_t b0 = row_block(g, y, z), i0 = ((uint64_t)z * L->side[1] + y) *
	    L->side[0];
	uint32_t seen = 0;	/* the levels of this row, a bit each */

	for (uint32_t x = 0; x < L->side[0]; x++) {
		double c = v[i0 + x];
		unsigned l = lev_b[b0 + (x >> g->lf)];
		if (!(c > 0.0))
			continue;
		L->lev[i0 + x] = (uint8_t)l;
		L->max[l] = c > L->max[l] ? c : L->max[l];
		L->sum[l] += c;
		if (L->cells[l]++ == 0) {
			L->lo[l][0] = L->hi[l][0] = x;
			L->lo[l][1] = L->hi[l][1] = y;
			L->lo[l][2] = L->hi[l][2] = z;
		}
		L->lo[l][0] = x < L->lo[l][0] ? x : L->lo[l][0];
		L->hi[l][0] = x > L->hi[l][0] ? x : L->hi[l][0];
		seen |= 1u << l;
	}
	for (unsigned l = 0; seen != 0; l++, seen >>= 1)
		if (seen & 1) {	/* rows come in order of y within z */
			L->lo[l][1] = y < L->lo[l][1] ? y : L->lo[l][1];
			L->hi[l][1] = y > L->hi[l][1] ? y : L->hi[l][1];
			L->hi[l][2] = z;
		}
}

/* The cells of row (y, z) of v into their blocks: the sum of log2 t
 * (log2 t0 + log2 v), the count of the cells of non-zero importance and
 * their largest value.  log2 v of a run of cells in one block from one
 * logarithm: the sum of their exponents and log2 of the product of their
 * mantissas (in [1, 2), the product kept below 2^513: close enough,
 * where a logarithm a cell cost most of the plan). */
static void sum_row(const struct frs_levels *L, const struct grid *gr,
    const double *v, uint32_t y, uint32_t z, double log2_t0, double *g,
    double *m, double *hi)
{
	uint64_t b0 = row_block(gr, y, z);
	const double *r = v + ((uint64_t)z * L->side[1] + y) * L->side[0];

	for (uint32_t x0 = 0; x0 < L->side[0]; x0 += (uint32_t)gr->f) {
		uint32_t x1 = L->side[0] - x0 < gr->f ? L->side[0] :
		    x0 + (uint32_t)gr->f;
		uint64_t b = b0 + (x0 >> gr->lf);
		double prod = 1.0, sum = 0.0, cnt = 0.0, top = hi[b];
		int64_t e = 0;
		for (uint32_t x = x0; x < x1; x++) {
			double c = r[x], mant;
			uint64_t bits;
			if (!(c > 0.0))
				continue;
			cnt += 1.0;
			top = c > top ? c : top;
			memcpy(&bits, &c, sizeof bits);
			if ((bits >> 52) == 0) {	/* subnormal */
				sum += log2_det(c);
				continue;
			}
			e += (int64_t)(bits >> 52) - 1023;
			bits = (bits & 0xfffffffffffffULL) | 0x3ff0000000000000ULL;
			memcpy(&mant, &bits, sizeof mant);
			prod *= mant;
			if (prod >= 0x1p512) {	/* exact: a power of two */
				prod *= 0x1p-512;
				e += 512;
			}
		}
		if (cnt > 0.0) {
			g[b] += cnt * log2_t0 + (double)e + log2_det(prod) + sum;
			m[b] += cnt;
			hi[b] = top;
		}
	}
}

/* The grid of blocks for smoothing over blur cells: as coarse as keeps
 * about four blocks to the standard deviation (smoothing, not detail, is
 * the point; the cost falls with f^k). */
static void make_grid(struct grid *g, const struct frs_levels *L,
    double blur)
{
	g->dims = L->dims;
	g->f = 1;
	g->lf = 0;
	while (blur > 0.0 && (double)(2 * g->f) <= blur / 4.0) {
		g->f *= 2;
		g->lf++;
	}
	for (unsigned a = 0; a < 3; a++)
		g->side[a] = (L->side[a] + g->f - 1) / g->f;
}

/* The coarsest level up to top whose elements, of 2^(k l) t, hold at
 * most nm / 4 (most[l] = nm / 4 / 2^(k l)): an element passes at most
 * once, so its threshold must stay well below the matrix's size for its
 * count to stay unbiased. */
static unsigned cap_level(double t, const double *most, unsigned top)
{
	unsigned l = top;

	while (l > 0 && t > most[l])
		l--;
	return l;
}

/*
 * Each cell of threshold t = t0 v > 0 takes the coarsest level whose
 * elements, of 2^(k l) t, stay at or below the sparsity bound nm /
 * sigma^k, judged on the smoothed log2 threshold s: l = floor((log2 nm -
 * k log2 sigma - s) / k), capped by top and by the cap of every cell of
 * its block (cap_level).  s is the mean of log2 t over the cells of
 * non-zero importance near the cell (a normalised convolution: empty
 * cells neither pull their neighbours to the coarsest level nor count)
 * on the grid of blocks, so that the levels' borders follow the blocks;
 * a cap of the block's rather than the cell's keeps a bright cell from
 * cutting a hole in its level.
 */
int frs_levels_plan(struct frs_levels *L, unsigned dims,
    const uint32_t *side, const double *v, double t0, unsigned top,
    double nm, double sigma, double blur)
{
	double k = dims, bound = log2(nm) - k * log2(sigma);
	double *g = NULL, *m = NULL, *p = NULL, *hi = NULL;
	double most[FRS_LEVELS_MAX];
	uint8_t *lev_b = NULL;
	struct grid gr;
	uint64_t nb;
	int rc = -1;

	memset(L, 0, sizeof *L);
	L->dims = dims;
	L->top = top < FRS_LEVELS_MAX ? top : FRS_LEVELS_MAX - 1;
	L->blur = blur;
	for (unsigned a = 0; a < 3; a++)
		L->side[a] = a < dims ? side[a] : 1;
	make_grid(&gr, L, blur);
	nb = grid_n(&gr);
	for (unsigned l = 0; l < FRS_LEVELS_MAX; l++)
		most[l] = ldexp(nm / 4.0, -(int)(dims * l));
	if ((L->lev = mem_calloc("levels", ncells(L), 1)) == NULL ||
	    (g = mem_calloc("levels", nb, sizeof *g)) == NULL ||
	    (m = mem_calloc("levels", nb, sizeof *m)) == NULL ||
	    (hi = mem_calloc("levels", nb, sizeof *hi)) == NULL ||
	    (p = mem_calloc("levels", nb + 1, sizeof *p)) == NULL ||
	    (lev_b = mem_calloc("levels", nb, 1)) == NULL)
		goto out;
	for (uint32_t z = 0; z < L->side[2]; z++)
		for (uint32_t y = 0; y < L->side[1]; y++)
			sum_row(L, &gr, v, y, z, log2_det(t0), g, m, hi);
	if (blur > 0.0) {
		uint64_t r = blur_radius(blur / (double)gr.f);
		blur_all(&gr, g, r, p);
		blur_all(&gr, m, r, p);
	}
	/* Each block's level: the cap of its brightest cell (the least of
	 * its cells' caps: cap_level falls as t grows). */
	for (uint64_t b = 0; b < nb; b++)
		if (m[b] > 0.0)
			lev_b[b] = (uint8_t)clamp_level((bound - g[b] / m[b]) / k,
			    cap_level(t0 * hi[b], most, L->top));
	for (uint32_t z = 0; z < L->side[2]; z++)
		for (uint32_t y = 0; y < L->side[1]; y++)
			add_row(L, &gr, lev_b, v, y, z);
	rc = 0;
out:
	if (rc < 0)
		frs_levels_free(L);
	free(g);
	free(m);
	free(hi);
	free(p);
	free(lev_b);
	return rc;
}

unsigned frs_levels_used(const struct frs_levels *L)
{
	unsigned k = 0;

	for (unsigned l = 0; l <= L->top; l++)
		k += L->cells[l] > 0;
	return k;
}
