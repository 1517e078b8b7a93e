/*
 * Differential domain analysis: the formulas are documented in ddaspec.h.
 *
 * Three passes, each over fixed chunks: (optionally) count the kept pairs
 * to choose the weight precision, splat every kept pair into one of a few
 * integer images (one per running thread; integer sums do not depend on
 * which image a chunk used, nor on the order), and finally sum the images
 * and divide by the normalisation per row.  The edge-correction counts E
 * come from a 2-D difference array, O(n + pixels).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "dda/ddaspec.h"
#include "cli/cli.h"

#define PT_CHUNK 16	/* points per parallel chunk */
#define ROW_CHUNK 16	/* image rows per parallel chunk */
#define WBITS 20	/* bits per 1-D weight, at most */

/* Mean spacing r_u of n points (the same formula as dens_spacing). */
static double mean_spacing(double n)
{
	return sqrt(2.0 / (sqrt(3.0) * n));
}

/* One integer accumulator with its scratch, used by one chunk at a time. */
struct slot {
	int64_t *img;		/* side^2 masses in units of 2^-2s */
	int64_t *wx, *wy;	/* 1-D weights of one pair */
	double *g;		/* Gaussian values before normalisation */
	void *scratch;		/* g, wx, wy */
	atomic_flag busy;
};

struct dda {
	const double *xy, *f;
	size_t n;
	double eps2;		/* eps^2 */
	double inv_ru;		/* 1 / r_u */
	double lim0;		/* (eps r_u)^2 */
	double topx;		/* r_u units to pixels: half / eps */
	double sigma, c2, reach; /* sigma_px, 1/(2 sigma^2), 3 sigma */
	double cstep;		/* exp(-2 c2) */
	double one;		/* 2^s */
	int64_t half, side;
	int s;			/* bits per 1-D weight */
	int maxtap;		/* taps per axis, at most */
	/* cell grid */
	uint32_t G;
	size_t *start;		/* G^2 + 1 */
	size_t *order;		/* n point indices, by cell, then index */
	double *cfmin;		/* smallest scale per cell */
	double fmin;
	/* work */
	int splat;		/* 0: count only */
	atomic_uint_fast64_t pairs;
	struct slot *slots;
	int nslots;
	const int64_t *ecount;	/* E doubled, per pixel */
	double *acc;
	double k;		/* 2^(1-2s) / ((n - 1) (h r_u)^2) */
};

static double scale(const struct dda *d, size_t i)
{
	return d->f != NULL ? d->f[i] : 1.0;
}

/* 1-D weights (3) around u (pixel units from the centre pixel), as
 * integers summing to 2^s; returns the first tap k (w[0] is tap k) and
 * the tap count in *len.  The Gaussian is evaluated from the nearest tap
 * k0 outwards, g(k0 + m) = g(k0 + m - 1) q_m with q_1 = exp(-(2e + 1) c2),
 * q_m+1 = q_m exp(-2 c2), e = k0 - u (three exponentials a tap row).
 * Every step is sign-symmetric: u and -u give mirrored weights, bit for
 * bit (the normalising sum adds the taps in pairs from both ends), which
 * makes the pairs (i, j) and (j, i) exact mirrors whichever is computed. */
static int64_t kernel1(const struct dda *d, double u, double *g, int64_t *w,
    int *len)
{
	int64_t k0 = llround(u), a, b, tot = 0;
	int L, c, lo, hi;
	double sum = 0.0;

	a = (int64_t)ceil(u - d->reach);
	b = (int64_t)floor(u + d->reach);
	if (a > k0)
		a = k0;
	if (b < k0)
		b = k0;
	L = (int)(b - a + 1);
	c = (int)(k0 - a);
	if (d->sigma > 0.0) {
		double e = (double)k0 - u, e2 = 2.0 * e;
		double q = exp(-(e2 + 1.0) * d->c2);
		double p = exp(-(1.0 - e2) * d->c2);
		g[c] = exp(-e * e * d->c2);
		for (int t = c + 1; t < L; t++, q *= d->cstep)
			g[t] = g[t - 1] * q;
		for (int t = c - 1; t >= 0; t--, p *= d->cstep)
			g[t] = g[t + 1] * p;
		for (lo = 0, hi = L - 1; lo < hi; lo++, hi--)
			sum += g[lo] + g[hi];
		if (lo == hi)
			sum += g[lo];
	}
	if (sum > 0.0) {
		double sc = d->one / sum;
		for (int t = 0; t < L; t++) {
			w[t] = (int64_t)(g[t] * sc + 0.5);
			tot += w[t];
		}
	} else {
		for (int t = 0; t < L; t++)
			w[t] = 0;
	}
	w[c] += ((int64_t)1 << d->s) - tot;
	*len = L;
	return a;
}

