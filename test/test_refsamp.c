/* Reference samplers against closed forms and independent checks:
 * classical Halton/Hammersley/Sobol' values, the (0,2)-net property of
 * scrambled Sobol', strata, Poisson-disk distance and density. */
#include "refsamputil.h"
#include "maps/imap.h"
#include "cli/refsamp.h"
#include "base/num.h"
#include "base/rng.h"

static double *gen(enum refsamp_kind k, uint64_t n, uint64_t seed,
    uint64_t *placed)
{
	double *xy = malloc(2 * refsamp_count(k, n) * sizeof *xy);
	assert_non_null(xy);
	assert_int_equal(refsamp_gen(k, n, seed, REFSAMP_DART_FAILURES, xy,
	    placed), 0);
	return xy;
}

static void in_unit(const double *xy, uint64_t m)
{
	for (uint64_t i = 0; i < 2 * m; i++)
		assert_true(xy[i] >= 0.0 && xy[i] < 1.0);
}

static void halton_classical(void **state)
{
	static const double want[][2] = { { 0.5, 1.0 / 3 }, { 0.25, 2.0 / 3 },
	    { 0.75, 1.0 / 9 }, { 0.125, 4.0 / 9 }, { 0.625, 7.0 / 9 } };
	uint64_t m;
	double *xy = gen(REFSAMP_HALTON, 5, 0, &m);
	(void)state;
	assert_int_equal(m, 5);
	for (int i = 0; i < 5; i++) {
		assert_true(xy[2 * i] == want[i][0]);
		/* Base 3 to the roundings of num_radical_inverse, whose
		 * bits hsw-sample's and frs-sample's Halton points have. */
		assert_true(fabs(xy[2 * i + 1] - want[i][1]) <= 0x1p-50);
		assert_true(xy[2 * i + 1] == num_radical_inverse(
		    (uint64_t)i + 1, 3));
	}
	free(xy);
	/* A seed shifts every point by the same amount mod 1. */
	xy = gen(REFSAMP_HALTON, 100, 7, &m);
	in_unit(xy, m);
	{
		double dx = fmod(xy[0] - 0.5 + 1.0, 1.0);
		double ex = fmod(xy[2] - 0.25 + 1.0, 1.0);
		assert_near(dx, ex, 1e-12);
	}
	free(xy);
}

static void hammersley_classical(void **state)
{
	const uint64_t n = 16;
	uint64_t m;
	double *xy = gen(REFSAMP_HAMMERSLEY, n, 0, &m);
	static const double vdc[8] = { 0, 0.5, 0.25, 0.75, 0.125, 0.625,
	    0.375, 0.875 };
	(void)state;
	for (uint64_t i = 0; i < n; i++)
		assert_true(xy[2 * i] == ((double)i + 0.5) / (double)n);
	for (int i = 0; i < 8; i++)
		assert_true(xy[2 * i + 1] == vdc[i]);
	free(xy);
}

static void sobol_classical(void **state)
{
	static const double want[8][2] = { { 0, 0 }, { 0.5, 0.5 },
	    { 0.75, 0.25 }, { 0.25, 0.75 }, { 0.375, 0.375 },
	    { 0.875, 0.875 }, { 0.625, 0.125 }, { 0.125, 0.625 } };
	uint64_t m;
	double *xy = gen(REFSAMP_SOBOL, 8, 0, &m);
	(void)state;
	for (int i = 0; i < 8; i++) {
		assert_true(xy[2 * i] == want[i][0]);
		assert_true(xy[2 * i + 1] == want[i][1]);
	}
	free(xy);
}

/* Every elementary interval 2^-a x 2^-b, a + b = log2 n, holds one point. */
static int is_02_net(const double *xy, uint64_t n, unsigned lg)
{
	unsigned *cnt = calloc(n, sizeof *cnt);
	int ok = 1;
	assert_non_null(cnt);
	for (unsigned a = 0; a <= lg && ok; a++) {
		uint64_t ca = (uint64_t)1 << a, cb = (uint64_t)1 << (lg - a);
		memset(cnt, 0, n * sizeof *cnt);
		for (uint64_t i = 0; i < n; i++) {
			uint64_t ix = (uint64_t)(xy[2 * i] * (double)ca);
			uint64_t iy = (uint64_t)(xy[2 * i + 1] * (double)cb);
			cnt[iy * ca + ix]++;
		}
		for (uint64_t c = 0; c < n; c++)
			if (cnt[c] != 1)
				ok = 0;
	}
	free(cnt);
	return ok;
}

