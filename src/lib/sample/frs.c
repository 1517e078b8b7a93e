#define _POSIX_C_SOURCE 200809L
#include "sample/frscore.h"
#include "base/err.h"
#include "base/mem.h"
#include "base/num.h"
#include "base/par.h"
#include "base/rng.h"
#include "base/wide.h"
#include "sample/frsprep.h"
#include "sample/tile.h"

#include "../../../cl/frs.cl"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Samples a parallel chunk of map pixels is meant to hold: its points
 * (24 bytes each with the density) stay in a core's cache between the
 * thresholding that writes them and the output that reads them, and
 * there are enough chunks for the threads to share even a peaked map. */
#define CHUNK_SAMPLES 16384

/* The implementations' names, by enum frs_impl. */
static const char *const algo_names[FRS_FLAT1 + 1] = {
	FRS_ALGO_NAMES, "flat1"
};

const char *frs_impl_name(enum frs_impl a)
{
	return (unsigned)a <= FRS_FLAT1 ? algo_names[a] : "?";
}

/* ---- setup (Listing 5.1) ------------------------------------------ */

/* The largest log2 n_s per dimension: n_s stays a uint32_t in 2-D, and
 * the (n_s s)^3 window elements of 3-D are past any run at 2^20. */
static const unsigned max_lns[4] = { 0, 0, 31, 20 };

/* Only ratios matter: an extreme map is scaled by a power of two (exact
 * for every value that stays normal), so that tau and the mean stay
 * finite; the thresholds of every other map are those of the map as it
 * is. */
int frs_cell_stats(const struct frs_imap *cells,
    const struct frs_imap_stats *known, struct frs_cells *c)
{
	struct frs_imap_stats st;
	uint64_t n = (uint64_t)cells->w * cells->h;

	if (known != NULL)
		st = *known;
	else
		imap_stats(cells, &st);
	if (!(st.max > 0.0) || st.nonfinite || st.negatives)
		return frs_fail("importance must be finite, non-negative and not "
		    "zero everywhere");
	c->iscale = 1.0;
	c->imean = st.mean;
	c->mean = st.mean;
	c->max = st.max;
	c->imax = st.max;
	if (!(st.max >= 0x1p-900 && st.max <= 0x1p900)) {
		int e = -ilogb(st.max);	/* 1074 for the smallest denormal */
		struct num_sum sum = { 0.0, 0.0 };
		double mx = 0.0;
		c->iscale = ldexp(1.0, e < 1023 ? e : 1023);
		for (uint64_t i = 0; i < n; i++) {
			double v = cells->v[i] * c->iscale;
			num_add(&sum, v);
			mx = v > mx ? v : mx;
		}
		c->imean = num_total(&sum) / (double)n;
		c->mean = c->imean / c->iscale;
		c->imax = mx;
	}
	return 0;
}

/* A random multiple of n_s on one axis, or of the matrix side m when n_s
 * exceeds it (every offset is then the same). */
uint64_t frs_window_offset(uint64_t seed, unsigned axis, uint64_t ns,
    uint32_t m)
{
	uint64_t u = ns < m ? ns : m;

	return (uint64_t)(frs_rand01(seed, FRS_STREAM_WINDOW, axis) *
	    (double)(m / u)) * u;
}

int frs_window_setup(struct frs_window *w, unsigned k, const uint32_t *side,
    const struct frs_imap *cells, const struct frs_cells *known,
    const struct frs_matrix *mat, uint64_t n, double sigma, uint64_t seed)
{
	const uint32_t msize[3] = { mat->w, mat->h, mat->d };
	uint32_t small = side[0];
	double vol, cube, a, x, wmin;
	struct frs_cells c;
	uint64_t ns = 1;

	memset(w, 0, sizeof *w);
	if (mat->dims != k)
		return frs_fail("a %u-D matrix cannot sample a %s", mat->dims,
		    k == 2 ? "2-D map" : "volume");
	if (n == 0)
		return frs_fail("the count must be at least 1");
	if (!(sigma >= 1.0 && isfinite(sigma)))
		return frs_fail("sigma %g is below 1", sigma);
	if (known != NULL)
		c = *known;
	else if (frs_cell_stats(cells, NULL, &c) < 0)
		return -1;
	w->mean = c.mean;
	w->max = c.max;
	w->iscale = c.iscale;
	w->imean = c.imean;
	for (unsigned i = 1; i < k; i++)
		small = side[i] < small ? side[i] : small;
	/* a = (cells) / small^k, the aspect ratio: the products are exact
	 * (fewer than 2^53 cells fit in memory), so a is the rounded ratio
	 * in any dimension, in 2-D that of large / small. */
	vol = side[0];
	cube = small;
	for (unsigned i = 1; i < k; i++) {
		vol *= side[i];
		cube *= small;
	}
	a = vol / cube;
	x = (double)n * c.imax / (w->imean * a);
	wmin = ceil(sigma * (k == 2 ? sqrt(x) : cbrt(x)));
	while ((double)small * (double)ns < wmin) {
		ns <<= 1;
		if (ns > ((uint64_t)1 << max_lns[k]))
			return frs_fail("%llu samples: the window would need more "
			    "than 2^%u elements per %s side", (unsigned long long)n,
			    max_lns[k], k == 2 ? "pixel" : "voxel");
	}
	w->ns = ns;
	for (unsigned i = 0; i < k; i++) {
		w->size[i] = ns * side[i];
		w->off[i] = frs_window_offset(seed, i, ns, msize[i]);
	}
	return 0;
}

int frs_setup(struct frs_setup *s, const struct frs_imap *map,
    const struct frs_matrix *mat, uint64_t n, double sigma, uint64_t seed)
{
	return frs_setup_known(s, map, NULL, mat, n, sigma, seed);
}

int frs_setup_known(struct frs_setup *s, const struct frs_imap *map,
    const struct frs_cells *known, const struct frs_matrix *mat, uint64_t n,
    double sigma, uint64_t seed)
{
	const uint32_t side[2] = { map->w, map->h };
	struct frs_window w;

	memset(s, 0, sizeof *s);
	if (frs_window_setup(&w, 2, side, map, known, mat, n, sigma, seed) < 0)
		return -1;
	s->iw = map->w;
	s->ih = map->h;
	s->mw = mat->w;
	s->mh = mat->h;
	FRS_SETUP_TAKE(s, w, n, sigma, seed);
	s->sw = w.size[0];
	s->sh = w.size[1];
	s->wx = w.off[0];
	s->wy = w.off[1];
	s->lfac = 1.0;
	s->sw0 = s->sw;
	s->sh0 = s->sh;
	s->tau = frs_tau(s, n);
	s->level0 = (unsigned)floor(log2(fmin((double)w.ns, sigma)));
	return 0;
}

double frs_tau(const struct frs_setup *s, uint64_t n)
{
	return s->lfac * frs_xtau_get(&s->exact, n, (double)n * (double)s->mw *
	    (double)s->mh / ((double)s->sw0 * (double)s->sh0 * s->imean));
}

uint64_t frs_level_seed(uint64_t seed, unsigned l)
{
	return l == 0 ? seed : frs_rand64(seed, FRS_STREAM_LEVEL, l);
}

