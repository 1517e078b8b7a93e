/*
 * Discrepancy, degenerate geometry: one point and many copies of it,
 * collinear sets (vertical, horizontal, diagonal, anti-diagonal: ties in
 * one or both coordinates, ranks reversed), coordinates 0 and 1 - 2^-53,
 * points exactly on the lines of the grid methods, and regular grids up
 * to 512 x 512.  The oracles:
 *   - one point p, by integrating d^2 over the corners:
 *       star D2^2 = 1/9 - (1 - x^2)(1 - y^2)/2 + (1 - x)(1 - y),
 *       rect D2^2 = 1/36 + 2 x(1 - x) y(1 - y)
 *     (a box of two uniform corners holds x with probability 2x(1-x),
 *     E[1_in |u - v|] = x(1 - x), E[|u - v|^2] = 1/6), and
 *       star Dinf = max(1 - xy, x, y), rect Dinf = 1 (a box shrinking on
 *     p holds it with area -> 0);
 *   - copies of one point have the empirical measure of one point;
 *   - the k x k grid of cell centres: star D2^2 = 1/(18k^2) + 7/(288k^4)
 *     (Warnock's sums factor over the axes);
 *   - Warnock's and the rect closed form as O(n^2) sums in long double,
 *     the exact Dinf over all critical boxes by enumeration, the grid
 *     methods by enumeration of every corner or box.
 */
#include "testutil.h"
#include "discref.h"
#include "discrepancy/disc.h"
#include "base/par.h"

#define ONE_ULP 0x1.fffffffffffffp-1	/* 1 - 2^-53 */

/* ---- oracles ------------------------------------------------------- */

static long double maxl2(long double a, long double b)
{
	return a > b ? a : b;
}

/* Warnock's D2 of star by its O(n^2) definition. */
static double warnock(const double *p, size_t n)
{
	long double s1 = 0, s2 = 0;

	for (size_t i = 0; i < n; i++) {
		long double x = p[2 * i], y = p[2 * i + 1];
		s1 += (1 - x * x) * (1 - y * y) / 4;
		for (size_t j = 0; j < n; j++)
			s2 += (1 - maxl2(x, p[2 * j])) * (1 - maxl2(y, p[2 * j + 1]));
	}
	return (double)sqrtl(1.0L / 9 - 2 * s1 / n + s2 / ((long double)n * n));
}

/* The rect closed form (discrepancy(1)) by its O(n^2) definition. */
static double rect_l2(const double *p, size_t n)
{
	long double s1 = 0, s2 = 0;

	for (size_t i = 0; i < n; i++) {
		long double x = p[2 * i], y = p[2 * i + 1];
		s1 += x * (1 - x) * y * (1 - y);
		for (size_t j = 0; j < n; j++) {
			long double u = p[2 * j], v = p[2 * j + 1];
			s2 += 2 * (x < u ? x : u) * (1 - maxl2(x, u)) *
			    2 * (y < v ? y : v) * (1 - maxl2(y, v));
		}
	}
	return (double)sqrtl(1.0L / 36 - 2 * s1 / n + s2 / ((long double)n * n));
}

/* Points with lo <= x <= hi (closed) or lo < x < hi (open) in each
 * axis. */
static size_t count_box(const double *p, size_t n, const double b[4],
    int closed)
{
	size_t c = 0;

	for (size_t i = 0; i < n; i++) {
		double x = p[2 * i], y = p[2 * i + 1];
		c += closed ? x >= b[0] && x <= b[1] && y >= b[2] && y <= b[3] :
		    x > b[0] && x < b[1] && y > b[2] && y < b[3];
	}
	return c;
}

/* The coordinates of axis k, and 0 and 1 when border. */
static size_t coords(const double *p, size_t n, int k, int border,
    double *c)
{
	size_t m = 0;

	for (size_t i = 0; i < n; i++)
		c[m++] = p[2 * i + k];
	if (border)
		c[m++] = 0.0, c[m++] = 1.0;
	return m;
}

