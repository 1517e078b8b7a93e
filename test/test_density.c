/* Density rho and the radial distribution function against independent
 * oracles: brute-force O(n^2) minima (bit for bit), an x-sorted sweep for
 * 2^20 points, closed forms of regular and hexagonal lattices, numerical
 * quadrature of the pair-distance distribution of uniform points, and the
 * expectation 1 of the RDF of uniform random sets. */
#include "testutil.h"
#include <time.h>

#include "dda/density.h"
#include "maps/imap.h"
#include "base/par.h"
#include "cli/refsamp.h"
#include "base/rng.h"


static double now(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The pair key as density.h defines it, written out independently;
 * larger != 0: the DENS_MAX rule, the larger scale squared. */
static double key_rule(const double *xy, const double *f, size_t i,
    size_t j, int torus, int larger)
{
	double dx = xy[2 * i] - xy[2 * j], dy = xy[2 * i + 1] - xy[2 * j + 1];
	double xx, yy, d2, ff;
	if (torus) {
		dx = fabs(dx);
		dy = fabs(dy);
		if (dx > 0.5)
			dx = 1 - dx;
		if (dy > 0.5)
			dy = 1 - dy;
	}
	xx = dx * dx;
	yy = dy * dy;
	d2 = xx + yy;
	if (f == NULL)
		ff = 1.0;
	else if (larger) {
		double m = f[i] < f[j] ? f[j] : f[i];
		ff = m * m;
	} else
		ff = f[i] * f[j];
	return d2 * ff;
}

static double key(const double *xy, const double *f, size_t i, size_t j,
    int torus)
{
	return key_rule(xy, f, i, j, torus, 0);
}

static double brute_min_rule(const double *xy, size_t n, const double *f,
    int torus, int larger)
{
	double best = INFINITY;
	for (size_t i = 0; i < n; i++)
		for (size_t j = i + 1; j < n; j++) {
			double k = key_rule(xy, f, i, j, torus, larger);
			if (k < best)
				best = k;
		}
	return sqrt(best);
}

static double brute_min(const double *xy, size_t n, const double *f,
    int torus)
{
	return brute_min_rule(xy, n, f, torus, 0);
}

static double dmin_of(const double *xy, size_t n, const double *f, int torus,
    int par)
{
	double d = -1;
	assert_int_equal(dens_min_distance(xy, n, f, torus, par, &d), 0);
	return d;
}

/* ---- lattices --------------------------------------------------------- */

static void lattices(void **state)
{
	(void)state;
	assert_near(dens_spacing(1024), sqrt(2 / (sqrt(3.0) * 1024)), 1e-17);
	for (size_t m = 2; m <= 64; m *= 2) {
		double *xy = tu_grid_points(m);
		for (int torus = 0; torus < 2; torus++) {
			double d = dmin_of(xy, m * m, NULL, torus, 1);
			assert_near(d, 1.0 / (double)m, 1e-15);
		}
		/* the density of a square grid (thesis Sec. 6.2) */
		assert_near(dens_rho(1.0 / (double)m, m * m),
		    sqrt(sqrt(3.0) / 2), 1e-12);
		free(xy);
	}
	assert_near(sqrt(sqrt(3.0) / 2), 0.9306, 5e-5);
	/* a patch of the hexagonal lattice, spacing a: rho ~ 1 */
	{
		size_t k = 32, rows = 0, n = 0;
		double a = 1.0 / (double)k, h = a * sqrt(3.0) / 2;
		double *xy = malloc(2 * 4096 * sizeof *xy), d;
		assert_non_null(xy);
		for (; ((double)rows + 0.5) * h < 1; rows++)
			for (size_t i = 0; i < k; i++) {
				xy[2 * n] = ((double)i + (rows % 2 ? 0.75 : 0.25)) * a;
				xy[2 * n + 1] = ((double)rows + 0.5) * h;
				n++;
			}
		d = dmin_of(xy, n, NULL, 0, 1);
		assert_near(d, a, 1e-15);
		assert_true(d == brute_min(xy, n, NULL, 0));
		print_message("hexagonal patch of %zu points: rho %.4f\n", n,
		    dens_rho(d, n));
		assert_near(dens_rho(d, n), 1.0, 0.02);
		free(xy);
	}
}

/* ---- exactness against brute force ------------------------------------ */

/* One random set against brute force.  mode 0: uniform, 1: clustered
 * (crowded cells), 2: a duplicate point, 3: points on the borders 0 and
 * 1 - 2^-53.  fm 0: no scales, 1: uniform in [1/4, 4), 2: log-uniform
 * over e^-3..e^3, 3: a few sparse points of tiny scale, whose closest
 * pair lies many cells apart. */
static void brute_one(size_t n, uint64_t seed, int mode, int fm, int torus)
{
	double *xy = tu_rnd_points(n, seed), *f = NULL, d, r;

	if (mode == 1)
		for (size_t i = 0; i < 2 * n; i++)
			xy[i] = 0.3 + 0.01 * xy[i];
	if (mode == 2 && n >= 4) {
		xy[2 * (n - 1)] = xy[0];
		xy[2 * (n - 1) + 1] = xy[1];
	}
	if (mode == 3 && n >= 4) {
		xy[0] = 0;
		xy[2] = 1 - 0x1p-53;
		xy[1] = xy[3] = 0.25;
		xy[4] = 0.5;
		xy[5] = 0;
		xy[7] = 1 - 0x1p-53;
	}
	if (fm > 0) {
		f = malloc(n * sizeof *f);
		assert_non_null(f);
		for (size_t i = 0; i < n; i++) {
			double u = frs_rand01(seed, FRS_STREAM_TEST, 1000000 + i);
			f[i] = fm == 1 ? 0.25 + 3.75 * u : fm == 2 ?
			    exp(6 * (u - 0.5)) : i % 50 == 7 ? 1e-3 * (1 + u) :
			    1.0;
		}
	}
	d = dmin_of(xy, n, f, torus, 1);
	r = brute_min(xy, n, f, torus);
	if (d != r)
		print_error("n %zu mode %d f %d torus %d: %.17g != %.17g\n", n,
		    mode, fm, torus, d, r);
	assert_true(d == r);
	assert_true(dmin_of(xy, n, f, torus, 0) == r);
	if (mode == 2 && n >= 4)
		assert_true(d == 0);
	/* the larger-scale rule (dda --density-rule max): its own brute
	 * force, and never below the geometric mean's */
	if (f != NULL) {
		double dm = -1, rm = brute_min_rule(xy, n, f, torus, 1);
		assert_int_equal(dens_min_distance_rule(xy, n, f, DENS_MAX,
		    torus, 1, &dm), 0);
		if (dm != rm)
			print_error("max rule: n %zu mode %d f %d torus %d: "
			    "%.17g != %.17g\n", n, mode, fm, torus, dm, rm);
		assert_true(dm == rm);
		assert_true(dm >= d);
	}
	if (mode == 3 && n >= 4 && torus && f == NULL)
		assert_true(d == 0x1p-53);
	free(f);
	free(xy);
}

static void brute_force(void **state)
{
	static const size_t ns[] = { 2, 3, 4, 5, 7, 10, 33, 100, 257, 1000,
	    3000 };
	uint64_t seed = 1;
	(void)state;
	for (size_t t = 0; t < sizeof ns / sizeof *ns; t++)
		for (int mode = 0; mode < 4; mode++)
			for (int fm = 0; fm < 4; fm++)
				for (int torus = 0; torus < 2; torus++)
					brute_one(ns[t], ++seed, mode, fm, torus);
}

/* The closest pair many cells apart: a few points of tiny scale among
 * ordinary ones, so the searches must walk out ring by ring and stop by
 * the bound exactly. */
static void far_pairs(void **state)
{
	(void)state;
	for (uint64_t t = 0; t < 400; t++) {
		size_t n = t % 2 ? 60 : 300, k = 2 + t % 3;
		double *xy = tu_rnd_points(n, 5000 + t), *f = malloc(n * sizeof *f);
		int torus = (int)(t / 2 % 2);
		assert_non_null(f);
		for (size_t i = 0; i < n; i++)
			f[i] = 1;
		for (size_t i = 0; i < k; i++)
			f[i * 7] = 1e-4 * (1 + 3 * frs_rand01(t, FRS_STREAM_TEST,
			    i + 1000000));
		assert_true(dmin_of(xy, n, f, torus, 1) ==
		    brute_min(xy, n, f, torus));
		free(f);
		free(xy);
	}
}

/* ---- Poisson disk sets ------------------------------------------------- */

static void dart(void **state)
{
	const uint64_t n = 1024;
	double mean = 0, r = refsamp_dart_radius(n);
	(void)state;
	for (uint64_t set = 0; set < 10; set++) {
		double *xy = malloc(2 * n * sizeof *xy), dp, dt, rho;
		uint64_t m;
		assert_non_null(xy);
		assert_int_equal(refsamp_gen(REFSAMP_DART, n, 50 + set,
		    REFSAMP_DART_FAILURES, xy, &m), 0);
		assert_int_equal(m, n);
		dt = dmin_of(xy, m, NULL, 1, 1);
		dp = dmin_of(xy, m, NULL, 0, 1);
		assert_true(dt == brute_min(xy, m, NULL, 1));
		assert_true(dp == brute_min(xy, m, NULL, 0));
		/* dart throwing keeps the toroidal distance >= r = 0.7 r_u */
		assert_true(dt >= r);
		assert_true(dp >= dt);
		rho = dens_rho(dt, m);
		assert_true(rho == dt / sqrt(2 / (sqrt(3.0) * (double)m)));
		assert_true(rho >= 0.7 * (1 - 1e-15));
		mean += rho / 10;
		free(xy);
	}
	print_message("dart throwing: mean rho %.4f (thesis Table 6.1: "
	    "0.70)\n", mean);
	assert_true(mean >= 0.7 && mean < 0.75);
}

/* ---- independence of threads and point order --------------------------- */

static void shuffle(double *xy, double *f, size_t n, uint64_t seed)
{
	struct frs_rng r;
	frs_rng_init(&r, seed, FRS_STREAM_TEST);
	for (size_t i = n - 1; i > 0; i--) {
		size_t j = (size_t)frs_rng_below(&r, i + 1);
		double t;
		for (int c = 0; c < 2; c++) {
			t = xy[2 * i + c];
			xy[2 * i + c] = xy[2 * j + c];
			xy[2 * j + c] = t;
		}
		if (f != NULL) {
			t = f[i];
			f[i] = f[j];
			f[j] = t;
		}
	}
}

static void invariance(void **state)
{
	const size_t n = 20000, nb = 32;
	double *xy = tu_rnd_points(n, 77), *f = malloc(n * sizeof *f);
	(void)state;
	assert_non_null(f);
	for (size_t i = 0; i < n; i++)
		f[i] = 0.5 + frs_rand01(78, FRS_STREAM_TEST, i);
	for (int torus = 0; torus < 2; torus++)
		for (int sc = 0; sc < 2; sc++) {
			const double *ff = sc ? f : NULL;
			double d[4], a[4][32];
			memset(a, 0, sizeof a);
			for (int v = 0; v < 4; v++) {
				frs_set_threads(v == 1 ? 2 : v == 2 ? 5 : 1);
				if (v == 3)
					shuffle(xy, f, n, 5);
				d[v] = dmin_of(xy, n, ff, torus, v != 0);
				assert_int_equal(dens_rdf_add(xy, n, ff, torus,
				    2.5, nb, v != 0, a[v]), 0);
			}
			frs_set_threads(1);
			for (int v = 1; v < 4; v++) {
				assert_true(d[v] == d[0]);
				assert_memory_equal(a[v], a[0], sizeof a[0]);
			}
		}
	free(f);
	free(xy);
}

/* ---- Wei-Wang scales ---------------------------------------------------- */

/* dens_scales of the 4 points xy on a w x h map m of two pixels,
 * importance 1 and 4 (mean 2.5): point i's scale from pixel pix[i]. */
static void two_pixels_ok(const double *xy, struct frs_imap *m, uint32_t w,
    uint32_t h, const int *pix)
{
	double f[4];
	assert_int_equal(imap_alloc(m, w, h), 0);
	m->v[0] = 1;
	m->v[1] = 4;
	assert_int_equal(dens_scales(xy, 4, m, f), 0);
	for (int i = 0; i < 4; i++)
		assert_near(f[i], sqrt(m->v[pix[i]] / 2.5), 1e-15);
}

static void scales(void **state)
{
	struct frs_imap m;
	double xy[8] = { 0.1, 0.2, 0.6, 0.9, 0.5, 0.0, 0.49, 0.99 }, f[4];
	(void)state;
	assert_int_equal(dens_scales(xy, 4, NULL, f), 0);
	for (int i = 0; i < 4; i++)
		assert_true(f[i] == 1);
	assert_int_equal(imap_alloc(&m, 3, 2), 0);
	for (int k = 0; k < 6; k++)
		m.v[k] = 0.7;
	assert_int_equal(dens_scales(xy, 4, &m, f), 0);
	for (int i = 0; i < 4; i++)
		assert_near(f[i], 1.0, 1e-15);
	imap_free(&m);
	/* two pixels side by side: point 2 (x = 0.5) in the right one */
	two_pixels_ok(xy, &m, 2, 1, (const int[]){ 0, 1, 1, 0 });
	imap_free(&m);
	/* one column, two rows: row 0 (y < 1/2) is at the top */
	two_pixels_ok(xy, &m, 1, 2, (const int[]){ 0, 1, 0, 1 });
	/* a point on a zero pixel */
	m.v[1] = 0;
	assert_int_equal(dens_scales(xy, 4, &m, f), -1);
	assert_err_has("point 1 ", "pixel (0, 1)");
	imap_free(&m);
	/* scales shrink the transformed distance: constant f = c gives c d */
	{
		double *p = tu_rnd_points(500, 3), *c = malloc(500 * sizeof *c);
		assert_non_null(c);
		for (int i = 0; i < 500; i++)
			c[i] = 4;
		assert_true(dmin_of(p, 500, c, 0, 1) ==
		    4 * dmin_of(p, 500, NULL, 0, 1));
		free(c);
		free(p);
	}
}

/* ---- the pair-distance distribution of uniform points ------------------ */

/* g(r, x), or with arc g(r, r sin(x)) r cos(x): the integrand over
 * u = r sin(t), smooth where the chord's length goes to 0. */
static double at(double (*g)(double, double), double r, double x, int arc)
{
	return arc ? g(r, r * sin(x)) * r * cos(x) : g(r, x);
}

/* Simpson's rule on [a, b] with k (even) intervals. */
static double simpson(double (*g)(double, double), double r, double a,
    double b, int k, int arc)
{
	double h = (b - a) / k, s = at(g, r, a, arc) + at(g, r, b, arc);
	for (int i = 1; i < k; i++)
		s += (i % 2 ? 4 : 2) * at(g, r, a + i * h, arc);
	return s * h / 3;
}

/* The integral of inner over u in [0, min(c, r)]: in u up to where the
 * disc of radius r leaves the square of side c, in t beyond. */
static double quad(double (*inner)(double, double), double r, double c)
{
	double s = sqrt(fmax(0, r * r - c * c)), e = fmin(c, r);
	return simpson(inner, r, 0, s, 2000, 0) +
	    simpson(inner, r, asin(s / r), asin(e / r), 2000, 1);
}

/* Plain: the differences (u, v) have density 4 (1-u)(1-v); v integrated
 * in closed form up to w = min(1, sqrt(r^2 - u^2)): w - w^2/2. */
static double plain_inner(double r, double u)
{
	double w = fmin(1, sqrt(fmax(0, r * r - u * u)));
	return 4 * (1 - u) * (w - w * w / 2);
}

/* Torus: area of the disc inside [-1/2, 1/2]^2, 4 int min(1/2, ...) du. */
static double torus_inner(double r, double u)
{
	return 4 * fmin(0.5, sqrt(fmax(0, r * r - u * u)));
}

static void pair_cdf(void **state)
{
	(void)state;
	for (int k = 1; k <= 200; k++) {
		double r = sqrt(2.0) * k / 200, rt = r / 2;
		assert_near(dens_pair_cdf(r, 0), quad(plain_inner, r, 1),
		    1e-12);
		assert_near(dens_pair_cdf(rt, 1), quad(torus_inner, rt, 0.5),
		    1e-12);
		if (r < 1 - 1e-4) {	/* the density of the brief */
			double h = 1e-5, d = (dens_pair_cdf(r + h, 0) -
			    dens_pair_cdf(r - h, 0)) / (2 * h);
			assert_near(d, 2 * PI * r - 8 * r * r + 2 * r * r * r,
			    1e-8);
		}
	}
	assert_true(dens_pair_cdf(0, 0) == 0 && dens_pair_cdf(-1, 1) == 0);
	assert_near(dens_pair_cdf(sqrt(2.0) * (1 - 1e-16), 0), 1, 1e-14);
	assert_near(dens_pair_cdf(sqrt(0.5) * (1 - 1e-16), 1), 1, 1e-14);
	assert_true(dens_pair_cdf(2, 0) == 1 && dens_pair_cdf(1, 1) == 1);
	/* continuous at the breaks */
	assert_near(dens_pair_cdf(1 + 1e-12, 0), PI - 13.0 / 6, 1e-10);
	assert_near(dens_pair_cdf(0.5 + 1e-12, 1), PI / 4, 1e-10);
	assert_near(dens_rdf_limit(0), sqrt(2.0), 0);
	assert_near(dens_rdf_limit(1), sqrt(0.5), 0);
}

/* ---- radial distribution function --------------------------------------- */

/* The bin's expected pair count of a uniform set, computed here. */
static double expect(size_t n, double rmax, size_t k, size_t nb, int torus)
{
	double a = rmax * (double)k / (double)nb;
	double b = rmax * (double)(k + 1) / (double)nb;
	return (double)n * (double)(n - 1) / 2 *
	    (dens_pair_cdf(b, torus) - dens_pair_cdf(a, torus));
}

/* Pair counts of one set against an O(n^2) histogram: counts are
 * integers, recovered from acc times the expected count. */
static void rdf_brute_one(size_t n, int sc, int torus)
{
	const size_t nb = 25;
	double *xy = tu_rnd_points(n, 300 + n), *f = NULL, acc[25] = { 0 };
	double rmax_ru = n < 100 ? 0.5 : 4, rmax, w;
	uint64_t cnt[25] = { 0 };

	if (sc) {
		f = malloc(n * sizeof *f);
		assert_non_null(f);
		for (size_t i = 0; i < n; i++)
			f[i] = exp(2 * (frs_rand01(9, FRS_STREAM_TEST, i) - 0.5));
	}
	rmax = rmax_ru * sqrt(2 / (sqrt(3.0) * (double)n));
	w = rmax / (double)nb;
	for (size_t i = 0; i < n; i++)
		for (size_t j = i + 1; j < n; j++) {
			double k = key(xy, f, i, j, torus);
			if (k < rmax * rmax) {
				size_t b = (size_t)(sqrt(k) / w);
				cnt[b < nb ? b : nb - 1]++;
			}
		}
	assert_int_equal(dens_rdf_add(xy, n, f, torus, rmax_ru, nb, 1, acc), 0);
	for (size_t k = 0; k < nb; k++) {
		double c = acc[k] * expect(n, rmax, k, nb, torus);
		assert_near(c, (double)cnt[k], 1e-6 * (1 + (double)cnt[k]));
	}
	free(f);
	free(xy);
}

static void rdf_brute(void **state)
{
	(void)state;
	for (int sc = 0; sc < 2; sc++)
		for (int torus = 0; torus < 2; torus++)
			for (size_t n = 2; n <= 2000; n = n * 5 + 3)
				rdf_brute_one(n, sc, torus);
}

static void rdf_uniform(void **state)
{
	const size_t n = 1000, nb = 24, sets = 20;
	const double rmax_ru = 3;
	double rmax = rmax_ru * dens_spacing((double)n);
	(void)state;
	for (int torus = 0; torus < 2; torus++) {
		double acc[24] = { 0 }, worst = 0, far = 0;
		for (size_t s = 0; s < sets; s++) {
			double *xy = tu_rnd_points(n, 1000 + s);
			assert_int_equal(dens_rdf_add(xy, n, NULL, torus,
			    rmax_ru, nb, 1, acc), 0);
			free(xy);
		}
		for (size_t k = 0; k < nb; k++) {
			/* counts are ~Poisson: sd of the mean 1/sqrt(sets E) */
			double g = acc[k] / (double)sets;
			double sd = 1 / sqrt((double)sets *
			    expect(n, rmax, k, nb, torus));
			double z = fabs(g - 1) / sd;
			worst = z > worst ? z : worst;
			assert_true(z < 5);
			if (!torus && k >= nb / 2) {
				/* without the edge correction: too low */
				double a = rmax * (double)k / (double)nb;
				double b = rmax * (double)(k + 1) / (double)nb;
				far += g * (dens_pair_cdf(b, 0) -
				    dens_pair_cdf(a, 0)) /
				    (PI * (b * b - a * a)) / (double)(nb / 2);
			}
		}
		print_message("%s rdf of %zu uniform sets: worst |g - 1| = %.2f "
		    "sd\n", torus ? "torus" : "plain", sets, worst);
		if (!torus) {
			print_message("plain without edge correction: %.4f\n",
			    far);
			assert_true(far < 0.95);
		}
	}
}

static void rdf_grid(void **state)
{
	const size_t m = 32, nb = 40;
	double *xy = tu_grid_points(m), ru = dens_spacing((double)(m * m));
	(void)state;
	for (int torus = 0; torus < 2; torus++) {
		double acc[40] = { 0 };
		assert_int_equal(dens_rdf_add(xy, m * m, NULL, torus, 2.0, nb,
		    1, acc), 0);
		for (size_t k = 0; k < nb; k++) {
			double hi = 2.0 * ru * (double)(k + 1) / (double)nb;
			double lo = 2.0 * ru * (double)k / (double)nb;
			if (hi < 1.0 / (double)m * (1 - 1e-9))
				assert_true(acc[k] == 0);
			if (lo < 1.0 / (double)m && hi > 1.0 / (double)m)
				assert_true(acc[k] > 1);	/* a peak */
		}
	}
	free(xy);
}

/* ---- errors ------------------------------------------------------------ */

static void errors(void **state)
{
	double xy[6] = { 0.1, 0.2, 0.3, 0.4, 0.5, 0.6 }, d, acc[4] = { 0 };
	double f[3] = { 1, 0, 1 };
	(void)state;
	assert_int_equal(dens_min_distance(xy, 1, NULL, 0, 1, &d), -1);
	assert_err_has("1 point");
	assert_int_equal(dens_min_distance_rule(xy, 3, NULL, (enum dens_rule)7,
	    0, 1, &d), -1);
	assert_err_has("unknown pair rule 7");
	assert_int_equal(dens_min_distance(xy, 3, f, 0, 1, &d), -1);
	assert_err_has("point 1", "scale");
	xy[4] = 1.0;
	assert_int_equal(dens_min_distance(xy, 3, NULL, 0, 1, &d), -1);
	assert_err_has("point 2", "outside");
	xy[4] = NAN;
	assert_int_equal(dens_rdf_add(xy, 3, NULL, 0, 1, 4, 1, acc), -1);
	assert_err_has("point 2", "outside");
	xy[4] = -0.0;
	assert_int_equal(dens_scales(xy, 3, NULL, f), 0);
	xy[4] = 0.5;
	assert_int_equal(dens_rdf_add(xy, 3, NULL, 0, 1, 0, 1, acc), -1);
	assert_err_has("bins");
	assert_int_equal(dens_rdf_add(xy, 3, NULL, 1, 2, 4, 1, acc), -1);
	assert_err_has("rmax");
	assert_int_equal(dens_rdf_add(xy, 3, NULL, 0, NAN, 4, 1, acc), -1);
	assert_err_has("rmax");
	for (int k = 0; k < 4; k++)
		assert_true(acc[k] == 0);
}

/* ---- 3-D sets ------------------------------------------------------------ */

/* n uniform random points of the unit cube. */
static double *rnd3(size_t n, uint64_t seed)
{
	double *x = malloc(3 * n * sizeof *x);
	assert_non_null(x);
	for (size_t i = 0; i < 3 * n; i++)
		x[i] = frs_rand01(seed, FRS_STREAM_TEST, i);
	return x;
}

/* The 3-D key of density.h, written out independently. */
static double key3(const double *x, size_t i, size_t j, int torus)
{
	double d[3], s;
	for (int a = 0; a < 3; a++) {
		d[a] = x[3 * i + (size_t)a] - x[3 * j + (size_t)a];
		if (torus) {
			d[a] = fabs(d[a]);
			if (d[a] > 0.5)
				d[a] = 1 - d[a];
		}
	}
	s = d[0] * d[0];
	s = s + d[1] * d[1];
	return s + d[2] * d[2];
}

static double brute_min3(const double *x, size_t n, int torus)
{
	double best = INFINITY;
	for (size_t i = 0; i < n; i++)
		for (size_t j = i + 1; j < n; j++) {
			double k = key3(x, i, j, torus);
			best = k < best ? k : best;
		}
	return sqrt(best);
}

static double dmin3_of(const double *x, size_t n, int torus, int par)
{
	double d = -1;
	assert_int_equal(dens_min_distance3(x, n, torus, par, &d), 0);
	return d;
}

/* Against brute force, bit for bit.  mode 0: uniform, 1: clustered in a
 * corner (crowded cells), 2: a duplicate point, 3: the closest pair
 * across the faces (the torus wraps it), 4: sparse points far apart
 * beside a dense clump (the search walks out many rings). */
static void brute3_one(size_t n, uint64_t seed, int mode, int torus)
{
	double *x = rnd3(n, seed), d, r;
	if (mode == 1)
		for (size_t i = 0; i < 3 * n; i++)
			x[i] = 0.6 + 0.02 * x[i];
	if (mode == 2 && n >= 3)
		memcpy(&x[3 * (n - 1)], &x[3], 3 * sizeof *x);
	if (mode == 3 && n >= 2) {
		/* spread the rest on a coarse lattice, then a pair across the
		 * x faces: 0.002 apart on the torus, ~1 in the plain cube */
		for (size_t i = 2; i < n; i++)
			for (int a = 0; a < 3; a++)
				x[3 * i + (size_t)a] = 0.1 + 0.8 *
				    floor(x[3 * i + (size_t)a] * 5) / 5;
		x[0] = 0.001, x[1] = 0.5, x[2] = 0.5;
		x[3] = 1 - 0.001, x[4] = 0.5, x[5] = 0.5;
	}
	if (mode == 4)
		for (size_t i = 0; i < 3 * n; i++)
			if (i / 3 % 10 != 0)
				x[i] = 0.2 + 0.05 * x[i];
	d = dmin3_of(x, n, torus, 1);
	r = brute_min3(x, n, torus);
	if (d != r)
		print_error("3-D n %zu mode %d torus %d: %.17g != %.17g\n", n,
		    mode, torus, d, r);
	assert_true(d == r);
	assert_true(dmin3_of(x, n, torus, 0) == r);
	if (mode == 2 && n >= 3)
		assert_true(d == 0);
	if (mode == 3 && n >= 2 && torus)	/* or a duplicate of the rest */
		assert_true(d <= 0.002 + 1e-12);
	free(x);
}

static void brute3(void **state)
{
	static const size_t ns[] = { 2, 3, 4, 9, 16, 17, 100, 250, 1000,
	    3000 };
	uint64_t seed = 100;
	(void)state;
	frs_set_threads(2);
	for (size_t t = 0; t < sizeof ns / sizeof *ns; t++)
		for (int mode = 0; mode < 5; mode++)
			for (int torus = 0; torus < 2; torus++)
				brute3_one(ns[t], ++seed, mode, torus);
	/* the torus wraps in every axis, also in corners */
	{
		double x[12] = { 0.9995, 0.9995, 0.9995, 0.0005, 0.0005, 0.0005,
		    0.5, 0.5, 0.5, 0.25, 0.75, 0.5 };
		assert_near(dmin3_of(x, 4, 1, 1), sqrt(3.0) * 0.001, 1e-12);
		assert_true(dmin3_of(x, 4, 0, 1) == brute_min3(x, 4, 0));
	}
}

/* A regular m^3 grid: dmin = 1/m, rho = (1/m) / r_u3(m^3) = 2^(-1/6)
 * (the FCC packing is denser than the cubic one by 2^(1/6) in
 * spacing), plain and on the torus. */
static void lattice3(void **state)
{
	(void)state;
	assert_near(dens_spacing3(1000), 0.11224620483093730, 1e-16);
	for (size_t m = 2; m <= 16; m *= 2) {
		size_t n = m * m * m;
		double *x = tu_grid_points3(m);
		for (int torus = 0; torus < 2; torus++) {
			double d = dmin3_of(x, n, torus, 1);
			assert_near(d, 1.0 / (double)m, 1e-15);
			assert_near(dens_rho3(d, n), pow(2.0, -1.0 / 6), 1e-12);
			assert_near(dens_rho3(d, n),
			    (1.0 / (double)m) / dens_spacing3((double)n), 1e-12);
		}
		free(x);
	}
}

/* Uniform random sets: the closest pair is Weibull distributed,
 * E[rho] = Gamma(4/3) (3/(2 pi))^(1/3) 2^(-1/6) n^(-1/3) = 0.0622 at
 * n = 1000, standard deviation 36 % of it (density.h): 10 sets give a
 * mean within 4.5 standard errors, [0.030, 0.094].  400 sets of 500
 * check the formula itself.  Jittered sets (one point per cell of a
 * 10^3 grid) spread better: 0.12 in a simulation of 2000 sets, sd 0.034
 * per set; 10 sets within [0.075, 0.17], and above the random ones. */
static double mean_rho3(size_t n, int sets, int jitter, int torus,
    double *se)
{
	double s1 = 0, s2 = 0;
	size_t m = (size_t)llround(cbrt((double)n));
	for (int t = 0; t < sets; t++) {
		double *x = rnd3(n, 7000 + (uint64_t)t), r;
		for (size_t i = 0; jitter && i < n; i++) {
			size_t c[3] = { i / (m * m), i / m % m, i % m };
			for (int a = 0; a < 3; a++)
				x[3 * i + (size_t)a] = ((double)c[a] +
				    x[3 * i + (size_t)a]) / (double)m;
		}
		r = dens_rho3(dmin3_of(x, n, torus, 1), n);
		s1 += r, s2 += r * r;
		free(x);
	}
	s1 /= sets;
	*se = sqrt((s2 / sets - s1 * s1) / (sets - 1));
	return s1;
}

static void uniform3(void **state)
{
	double e = tgamma(4.0 / 3) * cbrt(3 / (2 * PI)) * pow(2.0, -1.0 / 6);
	double se, r[2], j[2];
	(void)state;
	frs_set_threads(2);
	for (int torus = 0; torus < 2; torus++) {
		r[torus] = mean_rho3(1000, 10, 0, torus, &se);
		j[torus] = mean_rho3(1000, 10, 1, torus, &se);
		print_message("3-D n 1000, 10 sets, %s: mean rho %.4f random "
		    "(expected %.4f), %.4f jittered\n", torus ? "torus" :
		    "plain", r[torus], e / 10, j[torus]);
		assert_true(r[torus] > 0.030 && r[torus] < 0.094);
		assert_true(j[torus] > 0.075 && j[torus] < 0.17);
		assert_true(j[torus] > r[torus]);
	}
	{
		double m = mean_rho3(500, 400, 0, 1, &se);
		double want = e * pow(500, -1.0 / 3);
		if (fabs(m - want) > 4.5 * se)
			fail_msg("400 sets of 500: mean rho %.5g, expected "
			    "%.5g (se %.3g)", m, want, se);
	}
}

static void errors3(void **state)
{
	double x[9] = { 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9 }, d;
	(void)state;
	assert_int_equal(dens_min_distance3(x, 1, 0, 1, &d), -1);
	assert_err_has("1 point");
	x[5] = 1.0;
	assert_int_equal(dens_min_distance3(x, 3, 0, 1, &d), -1);
	assert_err_has("point 1", "outside [0, 1)^3");
	x[5] = NAN;
	assert_int_equal(dens_min_distance3(x, 3, 1, 1, &d), -1);
	assert_err_has("point 1", "outside");
	x[5] = 0.6;
	assert_int_equal(dens_min_distance3(x, 3, 0, 1, NULL), -1);
	assert_int_equal(dens_min_distance3(NULL, 3, 0, 1, &d), -1);
}

/* ---- 2^20 points --------------------------------------------------------- */

static int cmp_x(const void *a, const void *b)
{
	const double *p = a, *q = b;
	return (p[0] > q[0]) - (p[0] < q[0]);
}

/* Exact minimum by a sweep over the points sorted by x (an oracle that
 * knows nothing of cells): a pair's key is at least its dx^2. */
static double sweep_min(const double *xy0, size_t n, int torus)
{
	double *xy = malloc(2 * n * sizeof *xy), best = INFINITY;
	assert_non_null(xy);
	memcpy(xy, xy0, 2 * n * sizeof *xy);
	qsort(xy, n, 2 * sizeof *xy, cmp_x);
	for (size_t i = 0; i < n; i++)
		for (size_t t = 1; t < n; t++) {
			size_t j = (i + t) % n;
			double g, k;
			if (!torus && j < i)
				break;
			/* forward gap in x; on the torus a pair whose gap
			 * exceeds 1/2 is found from its other end */
			g = j > i ? xy[2 * j] - xy[2 * i] :
			    (xy[2 * j] + 1) - xy[2 * i];
			if (torus && g > 0.5 + 1e-9)
				break;
			if (g - 1e-15 > 0 && (g - 1e-15) * (g - 1e-15) > best)
				break;
			k = key(xy, NULL, i, j, torus);
			if (k < best)
				best = k;
		}
	free(xy);
	return sqrt(best);
}

static void huge(void **state)
{
	const size_t n = (size_t)1 << 20;
	double *xy = tu_rnd_points(n, 2024);
	(void)state;
	for (int torus = 0; torus < 2; torus++) {
		double t0, t1, t2, d1, d2, want;
		frs_set_threads(1);
		t0 = now();
		d1 = dmin_of(xy, n, NULL, torus, 1);
		t1 = now();
		frs_set_threads(2);
		d2 = dmin_of(xy, n, NULL, torus, 1);
		t2 = now();
		frs_set_threads(1);
		want = sweep_min(xy, n, torus);
		print_message("2^20 points, %s: dmin %.6g (rho %.3g), "
		    "%.3f s on 1 thread, %.3f s on 2; sweep %.3f s\n",
		    torus ? "torus" : "plain", d1, dens_rho(d1, n), t1 - t0,
		    t2 - t1, now() - t2);
		assert_true(d1 == want);
		assert_true(d2 == want);
		assert_true(t1 - t0 < 60);
	}
	free(xy);
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(lattices),
	cmocka_unit_test(brute_force),
	cmocka_unit_test(far_pairs),
	cmocka_unit_test(dart),
	cmocka_unit_test(invariance),
	cmocka_unit_test(scales),
	cmocka_unit_test(pair_cdf),
	cmocka_unit_test(rdf_brute),
	cmocka_unit_test(rdf_uniform),
	cmocka_unit_test(rdf_grid),
	cmocka_unit_test(errors),
	cmocka_unit_test(brute3),
	cmocka_unit_test(lattice3),
	cmocka_unit_test(uniform3),
	cmocka_unit_test(errors3),
	cmocka_unit_test(huge))