void frs_level_setup(struct frs_setup *s, const struct frs_setup *s0,
    unsigned l, double max)
{
	*s = *s0;
	FRS_LEVEL_TAKE(s, l, 2, max);
	s->sw = (uint64_t)s->ns * s->iw;
	s->sh = (uint64_t)s->ns * s->ih;
	s->wx = frs_window_offset(s->seed, 0, s->ns, s->mw);
	s->wy = frs_window_offset(s->seed, 1, s->ns, s->mh);
	s->tau = frs_tau(s, s->n);
	s->level0 = (unsigned)floor(log2(fmin((double)s->ns, s->sigma)));
}

double frs_xtau_get(const struct frs_xtau *x, uint64_t n, double dflt)
{
	for (unsigned k = 0; k < x->n; k++)
		if (x->steps[k] == n)
			return x->tau[k];
	return dflt;
}

/* The most count passes one step's search may take (it takes a few:
 * see frs-sample(1)); and the same-side landings after which it only
 * bisects. */
#define EXACT_PASSES 200
#define EXACT_STREAK 12
/* A bracket of this many counts or fewer is bisected: its counts are
 * steps, no longer a line. */
#define EXACT_BISECT 4

/*
 * The tau of exactly n from the guess t > lo, lo's count clo < n (tau 0,
 * count 0 for the first step).  The counts grow about in proportion to
 * tau, with a noise of about the square root of the keys crossed, so
 * each pass aims, on the line through the bracket's ends [lo, hi] (hi
 * unknown: the line through the origin and lo), at the middle of the
 * count n; after two passes on the same side of n it aims past n by the
 * square root of the miss, doubled at each further pass on that side, so
 * that the bracket closes from both sides.  Past EXACT_STREAK such passes
 * it bisects, and the search ends at the latest when lo and hi are
 * neighbouring doubles, which only two keys in one ulp of tau can cause.
 */
static int exact_one(uint64_t n, double lo, uint64_t clo, double t,
    frs_count_fn count, void *ctx, double *tau, unsigned *passes)
{
	double hi = INFINITY;
	uint64_t chi = 0, c;
	int side = 0, streak = 0;

	for (unsigned it = 0;; it++) {
		double target, margin, mid;
		int sd;
		if (it == EXACT_PASSES)
			return frs_fail("exact count: no threshold for exactly "
			    "%llu samples after %u count passes",
			    (unsigned long long)n, it);
		if (count(ctx, t, &c) < 0)
			return -1;
		(*passes)++;
		if (c == n) {
			*tau = t;
			return 0;
		}
		sd = c < n ? -1 : 1;
		streak = sd == side ? streak + 1 : 1;
		side = sd;
		if (c < n) {
			lo = t;
			clo = c;
		} else {
			hi = t;
			chi = c;
		}
		margin = streak < 2 ? 0.0 : sqrt((double)(c < n ? n - c : c - n)) *
		    ldexp(1.0, streak - 2);
		target = (double)n + 0.5 - (double)side * margin;
		if (!isfinite(hi)) {
			t = clo > 0 ? lo * (target / (double)clo) : 2.0 * lo;
			if (!(t > lo) || !isfinite(t))
				return frs_fail("exact count: no threshold "
				    "reaches %llu samples", (unsigned long long)n);
			continue;
		}
		mid = lo + (hi - lo) / 2;
		t = lo + (hi - lo) * ((target - (double)clo) /
		    (double)(chi - clo));
		if (streak > EXACT_STREAK || chi - clo <= EXACT_BISECT ||
		    !(t > lo && t < hi))
			t = mid;
		if (!(t > lo && t < hi))
			return frs_fail("exact count: %llu elements share the "
			    "threshold %.17g of sample %llu: no set of exactly "
			    "%llu", (unsigned long long)(chi - clo), hi,
			    (unsigned long long)(clo + 1), (unsigned long long)n);
	}
}

uint64_t frs_exact_most(const double *v, uint64_t ncell, uint32_t ns,
    unsigned dims)
{
	uint64_t e = 0;

	for (uint64_t i = 0; i < ncell; i++)
		e += v[i] > 0.0;
	for (unsigned d = 0; d < dims; d++)
		e = ns != 0 && e > UINT64_MAX / ns ? UINT64_MAX : e * ns;
	return e;
}

int frs_exact_taus(const uint64_t *steps, unsigned nsteps,
    const double *tau0, uint64_t most, frs_count_fn count, void *ctx,
    struct frs_xtau *x, unsigned *passes)
{
	double lo = 0.0;
	uint64_t clo = 0;

	memset(x, 0, sizeof *x);
	*passes = 0;
	if (frs_steps_check(steps, nsteps) < 0)
		return -1;
	if (steps[nsteps - 1] > most)
		return frs_fail("exact count: the window has %llu elements of "
		    "non-zero importance, fewer than %llu",
		    (unsigned long long)most,
		    (unsigned long long)steps[nsteps - 1]);
	for (unsigned k = 0; k < nsteps; k++) {
		double t = tau0[k], tk = 0.0;
		if (!(t > lo))
			t = clo > 0 ? lo * (double)steps[k] / (double)clo : 1.0;
		if (exact_one(steps[k], lo, clo, t, count, ctx, &tk, passes) < 0)
			return -1;
		x->steps[k] = steps[k];
		x->tau[k] = tk;
		lo = tk;
		clo = steps[k];
	}
	x->n = nsteps;
	x->passes = *passes;
	return 0;
}

double frs_unique(const struct frs_setup *s)
{
	return (double)s->mw * (double)s->mh / (s->sigma * s->sigma);
}

uint64_t frs_tiles_axis(uint64_t o, uint64_t n, uint64_t m)
{
	return (o + n - 1) / m - o / m + 1;
}

uint64_t frs_tiles(const struct frs_setup *s, uint64_t *tx, uint64_t *ty)
{
	*tx = frs_tiles_axis(s->wx, s->sw, s->mw);
	*ty = frs_tiles_axis(s->wy, s->sh, s->mh);
	return *tx * *ty;
}

uint32_t frs_tile_max_block(const struct frs_setup *s)
{
	uint64_t gx = frs_tile_step(s->mw), gy = frs_tile_step(s->mh);

	if (s->tiles != FRS_TILES_SHUFFLE)
		return s->mw < s->mh ? s->mw : s->mh;
	return (uint32_t)(gx < gy ? gx : gy);
}

/* ---- tiles -------------------------------------------------------- */

/* The window of setup s as the walks of cl/frs.cl see it: the tile of a
 * window element, its matrix block and the thresholding of every
 * implementation are defined there, once for the CPU and the device. */
static void win_of(const struct frs_setup *s, struct frs_win *w)
{
	*w = (struct frs_win){ .mw = s->mw, .mh = s->mh, .wx = s->wx,
	    .wy = s->wy, .sw = s->sw, .ns = s->ns, .seed = s->seed,
	    .tiles = s->tiles == FRS_TILES_SHUFFLE };
	frs_win_shifts(w);
}

uint64_t frs_matrix_index(const struct frs_setup *s, uint64_t x, uint64_t y)
{
	uint64_t X = s->wx + x, Y = s->wy + y, m[3] = { s->mw, s->mh, 1 };
	struct frs_tile t;
	struct frs_win w;

	win_of(s, &w);
	if (s->tiles != FRS_TILES_SHUFFLE)
		frs_tile_plain(&t);
	else
		frs_tile_make(&t, s->seed, 2, m, X / s->mw, Y / s->mh, 0);
	return frs_block_index(&w, &t, 0, X % s->mw, Y % s->mh);
}

