/*
 * Forced Random Sampling in three dimensions: threshold a window of the
 * tiled 3-D FRD matrix against importance * tau (the thesis's k-D claim,
 * Sec. 4.1, made concrete).
 *
 * Setup, the 2-D rule of frscore.h with cubes for squares: with the
 * volume's mean mu and maximum m, the window's element count must reach
 * sigma^3 n m / mu, so that at most one of sigma^3 elements passes at the
 * maximum; n_s, the window elements per voxel and side, is the smallest
 * power of two with (n_s s)^3 a >= sigma^3 n m / mu, s the volume's
 * smallest side and a = W H D / s^3; the window is n_s W x n_s H x n_s D,
 * offset per axis by a random multiple of n_s (of the matrix side when
 * n_s exceeds it), and tau = n S_M / (S_W mu) with S_M, S_W the element
 * counts of matrix and window.
 *
 * Thresholds, coins, progressive steps and jitter work as in 2-D; a
 * window element (x, y, z) has the id (z S_H + y) S_W,x + x for its coin
 * and jitter.  Two implementations: naive (every element of a voxel) and
 * sorted (the values of each matrix block of b^3 elements, b = min(n_s,
 * matrix sides), in ascending order: a voxel costs a bisection per block
 * and then only the elements that pass).  Both give the same elements in
 * the same order as the naive one up to order inside a voxel block.
 */
#ifndef FRS_FRS3_H
#define FRS_FRS3_H

#include <stdint.h>

#include "formats/frdio.h"
#include "sample/frscore.h"
#include "maps/vol.h"

struct frs3_setup {
	uint32_t iw, ih, id;	/* volume */
	uint32_t mw, mh, md;	/* matrix */
	uint64_t n;
	double sigma;
	double mean, max;	/* of the volume */
	uint32_t ns;
	uint64_t sw, sh, sd;	/* window */
	uint64_t wx, wy, wz;	/* its offset in the tiled matrix */
	double tau;
	uint64_t seed;
	enum frs_rule rule;
	enum frs_place jitter;
	enum frs_tiling tiles;	/* shuffled: 48 symmetries of a cube */
	double iscale, imean;	/* as in struct frs_setup */
	struct frs_xtau exact;	/* as in struct frs_setup */
	/* The multi-level window, as in struct frs_setup: lfac = 8^l. */
	unsigned level;
	double lfac;
	uint64_t sw0, sh0, sd0;
	const uint8_t *lev;	/* as in struct frs_setup, per voxel */
	uint64_t cell0, cell1;	/* as in struct frs_setup */
};

/* The volume must be validated (finite, >= 0, not all zero). */
int frs3_setup(struct frs3_setup *s, const struct frs_vol *vol,
    const struct frs_matrix *mat, uint64_t n, double sigma, uint64_t seed);
double frs3_tau(const struct frs3_setup *s, uint64_t n);
/* Level l (>= 1) of the multi-level window of s0 (level 0's setup):
 * frs_level_setup in 3-D, thresholds times 8^l. */
void frs3_level_setup(struct frs3_setup *s, const struct frs3_setup *s0,
    unsigned l, double max);
/* Samples the matrix gives without repetition: S_M / sigma^3. */
double frs3_unique(const struct frs3_setup *s);
/* Block side of the sorted lists that fit this setup (and its tiling). */
uint32_t frs3_block(const struct frs3_setup *s);

struct frs3_prep {
	const struct frs_matrix *m;
	uint32_t block;		/* 0: none (naive only) */
	uint32_t *sval, *sidx;	/* per block, ascending values, in-block index */
};

/* Sorted lists of blocks of b^3 (b a power of two dividing the matrix
 * sides, which must be powers of two); b = 0 prepares nothing. */
int frs3_prepare(struct frs3_prep *p, const struct frs_matrix *m, uint32_t b);
void frs3_prep_free(struct frs3_prep *p);
/* s->exact for steps (the last s->n, the rule unbiased) by count passes
 * over the window with p (Sorted when p has lists, else Naive); s->tau
 * the last step's.  See frs_exact_taus. */
int frs3_exact(struct frs3_setup *s, const struct frs_vol *vol,
    const struct frs3_prep *p, const uint64_t *steps, unsigned nsteps);

struct frs3_elem {
	uint32_t x, y, z;
	uint32_t step;
};

/* Elements per slice of voxels, in slice order (any thread count). */
struct frs3_chunk {
	struct frs3_elem *e;
	uint64_t n, cap, count;
	int failed;
};

struct frs3_result {
	struct frs3_chunk *chunk;
	uint64_t nchunk;
	uint64_t count;
};

/* algo: FRS_NAIVE or FRS_SORTED (p->block must fit the setup). */
int frs3_sample(const struct frs3_setup *s, const struct frs_vol *vol,
    const struct frs3_prep *p, enum frs_impl algo, const uint64_t *steps,
    unsigned nsteps, int count_only, struct frs3_result *r);
void frs3_result_free(struct frs3_result *r);

/* Visit the elements in output order: the steps in turn, each in slice
 * order (as frs-sample writes them); fn returns non-zero to stop, and
 * that value is returned. */
int frs3_each(const struct frs3_result *r, unsigned nsteps,
    int (*fn)(void *ctx, const struct frs3_elem *e), void *ctx);

/* The point of an element in [0, 1)^3, with the setup's jitter. */
void frs3_point(const struct frs3_setup *s, const struct frs3_elem *e,
    double p[3]);
/* Its density over the unit cube: I / mean I. */
double frs3_pdf(const struct frs3_setup *s, const struct frs_vol *vol,
    const struct frs3_elem *e);

#endif
