/*
 * Density rho and the radial distribution function, hard cases:
 * duplicate points (d_min 0, rho 0), two points, coordinates 0 and
 * 1 - 2^-53 (plain distance about sqrt 2, toroidal 2^-53 sqrt 2), pairs
 * that are close only across the wrap of the torus, every point on one
 * spot, and Wei-Wang scales at the last pixel.  The oracles: closed forms
 * (3-4-5 triangles, rho = d / sqrt(2 / (sqrt(3) n))), and the brute-force
 * minimum over all pairs with the distance of density.h written out here,
 * which the library must return bit for bit.
 */
#include "testutil.h"
#include "dda/density.h"
#include "hard.h"

#define ONE_ULP 0x1.fffffffffffffp-1	/* 1 - 2^-53 */

/* The squared pair distance of density.h: torus differences folded into
 * [0, 1/2], each product rounded on its own. */
static double d2_of(const double *p, size_t i, size_t j, int torus)
{
	double dx = fabs(p[2 * i] - p[2 * j]), dy = fabs(p[2 * i + 1] -
	    p[2 * j + 1]), xx, yy;

	if (torus) {
		dx = dx > 0.5 ? 1 - dx : dx;
		dy = dy > 0.5 ? 1 - dy : dy;
	}
	xx = dx * dx;
	yy = dy * dy;
	return xx + yy;
}

static double brute(const double *p, size_t n, int torus)
{
	double best = INFINITY;

	for (size_t i = 0; i < n; i++)
		for (size_t j = i + 1; j < n; j++)
			best = fmin(best, d2_of(p, i, j, torus));
	return sqrt(best);
}

/* d_min from the library, one thread and two: the same. */
static double dmin(const double *p, size_t n, int torus)
{
	double a = -1, b = -2;

	frs_set_threads(1);
	assert_int_equal(dens_min_distance(p, n, NULL, torus, 0, &a), 0);
	frs_set_threads(2);
	assert_int_equal(dens_min_distance(p, n, NULL, torus, 1, &b), 0);
	assert_true(a == b);
	return a;
}

static double rho_of(double d, double n)
{
	return d / sqrt(2.0 / (sqrt(3.0) * n));
}

/* ---- duplicates ----------------------------------------------------- */

static void duplicates(void **state)
{
	double two[4] = { 0.3, 0.7, 0.3, 0.7 };
	size_t n = 1000;
	double *p = tu_rnd_points(n, 31);
	(void)state;

	for (int torus = 0; torus < 2; torus++) {
		assert_true(dmin(two, 2, torus) == 0.0);
		assert_true(dens_rho(0.0, 2) == 0.0);
		/* one duplicate among 1000 random points */
		p[2 * 777] = p[2 * 123];
		p[2 * 777 + 1] = p[2 * 123 + 1];
		assert_true(dmin(p, n, torus) == 0.0);
	}
	/* 1000 points on one spot: the cell search meets them all */
	for (size_t i = 0; i < n; i++)
		p[2 * i] = p[2 * i + 1] = 0.25;
	assert_true(dmin(p, n, 0) == 0.0 && dmin(p, n, 1) == 0.0);
	/* two spots: d_min 0 still, not the distance between the spots */
	for (size_t i = 0; i < n; i += 2)
		p[2 * i] = ONE_ULP, p[2 * i + 1] = 0.0;
	assert_true(dmin(p, n, 0) == 0.0 && dmin(p, n, 1) == 0.0);
	free(p);
}

/* ---- two points and the edges of the square -------------------------- */

static void two_points(void **state)
{
	double a[4] = { 0.125, 0.25, 0.5, 0.75 };	/* 0.375, 0.5: 3-4-5 */
	double b[4] = { 0.1, 0.2, 0.9, 0.95 };
	double c[4] = { 0.0, 0.0, ONE_ULP, ONE_ULP };
	double e[4] = { 0.0, 0.5, ONE_ULP, 0.5 };
	(void)state;

	assert_true(dmin(a, 2, 0) == 0.625 && dmin(a, 2, 1) == 0.625);
	assert_near(dens_rho(0.625, 2), 0.625 * pow(3.0, 0.25), 1e-15);
	assert_near(dens_rho(0.625, 2), rho_of(0.625, 2), 1e-15);
	/* plain sqrt(0.8^2 + 0.75^2), toroidal sqrt(0.2^2 + 0.25^2) */
	assert_near(dmin(b, 2, 0), sqrt(0.64 + 0.5625), 1e-15);
	assert_near(dmin(b, 2, 1), sqrt(0.04 + 0.0625), 1e-15);
	/* (0,0) and (1 - 2^-53, 1 - 2^-53): folded differences of exactly
	 * 2^-53, d^2 = 2^-105 */
	assert_near(dmin(c, 2, 0), sqrt(2.0) * ONE_ULP, 1e-15);
	assert_true(dmin(c, 2, 1) == sqrt(0x1p-105));
	assert_true(dmin(e, 2, 1) == 0x1p-53);
	assert_true(dmin(e, 2, 0) == ONE_ULP);
	assert_true(dens_rho(dmin(e, 2, 1), 2) > 0);
}