static void sobol_scrambled_net(void **state)
{
	static const uint64_t seeds[] = { 0, 1, 2, 3, 12345, 0xdeadbeef };
	(void)state;
	for (unsigned s = 0; s < sizeof seeds / sizeof seeds[0]; s++) {
		for (unsigned lg = 8; lg <= 10; lg += 2) {
			uint64_t n = (uint64_t)1 << lg, m;
			double *xy = gen(REFSAMP_SOBOL, n, seeds[s], &m);
			in_unit(xy, m);
			assert_true(is_02_net(xy, n, lg));
			free(xy);
		}
	}
	/* Scrambling changes the points. */
	{
		uint64_t m;
		double *a = gen(REFSAMP_SOBOL, 256, 1, &m);
		double *b = gen(REFSAMP_SOBOL, 256, 2, &m);
		assert_true(memcmp(a, b, 512 * sizeof *a) != 0);
		assert_false(a[0] == 0 && a[1] == 0);
		free(a);
		free(b);
	}
	/* Random points are not a net: the check can fail. */
	{
		uint64_t m;
		double *r = gen(REFSAMP_RANDOM, 256, 1, &m);
		assert_false(is_02_net(r, 256, 8));
		free(r);
	}
}

static void strata(void **state)
{
	static const uint64_t ns[] = { 1, 2, 3, 100, 1000, 1024 };
	(void)state;
	assert_int_equal(refsamp_grid_side(1000), 32);
	assert_int_equal(refsamp_grid_side(2), 1);
	assert_int_equal(refsamp_grid_side(3), 2);
	for (unsigned t = 0; t < sizeof ns / sizeof ns[0]; t++)
		for (int j = 0; j < 2; j++) {
			enum refsamp_kind k = j ? REFSAMP_JITTERED : REFSAMP_REGULAR;
			uint64_t s = refsamp_grid_side(ns[t]), m;
			double *xy = gen(k, ns[t], 5, &m);
			unsigned *cnt = calloc(s * s, sizeof *cnt);
			assert_non_null(cnt);
			assert_int_equal(m, s * s);
			assert_true(s * s == refsamp_count(k, ns[t]));
			in_unit(xy, m);
			for (uint64_t i = 0; i < m; i++) {
				uint64_t cx = (uint64_t)(xy[2 * i] * (double)s);
				uint64_t cy = (uint64_t)(xy[2 * i + 1] * (double)s);
				cnt[cy * s + cx]++;
				if (!j) {
					assert_near(xy[2 * i], ((double)cx + 0.5) /
					    (double)s, 1e-15);
					assert_near(xy[2 * i + 1], ((double)cy + 0.5) /
					    (double)s, 1e-15);
				}
			}
			for (uint64_t c = 0; c < s * s; c++)
				assert_int_equal(cnt[c], 1);
			free(cnt);
			free(xy);
		}
}

static void dart(void **state)
{
	const uint64_t n = 1024;
	double r = refsamp_dart_radius(n), mean = 0;
	(void)state;
	assert_near(r, 0.7 * sqrt(2 / (sqrt(3.0) * 1024)), 1e-15);
	for (uint64_t set = 0; set < 10; set++) {
		uint64_t m;
		double *xy = gen(REFSAMP_DART, n, 100 + set, &m), d2;
		assert_int_equal(m, n);
		in_unit(xy, m);
		d2 = tu_torus_min_d2(xy, m, 2);
		assert_true(d2 >= r * r);
		mean += sqrt(d2) / sqrt(2 / (sqrt(3.0) * (double)n));
		free(xy);
	}
	mean /= 10;
	print_message("dart: mean rho %.4f (thesis Table 6.1: 0.70)\n", mean);
	assert_true(mean >= 0.65 && mean <= 0.75);
	/* Too few failures allowed: fewer points, still a valid set. */
	{
		double *xy = malloc(2 * 4096 * sizeof *xy);
		uint64_t m;
		assert_non_null(xy);
		assert_int_equal(refsamp_gen(REFSAMP_DART, 4096, 1, 1, xy, &m), 0);
		assert_true(m >= 1 && m < 4096);
		free(xy);
	}
}

static void random_uniform(void **state)
{
	const uint64_t n = 100000;
	uint64_t m, cnt[100] = { 0 };
	double *xy = gen(REFSAMP_RANDOM, n, 3, &m), chi = 0, e = (double)n / 100;
	(void)state;
	in_unit(xy, m);
	assert_true(xy[0] == frs_rand01(3, FRS_STREAM_REF, 0));
	assert_true(xy[1] == frs_rand01(3, FRS_STREAM_REF, 1));
	for (uint64_t i = 0; i < n; i++)
		cnt[(int)(xy[2 * i + 1] * 10) * 10 + (int)(xy[2 * i] * 10)]++;
	for (int c = 0; c < 100; c++)
		chi += ((double)cnt[c] - e) * ((double)cnt[c] - e) / e;
	/* 99 degrees of freedom: P(chi^2 > 160) < 1e-4. */
	print_message("random: chi^2 %.1f (99 dof)\n", chi);
	assert_true(chi < 160);
	free(xy);
}

