/* The FFT against the naive O(n^2) DFT, in one, two and three dimensions:
 * forward, inverse round trip, Parseval, and sizes that are not powers of
 * two refused. */
#include "testutil.h"
#include "cli/fft.h"


/* n complex values from (seed, FRS_STREAM_TEST), in [-1, 1). */
static double *rnd_complex(size_t n, uint64_t seed)
{
	double *x = malloc(2 * n * sizeof *x);

	assert_non_null(x);
	for (size_t i = 0; i < 2 * n; i++)
		x[i] = 2.0 * frs_rand01(seed, FRS_STREAM_TEST, i) - 1.0;
	return x;
}

/* The definition: X_k = sum_j x_j exp(sign 2 pi i j k / n), the angle
 * reduced modulo n in integers so that it stays exact. */
static void dft_naive(const double *x, double *y, size_t n, int sign)
{
	for (size_t k = 0; k < n; k++) {
		long double re = 0.0L, im = 0.0L;
		for (size_t j = 0; j < n; j++) {
			double a = sign * 2.0 * PI * (double)(j * k % n) / (double)n;
			re += x[2 * j] * cos(a) - x[2 * j + 1] * sin(a);
			im += x[2 * j] * sin(a) + x[2 * j + 1] * cos(a);
		}
		y[2 * k] = (double)re;
		y[2 * k + 1] = (double)im;
	}
}

static double max_abs_diff(const double *a, const double *b, size_t n)
{
	double d = 0.0;

	for (size_t i = 0; i < 2 * n; i++)
		d = fmax(d, fabs(a[i] - b[i]));
	return d;
}

static double energy(const double *x, size_t n)
{
	double e = 0.0;

	for (size_t i = 0; i < 2 * n; i++)
		e += x[i] * x[i];
	return e;
}

/* Every power of two to 1024, both signs: the DFT's values to a few ulps
 * of its magnitude (sqrt(n) for unit inputs). */
static void fft1_is_dft(void **state)
{
	(void)state;
	for (size_t n = 1; n <= 1024; n *= 2)
		for (int sign = -1; sign <= 1; sign += 2) {
			double *x = rnd_complex(n, n), *y = malloc(2 * n * sizeof *y);
			double *ref = malloc(2 * n * sizeof *ref);
			assert_true(y && ref);
			memcpy(y, x, 2 * n * sizeof *y);
			dft_naive(x, ref, n, sign);
			assert_int_equal(fft1(y, n, 1, sign), 0);
			if (max_abs_diff(y, ref, n) > 1e-13 * (double)n)
				print_error("n %zu sign %d: off by %g\n", n, sign,
				    max_abs_diff(y, ref, n));
			assert_true(max_abs_diff(y, ref, n) <= 1e-13 * (double)n);
			free(x);
			free(y);
			free(ref);
		}
}

/* Closed forms: an impulse at 0 gives all ones, a pure frequency f gives
 * n at f alone. */
static void fft1_closed_forms(void **state)
{
	size_t n = 64, f = 5;
	double x[128] = { 0 };

	(void)state;
	x[0] = 1.0;
	assert_int_equal(fft1(x, n, 1, -1), 0);
	for (size_t k = 0; k < n; k++) {
		assert_near(x[2 * k], 1.0, 1e-15);
		assert_near(x[2 * k + 1], 0.0, 1e-15);
	}
	for (size_t j = 0; j < n; j++) {
		x[2 * j] = cos(2.0 * PI * (double)(f * j) / (double)n);
		x[2 * j + 1] = sin(2.0 * PI * (double)(f * j) / (double)n);
	}
	assert_int_equal(fft1(x, n, 1, -1), 0);
	for (size_t k = 0; k < n; k++) {
		assert_near(x[2 * k], k == f ? (double)n : 0.0, 1e-12);
		assert_near(x[2 * k + 1], 0.0, 1e-12);
	}
}

/* Forward then inverse is n times the input; the energy of the
 * transform is n times the input's (Parseval). */
static void fft1_round_trip_parseval(void **state)
{
	(void)state;
	for (size_t n = 2; n <= 4096; n *= 4) {
		double *x = rnd_complex(n, 100 + n), *y = malloc(2 * n * sizeof *y);
		assert_non_null(y);
		memcpy(y, x, 2 * n * sizeof *y);
		assert_int_equal(fft1(y, n, 1, -1), 0);
		assert_near(energy(y, n) / (double)n, energy(x, n),
		    1e-12 * energy(x, n));
		assert_int_equal(fft1(y, n, 1, 1), 0);
		for (size_t i = 0; i < 2 * n; i++)
			y[i] /= (double)n;
		assert_true(max_abs_diff(x, y, n) < 1e-14 * log2((double)n) + 1e-15);
		free(x);
		free(y);
	}
}

