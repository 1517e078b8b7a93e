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

#include "../../../cl/defs.cl"

/* One Philox4x32-10 block. */
void frs_philox4x32_10(const uint32_t ctr[4], const uint32_t key[2],
    uint32_t out[4]);

/* 64 random bits at (seed, stream, index): words 0 and 1 of the block. */
uint64_t frs_rand64(uint64_t seed, uint32_t stream, uint64_t index);
/* The same with a fourth counter word, for two-index uses such as
 * (insertion step, cell). */
uint64_t frs_rand64x(uint64_t seed, uint32_t stream, uint64_t index,
    uint32_t sub);
/* Uniform double in [0, 1) with 53 random bits. */
double frs_rand01(uint64_t seed, uint32_t stream, uint64_t index);
/* Its 53 bits as an integer u, the double being u 2^-53: the coin of
 * the thresholding (cl/frs.cl), as cl/rng.cl's frs_rand53. */
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

/* A sequential stream over indices 0, 1, 2, ... of one (seed, stream), for
 * code whose order is fixed.  Each index gives 64 bits. */
struct frs_rng {
	uint64_t seed;
	uint64_t index;
	uint32_t stream;
};

void frs_rng_init(struct frs_rng *r, uint64_t seed, uint32_t stream);
uint64_t frs_rng_next64(struct frs_rng *r);
double frs_rng_next01(struct frs_rng *r);
/* Uniform integer in [0, bound), bound > 0, without modulo bias. */
uint64_t frs_rng_below(struct frs_rng *r, uint64_t bound);

#endif
