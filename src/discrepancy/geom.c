/*
 * Exact signs by a floating-point filter and, when the filter cannot
 * decide, an exact sum of the expression's terms as a nonoverlapping
 * expansion (Shewchuk 1997, grow-expansion with zero elimination).
 */
#define _POSIX_C_SOURCE 200809L
#include "discrepancy/geom.h"

static void two_diff(double a, double b, double *hi, double *lo)
{
	double x = a - b, bv = a - x, av = x + bv;
	*hi = x;
	*lo = (a - av) + (bv - b);
}

/* Append the exact product a * b as two terms. */
static int put_prod(double *t, int k, double a, double b)
{
	double p = a * b;
	t[k] = p;
	t[k + 1] = fma(a, b, -p);
	return k + 2;
}

/* Exact sign of t[0] + ... + t[k-1]. */
static int sum_sign(const double *t, int k)
{
	double e[40];
	int m = 0;

	for (int i = 0; i < k; i++) {
		double q = t[i];
		int mm = 0;
		for (int j = 0; j < m; j++) {
			double s = q + e[j], bv = s - q, av = s - bv;
			double h = (q - av) + (e[j] - bv);
			q = s;
			if (h != 0.0)
				e[mm++] = h;
		}
		if (q != 0.0)
			e[mm++] = q;
		m = mm;
	}
	return m == 0 ? 0 : e[m - 1] > 0.0 ? 1 : -1;
}

/* Exact sign of (u1 + u0)(v1 + v0) - (w1 + w0)(z1 + z0). */
static int det_sign(double u1, double u0, double v1, double v0, double w1,
    double w0, double z1, double z0)
{
	double t[16];
	int k = 0;

	k = put_prod(t, k, u1, v1);
	k = put_prod(t, k, u1, v0);
	k = put_prod(t, k, u0, v1);
	k = put_prod(t, k, u0, v0);
	k = put_prod(t, k, -w1, z1);
	k = put_prod(t, k, -w1, z0);
	k = put_prod(t, k, -w0, z1);
	k = put_prod(t, k, -w0, z0);
	return sum_sign(t, k);
}

int geom_orient_exact(double ax, double ay, double bx, double by, double px,
    double py)
{
	double u1, u0, v1, v0, w1, w0, z1, z0;

	two_diff(bx, ax, &u1, &u0);
	two_diff(py, ay, &v1, &v0);
	two_diff(by, ay, &w1, &w0);
	two_diff(px, ax, &z1, &z0);
	return det_sign(u1, u0, v1, v0, w1, w0, z1, z0);
}

/* Append -(d1 + d0)^2 as six terms. */
static int put_neg_square(double *t, int k, double d1, double d0)
{
	k = put_prod(t, k, -d1, d1);
	k = put_prod(t, k, -2.0 * d1, d0);
	return put_prod(t, k, -d0, d0);
}

int geom_incircle_exact(double ex, double ey, double r, double px,
    double py)
{
	double t[14], x1, x0, y1, y0;
	int k;

	two_diff(px, ex, &x1, &x0);
	two_diff(py, ey, &y1, &y0);
	k = put_prod(t, 0, r, r);
	k = put_neg_square(t, k, x1, x0);
	k = put_neg_square(t, k, y1, y0);
	return sum_sign(t, k);
}
