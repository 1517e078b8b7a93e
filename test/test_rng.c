/* The counter-based generator: order independence and uniformity (the
 * Random123 known answers: test_api_rng, through the public API). */
#include "testutil.h"
#include "base/rng.h"

/* A number depends only on (seed, stream, index), never on the order in
 * which numbers are drawn. */
static void order_independent(void **state)
{
	struct frs_rng r;
	uint64_t seq[1000];
	(void)state;

	frs_rng_init(&r, 12345, FRS_STREAM_TEST);
	for (int i = 0; i < 1000; i++)
		seq[i] = frs_rng_next64(&r);
	for (int i = 999; i >= 0; i -= 7)
		assert_true(frs_rand64(12345, FRS_STREAM_TEST, (uint64_t)i) ==
		    seq[i]);
	/* Different seeds, streams and high index bits give other numbers. */
	assert_true(frs_rand64(12346, FRS_STREAM_TEST, 0) != seq[0]);
	assert_true(frs_rand64(12345, FRS_STREAM_JITTER, 0) != seq[0]);
	assert_true(frs_rand64(12345, FRS_STREAM_TEST, (uint64_t)1 << 32) !=
	    seq[0]);
}

/* Chi-square of 100000 uniforms in 100 bins; with 99 degrees of freedom
 * the statistic exceeds 160 with probability below 1e-4. */
static void uniform01(void **state)
{
	unsigned bins[100] = { 0 };
	double chi = 0.0, e = 1000.0;
	(void)state;

	for (uint64_t i = 0; i < 100000; i++) {
		double u = frs_rand01(7, FRS_STREAM_TEST, i);
		assert_true(u >= 0.0 && u < 1.0);
		bins[(int)(u * 100.0)]++;
	}
	for (int b = 0; b < 100; b++)
		chi += (bins[b] - e) * (bins[b] - e) / e;
	assert_true(chi < 160.0);
}

/* Bounded integers: every residue reachable and no bias for a bound that
 * does not divide 2^64. */
static void below(void **state)
{
	struct frs_rng r;
	unsigned c[3] = { 0 };
	(void)state;

	frs_rng_init(&r, 99, FRS_STREAM_TEST);
	for (int i = 0; i < 30000; i++) {
		uint64_t v = frs_rng_below(&r, 3);
		assert_true(v < 3);
		c[v]++;
	}
	for (int k = 0; k < 3; k++)	/* 10000 +- 5 sigma (82) */
		assert_true(c[k] > 9590 && c[k] < 10410);
	assert_true(frs_rng_below(&r, 1) == 0);
	assert_true(frs_rng_below(&r, UINT64_MAX) < UINT64_MAX);
}

/* Indices for the batch checks: small, past 32 bits, the top ones. */
static uint64_t some_index(size_t q)
{
	static const uint64_t edge[] = { 0, 1, 0xffffffffu, 0x100000000u,
	    (uint64_t)1 << 53, (uint64_t)1 << 63, UINT64_MAX };

	return q < 7 ? edge[q] : frs_rand64(3, 11, q) >> (q % 64);
}

/* frs_rand01_pair: the top 53 bits of words 0-1 and 2-3 of the block
 * (the words straight from frs_philox4x32_10, the scaling written out);
 * frs_rand01_pair_n: the same bits for every count, whole groups of 16
 * and tails, whichever clone the processor runs. */
static void pair_bits(void **state)
{
	enum { N = 75 };
	uint64_t idx[N];
	double a[N], b[N];

	(void)state;
	for (size_t q = 0; q < N; q++)
		idx[q] = some_index(q);
	for (size_t n = 0; n <= N; n += n < 40 ? 1 : 17) {
		frs_rand01_pair_n(0x123456789abcdefu, 7, idx, n, a, b);
		for (size_t q = 0; q < n; q++) {
			uint32_t ctr[4] = { (uint32_t)idx[q],
			    (uint32_t)(idx[q] >> 32), 7, 0 };
			uint32_t key[2] = { 0x89abcdefu, 0x1234567u }, w[4];
			double x, y;
			frs_philox4x32_10(ctr, key, w);
			x = (double)((w[0] | (uint64_t)w[1] << 32) >> 11) /
			    9007199254740992.0;
			y = (double)((w[2] | (uint64_t)w[3] << 32) >> 11) /
			    9007199254740992.0;
			assert_true(memcmp(&a[q], &x, sizeof x) == 0);
			assert_true(memcmp(&b[q], &y, sizeof y) == 0);
			frs_rand01_pair(0x123456789abcdefu, 7, idx[q], &x, &y);
			assert_true(memcmp(&a[q], &x, sizeof x) == 0);
			assert_true(memcmp(&b[q], &y, sizeof y) == 0);
		}
	}
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(order_independent),
	cmocka_unit_test(uniform01),
	cmocka_unit_test(below),
	cmocka_unit_test(pair_bits))