/*
 * Star Dinf over the critical boxes: the excess #[0,a]x[0,b]/n - ab with
 * a, b point coordinates, the deficit ab - #[0,a)x[0,b)/n with a, b point
 * coordinates or 1 (a point at 0 is in every box of positive size).
 */
static double star_dinf(const double *p, size_t n)
{
	double *cx = malloc((n + 2) * sizeof *cx), *cy = malloc((n + 2) *
	    sizeof *cy), best = 0;
	size_t mx = coords(p, n, 0, 1, cx), my = coords(p, n, 1, 1, cy);

	for (size_t i = 0; i < mx; i++)
		for (size_t j = 0; j < my; j++) {
			double a = cx[i], b = cy[j], area = a * b;
			size_t le = 0, lt = 0;
			for (size_t k = 0; k < n; k++) {
				le += p[2 * k] <= a && p[2 * k + 1] <= b;
				lt += p[2 * k] < a && p[2 * k + 1] < b;
			}
			if (i < n && j < n)
				best = fmax(best, (double)le / n - area);
			best = fmax(best, area - (double)lt / n);
		}
	free(cx);
	free(cy);
	return best;
}

/* Rect Dinf: closed boxes on point coordinates for the excess, open
 * boxes on point coordinates and the border for the deficit. */
static double rect_dinf(const double *p, size_t n)
{
	double *cx = malloc((n + 2) * sizeof *cx), *cy = malloc((n + 2) *
	    sizeof *cy), best = 0;
	size_t mx = coords(p, n, 0, 1, cx), my = coords(p, n, 1, 1, cy);

	for (size_t a = 0; a < mx; a++)
	for (size_t b = 0; b < mx; b++)
	for (size_t c = 0; c < my; c++)
	for (size_t d = 0; d < my; d++) {
		double box[4] = { cx[a], cx[b], cy[c], cy[d] };
		double area = (box[1] - box[0]) * (box[3] - box[2]);
		if (box[1] < box[0] || box[3] < box[2])
			continue;
		if (a < n && b < n && c < n && d < n)
			best = fmax(best, (double)count_box(p, n, box, 1) / n -
			    area);
		best = fmax(best, area - (double)count_box(p, n, box, 0) / n);
	}
	free(cx);
	free(cy);
	return best;
}

/* The four exact methods of the library against the oracles. */
static void exact_ok(const char *what, const double *p, size_t n)
{
	double v, w;

	v = disc_star_l2_exact(p, n);
	w = warnock(p, n);
	if (!(fabs(v - w) <= 1e-13 * w + 1e-15)) {
		print_error("%s: star D2 %.17g, Warnock %.17g\n", what, v, w);
		fail();
	}
	v = disc_rect_l2_exact(p, n);
	w = rect_l2(p, n);
	if (!(fabs(v - w) <= 1e-13 * w + 1e-15)) {
		print_error("%s: rect D2 %.17g, sum %.17g\n", what, v, w);
		fail();
	}
	assert_int_equal(disc_star_dinf_exact(p, n, &v), 0);
	w = star_dinf(p, n);
	if (!(fabs(v - w) <= 1e-15)) {
		print_error("%s: star Dinf %.17g, critical boxes %.17g\n", what,
		    v, w);
		fail();
	}
	if (n <= 24) {
		assert_int_equal(disc_rect_dinf_exact(p, n, 1, &v), 0);
		w = rect_dinf(p, n);
		if (!(fabs(v - w) <= 1e-15)) {
			print_error("%s: rect Dinf %.17g, critical boxes %.17g\n",
			    what, v, w);
			fail();
		}
	}
}

