/* Fourier spectra against analytic oracles: regular grids (P = n on the
 * reciprocal lattice, 0 elsewhere), a naive complex-exponential sum, the
 * expectation E P(k) = 1 and the -10 dB anisotropy of 10 uniform random
 * sets, hand-computed radial statistics, and the PNG scale. */
#include "testutil.h"
#include <complex.h>
#include "maps/imap.h"
#include "maps/mapload.h"
#include "base/par.h"
#include "base/rng.h"
#include "dda/spectrum.h"


/* m x m cells, one point per cell: at the centre (jit 0) or uniform in
 * the cell (jit 1). */
static double *grid_points(size_t m, int jit, uint64_t seed)
{
	double *xy = malloc(2 * m * m * sizeof *xy);
	assert_non_null(xy);
	for (size_t j = 0; j < m; j++)
		for (size_t i = 0; i < m; i++) {
			size_t p = j * m + i;
			double u = jit ? frs_rand01(seed, FRS_STREAM_TEST, 2 * p) :
			    0.5;
			double v = jit ? frs_rand01(seed, FRS_STREAM_TEST,
			    2 * p + 1) : 0.5;
			xy[2 * p] = (i + u) / m;
			xy[2 * p + 1] = (j + v) / m;
		}
	return xy;
}

static void img(struct spec_img *im, uint32_t half)
{
	if (spec_img_alloc(im, half, 1.0) != 0)
		print_error("%s\n", frs_errmsg());
	assert_non_null(im->v);
}

static void run_exact(const double *xy, size_t n, struct spec_img *im)
{
	int rc = spec_fourier_exact(xy, n, 1, im);
	if (rc != 0)
		print_error("%s\n", frs_errmsg());
	assert_int_equal(rc, 0);
}

static void run_approx(const double *xy, size_t n, struct spec_img *im)
{
	int rc = spec_fourier_approx(xy, n, 1, im);
	if (rc != 0)
		print_error("%s\n", frs_errmsg());
	assert_int_equal(rc, 0);
}

static size_t side_of(const struct spec_img *im)
{
	return 2 * (size_t)im->half + 1;
}

/* P at frequency (kx, ky). */
static double at(const struct spec_img *im, long kx, long ky)
{
	size_t side = side_of(im);
	return im->v[(size_t)(ky + (long)im->half) * side +
	    (size_t)(kx + (long)im->half)];
}

/* max_k | |F_a(k)| - |F_e(k)| | / n, |F| = sqrt(n P). */
static double amp_err(const struct spec_img *a, const struct spec_img *e,
    size_t n)
{
	double m = 0.0;
	for (size_t i = 0; i < side_of(a) * side_of(a); i++) {
		double d = fabs(sqrt(n * a->v[i]) - sqrt(n * e->v[i])) / n;
		if (!(d <= m))
			m = d;
	}
	return m;
}

/* ---- regular grids: P = n on multiples of m, 0 elsewhere ---------- */

static void regular_grid(void **state)
{
	const size_t ms[] = { 8, 16 };
	(void)state;
	frs_set_threads(2);
	for (int t = 0; t < 2; t++) {
		size_t m = ms[t], n = m * m;
		double *xy = grid_points(m, 0, 0);
		struct spec_img e, a;
		long K = 40;
		img(&e, (uint32_t)K);
		img(&a, (uint32_t)K);
		run_exact(xy, n, &e);
		run_approx(xy, n, &a);
		for (long ky = -K; ky <= K; ky++)
			for (long kx = -K; kx <= K; kx++) {
				int on = kx % (long)m == 0 && ky % (long)m == 0;
				double want = on ? (double)n : 0.0;
				double fa = sqrt(n * at(&a, kx, ky));
				assert_near(at(&e, kx, ky), want, 1e-9 * n);
				assert_near(fa, sqrt(n * want),
				    SPEC_NUFFT_ERR * n);
			}
		spec_img_free(&e);
		spec_img_free(&a);
		free(xy);
	}
}

/* The approximation's worst cases: grids whose aliases add coherently
 * (a single point is one), at K = N / 4. */
