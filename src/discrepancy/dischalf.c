/*
 * Halfspace discrepancy (thesis Fig. 6.6, Eq. 6.16-6.17): lines through
 * s points on each side of the unit square, (i + 1/2)/s along it, joining
 * every two sides: 6 s^2 halfplanes.
 *
 * The shape of the line e -> f is the part of the square on its left, of
 * area given by the polygon e, f, and the square's corners from f back to
 * e.  Which side is taken does not matter: the boundary rule of geom.h
 * gives every point on the line to exactly one side, so a halfplane and
 * its complement have the same local discrepancy.
 *
 * For one e, the border points f on the later sides, in counter-clockwise
 * order, are also in angular order around e, and a point p lies left of
 * e -> f exactly for the f before p's direction.  A binary search with
 * the orientation predicate gives each point's place; a suffix sum gives
 * the counts of all lines through e: O(n log s + s) per e instead of
 * O(n s).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>

#include "discrepancy/disc.h"
#include "discrepancy/discint.h"
#include "cli/cli.h"
#include "discrepancy/geom.h"

double disc_half_pos(uint32_t i, uint32_t s)
{
	return ((double)i + 0.5) / (double)s;
}

void disc_half_point(int side, uint32_t i, uint32_t s, double *x, double *y)
{
	double t = disc_half_pos(i, s), u = disc_half_pos(s - 1 - i, s);

	switch (side) {
	case 0: *x = t, *y = 0.0; break;
	case 1: *x = 1.0, *y = t; break;
	case 2: *x = u, *y = 1.0; break;
	default: *x = 0.0, *y = u; break;
	}
}

double disc_half_area(int a, double ex, double ey, int b, double fx,
    double fy)
{
	static const double cx[4] = { 1, 1, 0, 0 }, cy[4] = { 0, 1, 1, 0 };
	double px[6], py[6], area = 0.0;
	int m = 0;

	px[m] = ex, py[m++] = ey;
	px[m] = fx, py[m++] = fy;
	for (int k = b;; k = (k + 1) & 3) {
		px[m] = cx[k], py[m++] = cy[k];
		if (k == ((a + 3) & 3))
			break;
	}
	for (int i = 0; i < m; i++) {
		int j = (i + 1) % m;
		area += px[i] * py[j] - px[j] * py[i];
	}
	return 0.5 * area;
}

struct half {
	const double *xy;
	size_t n;
	uint32_t s;
	double *bx, *by;	/* border points, side by side, 4 s */
	double *sum, *best;	/* per e */
};

/* Lines from e (side a, index i) to the sides after a. */
static int half_one(struct half *h, uint64_t e, uint32_t *hist,
    uint32_t *col)
{
	uint32_t s = h->s, a = (uint32_t)(e / s), m = (3 - a) * s;
	const double *fx = h->bx + (size_t)(a + 1) * s;
	const double *fy = h->by + (size_t)(a + 1) * s;
	double ex = h->bx[e], ey = h->by[e], n = (double)h->n;
	struct num_sum sum = { 0.0, 0.0 };
	double best = 0.0;
	uint64_t eq = 0, above = 0;

	for (uint32_t j = 0; j <= m; j++)
		hist[j] = col[j] = 0;
	for (size_t k = 0; k < h->n; k++) {
		double px = h->xy[2 * k], py = h->xy[2 * k + 1];
		uint32_t lo = 0, hi = m;
		if (px == ex && py == ey) {
			eq++;
			continue;
		}
		while (lo < hi) {
			uint32_t mid = lo + (hi - lo) / 2;
			if (geom_orient(ex, ey, fx[mid], fy[mid], px, py) > 0)
				lo = mid + 1;
			else
				hi = mid;
		}
		hist[lo]++;
		if (lo < m && geom_orient(ex, ey, fx[lo], fy[lo], px, py) == 0)
			col[lo]++;
	}
	for (uint32_t j = m; j-- > 0;) {
		uint64_t cnt;
		double v;
		above += hist[j + 1];
		cnt = above;
		if (geom_edge_closed(ex, ey, fx[j], fy[j]))
			cnt += col[j] + eq;
		v = fabs((double)cnt / n - disc_half_area((int)a, ex, ey,
		    (int)(a + 1 + j / s), fx[j], fy[j]));
		best = v > best ? v : best;
		num_add(&sum, v * v);
	}
	h->sum[e] = num_total(&sum);
	h->best[e] = best;
	return 0;
}

static int half_chunk(void *ctx, uint64_t b, uint64_t e)
{
	struct half *h = ctx;
	uint32_t *hist = malloc(2 * (3 * (size_t)h->s + 1) * sizeof *hist);

	if (hist == NULL)
		return cli_fail("no memory for %u border points", h->s);
	for (uint64_t k = b; k < e; k++)
		half_one(h, k, hist, hist + 3 * (size_t)h->s + 1);
	free(hist);
	return 0;
}

int disc_half(const double *xy, size_t n, uint32_t s, int par,
    struct disc_result *r)
{
	struct half h = { .xy = xy, .n = n, .s = s };
	size_t ne = 3 * (size_t)s;
	int rc;

	h.bx = malloc(8 * (size_t)s * sizeof *h.bx);
	h.sum = malloc(2 * ne * sizeof *h.sum);
	if (h.bx == NULL || h.sum == NULL) {
		free(h.bx), free(h.sum);
		return cli_fail("no memory for %u border points", s);
	}
	h.by = h.bx + 4 * (size_t)s;
	h.best = h.sum + ne;
	for (int side = 0; side < 4; side++)
		for (uint32_t i = 0; i < s; i++)
			disc_half_point(side, i, s, &h.bx[(size_t)side * s + i],
			    &h.by[(size_t)side * s + i]);
	rc = disc_run_chunks(ne, 8, half_chunk, &h, par);
	if (rc == 0) {
		double best = 0.0;
		for (size_t k = 0; k < ne; k++)
			best = h.best[k] > best ? h.best[k] : best;
		r->d2 = sqrt(num_sum(h.sum, ne) / (6.0 * s * s));
		r->dinf = best;
	}
	free(h.bx), free(h.sum);
	return rc;
}
