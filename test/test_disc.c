/* Discrepancy against independent oracles: exact integer arithmetic for
 * the predicates, brute-force enumeration of shapes, O(n^2) sums in long
 * double, closed forms for regular grids and single points, and the
 * expectation E[d(A)^2] = area(1 - area)/n of uniform random points. */
#include "testutil.h"
#include "discref.h"
#include "discrepancy/disc.h"
#include "discrepancy/discint.h"
#include "discrepancy/discshape.h"
#include "discrepancy/geom.h"
#include "base/par.h"
#include "base/rng.h"

#define U52 0x1p-52

/* ---- predicates against exact integer arithmetic ---- */

static int sgn128(__int128 v)
{
	return (v > 0) - (v < 0);
}

static void orient_exact(void **state)
{
	(void)state;
	for (uint64_t t = 0; t < 20000; t++) {
		/* a, b, p collinear on 52-bit integer coordinates, then p
		 * moved by one unit: the naive double formula rounds */
		int64_t ax = (int64_t)(frs_rand64(7, 0, 4 * t) >> 13);
		int64_t ay = (int64_t)(frs_rand64(7, 0, 4 * t + 1) >> 13);
		int64_t dx = (int64_t)(frs_rand64(7, 0, 4 * t + 2) >> 44) + 1;
		int64_t dy = (int64_t)(frs_rand64(7, 0, 4 * t + 3) >> 44) - 5000;
		int64_t q1 = 1000 + (int64_t)(t % 977), q2 = (int64_t)(t % 1013);
		int64_t bx = ax + dx * q1, by = ay + dy * q1;
		int64_t px = ax + dx * q2, py = ay + dy * q2;
		int64_t lim = (int64_t)1 << 52;
		__int128 det;
		if (by < 0 || by >= lim || bx >= lim || py < 0)
			continue;
		px += (int64_t)(t % 3) - 1;
		det = (__int128)(bx - ax) * (py - ay) -
		    (__int128)(by - ay) * (px - ax);
		assert_int_equal(geom_orient(ax * U52, ay * U52, bx * U52,
		    by * U52, px * U52, py * U52), sgn128(det));
	}
}

static void circle_exact(void **state)
{
	(void)state;
	for (uint64_t t = 0; t < 20000; t++) {
		/* 3-4-5 triangles: p on the circle, then moved by one unit */
		int64_t k = (int64_t)(frs_rand64(9, 0, 3 * t) >> 35) + 1;
		int64_t ex = ((int64_t)1 << 51) +
		    (int64_t)(frs_rand64(9, 0, 3 * t + 1) >> 14);
		int64_t ey = ((int64_t)1 << 51) +
		    (int64_t)(frs_rand64(9, 0, 3 * t + 2) >> 14);
		int64_t px = ex + 3 * k * (t & 1 ? 1 : -1);
		int64_t py = ey + 4 * k * (t & 2 ? 1 : -1), r = 5 * k;
		__int128 det;
		px += (int64_t)(t % 3) - 1;
		det = (__int128)r * r - (__int128)(px - ex) * (px - ex) -
		    (__int128)(py - ey) * (py - ey);
		assert_int_equal(geom_incircle(ex * U52, ey * U52, r * U52,
		    px * U52, py * U52), sgn128(det));
	}
}

static void boundary_rule(void **state)
{
	/* the unit-square box [0.25, 0.75)^2 as a CCW polygon */
	const double q[8] = { 0.25, 0.25, 0.75, 0.25, 0.75, 0.75, 0.25, 0.75 };
	(void)state;
	assert_true(disc_in_quad(q, 0.25, 0.25));	/* closed corner */
	assert_true(disc_in_quad(q, 0.5, 0.25));	/* bottom closed */
	assert_true(disc_in_quad(q, 0.25, 0.5));	/* left closed */
	assert_false(disc_in_quad(q, 0.75, 0.5));	/* right open */
	assert_false(disc_in_quad(q, 0.5, 0.75));	/* top open */
	assert_false(disc_in_quad(q, 0.75, 0.25));
	assert_false(disc_in_quad(q, 0.25, 0.75));
	/* circle: left half and the bottom point in, right half out */
	assert_true(geom_in_circle(0.5, 0.5, 0.25, 0.25, 0.5));
	assert_true(geom_in_circle(0.5, 0.5, 0.25, 0.5, 0.25));
	assert_false(geom_in_circle(0.5, 0.5, 0.25, 0.5, 0.75));
	assert_false(geom_in_circle(0.5, 0.5, 0.25, 0.75, 0.5));
	/* a line and its reverse split the points on it */
	assert_true(geom_left(0.1, 0.0, 0.9, 1.0, 0.5, 0.5) !=
	    geom_left(0.9, 1.0, 0.1, 0.0, 0.5, 0.5));
}

