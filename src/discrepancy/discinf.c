/*
 * Worst-case discrepancy of star and rect boxes: exact over the critical
 * boxes, and on the grids of the thesis.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "discrepancy/disc.h"
#include "discrepancy/discint.h"
#include "cli/cli.h"

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
 * x coordinates.  With the y coordinates sorted (y_j), the box up to y_j
 * has c_j points (y <= y_j, closed) or c'_j (y < y_j, open), and
 *   excess  = max_j c_j/n - a y_j,   deficit = max_j a y_j - c'_j/n:
 * the maximum of lines in a.  Inserting a point adds 1 to c on a suffix
 * of j.  The lines are kept in blocks of about sqrt(n), each with its
 * upper hull and a pending add for the whole block; a grows, so each
 * hull is walked forward.  O(n^1.5) instead of O(n^2).  A y_j of a point
 * not yet swept gives a real box too, so no line needs to be left out.
 */
struct lines {
	const double *y;	/* sorted */
	double sy, sc, n;	/* line j: sc c_j / n + sy y_j a */
	uint32_t *c, *hull, *ptr, *h, *add;
	unsigned char *dirty;
	size_t cnt, bsz, nb;
};

static double line_at(const struct lines *l, size_t j, uint32_t add, double a)
{
	return l->sc * (double)(l->c[j] + add) / l->n + l->sy * l->y[j] * a;
}

static void hull_build(struct lines *l, size_t b)
{
	size_t lo = b * l->bsz, hi = lo + l->bsz < l->cnt ? lo + l->bsz :
	    l->cnt, k = hi - lo;
	uint32_t *h = l->hull + lo, m = 0;

	for (size_t t = 0; t < k; t++) {
		/* by slope sy * y ascending */
		uint32_t j = (uint32_t)(l->sy > 0 ? lo + t : hi - 1 - t);
		double mj = l->sy * l->y[j], bj = l->sc * l->c[j];
		while (m > 0) {
			uint32_t p = h[m - 1];
			double mp = l->sy * l->y[p], bp = l->sc * l->c[p];
			if (mp == mj) {
				if (bp >= bj)
					goto skip;
				m--;
				continue;
			}
			if (m >= 2) {
				uint32_t q = h[m - 2];
				double mq = l->sy * l->y[q], bq = l->sc * l->c[q];
				/* p is never above both q and j */
				if ((bq - bj) * (mp - mq) <= (bq - bp) * (mj - mq)) {
					m--;
					continue;
				}
			}
			break;
		}
		h[m++] = j;
skip:		;
	}
	l->h[b] = m;
	l->ptr[b] = 0;
	l->dirty[b] = 0;
}

/* c_j += 1 for j >= from. */
static void lines_add(struct lines *l, size_t from)
{
	size_t b = from / l->bsz, end = (b + 1) * l->bsz;
	if (from >= l->cnt)	/* the suffix is empty */
		return;
	for (size_t j = from; j < end && j < l->cnt; j++)
		l->c[j]++;
	l->dirty[b] = 1;
	for (b++; b < l->nb; b++)
		l->add[b]++;
}

static double lines_max(struct lines *l, double a)
{
	double best = -1.0;
	for (size_t b = 0; b < l->nb; b++) {
		const uint32_t *h = l->hull + b * l->bsz;
		uint32_t p;
		double v;
		if (l->dirty[b])
			hull_build(l, b);
		p = l->ptr[b];
		v = line_at(l, h[p], l->add[b], a);
		while (p + 1 < l->h[b]) {
			double w = line_at(l, h[p + 1], l->add[b], a);
			if (w < v)
				break;
			v = w, p++;
		}
		l->ptr[b] = p;
		best = v > best ? v : best;
	}
	return best;
}

static int lines_init(struct lines *l, const double *y, size_t n, double sy)
{
	l->y = y, l->cnt = n, l->n = (double)n, l->sy = sy, l->sc = -sy;
	l->bsz = (size_t)sqrt((double)n) + 1;
	l->nb = (n + l->bsz - 1) / l->bsz;
	l->c = calloc(2 * n + 3 * l->nb, sizeof *l->c);
	l->dirty = malloc(l->nb);
	if (l->c == NULL || l->dirty == NULL) {
		free(l->c), free(l->dirty);
		return cli_fail("no memory for %zu points", n);
	}
	l->hull = l->c + n, l->ptr = l->hull + n;
	l->h = l->ptr + l->nb, l->add = l->h + l->nb;
	memset(l->dirty, 1, l->nb);
	return 0;
}