/*
 * Pairs close only across the wrap: a 24 x 24 grid of spacing 1/24, with
 * pairs added at the edges and the corners, each nearer through the wrap
 * than anything before it.  The library must find the brute-force minimum
 * exactly, plain and toroidal.
 */
static void torus_wrap(void **state)
{
	static const double extra[][2] = {
		{ 0.0, 0.51 }, { ONE_ULP, 0.5105 },	/* left/right, 5e-4 */
		{ 0.27, 0.0 }, { 0.2698, 0.99985 },	/* top/bottom, 2.5e-4 */
		{ 3e-5, 4e-5 }, { 0.99997, 0.99999 },	/* corners, 7.8e-5 */
	};
	size_t g = 24, n = g * g + 6;
	double *p = malloc(2 * n * sizeof *p);
	(void)state;

	for (size_t i = 0; i < g * g; i++) {
		p[2 * i] = ((double)(i % g) + 0.5) / (double)g;
		p[2 * i + 1] = ((double)(i / g) + 0.5) / (double)g;
	}
	for (size_t k = 0; k < 6; k++) {
		p[2 * (g * g + k)] = extra[k][0];
		p[2 * (g * g + k) + 1] = extra[k][1];
	}
	for (size_t m = 2; m <= 6; m += 2) {
		double t = dmin(p, g * g + m, 1), q = dmin(p, g * g + m, 0);
		print_message("%zu wrap pairs: torus %.17g, plain %.17g\n", m / 2,
		    t, q);
		assert_true(t == brute(p, g * g + m, 1));
		assert_true(q == brute(p, g * g + m, 0));
		assert_true(t < 0.002 && q > 0.01);
	}
	free(p);
}

/* ---- scales at the edges --------------------------------------------- */

/*
 * A 3x3 map with only its last pixel positive: a point at (1 - 2^-53,
 * 1 - 2^-53) lies on it and has f = sqrt(I / mean I) = 3; a point at
 * (0, 0) lies on zero importance, an error naming it.
 */
static void scales_at_edges(void **state)
{
	struct frs_imap m;
	double p[4] = { ONE_ULP, ONE_ULP, 0x1.ffffp-1, ONE_ULP }, f[2];
	double q[4] = { ONE_ULP, ONE_ULP, 0.0, 0.0 }, d;
	(void)state;

	hd_map(&m, 3, 3, 0.0);
	m.v[8] = 5.0;
	assert_int_equal(dens_scales(p, 2, &m, f), 0);
	assert_near(f[0], 3.0, 1e-15);
	assert_near(f[1], 3.0, 1e-15);
	/* the transformed distance: |dx| sqrt(f f) */
	assert_int_equal(dens_min_distance(p, 2, f, 0, 0, &d), 0);
	assert_near(d, (ONE_ULP - 0x1.ffffp-1) * 3.0, 1e-20);
	assert_int_equal(dens_scales(q, 2, &m, f), -1);
	assert_err_has("point 1 (0, 0)", "pixel (0, 0)", "importance 0");
	imap_free(&m);
}

/* ---- the radial distribution of duplicates ---------------------------- */

/* Plain P(|x - y| < r) for r <= 1 (density.h), written out here. */
static double pair_cdf(double r)
{
	return acos(-1.0) * r * r - 8.0 / 3 * r * r * r + 0.5 * r * r * r * r;
}

/* Two points on one spot: the only pair in bin 0, normalised by the
 * probability of a uniform pair there; every other bin 0. */
static void rdf_duplicates(void **state)
{
	double p[4] = { 0.4, 0.4, 0.4, 0.4 }, acc[50] = { 0 };
	double w = dens_spacing(2) / 50;	/* r_u = 0.76 for n = 2 */
	(void)state;

	assert_int_equal(dens_rdf_add(p, 2, NULL, 0, 1.0, 50, 0, acc), 0);
	assert_near(acc[0], 1.0 / pair_cdf(w), 1e-9 / pair_cdf(w));
	for (int b = 1; b < 50; b++)
		assert_true(acc[b] == 0.0);
	assert_near(dens_spacing(2), sqrt(1.0 / sqrt(3.0)), 1e-15);
}

TU_MAIN(NULL, tu_teardown,
	cmocka_unit_test(duplicates),
	cmocka_unit_test(two_points),
	cmocka_unit_test(torus_wrap),
	cmocka_unit_test(scales_at_edges),
	cmocka_unit_test(rdf_duplicates))
