/* 3-D reference samplers (ref-sample -d 3) against closed forms and
 * independent checks: the count and range of every kind, the exact cubic
 * grid, one jittered point per cell, classical Halton/Hammersley radical
 * inverses, Joe and Kuo's published Sobol' points, the (1,m,3)-net
 * property of (scrambled) Sobol', the Poisson-disk distance by brute
 * force and the uniformity of random points. */
#include "refsamputil.h"
#include "cli/refsamp.h"
#include "base/num.h"
#include "base/rng.h"

static double *gen3(enum refsamp_kind k, uint64_t n, uint64_t seed,
    uint64_t maxf, uint64_t *placed)
{
	double *p = malloc(3 * refsamp_count_dims(k, n, 3) * sizeof *p);
	assert_non_null(p);
	assert_int_equal(refsamp_gen_dims(k, 3, n, seed, maxf, p, placed), 0);
	return p;
}

static void in_cube(const double *p, uint64_t m)
{
	for (uint64_t i = 0; i < 3 * m; i++)
		assert_true(p[i] >= 0.0 && p[i] < 1.0);
}

/* Radical inverse written independently of the library: the digits of i
 * as a fraction num / b^m, one rounding. */
static double radinv(uint64_t i, uint64_t b)
{
	uint64_t num = 0, den = 1;
	for (; i > 0; i /= b) {
		num = num * b + i % b;
		den *= b;
	}
	return (double)num / (double)den;
}

/* v is radinv(i, b) up to the roundings of num_radical_inverse (num.h):
 * (digits + 2) ulps of 1; exact in base 2. */
static int radinv_near(double v, uint64_t i, uint64_t b)
{
	unsigned m = 0;

	for (uint64_t j = i; j > 0; j /= b)
		m++;
	return b == 2 ? v == radinv(i, b) :
	    fabs(v - radinv(i, b)) <= (m + 2) * 0x1p-53;
}

static void count_and_range(void **state)
{
	static const uint64_t ns[] = { 1, 2, 7, 100, 1000 };
	(void)state;
	for (int k = REFSAMP_RANDOM; k <= REFSAMP_DART; k++)
		for (unsigned t = 0; t < sizeof ns / sizeof ns[0]; t++)
			for (uint64_t seed = 0; seed < 2; seed++) {
				enum refsamp_kind kind = (enum refsamp_kind)k;
				uint64_t m, want = refsamp_count_dims(kind, ns[t], 3);
				double *p = gen3(kind, ns[t], seed,
				    REFSAMP_DART_FAILURES, &m);
				if (kind == REFSAMP_REGULAR ||
				    kind == REFSAMP_JITTERED) {
					uint64_t s = refsamp_cube_side(ns[t]);
					assert_int_equal(want, s * s * s);
				} else
					assert_int_equal(want, ns[t]);
				assert_int_equal(m, want);
				in_cube(p, m);
				free(p);
			}
}

static void cube_side(void **state)
{
	(void)state;
	assert_int_equal(refsamp_cube_side(1), 1);
	assert_int_equal(refsamp_cube_side(3), 1);	/* 1.44 */
	assert_int_equal(refsamp_cube_side(4), 2);	/* 1.59 */
	assert_int_equal(refsamp_cube_side(1000), 10);
	assert_int_equal(refsamp_cube_side(1157), 10);	/* 10.5^3 = 1157.6 */
	assert_int_equal(refsamp_cube_side(1158), 11);
	assert_int_equal(refsamp_cube_side(REFSAMP_MAX_N), 1625);
	/* (s - 1/2)^3 <= n < (s + 1/2)^3, exact in double here. */
	for (uint64_t n = 1; n <= 20000; n++) {
		double s = (double)refsamp_cube_side(n), v = (double)n;
		assert_true((s - 0.5) * (s - 0.5) * (s - 0.5) <= v || s == 1);
		assert_true(v < (s + 0.5) * (s + 0.5) * (s + 0.5));
	}
}

