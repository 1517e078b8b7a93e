/* The star discrepancy of 3-D sets against independent oracles: Warnock's
 * formula evaluated directly in long double, its factorisation for
 * product sets, the 2-D implementation at k = 2, the expectation
 * E[D2^2] = (2^-k - 3^-k)/n of uniform random points, every critical box
 * counted by brute force, a plain O(n^3) sweep without the bounds, and
 * every grid box counted (discref.h). */
#include "testutil.h"
#include "discref.h"
#include "discrepancy/disc.h"
#include "base/par.h"
#include "base/rng.h"

/* n uniform random points of k coordinates. */
static double *rnd_k(size_t n, unsigned k, uint64_t seed)
{
	double *x = malloc((n ? n : 1) * k * sizeof *x);
	assert_non_null(x);
	for (size_t i = 0; i < n * k; i++)
		x[i] = frs_rand01(seed, FRS_STREAM_TEST, i);
	return x;
}

/* Random points with the hard cases: coordinates on the lines i/s,
 * rounded to quarters (ties), duplicate points, 0 and 1 - ulp. */
static double *hard3(size_t n, uint32_t s, uint64_t seed)
{
	double *x = rnd_k(n, 3, seed);
	for (size_t i = 0; i < n; i += 3)
		x[3 * i] = (double)(i % s) / s;
	for (size_t i = 1; i < n; i += 4)
		x[3 * i + 1] = floor(x[3 * i + 1] * 4) / 4;
	for (size_t i = 2; i < n; i += 5)
		x[3 * i + 2] = (double)(i % (s + 1)) / (s + 1);
	x[0] = 0.0, x[1] = nextafter(1.0, 0.0);
	if (n > 6) {
		x[3] = nextafter(1.0, 0.0), x[4] = 0.0, x[5] = 0.5;
		memcpy(&x[9], &x[15], 3 * sizeof *x);	/* point 3 = point 5 */
	}
	return x;
}

/* ---- D2: Warnock's closed form -------------------------------------- */

/* The formula as written (discref.h's oracle), its root. */
static double warnock_direct(const double *x, size_t n, unsigned k)
{
	long double sq = ref_warnock_sq(x, n, k);

	return (double)sqrtl(sq > 0 ? sq : 0);
}

static void l2_direct(void **state)
{
	static const size_t ns[] = { 1, 2, 3, 17, 100, 333 };
	(void)state;
	frs_set_threads(2);
	for (unsigned k = 1; k <= 4; k++)
		for (size_t t = 0; t < sizeof ns / sizeof *ns; t++) {
			size_t n = ns[t];
			double *x = k == 3 ? hard3(n, 7, 10 + t) :
			    rnd_k(n, k, 10 + t);
			double r = warnock_direct(x, n, k);
			for (int par = 0; par < 2; par++) {
				double d = disc_star_l2_exact_k(x, n, k, par);
				if (fabs(d - r) > 1e-12 * r)
					fail_msg("k %u n %zu: %.17g, direct %.17g",
					    k, n, d, r);
			}
			free(x);
		}
}

/* The O(n log^2 n) divide and conquer against Warnock's formula as
 * written (discref.h), to 1e-14 on D2^2: the sets of ref_pair_set,
 * sizes around the blocks of 32 points and the levels above them, on
 * one thread and on the team (the same bits). */
static void l2_cdq_oracle(void **state)
{
	static const size_t ns[] = { 1, 2, 3, 5, 31, 32, 33, 63, 65, 97,
	    257, 1000 };
	(void)state;
	frs_set_threads(2);
	for (int kind = 0; kind < 4; kind++)
		for (size_t t = 0; t < sizeof ns / sizeof *ns; t++) {
			size_t n = ns[t];
			double *x = malloc(3 * n * sizeof *x), d, e;
			long double r;
			assert_non_null(x);
			ref_pair_set(x, n, 3, kind, 50 + t);
			d = disc_star_l2_exact_k(x, n, 3, 0);
			e = disc_star_l2_exact_k(x, n, 3, 1);
			r = ref_warnock_sq(x, n, 3);
			if (fabsl((long double)d * d - r) > 1e-14L || d != e)
				fail_msg("kind %d n %zu: D2^2 %.17g (team %.17g), "
				    "oracle %.17Lg", kind, n, d * d, e * e, r);
			free(x);
		}
}

/* Every point the same, or on the origin: the ties of all three axes
 * at once, through the levels (n = 200). */
