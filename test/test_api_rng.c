/*
 * The public random numbers (frs.h, API 2.2), through frs.h alone as a
 * user has them: Philox4x32-10 against the published known answers
 * (Random123's tests/kat_vectors, "philox4x32 10"), frs_rand64,
 * frs_rand64x and frs_rand01 against those answers and the words of the
 * block put together by hand, the sequential frs_rng against a
 * brute-force loop of the documented rejection rule, and statistical
 * checks of the numbers.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>

#include "frs.h"

/* Counter (4 words), key (2), result (4). */
static const uint32_t kat[3][10] = {
	{ 0, 0, 0, 0, 0, 0,
	  0x6627e8d5, 0xe169c58d, 0xbc57ac4c, 0x9b00dbd8 },
	{ 0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff,
	  0xffffffff, 0x408f276d, 0x41c83b0e, 0xa20bc7c6, 0x6d5451fd },
	{ 0x243f6a88, 0x85a308d3, 0x13198a2e, 0x03707344, 0xa4093822,
	  0x299f31d0, 0xd16cfe09, 0x94fdcceb, 0x5001e420, 0x24126ea1 },
};

static uint64_t words(uint32_t lo, uint32_t hi)
{
	return (uint64_t)hi << 32 | lo;
}

static void block_kat(void **state)
{
	(void)state;
	for (int i = 0; i < 3; i++) {
		uint32_t out[4];
		frs_philox4x32_10(kat[i], kat[i] + 4, out);
		for (int k = 0; k < 4; k++)
			assert_int_equal(out[k], kat[i][6 + k]);
	}
}

/* The same answers through the coordinates: the key is the seed, low
 * word first; the counter (index low, index high, stream, sub). */
static void rand64_kat(void **state)
{
	(void)state;
	for (int i = 0; i < 3; i++) {
		const uint32_t *c = kat[i], *r = kat[i] + 6;
		uint64_t seed = words(c[4], c[5]), index = words(c[0], c[1]);
		uint64_t want = words(r[0], r[1]);

		assert_true(frs_rand64x(seed, c[2], index, c[3]) == want);
		if (c[3] == 0)
			assert_true(frs_rand64(seed, c[2], index) == want);
	}
	assert_true(frs_rand64(0, 0, 0) == 0xe169c58d6627e8d5u);
}

/* frs_rand01: the top 53 bits of frs_rand64, scaled by 2^-53; and
 * frs_rand64 is frs_rand64x with sub 0, frs_rand64x words 0 and 1 of the
 * block, for indices past 32 bits and streams and subs of every size. */
static void rand01_bits(void **state)
{
	static const uint64_t seeds[] = { 0, 1, 0x299f31d0a4093822u,
	    UINT64_MAX };
	static const uint64_t idx[] = { 0, 1, 0xffffffffu, 0x100000000u,
	    (uint64_t)1 << 63, UINT64_MAX };
	static const uint32_t streams[] = { 0, 8, 0x56414331u, UINT32_MAX };
	(void)state;

	for (size_t a = 0; a < 4; a++)
		for (size_t b = 0; b < 6; b++)
			for (size_t c = 0; c < 4; c++) {
				uint64_t s = seeds[a], i = idx[b];
				uint32_t st = streams[c], out[4];
				uint32_t ctr[4] = { (uint32_t)i,
				    (uint32_t)(i >> 32), st, 0 };
				uint32_t key[2] = { (uint32_t)s,
				    (uint32_t)(s >> 32) };
				uint64_t x = frs_rand64(s, st, i);
				double u = ldexp((double)(x >> 11), -53);

				frs_philox4x32_10(ctr, key, out);
				assert_true(x == words(out[0], out[1]));
				assert_true(frs_rand64x(s, st, i, 0) == x);
				ctr[3] = st ^ 0x5a5a5a5au;
				frs_philox4x32_10(ctr, key, out);
				assert_true(frs_rand64x(s, st, i, ctr[3]) ==
				    words(out[0], out[1]));
				assert_true(frs_rand01(s, st, i) == u);
				assert_true(u >= 0.0 && u < 1.0);
			}
}

/* The sequential stream: the indices 0, 1, 2, ... in turn, next01 the
 * frs_rand01 of its index; init starts over. */