static void regular_grid(void **state)
{
	static const uint64_t ns[] = { 1, 27, 30, 1000 };
	(void)state;
	for (unsigned t = 0; t < sizeof ns / sizeof ns[0]; t++) {
		uint64_t s = refsamp_cube_side(ns[t]), m;
		double *p = gen3(REFSAMP_REGULAR, ns[t], 5, 1, &m);
		assert_int_equal(m, s * s * s);
		/* Point i is the centre of cell (i mod s, i / s mod s,
		 * i / s^2), x fastest. */
		for (uint64_t i = 0; i < m; i++) {
			assert_true(p[3 * i] ==
			    ((double)(i % s) + 0.5) / (double)s);
			assert_true(p[3 * i + 1] ==
			    ((double)(i / s % s) + 0.5) / (double)s);
			assert_true(p[3 * i + 2] ==
			    ((double)(i / (s * s)) + 0.5) / (double)s);
		}
		free(p);
	}
	{
		uint64_t m;
		double *p = gen3(REFSAMP_REGULAR, 8, 0, 1, &m);
		assert_true(p[0] == 0.25 && p[1] == 0.25 && p[2] == 0.25);
		assert_true(p[21] == 0.75 && p[22] == 0.75 && p[23] == 0.75);
		free(p);
	}
}

static void jittered_cells(void **state)
{
	static const uint64_t ns[] = { 1, 50, 343, 1000 };
	(void)state;
	for (unsigned t = 0; t < sizeof ns / sizeof ns[0]; t++) {
		uint64_t s = refsamp_cube_side(ns[t]), m;
		double *p = gen3(REFSAMP_JITTERED, ns[t], 11, 1, &m);
		unsigned *cnt = calloc(m, sizeof *cnt);
		assert_non_null(cnt);
		in_cube(p, m);
		for (uint64_t i = 0; i < m; i++) {
			uint64_t c[3];
			for (int a = 0; a < 3; a++)
				c[a] = (uint64_t)(p[3 * i + a] * (double)s);
			cnt[(c[2] * s + c[1]) * s + c[0]]++;
		}
		for (uint64_t c = 0; c < m; c++)
			assert_int_equal(cnt[c], 1);
		free(cnt);
		free(p);
	}
}

static void halton_classical(void **state)
{
	static const double first[][3] = { { 0.5, 1.0 / 3, 1.0 / 5 },
	    { 0.25, 2.0 / 3, 2.0 / 5 }, { 0.75, 1.0 / 9, 3.0 / 5 },
	    { 0.125, 4.0 / 9, 4.0 / 5 }, { 0.625, 7.0 / 9, 1.0 / 25 },
	    { 0.375, 2.0 / 9, 6.0 / 25 } };
	static const uint64_t base[3] = { 2, 3, 5 };
	uint64_t m, m2;
	double *p = gen3(REFSAMP_HALTON, 200, 0, 1, &m), *q;
	(void)state;
	assert_int_equal(m, 200);
	for (int i = 0; i < 6; i++)
		for (int a = 0; a < 3; a++)
			assert_true(fabs(p[3 * i + a] - first[i][a]) <= 0x1p-50);
	for (uint64_t i = 0; i < m; i++)
		for (int a = 0; a < 3; a++) {
			assert_true(radinv_near(p[3 * i + a], i + 1, base[a]));
			/* The bits of hsw-sample's and frs-sample's Halton. */
			assert_true(p[3 * i + a] == num_radical_inverse(i + 1,
			    (unsigned)base[a]));
		}
	free(p);
	/* A seed shifts every point by the same vector mod 1, and x, y are
	 * those of the 2-D set of that seed. */
	p = gen3(REFSAMP_HALTON, 100, 7, 1, &m);
	in_cube(p, m);
	for (uint64_t i = 1; i < m; i++)
		for (int a = 0; a < 3; a++) {
			double d0 = fmod(p[a] - radinv(1, base[a]) + 1.0, 1.0);
			double di = fmod(p[3 * i + a] - radinv(i + 1, base[a]) +
			    1.0, 1.0);
			assert_true(fabs(d0 - di) < 1e-12 ||
			    fabs(fabs(d0 - di) - 1.0) < 1e-12);
		}
	q = malloc(2 * 100 * sizeof *q);
	assert_non_null(q);
	assert_int_equal(refsamp_gen(REFSAMP_HALTON, 100, 7, 1, q, &m2), 0);
	for (uint64_t i = 0; i < m; i++) {
		assert_true(p[3 * i] == q[2 * i]);
		assert_true(p[3 * i + 1] == q[2 * i + 1]);
	}
	free(q);
	free(p);
}