static void regular_grid_approx_worst(void **state)
{
	const size_t ms[] = { 16, 1, 16 };
	const double off[] = { 0.5, 0.3, 0.123456 };
	const uint32_t Ks[] = { 128, 16, 16 };
	(void)state;
	frs_set_threads(2);
	for (int t = 0; t < 3; t++) {
		size_t m = ms[t], n = m * m;
		double *xy = malloc(2 * n * sizeof *xy);
		struct spec_img e, a;
		double err;
		assert_non_null(xy);
		for (size_t i = 0; i < n; i++) {
			xy[2 * i] = (i % m + off[t]) / m;
			xy[2 * i + 1] = (i / m + off[t]) / m;
		}
		img(&e, Ks[t]);
		img(&a, Ks[t]);
		run_exact(xy, n, &e);
		run_approx(xy, n, &a);
		err = amp_err(&a, &e, n);
		if (!(err <= SPEC_NUFFT_ERR))
			print_error("case %d: amplitude error %g\n", t, err);
		assert_true(err <= SPEC_NUFFT_ERR);
		spec_img_free(&e);
		spec_img_free(&a);
		free(xy);
	}
}

/* ---- exact against a naive sum --------------------------------------- */

static void naive(const double *xy, size_t n, long K, double *out)
{
	size_t side = 2 * (size_t)K + 1;
	for (long ky = -K; ky <= K; ky++)
		for (long kx = -K; kx <= K; kx++) {
			double complex f = 0.0;
			for (size_t j = 0; j < n; j++)
				f += cexp(-2.0 * PI * I * ((double)kx * xy[2 * j] +
				    (double)ky * xy[2 * j + 1]));
			out[(size_t)(ky + K) * side + (size_t)(kx + K)] =
			    (creal(f) * creal(f) + cimag(f) * cimag(f)) / n;
		}
}

static void exact_naive(void **state)
{
	const size_t ns[] = { 1, 37, 300, 2500 };
	const long Ks[] = { 3, 20, 17, 6 };
	(void)state;
	frs_set_threads(2);
	for (int t = 0; t < 4; t++) {
		size_t n = ns[t], side = 2 * (size_t)Ks[t] + 1;
		double *xy = tu_rnd_points(n, 100 + (uint64_t)t);
		double *ref = malloc(side * side * sizeof *ref);
		struct spec_img e;
		assert_non_null(ref);
		if (t == 2)	/* outside the unit square: only frac counts */
			for (size_t i = 0; i < 2 * n; i++)
				xy[i] = 5.0 * xy[i] - 2.0;
		naive(xy, n, Ks[t], ref);
		img(&e, (uint32_t)Ks[t]);
		run_exact(xy, n, &e);
		for (size_t i = 0; i < side * side; i++)
			assert_near(e.v[i], ref[i], 1e-9 * fmax(ref[i], 1.0));
		assert_near(e.v[(side * side) / 2], (double)n, 1e-12 * n);
		spec_img_free(&e);
		free(ref);
		free(xy);
	}
}

/* ---- approximate against exact -------------------------------------- */

static void approx_vs_exact(void **state)
{
	(void)state;
	frs_set_threads(2);
	for (int t = 0; t < 4; t++) {
		/* random and jittered, 1024 points, K = 128; then small K */
		uint32_t K = t < 2 ? 128 : t == 2 ? 5 : 77;
		double *xy = t % 2 ? grid_points(32, 1, 7) : tu_rnd_points(1024,
		    (uint64_t)t);
		struct spec_img e, a;
		double err;
		img(&e, K);
		img(&a, K);
		run_exact(xy, 1024, &e);
		run_approx(xy, 1024, &a);
		err = amp_err(&a, &e, 1024);
		if (!(err <= SPEC_NUFFT_ERR))
			print_error("set %d: amplitude error %g\n", t, err);
		assert_true(err <= SPEC_NUFFT_ERR);
		/* and P itself, by the stated consequence */
		for (size_t i = 0; i < side_of(&e) * side_of(&e); i++)
			assert_true(fabs(a.v[i] - e.v[i]) <= 2 * SPEC_NUFFT_ERR *
			    sqrt(1024 * e.v[i]) + SPEC_NUFFT_ERR *
			    SPEC_NUFFT_ERR * 1024 + 1e-12);
		spec_img_free(&e);
		spec_img_free(&a);
		free(xy);
	}
}