static void rng_sequence(void **state)
{
	struct frs_rng r;
	(void)state;

	frs_rng_init(&r, 0x1234, 77);
	for (uint64_t i = 0; i < 300; i++) {
		if (i % 3 == 2)
			assert_true(frs_rng_next01(&r) ==
			    frs_rand01(0x1234, 77, i));
		else
			assert_true(frs_rng_next64(&r) ==
			    frs_rand64(0x1234, 77, i));
	}
	assert_true(r.index == 300 && r.seed == 0x1234 && r.stream == 77);
	frs_rng_init(&r, 0x1234, 77);
	assert_true(frs_rng_next64(&r) == frs_rand64(0x1234, 77, 0));
}

/* frs_rng_below by the rule of frs.h, written out: x at the next index,
 * drawn again while x >= m, m the largest multiple of bound not above
 * 2^64 - 1 (found here by division, the multiple itself); bound 0 is
 * 2^64, every x.  2^63 + 1 rejects almost half the draws, 3 one value
 * of 2^64, 2^k the top 2^k values. */
static void below_rule(void **state)
{
	static const uint64_t bounds[] = { 0, 1, 2, 3, 7, 8, 1000,
	    ((uint64_t)1 << 63) + 1, ((uint64_t)1 << 63) - 1,
	    (uint64_t)1 << 63, UINT64_MAX - 1, UINT64_MAX };
	(void)state;

	for (size_t b = 0; b < sizeof bounds / sizeof *bounds; b++) {
		uint64_t bound = bounds[b], i = 0, m;
		struct frs_rng r;

		m = bound ? UINT64_MAX / bound * bound : 0;
		frs_rng_init(&r, 99, 5);
		for (int k = 0; k < 200; k++) {
			uint64_t x, want;
			do
				x = frs_rand64(99, 5, i++);
			while (bound != 0 && x >= m);
			want = bound ? x % bound : x;
			assert_true(frs_rng_below(&r, bound) == want);
			assert_true(r.index == i);
		}
	}
}

/* Chi-square of 100000 uniforms in 100 bins (99 degrees of freedom:
 * above 160 with probability below 1e-4), and of 50000 consecutive
 * pairs in 10 x 10 cells: numbers of neighbouring indices independent. */
static void uniform(void **state)
{
	unsigned bins[100] = { 0 }, cells[100] = { 0 };
	double chi = 0.0, chi2 = 0.0;
	(void)state;

	for (uint64_t i = 0; i < 100000; i++)
		bins[(int)(frs_rand01(7, 1, i) * 100.0)]++;
	for (uint64_t i = 0; i < 100000; i += 2)
		cells[(int)(frs_rand01(8, 1, i) * 10.0) * 10 +
		    (int)(frs_rand01(8, 1, i + 1) * 10.0)]++;
	for (int b = 0; b < 100; b++) {
		chi += (bins[b] - 1000.0) * (bins[b] - 1000.0) / 1000.0;
		chi2 += (cells[b] - 500.0) * (cells[b] - 500.0) / 500.0;
	}
	assert_true(chi < 160.0);
	assert_true(chi2 < 160.0);
}

/* Every one of the 64 bits of frs_rand64 set half the time (65536 draws:
 * 32768 +- 5 sigma, 640), over consecutive seeds and over streams; and
 * frs_rng_below(3)'s residues equally often. */
static void bits_and_residues(void **state)
{
	unsigned ones[64] = { 0 }, sones[64] = { 0 }, c[3] = { 0 };
	struct frs_rng r;
	(void)state;

	for (uint64_t i = 0; i < 65536; i++) {
		uint64_t x = frs_rand64(i, 3, 0);
		uint64_t y = frs_rand64(1, (uint32_t)i, 12);
		for (int k = 0; k < 64; k++) {
			ones[k] += (unsigned)(x >> k & 1);
			sones[k] += (unsigned)(y >> k & 1);
		}
	}
	for (int k = 0; k < 64; k++) {
		assert_true(ones[k] > 32128 && ones[k] < 33408);
		assert_true(sones[k] > 32128 && sones[k] < 33408);
	}
	frs_rng_init(&r, 4, 0);
	for (int i = 0; i < 30000; i++)
		c[frs_rng_below(&r, 3)]++;
	for (int k = 0; k < 3; k++)	/* 10000 +- 5 sigma (82 each) */
		assert_true(c[k] > 9590 && c[k] < 10410);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(block_kat),
		cmocka_unit_test(rand64_kat),
		cmocka_unit_test(rand01_bits),
		cmocka_unit_test(rng_sequence),
		cmocka_unit_test(below_rule),
		cmocka_unit_test(uniform),
		cmocka_unit_test(bits_and_residues),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