static void hammersley_classical(void **state)
{
	static const double phi3[9] = { 0, 1.0 / 3, 2.0 / 3, 1.0 / 9, 4.0 / 9,
	    7.0 / 9, 2.0 / 9, 5.0 / 9, 8.0 / 9 };
	const uint64_t n = 100;
	uint64_t m;
	double *p = gen3(REFSAMP_HAMMERSLEY, n, 0, 1, &m);
	(void)state;
	assert_int_equal(m, n);
	for (uint64_t i = 0; i < n; i++) {
		assert_true(p[3 * i] == ((double)i + 0.5) / (double)n);
		assert_true(radinv_near(p[3 * i + 1], i, 2));
		assert_true(radinv_near(p[3 * i + 2], i, 3));
	}
	for (int i = 0; i < 9; i++)
		assert_true(fabs(p[3 * i + 2] - phi3[i]) <= 0x1p-50);
	free(p);
}

static void sobol_classical(void **state)
{
	/* Joe and Kuo's example output of sobol.cc with new-joe-kuo-6.21201,
	 * N = 10, D = 3 (https://web.maths.unsw.edu.au/~fkuo/sobol/):
	 * Gray-code order from the origin. */
	static const double want[10][3] = { { 0, 0, 0 }, { 0.5, 0.5, 0.5 },
	    { 0.75, 0.25, 0.25 }, { 0.25, 0.75, 0.75 },
	    { 0.375, 0.375, 0.625 }, { 0.875, 0.875, 0.125 },
	    { 0.625, 0.125, 0.875 }, { 0.125, 0.625, 0.375 },
	    { 0.1875, 0.3125, 0.9375 }, { 0.6875, 0.8125, 0.4375 } };
	uint64_t m;
	double *p = gen3(REFSAMP_SOBOL, 10, 0, 1, &m);
	(void)state;
	assert_int_equal(m, 10);
	for (int i = 0; i < 10; i++)
		for (int a = 0; a < 3; a++)
			assert_true(p[3 * i + a] == want[i][a]);
	free(p);
}

/* Whether every elementary box 2^-a x 2^-b x 2^-c with a + b + c = m - t
 * holds exactly 2^t of the first 2^m points. */
static int is_net(const double *p, unsigned m, unsigned t)
{
	uint64_t n = (uint64_t)1 << m, boxes = n >> t;
	unsigned *cnt = calloc(boxes, sizeof *cnt);
	int ok = 1;
	assert_non_null(cnt);
	for (unsigned a = 0; a <= m - t && ok; a++)
		for (unsigned b = 0; a + b <= m - t && ok; b++) {
			unsigned c = m - t - a - b;
			memset(cnt, 0, boxes * sizeof *cnt);
			for (uint64_t i = 0; i < n; i++) {
				uint64_t ix = (uint64_t)ldexp(p[3 * i], (int)a);
				uint64_t iy = (uint64_t)ldexp(p[3 * i + 1], (int)b);
				uint64_t iz = (uint64_t)ldexp(p[3 * i + 2], (int)c);
				cnt[(iz << (a + b)) | (iy << a) | ix]++;
			}
			for (uint64_t k = 0; k < boxes; k++)
				if (cnt[k] != 1u << t)
					ok = 0;
		}
	free(cnt);
	return ok;
}

/* Every one-dimensional projection of the first 2^m points holds one
 * point in each interval [j 2^-m, (j + 1) 2^-m). */
static int strata_1d(const double *p, unsigned m)
{
	uint64_t n = (uint64_t)1 << m;
	unsigned char *seen = malloc(n);
	int ok = 1;
	assert_non_null(seen);
	for (int a = 0; a < 3; a++) {
		memset(seen, 0, n);
		for (uint64_t i = 0; i < n; i++) {
			uint64_t j = (uint64_t)ldexp(p[3 * i + a], (int)m);
			ok &= !seen[j];
			seen[j] = 1;
		}
	}
	free(seen);
	return ok;
}