/* ---- star ---- */

/* Warnock in long double, O(n^2), compensated. */
static double warnock_ref(const double *xy, size_t n)
{
	long double s1 = 0, s2 = 0, c = 0;
	for (size_t i = 0; i < n; i++) {
		long double x = xy[2 * i], y = xy[2 * i + 1];
		s1 += (1 - x * x) * (1 - y * y) / 4;
		for (size_t j = 0; j < n; j++) {
			long double mx = fmaxl(x, xy[2 * j]);
			long double my = fmaxl(y, xy[2 * j + 1]);
			long double v = (1 - mx) * (1 - my), t = s2 + v;
			c += (s2 - t) + v;
			s2 = t;
		}
	}
	s2 += c;
	return (double)sqrtl(1.0L / 9 - 2 * s1 / n + s2 / ((long double)n * n));
}

static void star_warnock(void **state)
{
	static const size_t ns[] = { 1, 2, 3, 17, 100, 256 };
	(void)state;
	for (size_t k = 0; k < sizeof ns / sizeof *ns; k++) {
		double *xy = tu_rnd_points(ns[k], 100 + k);
		double d = disc_star_l2_exact(xy, ns[k]);
		double r = warnock_ref(xy, ns[k]);
		assert_true(fabs(d - r) <= 1e-12 * r);
		free(xy);
	}
}

/* The O(n log n) sweep against Warnock's formula as written
 * (discref.h), to 1e-14 on D2^2 (a difference of terms near 0.1): the
 * sets of ref_pair_set, small odd n, and sizes on both sides of the
 * radix sort's insertion-sort cut (256). */
static void star_l2_oracle(void **state)
{
	static const size_t ns[] = { 1, 2, 3, 5, 7, 33, 255, 256, 257, 700 };
	(void)state;
	for (int kind = 0; kind < 4; kind++)
		for (size_t t = 0; t < sizeof ns / sizeof *ns; t++) {
			size_t n = ns[t];
			double *xy = malloc(2 * n * sizeof *xy), d;
			long double r;
			assert_non_null(xy);
			ref_pair_set(xy, n, 2, kind, 7 + t);
			d = disc_star_l2_exact(xy, n);
			r = ref_warnock_sq(xy, n, 2);
			if (fabsl((long double)d * d - r) > 1e-14L)
				fail_msg("kind %d n %zu: D2^2 %.17g, oracle %.17Lg",
				    kind, n, d * d, r);
			free(xy);
		}
}

/* disc_order: ascending, equal values by index, -0 equal to +0; the
 * radix sort and the small-n path alike. */
static void order_stable(void **state)
{
	static const size_t ns[] = { 1, 5, 255, 256, 3000 };
	(void)state;
	for (size_t t = 0; t < sizeof ns / sizeof *ns; t++) {
		size_t n = ns[t];
		double *v = malloc(n * sizeof *v);
		uint32_t *o = malloc(n * sizeof *o);
		uint64_t seed = t;
		assert_non_null(v), assert_non_null(o);
		for (size_t i = 0; i < n; i++)
			v[i] = i % 7 == 0 ? (i % 2 ? -0.0 : 0.0) :
			    floor(ref_u01(&seed) * 16) / 16;
		assert_int_equal(disc_order(v, n, 1, o), 0);
		for (size_t i = 1; i < n; i++)
			assert_true(v[o[i - 1]] < v[o[i]] ||
			    (v[o[i - 1]] == v[o[i]] && o[i - 1] < o[i]));
		free(v), free(o);
	}
}

/* Regular k x k grid at the cell centres: T^2 = 1/(18k^2) + 7/(288k^4)
 * (Warnock's sums factor into 1-D sums of (i + 1/2)/k). */
static void star_regular(void **state)
{
	(void)state;
	for (size_t k = 1; k <= 64; k *= 4) {
		double *xy = tu_grid_points(k), kk = (double)(k * k);
		double want = sqrt(1 / (18 * kk) + 7 / (288 * kk * kk));
		assert_near(disc_star_l2_exact(xy, k * k), want, 1e-13 * want);
		free(xy);
	}
}

