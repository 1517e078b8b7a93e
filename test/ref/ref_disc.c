/*
 * ref_disc: brute-force star discrepancy, the reference implementation
 * for the benchmark (scripts/bench-discrepancy.sh).  Independent of the
 * library's discrepancy code; libfrs only reads the point file.
 *
 *   ref_disc warnock FILE      D2 by the plain O(n^2) double loop of
 *                              Warnock's formula (sums in blocks)
 *   ref_disc stargrid S FILE   D2 and Dinf over the corners (i/s, j/s),
 *                              i, j = 1..s, from a full s x s summed-area
 *                              table of the counts of points with
 *                              px < i/s and py < j/s (half-open boxes)
 *
 * FILE holds one set of 2-D points.  Prints "D2 value" (and "Dinf value")
 * with %.17g on standard output.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/err.h"
#include "cli/ptsio.h"

static void die(const char *msg)
{
	fprintf(stderr, "ref_disc: %s\n", msg);
	exit(1);
}

/* The points of FILE as x, y pairs in [0,1)^2. */
static double *load(const char *path, size_t *n)
{
	struct frs_points p;
	size_t stride;
	double *xy;

	if (pts_read(path, &p) < 0)
		die(frs_errmsg());
	if (p.dims != 2 || p.n == 0)
		die("need a non-empty set of 2-D points");
	stride = 2 + p.extra;
	xy = malloc(2 * p.n * sizeof *xy);
	if (xy == NULL)
		die("no memory");
	for (size_t i = 0; i < p.n; i++) {
		xy[2 * i] = p.x[stride * i];
		xy[2 * i + 1] = p.x[stride * i + 1];
		if (!(xy[2 * i] >= 0 && xy[2 * i] < 1 &&
		    xy[2 * i + 1] >= 0 && xy[2 * i + 1] < 1))
			die("a point outside [0,1)^2");
	}
	*n = p.n;
	pts_free(&p);
	return xy;
}

/* Warnock: D2^2 = 1/9 - (2/n) sum (1-x^2)(1-y^2)/4
 *               + (1/n^2) sum_i sum_j (1-max(x_i,x_j))(1-max(y_i,y_j)). */
static double warnock(const double *xy, size_t n)
{
	double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y);
	long double s1 = 0, s2 = 0;

	if (x == NULL || y == NULL)
		die("no memory");
	for (size_t i = 0; i < n; i++)
		x[i] = xy[2 * i], y[i] = xy[2 * i + 1];
	for (size_t i = 0; i < n; i++)
		s1 += (1 - x[i] * x[i]) * (1 - y[i] * y[i]) / 4;
	/* The double loop; each row is summed in blocks of BLK terms, with
	 * NACC partial sums in double (small, so accurate), the blocks in
	 * long double: the result cancels to D2^2 ~ 1/n^2 from terms ~ 1. */
	enum { BLK = 256, NACC = 8 };
	for (size_t i = 0; i < n; i++) {
		double xi = x[i], yi = y[i];
		long double row = 0;
		for (size_t b = 0; b < n; b += BLK) {
			size_t e = b + BLK < n ? b + BLK : n, j = b;
			double acc[NACC] = { 0 }, blk = 0;
			for (; j + NACC <= e; j += NACC)
				for (size_t k = 0; k < NACC; k++) {
					double mx = xi > x[j + k] ? xi : x[j + k];
					double my = yi > y[j + k] ? yi : y[j + k];
					acc[k] += (1 - mx) * (1 - my);
				}
			for (; j < e; j++) {
				double mx = xi > x[j] ? xi : x[j];
				double my = yi > y[j] ? yi : y[j];
				blk += (1 - mx) * (1 - my);
			}
			for (size_t k = 0; k < NACC; k++)
				blk += acc[k];
			row += blk;
		}
		s2 += row;
	}
	free(x), free(y);
	long double d = 1.0L / 9 - 2 * s1 / (long double)n +
	    s2 / ((long double)n * (long double)n);
	return d > 0 ? sqrt((double)d) : 0;
}

/* The first grid line i in 1..s with p < i/s (p < 1, so i <= s). */
static size_t cell(double p, size_t s)
{
	size_t i = (size_t)(p * (double)s) + 1;
	if (i > s)
		i = s;
	while (i > 1 && p < (double)(i - 1) / (double)s)
		i--;
	while (i < s && !(p < (double)i / (double)s))
		i++;
	return i;
}

static void stargrid(const double *xy, size_t n, size_t s, double *d2,
    double *dinf)
{
	/* c[(j-1) s + (i-1)]: points first counted at corner (i, j), then
	 * summed over both axes: points with px < i/s, py < j/s. */
	uint32_t *c = calloc(s * s, sizeof *c);
	long double sum = 0;
	double mx = 0;

	if (c == NULL)
		die("no memory for the grid");
	for (size_t k = 0; k < n; k++)
		c[(cell(xy[2 * k + 1], s) - 1) * s + cell(xy[2 * k], s) - 1]++;
	for (size_t j = 0; j < s; j++)
		for (size_t i = 1; i < s; i++)
			c[j * s + i] += c[j * s + i - 1];
	for (size_t j = 1; j < s; j++)
		for (size_t i = 0; i < s; i++)
			c[j * s + i] += c[(j - 1) * s + i];
	for (size_t j = 1; j <= s; j++) {
		double yj = (double)j / (double)s;
		for (size_t i = 1; i <= s; i++) {
			double xi = (double)i / (double)s;
			double d = (double)c[(j - 1) * s + i - 1] / (double)n -
			    xi * yj;
			sum += (long double)d * d;
			if (fabs(d) > mx)
				mx = fabs(d);
		}
	}
	free(c);
	*d2 = sqrt((double)(sum / ((long double)s * (long double)s)));
	*dinf = mx;
}

int main(int argc, char **argv)
{
	size_t n;
	double *xy;

	if (argc == 3 && strcmp(argv[1], "warnock") == 0) {
		xy = load(argv[2], &n);
		printf("D2 %.17g\n", warnock(xy, n));
	} else if (argc == 4 && strcmp(argv[1], "stargrid") == 0) {
		char *end;
		unsigned long s = strtoul(argv[2], &end, 10);
		double d2, dinf;
		if (*end || s < 1 || s > 100000)
			die("S: a grid size 1..100000");
		xy = load(argv[3], &n);
		if (n > UINT32_MAX)
			die("too many points");
		stargrid(xy, n, s, &d2, &dinf);
		printf("D2 %.17g\nDinf %.17g\n", d2, dinf);
	} else {
		fprintf(stderr, "usage: ref_disc warnock FILE\n"
		    "       ref_disc stargrid S FILE\n");
		return 2;
	}
	free(xy);
	return 0;
}
