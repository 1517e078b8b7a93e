/*
 * Void-and-cluster threshold matrices (R. Ulichney, "The void-and-cluster
 * method for dither array generation", Proc. SPIE 1913, 1993), the
 * blue-noise baseline of frd-gen --method vac.
 *
 * The energy of a cell c is the Gaussian filter of the binary pattern,
 *
 *     E(c) = sum over the 1-cells o of  K(c - o),
 *     K(v) = exp(-|v|^2 / (2 sigma^2)),
 *
 * |v| the toroidal distance, the cell's own 1 included (K(0) = 1).  The
 * "tightest cluster" is the 1 of highest energy, the "largest void" the
 * 0 of lowest energy.
 *
 *   0. Initial pattern: ceil(N/10) cells (at least 1), the first ones of a
 *      Fisher-Yates shuffle of 0 .. N-1 drawn from the seed
 *      (vac_initial_cells).  Then, repeatedly, the tightest cluster is
 *      removed and a 1 put into the largest void of what is left, until
 *      that void is where the 1 came from (at most N moves).
 *   1. From that pattern, tightest clusters are removed one by one; they
 *      get the ranks ones-1 down to 0.
 *   2. From that pattern again, largest voids are filled one by one: ranks
 *      ones .. N/2-1.
 *   3. Ranks N/2 .. N-1: the 0 with the highest "zero energy" (the filter
 *      of the pattern of 0s: the tightest cluster of the minority pixels)
 *      becomes 1.  The zero energy is sum K - E(c), the same for every c
 *      on the torus, so this is again the 0 of lowest E: phase 3 is the
 *      phase-2 loop run on.  (test_vac checks this against an oracle that
 *      computes the zero energies.)
 *
 * Energies are integers: K is quantised to K_q(v) = round(2^S K(v)), S =
 * 61 - e where 2^(e-1) <= B < 2^e and B = prod over the axes of min(size,
 * 1 + sqrt(2 pi) sigma), a bound of sum K over the torus, so that no sum
 * can overflow.  Integer sums are exact, so adding the kernel of one
 * flipped cell gives the same energies as recomputing them, whatever the
 * order: the incremental generator and a brute-force recomputation pick
 * the same cells, and "sum K - E" above is exact.  Ties (equal energies)
 * go to the cell of lowest tie key (vac_tiekey, a random function of seed
 * and cell), then to the lowest index.
 *
 * Truncation: with tol > 0, K is 0 where K < tol, i.e. past the radius
 * sigma sqrt(2 ln(1/tol)) (6.4 cells for the default 1e-4 and sigma 1.5).
 * tol = 0 keeps the whole torus; the kernel is then applied only where
 * K_q is not 0 (within about 13 cells at sigma 1.5), which changes no
 * energy.  Each flip updates the energies of the cells within reach and
 * the two tournament trees (max over the 1s, min over the 0s) above them,
 * one contiguous run of leaves per row of the window: O(R^k log N) per
 * step, O(N R^k log N) in all.  One thread; the result depends only on
 * the parameters.
 */
#ifndef FRS_VAC_H
#define FRS_VAC_H

#include <stddef.h>
#include <stdint.h>

#include "frs.h"	/* struct frs_matrix */

struct cli_task;

struct vac_params {
	unsigned dims;		/* 2 or 3 */
	uint32_t w, h, d;	/* d = 1 for dims = 2 */
	double sigma;		/* Gaussian filter, cells */
	double tol;		/* K = 0 where K < tol; 0: whole torus */
	uint64_t seed;
};

struct vac_stats {
	uint64_t ones;		/* cells of the initial pattern */
	uint64_t moves;		/* cluster-to-void moves of phase 0 */
	double radius;		/* reach of the kernel applied, cells */
};

#define VAC_DEFAULT_SIGMA 1.5
#define VAC_DEFAULT_TOL 1e-4

/* sigma 1.5, tol 1e-4, seed 1. */
void vac_defaults(struct vac_params *pr);
/* Check a parameter set; the message names the offending option. */
int vac_check(const struct vac_params *pr);
/* The truncation radius sigma sqrt(2 ln(1/tol)); INFINITY for tol = 0. */
double vac_radius(const struct vac_params *pr);
/* S of the quantisation above. */
int vac_scale_bits(const struct vac_params *pr);
/* Bytes a run needs, to refuse impossible sizes up front. */
uint64_t vac_memory(const struct vac_params *pr);
/* The parameter text stored in the .frd header (method=vac). */
void vac_describe(const struct vac_params *pr, char *buf, size_t n);

/* Generate; out is allocated.  task (cli.h: the progress bar's) and st
 * may be NULL. */
int vac_run(const struct vac_params *pr, struct frs_matrix *out,
    struct cli_task *task, struct vac_stats *st);

/* The size of the initial pattern: ceil(n / 10), at least 1. */
uint64_t vac_ones(uint64_t n);
/* perm (n = w h d entries) becomes a permutation of 0 .. n-1 whose first
 * vac_ones(n) entries are the cells of the initial pattern. */
void vac_initial_cells(const struct vac_params *pr, uint32_t *perm);
/* The tie key of cell c: lower wins among equal energies. */
uint32_t vac_tiekey(const struct vac_params *pr, uint32_t c);

#endif