/* Rect for a product set: the pair and point sums factor into 1-D sums. */
static void rect_regular(void **state)
{
	(void)state;
	for (size_t k = 1; k <= 64; k *= 4) {
		double *xy = tu_grid_points(k);
		long double a = 0, p = 0, want;
		for (size_t i = 0; i < k; i++) {
			long double x = ((long double)i + 0.5L) / k;
			a += x * (1 - x);
			for (size_t j = 0; j < k; j++) {
				long double y = ((long double)j + 0.5L) / k;
				p += 2 * fminl(x, y) * (1 - fmaxl(x, y));
			}
		}
		a /= k, p /= (long double)k * k;
		want = sqrtl(1.0L / 36 - 2 * a * a + p * p);
		assert_near(disc_rect_l2_exact(xy, k * k), (double)want,
		    1e-12 * (double)want);
		free(xy);
	}
}

/* Points with coordinates on grid lines, repeated, 0 and 1 - ulp. */
static double *hard_points(size_t n, uint32_t s, uint64_t seed)
{
	double *xy = tu_rnd_points(n, seed);
	for (size_t i = 0; i < n; i += 3)
		xy[2 * i] = (double)(i % s) / s;
	for (size_t i = 1; i < n; i += 5)
		xy[2 * i + 1] = (double)(i % (s - 1)) / (s - 1);
	xy[0] = 0.0, xy[1] = nextafter(1.0, 0.0);
	if (n > 4) {
		xy[2] = nextafter(1.0, 0.0), xy[3] = 0.0;
		xy[4] = xy[6], xy[5] = xy[7];
	}
	return xy;
}

/* A grid class: the reference and the library's D2 and Dinf. */
struct grid_class {
	void (*ref)(const double *, size_t, uint32_t, double *, double *);
	double (*l2)(const double *, size_t, uint32_t);
	int (*dinf)(const double *, size_t, uint32_t, int, double *);
};

static void grids_brute(void **state)
{
	static const size_t ns[] = { 1, 2, 7, 40, 120 };
	static const struct grid_class cls[] = {
		{ ref_star_grid, disc_star_l2_grid, disc_star_dinf_grid },
		{ ref_rect_grid, disc_rect_l2_grid, disc_rect_dinf_grid },
	};
	(void)state;
	frs_set_threads(2);
	for (size_t k = 0; k < sizeof ns / sizeof *ns; k++)
		for (uint32_t s = 3; s <= 24; s += 7) {
			double *xy = hard_points(ns[k], s, 200 + k), d2, di, v;
			for (size_t c = 0; c < sizeof cls / sizeof *cls; c++) {
				cls[c].ref(xy, ns[k], s, &d2, &di);
				assert_near(cls[c].l2(xy, ns[k], s), d2,
				    1e-12 * d2 + 1e-15);
				assert_int_equal(cls[c].dinf(xy, ns[k], s, 1,
				    &v), 0);
				assert_near(v, di, 1e-15);
			}
			free(xy);
		}
}

/* The grid converges to the continuum: the right-endpoint sum of d^2
 * over s^2 cells is within 8/s of the integral (d^2 <= 1 changes by at
 * most 2(2/s + points in the cell's strips / n) over a cell). */
static void grid_converges(void **state)
{
	double *xy = tu_rnd_points(500, 300);
	double e2 = pow(disc_star_l2_exact(xy, 500), 2);
	double r2 = pow(disc_rect_l2_exact(xy, 500), 2);
	double last = 1.0;
	(void)state;
	for (uint32_t s = 10; s <= 10000; s *= 10) {
		double g = pow(disc_star_l2_grid(xy, 500, s), 2);
		assert_true(fabs(g - e2) <= 8.0 / s);
		assert_true(fabs(g - e2) < last);
		last = fabs(g - e2);
		g = pow(disc_rect_l2_grid(xy, 500, s), 2);
		assert_true(fabs(g - r2) <= 16.0 / s);
	}
	free(xy);
}

