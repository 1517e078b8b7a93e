/* Differential domain analysis against independent oracles: the Poisson
 * expectation 1 of uniform random sets (standard errors from the sets),
 * a brute-force O(n^2) reference in long double (every ordered pair, the
 * Gaussian taps of ddaspec.h, the edge correction counted per pixel), the
 * exact pair count of the total mass, the lattice of a regular grid, the
 * scale invariance of compressed sets, symmetry, thread count and point
 * order, and bad arguments. */
#include "testutil.h"
#include "dda/ddaspec.h"
#include "base/par.h"
#include "base/rng.h"

/* Scales in [1/2, 2), log-uniform. */
static double *rnd_scales(size_t n, uint64_t seed)
{
	double *f = malloc(n * sizeof *f);
	assert_non_null(f);
	for (size_t i = 0; i < n; i++)
		f[i] = 0.5 * pow(4.0, frs_rand01(seed, FRS_STREAM_TEST, i));
	return f;
}

static double *image(uint32_t half)
{
	size_t side = 2 * (size_t)half + 1;
	double *a = calloc(side * side, sizeof *a);
	assert_non_null(a);
	return a;
}

static double ru_of(size_t n)
{
	return sqrt(2.0 / (sqrt(3.0) * (double)n));
}

static double fsc(const double *f, size_t i)
{
	return f != NULL ? f[i] : 1.0;
}

/* ---- oracles ---- */

/* Twice the edge correction E of pixel (c, r), by its definition: the
 * points with x_i + d r_u / f_i in [0,1)^2, plus those with x_i - d ... */
static long ref_e2(const double *xy, size_t n, const double *f, double eps,
    uint32_t half, size_t c, size_t r)
{
	double h = eps / half, ru = ru_of(n);
	double dx = ((double)c - half) * h, dy = ((double)r - half) * h;
	long e = 0;
	for (size_t i = 0; i < n; i++)
		for (int sg = -1; sg <= 1; sg += 2) {
			double x = xy[2 * i] + sg * dx * ru / fsc(f, i);
			double y = xy[2 * i + 1] + sg * dy * ru / fsc(f, i);
			e += x >= 0 && x < 1 && y >= 0 && y < 1;
		}
	return e;
}

/* (n - 1) (h r_u)^2 E: the divisor of a pixel. */
static double ref_norm(const double *xy, size_t n, const double *f,
    double eps, uint32_t half, size_t c, size_t r)
{
	double h = eps / half, ru = ru_of(n);
	return (double)(n - 1) * (h * ru) * (h * ru) *
	    0.5 * (double)ref_e2(xy, n, f, eps, half, c, r);
}

/* Number of ordered pairs with |d_ij| < eps, by brute force. */
static long ref_pairs(const double *xy, size_t n, const double *f,
    double eps)
{
	long p = 0;
	double ru = ru_of(n);
	for (size_t i = 0; i < n; i++)
		for (size_t j = 0; j < n; j++) {
			long double s = sqrtl((long double)fsc(f, i) * fsc(f, j));
			long double dx = (xy[2 * j] - xy[2 * i]) * s / ru;
			long double dy = (xy[2 * j + 1] - xy[2 * i + 1]) * s / ru;
			p += i != j && dx * dx + dy * dy < (long double)eps * eps;
		}
	return p;
}

/* 1-D taps of one pair: |k - u| <= 3 sigma and the nearest k. */
static int ref_taps(double u, double sigma, long *k0, long double *w)
{
	long kn = lround(u), a = (long)ceil(u - 3 * sigma);
	long b = (long)floor(u + 3 * sigma);
	long double s = 0;
	if (a > kn)
		a = kn;
	if (b < kn)
		b = kn;
	for (long k = a; k <= b; k++) {
		long double e = (long double)k - u;
		w[k - a] = sigma > 0 ? expl(-e * e / (2.0L * sigma * sigma)) :
		    (k == kn);
		s += w[k - a];
	}
	for (long k = a; k <= b; k++)
		w[k - a] /= s;
	*k0 = a;
	return (int)(b - a + 1);
}

