/*
 * Numerics shared by the samplers and the analyses: Neumaier's
 * compensated sum and the radical inverse of the Halton points.
 */
#ifndef FRS_NUM_H
#define FRS_NUM_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

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

/* -1, 0 or 1 as a < b, a == b or a > b: the step of a qsort comparison
 * (a subtraction overflows, and a double's is not an int). */
#define NUM_CMP(a, b) (((a) > (b)) - ((a) < (b)))

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

#endif