static void l2_cdq_ties(void **state)
{
	static const double at[] = { 0.0, 0.25, 0.5 };
	(void)state;
	for (size_t a = 0; a < 3; a++) {
		size_t n = 200;
		double *x = malloc(3 * n * sizeof *x), d;
		assert_non_null(x);
		for (size_t i = 0; i < 3 * n; i++)
			x[i] = at[a];
		d = disc_star_l2_exact_k(x, n, 3, 1);
		assert_true(fabsl((long double)d * d - ref_warnock_sq(x, n,
		    3)) <= 1e-14L);
		free(x);
	}
}

/* k = 2: the O(n log n) sweep of disc.c, another route to the same. */
static void l2_two_dims(void **state)
{
	(void)state;
	for (size_t n = 1; n <= 4096; n *= 8) {
		double *xy = rnd_k(n, 2, 40 + n);
		double a = disc_star_l2_exact(xy, n);
		double b = disc_star_l2_exact_k(xy, n, 2, 1);
		assert_true(fabs(a - b) <= 1e-12 * a);
		free(xy);
	}
}

/* A product set X^3, X the m centres (i + 1/2)/m: the sums factor,
 * D2^2 = 3^-3 - 2^-2 A^3 + B^3 with A = mean of 1 - x^2 and B = mean
 * over pairs of 1 - max. */
static void l2_product(void **state)
{
	(void)state;
	for (size_t m = 1; m <= 16; m *= 2) {
		size_t n = m * m * m;
		double *x = tu_grid_points3(m);
		long double a = 0, b = 0, want;
		for (size_t i = 0; i < m; i++) {
			long double u = ((long double)i + 0.5L) / m;
			a += 1 - u * u;
			for (size_t j = 0; j < m; j++)
				b += 1 - fmaxl(u, ((long double)j + 0.5L) / m);
		}
		a /= m, b /= (long double)m * m;
		want = sqrtl(1.0L / 27 - a * a * a / 4 + b * b * b);
		assert_near(disc_star_l2_exact_k(x, n, 3, 1), (double)want,
		    1e-12 * (double)want);
		free(x);
	}
}

/* Mean D2^2 of m random sets against E = sum of v(1 - v)/n over the
 * boxes: (2^-3 - 3^-3)/n for the continuum; z-score from the sample
 * variance.  Grid and exact, and D2 <= Dinf for each set. */
static void expectation(void **state)
{
	const size_t n = 64;
	const int m = 300;
	const uint32_t s = 12;
	double e[2] = { (1.0 / 8 - 1.0 / 27) / (double)n, 0 };
	double s1[2] = { 0, 0 }, s2[2] = { 0, 0 };
	(void)state;
	for (uint32_t i = 1; i <= s; i++)
	for (uint32_t j = 1; j <= s; j++)
	for (uint32_t l = 1; l <= s; l++) {
		double v = (double)i / s * ((double)j / s) * ((double)l / s);
		e[1] += v * (1 - v);
	}
	e[1] /= (double)s * s * s * (double)n;
	for (int k = 0; k < m; k++) {
		double *x = rnd_k(n, 3, 2000 + (uint64_t)k), v;
		struct disc_result g;
		v = disc_star_l2_exact_k(x, n, 3, 0);
		s1[0] += v * v, s2[0] += v * v * v * v;
		assert_int_equal(disc3_star_grid(x, n, s, 0, &g), 0);
		s1[1] += g.d2 * g.d2, s2[1] += pow(g.d2, 4);
		assert_true(g.d2 <= g.dinf);
		assert_int_equal(disc3_star_dinf_exact(x, n, 0, &g.dinf), 0);
		assert_true(v <= g.dinf);
		free(x);
	}
	for (int w = 0; w < 2; w++) {
		double mean = s1[w] / m;
		double se = sqrt((s2[w] / m - mean * mean) / (m - 1));
		if (fabs(mean - e[w]) > 4.5 * se)
			fail_msg("%s: mean D2^2 %.6g, expected %.6g (se %.3g)",
			    w ? "grid" : "exact", mean, e[w], se);
	}
}

/* ---- the grid --------------------------------------------------------- */

