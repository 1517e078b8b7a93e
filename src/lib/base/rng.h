/*
 * Random numbers that are a pure function of (seed, stream, index).
 *
 * The generator is Philox4x32-10 (Salmon et al., "Parallel random numbers:
 * as easy as 1, 2, 3", SC 2011): the key is the 64-bit seed, the 128-bit
 * counter is (index low, index high, stream, 0).  Because a number depends
 * only on its coordinates, results do not depend on thread count, work
 * order or device; OpenCL kernels use the same function.
 *
 * Streams separate independent uses of one seed; each consumer owns one
 * of the FRS_STREAM_* values (cl/defs.cl, which the kernels share) and
 * derives the index from what it randomises (an insertion step, a window
 * element, a point number).
 */
#ifndef FRS_RNG_H
#define FRS_RNG_H

#include <stddef.h>
#include <stdint.h>

/* The public part, API 2.2: frs_philox4x32_10, frs_rand64,
 * frs_rand64x, frs_rand01 and the sequential struct frs_rng with
 * frs_rng_init, _next64, _next01 and _below, declared once, in frs.h
 * (test/t_layout.sh lets this header include it). */
#include "frs.h"
#include "../../../cl/defs.cl"

/* The 53 bits of frs_rand01 as an integer u, the double being u 2^-53:
 * the coin of the thresholding (cl/frs.cl), as cl/rng.cl's frs_rand53. */
static inline uint64_t frs_rand53(uint64_t seed, uint32_t stream,
    uint64_t index)
{
	return frs_rand64(seed, stream, index) >> 11;
}
/* Two uniform doubles in [0, 1) from one block: *a from words 0 and 1,
 * *b from words 2 and 3 (53 bits each). */
void frs_rand01_pair(uint64_t seed, uint32_t stream, uint64_t index,
    double *a, double *b);
/* frs_rand01_pair(seed, stream, index[q], &a[q], &b[q]) for q < n, the
 * same bits, the blocks of 16 indices side by side in vectors. */
void frs_rand01_pair_n(uint64_t seed, uint32_t stream,
    const uint64_t *index, size_t n, double *a, double *b);

#endif
