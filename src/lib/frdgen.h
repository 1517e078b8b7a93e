/*
 * Forced Random Dithering matrices (thesis ch. 3, Listing 3.1).
 *
 * The values 0 .. N-1 are inserted one by one into a toroidal force field.
 * Value i goes to the cell with the smallest accumulated force among a
 * random Bernoulli(p) subset of the free cells; then every cell within the
 * insertion's radius gets f(r) = exp(-(r/s)^q) added, r the toroidal
 * distance in cells.
 *
 * The minimum over a Bernoulli(p) subset is, in law, the K-th smallest free
 * cell with K ~ Geometric(p) (truncated to the free count), which needs
 * only the few smallest cells: a min-pyramid over tiles of cells finds
 * them.  Ties in the force (exact equality) are broken by a random key per
 * (insertion, cell).  Cells that no force has reached yet hold exactly 0,
 * and early on they are most of the matrix: while there are any, the value
 * goes to one of them drawn uniformly (frdgen_zerorank), the r-th in the
 * order of frdgen_cellorder, found through per-tile counts in O(log N).  Every random number is a function of (seed, step),
 * and every cell gets one double add per insertion, in insertion order, so
 * the result is the same for any thread count.
 *
 * Accuracy: contributions below tol * f(0) may be neglected, i.e. the
 * radius is s * ln(1/tol)^(1/q).  Early insertions are far apart, so the
 * radius also grows to reach * (expected spacing of the values inserted so
 * far), so that the field is never zero in a gap and the first values are
 * spread evenly however large the matrix.  Not much further, though: a
 * field exact to several spacings makes every value go to the centre of
 * the largest gap, and the values crystallise into a lattice (spectral
 * peaks of 7 to 30 times the plateau at reach 3; about 2 at 0.7, where
 * the thesis authors' matrix has 1.4 to 1.7).  tol = 0 keeps every
 * contribution (the full torus for every insertion, O(N^2)).
 */
#ifndef FRS_FRDGEN_H
#define FRS_FRDGEN_H

#include <stdint.h>

#include "frdio.h"

struct progress;

struct frdgen_params {
	unsigned dims;		/* 2 or 3 */
	uint32_t w, h, d;	/* d = 1 for dims = 2 */
	double p;		/* candidate fraction, (0, 1] */
	double s, q;		/* force f(r) = exp(-(r/s)^q) */
	double tol;		/* neglect f < tol * f(0); 0: exact */
	double reach;		/* radius >= reach * spacing; 0: off */
	uint64_t seed;
	const char *checkpoint;	/* resume from / save to this file, or NULL */
	double checkpoint_every;	/* seconds between checkpoints */
};

/* Defaults: s = q = 1/2, p = 1/2, the default tolerance, reach 0.7. */
void frdgen_defaults(struct frdgen_params *pr);
/* Check dimension count and sizes (also for frd-gen --method vac). */
int frdgen_check_size(unsigned dims, uint32_t w, uint32_t h, uint32_t d);
/* Check a parameter set; the message names the offending parameter. */
int frdgen_check(const struct frdgen_params *pr);
/* The neglect radius for a tolerance (cells), INFINITY for tol = 0. */
double frdgen_radius(const struct frdgen_params *pr);
/* Bytes of memory a run needs, to refuse impossible sizes up front. */
uint64_t frdgen_memory(const struct frdgen_params *pr);
/* The parameter text stored in the .frd header. */
void frdgen_describe(const struct frdgen_params *pr, char *buf, size_t n);

/* Generate; out is allocated.  pr may be NULL. */
int frdgen_run(const struct frdgen_params *par, struct frs_matrix *out,
    struct progress *pr);

/* Force of the default kernel at distance r (tests use it). */
double frdgen_force(const struct frdgen_params *pr, double r);
/* The truncated Geometric(p) rank K in [1, free] that insertion step
 * "step" uses (tests use it). */
uint64_t frdgen_rank(const struct frdgen_params *pr, uint64_t step,
    uint64_t free);
/* The tie key of cell c at insertion step "step". */
uint64_t frdgen_tiekey(const struct frdgen_params *pr, uint64_t step,
    uint32_t c);
/* Which of z zero-force cells step "step" takes (0 .. z-1). */
uint64_t frdgen_zerorank(const struct frdgen_params *pr, uint64_t step,
    uint64_t z);
/* The order in which zero cells are counted: tile by tile (tiles of
 * 16 x 8 cells in 2-D, 8 x 4 x 4 in 3-D, in row-major order of tiles),
 * row-major inside a tile.  Returns the sort key of cell c. */
uint64_t frdgen_cellorder(const struct frdgen_params *pr, uint32_t c);

#endif