/* Splat the pair (i, j) at pixel offsets (ux, uy) from the centre pixel;
 * its mirror (j, i) at (-ux, -uy) is added at the end (pixel p of the
 * image gets the mass of p and of side^2 - 1 - p). */
static void splat(const struct dda *d, struct slot *sl, double ux,
    double uy)
{
	int lx, ly;
	int64_t ax = kernel1(d, ux, sl->g, sl->wx, &lx) + d->half;
	int64_t ay = kernel1(d, uy, sl->g, sl->wy, &ly) + d->half;
	int tx0 = ax < 0 ? (int)-ax : 0, ty0 = ay < 0 ? (int)-ay : 0;
	int tx1 = ax + lx > d->side ? (int)(d->side - ax) : lx;
	int ty1 = ay + ly > d->side ? (int)(d->side - ay) : ly;
	int64_t *img = sl->img;

	for (int ty = ty0; ty < ty1; ty++) {
		int64_t wy = sl->wy[ty], p = (ay + ty) * d->side + ax;
		for (int tx = tx0; tx < tx1; tx++)
			img[p + tx] += sl->wx[tx] * wy;
	}
}

/* Visit the kept pairs (i, j), j > i, of point i and their mirrors
 * (j, i); returns the number of ordered pairs, and splats them when
 * d->splat. */
static uint64_t visit(const struct dda *d, size_t i, struct slot *sl)
{
	const double *xy = d->xy;
	double xi = xy[2 * i], yi = xy[2 * i + 1], fi = scale(d, i);
	double lim = d->lim0 / fi * (1.0 + 1e-9), rad, G = d->G;
	int64_t cx0, cx1, cy0, cy1, gmax = (int64_t)d->G - 1;
	uint64_t cnt = 0;

	/* |x_j - x_i|^2 f_j < lim for a kept pair (with a little slack) */
	rad = sqrt(lim / d->fmin);
	cx0 = xi - rad <= 0.0 ? 0 : (int64_t)((xi - rad) * G) - 1;
	cx1 = xi + rad >= 1.0 ? gmax : (int64_t)((xi + rad) * G) + 1;
	cy0 = yi - rad <= 0.0 ? 0 : (int64_t)((yi - rad) * G) - 1;
	cy1 = yi + rad >= 1.0 ? gmax : (int64_t)((yi + rad) * G) + 1;
	cx0 = cx0 < 0 ? 0 : cx0, cy0 = cy0 < 0 ? 0 : cy0;
	cx1 = cx1 > gmax ? gmax : cx1, cy1 = cy1 > gmax ? gmax : cy1;
	for (int64_t cy = cy0; cy <= cy1; cy++) {
		double by = fmax(0.0, fmax((double)cy / G - yi,
		    yi - (double)(cy + 1) / G) - 1e-12);
		for (int64_t cx = cx0; cx <= cx1; cx++) {
			size_t c = (size_t)(cy * (int64_t)d->G + cx);
			double bx = fmax(0.0, fmax((double)cx / G - xi,
			    xi - (double)(cx + 1) / G) - 1e-12);
			if ((bx * bx + by * by) * d->cfmin[c] >= lim)
				continue;
			for (size_t k = d->start[c]; k < d->start[c + 1]; k++) {
				size_t j = d->order[k];
				double s, dx, dy;
				if (j <= i)
					continue;
				s = sqrt(fi * scale(d, j));
				dx = (xy[2 * j] - xi) * s * d->inv_ru;
				dy = (xy[2 * j + 1] - yi) * s * d->inv_ru;
				if (dx * dx + dy * dy >= d->eps2)
					continue;
				cnt += 2;
				if (d->splat)
					splat(d, sl, dx * d->topx,
					    dy * d->topx);
			}
		}
	}
	return cnt;
}

