/*
 * Forced Random Sampling (thesis ch. 4-5): threshold a window of the
 * tiled FRD matrix against importance * tau.
 *
 * Setup (Listing 5.1, done once here for every implementation): with the
 * map's mean mu and maximum m, the window's smaller side needs at least
 * w_min = ceil(sigma * sqrt(n m / (mu a))) elements, a the map's aspect
 * ratio; n_s, the window elements per map pixel and side, is the smallest
 * power of two with n_s * (smaller map side) >= w_min, the same in x and
 * y, and the window is S_W = n_s * S_I in integers.  The window offset is
 * a random multiple of n_s (of the matrix size when n_s exceeds it) per
 * axis, and tau = n S_M^2 / (S_W,x S_W,y mu).
 *
 * Thresholds (unbiased, the default): with T = tau * I(pixel), an element
 * whose matrix value v is below floor(T) passes, v == floor(T) passes with
 * probability frac(T) by a coin of (seed, window element), so that every
 * pixel gets n I / sum(I) samples in expectation.  The thesis's rule,
 * v < T (Eq. 4.14), passes ceil(T) values of each matrix tile and biases
 * dark pixels upwards; FRS_THESIS selects it.
 *
 * Implementations (Naive, Stack, Level 1, Level 2, Sorted) differ only in
 * which elements they look at: all produce the same window elements, which
 * frs_point turns into points the same way, with jitter and coins that
 * depend only on (seed, window element).
 */
#ifndef FRS_FRSCORE_H
#define FRS_FRSCORE_H

#include <stddef.h>
#include <stdint.h>

#include "formats/frdio.h"
#include "maps/imap.h"
#include "sample/frsprep.h"

/* The implementations of Chapter 5, with the values of frs.h's enum
 * frs_algorithm (api.c asserts it: one vocabulary); Flat 1, the device's
 * alone, after them.  FRS_NALGO counts the CPU's. */
enum frs_impl {
	FRS_SORTED, FRS_NAIVE, FRS_STACK, FRS_LEVEL1, FRS_LEVEL2, FRS_FLAT1
};
/* Their names, but the device's flat1, by value: the one list, which
 * frs_impl_name's table and frs_names' (api.c) spell out. */
#define FRS_ALGO_NAMES "sorted", "naive", "stack", "level1", "level2"
#define FRS_NALGO FRS_FLAT1
/* Where a sample sits inside its element: the centre, or offset by
 * Halton or random points; the values of frs.h's enum frs_jitter_mode
 * (FRS_JIT_*; api.c asserts it). */
enum frs_place { FRS_PLACE_CENTRE, FRS_PLACE_HALTON, FRS_PLACE_RANDOM };
/* The pass rule, frs.h's enum frs_rule_mode value for value (api.c
 * asserts it): the thesis's v < T, or the unbiased rule, whose taus
 * FRS_EXACT moves (struct frs_xtau); a sampler asks for FRS_THESIS
 * only. */
enum frs_rule { FRS_UNBIASED, FRS_THESIS, FRS_EXACT };
/* How a window larger than the matrix tiles it, frs.h's enum
 * frs_tiling_mode value for value: each tile through its own transform
 * of (seed, tile) (cl/tile.cl), or the thesis's plain repetition, alone
 * or at each level of the multi-level window; a sampler asks for
 * FRS_TILES_SHUFFLE only. */
enum frs_tiling { FRS_TILES_LEVELS, FRS_TILES_SHUFFLE, FRS_TILES_PLAIN };

/* Exact counts (frs-sample --exact-count): the tau of each step moved so
 * that exactly steps[k] elements of the window pass.  Under the unbiased
 * rule an element of value v and coin u passes when v + u < tau I, its
 * key (v + u) / I is continuous, and tau[k] is the steps[k]-th smallest
 * key over the window (frs_exact_taus).  n 0: the taus of frs_tau. */
struct frs_xtau {
	unsigned n;
	uint64_t steps[16];
	double tau[16];
	unsigned passes;	/* count passes the search made */
};