/* ---- uniform random sets: E P = 1, anisotropy -10 dB ---------------- */

static void uniform_stats(void **state)
{
	const size_t n = 1024, sets = 10;
	const uint32_t K = 128;
	struct spec_img e;
	struct spec_radial r;
	double sum = 0.0, an = 0.0;
	size_t side = 2 * (size_t)K + 1, cnt = 0, nan = 0;
	(void)state;
	frs_set_threads(2);
	img(&e, K);
	for (size_t s = 0; s < sets; s++) {
		double *xy = tu_rnd_points(n, 1000 + s);
		run_exact(xy, n, &e);
		free(xy);
	}
	for (size_t i = 0; i < side * side; i++)
		e.v[i] /= (double)sets;
	assert_near(at(&e, 0, 0), (double)n, 1e-9 * n);
	for (size_t i = 0; i < side * side; i++)
		if (i != side * side / 2) {
			sum += e.v[i];
			cnt++;
		}
	/* P(k) = P(-k); otherwise uncorrelated with variance (n-1)/n per
	 * set: standard error 1 / sqrt(sets * cnt / 2) = 0.0017 */
	assert_near(sum / (double)cnt, 1.0, 5.0 / sqrt(sets * cnt / 2.0));

	assert_int_equal(spec_radial(&e, 2.0, &r), 0);
	assert_int_equal(r.nbins, 64);
	/* annulus 0: DC (n) and its 8 neighbours */
	assert_int_equal(r.count[0], 9);
	assert_true(r.mean[0] > n / 9.0 && r.mean[0] < n / 9.0 + 3.0);
	for (size_t i = 1; i < r.nbins; i++) {
		/* the mean of count/2 independent Gamma(10, 1/10) values */
		double se = sqrt(0.1 / (r.count[i] / 2.0));
		assert_true(r.count[i] > 0);
		assert_near(r.lo[i], 2.0 * i, 0.0);
		assert_near(r.mean[i], 1.0, 5.0 * se);
		an += r.aniso[i];
		nan += isnan(r.aniso[i]) || isnan(r.mean[i]);
	}
	an /= (double)(r.nbins - 1);
	assert_int_equal(nan, 0);
	assert_near(an, -10.0, 1.0);
	/* tighter: the estimate's own noise is ~0.15 dB */
	assert_near(an, -10.0, 0.5);
	spec_radial_free(&r);
	spec_img_free(&e);
}

/* ---- radial binning against hand-computed images ------------------- */

