/*
 * Numerics shared by the samplers and the analyses: Neumaier's
 * compensated sum and the radical inverse of the Halton points.
 */
#ifndef FRS_NUM_H
#define FRS_NUM_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

/*
 * Neumaier's compensated sum (Neumaier 1974, Kahan-Babuska): s the
 * running sum, c the sum of what its roundings lost, each loss exact
 * (Fast2Sum with the larger operand first); the total is s + c.  Inline:
 * it is the inner loop of the discrepancy grids.
 */
struct num_sum {
	double s, c;
};

static inline void num_add(struct num_sum *a, double v)
{
	double t = a->s + v;

	a->c += fabs(a->s) >= fabs(v) ? (a->s - t) + v : (v - t) + a->s;
	a->s = t;
}

static inline double num_total(const struct num_sum *a)
{
	return a->s + a->c;
}

/* pi to more digits than a double holds (C11's math.h has no M_PI). */
#define NUM_PI 3.14159265358979323846

/* -1, 0 or 1 as a < b, a == b or a > b: the step of a qsort comparison
 * (a subtraction overflows, and a double's is not an int). */
#define NUM_CMP(a, b) (((a) > (b)) - ((a) < (b)))

/* A value and where it came from, for a qsort by value (the samplers'
 * block lists). */
struct num_vi {
	uint32_t v, i;
};

static inline int num_vi_cmp(const void *a, const void *b)
{
	const struct num_vi *x = a, *y = b;

	return NUM_CMP(x->v, y->v);
}

/* The compensated sum of v[0 .. n - 1], in order. */
double num_sum(const double *v, size_t n);

/*
 * The radical inverse of i in base b >= 2, the coordinate of Halton
 * point i: the digits d_k of i mirrored at the point, summed from the
 * lowest digit as r += d_k w_k with w_0 = 1/b and w_(k+1) = w_k * (1/b),
 * each rounded.  Exact in base 2 for i < 2^53; in other bases within
 * (digits + 2) ulps of 1.  Every Halton point of the library has these
 * bits (hsw.c's fast paths reproduce them); the value may round up to 1.
 */
double num_radical_inverse(uint64_t i, unsigned b);
/* num_radical_inverse(i[q], b) into out[q] for q < n, the same bits; in
 * vectors for base 2 (the mirrored bits of i). */
void num_radical_inverse_n(const uint64_t *i, size_t n, unsigned b,
    double *out);
/*
 * The radical inverse of i in base 3 by a table: the digits mirrored 7 at
 * a time (3^7 = 2187 mirrors), summed by Horner's rule from the highest
 * chunk, r = (r + m_j) / 2187 with a product by the rounded reciprocal.
 * Within 3 ulps of the exact value, as num_radical_inverse is within
 * (digits + 2), but not its bits; in vectors 1.8 ns an index on a 2-core
 * Xeon, against 4.5 for the loop's bits (the jitter's Halton points).
 * Below 1 for i < 3^21; the value may round up to 1 beyond.
 */
double num_radical3(uint64_t i);
/* num_radical3(i[q]) into out[q] for q < n, the same bits, in vectors
 * where the 32 indices of a group are below 2^32. */
void num_radical3_n(const uint64_t *i, size_t n, double *out);
/*
 * (double)v for v < 2^53, as loops that vectorise want it: AVX2 has no
 * conversion of 64-bit integers, so in two exact parts, the low 52 bits
 * through the bits of 2^52 + v, then 2^52 where bit 52 is set.
 */
static inline double num_u53(uint64_t v)
{
	uint64_t b = (v & (((uint64_t)1 << 52) - 1)) | 0x4330000000000000u;
	double d;

	memcpy(&d, &b, sizeof d);
	return (d - 0x1p52) + (double)(v >> 52) * 0x1p52;
}

/* Whether v is a power of two (the minmap's and the lists' sides must be). */
static inline int num_is_pow2(uint64_t v)
{
	return v && !(v & (v - 1));
}

/* The smallest l with 2^l >= v: log2 of a power of two. */
static inline unsigned num_log2_ceil(uint64_t v)
{
	unsigned l = 0;

	while (((uint64_t)1 << l) < v)
		l++;
	return l;
}

/* x with its 64 bits in the mirror order (inline: the loops of the
 * Halton points vectorise it). */
static inline uint64_t num_bit_reverse(uint64_t x)
{
	x = (x >> 1 & 0x5555555555555555u) | (x & 0x5555555555555555u) << 1;
	x = (x >> 2 & 0x3333333333333333u) | (x & 0x3333333333333333u) << 2;
	x = (x >> 4 & 0x0f0f0f0f0f0f0f0fu) | (x & 0x0f0f0f0f0f0f0f0fu) << 4;
	x = (x >> 8 & 0x00ff00ff00ff00ffu) | (x & 0x00ff00ff00ff00ffu) << 8;
	x = (x >> 16 & 0x0000ffff0000ffffu) | (x & 0x0000ffff0000ffffu) << 16;
	return x >> 32 | x << 32;
}

/* num_radical_inverse(i, 2) for i < 2^53: the loop adds at most 53
 * powers of two, each sum exact, which is the mirrored integer (its low
 * 11 bits clear, 53 bits at most, so exact as a double) times 2^-64. */
static inline double num_radical2(uint64_t i)
{
	return num_u53(num_bit_reverse(i) >> 11) * 0x1p-53;
}

#endif