/* ---- thresholds --------------------------------------------------- */

void frs_thr_make(struct frs_thr *th, double t, enum frs_rule rule)
{
	uint64_t tf;
	double frac, c;

	/* Past 2^33 every value of a uint32 matrix passes. */
	if (!(t < 0x1p33))
		t = 0x1p33;
	/* floor(t) for t >= 0 (and below 2^64): the conversion truncates,
	 * exactly, and costs a library call less a pixel. */
	tf = (uint64_t)t;
	frac = t - (double)tf;
	if (rule == FRS_THESIS) {	/* v < T  <=>  v < ceil(T) */
		th->lim = (uint64_t)ceil(t);
		th->pw[0] = th->lim;
		th->pw[1] = 0;
		return;
	}
	th->lim = tf + (frac > 0.0);
	/* The coin's bound ceil(frac 2^53), the product exact: truncated,
	 * then one up unless it was whole, without a call a pixel. */
	c = frac * 0x1p53;
	th->pw[0] = tf;
	th->pw[1] = (uint64_t)c;
	th->pw[1] += (double)th->pw[1] < c;
}

unsigned frs_thr_step(const uint64_t *thr, unsigned nsteps, uint64_t v,
    uint64_t seed, uint64_t id)
{
	return frs_step(thr, nsteps, v, seed, id);
}

uint64_t frs_thr_words(uint64_t *thr, const double *tau, unsigned nsteps,
    double imp, enum frs_rule rule)
{
	struct frs_thr th = { 0 };

	for (unsigned k = 0; k < nsteps; k++) {
		frs_thr_make(&th, tau[k] * imp, rule);
		thr[2 * k] = th.pw[0];
		thr[2 * k + 1] = th.pw[1];
	}
	return th.lim;
}

/* ---- the implementations ------------------------------------------ */

struct run {
	const struct frs_setup *s;
	const struct frs_imap *map;
	const struct frs_prep *p;
	enum frs_impl algo;
	const double *tau;	/* per step */
	unsigned nsteps;
	int count_only;
	/* frs_sample_each: chunks from c0, handed to fn, not kept */
	uint64_t c0;
	const uint64_t *at;
	struct frs_elem *store;
	double *xy, *pdf;	/* points made in place, or NULL */
	frs_chunk_fn fn;
	void *ctx;
	unsigned start;		/* the minmap level Stack and Level N start
				 * at (frs_impl_level), once a run */
	/* Sorted with shuffled tiles: the values below npos by square of
	 * side bside of the matrix (first_values), for pixels whose few
	 * passing values are cheaper to look up than their blocks
	 * (pix_few): square q holds bval[bstart[q] .. bstart[q + 1] - 1],
	 * ascending, at matrix indices bpos[...]; value v < npos is at
	 * matrix index vpos[v]. */
	uint32_t *bval, *bpos, *bstart, *vpos;
	uint64_t npos;
	unsigned lside, lmw, lmh;	/* log2 of the squares' side, mw, mh */
	double share;		/* of the matrix the squares of a pixel's
				 * part of a tile cover, at most */
};

/* The most blocks a pixel's descent marks (64 x 64); a pixel of more
 * looks at each. */
#define LIVE_MAX 4096
/* The most values first_values sorts into squares. */
#define FEW_MAX 65536
/* The most values pix_few expects to look at: it sorts what passes by
 * insertion. */
#define FEW_SORT 256.0

/* What one pixel's work needs: the walk first, as the hooks of
 * cl/frs.cl get it. */
struct pix {
	struct frs_walk w;
	const struct run *run;
	struct frs_chunk *c;
	uint64_t thr[2 * 16];	/* per step, the pass words (frs_walk) */
	double pdf;		/* its density, for points made in place */
	uint8_t live[LIVE_MAX];	/* Sorted, shuffled tiles: its blocks worth
				 * a look (mark_live) */
	struct few {
		uint64_t key;	/* block of the pixel, then value */
		uint32_t x, y;	/* window element */
	} few[LIVE_MAX];	/* pix_few's elements */
};
_Static_assert(offsetof(struct pix, w) == 0, "the hooks' walk is the pixel");

/* Room for k more elements in c; a chunk in a caller's store
 * (frs_sample_each) is never grown: overflowing it fails. */
static int grow(struct frs_chunk *c, uint64_t k)
{
	if (c->fixed)
		c->failed = 1;
	else
		c->e = frs_elems_grow(c->e, sizeof *c->e, c->n + k, &c->cap,
		    &c->failed);
	return c->failed ? -1 : 0;
}

/* cl/frs.cl's hook: element (x, y) passed at step `step`. */
static inline void frs_walk_put(struct frs_walk *w, uint64_t x, uint64_t y,
    uint32_t step)
{
	struct pix *px = (struct pix *)w;
	struct frs_chunk *c = px->c;

	c->count++;
	if (px->run->count_only)
		return;
	if (c->n == c->cap && grow(c, 1) < 0)
		return;
	c->e[c->n++] = (struct frs_elem){ (uint32_t)x, (uint32_t)y, step };
}

unsigned frs_start_level(const struct frs_setup *s, const struct frs_prep *p,
    unsigned want)
{
	unsigned l = want, lns = num_log2_ceil(s->ns);
	unsigned lt = num_log2_ceil(frs_tile_max_block(s));

	if (l > lns)
		l = lns;
	if (l > lt)
		l = lt;
	if (l > p->nlev - 1)
		l = p->nlev - 1;
	return l;
}

enum frs_impl frs_sorted_walk(const struct frs_setup *s)
{
	return s->ns <= FRS_SCAN_NS ? FRS_NAIVE : FRS_STACK;
}

unsigned frs_impl_level(const struct frs_setup *s, const struct frs_prep *p,
    enum frs_impl algo)
{
	return frs_start_level(s, p, algo == FRS_LEVEL1 ? 1 :
	    algo == FRS_LEVEL2 ? 2 : s->level0);
}

/* The coordinate of window element e with jitter j in [0, 1) on a side
 * of the window: the one formula of frs_point, frs_points and
 * take_points. */
static double coord(uint64_t e, double j, double side)
{
	return frs_below_one(((double)e + j) / side);
}

/* The k elements of a block that frs_sorted_cut accepted, as points
 * (no jitter: the centre of the element) straight into the chunk's xy,
 * with the pixel's density: frs_point and api_pdf without the elements
 * in between, a third of the memory traffic. */