static int pairs_chunk(void *ctx, uint64_t b, uint64_t e)
{
	struct dda *d = ctx;
	struct slot *sl = NULL;
	uint64_t cnt = 0;

	if (d->splat) {
		for (int k = 0; k < d->nslots && sl == NULL; k++)
			if (!atomic_flag_test_and_set(&d->slots[k].busy))
				sl = &d->slots[k];
		if (sl == NULL)
			return cli_fail("dda: no free accumulator");
	}
	for (uint64_t i = b; i < e; i++)
		cnt += visit(d, (size_t)i, sl);
	atomic_fetch_add(&d->pairs, cnt);
	if (sl != NULL)
		atomic_flag_clear(&sl->busy);
	return 0;
}

/* Rows [b, e): sum the integer images, each pixel with its mirror (the
 * pairs j > i at d, j < i at -d), divide by (4). */
static int norm_chunk(void *ctx, uint64_t b, uint64_t e)
{
	struct dda *d = ctx;
	size_t side = (size_t)d->side, last = side * side - 1;

	for (size_t p = (size_t)b * side; p < (size_t)e * side; p++) {
		int64_t m = 0, e2 = d->ecount[p] + d->ecount[last - p];
		for (int k = 0; k < d->nslots; k++)
			m += d->slots[k].img[p] + d->slots[k].img[last - p];
		if (e2 > 0)
			d->acc[p] += (double)m * d->k / (double)e2;
	}
	return 0;
}

/* Count per pixel of the points i with x_i + d r_u / f_i in [0,1)^2 (the
 * first term of (5)): one box of pixels per point into a difference
 * array, then prefix sums.  Returns side^2 counts, or NULL. */
static int64_t *edge_counts(const struct dda *d, double h, double ru)
{
	size_t side = (size_t)d->side, w = side + 1;
	int64_t *diff = calloc(w * w, sizeof *diff), *out;
	double hf = (double)d->half + 1.0;

	out = malloc(side * side * sizeof *out);
	if (diff == NULL || out == NULL) {
		free(diff), free(out);
		cli_fail("dda: no memory for a %zu x %zu image", side, side);
		return NULL;
	}
	for (size_t i = 0; i < d->n; i++) {
		/* pixel offsets k with k h >= -x f / r_u, k h < (1 - x) f / r_u */
		double sc = scale(d, i) / (ru * h);
		int64_t lo[2], hi[2];
		for (int a = 0; a < 2; a++) {
			double x = d->xy[2 * i + (size_t)a];
			double l = ceil(-x * sc), u = ceil((1.0 - x) * sc) - 1;
			l = fmin(fmax(l, -hf), hf);
			u = fmin(fmax(u, -hf), hf);
			lo[a] = (int64_t)l + d->half;
			hi[a] = (int64_t)u + d->half;
			if (lo[a] < 0)
				lo[a] = 0;
			if (hi[a] > d->side - 1)
				hi[a] = d->side - 1;
		}
		if (lo[0] > hi[0] || lo[1] > hi[1])
			continue;
		diff[(size_t)lo[1] * w + (size_t)lo[0]]++;
		diff[(size_t)lo[1] * w + (size_t)hi[0] + 1]--;
		diff[(size_t)(hi[1] + 1) * w + (size_t)lo[0]]--;
		diff[(size_t)(hi[1] + 1) * w + (size_t)hi[0] + 1]++;
	}
	for (size_t r = 0; r < side; r++)
		for (size_t c = 0; c < side; c++) {
			int64_t v = diff[r * w + c];
			if (c > 0)
				v += diff[r * w + c - 1];
			if (r > 0)
				v += diff[(r - 1) * w + c];
			if (r > 0 && c > 0)
				v -= diff[(r - 1) * w + c - 1];
			diff[r * w + c] = v;
			out[r * side + c] = v;
		}
	free(diff);
	return out;
}

