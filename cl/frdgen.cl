/*
 * Forced Random Dithering on the device (src/frd-gen/frdgencl.c): the force
 * update of one insertion and the minimum of every tile it touched.  The
 * toroidal offsets and reaches are one definition with the CPU
 * (src/frd-gen/frdgen.c includes this file; the kernel is OpenCL's only).
 *
 * The field is stored tile by tile as in src/frd-gen/frdgen.c (tiles of
 * 2^LX x 2^LY x 2^LZ cells, row-major inside a tile, padding cells +inf).
 * One work-group per tile of the insertion's window, one work-item per
 * tile row.  Every cell gets at most one add per insertion, of an entry of
 * the force table computed on the host, so the field holds the same
 * doubles as on the CPU whatever the device: the selection of cells
 * (ranks, ties, random draws) stays on the host.
 *
 * Which cells get a force repeats frdgen.c exactly: the tile's toroidal
 * gap to the centre within r, |dy| <= ey, |dz| <= ez, the x reach of the
 * row (largest e with e^2 <= r^2 - dy^2 - dz^2, capped at w/2), and the
 * x offset taken from the tile's first cell when the window is "fast".
 */
#ifdef __OPENCL_VERSION__
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
#pragma OPENCL FP_CONTRACT OFF
#else
#include <math.h>
#endif

/* Toroidal offset a - c in (-n/2, n/2]. */
FRS_FN FRS_I64 frd_toff(FRS_U32 a, FRS_U32 c, FRS_U32 n)
{
	FRS_I64 d = (FRS_I64)a - (FRS_I64)c;
	if (d > (FRS_I64)(n / 2))
		d -= (FRS_I64)n;
	else if (d <= -(FRS_I64)((n + 1) / 2))
		d += (FRS_I64)n;
	return d;
}

/* Toroidal distance from c to the nearest of the cells [a, b]. */
FRS_FN FRS_U32 frd_tgap(FRS_U32 c, FRS_U32 a, FRS_U32 b, FRS_U32 n)
{
	FRS_I64 da, db;

	if (c >= a && c <= b)
		return 0;
	da = frd_toff(a, c, n);
	db = frd_toff(b, c, n);
	da = da < 0 ? -da : da;
	db = db < 0 ? -db : db;
	return (FRS_U32)(da < db ? da : db);
}

/* Largest e with e^2 <= rr, capped at cap (exact whatever sqrt gives). */
FRS_FN FRS_U32 frd_extent(double rr, FRS_U32 cap)
{
	double e;

	if (rr < 0.0)
		return 0;
	if (rr >= (double)cap * (double)cap)
		return cap;
	e = floor(sqrt(rr));
	while ((e + 1.0) * (e + 1.0) <= rr)
		e += 1.0;
	while (e * e > rr)
		e -= 1.0;
	return (FRS_U32)e;
}

#ifdef __OPENCL_VERSION__
#ifndef FRD_TS
#define FRD_TS 128	/* cells per tile */
#endif
#ifndef FRD_ROWS
#define FRD_ROWS 8	/* rows per tile */
#endif

/*
 * One work-group per tile of the window, one work-item per tile row
 * (FRD_ROWS rows of 2^lg.x cells).
 * dim: w, h, d, 0; hf: w/2, h/2, d/2, 0; nt: tiles per axis, 0;
 * lg: log2 of the tile sides, 0; cen: the cell just taken, 0;
 * first, cnt: the window's tiles per axis, (first + i) mod nt for
 * i < cnt; eyz: ey, ez, fast, 0.  out[2 g], out[2 g + 1]: minimum and
 * count of zero cells of the g-th tile of the window; out[2 G + g TS + i]
 * (G groups): its cells, so that the host reads all in one transfer.
 */