const char *frs_impl_name(enum frs_impl a);

struct frs_setup {
	uint32_t iw, ih;	/* importance map */
	uint32_t mw, mh;	/* matrix */
	uint64_t n;		/* samples asked for (the last step) */
	double sigma;
	double mean, max;	/* of the map */
	uint32_t ns;		/* window elements per pixel side, 2^k */
	uint64_t sw, sh;	/* window: ns * iw, ns * ih */
	uint64_t wx, wy;	/* window offset in the tiled matrix */
	double tau;		/* for n */
	unsigned level0;	/* first minmap level: log2 min(ns, sigma) */
	uint64_t seed;
	enum frs_rule rule;
	enum frs_place jitter;
	enum frs_tiling tiles;
	/* Thresholds are T = tau * (I * iscale): iscale is a power of two, 1
	 * unless the map's maximum lies outside [2^-900, 2^900], where tau
	 * (denormal maps) or the mean (a sum past DBL_MAX) would overflow;
	 * imean is the mean of I * iscale, which tau uses. */
	double iscale, imean;
	struct frs_xtau exact;	/* exact counts; n 0 unless asked */
	/* The multi-level window (levels.h): this setup's level l, whose
	 * elements are 2^l x 2^l of level 0's and whose thresholds are
	 * lfac = 4^l times theirs; level 0's window sw0 x sh0, over which
	 * tau is reckoned (and exact taus kept).  A single-level setup is
	 * level 0: lfac 1, sw0 x sh0 its own window. */
	unsigned level;
	double lfac;
	uint64_t sw0, sh0;
	const uint8_t *lev;	/* the level of each pixel (levels.h), or
				 * NULL: every pixel is this setup's */
	uint64_t cell0, cell1;	/* with lev: the pixels (row-major) before
				 * cell0 and from cell1 are none of its */
};

/* Whether cell i (a pixel or voxel) belongs to the level of a setup
 * whose cells have the levels lev (NULL: all cells are its). */
static inline int frs_cell_here(const uint8_t *lev, unsigned level,
    uint64_t i)
{
	return lev == NULL || lev[i] == level;
}

/* Listing 5.1 in k = 2 or 3 dimensions, the one setup of frs_setup and
 * frs3_setup: over the cells (map pixels or volume voxels) of sides
 * side[0 .. k - 1], whose values cells holds (a volume as vol_as_map),
 * the window of a matrix of k dimensions (see frs3.h for k = 3). */
struct frs_window {
	uint64_t ns;		/* window elements per cell side, 2^l */
	uint64_t size[3];	/* the window: ns * side */
	uint64_t off[3];	/* its offset in the tiled matrix */
	double mean, max;	/* of the cells */
	double iscale, imean;	/* as in struct frs_setup */
};
/* What Listing 5.1 needs of the cells (mean and maximum, and their
 * power-of-two scale for extreme maps, struct frs_setup's iscale and
 * imean; imax the maximum times iscale): one pass over them, which a
 * caller that sets up many runs of one map (one per set) keeps. */
struct frs_cells {
	double mean, max, iscale, imean, imax;
};
/* known: the cells' imap_stats when a check just made them (as
 * imap_validate_stats does), or NULL for that pass here. */
int frs_cell_stats(const struct frs_imap *cells,
    const struct frs_imap_stats *known, struct frs_cells *c);
/* known: the cells' frs_cell_stats, or NULL to compute them. */
int frs_window_setup(struct frs_window *w, unsigned k, const uint32_t *side,
    const struct frs_imap *cells, const struct frs_cells *known,
    const struct frs_matrix *mat, uint64_t n, double sigma, uint64_t seed);
/* What frs_setup and frs3_setup take alike from their arguments and
 * their window w: a macro, as the two setups are of two types. */
