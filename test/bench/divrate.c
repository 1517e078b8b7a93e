/*
 * divrate: the divider's throughput, for scripts/bench-build.sh's floor
 * of HSW's descent.
 *   divrate [COUNT]
 * prints "ns_per_division D": the best of 7 passes of COUNT (default
 * 2^22) double divisions, two independent ones an element as the
 * descent makes them (src/lib/sample/hsw.c), over arrays that stay in
 * the first-level cache.  The loads and stores run beside the divider,
 * so D is its rate: the least a descent that divides spends a quotient
 * on this processor.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "base/wide.h"

#define LEN 1024

static double now(void)
{
	struct timespec t;

	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* One sweep: u / a and v / b for every element, as one level of the
 * descent does for a group of points. */
FRS_WIDE static void sweep(const double *a, const double *b, double *u,
    double *v)
{
	for (unsigned i = 0; i < LEN; i++) {
		u[i] = u[i] / a[i];
		v[i] = v[i] / b[i];
	}
}

int main(int argc, char **argv)
{
	static double a[LEN], b[LEN], u[LEN], v[LEN];
	long count = argc > 1 ? atol(argv[1]) : 1L << 22;
	long sweeps = count / (2 * LEN) > 0 ? count / (2 * LEN) : 1;
	double best = 0.0, sum = 0.0;

	for (unsigned i = 0; i < LEN; i++) {
		/* Quotients near 1: no overflow, no subnormal, over passes. */
		a[i] = 1.0 + 1e-9 * i;
		b[i] = 1.0 - 1e-9 * i;
		u[i] = 0.5 + 1e-4 * i;
		v[i] = 0.25 + 1e-4 * i;
	}
	for (int pass = 0; pass < 7; pass++) {
		double t0 = now(), t;
		for (long s = 0; s < sweeps; s++)
			sweep(a, b, u, v);
		t = now() - t0;
		best = pass == 0 || t < best ? t : best;
	}
	for (unsigned i = 0; i < LEN; i++)
		sum += u[i] + v[i];
	/* The sum keeps the work from being optimised away. */
	printf("ns_per_division %.4f\n", 1e9 * best / (2.0 * LEN * sweeps));
	return sum > 0.0 ? 0 : 1;
}
