#define _POSIX_C_SOURCE 200809L
#include "base/num.h"
#include "base/wide.h"

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

/* Indices a group of the vector paths: enough vectors in flight to
 * hide the latency of a digit. */
#define GROUP 32
/* Base-3 digits of a 32-bit word: 3^21 > 2^32. */
#define DIGITS3 21

/*
 * Base 2: below 2^53 the loop adds at most 53 powers of two, each sum
 * exact, which is the mirrored integer (53 bits at most, so exact as a
 * double) times 2^-64.
 */
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
	/* The mirror of i < 2^53 has its low 11 bits clear. */
	for (size_t q = 0; q < n; q++)
		out[q] = num_u53(num_bit_reverse(i[q]) >> 11) * 0x1p-53;
}

/*
 * Base 3 of a group below 2^32: the loop's sum in its order, digit k of
 * every index at once, with the loop's weights; digits past an index's
 * highest add 0, which leaves the sum as it is.  A digit is h - 3 (h / 3),
 * the quotient a product by the reciprocal of 3 in 33 bits (exact for
 * every 32-bit h): a vector multiply.
 */
static inline void radical3_group(const uint64_t *i, double *out, const double *w,
    unsigned digits)
{
	uint32_t h[GROUP];
	double r[GROUP];

	for (size_t q = 0; q < GROUP; q++) {
		h[q] = (uint32_t)i[q];
		r[q] = 0.0;
	}
	for (unsigned k = 0; k < digits; k++)
		for (size_t q = 0; q < GROUP; q++) {
			uint32_t d3 = (uint32_t)(((uint64_t)h[q] * 0xAAAAAAABu) >> 33);
			int d = (int)(h[q] - 3 * d3);
			r[q] += (double)d * w[k];
			h[q] = d3;
		}
	for (size_t q = 0; q < GROUP; q++)
		out[q] = r[q];
}

FRS_WIDE static void radical3_n(const uint64_t *i, size_t n, double *out)
{
	double w[DIGITS3], inv = 1.0 / 3, f = inv;
	size_t p = 0;

	for (unsigned k = 0; k < DIGITS3; k++, f *= inv)
		w[k] = f;
	for (; p + GROUP <= n; p += GROUP) {
		uint64_t most = 0, pow3 = 1;
		unsigned digits = 0;
		for (size_t q = 0; q < GROUP; q++)
			most = i[p + q] > most ? i[p + q] : most;
		for (; pow3 <= most && digits < DIGITS3; pow3 *= 3)
			digits++;
		if (most >> 32 == 0)
			radical3_group(i + p, out + p, w, digits);
		else
			for (size_t q = 0; q < GROUP; q++)
				out[p + q] = num_radical_inverse(i[p + q], 3);
	}
	for (; p < n; p++)
		out[p] = num_radical_inverse(i[p], 3);
}

void num_radical_inverse_n(const uint64_t *i, size_t n, unsigned b,
    double *out)
{
	if (b == 2)
		radical2_n(i, n, out);
	else if (b == 3)
		radical3_n(i, n, out);
	else
		for (size_t q = 0; q < n; q++)
			out[q] = num_radical_inverse(i[q], b);
}