static void sobol_net(void **state)
{
	static const uint64_t seeds[] = { 0, 1, 2, 12345, 0xdeadbeef };
	(void)state;
	for (unsigned s = 0; s < sizeof seeds / sizeof seeds[0]; s++) {
		uint64_t m;
		double *p = gen3(REFSAMP_SOBOL, 2048, seeds[s], 1, &m);
		in_cube(p, m);
		/* The first three Sobol' dimensions form a (1,3)-sequence
		 * (t = sum of the polynomial degrees minus one: 0 + 0 + 1), so
		 * every prefix of 2^m points is a (1,m,3)-net; Owen
		 * scrambling keeps that. */
		for (unsigned lg = 1; lg <= 11; lg++) {
			assert_true(is_net(p, lg, 1));
			assert_true(strata_1d(p, lg));
		}
		free(p);
	}
	/* t = 0 fails (no (0,3)-sequence exists in base 2; here the 1024
	 * points are no (0,10,3)-net), and random points are no net: the
	 * checks can fail. */
	{
		uint64_t m;
		double *p = gen3(REFSAMP_SOBOL, 1024, 0, 1, &m);
		double *r = gen3(REFSAMP_RANDOM, 1024, 1, 1, &m);
		assert_false(is_net(p, 10, 0));
		assert_false(is_net(r, 10, 1));
		assert_false(strata_1d(r, 10));
		free(p);
		free(r);
	}
	/* Scrambling changes the points; x, y are the 2-D set's. */
	{
		uint64_t m, m2;
		double *a = gen3(REFSAMP_SOBOL, 256, 1, 1, &m);
		double *b = gen3(REFSAMP_SOBOL, 256, 2, 1, &m);
		double *q = malloc(2 * 256 * sizeof *q);
		assert_non_null(q);
		assert_true(memcmp(a, b, 3 * 256 * sizeof *a) != 0);
		assert_false(a[0] == 0 && a[1] == 0 && a[2] == 0);
		assert_int_equal(refsamp_gen(REFSAMP_SOBOL, 256, 1, 1, q, &m2), 0);
		for (uint64_t i = 0; i < 256; i++) {
			assert_true(a[3 * i] == q[2 * i]);
			assert_true(a[3 * i + 1] == q[2 * i + 1]);
		}
		free(q);
		free(a);
		free(b);
	}
}

static void dart(void **state)
{
	const uint64_t n = 1000;
	double r = refsamp_dart_radius3(n), mean = 0;
	(void)state;
	/* 0.7 of the FCC packing distance: n d^3 / sqrt 2 = 1. */
	assert_near(r, 0.7 * cbrt(sqrt(2.0) / 1000), 1e-15);
	assert_near(r, 0.7 * 0.1 * pow(2.0, 1.0 / 6), 1e-15);
	for (uint64_t set = 0; set < 5; set++) {
		uint64_t m;
		double *p = gen3(REFSAMP_DART, n, 100 + set,
		    REFSAMP_DART_FAILURES, &m), d2;
		assert_int_equal(m, n);
		in_cube(p, m);
		d2 = tu_torus_min_d2(p, m, 3);
		assert_true(d2 >= r * r);
		mean += sqrt(d2) / cbrt(sqrt(2.0) / (double)n);
		free(p);
	}
	mean /= 5;
	print_message("dart 3-D: mean rho %.4f\n", mean);
	assert_true(mean >= 0.7 - 1e-9 && mean <= 0.8);
	/* Small counts: the grid is smaller than a neighbourhood. */
	for (uint64_t k = 1; k <= 40; k++) {
		uint64_t m;
		double *p = gen3(REFSAMP_DART, k, 3, REFSAMP_DART_FAILURES, &m);
		double rk = refsamp_dart_radius3(k);
		for (uint64_t i = 0; i < m; i++)
			for (uint64_t j = i + 1; j < m; j++)
				assert_true(tu_torus_d2(p + 3 * i, p + 3 * j, 3) >=
				    rk * rk);
		assert_int_equal(m, k);
		free(p);
	}
	/* Too few failures allowed: fewer points, still a valid set. */
	{
		uint64_t m;
		double *p = gen3(REFSAMP_DART, 20000, 1, 1, &m);
		assert_true(m >= 1 && m < 20000);
		in_cube(p, m);
		free(p);
	}
}