/* Exact star Dinf against all critical boxes, O(n^3). */
static double star_dinf_brute(const double *xy, size_t n)
{
	double best = 0;
	for (size_t i = 0; i <= n; i++)
		for (size_t j = 0; j <= n; j++) {
			double a = i < n ? xy[2 * i] : 1.0;
			double b = j < n ? xy[2 * j + 1] : 1.0;
			size_t open = 0, closed = 0;
			for (size_t k = 0; k < n; k++) {
				open += xy[2 * k] < a && xy[2 * k + 1] < b;
				closed += xy[2 * k] <= a && xy[2 * k + 1] <= b;
			}
			best = fmax(best, a * b - (double)open / (double)n);
			if (i < n && j < n)
				best = fmax(best, (double)closed / (double)n -
				    a * b);
		}
	return best;
}

/* The plain O(n^2) sweep: y of the swept points kept sorted. */
static int dcmp(const void *a, const void *b)
{
	double p = *(const double *)a, q = *(const double *)b;
	return (p > q) - (p < q);
}

static double star_dinf_sweep(const double *xy, size_t n)
{
	double (*pt)[2] = malloc(n * sizeof *pt), *y = malloc(n * sizeof *y);
	double best = 0;
	size_t m = 0, k = 0;
	memcpy(pt, xy, n * sizeof *pt);
	qsort(pt, n, sizeof *pt, dcmp);
	while (k < n) {
		double a = pt[k][0];
		best = fmax(best, a - (double)m / n);
		for (size_t j = 0; j < m; j++)
			best = fmax(best, a * y[j] - (double)j / n);
		for (; k < n && pt[k][0] == a; k++) {
			size_t at = m++;
			while (at > 0 && y[at - 1] > pt[k][1])
				y[at] = y[at - 1], at--;
			y[at] = pt[k][1];
		}
		for (size_t j = 0; j < m; j++)
			best = fmax(best, (double)(j + 1) / n - a * y[j]);
	}
	for (size_t j = 0; j < m; j++)
		best = fmax(best, y[j] - (double)j / n);
	free(pt), free(y);
	return best;
}

static void star_dinf(void **state)
{
	static const double one[][2] = { { 0, 0 }, { 0.5, 0.5 }, { 0.9, 0.2 },
	    { 0.999, 0.999 }, { 0.1, 0.3 } };
	double v;
	(void)state;
	/* a single point: max(1 - xy, x, y) */
	for (size_t k = 0; k < 5; k++) {
		double x = one[k][0], y = one[k][1];
		assert_int_equal(disc_star_dinf_exact(one[k], 1, &v), 0);
		assert_near(v, fmax(1 - x * y, fmax(x, y)), 1e-15);
	}
	for (size_t n = 2; n <= 60; n += 29) {
		double *xy = hard_points(n, 5, 400 + n);
		assert_int_equal(disc_star_dinf_exact(xy, n, &v), 0);
		assert_near(v, star_dinf_brute(xy, n), 1e-15);
		/* the grid never exceeds the exact value */
		{
			double g;
			assert_int_equal(disc_star_dinf_grid(xy, n, 97, 0,
			    &g), 0);
			assert_true(g <= v + 1e-15);
		}
		free(xy);
	}
	/* many blocks of lines: against the plain sweep */
	for (size_t n = 500; n <= 4000; n *= 8) {
		double *xy = hard_points(n, 37, 450 + n);
		for (size_t i = 0; i < n; i += 7)	/* rounded: ties */
			xy[2 * i + 1] = floor(xy[2 * i + 1] * 64) / 64;
		assert_int_equal(disc_star_dinf_exact(xy, n, &v), 0);
		assert_near(v, star_dinf_sweep(xy, n), 1e-15);
		free(xy);
	}
	{
		double *xy = tu_grid_points(30);
		assert_int_equal(disc_star_dinf_exact(xy, 900, &v), 0);
		assert_near(v, star_dinf_sweep(xy, 900), 1e-15);
		free(xy);
	}
}

/* Exact rect Dinf against every box on the critical coordinates (and
 * the border for the open ones), O(n^5). */
static double rect_dinf_brute(const double *xy, size_t n)
{
	double best = 0, *cx = malloc((n + 2) * sizeof *cx);
	double *cy = malloc((n + 2) * sizeof *cy);
	for (size_t i = 0; i < n; i++)
		cx[i] = xy[2 * i], cy[i] = xy[2 * i + 1];
	cx[n] = cy[n] = 0, cx[n + 1] = cy[n + 1] = 1;
	for (size_t a = 0; a < n + 2; a++)
	for (size_t b = 0; b < n + 2; b++)
	for (size_t c = 0; c < n + 2; c++)
	for (size_t d = 0; d < n + 2; d++) {
		double w = cx[b] - cx[a], h = cy[d] - cy[c];
		size_t open = 0, closed = 0;
		if (w < 0 || h < 0)
			continue;
		for (size_t k = 0; k < n; k++) {
			double x = xy[2 * k], y = xy[2 * k + 1];
			open += x > cx[a] && x < cx[b] && y > cy[c] && y < cy[d];
			closed += x >= cx[a] && x <= cx[b] && y >= cy[c] &&
			    y <= cy[d];
		}
		best = fmax(best, w * h - (double)open / n);
		if (a < n && b < n && c < n && d < n)
			best = fmax(best, (double)closed / n - w * h);
	}
	free(cx), free(cy);
	return best;
}