static int check_args(const double *xy, size_t n, const double *f,
    double eps, uint32_t half, double sigma_px, const double *acc)
{
	if (xy == NULL || acc == NULL)
		return cli_fail("dda: no points or no image");
	if (n < 2)
		return cli_fail("dda: %zu points; the analysis needs at least 2",
		    n);
	if (!(eps > 0.0) || !isfinite(eps))
		return cli_fail("dda: neighbourhood eps = %g must be positive "
		    "and finite", eps);
	if (half < 1 || half > DDA_MAX_HALF)
		return cli_fail("dda: image half size %u out of range 1..%u",
		    half, DDA_MAX_HALF);
	if (!(sigma_px >= 0.0) || !(sigma_px <= (double)DDA_MAX_HALF))
		return cli_fail("dda: kernel sigma %g pixels out of range "
		    "0..%u", sigma_px, DDA_MAX_HALF);
	for (size_t i = 0; i < n; i++) {
		double x = xy[2 * i], y = xy[2 * i + 1];
		if (!(x >= 0.0 && x < 1.0 && y >= 0.0 && y < 1.0))
			return cli_fail("dda: point %zu (%g, %g) lies outside "
			    "[0,1)^2", i, x, y);
		if (f != NULL && !(f[i] > 0.0 && isfinite(f[i])))
			return cli_fail("dda: scale of point %zu is %g; it must "
			    "be positive and finite", i, f[i]);
	}
	return 0;
}

/* The cell grid: about 4 points a cell, at most 4096 cells a side. */
static int build_grid(struct dda *d)
{
	size_t n = d->n, g2;
	double gd = ceil(sqrt((double)n / 4.0));
	uint32_t G = gd < 1.0 ? 1 : gd > 4096.0 ? 4096 : (uint32_t)gd;
	size_t *cell;

	d->G = G;
	g2 = (size_t)G * G;
	d->start = calloc(g2 + 1, sizeof *d->start);
	d->order = malloc(n * sizeof *d->order);
	d->cfmin = malloc(g2 * sizeof *d->cfmin);
	cell = malloc(n * sizeof *cell);
	if (d->start == NULL || d->order == NULL || d->cfmin == NULL ||
	    cell == NULL) {
		free(cell);
		return cli_fail("dda: no memory for %zu points", n);
	}
	for (size_t c = 0; c < g2; c++)
		d->cfmin[c] = INFINITY;
	d->fmin = INFINITY;
	for (size_t i = 0; i < n; i++) {
		size_t cx = (size_t)(d->xy[2 * i] * G);
		size_t cy = (size_t)(d->xy[2 * i + 1] * G);
		double fi = scale(d, i);
		cx = cx >= G ? G - 1 : cx;
		cy = cy >= G ? G - 1 : cy;
		cell[i] = cy * G + cx;
		d->start[cell[i] + 1]++;
		d->cfmin[cell[i]] = fmin(d->cfmin[cell[i]], fi);
		d->fmin = fmin(d->fmin, fi);
	}
	for (size_t c = 0; c < g2; c++)
		d->start[c + 1] += d->start[c];
	{
		size_t *pos = malloc(g2 * sizeof *pos);
		if (pos == NULL) {
			free(cell);
			return cli_fail("dda: no memory for %zu points", n);
		}
		memcpy(pos, d->start, g2 * sizeof *pos);
		for (size_t i = 0; i < n; i++)
			d->order[pos[cell[i]]++] = i;
		free(pos);
	}
	free(cell);
	return 0;
}

static int bitlen(uint64_t v)
{
	int b = 0;
	for (; v != 0; v >>= 1)
		b++;
	return b;
}

