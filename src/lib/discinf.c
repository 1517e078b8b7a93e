/*
 * Worst-case discrepancy of star and rect boxes: exact over the critical
 * boxes, and on the grids of the thesis.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "disc.h"
#include "discint.h"
#include "err.h"

int disc_rows_make(struct disc_rows *r, const uint32_t *bin, size_t n,
    uint32_t nbins)
{
	r->start = calloc((size_t)nbins + 1, sizeof *r->start);
	r->idx = malloc((n ? n : 1) * sizeof *r->idx);
	if (r->start == NULL || r->idx == NULL) {
		disc_rows_free(r);
		return frs_fail("no memory for a grid of %u rows", nbins);
	}
	for (size_t i = 0; i < n; i++)
		r->start[bin[i] + 1]++;
	for (uint32_t b = 0; b < nbins; b++)
		r->start[b + 1] += r->start[b];
	for (size_t i = 0; i < n; i++)
		r->idx[r->start[bin[i]]++] = (uint32_t)i;
	for (uint32_t b = nbins; b > 0; b--)
		r->start[b] = r->start[b - 1];
	r->start[0] = 0;
	return 0;
}

void disc_rows_free(struct disc_rows *r)
{
	free(r->start);
	free(r->idx);
	r->start = r->idx = NULL;
}

static int dcmp(const void *a, const void *b)
{
	double p = *(const double *)a, q = *(const double *)b;
	return (p > q) - (p < q);
}

/*
 * Star Dinf over the critical boxes.  Too many points: the sup over
 * half-open boxes [0,a) x [0,b) of count/n - ab is reached by closed boxes
 * whose corner coordinates are point coordinates; too few: by open boxes
 * whose corner coordinates are point coordinates or 1.  Sweep a over the
 * x coordinates, keeping the y coordinates of the points left of the
 * sweep sorted (Y); the j-th smallest gives both kinds of box.  With ties,
 * the maximum over j still picks the right count: the last of equal
 * values for the excess, the first for the deficit.  O(n^2).
 */
static double deficit(const double *y, size_t m, double a, double n)
{
	double best = a - (double)m / n;
	for (size_t j = 0; j < m; j++) {
		double v = a * y[j] - (double)j / n;
		best = v > best ? v : best;
	}
	return best;
}

static double excess(const double *y, size_t m, double a, double n)
{
	double best = 0.0;
	for (size_t j = 0; j < m; j++) {
		double v = (double)(j + 1) / n - a * y[j];
		best = v > best ? v : best;
	}
	return best;
}

int disc_star_dinf_exact(const double *xy, size_t n, double *dinf)
{
	double *x = malloc(2 * n * sizeof *x), *y, best = 0.0, nn = (double)n;
	size_t m = 0;

	if (x == NULL)
		return frs_fail("no memory for %zu points", n);
	y = x + n;
	{
		/* the points sorted by x (dcmp looks at the first double) */
		double (*pt)[2] = malloc(n * sizeof *pt);
		if (pt == NULL) {
			free(x);
			return frs_fail("no memory for %zu points", n);
		}
		memcpy(pt, xy, n * sizeof *pt);
		qsort(pt, n, sizeof *pt, dcmp);
		for (size_t i = 0; i < n; i++)
			x[i] = pt[i][0];
		for (size_t k = 0; k < n;) {
			double a = x[k], v;
			v = deficit(y, m, a, nn);
			best = v > best ? v : best;
			for (; k < n && x[k] == a; k++) {
				double py = pt[k][1];
				size_t lo = 0, hi = m;
				while (lo < hi) {
					size_t mid = (lo + hi) / 2;
					if (y[mid] <= py)
						lo = mid + 1;
					else
						hi = mid;
				}
				memmove(y + lo + 1, y + lo,
				    (m - lo) * sizeof *y);
				y[lo] = py;
				m++;
			}
			v = excess(y, m, a, nn);
			best = v > best ? v : best;
		}
		free(pt);
	}
	{
		double v = deficit(y, m, 1.0, nn);
		best = v > best ? v : best;
	}
	free(x);
	*dinf = best;
	return 0;
}