static void radial_hand(void **state)
{
	struct spec_img im;
	struct spec_radial r;
	(void)state;

	/* half 2, bin 1: annulus 0 is DC alone (1 pixel: no statistics),
	 * annulus 1 the 4 axis neighbours (1) and 4 diagonals (3): mean 2,
	 * unbiased variance 8/7; (+-2, 0) lie in annulus 2, not reported */
	assert_int_equal(spec_img_alloc(&im, 2, 1.0), 0);
	for (int i = 0; i < 25; i++)
		im.v[i] = 100.0;
	im.v[12] = 50.0;
	im.v[7] = im.v[11] = im.v[13] = im.v[17] = 1.0;
	im.v[6] = im.v[8] = im.v[16] = im.v[18] = 3.0;
	assert_int_equal(spec_radial(&im, 1.0, &r), 0);
	assert_int_equal(r.nbins, 2);
	assert_int_equal(r.count[0], 0);
	assert_true(r.mean[0] == 0.0 && r.aniso[0] == 0.0);
	assert_int_equal(r.count[1], 8);
	assert_near(r.lo[1], 1.0, 0.0);
	assert_near(r.mean[1], 2.0, 1e-15);
	assert_near(r.aniso[1], 10.0 * log10(8.0 / 7.0 / 4.0), 1e-12);
	spec_radial_free(&r);
	spec_img_free(&im);

	/* half 6, bin 3 (not 2): v = r^2 = dx^2 + dy^2.  Annulus 0: r^2 < 9,
	 * r^2 in {0, 1, 2, 4, 5, 8} with 1, 4, 4, 4, 8, 4 pixels (25), sum
	 * 100, mean 4, squared deviations 140; (+-3, 0) at exactly 3 go to
	 * annulus 1: 9 <= r^2 < 36, 109 - 25 = 84 pixels. */
	assert_int_equal(spec_img_alloc(&im, 6, 1.0), 0);
	for (int y = -6; y <= 6; y++)
		for (int x = -6; x <= 6; x++)
			im.v[(y + 6) * 13 + x + 6] = x * x + y * y;
	assert_int_equal(spec_radial(&im, 3.0, &r), 0);
	assert_int_equal(r.nbins, 2);
	assert_int_equal(r.count[0], 25);
	assert_near(r.mean[0], 4.0, 1e-15);
	assert_near(r.aniso[0], 10.0 * log10(140.0 / 24.0 / 16.0), 1e-12);
	assert_int_equal(r.count[1], 84);
	assert_near(r.lo[1], 3.0, 0.0);
	spec_radial_free(&r);
	/* DC only in annulus 0 */
	im.v[6 * 13 + 6] = 1000.0;
	assert_int_equal(spec_radial(&im, 3.0, &r), 0);
	assert_near(r.mean[0], 44.0, 1e-13);
	assert_int_equal(r.count[1], 84);
	spec_radial_free(&r);
	spec_img_free(&im);

	/* scale 0.5, bin 0.75: radius 2, annuli [0, 0.75) and [0.75, 1.5):
	 * r^2 < 2.25 (9 pixels) and 2.25 <= r^2 < 9 (r^2 = 4, 5, 8: 16) */
	assert_int_equal(spec_img_alloc(&im, 4, 0.5), 0);
	for (int i = 0; i < 81; i++)
		im.v[i] = 2.0;
	assert_int_equal(spec_radial(&im, 0.75, &r), 0);
	assert_int_equal(r.nbins, 2);
	assert_int_equal(r.count[0], 9);
	assert_int_equal(r.count[1], 16);
	assert_near(r.lo[1], 0.75, 0.0);
	assert_near(r.mean[1], 2.0, 0.0);
	assert_true(r.aniso[1] == -INFINITY);	/* constant annulus */
	spec_radial_free(&r);
	/* zero mean: no statistics, no NaN */
	memset(im.v, 0, 81 * sizeof *im.v);
	assert_int_equal(spec_radial(&im, 0.75, &r), 0);
	for (size_t i = 0; i < r.nbins; i++)
		assert_true(r.count[i] == 0 && r.mean[i] == 0.0 &&
		    r.aniso[i] == 0.0);
	spec_radial_free(&r);
	/* bad widths */
	assert_int_equal(spec_radial(&im, 0.0, &r), -1);
	assert_err_has("annulus width");
	assert_int_equal(spec_radial(&im, NAN, &r), -1);
	assert_int_equal(spec_radial(&im, 2.5, &r), -1);
	assert_err_has("radius");
	assert_true(r.nbins == 0 && r.mean == NULL);
	im.v[3] = NAN;
	assert_int_equal(spec_radial(&im, 1.0, &r), -1);
	assert_err_has("not finite");
	spec_img_free(&im);
}

/* ---- determinism and invariance ------------------------------------- */