/* The grid methods against enumeration, for grid sizes s. */
static void grid_ok(const char *what, const double *p, size_t n, uint32_t s)
{
	double d2, di, v;

	ref_star_grid(p, n, s, &d2, &di);
	v = disc_star_l2_grid(p, n, s);
	if (!(fabs(v - d2) <= 1e-12 * d2 + 1e-15)) {
		print_error("%s, s %u: star grid D2 %.17g, enumerated %.17g\n",
		    what, s, v, d2);
		fail();
	}
	assert_int_equal(disc_star_dinf_grid(p, n, s, 1, &v), 0);
	if (!(fabs(v - di) <= 1e-15)) {
		print_error("%s, s %u: star grid Dinf %.17g, enumerated %.17g\n",
		    what, s, v, di);
		fail();
	}
	ref_rect_grid(p, n, s, &d2, &di);
	v = disc_rect_l2_grid(p, n, s);
	if (!(fabs(v - d2) <= 1e-12 * d2 + 1e-15)) {
		print_error("%s, s %u: rect grid D2 %.17g, enumerated %.17g\n",
		    what, s, v, d2);
		fail();
	}
	assert_int_equal(disc_rect_dinf_grid(p, n, s, 1, &v), 0);
	if (!(fabs(v - di) <= 1e-15)) {
		print_error("%s, s %u: rect grid Dinf %.17g, enumerated %.17g\n",
		    what, s, v, di);
		fail();
	}
}

/* ---- one point, and copies of it ------------------------------------ */

static const double corners[][2] = {
	{ 0.3, 0.6 }, { 0.0, 0.0 }, { ONE_ULP, ONE_ULP }, { 0.0, ONE_ULP },
	{ ONE_ULP, 0.0 }, { 0.5, 0.5 }, { 1e-300, 0.7 }, { 0.125, 0x1p-52 },
};

static void closed_forms(const double *p, size_t n, double x, double y)
{
	long double lx = x, ly = y;
	double d2 = (double)sqrtl(1.0L / 9 - (1 - lx * lx) * (1 - ly * ly) / 2 +
	    (1 - lx) * (1 - ly));
	double r2 = (double)sqrtl(1.0L / 36 + 2 * lx * (1 - lx) * ly * (1 - ly));
	double di = fmax(1 - x * y, fmax(x, y)), v;

	print_message("(%.17g, %.17g) x %zu: star D2 %.17g Dinf %.17g, rect "
	    "D2 %.17g\n", x, y, n, d2, di, r2);
	assert_near(disc_star_l2_exact(p, n), d2, 1e-14 * d2);
	assert_near(disc_rect_l2_exact(p, n), r2, 1e-14 * r2);
	assert_int_equal(disc_star_dinf_exact(p, n, &v), 0);
	assert_near(v, di, 1e-16);
	assert_int_equal(disc_rect_dinf_exact(p, n, 1, &v), 0);
	assert_near(v, 1.0, 0);
}

static void single_point(void **state)
{
	(void)state;
	for (size_t k = 0; k < sizeof corners / sizeof *corners; k++)
		closed_forms(corners[k], 1, corners[k][0], corners[k][1]);
}

/* 97 copies: the same measure; the sweeps meet 97-fold ties in both
 * coordinates. */
static void identical_points(void **state)
{
	const size_t n = 97;
	double *p = malloc(2 * n * sizeof *p);
	(void)state;

	frs_set_threads(2);
	for (size_t k = 0; k < sizeof corners / sizeof *corners; k++) {
		for (size_t i = 0; i < n; i++)
			p[2 * i] = corners[k][0], p[2 * i + 1] = corners[k][1];
		closed_forms(p, n, corners[k][0], corners[k][1]);
		grid_ok("copies", p, 12, 9);
	}
	free(p);
}

/* ---- collinear sets ------------------------------------------------- */

/* n points on a line: 0 vertical at x = 3/7, 1 horizontal, 2 diagonal, 3
 * anti-diagonal, 4 vertical at x = 0 with y from 0 to 1 - 2^-53. */