/* Star Dinf on the grid: chunks of columns sweep the rows, keeping the
 * count of each column's box in A. */
struct sgrid {
	const uint32_t *kx;
	struct disc_rows rows;
	const double *g;	/* g[i] = i/s, i = 0..s */
	uint32_t s;
	double n;
	double *best;		/* per chunk */
	uint64_t chunk;
};

static int sgrid_chunk(void *ctx, uint64_t b, uint64_t e)
{
	struct sgrid *c = ctx;
	size_t w = (size_t)(e - b);
	uint32_t *a = calloc(2 * w + 1, sizeof *a), *diff;
	double best = 0.0;

	if (a == NULL)
		return frs_fail("no memory for the grid");
	diff = a + w;
	for (uint32_t j = 1; j <= c->s; j++) {
		uint32_t r = 0;
		for (uint32_t q = c->rows.start[j - 1];
		    q < c->rows.start[j]; q++) {
			uint64_t col = (uint64_t)c->kx[c->rows.idx[q]] + 1;
			if (col <= b)
				r++;
			else if (col <= e)
				diff[col - b - 1]++;
		}
		for (size_t i = 0; i < w; i++) {
			double v;
			r += diff[i];
			diff[i] = 0;
			a[i] += r;
			v = fabs((double)a[i] / c->n - c->g[b + 1 + i] *
			    c->g[j]);
			best = v > best ? v : best;
		}
	}
	c->best[b / c->chunk] = best;
	free(a);
	return 0;
}

static double max_of(const double *v, size_t k)
{
	double m = 0.0;
	for (size_t i = 0; i < k; i++)
		m = v[i] > m ? v[i] : m;
	return m;
}

int disc_star_dinf_grid(const double *xy, size_t n, uint32_t s, int par,
    double *dinf)
{
	struct sgrid c = { .s = s, .n = (double)n, .chunk = 256 };
	uint32_t *kx = malloc(2 * n * sizeof *kx), *ky;
	double *g = malloc(((size_t)s + 1) * sizeof *g);
	size_t nch = (s + c.chunk - 1) / c.chunk;
	int rc = -1;

	c.best = calloc(nch, sizeof *c.best);
	if (kx == NULL || g == NULL || c.best == NULL) {
		free(kx), free(g), free(c.best);
		return frs_fail("no memory for a %u grid", s);
	}
	ky = kx + n;
	for (size_t i = 0; i < n; i++) {
		kx[i] = disc_star_bin(xy[2 * i], s);
		ky[i] = disc_star_bin(xy[2 * i + 1], s);
	}
	for (uint32_t i = 0; i <= s; i++)
		g[i] = disc_star_line(i, s);
	c.kx = kx, c.g = g;
	if (disc_rows_make(&c.rows, ky, n, s) == 0) {
		rc = disc_run_chunks(s, c.chunk, sgrid_chunk, &c, par);
		disc_rows_free(&c.rows);
	}
	if (rc == 0)
		*dinf = max_of(c.best, nch);
	free(kx), free(g), free(c.best);
	return rc;
}

/*
 * Rect Dinf on the grid.  For the rows between lines c < d, the box
 * [a, b) holds G(b) - G(a) points, G(a) the points of the rows in columns
 * before a, so d = |phi(b) - phi(a)| with phi(a) = G(a)/n - h g_a, and the
 * largest over a < b is max phi - min phi.  phi falls linearly between the
 * columns that hold points, so with few points only the columns next to
 * them are candidates (sorted list); with many, a scan of all columns.
 */
struct rgrid {
	const uint32_t *bx;
	struct disc_rows rows;
	const double *g;
	uint32_t s;
	size_t n;
	double *best;
};