static void rect_dinf(void **state)
{
	double v, g;
	(void)state;
	for (size_t n = 1; n <= 13; n += 4) {
		double *xy = hard_points(n, 4, 700 + n);
		for (size_t i = 0; i < n; i += 3)	/* ties */
			xy[2 * i + 1] = floor(xy[2 * i + 1] * 4) / 4;
		assert_int_equal(disc_rect_dinf_exact(xy, n, 1, &v), 0);
		assert_near(v, rect_dinf_brute(xy, n), 1e-15);
		free(xy);
	}
	{
		/* one point (x, y): the excess 1 of the box [p, p], the
		 * deficit of the largest box beside it */
		double p[2] = { 0.3, 0.6 };
		assert_int_equal(disc_rect_dinf_exact(p, 1, 0, &v), 0);
		assert_near(v, 1.0, 1e-15);
	}
	{
		double *xy = tu_rnd_points(300, 750);
		assert_int_equal(disc_rect_dinf_exact(xy, 300, 1, &v), 0);
		assert_int_equal(disc_rect_dinf_grid(xy, 300, 200, 0, &g), 0);
		assert_true(g <= v + 1e-15 && g > 0.8 * v);
		free(xy);
	}
}

/* ---- half ---- */

/* Area left of e -> f in the unit square by clipping the square
 * (Sutherland-Hodgman), independent of disc_half_area's corner walk. */
static double clip_area(double ex, double ey, double fx, double fy)
{
	double px[8] = { 0, 1, 1, 0 }, py[8] = { 0, 0, 1, 1 }, qx[8], qy[8];
	double area = 0;
	int m = 4, k = 0;
	for (int i = 0; i < m; i++) {
		int j = (i + 1) % m;
		double si = (fx - ex) * (py[i] - ey) - (fy - ey) * (px[i] - ex);
		double sj = (fx - ex) * (py[j] - ey) - (fy - ey) * (px[j] - ex);
		if (si >= 0)
			qx[k] = px[i], qy[k++] = py[i];
		if ((si > 0 && sj < 0) || (si < 0 && sj > 0)) {
			double t = si / (si - sj);
			qx[k] = px[i] + t * (px[j] - px[i]);
			qy[k++] = py[i] + t * (py[j] - py[i]);
		}
	}
	for (int i = 0; i < k; i++) {
		int j = (i + 1) % k;
		area += qx[i] * qy[j] - qx[j] * qy[i];
	}
	return area / 2;
}

static void half_brute(void **state)
{
	(void)state;
	frs_set_threads(2);
	for (uint32_t s = 2; s <= 9; s += 7)
		for (size_t n = 1; n <= 90; n += 89) {
			double *xy = tu_rnd_points(n, 500 + n), best = 0;
			long double sum = 0;
			struct disc_result r;
			/* points on the border points and on lines */
			for (size_t i = 0; i + 1 < n && i < 8; i++)
				disc_half_point((int)(i % 4), (uint32_t)i % s,
				    s, &xy[2 * i], &xy[2 * i + 1]);
			for (size_t i = 0; i < n; i++)
				if (xy[2 * i] >= 1.0 || xy[2 * i + 1] >= 1.0)
					xy[2 * i] = xy[2 * i + 1] = 0.5;
			for (int a = 0; a < 4; a++)
			for (int b = a + 1; b < 4; b++)
			for (uint32_t i = 0; i < s; i++)
			for (uint32_t j = 0; j < s; j++) {
				double ex, ey, fx, fy, d, ar;
				size_t c = 0;
				disc_half_point(a, i, s, &ex, &ey);
				disc_half_point(b, j, s, &fx, &fy);
				for (size_t k = 0; k < n; k++)
					c += geom_left(ex, ey, fx, fy, xy[2 * k],
					    xy[2 * k + 1]);
				ar = clip_area(ex, ey, fx, fy);
				assert_near(disc_half_area(a, ex, ey, b, fx,
				    fy), ar, 1e-14);
				d = fabs((double)c / (double)n - ar);
				sum += (long double)d * d;
				best = fmax(best, d);
			}
			assert_int_equal(disc_half(xy, n, s, 1, &r), 0);
			assert_near(r.d2, (double)sqrtl(sum / (6.0L * s * s)),
			    1e-12);
			assert_near(r.dinf, best, 1e-13);
			free(xy);
		}
}