#define FRS_SETUP_TAKE(s, w, n_, sigma_, seed_) do {			\
	(s)->n = (n_);							\
	(s)->sigma = (sigma_);						\
	(s)->seed = (seed_);						\
	(s)->mean = (w).mean;						\
	(s)->max = (w).max;						\
	(s)->iscale = (w).iscale;					\
	(s)->imean = (w).imean;						\
	(s)->ns = (uint32_t)(w).ns;					\
} while (0)
/* What frs_level_setup and frs3_level_setup do alike to s, a copy of
 * level 0's setup, for level l of k dimensions: n_s / 2^l elements a
 * cell side, thresholds times 2^(k l), the level's seed and max; the
 * window and its offset are the caller's, per axis. */
#define FRS_LEVEL_TAKE(s, l, k, max_) do {				\
	(s)->level = (l);						\
	(s)->lfac = ldexp(1.0, (k) * (int)(l));				\
	(s)->ns >>= (l);						\
	(s)->seed = frs_level_seed((s)->seed, (l));			\
	(s)->max = (max_);						\
	(s)->tiles = FRS_TILES_PLAIN;					\
} while (0)
/* Listing 5.1.  The map must be validated (finite, >= 0, not all zero). */
int frs_setup(struct frs_setup *s, const struct frs_imap *map,
    const struct frs_matrix *mat, uint64_t n, double sigma, uint64_t seed);
/* The same with the map's frs_cell_stats known (NULL: computed). */
int frs_setup_known(struct frs_setup *s, const struct frs_imap *map,
    const struct frs_cells *known, const struct frs_matrix *mat, uint64_t n,
    double sigma, uint64_t seed);
/* tau for another count with the same window (progressive steps); the
 * exact tau of a step when s->exact has it; times lfac. */
double frs_tau(const struct frs_setup *s, uint64_t n);
/* Level l (>= 1) of the multi-level window of s0 (a setup of level 0)
 * into s: n_s / 2^l elements a pixel, thresholds times 4^l, its own seed
 * and window offset; max is the largest value of the level's pixels.
 * The level must exist: 2^l <= n_s.  s->lev is left to the caller. */
void frs_level_setup(struct frs_setup *s, const struct frs_setup *s0,
    unsigned l, double max);
/* The seed of level l of a run with this seed: the seed itself at
 * level 0. */
uint64_t frs_level_seed(uint64_t seed, unsigned l);
/* A window's offset on one axis: a random multiple of n_s, or of the
 * matrix side m when n_s exceeds it (every offset is then the same). */
uint64_t frs_window_offset(uint64_t seed, unsigned axis, uint64_t ns,
    uint32_t m);
/* x's tau for the count n, or dflt when x has none. */
double frs_xtau_get(const struct frs_xtau *x, uint64_t n, double dflt);
/* The count of a run at threshold scale tau; -1 after frs_fail. */
typedef int (*frs_count_fn)(void *ctx, double tau, uint64_t *count);
/*
 * The exact taus of steps (increasing, 1 to 16) into x: for each step the
 * tau at which count(tau) is exactly steps[k], found by a safeguarded
 * secant bisection over the count passes from the guess tau0[k]
 * (frs_tau's).  The counts must not decrease with tau, and most is the
 * count of a tau that passes everything (the window elements of non-zero
 * importance): more fails.  Two keys in one double (an ulp of tau apart)
 * would make the count jump past steps[k]; that fails too.  *passes gets
 * the number of count passes made.
 */
int frs_exact_taus(const uint64_t *steps, unsigned nsteps,
    const double *tau0, uint64_t most, frs_count_fn count, void *ctx,
    struct frs_xtau *x, unsigned *passes);
/* frs_exact_taus's most: the window elements of the ncell map pixels (or
 * volume voxels) v of non-zero importance, ns^dims each, saturated. */
uint64_t frs_exact_most(const double *v, uint64_t ncell, uint32_t ns,
    unsigned dims);
/* Samples a matrix gives without repetition: S_M^2 / sigma^2 (Eq. 4.17). */
double frs_unique(const struct frs_setup *s);
/* Tiles of side m met by n elements from offset o on one axis. */
uint64_t frs_tiles_axis(uint64_t o, uint64_t n, uint64_t m);
/* Matrix tiles the window touches, per axis and in all. */
uint64_t frs_tiles(const struct frs_setup *s, uint64_t *tx, uint64_t *ty);
/* The largest block (sorted lists, minmap start level) that the tiling
 * keeps whole: the offset step with shuffled tiles, else the matrix. */
