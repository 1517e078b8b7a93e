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

#include "frs.h"	/* struct frs_matrix */
#include "frd-gen/frdparam.h"

struct cli_task;

/* Generate; out is allocated.  task (cli.h: the progress bar's) may be
 * NULL. */
int frdgen_run(const struct frdgen_params *par, struct frs_matrix *out,
    struct cli_task *task);

#endif