/* A stride transforms every stride-th value and leaves the rest alone. */
static void fft1_stride(void **state)
{
	size_t n = 32, st = 3;
	double *x = rnd_complex(n * st, 7), *y = malloc(2 * n * st * sizeof *y);
	double col[64], ref[64];

	(void)state;
	assert_non_null(y);
	memcpy(y, x, 2 * n * st * sizeof *y);
	assert_int_equal(fft1(y, n, st, -1), 0);
	for (size_t j = 0; j < n; j++) {
		col[2 * j] = x[2 * j * st];
		col[2 * j + 1] = x[2 * j * st + 1];
	}
	dft_naive(col, ref, n, -1);
	for (size_t j = 0; j < n * st; j++)
		if (j % st == 0) {
			assert_near(y[2 * j], ref[2 * (j / st)], 1e-12);
			assert_near(y[2 * j + 1], ref[2 * (j / st) + 1], 1e-12);
		} else {
			assert_true(y[2 * j] == x[2 * j]);
			assert_true(y[2 * j + 1] == x[2 * j + 1]);
		}
	free(x);
	free(y);
}

/* The 2-D and 3-D transforms against the separable definition written
 * out: X(u, v, t) = sum x(a, b, c) exp(-2 pi i (ua/w + vb/h + tc/d)). */
static void fft3_is_dft(void **state)
{
	static const size_t sz[][3] = { { 8, 4, 1 }, { 2, 16, 1 }, { 4, 2, 8 },
	    { 2, 4, 2 }, { 1, 1, 4 } };

	(void)state;
	for (size_t s = 0; s < sizeof sz / sizeof sz[0]; s++) {
		size_t w = sz[s][0], h = sz[s][1], d = sz[s][2], n = w * h * d;
		double *x = rnd_complex(n, 40 + s), *y = malloc(2 * n * sizeof *y);
		assert_non_null(y);
		memcpy(y, x, 2 * n * sizeof *y);
		if (d == 1)
			assert_int_equal(fft2(y, w, h, -1), 0);
		else
			assert_int_equal(fft3(y, w, h, d, -1), 0);
		for (size_t t = 0; t < d; t++)
			for (size_t v = 0; v < h; v++)
				for (size_t u = 0; u < w; u++) {
					double re = 0.0, im = 0.0;
					for (size_t i = 0; i < n; i++) {
						size_t a = i % w, b = i / w % h, c = i / w / h;
						double ang = -2.0 * PI * ((double)(u * a % w) /
						    (double)w + (double)(v * b % h) / (double)h +
						    (double)(t * c % d) / (double)d);
						re += x[2 * i] * cos(ang) - x[2 * i + 1] * sin(ang);
						im += x[2 * i] * sin(ang) + x[2 * i + 1] * cos(ang);
					}
					size_t k = (t * h + v) * w + u;
					assert_near(y[2 * k], re, 1e-12);
					assert_near(y[2 * k + 1], im, 1e-12);
				}
		assert_near(energy(y, n) / (double)n, energy(x, n), 1e-12 * (double)n);
		free(x);
		free(y);
	}
}

/* Only powers of two: the others are refused with the size named, and
 * the data left as it was. */
static void non_powers_refused(void **state)
{
	static const size_t bad[] = { 0, 3, 6, 12, 1000 };
	double x[2 * 1000] = { 0 };

	(void)state;
	x[3] = 1.5;
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		char want[32];
		assert_false(fft_is_pow2(bad[i]));
		assert_int_equal(fft1(x, bad[i], 1, -1), -1);
		snprintf(want, sizeof want, "%zu", bad[i]);
		assert_err_has("not a power of two", want);
	}
	assert_true(x[3] == 1.5);
	for (size_t n = 1; n < ((size_t)1 << 40); n *= 2) {
		assert_true(fft_is_pow2(n));
		assert_false(fft_is_pow2(3 * n));
		assert_true(n == 1 || !fft_is_pow2(n + 1));
	}
	assert_int_equal(fft2(x, 8, 6, -1), -1);
	assert_err_has("8x6");
	assert_int_equal(fft3(x, 4, 4, 3, -1), -1);
	assert_err_has("4x4x3");
	assert_int_equal(fft3(x, 5, 4, 2, -1), -1);
	assert_true(x[3] == 1.5);
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(fft1_is_dft),
	cmocka_unit_test(fft1_closed_forms),
	cmocka_unit_test(fft1_round_trip_parseval),
	cmocka_unit_test(fft1_stride),
	cmocka_unit_test(fft3_is_dft),
	cmocka_unit_test(non_powers_refused))