static void deterministic(void **state)
{
	(void)state;
	tu_refsamp_deterministic(gen, 2);
}

static void names(void **state)
{
	enum refsamp_kind k;
	(void)state;
	assert_int_equal(refsamp_parse("sobol", &k), 0);
	assert_int_equal(k, REFSAMP_SOBOL);
	assert_string_equal(refsamp_name(REFSAMP_DART), "dart");
	assert_int_equal(refsamp_parse("blue", &k), -1);
	assert_err_has("blue", "unknown kind");
	{
		double xy[2];
		uint64_t m;
		assert_int_equal(refsamp_gen(REFSAMP_RANDOM, 0, 1, 1, xy, &m), -1);
	}
}

/* A w x h map: left half a, right half b. */
static void halves(struct frs_imap *m, uint32_t w, uint32_t h, double a,
    double b)
{
	assert_int_equal(imap_alloc(m, w, h), 0);
	for (uint32_t j = 0; j < h; j++)
		for (uint32_t i = 0; i < w; i++)
			m->v[(uint64_t)j * w + i] = i < w / 2 ? a : b;
}

static void relaxed_dart(void **state)
{
	struct frs_imap m;
	uint64_t n = 2000, left = 0;
	double *xy = malloc(2 * n * sizeof *xy), *xy2 = malloc(2 * n *
	    sizeof *xy2), r0, mean = 2.5, frac;
	(void)state;
	assert_non_null(xy);
	assert_non_null(xy2);
	/* Zero on the left: no point there. */
	halves(&m, 16, 16, 0.0, 1.0);
	assert_int_equal(refsamp_relaxed_dart(n, 3, REFSAMP_RELAXED_FAILURES,
	    &m, xy, &r0), 0);
	in_unit(xy, n);
	for (uint64_t i = 0; i < n; i++)
		assert_true(xy[2 * i] >= 0.5);
	imap_free(&m);
	/* 1 left, 4 right: 1/5 and 4/5 of the points, within 10%. */
	halves(&m, 16, 16, 1.0, 4.0);
	assert_int_equal(refsamp_relaxed_dart(n, 5, REFSAMP_RELAXED_FAILURES,
	    &m, xy, &r0), 0);
	in_unit(xy, n);
	for (uint64_t i = 0; i < n; i++)
		left += xy[2 * i] < 0.5;
	frac = (double)left / (double)n;
	assert_true(frac > 0.2 * 0.9 && frac < 0.2 * 1.1);
	/* The conflict rule at the final r0, all pairs. */
	for (uint64_t i = 0; i < n; i++)
		for (uint64_t k = i + 1; k < n; k++) {
			double fi = sqrt(mean / (xy[2 * i] < 0.5 ? 1.0 : 4.0));
			double fk = sqrt(mean / (xy[2 * k] < 0.5 ? 1.0 : 4.0));
			double r = r0 * (fi > fk ? fi : fk);
			double dx = xy[2 * i] - xy[2 * k];
			double dy = xy[2 * i + 1] - xy[2 * k + 1];
			assert_true(dx * dx + dy * dy >= r * r);
		}
	/* The same bytes for the same seed, others for another. */
	assert_int_equal(refsamp_relaxed_dart(n, 5, REFSAMP_RELAXED_FAILURES,
	    &m, xy2, NULL), 0);
	assert_memory_equal(xy, xy2, 2 * n * sizeof *xy);
	assert_int_equal(refsamp_relaxed_dart(n, 6, REFSAMP_RELAXED_FAILURES,
	    &m, xy2, NULL), 0);
	assert_true(memcmp(xy, xy2, 2 * n * sizeof *xy) != 0);
	imap_free(&m);
	/* All zero: an error. */
	halves(&m, 4, 4, 0.0, 0.0);
	assert_int_equal(refsamp_relaxed_dart(10, 1, 10, &m, xy, NULL), -1);
	assert_err_has("zero", "zero everywhere");
	imap_free(&m);
	/* Through refsamp_gen: constant importance, exactly n. */
	{
		uint64_t placed;
		assert_int_equal(refsamp_gen(REFSAMP_RELAXED_DART, 500, 1,
		    REFSAMP_RELAXED_FAILURES, xy, &placed), 0);
		assert_int_equal(placed, 500);
		in_unit(xy, 500);
	}
	free(xy);
	free(xy2);
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(halton_classical),
	cmocka_unit_test(hammersley_classical),
	cmocka_unit_test(sobol_classical),
	cmocka_unit_test(sobol_scrambled_net),
	cmocka_unit_test(strata),
	cmocka_unit_test(dart),
	cmocka_unit_test(random_uniform),
	cmocka_unit_test(deterministic),
	cmocka_unit_test(names),
	cmocka_unit_test(relaxed_dart))
