/*
 * Brute-force references of the grid discrepancies (test_disc,
 * test_disc3 and test/hard/test_hard_disc): every corner or box of the
 * grid, every point, in long double.  The oracle the fast methods of disc.c are
 * checked against.
 */
#ifndef FRS_DISCREF_H
#define FRS_DISCREF_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

/* Star grid: corners (i/s, j/s), i, j = 1..s, boxes [0,x) x [0,y). */
static inline void ref_star_grid(const double *xy, size_t n, uint32_t s,
    double *d2, double *dinf)
{
	long double sum = 0;

	*dinf = 0;
	for (uint32_t i = 1; i <= s; i++)
		for (uint32_t j = 1; j <= s; j++) {
			double x = (double)i / s, y = (double)j / s, d;
			size_t c = 0;
			for (size_t k = 0; k < n; k++)
				c += xy[2 * k] < x && xy[2 * k + 1] < y;
			d = fabs((double)c / (double)n - x * y);
			sum += (long double)d * d;
			*dinf = d > *dinf ? d : *dinf;
		}
	*d2 = (double)sqrtl(sum / ((long double)s * s));
}

/* Rect grid: lines a/(s-1), boxes [x0,x1) x [y0,y1) between them. */
static inline void ref_rect_grid(const double *xy, size_t n, uint32_t s,
    double *d2, double *dinf)
{
	long double sum = 0, cnt = 0;

	*dinf = 0;
	for (uint32_t a = 0; a < s; a++)
	for (uint32_t b = a + 1; b < s; b++)
	for (uint32_t c = 0; c < s; c++)
	for (uint32_t e = c + 1; e < s; e++) {
		double x0 = (double)a / (s - 1), x1 = (double)b / (s - 1);
		double y0 = (double)c / (s - 1), y1 = (double)e / (s - 1), d;
		size_t m = 0;
		for (size_t k = 0; k < n; k++)
			m += xy[2 * k] >= x0 && xy[2 * k] < x1 &&
			    xy[2 * k + 1] >= y0 && xy[2 * k + 1] < y1;
		d = fabs((double)m / (double)n - (x1 - x0) * (y1 - y0));
		sum += (long double)d * d, cnt++;
		*dinf = d > *dinf ? d : *dinf;
	}
	*d2 = (double)sqrtl(sum / cnt);
}

/* 3-D star grid: corners (i/s, j/s, l/s), i, j, l = 1..s, boxes
 * [0,x) x [0,y) x [0,z), every point counted in every box. */
static inline void ref_star_grid3(const double *xyz, size_t n, uint32_t s,
    double *d2, double *dinf)
{
	long double sum = 0;

	*dinf = 0;
	for (uint32_t i = 1; i <= s; i++)
	for (uint32_t j = 1; j <= s; j++)
	for (uint32_t l = 1; l <= s; l++) {
		double x = (double)i / s, y = (double)j / s, z = (double)l / s;
		double d;
		size_t c = 0;
		for (size_t k = 0; k < n; k++)
			c += xyz[3 * k] < x && xyz[3 * k + 1] < y &&
			    xyz[3 * k + 2] < z;
		d = fabs((double)c / (double)n - x * y * z);
		sum += (long double)d * d;
		*dinf = d > *dinf ? d : *dinf;
	}
	*d2 = (double)sqrtl(sum / ((long double)s * s * s));
}

/* Sets for the pair-sum tests, n points of k coordinates in x: kind 0
 * uniform random, 1 Halton-like (radical inverses, bases 2, 3, 5, 7,
 * shifted by the index seed), 2 ties (coordinates in eighths: equal
 * values, duplicate points, points on 0), 3 the hard ones together:
 * random with every third point's first coordinate 0, every fourth
 * point a copy of the one before, and the largest double below 1.
 * splitmix64 for the random numbers: nothing shared with the library. */
static inline double ref_u01(uint64_t *s)
{
	uint64_t z = (*s += 0x9e3779b97f4a7c15u);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
	return (double)((z ^ (z >> 31)) >> 11) * 0x1p-53;
}

static inline double ref_radical(uint64_t i, unsigned b)
{
	double f = 1, r = 0;
	for (; i > 0; i /= b) {
		f /= b;
		r += f * (double)(i % b);
	}
	return r;
}

static inline void ref_pair_set(double *x, size_t n, unsigned k, int kind,
    uint64_t seed)
{
	static const unsigned base[] = { 2, 3, 5, 7 };

	for (size_t i = 0; i < n; i++)
		for (unsigned d = 0; d < k; d++) {
			double v = ref_u01(&seed);
			if (kind == 1)
				v = ref_radical(i + seed % 97, base[d % 4]);
			else if (kind == 2)
				v = floor(v * 8) / 8;
			x[k * i + d] = v;
		}
	if (kind != 3)
		return;
	for (size_t i = 0; i < n; i++) {
		if (i % 3 == 0)
			x[k * i] = 0.0;
		if (i % 4 == 3)
			for (unsigned d = 0; d < k; d++)
				x[k * i + d] = x[k * (i - 1) + d];
	}
	x[k - 1] = nextafter(1.0, 0.0);
}

/* D2^2 of the L2 star discrepancy of n points of k coordinates by
 * Warnock's formula as written, every ordered pair, in long double with
 * a compensated (Kahan) sum of the pairs: O(n^2), the oracle of the
 * O(n log n) and O(n log^2 n) pair sums of disc.c and disc3.c. */
static inline long double ref_warnock_sq(const double *x, size_t n,
    unsigned k)
{
	long double s1 = 0, s2 = 0, c = 0, t3 = 1, t2 = 1;

	for (unsigned d = 0; d < k; d++)
		t3 /= 3, t2 /= 2;
	for (size_t i = 0; i < n; i++) {
		long double p = 1;
		for (unsigned d = 0; d < k; d++) {
			long double v = x[k * i + d];
			p *= 1 - v * v;
		}
		s1 += p;
		for (size_t j = 0; j < n; j++) {
			long double q = 1, y, t;
			for (unsigned d = 0; d < k; d++)
				q *= 1 - fmaxl(x[k * i + d], x[k * j + d]);
			y = q - c;
			t = s2 + y;
			c = (t - s2) - y;
			s2 = t;
		}
	}
	return t3 - 2 * t2 * s1 / n + s2 / ((long double)n * n);
}

#endif
