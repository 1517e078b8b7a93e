/*
 * The matrix prepared for the thresholding of frscore.h (frsprep.c):
 * the minmap levels that Stack, Level N and Flat 1 walk and the
 * block-sorted lists that Sorted reads, made once a matrix and kept
 * (api/mask.c, .frp files of frpio.h).
 */
#ifndef FRS_FRSPREP_H
#define FRS_FRSPREP_H

#include <stdint.h>

#include "formats/frdio.h"

/* The matrix prepared for the implementations: minmap levels and
 * block-sorted lists. */
struct frs_prep {
	const struct frs_matrix *m;
	unsigned nlev;		/* levels 0 (the matrix) .. nlev - 1 */
	uint32_t *lev[32];	/* level l: (mw >> l) x (mh >> l) minima */
	uint32_t block;		/* block size of the sorted lists, 0: none */
	uint32_t *sval;		/* per block, ascending values */
	uint32_t *sidx;		/* and their index inside the block */
	uint32_t *soff;		/* block k's list: soff[k] .. soff[k + 1] - 1 */
	uint64_t below;		/* the lists hold every value below this */
};

/* frs_prepare_below's bound for complete lists. */
#define FRS_ALL_VALUES UINT64_MAX

/* Build the minmap (stack, levels) and, when block > 0, the sorted lists
 * of blocks x blocks (sorted).  Power-of-two matrices only. */
int frs_prepare(struct frs_prep *p, const struct frs_matrix *m,
    int minmap, uint32_t block);
/* The same with lists of the values below below only: a run whose thresholds stay
 * under it (frs_lim_most) reads nothing else, and they cost a pass over
 * the matrix and O(below), not O(S_M^2).  Complete lists when below is
 * half the matrix's values or more, or when the values below repeat and
 * the lists come through the inverse (by_bands in frsprep.c chooses). */
int frs_prepare_below(struct frs_prep *p, const struct frs_matrix *m,
    int minmap, uint32_t block, uint64_t below);
/* Below this many values (or with many small blocks) the partial lists
 * are dealt in one serial pass, else counted in parallel; tests lower it
 * to take both ways. */
extern uint64_t frs_deal_below;
void frs_prep_free(struct frs_prep *p);

#endif