static void grid_brute(void **state)
{
	static const size_t ns[] = { 1, 2, 7, 40, 90 };
	(void)state;
	frs_set_threads(2);
	for (size_t t = 0; t < sizeof ns / sizeof *ns; t++)
		for (uint32_t s = 2; s <= 11; s += 3) {
			double *x = hard3(ns[t], s, 100 + t), d2, di;
			struct disc_result r;
			ref_star_grid3(x, ns[t], s, &d2, &di);
			for (int par = 0; par < 2; par++) {
				assert_int_equal(disc3_star_grid(x, ns[t], s, par,
				    &r), 0);
				assert_near(r.d2, d2, 1e-12 * d2 + 1e-15);
				assert_near(r.dinf, di, 1e-15);
			}
			free(x);
		}
	/* more planes than one chunk holds, points on every line */
	{
		uint32_t s = 19;
		double *x = hard3(60, s, 150), d2, di;
		struct disc_result r;
		for (size_t i = 0; i < 60; i++)
			x[3 * i + (i % 3)] = (double)(i % s) / s;
		ref_star_grid3(x, 60, s, &d2, &di);
		assert_int_equal(disc3_star_grid(x, 60, s, 1, &r), 0);
		assert_near(r.d2, d2, 1e-12 * d2);
		assert_near(r.dinf, di, 1e-15);
		free(x);
	}
}

/* The grid is a right-endpoint sum of d^2 over s^3 cells: within 12/s
 * of the exact integral (d^2 <= 1 changes over a cell by at most twice
 * the volume change, 3/s, plus the points in its slabs, 3/s on
 * average); and its Dinf never exceeds the exact one. */
static void grid_converges(void **state)
{
	double *x = rnd_k(300, 3, 300), e, v, last = 1;
	(void)state;
	e = disc_star_l2_exact_k(x, 300, 3, 1);
	assert_int_equal(disc3_star_dinf_exact(x, 300, 1, &v), 0);
	for (uint32_t s = 4; s <= 256; s *= 4) {
		struct disc_result g;
		assert_int_equal(disc3_star_grid(x, 300, s, 1, &g), 0);
		assert_true(fabs(g.d2 * g.d2 - e * e) <= 12.0 / s);
		assert_true(fabs(g.d2 * g.d2 - e * e) < last);
		last = fabs(g.d2 * g.d2 - e * e);
		assert_true(g.dinf <= v + 1e-15);
	}
	free(x);
}

/* ---- Dinf over the critical boxes ------------------------------------- */

/* Every corner (a, b, c), each a point coordinate of its axis or 1,
 * both counts by looking at every point: O(n^4). */
static double dinf_brute(const double *x, size_t n)
{
	double best = 0;
	for (size_t i = 0; i <= n; i++)
	for (size_t j = 0; j <= n; j++)
	for (size_t l = 0; l <= n; l++) {
		double a = i < n ? x[3 * i] : 1.0;
		double b = j < n ? x[3 * j + 1] : 1.0;
		double c = l < n ? x[3 * l + 2] : 1.0, v = a * b * c;
		size_t open = 0, closed = 0;
		for (size_t k = 0; k < n; k++) {
			const double *p = &x[3 * k];
			open += p[0] < a && p[1] < b && p[2] < c;
			closed += p[0] <= a && p[1] <= b && p[2] <= c;
		}
		best = fmax(best, v - (double)open / (double)n);
		best = fmax(best, (double)closed / (double)n - v);
	}
	return best;
}

static int dcmp(const void *a, const void *b)
{
	double p = *(const double *)a, q = *(const double *)b;
	return (p > q) - (p < q);
}

/* Sorted distinct values of coordinate c, and 1. */
static double *values(const double *x, size_t n, int c, size_t *m)
{
	double *v = malloc((n + 1) * sizeof *v);
	size_t k = 0;
	assert_non_null(v);
	for (size_t i = 0; i < n; i++)
		v[i] = x[3 * i + (size_t)c];
	qsort(v, n, sizeof *v, dcmp);
	for (size_t i = 0; i < n; i++)
		if (k == 0 || v[i] != v[k - 1])
			v[k++] = v[i];
	if (k == 0 || v[k - 1] != 1.0)
		v[k++] = 1.0;
	*m = k;
	return v;
}

/* The same corners by a plain sweep, O(n^3): for each a, the points
 * below (strictly, and or at) a counted into a y-z table by binary
 * search, summed up, every corner looked at. */
static size_t rank_le(const double *v, size_t m, double t)
{
	size_t lo = 0, hi = m;
	while (lo < hi) {
		size_t mid = (lo + hi) / 2;
		if (v[mid] <= t)
			lo = mid + 1;
		else
			hi = mid;
	}
	return lo;	/* values <= t */
}