/* The splatted mass per pixel, every ordered pair, long double. */
static long double *ref_mass(const double *xy, size_t n, const double *f,
    double eps, uint32_t half, double sigma)
{
	size_t side = 2 * (size_t)half + 1;
	long double *m = calloc(side * side, sizeof *m), wx[64], wy[64];
	double ru = ru_of(n), topx = half / eps;
	assert_non_null(m);
	for (size_t i = 0; i < n; i++)
		for (size_t j = 0; j < n; j++) {
			double s = sqrt(fsc(f, i) * fsc(f, j)), dx, dy;
			long ax, ay;
			int lx, ly;
			if (i == j)
				continue;
			dx = (xy[2 * j] - xy[2 * i]) * s / ru;
			dy = (xy[2 * j + 1] - xy[2 * i + 1]) * s / ru;
			if (dx * dx + dy * dy >= eps * eps)
				continue;
			lx = ref_taps(dx * topx, sigma, &ax, wx);
			ly = ref_taps(dy * topx, sigma, &ay, wy);
			for (int ty = 0; ty < ly; ty++)
				for (int tx = 0; tx < lx; tx++) {
					long c = ax + tx + half, r = ay + ty + half;
					if (c >= 0 && r >= 0 && c < (long)side &&
					    r < (long)side)
						m[r * side + c] += wx[tx] * wy[ty];
				}
		}
	return m;
}

/* ---- the Poisson expectation ---- */

/* 10 sets of 1024 uniform random points: D is 1 in expectation at every
 * d.  The mean over 2 <= |d| < 10 and the radial means of unit annuli,
 * each against its standard error over the sets. */
static void uniform_poisson(void **state)
{
	enum { SETS = 10, NA = 11 };
	uint32_t half = DDA_HALF;
	size_t n = 1024, side = 2 * (size_t)half + 1;
	double h = DDA_EPS / half, m[SETS], ra[NA][SETS];
	(void)state;
	frs_set_threads(2);
	for (int k = 0; k < SETS; k++) {
		double *xy = tu_rnd_points(n, 100 + (uint64_t)k), *a = image(half);
		double s = 0, rs[NA] = { 0 };
		long cnt = 0, rc[NA] = { 0 };
		assert_int_equal(dda_add(xy, n, NULL, DDA_EPS, half,
		    DDA_SIGMA_PX, 1, a), 0);
		for (size_t r = 0; r < side; r++)
			for (size_t c = 0; c < side; c++) {
				double dx = ((double)c - half) * h;
				double dy = ((double)r - half) * h;
				double d = sqrt(dx * dx + dy * dy), v = a[r * side + c];
				assert_true(isfinite(v) && v >= 0);
				if (d >= 2 && d < 10)
					s += v, cnt++;
				if (d >= 0.5 && d < NA - 0.5) {
					int b = (int)(d + 0.5);
					rs[b] += v, rc[b]++;
				}
			}
		m[k] = s / (double)cnt;
		for (int b = 1; b < NA; b++)
			ra[b][k] = rs[b] / (double)rc[b];
		free(xy), free(a);
	}
	for (int b = 0; b < NA; b++) {
		double *v = b == 0 ? m : ra[b], mean = 0, var = 0, se;
		for (int k = 0; k < SETS; k++)
			mean += v[k] / SETS;
		for (int k = 0; k < SETS; k++)
			var += (v[k] - mean) * (v[k] - mean) / (SETS - 1);
		se = sqrt(var / SETS);
		/* the test must be able to fail: a tight bound */
		assert_true(se > 0 && se < (b == 0 ? 0.01 : 0.03));
		if (fabs(mean - 1) > 4.5 * se)
			fail_msg("%s %d: mean %.5f, expected 1 (se %.5f)",
			    b == 0 ? "2 <= |d| < 10" : "annulus", b, mean, se);
	}
}