/* ---- quad and circle ---- */

static void quad_shapes(void **state)
{
	double draws = 0;
	const int k = 20000;
	(void)state;
	for (int i = 0; i < k; i++) {
		double q[8];
		draws += disc_quad_shape(3, (uint64_t)i, q);
		for (int v = 0; v < 4; v++) {
			int w = (v + 1) & 3, u = (v + 2) & 3;
			assert_true(q[2 * v] >= 0 && q[2 * v] < 1);
			assert_int_equal(geom_orient(q[2 * v], q[2 * v + 1],
			    q[2 * w], q[2 * w + 1], q[2 * u], q[2 * u + 1]), 1);
		}
		assert_true(disc_quad_area(q) > 0);
	}
	/* four uniform points are convex with probability 25/36 and then
	 * in a crossing order with probability 1/3: 108/25 draws */
	assert_near(draws / k, 108.0 / 25, 0.08);
	for (int i = 0; i < 1000; i++) {
		double c[3];
		disc_circle_shape(3, (uint64_t)i, c);
		assert_true(c[2] >= 0);
		assert_true(c[0] - c[2] >= 0 && c[0] + c[2] <= 1);
		assert_true(c[1] - c[2] >= 0 && c[1] + c[2] <= 1);
	}
}

static void shapes_brute(void **state)
{
	(void)state;
	frs_set_threads(2);
	for (int cls = DISC_QUAD; cls <= DISC_CIRCLE; cls += 2) {
		struct disc_opts o = { .cls = (enum disc_class)cls,
		    .shapes = 1500, .seed = 11 };
		struct disc_ctx *c = disc_ctx_new(&o);
		size_t n = 3000;	/* 38 x 38 cells, many wholly inside */
		double *xy = tu_rnd_points(n, 600), best = 0;
		long double sum = 0;
		struct disc_result r;
		/* points on the corners of the first shapes */
		for (uint64_t k = 0; k < 20; k++) {
			double q[8];
			if (cls == DISC_QUAD) {
				disc_quad_shape(11, k, q);
				xy[4 * k] = q[0], xy[4 * k + 1] = q[1];
				xy[4 * k + 2] = q[4], xy[4 * k + 3] = q[5];
			}
		}
		for (uint64_t k = 0; k < o.shapes; k++) {
			double q[8], d, area;
			size_t m = 0;
			if (cls == DISC_QUAD)
				disc_quad_shape(11, k, q);
			else
				disc_circle_shape(11, k, q);
			for (size_t i = 0; i < n; i++)
				m += cls == DISC_QUAD ?
				    disc_in_quad(q, xy[2 * i], xy[2 * i + 1]) :
				    geom_in_circle(q[0], q[1], q[2], xy[2 * i],
				    xy[2 * i + 1]);
			area = cls == DISC_QUAD ? disc_quad_area(q) :
			    PI * q[2] * q[2];
			d = fabs((double)m / (double)n - area);
			sum += (long double)d * d;
			best = fmax(best, d);
		}
		assert_non_null(c);
		assert_int_equal(disc_set(c, xy, n, 1, &r), 0);
		assert_near(r.d2, (double)sqrtl(sum / o.shapes), 1e-12);
		assert_true(r.dinf == best);
		disc_ctx_free(c);
		free(xy);
	}
}

/* ---- expectations: uniform random points ---- */

/* Mean over m random sets of D2^2 against sum of area(1-area)/(n K)
 * over the shapes tested; z-score from the sample variance. */