static double dinf_sweep(const double *x, size_t n)
{
	size_t mx, my, mz;
	double *vx = values(x, n, 0, &mx), *vy = values(x, n, 1, &my);
	double *vz = values(x, n, 2, &mz), best = 0;
	size_t w = mz + 1;
	long *op = malloc((my + 1) * w * sizeof *op);
	long *cl = malloc((my + 1) * w * sizeof *cl);
	assert_true(op != NULL && cl != NULL);
	for (size_t ia = 0; ia < mx; ia++) {
		double a = vx[ia];
		memset(op, 0, (my + 1) * w * sizeof *op);
		memset(cl, 0, (my + 1) * w * sizeof *cl);
		/* cell (j, l): points with y rank j (y = vy[j - 1]) */
		for (size_t k = 0; k < n; k++) {
			const double *p = &x[3 * k];
			size_t j = rank_le(vy, my, p[1]);
			size_t l = rank_le(vz, mz, p[2]);
			if (p[0] < a)
				op[j * w + l]++;
			if (p[0] <= a)
				cl[j * w + l]++;
		}
		for (size_t j = 0; j <= my; j++)
			for (size_t l = 0; l <= mz; l++) {
				long *t[2] = { op, cl };
				for (int u = 0; u < 2; u++) {
					long v = t[u][j * w + l];
					if (j > 0)
						v += t[u][(j - 1) * w + l];
					if (l > 0)
						v += t[u][j * w + l - 1];
					if (j > 0 && l > 0)
						v -= t[u][(j - 1) * w + l - 1];
					t[u][j * w + l] = v;
				}
			}
		/* corner (a, vy[j], vz[l]): closed up to ranks j+1, l+1,
		 * open up to j, l */
		for (size_t j = 0; j < my; j++)
			for (size_t l = 0; l < mz; l++) {
				double v = a * vy[j] * vz[l];
				best = fmax(best, v - (double)op[j * w + l] / n);
				best = fmax(best, (double)cl[(j + 1) * w + l + 1] /
				    n - v);
			}
	}
	free(vx), free(vy), free(vz), free(op), free(cl);
	return best;
}

static double dinf_of(const double *x, size_t n, int par)
{
	double v = -1;
	assert_int_equal(disc3_star_dinf_exact(x, n, par, &v), 0);
	return v;
}

static void dinf_brute_small(void **state)
{
	static const double one[][3] = { { 0, 0, 0 }, { 0.5, 0.5, 0.5 },
	    { 0.9, 0.2, 0.4 }, { 0.999, 0.999, 0.999 }, { 0.1, 0.3, 0.05 } };
	(void)state;
	frs_set_threads(2);
	/* one point: max(1 - xyz, x, y, z) */
	for (size_t k = 0; k < 5; k++) {
		const double *p = one[k];
		double want = fmax(1 - p[0] * p[1] * p[2],
		    fmax(p[0], fmax(p[1], p[2])));
		assert_near(dinf_of(p, 1, 0), want, 1e-15);
		assert_near(dinf_brute(p, 1), want, 1e-15);
	}
	for (size_t n = 2; n <= 44; n += 7) {
		double *x = hard3(n, 3, 500 + n), b = dinf_brute(x, n);
		assert_near(dinf_of(x, n, 0), b, 1e-15);
		assert_near(dinf_of(x, n, 1), b, 1e-15);
		assert_near(dinf_sweep(x, n), b, 1e-15);
		free(x);
	}
	/* all points equal */
	for (int v = 0; v < 3; v++) {
		double at = v == 0 ? 0.0 : v == 1 ? nextafter(1.0, 0.0) : 0.5;
		double x[3 * 9];
		for (size_t i = 0; i < 27; i++)
			x[i] = at;
		assert_near(dinf_of(x, 9, 1), dinf_brute(x, 9), 1e-15);
	}
}

/* Larger sets against the plain sweep: random, many ties, tie groups in
 * x longer than the pending list, a low-discrepancy set (Halton bases
 * 2, 3, 5: the bounds rule out little), and a clustered one. */
static double radical(uint64_t i, unsigned b)
{
	double f = 1, r = 0;
	for (; i > 0; i /= b) {
		f /= b;
		r += f * (double)(i % b);
	}
	return r;
}