/* ---- against the brute-force reference ---- */

static void check_ref(const double *xy, size_t n, const double *f,
    double eps, uint32_t half, double sigma)
{
	size_t side = 2 * (size_t)half + 1;
	double *a = image(half);
	long double *m = ref_mass(xy, n, f, eps, half, sigma), tot = 0, got = 0;
	long double lost = 0;
	long pairs = ref_pairs(xy, n, f, eps);
	assert_int_equal(dda_add(xy, n, f, eps, half, sigma, 1, a), 0);
	for (size_t r = 0; r < side; r++)
		for (size_t c = 0; c < side; c++) {
			double nm = ref_norm(xy, n, f, eps, half, c, r);
			double v = a[r * side + c], ms = v * nm;
			long double want = m[r * side + c];
			tot += want;
			if (nm == 0) {	/* E = 0: left alone */
				assert_true(v == 0);
				lost += want;
				continue;
			}
			/* masses: 1-D weights are rounded to 2^-20 */
			if (!(fabsl(ms - want) <= 1e-4L + 1e-9L * want))
				fail_msg("pixel (%zu, %zu), sigma %g: mass %.9g, "
				    "reference %.9Lg", c, r, sigma, ms, want);
			got += ms;
		}
	/* the kernel inside the image: the reference's mass is the number
	 * of ordered pairs within eps (some of it may fall where E = 0) */
	if (3 * sigma < 1)
		assert_true(fabsl(tot - pairs) <= 1e-9L * pairs);
	else
		assert_true(tot <= pairs + 1e-6 && tot > 0.9 * pairs);
	if (!(fabsl(got - (tot - lost)) <= 1e-6L * pairs))
		fail_msg("sigma %g: mass %.9Lg, reference %.9Lg of %ld pairs",
		    sigma, got, tot - lost, pairs);
	if (!(lost <= 0.05L * pairs))
		fail_msg("sigma %g eps %g f %d: %.6Lg of %ld pairs where E = 0",
		    sigma, eps, f != NULL, lost, pairs);
	free(a), free(m);
}

static void brute_force(void **state)
{
	size_t n = 150;
	double *xy = tu_rnd_points(n, 7), *f = rnd_scales(n, 8);
	const double sig[] = { 0, 0.3, 1, 2.5 };
	(void)state;
	frs_set_threads(2);
	for (int k = 0; k < 4; k++) {
		check_ref(xy, n, NULL, 12, 24, sig[k]);
		check_ref(xy, n, f, 12, 24, sig[k]);
	}
	/* small eps: the cell grid prunes */
	check_ref(xy, n, f, 3, 16, 0.3);
	check_ref(xy, n, NULL, 2.5, 8, 1);
	free(xy), free(f);
	/* strongly varying scales, more points than the grid's cell */
	n = 600;
	xy = tu_rnd_points(n, 9);
	f = malloc(n * sizeof *f);
	for (size_t i = 0; i < n; i++)
		f[i] = 0.1 * pow(100.0, frs_rand01(10, FRS_STREAM_TEST, i));
	check_ref(xy, n, f, 4, 12, 0.3);
	free(xy), free(f);
}

/* ---- invariances ---- */

static void ones_is_uniform(void **state)
{
	size_t n = 800, side = 2 * 64 + 1;
	double *xy = tu_rnd_points(n, 11), *f = malloc(n * sizeof *f);
	double *a = image(64), *b = image(64);
	(void)state;
	for (size_t i = 0; i < n; i++)
		f[i] = 1.0;
	assert_int_equal(dda_add(xy, n, NULL, 12, 64, 1, 1, a), 0);
	assert_int_equal(dda_add(xy, n, f, 12, 64, 1, 1, b), 0);
	assert_memory_equal(a, b, side * side * sizeof *a);
	/* dda_add adds */
	assert_int_equal(dda_add(xy, n, f, 12, 64, 1, 0, b), 0);
	for (size_t p = 0; p < side * side; p++)
		assert_true(b[p] == a[p] + a[p]);
	free(xy), free(f), free(a), free(b);
}