static double rgrid_dense(const uint32_t *cnt, const double *g, uint32_t s,
    double h, double n)
{
	double lo = 0.0, hi = 0.0;
	uint32_t gsum = 0;
	for (uint32_t a = 1; a < s; a++) {
		double p;
		gsum += cnt[a - 1];
		p = (double)gsum / n - h * g[a];
		lo = p < lo ? p : lo;
		hi = p > hi ? p : hi;
	}
	return hi - lo;
}

static double rgrid_sparse(const uint32_t *list, size_t k, const double *g,
    uint32_t s, double h, double n)
{
	double lo = 0.0, hi = 0.0, p;
	size_t q = 0;
	while (q < k) {
		uint32_t x = list[q];
		p = (double)q / n - h * g[x];
		lo = p < lo ? p : lo;
		while (q < k && list[q] == x)
			q++;
		p = (double)q / n - h * g[x + 1];
		hi = p > hi ? p : hi;
		lo = p < lo ? p : lo;
	}
	p = (double)k / n - h * g[s - 1];
	lo = p < lo ? p : lo;
	hi = p > hi ? p : hi;
	return hi - lo;
}

static int rgrid_chunk(void *ctx, uint64_t b, uint64_t e)
{
	struct rgrid *c = ctx;
	uint32_t s = c->s, *cnt = calloc(s, sizeof *cnt);
	uint32_t *list = malloc((c->n + 1) * sizeof *list);
	double n = (double)c->n, best = 0.0;

	if (cnt == NULL || list == NULL) {
		free(cnt), free(list);
		return frs_fail("no memory for the grid");
	}
	for (uint64_t bot = b; bot < e; bot++) {
		size_t k = 0;
		int sparse = 1;
		memset(cnt, 0, s * sizeof *cnt);
		for (uint32_t top = (uint32_t)bot + 1; top < s; top++) {
			double h = c->g[top] - c->g[bot], v;
			for (uint32_t q = c->rows.start[top - 1];
			    q < c->rows.start[top]; q++) {
				uint32_t x = c->bx[c->rows.idx[q]];
				cnt[x]++;
				if (sparse) {
					size_t at = k;
					while (at > 0 && list[at - 1] > x) {
						list[at] = list[at - 1];
						at--;
					}
					list[at] = x;
				}
				k++;
			}
			if (sparse && 4 * k > s)
				sparse = 0;
			v = sparse ? rgrid_sparse(list, k, c->g, s, h, n) :
			    rgrid_dense(cnt, c->g, s, h, n);
			best = v > best ? v : best;
		}
	}
	c->best[b] = best;
	free(cnt), free(list);
	return 0;
}

int disc_rect_dinf_grid(const double *xy, size_t n, uint32_t s, int par,
    double *dinf)
{
	struct rgrid c = { .s = s, .n = n };
	uint32_t *bx = malloc(2 * n * sizeof *bx), *by;
	double *g = malloc((size_t)s * sizeof *g);
	int rc = -1;

	c.best = calloc(s, sizeof *c.best);
	if (bx == NULL || g == NULL || c.best == NULL) {
		free(bx), free(g), free(c.best);
		return frs_fail("no memory for a %u grid", s);
	}
	by = bx + n;
	for (size_t i = 0; i < n; i++) {
		bx[i] = disc_rect_bin(xy[2 * i], s);
		by[i] = disc_rect_bin(xy[2 * i + 1], s);
	}
	for (uint32_t a = 0; a < s; a++)
		g[a] = disc_rect_line(a, s);
	c.bx = bx, c.g = g;
	if (disc_rows_make(&c.rows, by, n, s - 1) == 0) {
		rc = disc_run_chunks(s - 1, 1, rgrid_chunk, &c, par);
		disc_rows_free(&c.rows);
	}
	if (rc == 0)
		*dinf = max_of(c.best, s - 1);
	free(bx), free(g), free(c.best);
	return rc;
}