static void dinf_sweep_sets(void **state)
{
	(void)state;
	frs_set_threads(2);
	for (int kind = 0; kind < 5; kind++) {
		size_t n = kind == 2 ? 600 : 400;
		double *x = rnd_k(n, 3, 700 + (uint64_t)kind), v, w;
		for (size_t i = 0; i < n; i++) {
			double *p = &x[3 * i];
			if (kind == 1)	/* ties in every axis */
				p[i % 3] = floor(p[i % 3] * 16) / 16;
			if (kind == 2)	/* 4 x values: groups of ~150 */
				p[0] = floor(p[0] * 4) / 4;
			if (kind == 3)
				p[0] = radical(i + 1, 2), p[1] = radical(i + 1, 3),
				p[2] = radical(i + 1, 5);
			if (kind == 4)	/* a corner of the cube */
				p[0] *= 0.2, p[1] *= 0.3, p[2] = 0.5 + p[2] * 0.1;
		}
		w = dinf_sweep(x, n);
		frs_set_threads(1);
		v = dinf_of(x, n, 0);
		assert_near(v, w, 1e-15);
		frs_set_threads(2);
		assert_true(dinf_of(x, n, 1) == v);
		free(x);
	}
}

/* Many moderate sets of five kinds against the plain sweep: a wrong
 * bound or count only shows when the maximum lies where it errs, which
 * one set in ten to a hundred hits. */
static void dinf_many(void **state)
{
	(void)state;
	frs_set_threads(2);
	for (uint64_t t = 0; t < 80; t++) {
		size_t n = 80 + (size_t)(frs_rand01(99, 1, t) * 150);
		int kind = (int)(t % 5);
		double *x = rnd_k(n, 3, 5000 + t), w;
		for (size_t i = 0; i < n; i++) {
			double *p = &x[3 * i];
			size_t c = i % 125;
			if (kind == 1)
				p[i % 3] = floor(p[i % 3] * 16) / 16;
			if (kind == 2)
				p[0] = floor(p[0] * 4) / 4;
			if (kind == 3)
				p[0] = radical(i + 1 + t, 2),
				p[1] = radical(i + 1 + t, 3),
				p[2] = radical(i + 1 + t, 5);
			if (kind == 4)	/* jittered 5^3 */
				p[0] = ((double)(c / 25) + p[0]) / 5,
				p[1] = ((double)(c / 5 % 5) + p[1]) / 5,
				p[2] = ((double)(c % 5) + p[2]) / 5;
		}
		w = dinf_sweep(x, n);
		if (fabs(dinf_of(x, n, t & 1) - w) > 1e-15)
			fail_msg("set %llu (kind %d, n %zu): %.17g, sweep %.17g",
			    (unsigned long long)t, kind, n, dinf_of(x, n, 0), w);
		free(x);
	}
}

/* Order of the points, thread count: the same bits. */
static void invariants(void **state)
{
	size_t n = 500;
	double *x = rnd_k(n, 3, 900), *perm = malloc(3 * n * sizeof *perm);
	struct disc_result g[3];
	double e[3], d[3];
	(void)state;
	assert_non_null(perm);
	for (size_t i = 0; i < n; i++)
		memcpy(&perm[3 * ((i * 263) % n)], &x[3 * i], 3 * sizeof *x);
	for (int t = 0; t < 3; t++) {
		const double *p = t == 2 ? perm : x;
		frs_set_threads(t == 0 ? 1 : 2);
		e[t] = disc_star_l2_exact_k(p, n, 3, t != 0);
		d[t] = dinf_of(p, n, t != 0);
		assert_int_equal(disc3_star_grid(p, n, 37, t != 0, &g[t]), 0);
	}
	assert_true(e[0] == e[1] && d[0] == d[1]);
	assert_true(g[0].d2 == g[1].d2 && g[0].dinf == g[1].dinf);
	assert_near(e[2], e[0], 1e-14 * e[0]);
	assert_true(d[2] == d[0] && g[2].dinf == g[0].dinf);
	assert_near(g[2].d2, g[0].d2, 1e-14 * g[0].d2);
	assert_true(e[0] <= d[0] && g[0].d2 <= g[0].dinf);
	free(x), free(perm);
}

/* ---- the driver ------------------------------------------------------- */