static void threads_and_order(void **state)
{
	/* 3000 points: more than one block of the exact product */
	const size_t n = 3000;
	const uint32_t K = 50;
	double *xy = tu_rnd_points(n, 55), *rev = malloc(2 * n * sizeof *rev);
	size_t side = 2 * (size_t)K + 1, bytes = side * side * sizeof(double);
	(void)state;
	assert_non_null(rev);
	for (size_t i = 0; i < n; i++) {
		rev[2 * i] = xy[2 * (n - 1 - i)];
		rev[2 * i + 1] = xy[2 * (n - 1 - i) + 1];
	}
	for (int m = 0; m < 2; m++) {
		int (*f)(const double *, size_t, int, struct spec_img *) =
		    m ? spec_fourier_approx : spec_fourier_exact;
		struct spec_img a, b, c, d;
		img(&a, K);
		img(&b, K);
		img(&c, K);
		img(&d, K);
		frs_set_threads(1);
		assert_int_equal(f(xy, n, 1, &a), 0);
		frs_set_threads(2);
		assert_int_equal(f(xy, n, 1, &b), 0);
		assert_int_equal(f(xy, n, 0, &c), 0);
		frs_set_threads(3);
		assert_int_equal(f(rev, n, 1, &d), 0);
		assert_memory_equal(a.v, b.v, bytes);
		assert_memory_equal(a.v, c.v, bytes);
		for (size_t i = 0; i < side * side; i++) {
			assert_near(d.v[i], a.v[i], 1e-12 * fmax(a.v[i], 1.0));
			/* exact: P(-k) = P(k) bit for bit */
			if (m == 0)
				assert_true(a.v[i] == a.v[side * side - 1 - i]);
			else
				assert_near(a.v[i], a.v[side * side - 1 - i],
				    1e-12 * fmax(a.v[i], 1.0));
		}
		/* a second set adds */
		assert_int_equal(f(xy, n, 1, &b), 0);
		for (size_t i = 0; i < side * side; i++)
			assert_true(b.v[i] == 2.0 * a.v[i]);
		spec_img_free(&a);
		spec_img_free(&b);
		spec_img_free(&c);
		spec_img_free(&d);
	}
	frs_set_threads(1);
	free(rev);
	free(xy);
}

/* P does not change when the points move by whole grid cells of the
 * approximation (N = 512 at K = 128, spectrum.h): the spread grid only
 * shifts, so any point lost or weighted wrongly at a chunk's edge shows.
 * Nor, for the exact sum, when they move by anything. */
static void translation(void **state)
{
	const size_t n = 1024;
	const uint32_t K = 128;
	double *xy = tu_rnd_points(n, 77), *sh = malloc(2 * n * sizeof *sh);
	size_t side = 2 * (size_t)K + 1;
	(void)state;
	assert_non_null(sh);
	frs_set_threads(2);
	for (int m = 0; m < 2; m++) {
		int (*f)(const double *, size_t, int, struct spec_img *) =
		    m ? spec_fourier_approx : spec_fourier_exact;
		double dx = m ? 5.0 / 512 : 0.3141, dy = m ? 3.0 / 512 : 0.2718;
		struct spec_img a, b;
		for (size_t i = 0; i < n; i++) {
			sh[2 * i] = xy[2 * i] + dx;
			sh[2 * i + 1] = xy[2 * i + 1] - dy;
		}
		img(&a, K);
		img(&b, K);
		assert_int_equal(f(xy, n, 1, &a), 0);
		assert_int_equal(f(sh, n, 1, &b), 0);
		for (size_t i = 0; i < side * side; i++)
			assert_near(b.v[i], a.v[i], 1e-12 * fmax(a.v[i], 1.0));
		spec_img_free(&a);
		spec_img_free(&b);
	}
	free(sh);
	free(xy);
}

/* ---- errors ---------------------------------------------------------- */