uint32_t frs_tile_max_block(const struct frs_setup *s);
/* The matrix index (y * mw + x) that window element (x, y) shows. */
uint64_t frs_matrix_index(const struct frs_setup *s, uint64_t x, uint64_t y);

/* The minmap level at which Stack, Level N and Flat 1 start for the
 * wanted level: at most log2 n_s, the top level and the tiling's block. */
unsigned frs_start_level(const struct frs_setup *s, const struct frs_prep *p,
    unsigned want);
/* Sorted without lists (a small window of a multi-level run, see
 * api_lev2_lists) visits each pixel as Naive does when it has at most
 * FRS_SCAN_NS^2 elements (a scan along rows beats random lookups), else
 * walks the minmap as Stack does; the device does the same, so that the
 * elements come in the same order. */
#define FRS_SCAN_NS 16
enum frs_impl frs_sorted_walk(const struct frs_setup *s);
/* The start level of algo: Stack's (and Flat 1's) log2 min(n_s, sigma),
 * Level N's N. */
unsigned frs_impl_level(const struct frs_setup *s, const struct frs_prep *p,
    enum frs_impl algo);

/* One accepted window element; (x, y) window coordinates (windows of
 * 2^32 or more elements a side can only be counted). */
struct frs_elem {
	uint32_t x, y;
	uint32_t step;		/* progressive step, 0 for the first */
};

/* Elements in chunks of map pixels, in row-major order: the same order for any
 * thread count, and no copy to join them. */
struct frs_chunk {
	struct frs_elem *e;
	uint64_t n, cap;
	uint64_t count;
	int failed;
	int fixed;		/* e is room in a caller's store: never grown */
	double *xy, *pdf;	/* frs_sample_each's points made in place */
};

struct frs_result {
	struct frs_chunk *chunk;
	uint64_t nchunk;
	uint64_t count;		/* elements accepted (also with count_only) */
};

/*
 * Threshold the window.  steps: the counts of progressive sampling in
 * increasing order (nsteps >= 1, the last equal to s->n); each element
 * records the first step at which it passes.  count_only: count, store
 * nothing.  threads: see frs_set_threads; the elements come in the same
 * order for any thread count.
 */
int frs_sample(const struct frs_setup *s, const struct frs_imap *map,
    const struct frs_prep *p, enum frs_impl algo, const uint64_t *steps,
    unsigned nsteps, int count_only, struct frs_result *r);
void frs_result_free(struct frs_result *r);

/*
 * What frs_sample and frs3_sample share, whatever their element: the
 * kind of chunk (its size, and where its element array and its count
 * lie: offsetof), and a run over nchunk zeroed chunks, task(ctx, chunk,
 * c0, c1) thresholding chunks [c0, c1) of the array in parallel.  The
 * array comes back with *count the total of the chunks' counts; on
 * failure NULL, all released, *count 0.
 */
struct frs_chunk_kind {
	size_t size;
	size_t elems, count;
};
#define FRS_CHUNK_KIND(type) \
	{ sizeof(type), offsetof(type, e), offsetof(type, count) }
typedef int (*frs_chunks_task)(void *ctx, void *chunk, uint64_t c0,
    uint64_t c1);
void *frs_chunks_run(const struct frs_chunk_kind *k, uint64_t nchunk,
    frs_chunks_task task, void *ctx, uint64_t *count);
/* Free the element arrays of the chunks and the array. */
void frs_chunks_free(const struct frs_chunk_kind *k, void *chunk,
    uint64_t nchunk);
/* Room for need elements of size bytes in e, which has room for *cap:
 * doubled from 1024 until it fits.  The array (e itself when it fits
 * already), or e untouched and *failed set when out of memory. */