FRS_WIDE static void take_points(struct pix *px, const struct frs_tile *t,
    const uint32_t *idx, uint64_t x, uint64_t y, uint64_t k)
{
	const struct frs_setup *s = px->run->s;
	struct frs_chunk *c = px->c;
	double sw = (double)s->sw, sh = (double)s->sh, *o;
	uint64_t ex, ey, b = px->w.b;
	unsigned lb = px->w.lb;

	if (c->n + k > c->cap) {
		c->failed = 1;
		return;
	}
	o = c->xy + 2 * c->n;
	if (t->flip == 0 && t->perm[0] == 0) {	/* plain: the fast path */
		for (uint64_t j = 0; j < k; j++) {
			o[2 * j] = coord(x + (idx[j] & (b - 1)), 0.5, sw);
			o[2 * j + 1] = coord(y + (idx[j] >> lb), 0.5, sh);
		}
	} else {
		for (uint64_t j = 0; j < k; j++) {
			frs_block_elem(t, b, lb, idx[j], x, y, &ex, &ey);
			o[2 * j] = coord(ex, 0.5, sw);
			o[2 * j + 1] = coord(ey, 0.5, sh);
		}
	}
	for (uint64_t j = 0; c->pdf != NULL && j < k; j++)
		c->pdf[c->n + j] = px->pdf;
	c->n += k;
}

/* cl/frs.cl's hook for Sorted with one step: the first k elements (k >
 * 0) of the list idx of the block of tile t at window element (x, y)
 * pass, without further tests. */
static inline void frs_walk_take(struct frs_walk *w, const struct frs_tile *t,
    const uint32_t *idx, uint64_t k, uint64_t x, uint64_t y)
{
	struct pix *px = (struct pix *)w;
	struct frs_chunk *c = px->c;
	uint64_t ex, ey, b = w->b;
	unsigned lb = w->lb;

	c->count += k;
	if (px->run->count_only)
		return;
	if (c->xy != NULL) {
		take_points(px, t, idx, x, y, k);
		return;
	}
	if (c->n + k > c->cap && grow(c, k) < 0)
		return;
	if (t->flip == 0 && t->perm[0] == 0) {	/* plain: the fast path */
		for (uint64_t j = 0; j < k; j++)
			c->e[c->n + j] = (struct frs_elem){
			    (uint32_t)(x + (idx[j] & (b - 1))),
			    (uint32_t)(y + (idx[j] >> lb)), 0 };
	} else {
		for (uint64_t j = 0; j < k; j++) {
			frs_block_elem(t, b, lb, idx[j], x, y, &ex, &ey);
			c->e[c->n + j] = (struct frs_elem){ (uint32_t)ex,
			    (uint32_t)ey, 0 };
		}
	}
	c->n += k;
}

/* A lower bound of the values that the window-aligned square of the
 * given side from window element (x, y) shows (inside one tile, as an
 * aligned square of a side below the matrix's is): the minmap of level
 * log2 side over the (at most 2 x 2) blocks its matrix region meets, or 0
 * when there is no such level.  A dark square then costs four lookups
 * instead of a bisection per block. */
static uint32_t region_bound(struct pix *px, uint64_t x, uint64_t y,
    uint64_t side)
{
	const struct frs_setup *s = px->run->s;
	const struct frs_prep *p = px->run->p;
	unsigned L = num_log2_ceil(side);
	uint64_t lx, ly, c[2][2], lo[2], m[2] = { s->mw, s->mh };
	uint32_t v = UINT32_MAX;
	const struct frs_tile *t;

	if (side >= s->mw || side >= s->mh || L >= p->nlev)
		return 0;
	t = frs_tile_at(&px->w.win, &px->w.tc, x, y, &lx, &ly);
	for (uint64_t k = 0; k < 2; k++) {	/* opposite corners */
		uint64_t i = frs_block_index(&px->w.win, t, 0,
		    lx + k * (side - 1), ly + k * (side - 1));
		c[k][0] = i % s->mw;
		c[k][1] = i / s->mw;
	}
	/* The region starts at the smaller corner, or wraps around. */
	for (int i = 0; i < 2; i++)
		lo[i] = c[0][i] < c[1][i] ? c[0][i] : c[1][i];
	for (int i = 0; i < 2; i++)
		if ((c[0][i] > c[1][i] ? c[0][i] - c[1][i] : c[1][i] - c[0][i]) !=
		    side - 1)
			lo[i] = c[0][i] > c[1][i] ? c[0][i] : c[1][i];
	for (uint64_t qy = 0; qy < 2; qy++)
		for (uint64_t qx = 0; qx < 2; qx++) {
			uint64_t bx = ((lo[0] >> L) + qx) % (m[0] >> L);
			uint64_t by = ((lo[1] >> L) + qy) % (m[1] >> L);
			uint32_t w = p->lev[L][by * (m[0] >> L) + bx];
			v = w < v ? w : v;
		}
	return v;
}

/* Shuffled tiles, a pixel of nb x nb blocks of side b (blocks smaller
 * than it): mark in px->live the blocks that a descent over the
 * window-aligned squares from the square of `side` at (x, y) reaches,
 * skipping each square whose bound reaches the limit.  The blocks are
 * then taken in their order; the descent only skips, in O(log) lookups
 * for a dark square where looking at each block cost one per block. */
static void mark_live(struct pix *px, uint64_t x, uint64_t y, uint64_t side,
    uint32_t b, uint64_t nb)
{
	uint64_t h = side / 2;

	if (side == b) {
		px->live[(y - px->w.y0) / b * nb + (x - px->w.x0) / b] = 1;
		return;
	}
	if (region_bound(px, x, y, side) >= px->w.lim)
		return;
	for (uint64_t q = 0; q < 4; q++)
		mark_live(px, x + (q & 1) * h, y + (q >> 1) * h, h, b, nb);
}

/* The live blocks of the pixel (1 when worth a look), from squares of
 * at most half the matrix's side (the largest a bound can be had for). */
static void pixel_live(struct pix *px, uint32_t b, uint64_t nb)
{
	const struct frs_setup *s = px->run->s;
	uint64_t side = s->ns, m = s->mw < s->mh ? s->mw : s->mh;

	memset(px->live, 0, nb * nb);
	while (side >= m && side > b)
		side /= 2;
	for (uint64_t y = 0; y < s->ns; y += side)
		for (uint64_t x = 0; x < s->ns; x += side)
			mark_live(px, px->w.x0 + x, px->w.y0 + y, side, b, nb);
}

/* One element that passes, nsteps 1: frs_walk_take's work for a
 * block of one. */
static void take_one(struct pix *px, uint64_t x, uint64_t y)
{
	const struct frs_setup *s = px->run->s;
	struct frs_chunk *c = px->c;

	c->count++;
	if (px->run->count_only)
		return;
	if (c->xy != NULL) {
		if (c->n + 1 > c->cap) {
			c->failed = 1;
			return;
		}
		c->xy[2 * c->n] = coord(x, 0.5, (double)s->sw);
		c->xy[2 * c->n + 1] = coord(y, 0.5, (double)s->sh);
		if (c->pdf != NULL)
			c->pdf[c->n] = px->pdf;
		c->n++;
		return;
	}
	if (c->n == c->cap && grow(c, 1) < 0)
		return;
	c->e[c->n++] = (struct frs_elem){ (uint32_t)x, (uint32_t)y, 0 };
}

/* The squares of side B on an axis of m (m / B of them) that the
 * toroidal interval [a, a + len) meets: first *q0, count *nq. */
static void squares_met(uint64_t a, uint64_t len, uint64_t m, unsigned lB,
    uint64_t *q0, uint64_t *nq)
{
	uint64_t B = (uint64_t)1 << lB, n = ((a & (B - 1)) + len + B - 1) >> lB;

	*q0 = a >> lB;
	*nq = n < m >> lB ? n : m >> lB;
}