static void errors(void **state)
{
	struct spec_img im, s2;
	double xy[4] = { 0.1, 0.2, 0.3, 0.4 };
	(void)state;
	img(&im, 4);
	assert_int_equal(spec_fourier_exact(xy, 0, 1, &im), -1);
	assert_err_has("no points");
	assert_int_equal(spec_fourier_approx(NULL, 2, 1, &im), -1);
	assert_err_has("no points");
	xy[3] = NAN;
	assert_int_equal(spec_fourier_exact(xy, 2, 1, &im), -1);
	assert_err_has("point 1", "not finite");
	xy[3] = INFINITY;
	assert_int_equal(spec_fourier_approx(xy, 2, 1, &im), -1);
	assert_err_has("point 1", "not finite");
	xy[3] = 0.4;
	assert_int_equal(spec_img_alloc(&s2, 4, 0.5), 0);
	assert_int_equal(spec_fourier_exact(xy, 2, 1, &s2), -1);
	assert_err_has("scale");
	spec_img_free(&s2);
	assert_int_equal(spec_img_alloc(&s2, SPEC_MAX_HALF + 1, 1.0), -1);
	assert_null(s2.v);
	assert_int_equal(spec_img_alloc(&s2, 3, 0.0), -1);
	assert_null(s2.v);
	/* K = 0: DC alone */
	spec_img_free(&im);
	img(&im, 0);
	assert_int_equal(spec_fourier_exact(xy, 2, 1, &im), 0);
	assert_near(im.v[0], 2.0, 1e-15);
	assert_int_equal(spec_fourier_approx(xy, 2, 1, &im), 0);
	assert_near(im.v[0], 4.0, 1e-9);
	spec_img_free(&im);
}

/* ---- PNG ------------------------------------------------------------- */

static void png(void **state)
{
	const char *path = tu_path("spec.png");
	struct spec_img im;
	struct frs_imap m;
	FILE *fp;
	/* values and their grey levels at -10..+10 dB */
	const double v[] = { 1e6, 1.0, 0.1, 0.0, sqrt(10.0), -1.0, 0.01,
	    10.0, NAN };
	const int grey[] = { 255, 128, 0, 0, 191, 0, 0, 255, 0 };
	(void)state;

	assert_int_equal(spec_img_alloc(&im, 1, 1.0), 0);
	memcpy(im.v, v, sizeof v);
	fp = fopen(path, "wb");
	assert_non_null(fp);
	assert_int_equal(spec_write_png(fp, path, &im, -10.0, 10.0), 0);
	assert_int_equal(fclose(fp), 0);
	assert_int_equal(imap_load_raw(path, 0, 0, 0, &m), 0);
	assert_int_equal(m.w, 3);
	assert_int_equal(m.h, 3);
	for (int i = 0; i < 9; i++)
		assert_int_equal((int)lround(m.v[i] * 255.0), grey[i]);
	imap_free(&m);
	spec_img_free(&im);

	/* a spectrum: DC, the brightest, is the centre pixel */
	{
		double *xy = tu_rnd_points(256, 3);
		uint32_t K = 20;
		size_t side = 2 * K + 1;
		img(&im, K);
		run_exact(xy, 256, &im);
		fp = fopen(path, "wb");
		assert_non_null(fp);
		assert_int_equal(spec_write_png(fp, path, &im, -10.0, 10.0),
		    0);
		assert_int_equal(fclose(fp), 0);
		assert_int_equal(imap_load_raw(path, 0, 0, 0, &m), 0);
		assert_int_equal(m.w, side);
		assert_int_equal(m.h, side);
		assert_true(m.v[K * side + K] == 1.0);
		/* P(k) < 10 away from DC for this set: not white */
		for (size_t i = 0; i < side * side; i++)
			if (i != K * side + K)
				assert_true(im.v[i] >= 9.9 || m.v[i] < 1.0);
		imap_free(&m);
		spec_img_free(&im);
		free(xy);
	}
	/* the scale must increase */
	img(&im, 1);
	fp = fopen(path, "wb");
	assert_non_null(fp);
	assert_int_equal(spec_write_png(fp, path, &im, 5.0, 5.0), -1);
	assert_err_has("colour scale");
	fclose(fp);
	spec_img_free(&im);
}

TU_MAIN(NULL, tu_teardown,
	cmocka_unit_test(regular_grid),
	cmocka_unit_test(regular_grid_approx_worst),
	cmocka_unit_test(exact_naive),
	cmocka_unit_test(approx_vs_exact),
	cmocka_unit_test(uniform_stats),
	cmocka_unit_test(radial_hand),
	cmocka_unit_test(threads_and_order),
	cmocka_unit_test(translation),
	cmocka_unit_test(errors),
	cmocka_unit_test(png))
