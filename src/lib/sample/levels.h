/*
 * The multi-level window: window elements whose size follows the map.
 *
 * The thesis's window (Listing 5.1) gives every cell (map pixel or
 * volume voxel) n_s^k elements, n_s = 2^top sized for the brightest
 * cell, so that at most one element in sigma^k passes there.  Where the
 * map is dark an element's threshold T = tau I is tiny: only the first
 * few values of each matrix tile pass, every tile puts them at the same
 * place, and a window hundreds of tiles wide shows the matrix's period
 * as a lattice.
 *
 * Level l instead gives a cell (n_s / 2^l)^k elements, each the union
 * of 2^l x 2^l (x 2^l) level-0 elements with their summed threshold
 * 2^(k l) T: fewer, larger elements where the map is dark, thresholded
 * at a higher density, and a window 2^l times smaller on each side, which
 * repeats the matrix 4^l (8^l) times less.  Each cell takes the coarsest
 * level whose elements stay at or below the sparsity bound S_M / sigma^k
 * (the matrix's element count over sigma^k, the threshold of the
 * brightest cell at level 0), judged on the log threshold smoothed over a
 * Gaussian of `blur` cells on a grid of blocks (so that level regions
 * are large and their borders few: where two levels meet, two unrelated
 * patterns meet), and capped: no element of its block holds more than
 * S_M / 4 (an element passes at most once, so its threshold must stay
 * well below S_M for the count to stay unbiased), and none is coarser
 * than top, which the caller sets to the coarsest level a run needs (at
 * which the window of the whole map fits the matrix: a dark region then
 * takes the first values of one tile, a prefix of the matrix, which is
 * blue noise; coarser levels would only add seams).
 *
 * Every level is then a thresholding of its own: the map masked to the
 * level's cells (zero elsewhere), n_s / 2^l elements a cell side, tau
 * times 2^(k l), its own window offset and its own coins, jitter and
 * offset from a seed of its own (level 0 keeps the run's: a map whose
 * cells are all at level 0 gives the thesis's samples, bit for bit).
 * Each element's expected count is its summed threshold over S_M, as at
 * level 0, so the density of the samples stays exactly the map's.  The
 * levels depend on the map and n only, not on the seed, the step or an
 * exact count's tau: progressive steps nest, and sets differ only in
 * their offsets and coins.
 */
#ifndef FRS_LEVELS_H
#define FRS_LEVELS_H

#include <stdint.h>

/* The most levels: log2 n_s is at most 31 (frscore.h); frs.h defines
 * it too, the same (a difference would not compile where both are). */
#define FRS_LEVELS_MAX 32

/* Smoothing of the levels by default, in cells: wide enough that level
 * regions are large on a real environment map (1024 x 512), narrow
 * enough to follow a sun's halo. */
#define FRS_LEVEL_BLUR 16.0

struct frs_levels {
	unsigned dims;		/* 2 or 3 */
	uint32_t side[3];	/* cells per axis (1 for an absent axis) */
	unsigned top;		/* log2 n_s of level 0: levels 0 .. top */
	uint8_t *lev;		/* per cell, row-major (x fastest) */
	uint64_t cells[FRS_LEVELS_MAX];	/* cells of non-zero importance */
	uint32_t lo[FRS_LEVELS_MAX][3];	/* and their box, per axis from */
	uint32_t hi[FRS_LEVELS_MAX][3];	/* lo to hi (both in) */
	double max[FRS_LEVELS_MAX];	/* the largest and the sum of */
	double sum[FRS_LEVELS_MAX];	/* their values */
	double blur;
};

/*
 * The level of every cell of the values v (side[0] x side[1] [x side[2]],
 * dims 2 or 3, validated: finite, >= 0) for a run whose level-0 elements
 * have thresholds t0 * v (t0: tau times the map's iscale), n_s = 2^top,
 * a matrix of nm elements and sparsity sigma, smoothed over blur cells
 * (0: none, each cell on its own).  -1 after frs_fail (out of memory).
 */
int frs_levels_plan(struct frs_levels *L, unsigned dims,
    const uint32_t *side, const double *v, double t0, unsigned top,
    double nm, double sigma, double blur);
void frs_levels_free(struct frs_levels *L);
/* The number of levels that have cells, and whether only level 0 has. */
unsigned frs_levels_used(const struct frs_levels *L);
#endif