/* Value v at matrix index pos, if tile t shows it inside the pixel (and
 * it passes), into px->few at *k (counted only, for a count); 0, or -1
 * when px->few is full. */
static inline int few_one(struct pix *px, const struct frs_tile *t,
    uint64_t wx, uint64_t wy, uint32_t pos, uint32_t v, unsigned lb,
    uint64_t nb, uint64_t *k)
{
	const struct run *run = px->run;
	const struct frs_setup *s = run->s;
	/* frs_tile_block at level 0, backwards, without branches: the
	 * matrix's sides are powers of two, so a coordinate wraps by a mask
	 * and m - 1 - x is (m - 1) ^ x. */
	uint64_t mx = s->mw - 1, my = s->mh - 1;
	uint64_t fx = (t->flip & 1u) ? mx : 0, fy = (t->flip & 2u) ? my : 0;
	int swap = t->perm[0] != 0;
	uint64_t a0 = (((pos & mx) - t->off[0]) & mx) ^ fx;
	uint64_t a1 = (((pos >> run->lmw) - t->off[1]) & my) ^ fy;
	/* inside the pixel: (ex, ey) from its corner, below n_s */
	uint64_t ex = wx + (swap ? a1 : a0) - px->w.x0;
	uint64_t ey = wy + (swap ? a0 : a1) - px->w.y0;

	if (ex >= s->ns || ey >= s->ns ||
	    !frs_pass(px->thr, v, s->seed, (px->w.y0 + ey) * s->sw +
	    px->w.x0 + ex))
		return 0;
	if (run->count_only) {
		px->c->count++;
		return 0;
	}
	if (*k == LIVE_MAX)
		return -1;
	px->few[(*k)++] = (struct few){ ((ey >> lb) * nb + (ex >> lb)) << 32 |
	    v, (uint32_t)(px->w.x0 + ex), (uint32_t)(px->w.y0 + ey) };
	return 0;
}

/* The values of square q below the limit that tile t shows in the pixel,
 * as few_one. */
static int few_square(struct pix *px, const struct frs_tile *t,
    uint64_t wx, uint64_t wy, uint64_t q, unsigned lb, uint64_t nb,
    uint64_t *k)
{
	const struct run *run = px->run;

	for (uint32_t i = run->bstart[q]; i < run->bstart[q + 1] &&
	    run->bval[i] < px->w.lim; i++)
		if (few_one(px, t, wx, wy, run->bpos[i], run->bval[i], lb, nb,
		    k) < 0)
			return -1;
	return 0;
}

/* The elements of the part of the pixel in tile (tx, ty): the squares of
 * the matrix that the part shows, through the tile's transform. */
static int few_tile(struct pix *px, uint64_t tx, uint64_t ty, unsigned lb,
    uint64_t nb, uint64_t *k)
{
	const struct run *run = px->run;
	const struct frs_setup *s = run->s;
	uint64_t wx = (tx << run->lmw) - s->wx, wy = (ty << run->lmh) - s->wy;
	uint64_t m[2] = { s->mw, s->mh }, lo[2], hi[2];
	unsigned lB = run->lside;
	uint64_t q0[2], nq[2], sq = s->mw >> lB, sqy = s->mh >> lB;
	const struct frs_tile *t;

	/* The part, in the tile's window coordinates: [lo, hi). */
	lo[0] = px->w.x0 > wx ? px->w.x0 - wx : 0;
	lo[1] = px->w.y0 > wy ? px->w.y0 - wy : 0;
	hi[0] = px->w.x0 + s->ns - wx < s->mw ? px->w.x0 + s->ns - wx : s->mw;
	hi[1] = px->w.y0 + s->ns - wy < s->mh ? px->w.y0 + s->ns - wy : s->mh;
	t = frs_tile_get(&px->w.win, &px->w.tc, tx, ty);
	/* Matrix axis a shows window axis perm[a], flipped or not, then
	 * shifted: the interval it covers there. */
	for (unsigned a = 0; a < 2; a++) {
		uint64_t p = t->perm[a], f = (t->flip >> a & 1u) ?
		    m[a] - hi[p] : lo[p];
		squares_met((f + t->off[a]) & (m[a] - 1), hi[p] - lo[p], m[a],
		    lB, &q0[a], &nq[a]);
	}
	/* Fewer values below the limit than squares to ask (the darkest
	 * pixels): each value where the matrix has it. */
	if (px->w.lim < nq[0] * nq[1]) {
		for (uint32_t v = 0; v < px->w.lim; v++)
			if (few_one(px, t, wx, wy, run->vpos[v], v, lb, nb, k) < 0)
				return -1;
		return 0;
	}
	for (uint64_t j = 0; j < nq[1]; j++)
		for (uint64_t i = 0; i < nq[0]; i++) {
			uint64_t q = ((q0[1] + j) & (sqy - 1)) * sq +
			    ((q0[0] + i) & (sq - 1));
			if (few_square(px, t, wx, wy, q, lb, nb, k) < 0)
				return -1;
		}
	return 0;
}

/*
 * Shuffled tiles, a pixel whose limit is small against its blocks (a dark
 * pixel of a wide window): the values below the limit are few, and where
 * each sits in the matrix is known (run->bval, by square), so each tile
 * the pixel meets is asked where it shows those of the squares its part
 * covers, through its transform inverted, instead of the pixel's blocks
 * being looked at one by one.  The elements then go out in pix_sorted's
 * order: by block of side b in the pixel, row by row, and by value inside
 * a block.  0, or -1 (nothing taken) when they are too many to hold.
 */
static int pix_few(struct pix *px, unsigned lb, uint64_t nb)
{
	const struct run *run = px->run;
	const struct frs_setup *s = run->s;
	uint64_t X0 = s->wx + px->w.x0, Y0 = s->wy + px->w.y0, k = 0;

	for (uint64_t ty = Y0 >> run->lmh; ty <= (Y0 + s->ns - 1) >> run->lmh;
	    ty++)
		for (uint64_t tx = X0 >> run->lmw;
		    tx <= (X0 + s->ns - 1) >> run->lmw; tx++)
			if (few_tile(px, tx, ty, lb, nb, &k) < 0)
				return -1;
	/* By key: insertion for the few a dark pixel has. */
	for (uint64_t i = 1; i < k; i++) {
		struct few f = px->few[i];
		uint64_t j = i;
		for (; j > 0 && px->few[j - 1].key > f.key; j--)
			px->few[j] = px->few[j - 1];
		px->few[j] = f;
	}
	for (uint64_t i = 0; i < k; i++)
		take_one(px, px->few[i].x, px->few[i].y);
	return 0;
}

/* Whether pix_few serves the pixel: one step, the values below its limit
 * known, and fewer of them to place (the limit times the tiles it meets
 * times the share of the matrix their squares cover) than blocks to look
 * at, and few enough to sort by insertion. */
static int few_serves(const struct pix *px, uint64_t nb)
{
	const struct run *run = px->run;
	const struct frs_setup *s = run->s;
	uint64_t X0 = s->wx + px->w.x0, Y0 = s->wy + px->w.y0;
	uint64_t nt = (((X0 + s->ns - 1) >> run->lmw) - (X0 >> run->lmw) + 1) *
	    (((Y0 + s->ns - 1) >> run->lmh) - (Y0 >> run->lmh) + 1);
	double cost = (double)px->w.lim * (double)nt * run->share;

	return run->nsteps == 1 && px->w.lim <= run->npos &&
	    cost <= (double)(nb * nb) && cost <= FEW_SORT;
}