static size_t bound(const double *y, size_t n, double v, int upper)
{
	size_t lo = 0, hi = n;
	while (lo < hi) {
		size_t mid = lo + (hi - lo) / 2;
		if (y[mid] < v || (upper && y[mid] == v))
			lo = mid + 1;
		else
			hi = mid;
	}
	return lo;
}

int disc_star_dinf_exact(const double *xy, size_t n, double *dinf)
{
	double (*pt)[2] = malloc(n * sizeof *pt), *y = malloc(n * sizeof *y);
	double best = 0.0, nn = (double)n;
	struct lines ex, de;
	size_t k = 0;

	if (pt == NULL || y == NULL) {
		free(pt), free(y);
		return cli_fail("no memory for %zu points", n);
	}
	memcpy(pt, xy, n * sizeof *pt);
	qsort(pt, n, sizeof *pt, dcmp);	/* by x: dcmp reads the first */
	for (size_t i = 0; i < n; i++)
		y[i] = pt[i][1];
	qsort(y, n, sizeof *y, dcmp);
	if (lines_init(&ex, y, n, -1.0) < 0) {
		free(pt), free(y);
		return -1;
	}
	if (lines_init(&de, y, n, 1.0) < 0) {
		free(ex.c), free(ex.dirty), free(pt), free(y);
		return -1;
	}
	while (k < n) {
		double a = pt[k][0], v;
		v = fmax(lines_max(&de, a), a - (double)k / nn);
		best = v > best ? v : best;
		for (; k < n && pt[k][0] == a; k++) {
			lines_add(&ex, bound(y, n, pt[k][1], 0));
			lines_add(&de, bound(y, n, pt[k][1], 1));
		}
		v = lines_max(&ex, a);
		best = v > best ? v : best;
	}
	best = fmax(best, lines_max(&de, 1.0));
	free(ex.c), free(ex.dirty), free(de.c), free(de.dirty);
	free(pt), free(y);
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
		return cli_fail("no memory for the grid");
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

/* The grid bins of the points, new: b[i] of x_i, b[n + i] of y_i; NULL
 * when out of memory. */
static uint32_t *bin_points(const double *xy, size_t n, uint32_t s,
    uint32_t (*bin)(double, uint32_t))
{
	uint32_t *b = malloc(2 * n * sizeof *b);

	for (size_t i = 0; b != NULL && i < n; i++) {
		b[i] = bin(xy[2 * i], s);
		b[n + i] = bin(xy[2 * i + 1], s);
	}
	return b;
}

int disc_star_dinf_grid(const double *xy, size_t n, uint32_t s, int par,
    double *dinf)
{
	struct sgrid c = { .s = s, .n = (double)n, .chunk = 256 };
	uint32_t *kx = bin_points(xy, n, s, disc_star_bin), *ky;
	double *g = malloc(((size_t)s + 1) * sizeof *g);
	size_t nch = (s + c.chunk - 1) / c.chunk;
	int rc = -1;

	c.best = calloc(nch, sizeof *c.best);
	if (kx == NULL || g == NULL || c.best == NULL) {
		free(kx), free(g), free(c.best);
		return cli_fail("no memory for a %u grid", s);
	}
	ky = kx + n;
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
		return cli_fail("no memory for the grid");
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
	uint32_t *bx = bin_points(xy, n, s, disc_rect_bin), *by;
	double *g = malloc((size_t)s * sizeof *g);
	int rc = -1;

	c.best = calloc(s, sizeof *c.best);
	if (bx == NULL || g == NULL || c.best == NULL) {
		free(bx), free(g), free(c.best);
		return cli_fail("no memory for a %u grid", s);
	}
	by = bx + n;
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

/*
 * Rect Dinf over all boxes, exactly.  As for star, the excess is reached
 * by closed boxes [a,b] x [c,d] whose sides lie on point coordinates, the
 * deficit by open boxes (a,b) x (c,d) whose sides lie on point coordinates
 * or the border.  For each pair of y sides, the points between them,
 * sorted by x (L), give count - area as a difference of a term of b and
 * a term of a, maximised by one scan that keeps the best a so far.
 * O(n^3) in all (Dobkin, Gunopulos and Maass give O(n^2 log n)).
 */
struct xlist {
	double *x;
	size_t k;
};

static void xl_insert(struct xlist *l, double v)
{
	size_t at = l->k;
	while (at > 0 && l->x[at - 1] > v) {
		l->x[at] = l->x[at - 1];
		at--;
	}
	l->x[at] = v;
	l->k++;
}

/* max over a <= b of #(a <= x <= b)/n - h (b - a) */
static double xl_excess(const struct xlist *l, double h, double n)
{
	double best = 0.0, mina = INFINITY;
	size_t q = 0;
	while (q < l->k) {
		double v = l->x[q], a = (double)q / n - h * v, b;
		while (q < l->k && l->x[q] == v)
			q++;
		mina = a < mina ? a : mina;
		b = (double)q / n - h * v - mina;
		best = b > best ? b : best;
	}
	return best;
}

/* max over a < b, a in {0, x}, b in {x, 1}, of h (b - a) - #(a < x < b)/n */
static double xl_deficit(const struct xlist *l, double h, double n)
{
	double best = 0.0, mina = l->k == 0 || l->x[0] > 0.0 ? 0.0 : INFINITY;
	size_t q = 0;
	while (q < l->k) {
		double v = l->x[q], b = h * v - (double)q / n - mina;
		best = b > best ? b : best;
		while (q < l->k && l->x[q] == v)
			q++;
		b = h * v - (double)q / n;
		mina = b < mina ? b : mina;
	}
	{
		double b = h - (double)l->k / n - mina;
		best = b > best ? b : best;
	}
	return best;
}

static int ycmp(const void *a, const void *b)
{
	const double *p = a, *q = b;
	return (p[1] > q[1]) - (p[1] < q[1]);
}

struct rexact {
	const double (*pt)[2];	/* by y */
	size_t n;
	double *best;		/* per bottom side */
};

/* Boxes with the bottom side on the y of point i - 1 (i = 0: the
 * border), when it is the first point of that y. */
static int rexact_chunk(void *ctx, uint64_t b, uint64_t e)
{
	struct rexact *r = ctx;
	const double (*pt)[2] = r->pt;
	size_t n = r->n;
	double nn = (double)n;
	struct xlist l = { malloc((n ? n : 1) * sizeof *l.x), 0 };

	if (l.x == NULL)
		return cli_fail("no memory for %zu points", n);
	for (uint64_t i = b; i < e; i++) {
		double c = i == 0 ? 0.0 : pt[i - 1][1], best = 0.0, v;
		size_t j = 0;
		r->best[i] = 0.0;
		if (i >= 2 && pt[i - 1][1] == pt[i - 2][1])
			continue;
		/* excess: closed boxes from y = c up */
		l.k = 0;
		for (j = i == 0 ? n : i - 1; j < n;) {
			double d = pt[j][1];
			for (; j < n && pt[j][1] == d; j++)
				xl_insert(&l, pt[j][0]);
			v = xl_excess(&l, d - c, nn);
			best = v > best ? v : best;
		}
		/* deficit: open boxes above c, the top at the next ys and 1 */
		for (j = 0; j < n && pt[j][1] <= c; j++)
			;
		l.k = 0;
		while (j < n) {
			double d = pt[j][1];
			v = xl_deficit(&l, d - c, nn);
			best = v > best ? v : best;
			for (; j < n && pt[j][1] == d; j++)
				xl_insert(&l, pt[j][0]);
		}
		v = xl_deficit(&l, 1.0 - c, nn);
		r->best[i] = v > best ? v : best;
	}
	free(l.x);
	return 0;
}

int disc_rect_dinf_exact(const double *xy, size_t n, int par, double *dinf)
{
	double (*pt)[2] = malloc(n * sizeof *pt);
	struct rexact r = { NULL, n, calloc(n + 1, sizeof(double)) };
	int rc;

	if (pt == NULL || r.best == NULL) {
		free(pt), free(r.best);
		return cli_fail("no memory for %zu points", n);
	}
	memcpy(pt, xy, n * sizeof *pt);
	qsort(pt, n, sizeof *pt, ycmp);
	r.pt = (const double (*)[2])pt;
	rc = disc_run_chunks(n + 1, 4, rexact_chunk, &r, par);
	if (rc == 0)
		*dinf = max_of(r.best, n + 1);
	free(pt), free(r.best);
	return rc;
}
