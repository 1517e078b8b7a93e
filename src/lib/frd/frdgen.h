/*
 * Forced Random Dithering matrices (thesis ch. 3, Listing 3.1).
 *
 * The values 0 .. N-1 are inserted one by one into a toroidal force field.
 * Value i goes to the cell with the smallest accumulated force among a
 * random Bernoulli(p) subset of the free cells; then every cell within the
 * insertion's radius gets the force f(r) added, r the toroidal distance
 * in cells.
 *
 * The minimum over a Bernoulli(p) subset is, in law, the K-th smallest free
 * cell with K ~ Geometric(p) (truncated to the free count), which needs
 * only the few smallest cells: a min-pyramid over tiles of cells finds
 * them.  Ties in the force (exact equality) are broken by a random key per
 * (insertion, cell).  Cells that no force has reached yet hold exactly 0,
 * and early on they are most of the matrix: the value goes to one of them
 * (see Selection below), the r-th in the order of frdgen_cellorder, found
 * through per-tile counts in O(log N).  Every random number is a function
 * of (seed, step), and every cell gets one double add per insertion, in
 * insertion order, so the result is the same for any thread count.
 *
 * The force and its reach (the defaults are ours; frd-gen(1) has the
 * measurements behind them):
 * - field double, force power: f(r) = (1 + r/s)^-q, s = 1, q = 4.  A power
 *   law has no scale of its own: the field of the first values, hundreds
 *   of cells apart, is shaped as that of the last, a few cells apart.
 *   The thesis's exp(-(r/s)^q) (force exp, s = q = 1/2) is soft at the
 *   spacing of a few cells and a hard core at hundreds: there the value
 *   goes to the centre of the largest gap, and the first levels of a
 *   large matrix form hexagonal domains.
 * - The radius R of an insertion follows the spacing of the values
 *   inserted so far: R = reach * spacing, at least the neglect radius
 *   (where f falls below tol f(0): s (tol^(-1/q) - 1) for the power law,
 *   s ln(1/tol)^(1/q) for exp), at most cap times
 *   the shortest side.  The cap keeps the first insertions short of the
 *   whole torus: their values then go to cells no force has reached,
 *   drawn at random, like dart throwing.  Without it the first values go
 *   to the exact minima of a field over the whole torus, which on a
 *   square torus form a square lattice, and every later level inherits
 *   it.
 * - taper: inside R the force is f(r) - f(R), continuous at the cut-off.
 *   A hard cut leaves a step of f(R) in the field, which draws later
 *   values to just beyond R of earlier ones: a ring at R in every
 *   spectrum.
 * - field int32: the thesis authors' integer table (UTK's
 *   ForcedRandomDithering), (int)(scale exp(-sqrt(2 r))) with scale =
 *   min(INT_MAX / 20, 1 / f(S/2)), S the shortest side; the field is the
 *   exact sum of these integers, the radius where they reach 0 (171 cells
 *   for S >= 342), no reach, cap or taper.  Our coins, their law.
 * tol = 0 keeps every contribution (the full torus for every insertion,
 * O(N^2)).
 *
 * Selection: the K-th smallest free cell in the order (force, tie key)
 * with K ~ Geometric(p) is, in law, the minimum over a Bernoulli(p)
 * subset with ties broken uniformly.  When z > 0 free cells have force 0
 * and K <= z, the K-th is one of them, uniformly: it is drawn by
 * frdgen_zerorank without sorting them.
 */
#ifndef FRS_FRDGEN_H
#define FRS_FRDGEN_H

#include <stdint.h>

#include "formats/frdio.h"

struct progress;

enum frdgen_field {
	FRDGEN_FIELD_DOUBLE,	/* exp(-(r/s)^q) in double precision */
	FRDGEN_FIELD_INT32	/* the thesis authors' integer table */
};

enum frdgen_force {
	FRDGEN_FORCE_POWER,	/* (1 + r/s)^-q */
	FRDGEN_FORCE_EXP	/* exp(-(r/s)^q), the thesis's */
};

struct frdgen_params {
	unsigned dims;		/* 2 or 3 */
	uint32_t w, h, d;	/* d = 1 for dims = 2 */
	double p;		/* candidate fraction, (0, 1] */
	enum frdgen_force force;
	double s, q;		/* the force's scale and exponent */
	double tol;		/* neglect f < tol * f(0); 0: exact */
	double reach;		/* radius >= reach * spacing; 0: off */
	double cap;		/* radius <= cap * shortest side; 0: off */
	int taper;		/* f(r) - f(R) inside R instead of a hard cut */
	enum frdgen_field field;
	uint64_t seed;
	const char *checkpoint;	/* resume from / save to this file, or NULL */
	double checkpoint_every;	/* seconds between checkpoints */
};

/* Defaults: p = 1/2, force power with s = 1, q = 4, tol 1e-2, reach 3,
 * cap 1/3, taper, field double. */
void frdgen_defaults(struct frdgen_params *pr);
/* Check dimension count and sizes (also for frd-gen --method vac). */
int frdgen_check_size(unsigned dims, uint32_t w, uint32_t h, uint32_t d);
/* Check a parameter set; the message names the offending parameter. */
int frdgen_check(const struct frdgen_params *pr);
/* The neglect radius for a tolerance (cells), INFINITY for tol = 0. */
double frdgen_radius(const struct frdgen_params *pr);
/* The radius of the insertion after "inserted" values, rtol the neglect
 * radius of frdgen_radius. */
double frdgen_radius_after(const struct frdgen_params *pr, double rtol,
    uint64_t inserted);
/* Bytes of memory a run needs, to refuse impossible sizes up front. */
uint64_t frdgen_memory(const struct frdgen_params *pr);
/* The parameter text stored in the .frd header. */
void frdgen_describe(const struct frdgen_params *pr, char *buf, size_t n);

/* Generate; out is allocated.  pr may be NULL. */
int frdgen_run(const struct frdgen_params *par, struct frs_matrix *out,
    struct progress *pr);

/* The force at distance r before the taper: (1 + r/s)^-q or
 * exp(-(r/s)^q), or the authors' integer for field int32 (tests use
 * it). */
double frdgen_force(const struct frdgen_params *pr, double r);
/* The scale of the int32 table: min(INT_MAX / 20, 1 / f(S/2)). */
double frdgen_int_scale(const struct frdgen_params *pr);
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