/* Sorted: frs_walk_sorted with the shortcuts of a pixel of many blocks,
 * which only skip work (pix_few, the live blocks, the bound of the
 * whole pixel). */
static void pix_sorted(struct pix *px)
{
	struct frs_walk *w = &px->w;
	uint64_t b = w->b, nb = w->win.ns / b;
	int live = nb > 1 && nb * nb <= LIVE_MAX;

	if (live && few_serves(px, nb) && pix_few(px, w->lb, nb) == 0)
		return;
	if (!live) {
		if (nb == 1 ||
		    region_bound(px, w->x0, w->y0, w->win.ns) < w->lim)
			frs_walk_sorted(w);
		return;
	}
	pixel_live(px, (uint32_t)b, nb);
	for (uint64_t by = 0; by < nb; by++)
		for (uint64_t bx = 0; bx < nb; bx++)
			if (px->live[by * nb + bx])
				frs_sorted_block(w, w->x0 + bx * b,
				    w->y0 + by * b);
}

/* Map pixels per chunk, in row-major order: about CHUNK_SAMPLES
 * samples at the map's mean.  Chunks only divide the work; the samples
 * come in map order for any chunking. */
static uint64_t chunk_pixels(const struct frs_setup *s)
{
	uint64_t npix = (uint64_t)s->iw * s->ih;
	uint64_t p = s->n > 0 ? CHUNK_SAMPLES * npix / s->n : npix;

	return p < 1 ? 1 : p > npix ? npix : p;
}

/* The map pixels of chunk ci into px->c. */
static void run_chunk(struct pix *px, uint64_t ci)
{
	const struct run *run = px->run;
	const struct frs_setup *s = run->s;
	uint64_t per = chunk_pixels(s), i1 = (ci + 1) * per;

	uint64_t i0 = ci * per > s->cell0 ? ci * per : s->cell0;
	uint64_t py = i0 / s->iw, pxi = i0 % s->iw;

	i1 = i1 < (uint64_t)s->iw * s->ih ? i1 : (uint64_t)s->iw * s->ih;
	i1 = s->lev != NULL && i1 > s->cell1 ? s->cell1 : i1;
	/* (pxi, py) follow i: no division a pixel. */
	for (uint64_t i = i0; i < i1; i++, pxi = pxi + 1 < s->iw ? pxi + 1 :
	    (py++, (uint64_t)0)) {
		double imp;
		if (!frs_cell_here(s->lev, s->level, i) ||
		    !((imp = run->map->v[i]) > 0.0))
			continue;	/* zero importance costs nothing */
		px->w.lim = frs_thr_words(px->thr, run->tau, run->nsteps,
		    imp * s->iscale, s->rule);
		if (px->w.lim == 0)
			continue;
		px->w.x0 = pxi * s->ns;
		px->w.y0 = py * s->ns;
		px->pdf = imp / s->mean;
		switch (run->algo) {
		case FRS_NAIVE: frs_walk_naive(&px->w); break;
		case FRS_STACK:
		case FRS_LEVEL1:
		case FRS_LEVEL2: frs_walk_minmap(&px->w, run->start); break;
		default: pix_sorted(px); break;
		}
	}
}

/* The walk of a thread's pixels: the run's window, minmap, lists and
 * steps. */
static void pix_start(struct pix *px, const struct run *run)
{
	const struct frs_prep *p = run->p;
	struct frs_walk *w = &px->w;

	px->run = run;
	win_of(run->s, &w->win);
	for (unsigned l = 0; l < 32; l++)
		w->lev[l] = l < p->nlev ? p->lev[l] : NULL;
	if (p->m != NULL)	/* lists alone may have no level 0 */
		w->lev[0] = p->m->v;
	w->sval = p->sval;
	w->sidx = p->sidx;
	w->soff = p->soff;
	w->b = p->block ? p->block : 1;
	w->lb = num_log2_ceil(w->b);
	w->bmin = run->s->ns / w->b > 1 && w->lb < p->nlev ? p->lev[w->lb] :
	    NULL;
	w->thr = px->thr;
	w->nsteps = run->nsteps;
	frs_tcache_init(&w->tc);
}

/* run->bval, bpos, bstart, npos and lside for Sorted with shuffled tiles
 * (pix_few): the first values of the matrix, from its sorted lists in
 * O(blocks + values), by square of side bside (the pixel's side or the
 * next power of two above, at most half the matrix's) and by value.  None
 * (npos 0) without lists or memory, which costs only time. */
static void first_values(struct run *run)
{
	const struct frs_setup *s = run->s;
	const struct frs_prep *p = run->p;
	uint64_t want = (uint64_t)s->mw * s->mh, nbx, nblk, B = 1, sq, nsq;
	uint32_t *at;
	unsigned lb;

	run->bval = run->bpos = run->bstart = run->vpos = NULL;
	run->npos = 0;
	/* pix_few's shifts and masks want powers of two (as lists do). */
	if (run->algo != FRS_SORTED || s->tiles != FRS_TILES_SHUFFLE ||
	    p->block == 0 || s->ns / p->block < 2 || (s->mw & (s->mw - 1)) ||
	    (s->mh & (s->mh - 1)))
		return;
	while (B < s->ns && 2 * B <= s->mw / 2 && 2 * B <= s->mh / 2)
		B *= 2;
	B = B <= s->mw / 2 && B <= s->mh / 2 ? B : (s->mw < s->mh ? s->mw :
	    s->mh);
	sq = (s->ns + B - 1) / B + 1;	/* squares met on an axis, at most */
	run->share = (double)(sq * sq) * (double)(B * B) /
	    ((double)s->mw * (double)s->mh);
	run->share = run->share < 1.0 ? run->share : 1.0;
	/* No more values than a pixel that pix_few serves can pass. */
	want = want < FEW_MAX ? want : FEW_MAX;
	want = want < p->below ? want : p->below;
	want = (double)want <= FEW_SORT / run->share ? want :
	    (uint64_t)(FEW_SORT / run->share) + 1;
	sq = s->mw / B;
	nsq = sq * (s->mh / B);
	run->bval = malloc(want * sizeof *run->bval);
	run->bpos = malloc(want * sizeof *run->bpos);
	run->bstart = calloc(nsq + 1, sizeof *run->bstart);
	at = malloc(want * sizeof *at);
	if (run->bval == NULL || run->bpos == NULL || run->bstart == NULL ||
	    at == NULL) {
		MEM_FREE(run->bval, run->bpos, run->bstart, at);
		run->bval = run->bpos = run->bstart = NULL;
		return;
	}
	lb = num_log2_ceil(p->block);
	nbx = s->mw / p->block;
	nblk = nbx * (s->mh / p->block);
	for (uint64_t blk = 0; blk < nblk; blk++) {
		uint64_t x = blk % nbx * p->block, y = blk / nbx * p->block;
		for (uint32_t k = p->soff[blk]; k < p->soff[blk + 1] &&
		    p->sval[k] < want; k++)
			at[p->sval[k]] = (uint32_t)((y + (p->sidx[k] >> lb)) *
			    s->mw + x + (p->sidx[k] & (p->block - 1)));
	}
	/* A counting sort by square; values in order within each. */
	for (uint64_t v = 0; v < want; v++)
		run->bstart[at[v] / s->mw / B * sq + at[v] % s->mw / B + 1]++;
	for (uint64_t q = 0; q < nsq; q++)
		run->bstart[q + 1] += run->bstart[q];
	for (uint64_t v = 0; v < want; v++) {
		uint64_t q = at[v] / s->mw / B * sq + at[v] % s->mw / B;
		uint32_t i = run->bstart[q]++;
		run->bval[i] = (uint32_t)v;
		run->bpos[i] = at[v];
	}
	for (uint64_t q = nsq; q > 0; q--)
		run->bstart[q] = run->bstart[q - 1];
	run->bstart[0] = 0;
	run->vpos = at;
	run->npos = want;
	run->lside = num_log2_ceil(B);
	run->lmw = num_log2_ceil(s->mw);
	run->lmh = num_log2_ceil(s->mh);
}