/* A set compressed into [0, 1/2)^2 with f = 2 (4x the importance there)
 * has the same differentials, bit for bit; only E differs (the points
 * whose neighbourhood leaves [0,1)^2 now stays inside [0,2)^2).  The
 * masses, D (c, r) times the divisor of each set, are the same, and sum
 * to the number of ordered pairs within eps. */
static void scale_invariance(void **state)
{
	size_t n = 300;
	uint32_t half = 40;
	size_t side = 2 * (size_t)half + 1;
	double *xy = tu_rnd_points(n, 12), *half_xy = malloc(2 * n * sizeof *xy);
	double *f = malloc(n * sizeof *f), *a = image(half), *b = image(half);
	double ta = 0, tb = 0, pairs;
	int differ = 0;
	(void)state;
	for (size_t i = 0; i < 2 * n; i++)
		half_xy[i] = xy[i] / 2;
	for (size_t i = 0; i < n; i++)
		f[i] = 2;
	pairs = (double)ref_pairs(xy, n, NULL, 12);
	assert_true(pairs == (double)ref_pairs(half_xy, n, f, 12));
	assert_int_equal(dda_add(xy, n, NULL, 12, half, 0.3, 1, a), 0);
	assert_int_equal(dda_add(half_xy, n, f, 12, half, 0.3, 1, b), 0);
	for (size_t r = 0; r < side; r++)
		for (size_t c = 0; c < side; c++) {
			double na = ref_norm(xy, n, NULL, 12, half, c, r);
			double nb = ref_norm(half_xy, n, f, 12, half, c, r);
			double ma = a[r * side + c] * na, mb = b[r * side + c] * nb;
			assert_true(nb >= na);
			differ += nb != na && ma > 0;
			assert_near(ma, mb, 1e-12 * (1 + ma));
			ta += ma, tb += mb;
		}
	assert_true(differ > 100);	/* the edge correction matters */
	assert_near(ta, pairs, 1e-9 * pairs);
	assert_near(tb, pairs, 1e-9 * pairs);
	free(xy), free(half_xy), free(f), free(a), free(b);
}

/* A regular m x m grid: differentials only at the lattice vectors
 * (a, b) / (m r_u); nothing farther than the kernel's reach from them. */
static void lattice(void **state)
{
	uint32_t m = 32, half = DDA_HALF;
	size_t n = (size_t)m * m, side = 2 * (size_t)half + 1;
	double *xy = malloc(2 * n * sizeof *xy), *a = image(half);
	double L = 1.0 / (m * ru_of(n)) * half / DDA_EPS; /* lattice, pixels */
	(void)state;
	for (size_t i = 0; i < n; i++) {
		xy[2 * i] = ((double)(i % m) + 0.5) / m;
		xy[2 * i + 1] = ((double)(i / m) + 0.5) / m;
	}
	assert_true(L > 9 && L < 11);
	for (int pass = 0; pass < 2; pass++) {
		/* taps: |k - u| <= 3 sigma per axis, or the nearest */
		double sigma = pass == 0 ? 0.5 : 1.0;
		double reach = fmax(3 * sigma, 0.5) + 1e-6;
		long zero = 0, nonzero = 0;
		memset(a, 0, side * side * sizeof *a);
		assert_int_equal(dda_add(xy, n, NULL, DDA_EPS, half, sigma, 1, a),
		    0);
		for (size_t r = 0; r < side; r++)
			for (size_t c = 0; c < side; c++) {
				double x = ((double)c - half) / L;
				double y = ((double)r - half) / L;
				double ex = (x - round(x)) * L, ey = (y - round(y)) * L;
				double v = a[r * side + c];
				if (fmax(fabs(ex), fabs(ey)) > reach) {
					if (v != 0)
						fail_msg("pixel (%zu, %zu) is %g, "
						    "far from the lattice", c, r, v);
					zero++;
				} else {
					nonzero += v > 0;
				}
			}
		assert_true(zero > (long)(side * side / 2));
		/* every lattice vector within eps has mass (about pi 12^2
		 * / L^2 * (half/eps)^2 of them) */
		assert_true(nonzero > 1300);
		/* no pair with itself: the centre is empty */
		assert_true(a[half * side + half] == 0);
		/* (1/m, 0): a local maximum */
		{
			size_t c = half + (size_t)lround(L), r = half;
			double v = a[r * side + c], mass = 0;
			for (int dy = -1; dy <= 1; dy++)
				for (int dx = -1; dx <= 1; dx++)
					if (dx || dy)
						assert_true(v > a[(r + dy) * side +
						    c + dx]);
			/* its mass: the m (m - 1) pairs one column apart */
			for (int dy = -5; dy <= 5; dy++)
				for (int dx = -5; dx <= 5; dx++) {
					size_t cc = c + dx, rr = r + dy;
					mass += a[rr * side + cc] * ref_norm(xy, n,
					    NULL, DDA_EPS, half, cc, rr);
				}
			assert_near(mass, m * (m - 1), 1e-6 * m * m);
		}
	}
	free(xy), free(a);
}

