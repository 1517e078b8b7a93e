#define _POSIX_C_SOURCE 200809L
#include "base/num.h"
#include "base/wide.h"

#include <pthread.h>

double num_sum(const double *v, size_t n)
{
	struct num_sum a = { 0.0, 0.0 };

	for (size_t i = 0; i < n; i++)
		num_add(&a, v[i]);
	return num_total(&a);
}

double num_radical_inverse(uint64_t i, unsigned b)
{
	double inv = 1.0 / b, f = inv, r = 0.0;

	while (i > 0) {
		r += (double)(i % b) * f;
		i /= b;
		f *= inv;
	}
	return r;
}

/* Indices a group of the vector paths. */
#define GROUP 32

/* Base 2: num_radical2 where every index is below 2^53. */
FRS_WIDE static void radical2_n(const uint64_t *i, size_t n, double *out)
{
	uint64_t most = 0;

	for (size_t q = 0; q < n; q++)
		most |= i[q];
	if (most >> 53 != 0) {
		for (size_t q = 0; q < n; q++)
			out[q] = num_radical_inverse(i[q], 2);
		return;
	}
	for (size_t q = 0; q < n; q++)
		out[q] = num_radical2(i[q]);
}

/*
 * num_radical3: the base-3 digits of i mirrored at the point, 7 at a time
 * from a table of the 3^7 mirrors, summed by Horner's rule from the
 * highest chunk c_J down: r = (r + mirror(c_j)) / 3^7 with the quotient a
 * product by the rounded 1 / 3^7.  Two roundings a chunk against the
 * loop's one a digit; chunks above the highest add 0 to 0 and leave r 0,
 * so every path that covers the index's chunks gives the same bits.
 */
#define CHUNK3 7
#define CHUNK3N 2187
static double mirror3[CHUNK3N];
static pthread_once_t mirror3_once = PTHREAD_ONCE_INIT;

static void mirror3_make(void)
{
	for (unsigned c = 0; c < CHUNK3N; c++) {
		unsigned m = 0;
		for (unsigned k = 0, y = c; k < CHUNK3; k++, y /= 3)
			m = 3 * m + y % 3;
		mirror3[c] = (double)m;
	}
}

double num_radical3(uint64_t i)
{
	const double inv = 1.0 / CHUNK3N;
	unsigned c[10], nc = 0;
	double r = 0.0;

	pthread_once(&mirror3_once, mirror3_make);
	for (; i > 0; i /= CHUNK3N)
		c[nc++] = (unsigned)(i % CHUNK3N);
	while (nc > 0)
		r = (r + mirror3[c[--nc]]) * inv;
	return r;
}

/* A group below 2^32: three chunks, the quotients by 3^7 products by its
 * reciprocal in 40 bits, exact for every 32-bit word (Granlund and
 * Montgomery: 2187 m - 2^40 = 11 <= 2^8): vector multiplies, and the
 * table read by gathers. */
FRS_WIDE static void radical3_group(const uint64_t *i, double *out,
    const double *mirror)
{
	const double inv = 1.0 / CHUNK3N;

	for (size_t q = 0; q < GROUP; q++) {
		uint32_t x = (uint32_t)i[q];
		uint32_t x1 = (uint32_t)(((uint64_t)x * 502748801u) >> 40);
		uint32_t x2 = (uint32_t)(((uint64_t)x1 * 502748801u) >> 40);
		double r = (0.0 + mirror[x2]) * inv;
		r = (r + mirror[x1 - CHUNK3N * x2]) * inv;
		out[q] = (r + mirror[x - CHUNK3N * x1]) * inv;
	}
}

void num_radical3_n(const uint64_t *i, size_t n, double *out)
{
	size_t p = 0;

	pthread_once(&mirror3_once, mirror3_make);
	for (; p + GROUP <= n; p += GROUP) {
		uint64_t most = 0;
		for (size_t q = 0; q < GROUP; q++)
			most |= i[p + q];
		if (most >> 32 == 0)
			radical3_group(i + p, out + p, mirror3);
		else
			for (size_t q = 0; q < GROUP; q++)
				out[p + q] = num_radical3(i[p + q]);
	}
	for (; p < n; p++)
		out[p] = num_radical3(i[p]);
}

void num_radical_inverse_n(const uint64_t *i, size_t n, unsigned b,
    double *out)
{
	if (b == 2)
		radical2_n(i, n, out);
	else
		for (size_t q = 0; q < n; q++)
			out[q] = num_radical_inverse(i[q], b);
}