static void first_values_free(struct run *run)
{
	MEM_FREE(run->bval, run->bpos, run->bstart, run->vpos);
}

/* frs_sample: chunks [b, e) of the result's array. */
static int result_task(void *ctx, void *chunk, uint64_t b, uint64_t e)
{
	struct frs_chunk *c = chunk;
	struct pix px;

	pix_start(&px, ctx);
	for (uint64_t ci = b; ci < e; ci++) {
		px.c = &c[ci];
		run_chunk(&px, ci);
		if (px.c->failed)
			return frs_fail("out of memory for the samples");
	}
	return 0;
}

/* frs_sample_each: chunks c0 + [b, e), each in its place in the caller's
 * store, handed to fn. */
static int each_task(void *ctx, uint64_t b, uint64_t e)
{
	const struct run *run = ctx;
	struct pix px;

	pix_start(&px, run);
	for (uint64_t ci = b; ci < e; ci++) {
		struct frs_chunk c = { 0 };
		int rc = 0;
		c.e = run->store + run->at[ci];
		c.cap = run->at[ci + 1] - run->at[ci];
		c.fixed = 1;
		if (run->xy != NULL) {
			c.xy = run->xy + 2 * run->at[ci];
			c.pdf = run->pdf != NULL ? run->pdf + run->at[ci] : NULL;
		}
		px.c = &c;
		run_chunk(&px, run->c0 + ci);
		if (c.failed)
			rc = frs_fail("out of memory for the samples");
		else
			rc = run->fn(run->ctx, run->c0 + ci, &c);
		if (rc < 0)
			return -1;
	}
	return 0;
}

int frs_steps_check(const uint64_t *steps, unsigned nsteps)
{
	if (nsteps < 1 || nsteps > 16)
		return frs_fail("progressive counts: 1 to 16 steps");
	for (unsigned k = 1; k < nsteps; k++)
		if (steps[k] <= steps[k - 1])
			return frs_fail("progressive counts: counts must increase");
	return 0;
}

uint64_t frs_lim_most(const struct frs_setup *s, double tau)
{
	struct frs_thr th;

	frs_thr_make(&th, tau * (s->max * s->iscale), s->rule);
	return th.lim;
}

int frs_sample_check(const struct frs_setup *s, const struct frs_prep *p,
    int algo, const char *name, const uint64_t *steps, unsigned nsteps,
    int count_only, double *tau)
{
	if (frs_steps_check(steps, nsteps) < 0)
		return -1;
	for (unsigned k = 0; k < nsteps; k++)
		tau[k] = frs_tau(s, steps[k]);
	if (!count_only && (s->sw > UINT32_MAX || s->sh > UINT32_MAX))
		return frs_fail("the window of %llux%llu elements is too large to "
		    "store samples (a count-only run counts them)",
		    (unsigned long long)s->sw, (unsigned long long)s->sh);
	if (algo != FRS_NAIVE && (algo != FRS_SORTED || p->block == 0) &&
	    p->nlev < 2)
		return frs_fail("%s: the matrix has no minmap", name);
	if (algo == FRS_SORTED && p->block != 0 && (p->block > s->ns ||
	    s->ns % p->block))
		return frs_fail("sorted: lists of blocks of %u do not fit "
		    "n_s = %u", p->block, s->ns);
	if (algo == FRS_SORTED && p->block > frs_tile_max_block(s))
		return frs_fail("sorted: shuffled tiles keep blocks of at most "
		    "%u whole, not %u", frs_tile_max_block(s), p->block);
	if (algo == FRS_SORTED && p->block != 0 && p->below != FRS_ALL_VALUES &&
	    frs_lim_most(s, tau[nsteps - 1]) > p->below)
		return frs_fail("sorted: the lists hold the values below "
		    "%llu, the thresholds reach %llu",
		    (unsigned long long)p->below, (unsigned long long)
		    frs_lim_most(s, tau[nsteps - 1]));
	return 0;
}

uint64_t frs_nchunks(const struct frs_setup *s)
{
	uint64_t per = chunk_pixels(s);
	return ((uint64_t)s->iw * s->ih + per - 1) / per;
}

int frs_sample_each(const struct frs_setup *s, const struct frs_imap *map,
    const struct frs_prep *p, enum frs_impl algo, uint64_t c0, uint64_t c1,
    const uint64_t *at, struct frs_elem *store, double *xy, double *pdf,
    frs_chunk_fn fn, void *ctx)
{
	double tau;
	struct run run = { .s = s, .map = map, .p = p, .algo = algo,
	    .tau = &tau, .nsteps = 1, .c0 = c0, .at = at, .store = store,
	    .fn = fn, .ctx = ctx };
	int rc;

	if (frs_sample_check(s, p, (int)algo, frs_impl_name(algo), &s->n, 1, 0,
	    &tau) < 0)
		return -1;
	if (algo == FRS_SORTED && p->block == 0)
		run.algo = frs_sorted_walk(s);
	run.start = frs_impl_level(s, p, run.algo);
	/* Points in place need Sorted's lists without jitter
	 * (take_points). */
	if (xy != NULL && algo == FRS_SORTED && p->block != 0 &&
	    s->jitter == FRS_PLACE_CENTRE) {
		run.xy = xy;
		run.pdf = pdf;
	}
	if (c1 > frs_nchunks(s) || c0 > c1)
		return frs_fail("frs_sample_each: chunks %llu to %llu of %llu",
		    (unsigned long long)c0, (unsigned long long)c1,
		    (unsigned long long)frs_nchunks(s));
	first_values(&run);
	rc = frs_parallel(c1 - c0, 1, each_task, &run, NULL);
	first_values_free(&run);
	return rc;
}

static const struct frs_chunk_kind chunk_kind =
    FRS_CHUNK_KIND(struct frs_chunk);