__kernel void frd_add(__global double *field, __global const double *table,
    __global double *out, uint4 dim, uint4 hf, uint4 nt, uint4 lg,
    uint4 cen, uint4 first, uint4 cnt, uint4 eyz, double r2, double sub)
{
	__local double lmin[FRD_ROWS];
	__local uint lzero[FRD_ROWS];
	uint g = (uint)get_group_id(0), l = (uint)get_local_id(0);
	uint gi = g % cnt.x, gj = g / cnt.x % cnt.y, gk = g / cnt.x / cnt.y;
	uint tx = (first.x + gi) % nt.x, ty = (first.y + gj) % nt.y;
	uint tz = (first.z + gk) % nt.z;
	uint sx = 1u << lg.x, sy = 1u << lg.y, sz = 1u << lg.z;
	ulong t = ((ulong)tz * nt.y + ty) * nt.x + tx;
	uint x0 = tx * sx, y0 = ty * sy, z0 = tz * sz;
	uint x1 = min(x0 + sx, dim.x) - 1, y1 = min(y0 + sy, dim.y) - 1;
	uint z1 = min(z0 + sz, dim.z) - 1;
	uint y = y0 + (l & (sy - 1)), z = z0 + (l >> lg.y);
	size_t at = (size_t)t * FRD_TS + (size_t)l * sx;
	__global double *o = out + 2 * get_num_groups(0) + (size_t)g * FRD_TS +
	    (size_t)l * sx;
	double m = INFINITY;
	uint zc = 0;

	if (y <= y1 && z <= z1) {
		ulong gx = frd_tgap(cen.x, x0, x1, dim.x);
		ulong gy = frd_tgap(cen.y, y0, y1, dim.y);
		ulong gz = frd_tgap(cen.z, z0, z1, dim.z);
		long e = -1, dy = frd_toff(y, cen.y, dim.y);
		long dz = frd_toff(z, cen.z, dim.z);
		long ady = dy < 0 ? -dy : dy, adz = dz < 0 ? -dz : dz;
		__global const double *trow = table;

		/* What frdgen.c's add_tile and add_tile_row decide before
		 * the loop over x. */
		if ((double)gx * (double)gx + (double)gy * (double)gy +
		    (double)gz * (double)gz <= r2 && ady <= (long)eyz.x &&
		    adz <= (long)eyz.y) {
			double rr = r2 - (double)(dy * dy) - (double)(dz * dz);
			if (!(rr < 0.0))
				e = (long)frd_extent(rr, hf.x);
			trow = table + ((size_t)adz * (hf.y + 1) + (size_t)ady) *
			    (hf.x + 1);
		}
		for (uint x = x0; x <= x1; x++) {
			size_t i = x - x0;
			double v = field[at + i];
			int w = 0;
			if (x == cen.x && y == cen.y && z == cen.z) {
				v = INFINITY;
				w = 1;
			}
			if (e >= 0) {
				long dx = eyz.z ? frd_toff(x0, cen.x, dim.x) +
				    (long)i : frd_toff(x, cen.x, dim.x);
				dx = dx < 0 ? -dx : dx;
				if (dx <= e) {
					/* frdgen_add: the taper, never below 0 */
					double a = trow[dx] - sub;
					v += a > 0.0 ? a : 0.0;
					w = 1;
				}
			}
			if (w)
				field[at + i] = v;
			o[i] = v;
			m = v < m ? v : m;
			zc += v == 0.0 ? 1u : 0u;
		}
		for (uint x = x1 + 1; x < x0 + sx; x++)
			o[x - x0] = INFINITY;	/* padding */
	} else {
		for (uint i = 0; i < sx; i++)
			o[i] = INFINITY;
	}
	lmin[l] = m;
	lzero[l] = zc;
	barrier(CLK_LOCAL_MEM_FENCE);
	if (l == 0) {
		for (uint i = 1; i < FRD_ROWS; i++) {
			m = lmin[i] < m ? lmin[i] : m;
			zc += lzero[i];
		}
		out[2 * (size_t)g] = m;
		out[2 * (size_t)g + 1] = (double)zc;
	}
}
#endif