int dda_add(const double *xy, size_t n, const double *f, double eps,
    uint32_t half, double sigma_px, int par, double *acc)
{
	struct dda d;
	size_t side, npix;
	double ru, h, nn = (double)n;
	int64_t *ecount = NULL;
	uint64_t bound;
	int rc = -1;

	if (check_args(xy, n, f, eps, half, sigma_px, acc) < 0)
		return -1;
	memset(&d, 0, sizeof d);
	side = 2 * (size_t)half + 1;
	npix = side * side;
	ru = mean_spacing(nn);
	h = eps / half;
	d.xy = xy, d.f = f, d.n = n;
	d.eps2 = eps * eps;
	d.inv_ru = 1.0 / ru;
	d.lim0 = eps * ru * (eps * ru);
	d.topx = half / eps;
	d.sigma = sigma_px;
	d.c2 = sigma_px > 0.0 ? 1.0 / (2.0 * sigma_px * sigma_px) : 0.0;
	d.reach = 3.0 * sigma_px;
	d.cstep = exp(-2.0 * d.c2);
	d.half = half, d.side = (int64_t)side;
	d.maxtap = 2 * (int)ceil(d.reach) + 3;
	atomic_init(&d.pairs, 0);
	if (build_grid(&d) < 0)
		goto out;

	/* Precision: a pixel holds at most all P kept pairs, each 2^2s, and
	 * must stay below 2^62; P <= n (n - 1), counted when that bound is
	 * too loose. */
	bound = (uint64_t)n * (uint64_t)(n - 1);
	if (n > UINT32_MAX || bitlen(bound) > 62 - 2 * WBITS) {
		d.splat = 0;
		if (cli_parallel_if(par, n, PT_CHUNK, pairs_chunk, &d) < 0)
			goto out;
		bound = atomic_load(&d.pairs);
		atomic_store(&d.pairs, 0);
	}
	d.s = (62 - bitlen(bound)) / 2;
	d.s = d.s > WBITS ? WBITS : d.s;
	d.one = ldexp(1.0, d.s);
	if (d.s < 4) {
		cli_fail("dda: too many pairs (%llu) within eps",
		    (unsigned long long)bound);
		goto out;
	}

	/* Splat into one integer image per running thread. */
	{
		uint64_t nchunks = (n + PT_CHUNK - 1) / PT_CHUNK;
		int nt = par ? cli_threads() : 1;
		d.nslots = (uint64_t)nt < nchunks ? nt : (int)nchunks;
	}
	d.slots = calloc((size_t)d.nslots, sizeof *d.slots);
	if (d.slots == NULL) {
		cli_fail("dda: no memory");
		goto out;
	}
	for (int k = 0; k < d.nslots; k++) {
		struct slot *sl = &d.slots[k];
		atomic_flag_clear(&sl->busy);
		/* scratch of its own cache lines: no false sharing */
		size_t tb = (size_t)d.maxtap * 8;
		sl->img = calloc(npix, sizeof *sl->img);
		sl->scratch = aligned_alloc(64, (3 * tb + 63) / 64 * 64);
		if (sl->img == NULL || sl->scratch == NULL) {
			cli_fail("dda: no memory for a %zu x %zu image", side,
			    side);
			goto out;
		}
		sl->g = sl->scratch;
		sl->wx = (int64_t *)((char *)sl->scratch + tb);
		sl->wy = (int64_t *)((char *)sl->scratch + 2 * tb);
	}
	d.splat = 1;
	if (cli_parallel_if(par, n, PT_CHUNK, pairs_chunk, &d) < 0)
		goto out;

	ecount = edge_counts(&d, h, ru);
	if (ecount == NULL)
		goto out;
	d.ecount = ecount;
	d.acc = acc;
	/* (4) with E = (ecount(p) + ecount(mirror p)) / 2 */
	d.k = ldexp(1.0, 1 - 2 * d.s) / ((nn - 1.0) * (h * ru) * (h * ru));
	rc = cli_parallel_if(par, side, ROW_CHUNK, norm_chunk, &d);
out:
	if (d.slots != NULL)
		for (int k = 0; k < d.nslots; k++) {
			free(d.slots[k].img), free(d.slots[k].scratch);
		}
	free(d.slots);
	free(ecount);
	free(d.start), free(d.order), free(d.cfmin);
	return rc;
}