static double *line(int kind, size_t n)
{
	double *p = malloc(2 * n * sizeof *p);

	assert_non_null(p);
	for (size_t i = 0; i < n; i++) {
		double t = ((double)i + 0.5) / (double)n;
		double *q = p + 2 * i;
		switch (kind) {
		case 0: q[0] = 3.0 / 7, q[1] = t; break;
		case 1: q[0] = t, q[1] = 3.0 / 7; break;
		case 2: q[0] = t, q[1] = t; break;
		case 3: q[0] = t, q[1] = 1 - t; break;
		default:
			q[0] = 0.0;
			q[1] = i + 1 == n ? ONE_ULP : (double)i / (double)n;
		}
	}
	return p;
}

static void collinear(void **state)
{
	static const char *names[] = { "vertical", "horizontal", "diagonal",
	    "anti-diagonal", "x = 0" };
	(void)state;

	frs_set_threads(2);
	for (int k = 0; k < 5; k++) {
		double *p = line(k, 300), v;
		exact_ok(names[k], p, 300);
		free(p);
		p = line(k, 20);
		exact_ok(names[k], p, 20);
		/* a line of points holds a box of area -> 0 with all of
		 * them: rect Dinf 1 for the axis-parallel lines */
		if (k == 0 || k == 1 || k == 4) {
			assert_int_equal(disc_rect_dinf_exact(p, 20, 1, &v), 0);
			assert_near(v, 1.0, 0);
		}
		free(p);
	}
}

/* Below 1, not below 0. */
static double unit(double v)
{
	return v < 0 ? 0.0 : v < 1 ? v : ONE_ULP;
}

/*
 * Points exactly on the lines of the grids, x = i/s of the star grid and y
 * = i/(s-1) of the rect grid, and one ulp below and above them (where
 * floor(v s) rounds onto the line), with 0 and 1 - 2^-53; s = 7 and 23
 * (lines that are not binary fractions; (13/23) 23 and (15/22) 22 are
 * not 13 and 15 in double), and the grid one finer.
 */
static void on_grid_lines(void **state)
{
	static const uint32_t ss[] = { 7, 23 };
	(void)state;

	frs_set_threads(2);
	for (int t = 0; t < 2; t++) {
		uint32_t s = ss[t];
		size_t n = 0;
		double p[2 * 3 * 24];
		for (uint32_t i = 0; i <= s; i++) {
			double x = unit((double)i / s), y = unit((double)i / (s - 1));
			p[2 * n] = x, p[2 * n + 1] = y, n++;
			p[2 * n] = unit(nextafter(x, 0)), p[2 * n + 1] =
			    unit(nextafter(y, 2)), n++;
			p[2 * n] = unit(nextafter(x, 2)), p[2 * n + 1] =
			    unit(nextafter(y, 0)), n++;
		}
		grid_ok("on the lines", p, n, s);
		grid_ok("on the lines, other grid", p, n, s + 1);
		exact_ok("on the lines", p, n);
		exact_ok("on the lines, 24", p, 24);
	}
}

/* ---- regular grids ---------------------------------------------------- */

static void regular_grids(void **state)
{
	static const size_t ks[] = { 1, 2, 3, 7, 100, 512 };
	(void)state;

	for (size_t t = 0; t < sizeof ks / sizeof *ks; t++) {
		size_t k = ks[t], n = k * k;
		double *p = malloc(2 * n * sizeof *p), v;
		long double kk = (long double)k * k;
		double want = (double)sqrtl(1 / (18 * kk) + 7 / (288 * kk * kk));
		for (size_t i = 0; i < k; i++)
			for (size_t j = 0; j < k; j++) {
				p[2 * (i * k + j)] = ((double)i + 0.5) / (double)k;
				p[2 * (i * k + j) + 1] = ((double)j + 0.5) / (double)k;
			}
		v = disc_star_l2_exact(p, n);
		print_message("%zu x %zu: star D2 %.17g, closed form %.17g\n", k,
		    k, v, want);
		assert_near(v, want, 1e-11 * want);
		free(p);
	}
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(single_point),
	cmocka_unit_test(identical_points),
	cmocka_unit_test(collinear),
	cmocka_unit_test(on_grid_lines),
	cmocka_unit_test(regular_grids))