static void symmetry(void **state)
{
	size_t n = 700;
	uint32_t half = 100;
	size_t side = 2 * (size_t)half + 1, last = side * side - 1;
	double *xy = tu_rnd_points(n, 13), *f = rnd_scales(n, 14);
	double *a = image(half), *b = image(half);
	long asym = 0;
	(void)state;
	assert_int_equal(dda_add(xy, n, NULL, 12, half, 1, 1, a), 0);
	assert_int_equal(dda_add(xy, n, f, 12, half, 1.7, 1, b), 0);
	for (size_t p = 0; p <= last; p++) {
		assert_true(a[p] == a[last - p]);
		assert_true(b[p] == b[last - p]);
		/* not trivially symmetric: mirrored in x alone it is not */
		asym += a[p] != a[(p / side) * side + side - 1 - p % side];
	}
	assert_true(asym > (long)(side * side / 4));
	free(xy), free(f), free(a), free(b);
}

/* Thread count and point order; more than 2048 points (the pair count
 * pass) and adaptive scales. */
static void threads_order(void **state)
{
	size_t n = 2100;
	uint32_t half = 96;
	size_t side = 2 * (size_t)half + 1;
	double *xy = tu_rnd_points(n, 15), *f = rnd_scales(n, 16);
	double *px = malloc(2 * n * sizeof *px), *pf = malloc(n * sizeof *pf);
	double *a[5];
	(void)state;
	for (size_t i = 0; i < n; i++) {
		size_t j = (i * 1031) % n;	/* 1031 is prime to 2100 */
		px[2 * j] = xy[2 * i], px[2 * j + 1] = xy[2 * i + 1];
		pf[j] = f[i];
	}
	for (int k = 0; k < 5; k++)
		a[k] = image(half);
	frs_set_threads(1);
	assert_int_equal(dda_add(xy, n, f, 12, half, 1, 0, a[0]), 0);
	assert_int_equal(dda_add(xy, n, f, 12, half, 1, 1, a[1]), 0);
	frs_set_threads(2);
	assert_int_equal(dda_add(xy, n, f, 12, half, 1, 1, a[2]), 0);
	frs_set_threads(3);
	assert_int_equal(dda_add(xy, n, f, 12, half, 1, 1, a[3]), 0);
	assert_int_equal(dda_add(px, n, pf, 12, half, 1, 1, a[4]), 0);
	for (int k = 1; k < 4; k++)
		assert_memory_equal(a[0], a[k], side * side * sizeof *a[0]);
	for (size_t p = 0; p < side * side; p++)
		assert_near(a[4][p], a[0][p], 1e-12 * a[0][p]);
	for (int k = 0; k < 5; k++)
		free(a[k]);
	free(xy), free(f), free(px), free(pf);
}