static void random_uniform(void **state)
{
	const uint64_t n = 100000;
	uint64_t m, *cnt = calloc(1000, sizeof *cnt);
	double *p = gen3(REFSAMP_RANDOM, n, 3, 1, &m), chi = 0;
	double e = (double)n / 1000, sd = sqrt(1.0 / 12 / (double)n);
	(void)state;
	assert_non_null(cnt);
	in_cube(p, m);
	for (int a = 0; a < 3; a++)
		assert_true(p[a] == frs_rand01(3, FRS_STREAM_REF, (uint64_t)a));
	/* Mean per axis within 4 standard errors of 1/2. */
	for (int a = 0; a < 3; a++) {
		double s = 0;
		for (uint64_t i = 0; i < n; i++)
			s += p[3 * i + (uint64_t)a];
		print_message("random 3-D: mean %c %.5f\n", 'x' + a,
		    s / (double)n);
		assert_true(fabs(s / (double)n - 0.5) < 4 * sd);
	}
	for (uint64_t i = 0; i < n; i++)
		cnt[(int)(p[3 * i + 2] * 10) * 100 + (int)(p[3 * i + 1] * 10) * 10 +
		    (int)(p[3 * i] * 10)]++;
	for (int c = 0; c < 1000; c++)
		chi += ((double)cnt[c] - e) * ((double)cnt[c] - e) / e;
	/* 999 degrees of freedom: sd 44.7, 1180 is 4 sd above the mean. */
	print_message("random 3-D: chi^2 %.1f (999 dof)\n", chi);
	assert_true(chi < 1180);
	free(cnt);
	free(p);
}

/* gen3 with room for 100000 dart failures. */
static double *gen3_darts(enum refsamp_kind k, uint64_t n, uint64_t seed,
    uint64_t *placed)
{
	return gen3(k, n, seed, 100000, placed);
}

static void deterministic(void **state)
{
	(void)state;
	tu_refsamp_deterministic(gen3_darts, 3);
}

/* dims 2 is refsamp_gen, byte for byte; bad dims and 3-D relaxed dart
 * are refused. */
static void dims_api(void **state)
{
	double a[2 * 300], b[2 * 300], c[3 * 10];
	uint64_t ma, mb;
	(void)state;
	for (int k = REFSAMP_RANDOM; k <= REFSAMP_DART; k++) {
		enum refsamp_kind kind = (enum refsamp_kind)k;
		assert_int_equal(refsamp_gen(kind, 300, 4, 100000, a, &ma), 0);
		assert_int_equal(refsamp_gen_dims(kind, 2, 300, 4, 100000, b,
		    &mb), 0);
		assert_int_equal(ma, mb);
		assert_memory_equal(a, b, 2 * ma * sizeof *a);
		assert_int_equal(refsamp_count_dims(kind, 300, 2),
		    refsamp_count(kind, 300));
	}
	assert_int_equal(refsamp_count_dims(REFSAMP_JITTERED, 1000, 3), 1000);
	assert_int_equal(refsamp_count_dims(REFSAMP_REGULAR, 30, 3), 27);
	assert_int_equal(refsamp_count_dims(REFSAMP_HALTON, 30, 3), 30);
	assert_int_equal(refsamp_gen_dims(REFSAMP_RANDOM, 4, 10, 1, 1, c, &ma),
	    -1);
	assert_err_has("4 dimensions", "2 or 3");
	assert_int_equal(refsamp_gen_dims(REFSAMP_RELAXED_DART, 3, 10, 1, 1, c,
	    &ma), -1);
	assert_err_has("relaxed-dart", "two-dimensional");
	assert_int_equal(refsamp_gen_dims(REFSAMP_RANDOM, 3, 0, 1, 1, c, &ma),
	    -1);
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(count_and_range),
	cmocka_unit_test(cube_side),
	cmocka_unit_test(regular_grid),
	cmocka_unit_test(jittered_cells),
	cmocka_unit_test(halton_classical),
	cmocka_unit_test(hammersley_classical),
	cmocka_unit_test(sobol_classical),
	cmocka_unit_test(sobol_net),
	cmocka_unit_test(dart),
	cmocka_unit_test(random_uniform),
	cmocka_unit_test(deterministic),
	cmocka_unit_test(dims_api))
