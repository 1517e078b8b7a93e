/*
 * Hierarchical Sample Warping: the descent of one point, one definition
 * for the CPU (src/lib/sample/hsw.c includes this file) and for the
 * device, where one work-item warps one point.  In double on both, so
 * that the points are the CPU's bit for bit.  The quadtree (struct
 * hsw_tree's sums, Morton order per level) is built on the host and
 * uploaded once; the points are warped in place.
 *
 * No contraction of a * b + c into a fused multiply-add: the host does
 * not fuse (and where it might, the products here are exact anyway: f is
 * 0 or 1).  Division and the comparisons are correctly rounded / exact
 * in OpenCL's double precision, and nextafter is exact.
 */
#ifdef __OPENCL_VERSION__
#pragma OPENCL FP_CONTRACT OFF
#ifdef cl_khr_fp64
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
#endif
#else
#include <math.h>
#endif

/* The largest double below 1. */
#define BELOW_ONE 0x1.fffffffffffffp-1

/* Split u in [0,1) between parts of weight a and b: returns 0 (first) or
 * 1, u rescaled to [0,1) of that part.  The test u < a / (a + b) is done
 * as u (a + b) < a, and the selection without branches (the choice is a
 * coin toss the processor cannot predict).  A zero part is never chosen:
 * b = 0 keeps to the first, a = 0 gives u (a + b) >= a always. */
FRS_FN FRS_U32 hsw_split(double a, double b, double *u)
{
	double t = *u * (a + b), num, den, v, f;
	FRS_U32 c = (FRS_U32)(t >= a) & (FRS_U32)(b > 0.0);

	/* Arithmetic, not branches: the processor cannot predict the coin.
	 * 1 * x + 0 * y is exactly x for finite x and y. */
	f = (double)c;
	num = t - f * a;
	den = f * b + (1.0 - f) * a;
	v = num / den;
	*u = v < BELOW_ONE ? v : BELOW_ONE;
	return c;
}

/* (i + u) / n inside pixel i of n: rounding may not move it out. */
FRS_FN double hsw_place(FRS_U32 i, double u, FRS_U32 n)
{
	double x = ((double)i + u) / (double)n;

	while (x * (double)n >= (double)i + 1.0 || x >= 1.0)
		x = nextafter(x, 0.0);
	while (x * (double)n < (double)i)
		x = nextafter(x, 1.0);
	return x;
}

/* Warp the point (*x, *y) in [0,1)^2 by the tree sums sum of `levels`
 * levels over a w x h map; returns the pixel it lands in, j w + i. */
FRS_FN FRS_U64 hsw_descend(FRS_GLOBAL const double *sum, FRS_U32 levels,
    FRS_U32 w, FRS_U32 h, double *x, double *y)
{
	FRS_U64 k = 0, off = 0;
	FRS_U32 i = 0, j = 0;
	double u = *x, v = *y;

	for (FRS_U32 l = 0; l < levels; l++) {
		FRS_GLOBAL const double *c;
		FRS_U32 cx, cy;

		off += (FRS_U64)1 << (2 * l);	/* start of level l + 1 */
		c = sum + off + 4 * k;
		cx = hsw_split(c[0] + c[2], c[1] + c[3], &u);
		cy = hsw_split(c[cx], c[cx + 2], &v);
		k = 4 * k + 2 * cy + cx;
		i = 2 * i + cx;
		j = 2 * j + cy;
	}
	*x = hsw_place(i, u, w);
	*y = hsw_place(j, v, h);
	return (FRS_U64)j * w + i;
}

#ifdef __OPENCL_VERSION__
/* Warp points pts[0..n-1] (pairs x, y) in place. */
__kernel void hsw_warp(__global const double *sum, uint levels, uint w,
    uint h, __global double *pts, ulong n)
{
	ulong p = get_global_id(0);
	double x, y;

	if (p >= n)
		return;
	x = pts[2 * p];
	y = pts[2 * p + 1];
	hsw_descend(sum, levels, w, h, &x, &y);
	pts[2 * p] = x;
	pts[2 * p + 1] = y;
}
#endif
