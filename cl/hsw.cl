/*
 * Hierarchical Sample Warping on the device: one work-item per point,
 * the same descent as hsw_warp in src/lib/sample/hsw.c, operation for
 * operation, in double, so that the points are the CPU's bit for bit.
 * The quadtree (struct hsw_tree's sums, Morton order per level) is built
 * on the host and uploaded once; the points are warped in place.
 *
 * No contraction of a * b + c into a fused multiply-add: the host does
 * not fuse (and where it might, the products here are exact anyway:
 * f is 0 or 1).  Division and the comparisons are correctly rounded /
 * exact in OpenCL's double precision, and nextafter is exact.
 */
#pragma OPENCL FP_CONTRACT OFF
#ifdef cl_khr_fp64
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
#endif

/* The largest double below 1 (0x1.fffffffffffffp-1). */
#define HSW_BELOW_ONE as_double(0x3FEFFFFFFFFFFFFFUL)

/* split in hsw.c: returns 0 or 1, *u rescaled to [0,1) of that part. */
uint hsw_split(double a, double b, double *u)
{
	double t = *u * (a + b), num, den, v, f;
	uint c = (uint)(t >= a) & (uint)(b > 0.0);

	f = (double)c;
	num = t - f * a;
	den = f * b + (1.0 - f) * a;
	v = num / den;
	*u = v < HSW_BELOW_ONE ? v : HSW_BELOW_ONE;
	return c;
}

/* place in hsw.c: (i + u) / n, kept inside pixel i of n. */
double hsw_place(uint i, double u, uint n)
{
	double x = ((double)i + u) / (double)n;

	while (x * (double)n >= (double)i + 1.0 || x >= 1.0)
		x = nextafter(x, 0.0);
	while (x * (double)n < (double)i)
		x = nextafter(x, 1.0);
	return x;
}

/* Warp points pts[0..n-1] (pairs x, y) in place by the tree sum of
 * `levels` levels over a w x h map. */
__kernel void hsw_warp(__global const double *sum, uint levels, uint w,
    uint h, __global double *pts, ulong n)
{
	ulong p = get_global_id(0), k = 0, off = 0;
	uint i = 0, j = 0;
	double u, v;

	if (p >= n)
		return;
	u = pts[2 * p];
	v = pts[2 * p + 1];
	for (uint l = 0; l < levels; l++) {
		__global const double *c;
		uint cx, cy;

		off += (ulong)1 << (2 * l);	/* start of level l + 1 */
		c = sum + off + 4 * k;
		cx = hsw_split(c[0] + c[2], c[1] + c[3], &u);
		cy = hsw_split(c[cx], c[cx + 2], &v);
		k = 4 * k + 2 * cy + cx;
		i = 2 * i + cx;
		j = 2 * j + cy;
	}
	pts[2 * p] = hsw_place(i, u, w);
	pts[2 * p + 1] = hsw_place(j, v, h);
}