static void expect_class(struct disc_opts *o, double ea, size_t n, int m)
{
	struct disc_ctx *c = disc_ctx_new(o);
	double s1 = 0, s2 = 0, mean, se;
	assert_non_null(c);
	for (int k = 0; k < m; k++) {
		double *xy = tu_rnd_points(n, 1000 + (uint64_t)k), v;
		struct disc_result r;
		assert_int_equal(disc_set(c, xy, n, 0, &r), 0);
		assert_true(r.d2 <= r.dinf);
		v = r.d2 * r.d2;
		s1 += v, s2 += v * v;
		free(xy);
	}
	mean = s1 / m;
	se = sqrt((s2 / m - mean * mean) / (m - 1));
	if (fabs(mean - ea / (double)n) > 4.5 * se)
		fail_msg("%s: mean D2^2 %.6g, expected %.6g (se %.3g)",
		    disc_class_name(o->cls), mean, ea / (double)n, se);
	disc_ctx_free(c);
}

static double grid_star_ea(uint32_t s)
{
	double t = 0;
	for (uint32_t i = 1; i <= s; i++)
		for (uint32_t j = 1; j <= s; j++) {
			double a = (double)i / s * ((double)j / s);
			t += a * (1 - a);
		}
	return t / ((double)s * s);
}

static void expectations(void **state)
{
	struct disc_opts o = { .seed = 5 };
	(void)state;
	o.cls = DISC_STAR, o.exact_d2 = 1, o.exact_dinf = 1;
	expect_class(&o, 5.0 / 36, 64, 400);
	o.cls = DISC_RECT, o.grid = 40;
	expect_class(&o, 1.0 / 12, 64, 400);
	o.exact_d2 = o.exact_dinf = 0;
	o.cls = DISC_STAR, o.grid = 64;
	expect_class(&o, grid_star_ea(64), 64, 400);
	{
		double t = 0;
		o.cls = DISC_HALF, o.grid = 16;
		for (int a = 0; a < 4; a++)
		for (int b = a + 1; b < 4; b++)
		for (uint32_t i = 0; i < 16; i++)
		for (uint32_t j = 0; j < 16; j++) {
			double ex, ey, fx, fy, ar;
			disc_half_point(a, i, 16, &ex, &ey);
			disc_half_point(b, j, 16, &fx, &fy);
			ar = clip_area(ex, ey, fx, fy);
			t += ar * (1 - ar);
		}
		expect_class(&o, t / (6 * 256), 64, 300);
	}
	for (int cls = DISC_QUAD; cls <= DISC_CIRCLE; cls += 2) {
		double t = 0, q[8], ar;
		o.cls = (enum disc_class)cls, o.shapes = 2000;
		for (uint64_t k = 0; k < o.shapes; k++) {
			if (cls == DISC_QUAD) {
				disc_quad_shape(o.seed, k, q);
				ar = disc_quad_area(q);
			} else {
				disc_circle_shape(o.seed, k, q);
				ar = PI * q[2] * q[2];
			}
			t += ar * (1 - ar);
		}
		expect_class(&o, t / (double)o.shapes, 64, 300);
	}
}

/* ---- invariants and hard cases ---- */

static void run_all(const double *xy, size_t n, int par,
    struct disc_result *r)
{
	struct disc_opts o = { .seed = 2, .shapes = 5000 };
	for (int cls = 0; cls < 5; cls++) {
		struct disc_ctx *c;
		o.cls = (enum disc_class)cls;
		o.grid = cls == DISC_RECT ? 60 : 200;
		c = disc_ctx_new(&o);
		assert_non_null(c);
		assert_int_equal(disc_set(c, xy, n, par, &r[cls]), 0);
		disc_ctx_free(c);
		o.exact_d2 = o.exact_dinf = 1;
		if (cls <= DISC_RECT) {
			c = disc_ctx_new(&o);
			assert_int_equal(disc_set(c, xy, n, par, &r[5 + cls]),
			    0);
			disc_ctx_free(c);
		}
		o.exact_d2 = o.exact_dinf = 0;
	}
}

static void invariants(void **state)
{
	size_t n = 700;
	double *xy = tu_rnd_points(n, 800), *perm = malloc(2 * n * sizeof *perm);
	struct disc_result a[7], b[7], c[7];
	(void)state;
	assert_non_null(perm);
	for (size_t i = 0; i < n; i++) {
		size_t j = (i * 263) % n;	/* 263 is prime to 700 */
		perm[2 * j] = xy[2 * i], perm[2 * j + 1] = xy[2 * i + 1];
	}
	frs_set_threads(1);
	run_all(xy, n, 0, a);
	frs_set_threads(2);
	run_all(xy, n, 1, b);
	run_all(perm, n, 1, c);
	for (int k = 0; k < 7; k++) {
		assert_true(a[k].d2 == b[k].d2 && a[k].dinf == b[k].dinf);
		assert_near(c[k].d2, a[k].d2, 1e-14 * a[k].d2);
		assert_true(c[k].dinf == a[k].dinf || k == 5);
		assert_true(a[k].d2 <= a[k].dinf);
		assert_true(a[k].d2 > 0);
	}
	free(xy), free(perm);
}