static void bad_input(void **state)
{
	static const struct {
		double v;
		const char *frag;
	} bad_x[] = {
		{ 1.0, "point 1" }, { -0.1, "outside" }, { NAN, "outside" },
	}, bad_f[] = {
		{ 0, "scale of point 2" }, { -1, "positive" },
		{ INFINITY, "positive" },
	};
	double xy[6] = { 0.1, 0.2, 0.3, 0.4, 0.5, 0.6 }, f[3] = { 1, 1, 1 };
	double *a = image(4), *zero = image(4);
	size_t bytes = 9 * 9 * sizeof *a;
	(void)state;
#define BAD(call, frag) do { \
		frs_clearerr(); \
		assert_int_equal(call, -1); \
		assert_err_has("dda", frag); \
		assert_memory_equal(a, zero, bytes); \
	} while (0)
	BAD(dda_add(xy, 0, NULL, 12, 4, 1, 0, a), "at least 2");
	BAD(dda_add(xy, 1, NULL, 12, 4, 1, 0, a), "at least 2");
	BAD(dda_add(xy, 3, NULL, 0, 4, 1, 0, a), "eps");
	BAD(dda_add(xy, 3, NULL, -1, 4, 1, 0, a), "eps");
	BAD(dda_add(xy, 3, NULL, NAN, 4, 1, 0, a), "eps");
	BAD(dda_add(xy, 3, NULL, INFINITY, 4, 1, 0, a), "eps");
	BAD(dda_add(xy, 3, NULL, 12, 0, 1, 0, a), "half");
	BAD(dda_add(xy, 3, NULL, 12, DDA_MAX_HALF + 1, 1, 0, a), "half");
	BAD(dda_add(xy, 3, NULL, 12, 4, -1, 0, a), "sigma");
	BAD(dda_add(xy, 3, NULL, 12, 4, NAN, 0, a), "sigma");
	BAD(dda_add(NULL, 3, NULL, 12, 4, 1, 0, a), "no points");
	BAD(dda_add(xy, 3, NULL, 12, 4, 1, 0, NULL), "no image");
	/* a bad coordinate of point 1, then a bad scale of point 2 */
	for (size_t i = 0; i < sizeof bad_x / sizeof *bad_x; i++) {
		xy[2] = bad_x[i].v;
		BAD(dda_add(xy, 3, NULL, 12, 4, 1, 0, a), bad_x[i].frag);
	}
	xy[2] = 0.3;
	for (size_t i = 0; i < sizeof bad_f / sizeof *bad_f; i++) {
		f[2] = bad_f[i].v;
		BAD(dda_add(xy, 3, f, 12, 4, 1, 0, a), bad_f[i].frag);
	}
	f[2] = 1;
	/* the smallest valid cases */
	assert_int_equal(dda_add(xy, 2, NULL, 12, 1, 0, 0, a), 0);
	assert_int_equal(dda_add(xy, 3, f, 1e-3, 4, 0, 1, a), 0);
	/* all points equal: every pair at d = 0 */
	{
		double same[8] = { 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5 };
		double *c = image(4);
		assert_int_equal(dda_add(same, 4, NULL, 12, 4, 0, 1, c), 0);
		for (size_t p = 0; p < 81; p++)
			assert_true(p == 40 ? c[p] > 0 : c[p] == 0);
		free(c);
	}
#undef BAD
	free(a), free(zero);
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(uniform_poisson),
	cmocka_unit_test(brute_force),
	cmocka_unit_test(ones_is_uniform),
	cmocka_unit_test(scale_invariance),
	cmocka_unit_test(lattice),
	cmocka_unit_test(symmetry),
	cmocka_unit_test(threads_order),
	cmocka_unit_test(bad_input))
