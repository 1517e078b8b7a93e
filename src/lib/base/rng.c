#define _POSIX_C_SOURCE 200809L
#include "base/rng.h"
#include "base/num.h"
#include "base/wide.h"

#define PHILOX_M0 0xD2511F53u
#define PHILOX_M1 0xCD9E8D57u
#define PHILOX_W0 0x9E3779B9u
#define PHILOX_W1 0xBB67AE85u

static void mulhilo(uint32_t a, uint32_t b, uint32_t *hi, uint32_t *lo)
{
	uint64_t p = (uint64_t)a * b;
	*hi = (uint32_t)(p >> 32);
	*lo = (uint32_t)p;
}

void frs_philox4x32_10(const uint32_t ctr[4], const uint32_t key[2],
    uint32_t out[4])
{
	uint32_t c0 = ctr[0], c1 = ctr[1], c2 = ctr[2], c3 = ctr[3];
	uint32_t k0 = key[0], k1 = key[1];

	for (int round = 0; round < 10; round++) {
		uint32_t hi0, lo0, hi1, lo1;
		if (round > 0) {
			k0 += PHILOX_W0;
			k1 += PHILOX_W1;
		}
		mulhilo(PHILOX_M0, c0, &hi0, &lo0);
		mulhilo(PHILOX_M1, c2, &hi1, &lo1);
		c0 = hi1 ^ c1 ^ k0;
		c1 = lo1;
		c2 = hi0 ^ c3 ^ k1;
		c3 = lo0;
	}
	out[0] = c0;
	out[1] = c1;
	out[2] = c2;
	out[3] = c3;
}

uint64_t frs_rand64(uint64_t seed, uint32_t stream, uint64_t index)
{
	return frs_rand64x(seed, stream, index, 0);
}

uint64_t frs_rand64x(uint64_t seed, uint32_t stream, uint64_t index,
    uint32_t sub)
{
	uint32_t ctr[4] = { (uint32_t)index, (uint32_t)(index >> 32), stream,
	    sub };
	uint32_t key[2] = { (uint32_t)seed, (uint32_t)(seed >> 32) };
	uint32_t out[4];

	frs_philox4x32_10(ctr, key, out);
	return (uint64_t)out[0] | (uint64_t)out[1] << 32;
}

double frs_rand01(uint64_t seed, uint32_t stream, uint64_t index)
{
	return (double)(frs_rand64(seed, stream, index) >> 11) * 0x1p-53;
}

/* 53 bits, the top of two words, as a double in [0, 1). */
static double unit53(uint32_t lo, uint32_t hi)
{
	return (double)(((uint64_t)lo | (uint64_t)hi << 32) >> 11) * 0x1p-53;
}

void frs_rand01_pair(uint64_t seed, uint32_t stream, uint64_t index,
    double *a, double *b)
{
	uint32_t ctr[4] = { (uint32_t)index, (uint32_t)(index >> 32), stream,
	    0 };
	uint32_t key[2] = { (uint32_t)seed, (uint32_t)(seed >> 32) };
	uint32_t out[4];

	frs_philox4x32_10(ctr, key, out);
	*a = unit53(out[0], out[1]);
	*b = unit53(out[2], out[3]);
}

/* Counters a group of frs_rand01_pair_n. */
#define LANES 16

/* unit53 in vector form (num_u53), for philox_group alone: folded into
 * unit53, which frs_rand01_pair also calls, it was no longer inlined into
 * pair_n's clones by gcc 12, which then stayed scalar (4.7 -> 15 ns a
 * block). */
static inline double unit53v(uint32_t lo, uint32_t hi)
{
	return num_u53(((uint64_t)lo | (uint64_t)hi << 32) >> 11) * 0x1p-53;
}

/*
 * frs_philox4x32_10 of LANES counters (index, stream, 0) under one key:
 * the rounds outside, the lanes inside, so that a round of all lanes is a
 * few vector instructions (32-bit products in 64-bit lanes).
 */
static inline void philox_group(uint32_t k0, uint32_t k1, uint32_t stream,
    const uint64_t *index, double *a, double *b)
{
	uint32_t c0[LANES], c1[LANES], c2[LANES], c3[LANES];

	for (size_t q = 0; q < LANES; q++) {
		c0[q] = (uint32_t)index[q];
		c1[q] = (uint32_t)(index[q] >> 32);
		c2[q] = stream;
		c3[q] = 0;
	}
	for (int round = 0; round < 10; round++) {
		if (round > 0) {
			k0 += PHILOX_W0;
			k1 += PHILOX_W1;
		}
		for (size_t q = 0; q < LANES; q++) {
			uint64_t p0 = (uint64_t)PHILOX_M0 * c0[q];
			uint64_t p1 = (uint64_t)PHILOX_M1 * c2[q];
			c0[q] = (uint32_t)(p1 >> 32) ^ c1[q] ^ k0;
			c1[q] = (uint32_t)p1;
			c2[q] = (uint32_t)(p0 >> 32) ^ c3[q] ^ k1;
			c3[q] = (uint32_t)p0;
		}
	}
	for (size_t q = 0; q < LANES; q++) {
		a[q] = unit53v(c0[q], c1[q]);
		b[q] = unit53v(c2[q], c3[q]);
	}
}

FRS_WIDE static void pair_n(uint64_t seed, uint32_t stream,
    const uint64_t *index, size_t n, double *a, double *b)
{
	uint32_t k0 = (uint32_t)seed, k1 = (uint32_t)(seed >> 32);
	size_t p = 0;

	for (; p + LANES <= n; p += LANES)
		philox_group(k0, k1, stream, index + p, a + p, b + p);
	for (; p < n; p++)
		frs_rand01_pair(seed, stream, index[p], &a[p], &b[p]);
}

void frs_rand01_pair_n(uint64_t seed, uint32_t stream,
    const uint64_t *index, size_t n, double *a, double *b)
{
	pair_n(seed, stream, index, n, a, b);
}

void frs_rng_init(struct frs_rng *r, uint64_t seed, uint32_t stream)
{
	r->seed = seed;
	r->stream = stream;
	r->index = 0;
}

uint64_t frs_rng_next64(struct frs_rng *r)
{
	return frs_rand64(r->seed, r->stream, r->index++);
}

double frs_rng_next01(struct frs_rng *r)
{
	return (double)(frs_rng_next64(r) >> 11) * 0x1p-53;
}

uint64_t frs_rng_below(struct frs_rng *r, uint64_t bound)
{
	/* Rejection from the top of the range keeps every residue equally
	 * likely. */
	uint64_t limit, x;

	if (bound == 0)		/* 2^64: every value */
		return frs_rng_next64(r);
	limit = UINT64_MAX - UINT64_MAX % bound;
	do
		x = frs_rng_next64(r);
	while (x >= limit);
	return x % bound;
}