static void driver(void **state)
{
	double *x = rnd_k(200, 3, 950), v;
	struct disc_opts o = { .cls = DISC_STAR, .grid = DISC3_STAR_GRID };
	struct disc_result r, g;
	struct disc_ctx *c;
	(void)state;
	frs_set_threads(2);
	/* grid: D2 and Dinf of the grid */
	c = disc_ctx_new(&o);
	assert_non_null(c);
	assert_int_equal(disc_set_dims(c, x, 200, 3, 1, &r), 0);
	assert_int_equal(disc3_star_grid(x, 200, DISC3_STAR_GRID, 0, &g), 0);
	assert_true(r.d2 == g.d2 && r.dinf == g.dinf);
	assert_true(disc_tests_dims(&o, 3) == 1e6);
	disc_ctx_free(c);
	/* --exact --grid: exact D2, Dinf of the grid */
	o.exact_d2 = 1, o.grid = 20;
	c = disc_ctx_new(&o);
	assert_int_equal(disc_set_dims(c, x, 200, 3, 1, &r), 0);
	assert_int_equal(disc3_star_grid(x, 200, 20, 0, &g), 0);
	assert_true(r.d2 == disc_star_l2_exact_k(x, 200, 3, 0));
	assert_true(r.dinf == g.dinf);
	disc_ctx_free(c);
	/* --exact */
	o.exact_dinf = 1;
	c = disc_ctx_new(&o);
	assert_int_equal(disc_set_dims(c, x, 200, 3, 0, &r), 0);
	assert_int_equal(disc3_star_dinf_exact(x, 200, 1, &v), 0);
	assert_true(r.dinf == v);
	disc_ctx_free(c);
	free(x);
}

static void limits(void **state)
{
	struct disc_opts o = { .cls = DISC_RECT, .grid = 50 };
	double p[3] = { 0.1, 0.2, 0.3 }, v;
	struct disc_result r;
	(void)state;
	assert_int_equal(disc_check(&o, 2, 10), 0);
	assert_int_equal(disc_check(&o, 3, 10), -1);
	assert_non_null(strstr(frs_errmsg(), "class rect is 2-D only"));
	assert_null(strstr(frs_errmsg(), "-c"));	/* the program's flag */
	o.cls = DISC_CIRCLE;
	assert_int_equal(disc_check(&o, 3, 10), -1);
	assert_non_null(strstr(frs_errmsg(), "circle"));
	o.cls = DISC_STAR;
	assert_int_equal(disc_check(&o, 3, 10), 0);
	assert_int_equal(disc_check(&o, 4, 10), -1);
	o.grid = DISC3_MAX_GRID + 1;
	assert_int_equal(disc_check(&o, 3, 10), -1);
	assert_non_null(strstr(frs_errmsg(), "grid 1001: a 3-D grid"));
	assert_null(strstr(frs_errmsg(), "--"));
	assert_int_equal(disc_check(&o, 2, 10), 0);
	o.exact_d2 = o.exact_dinf = 1;
	assert_int_equal(disc_check(&o, 3, DISC3_MAX_EXACT_N), 0);
	assert_int_equal(disc_check(&o, 3, DISC3_MAX_EXACT_N + 1), -1);
	assert_non_null(strstr(frs_errmsg(), "limited to 4096 points"));
	assert_null(strstr(frs_errmsg(), "--"));
	assert_int_equal(disc3_star_dinf_exact(p, DISC3_MAX_EXACT_N + 1, 0,
	    &v), -1);
	o.exact_dinf = 0, o.grid = 100;
	assert_int_equal(disc_check(&o, 3, DISC3_MAX_EXACT_N + 1), 0);
	assert_int_equal(disc_check(&o, 3, DISC3_MAX_EXACT_D2 + 1), -1);
	assert_int_equal(disc_check(&o, 3, 0), -1);
	assert_int_equal(disc3_star_grid(p, 1, DISC3_MAX_GRID + 1, 0, &r), -1);
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(l2_direct),
	cmocka_unit_test(l2_cdq_oracle),
	cmocka_unit_test(l2_cdq_ties),
	cmocka_unit_test(l2_two_dims),
	cmocka_unit_test(l2_product),
	cmocka_unit_test(expectation),
	cmocka_unit_test(grid_brute),
	cmocka_unit_test(grid_converges),
	cmocka_unit_test(dinf_brute_small),
	cmocka_unit_test(dinf_sweep_sets),
	cmocka_unit_test(dinf_many),
	cmocka_unit_test(invariants),
	cmocka_unit_test(driver),
	cmocka_unit_test(limits))