static void hard_cases(void **state)
{
	struct disc_result r[7];
	double *xy;
	(void)state;
	frs_set_threads(2);
	/* all points equal, on the corner and near 1 */
	for (int v = 0; v < 3; v++) {
		double at = v == 0 ? 0.0 : v == 1 ? nextafter(1.0, 0.0) : 0.5;
		size_t n = 50;
		xy = malloc(2 * n * sizeof *xy);
		for (size_t i = 0; i < 2 * n; i++)
			xy[i] = at;
		run_all(xy, n, 1, r);
		for (int k = 0; k < 7; k++) {
			assert_true(isfinite(r[k].d2) && r[k].d2 >= 0);
			assert_true(r[k].d2 <= r[k].dinf && r[k].dinf <= 1);
		}
		free(xy);
	}
	/* one point */
	{
		double one[2] = { 0.3, 0.6 };
		run_all(one, 1, 1, r);
		for (int k = 0; k < 7; k++)
			assert_true(r[k].d2 > 0 && r[k].d2 <= r[k].dinf);
		assert_near(r[5].dinf, 0.82, 1e-15);	/* max(1-xy, x, y) */
	}
}

static void huge(void **state)
{
	size_t n = (size_t)1 << 20;
	uint64_t m;
	double *xy = malloc(2 * n * sizeof *xy), e, g, di;
	(void)state;
	/* jittered 1024 x 1024 */
	m = 0;
	for (size_t i = 0; i < 1024; i++)
		for (size_t j = 0; j < 1024; j++, m++) {
			xy[2 * m] = ((double)i + frs_rand01(1, 0, 2 * m)) / 1024;
			xy[2 * m + 1] = ((double)j +
			    frs_rand01(1, 0, 2 * m + 1)) / 1024;
		}
	e = disc_star_l2_exact(xy, n);
	g = disc_star_l2_grid(xy, n, 4096);
	assert_true(isfinite(e) && e > 0 && e < 1e-4);
	assert_true(fabs(g * g - e * e) <= 8.0 / 4096);
	frs_set_threads(2);
	/* a grid that does not follow the strata: the values vary there */
	assert_int_equal(disc_star_dinf_grid(xy, n, 1000, 1, &di), 0);
	assert_true(di >= e && di < 1e-2);
	e = disc_rect_l2_exact(xy, n);
	assert_true(isfinite(e) && e > 0 && e < 1e-4);
	/* the shape classes: few shapes, all 2^20 points counted */
	for (int cls = DISC_QUAD; cls <= DISC_CIRCLE; cls++) {
		struct disc_opts o = { .cls = (enum disc_class)cls, .grid = 3,
		    .shapes = 200, .seed = 1 };
		struct disc_ctx *c = disc_ctx_new(&o);
		struct disc_result r;
		assert_non_null(c);
		assert_int_equal(disc_set(c, xy, n, 1, &r), 0);
		assert_true(isfinite(r.d2) && r.d2 > 0 && r.d2 <= r.dinf);
		assert_true(r.dinf < 1e-3);	/* jittered: O(n^-3/4) */
		disc_ctx_free(c);
	}
	free(xy);
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(orient_exact),
	cmocka_unit_test(circle_exact),
	cmocka_unit_test(boundary_rule),
	cmocka_unit_test(star_warnock),
	cmocka_unit_test(star_l2_oracle),
	cmocka_unit_test(order_stable),
	cmocka_unit_test(star_regular),
	cmocka_unit_test(rect_regular),
	cmocka_unit_test(grids_brute),
	cmocka_unit_test(grid_converges),
	cmocka_unit_test(star_dinf),
	cmocka_unit_test(rect_dinf),
	cmocka_unit_test(half_brute),
	cmocka_unit_test(quad_shapes),
	cmocka_unit_test(shapes_brute),
	cmocka_unit_test(expectations),
	cmocka_unit_test(invariants),
	cmocka_unit_test(hard_cases),
	cmocka_unit_test(huge))
