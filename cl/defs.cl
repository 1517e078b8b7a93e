/*
 * What the C side and the OpenCL kernels both name, defined once in the
 * common subset of C and OpenCL C: every kernel source is built after
 * this one (src/lib/base/ocl.c), and src/lib/base/rng.h includes it.
 *
 * The random streams: a pure function of (seed, stream, index) gives
 * the same numbers on the CPU and on every device (src/lib/base/rng.h),
 * so each consumer owns one stream and both sides must agree on it.
 */
#ifndef FRS_DEFS_CL
#define FRS_DEFS_CL

enum {
	FRS_STREAM_TEST = 0,
	FRS_STREAM_FRD_COIN = 1,	/* frd-gen candidate selection */
	FRS_STREAM_FRD_TIE = 2,		/* frd-gen tie breaking */
	FRS_STREAM_WINDOW = 3,		/* frs window offset */
	FRS_STREAM_JITTER = 4,		/* frs jitter, per window element */
	FRS_STREAM_COIN = 5,		/* frs fractional threshold coin */
	FRS_STREAM_REF = 6,		/* reference samplers */
	FRS_STREAM_HSW = 7,		/* hierarchical sample warping */
	FRS_STREAM_SHAPES = 8,		/* discrepancy random shapes */
	FRS_STREAM_SET = 9,		/* per-set seeds of repeated runs */
	FRS_STREAM_FRD_DRAW = 10,	/* frd-gen cells drawn for large ties */
	FRS_STREAM_TILE = 11,		/* shuffled tiles (cl/tile.cl) */
	FRS_STREAM_LEVEL = 12,		/* seeds of the multi-level window's
					   levels (levels.h) */
	FRS_STREAM_PLACE = 13		/* the level-0 element a coarser
					   level's sample goes to */
};

/* Types and qualifiers for code written once for both sides (cl/tile.cl,
 * cl/frs.cl, the CPU twins in cl/hsw.cl and cl/frdgen.cl).  FRS_GLOBAL: a pointer
 * the kernel passes from a buffer (OpenCL C 1.2 has no generic address
 * space). */
#ifdef __OPENCL_VERSION__
#define FRS_U32 uint
#define FRS_U64 ulong
#define FRS_I64 long
#define FRS_FN static
#define FRS_GLOBAL __global
#else
#include <stdint.h>
#define FRS_U32 uint32_t
#define FRS_U64 uint64_t
#define FRS_I64 int64_t
#define FRS_FN static inline
#define FRS_GLOBAL
#endif

/*
 * Forced Random Sampling on OpenCL (cl/frs.cl, src/lib/sample/frscl.c):
 * the host turns each active pixel's thresholds into integers
 * (frs_thr_words, the words the CPU's walks read too), so that no
 * floating point happens on the device.  The record of an active
 * pixel, FRSCL_RECORD(nsteps) words, holds
 *   FRSCL_REC_PIXEL      px | py << 32, the pixel
 *   FRSCL_REC_LIM        values from lim never pass (last step)
 *   FRSCL_REC_TF(k)      values below tf_k pass at step k
 *   FRSCL_REC_COIN(k)    v == tf_k passes when the 53-bit coin < c_k
 *                        (c_k = ceil(frac_k 2^53); 0: never)
 */
#define FRSCL_REC_PIXEL 0
#define FRSCL_REC_LIM 1
#define FRSCL_REC_TF(k) (2 + 2 * (k))
#define FRSCL_RECORD(nsteps) (2 + 2 * (nsteps))

/* The words of the run's setup, the first argument of every frs kernel. */
enum {
	FRSCL_SW,		/* window width, the coins' row stride */
	FRSCL_NS,		/* window elements per pixel side, n_s */
	FRSCL_WX, FRSCL_WY,	/* window offset */
	FRSCL_MW, FRSCL_MH,	/* matrix size */
	FRSCL_SEED,
	FRSCL_NSTEPS,		/* progressive steps */
	FRSCL_NACT,		/* active pixels: records */
	FRSCL_START,		/* start level; Sorted: the block side */
	FRSCL_TILES,		/* 1: shuffled tiles (cl/tile.cl), 0: plain */
	FRSCL_NSETUP
};

#endif