int frs_sample(const struct frs_setup *s, const struct frs_imap *map,
    const struct frs_prep *p, enum frs_impl algo, const uint64_t *steps,
    unsigned nsteps, int count_only, struct frs_result *r)
{
	double tau[16];
	struct run run = { .s = s, .map = map, .p = p, .algo = algo,
	    .tau = tau, .nsteps = nsteps, .count_only = count_only };

	memset(r, 0, sizeof *r);
	if (frs_sample_check(s, p, (int)algo, frs_impl_name(algo), steps,
	    nsteps, count_only, tau) < 0)
		return -1;
	if (algo == FRS_SORTED && p->block == 0)
		run.algo = frs_sorted_walk(s);
	run.start = frs_impl_level(s, p, run.algo);
	first_values(&run);
	r->chunk = frs_chunks_run(&chunk_kind, frs_nchunks(s), result_task,
	    &run, &r->count);
	first_values_free(&run);
	r->nchunk = r->chunk != NULL ? frs_nchunks(s) : 0;
	return r->chunk != NULL ? 0 : -1;
}

void frs_result_free(struct frs_result *r)
{
	frs_chunks_free(&chunk_kind, r->chunk, r->nchunk);
	memset(r, 0, sizeof *r);
}

/* ---- chunks of any element ------------------------------------------ */

struct chunks_job {
	frs_chunks_task task;
	void *ctx;
	void *chunk;
};

static int chunks_job(void *ctx, uint64_t b, uint64_t e)
{
	struct chunks_job *j = ctx;

	return j->task(j->ctx, j->chunk, b, e);
}

/* The chunks' fields are read by their offsets: memcpy, as the kind's
 * struct is not known here. */
static char *chunk_at(const struct frs_chunk_kind *k, void *chunk,
    uint64_t i, size_t field)
{
	return (char *)chunk + i * k->size + field;
}

void *frs_chunks_run(const struct frs_chunk_kind *k, uint64_t nchunk,
    frs_chunks_task task, void *ctx, uint64_t *count)
{
	struct chunks_job j = { task, ctx, calloc(nchunk, k->size) };
	int rc;

	*count = 0;
	if (j.chunk == NULL) {
		frs_fail("out of memory");
		return NULL;
	}
	rc = frs_parallel(nchunk, 1, chunks_job, &j, NULL);
	for (uint64_t i = 0; i < nchunk; i++) {
		uint64_t n;
		memcpy(&n, chunk_at(k, j.chunk, i, k->count), sizeof n);
		*count += n;
	}
	if (rc < 0) {
		frs_chunks_free(k, j.chunk, nchunk);
		*count = 0;
		return NULL;
	}
	return j.chunk;
}

void frs_chunks_free(const struct frs_chunk_kind *k, void *chunk,
    uint64_t nchunk)
{
	for (uint64_t i = 0; i < nchunk; i++) {
		void *e;
		memcpy(&e, chunk_at(k, chunk, i, k->elems), sizeof e);
		free(e);
	}
	free(chunk);
}

void *frs_elems_grow(void *e, size_t size, uint64_t need, uint64_t *cap,
    int *failed)
{
	uint64_t ncap = *cap ? 2 * *cap : 1024;
	void *ne;

	if (need <= *cap)
		return e;
	while (ncap < need)
		ncap *= 2;
	ne = realloc(e, ncap * size);
	if (ne == NULL) {
		*failed = 1;
		return e;
	}
	*cap = ncap;
	return ne;
}

/* ---- points ------------------------------------------------------- */

double frs_below_one(double v)
{
	return v < 1.0 ? v : 0x1.fffffffffffffp-1;
}

uint64_t frs_level_place(uint64_t seed, unsigned level, uint64_t id,
    unsigned axis)
{
	uint64_t r = frs_rand64(seed, FRS_STREAM_PLACE, id);

	return (r >> (21 * axis)) & (((uint64_t)1 << level) - 1);
}

/*
 * An element's point, at every level alike: each level's element grid is
 * as fine against its samples' spacing as level 0's (sigma elements at
 * the sparsity bound), so centres are as good a place at every level.
 * (A volume's levels go to level 0's grid instead, frs3_point.)
 */
void frs_point(const struct frs_setup *s, const struct frs_elem *e,
    double *x, double *y)
{
	double xy[2];

	frs_points(s, e, 1, xy);
	*x = xy[0];
	*y = xy[1];
}

/* Elements a piece of jittered_points: its arrays stay in the
 * first-level cache. */
#define JPIECE 256

/* v[i] + r - floor(v[i] + r), the rotation of Halton points, for
 * v[i] and r in [0, 1]: the sum is below 2, and where it is 1 or more the
 * subtraction of 1 is exact (Sterbenz), as floor's would be, so a select
 * gives floor's bits and vectorises without SSE4.1. */
FRS_WIDE static void rotate_n(double *v, size_t n, double r)
{
	for (size_t i = 0; i < n; i++) {
		double t = v[i] + r;
		v[i] = t >= 1.0 ? t - 1.0 : t;
	}
}

/*
 * The jitter of n <= JPIECE elements in [0, 1)^2, by (seed, element):
 * random, both coordinates from one Philox block (half the cost of a
 * block each); or the Halton point (2, 3) of the element's number + 1,
 * rotated by the seed (Cranley-Patterson), so that it depends on nothing
 * but both, base 3 from num_radical3's table.  The random numbers and
 * the radical inverses are made in vectors.
 */
static void jitter_n(const struct frs_setup *s, const struct frs_elem *e,
    size_t n, double *jx, double *jy)
{
	uint64_t ix[JPIECE];

	for (size_t i = 0; i < n; i++) {
		uint64_t id = (uint64_t)e[i].y * s->sw + e[i].x;
		ix[i] = s->jitter == FRS_PLACE_RANDOM ? id : id + 1;
	}
	if (s->jitter == FRS_PLACE_RANDOM) {
		frs_rand01_pair_n(s->seed, FRS_STREAM_JITTER, ix, n, jx, jy);
		return;
	}
	num_radical_inverse_n(ix, n, 2, jx);
	num_radical3_n(ix, n, jy);
	rotate_n(jx, n, frs_rand01(s->seed, FRS_STREAM_JITTER, UINT64_MAX));
	rotate_n(jy, n, frs_rand01(s->seed, FRS_STREAM_JITTER, UINT64_MAX - 1));
}

/* The n points of elements e with jitter jx, jy: coord of each. */
FRS_WIDE static void coords_n(const struct frs_elem *e, size_t n,
    const double *jx, const double *jy, double sw, double sh, double *xy)
{
	for (size_t i = 0; i < n; i++) {
		xy[2 * i] = coord(e[i].x, jx[i], sw);
		xy[2 * i + 1] = coord(e[i].y, jy[i], sh);
	}
}

void frs_points(const struct frs_setup *s, const struct frs_elem *e,
    size_t n, double *xy)
{
	double sw = (double)s->sw, sh = (double)s->sh;

	if (s->jitter != FRS_PLACE_CENTRE) {
		double jx[JPIECE], jy[JPIECE];
		for (size_t p = 0; p < n; p += JPIECE) {
			size_t m = n - p < JPIECE ? n - p : JPIECE;
			jitter_n(s, e + p, m, jx, jy);
			coords_n(e + p, m, jx, jy, sw, sh, xy + 2 * p);
		}
		return;
	}
	for (size_t i = 0; i < n; i++) {
		xy[2 * i] = coord(e[i].x, 0.5, sw);
		xy[2 * i + 1] = coord(e[i].y, 0.5, sh);
	}
}