void *frs_elems_grow(void *e, size_t size, uint64_t need, uint64_t *cap,
    int *failed);

/*
 * One step without a result: the chunks c0 .. c1 - 1 of the window (map
 * rows in chunks), each in the caller's store, from store + at[c - c0]
 * with room for at[c - c0 + 1] - at[c - c0] elements (the counts of a
 * count_only run: exact), handed to fn by the thread that thresholded it.
 * fn runs in parallel for different chunks; a chunk that overflows its
 * room fails.  Memory in proportion to the chunks in flight, not to the
 * samples of the run.
 */
typedef int (*frs_chunk_fn)(void *ctx, uint64_t ci, const struct frs_chunk *c);
/* xy (and pdf, if not NULL) not NULL: with Sorted and no jitter each
 * chunk's points go straight to xy + 2 at[c - c0] (its densities to pdf
 * + at[c - c0]), frs_points and api_pdf as they would give them, and
 * the chunk handed to fn has xy set and no elements. */
int frs_sample_each(const struct frs_setup *s, const struct frs_imap *map,
    const struct frs_prep *p, enum frs_impl algo, uint64_t c0, uint64_t c1,
    const uint64_t *at, struct frs_elem *store, double *xy, double *pdf,
    frs_chunk_fn fn, void *ctx);
/* The number of chunks of map pixels (about 16384 samples each). */
uint64_t frs_nchunks(const struct frs_setup *s);
/* Progressive counts: 1 to 16, increasing. */
int frs_steps_check(const uint64_t *steps, unsigned nsteps);
/* The argument checks of frs_sample (and frs_sample_cl): the steps, the
 * window, what algorithm algo (named name in messages) needs of p; tau[k]
 * gets the threshold of steps[k]. */
int frs_sample_check(const struct frs_setup *s, const struct frs_prep *p,
    int algo, const char *name, const uint64_t *steps, unsigned nsteps,
    int count_only, double *tau);
/* The largest lim of any pixel for threshold tau, the brightest
 * pixel's (the thresholds grow with I, roundings included): the values
 * the sorted lists must hold. */
uint64_t frs_lim_most(const struct frs_setup *s, double tau);

/* The threshold of one pixel (or voxel) for one step. */
struct frs_thr {
	uint64_t lim;	/* values below lim may pass, values from lim never */
	uint64_t pw[2];	/* the rule in integers, the words of frs_pass
			 * (cl/frs.cl) */
};
void frs_thr_make(struct frs_thr *th, double t, enum frs_rule rule);
/* The pass words (pw) of the thresholds tau[k] imp of nsteps steps into
 * thr[2 k], thr[2 k + 1], as the thresholding reads them on the CPU and
 * on the device (a pixel's record, cl/defs.cl); returns the last step's
 * limit. */
uint64_t frs_thr_words(uint64_t *thr, const double *tau, unsigned nsteps,
    double imp, enum frs_rule rule);
/* The first step of those words at which value v passes, nsteps when
 * none; id numbers the window element for its coin (cl/frs.cl's
 * frs_step, for the 3-D sampler). */
unsigned frs_thr_step(const uint64_t *thr, unsigned nsteps, uint64_t v,
    uint64_t seed, uint64_t id);
/* v, or the double below 1 if v is 1. */
double frs_below_one(double v);

/* The point of an element, in [0, 1)^2, with the setup's jitter:
 * frs_points of one. */
void frs_point(const struct frs_setup *s, const struct frs_elem *e,
    double *x, double *y);
/* The level-0 element, on axis 0, 1 or 2, that the sample of a volume's
 * level-l element id (l <= 21) goes to within it (frs3_point): l random
 * bits of (level seed, element). */
uint64_t frs_level_place(uint64_t seed, unsigned level, uint64_t id,
    unsigned axis);
/* The points of n elements into xy (x, y pairs), the jitter made in
 * vectors; one loop without calls when there is none. */
void frs_points(const struct frs_setup *s, const struct frs_elem *e,
    size_t n, double *xy);

#endif
