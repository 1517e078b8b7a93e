/*
 * Forced Random Sampling's thresholding (thesis Ch. 5), one definition
 * for the CPU (src/lib/sample/frs.c includes this file) and for OpenCL:
 * the pass test and its coin, the tile of a window element, Naive's
 * element walk, the depth-first minmap walk of Stack and Level N, and
 * Sorted's block, in the common subset of C and OpenCL C.  Every side
 * thus emits the same elements in the same order by construction.
 *
 * What a side does with an element that passes is its own: the CPU
 * stores it in its chunk (or makes its point in place), a kernel counts
 * it or writes it as an (x, y, step) uint triple.  Each side defines the
 * two hooks frs_walk_put and frs_walk_take for that, over its own pixel
 * whose first member is the struct frs_walk the walks get.  The CPU's
 * shortcuts that only skip work (Sorted's live blocks, region bounds and
 * pix_few) stay in frs.c.
 *
 * The kernels, OpenCL's alone (at the end): Naive, Stack, Level N and
 * Sorted with one work-item per active map pixel, and Flat 1 (Sec. 5.4)
 * with one launch per minmap level over a list of candidate blocks.  The
 * host (src/lib/sample/frscl.c) does the setup and turns each pixel's
 * thresholds into integers (frs_thr_words, as the CPU does), so no
 * floating point happens here.  The records of the active pixels and the
 * words of the setup (the first argument) are laid out as cl/defs.cl
 * says.  Every per-pixel kernel runs twice: with write = 0 it stores the
 * number of elements of each pixel in cnt; with write = 1 it writes them
 * from out[3 off[p]].  All window coordinates are 64-bit.
 */

/* The transforms of the tiles met last, direct-mapped by tile column.
 * On the CPU a thread's rows of pixels cross a row of tiles again and
 * again, and a transform costs two Philox blocks: 1024 columns, so that
 * a window of up to 1024 tiles a row (a sun's) computes each transform
 * once a row of tiles, not once a row of pixels (interior.exr at 262144:
 * 9 ms).  A work-item's pixel meets few tiles: the last one. */
#ifdef __OPENCL_VERSION__
#define FRS_TCACHE 1
#else
#define FRS_TCACHE 1024
#endif

/* The window over the tiled matrix, as a run sees it. */
struct frs_win {
	FRS_U64 mw, mh;		/* matrix */
	FRS_U64 wx, wy;		/* window offset */
	FRS_U64 sw;		/* window width, the coins' row stride */
	FRS_U64 ns;		/* window elements per pixel side */
	FRS_U64 seed;
	FRS_U32 tiles;		/* 1: shuffled (cl/tile.cl), 0: plain */
	FRS_U32 sx, sy;		/* log2 of mw and mh, 64 unless both are
				 * powers of two (frs_win_shifts) */
};

struct frs_tcache {
	struct {
		FRS_U64 tx, ty;
		int valid;
		struct frs_tile t;
	} e[FRS_TCACHE];
};

/* The smallest l with 2^l >= v: the host's num_log2_ceil (base/num.h),
 * written again only for the device, which has no num.h. */
#ifdef __OPENCL_VERSION__
FRS_FN FRS_U32 frs_log2(FRS_U64 v)
{
	FRS_U32 l = 0;

	while (((FRS_U64)1 << l) < v)
		l++;
	return l;
}
#else
#define frs_log2 num_log2_ceil
#endif

/* Matrices of power-of-two sides (all that frd-gen makes) find an
 * element's tile by a shift: a 64-bit division is some 40 cycles, and
 * frs_tile_at runs per block. */
FRS_FN void frs_win_shifts(struct frs_win *w)
{
	int pow2 = (w->mw & (w->mw - 1)) == 0 && (w->mh & (w->mh - 1)) == 0;

	w->sx = pow2 ? frs_log2(w->mw) : 64;
	w->sy = pow2 ? frs_log2(w->mh) : 64;
}

FRS_FN void frs_tcache_init(struct frs_tcache *c)
{
	for (FRS_U32 k = 0; k < FRS_TCACHE; k++)
		c->e[k].valid = 0;
}

/* The transform of tile (tx, ty), from the cache or made into it. */
FRS_FN const struct frs_tile *frs_tile_get(const struct frs_win *w,
    struct frs_tcache *c, FRS_U64 tx, FRS_U64 ty)
{
	FRS_U32 k = (FRS_U32)(tx % FRS_TCACHE);

	if (!c->e[k].valid || c->e[k].tx != tx || c->e[k].ty != ty) {
		FRS_U64 m[3];
		m[0] = w->mw;
		m[1] = w->mh;
		m[2] = 1;
		if (w->tiles)
			frs_tile_make(&c->e[k].t, w->seed, 2, m, tx, ty, 0);
		else
			frs_tile_plain(&c->e[k].t);
		c->e[k].tx = tx;
		c->e[k].ty = ty;
		c->e[k].valid = 1;
	}
	return &c->e[k].t;
}

/* The tile of window element (x, y), the element's place in it in
 * (*lx, *ly). */
FRS_FN const struct frs_tile *frs_tile_at(const struct frs_win *w,
    struct frs_tcache *c, FRS_U64 x, FRS_U64 y, FRS_U64 *lx, FRS_U64 *ly)
{
	FRS_U64 X = w->wx + x, Y = w->wy + y, tx, ty;

	if (w->sx < 64) {
		tx = X >> w->sx;
		ty = Y >> w->sy;
	} else {
		tx = X / w->mw;
		ty = Y / w->mh;
	}
	*lx = X - tx * w->mw;
	*ly = Y - ty * w->mh;
	return frs_tile_get(w, c, tx, ty);
}

/* The index of the level-l matrix block that shows the level-l block of
 * tile position (lx, ly), on the grid of (mw >> l) x (mh >> l). */
FRS_FN FRS_U64 frs_block_index(const struct frs_win *w,
    const struct frs_tile *t, FRS_U32 l, FRS_U64 lx, FRS_U64 ly)
{
	FRS_U64 m[3], u[2], v[2];

	m[0] = w->mw;
	m[1] = w->mh;
	m[2] = 1;
	u[0] = lx >> l;
	u[1] = ly >> l;
	frs_tile_block(t, 2, m, l, u, v);
	return v[1] * (w->mw >> l) + v[0];
}

/* Element k of a sorted block of side b = 2^lb, at the block's window
 * origin (x, y). */
FRS_FN void frs_block_elem(const struct frs_tile *t, FRS_U64 b, FRS_U32 lb,
    FRS_U32 k, FRS_U64 x, FRS_U64 y, FRS_U64 *ex, FRS_U64 *ey)
{
	FRS_U64 w[2], u[2];

	w[0] = k & (b - 1);
	w[1] = k >> lb;
	frs_tile_inblock(t, 2, b, w, u);
	*ex = x + u[0];
	*ey = y + u[1];
}

FRS_FN FRS_U64 frs_wrap(FRS_U64 v, FRS_U64 n)
{
	return (n & (n - 1)) == 0 ? v & (n - 1) : v % n;
}

/*
 * The threshold rule of one step, in integers (frs_thr_make's pw words):
 * values below tc[0] pass, and tc[0] passes when the 53-bit coin of
 * (seed, element id) is below tc[1] (0: never).  Unbiased, tc[0] =
 * floor(T) and tc[1] = ceil(frac(T) 2^53): the coin u 2^-53 < frac(T)
 * exactly when u < tc[1].  The thesis's v < T is tc[0] = ceil(T), no
 * coin.
 */
FRS_FN int frs_pass(FRS_GLOBAL const FRS_U64 *tc, FRS_U64 v, FRS_U64 seed,
    FRS_U64 id)
{
	if (v < tc[0])
		return 1;
	return v == tc[0] && tc[1] > 0 &&
	    frs_rand53(seed, FRS_STREAM_COIN, id) < tc[1];
}

/* The first of nsteps steps (words thr, two a step) at which value v of
 * element id passes, or nsteps when it passes none: the last step first,
 * as most values that reach the test fail it. */
FRS_FN FRS_U32 frs_step(FRS_GLOBAL const FRS_U64 *thr, FRS_U32 nsteps,
    FRS_U64 v, FRS_U64 seed, FRS_U64 id)
{
	FRS_U32 k, last = nsteps - 1;

	if (!frs_pass(thr + 2 * last, v, seed, id))
		return nsteps;
	for (k = 0; k < last && !frs_pass(thr + 2 * k, v, seed, id); k++)
		;
	return k;
}

/* What the walks read of one pixel and its run. */
struct frs_walk {
	struct frs_win win;
	FRS_GLOBAL const FRS_U32 *lev[32];	/* minmap level l (0: matrix) */
	/* Sorted: the lists of blocks of side b = 2^lb, block k's from
	 * soff[k] (frsprep.h); bmin, when not 0, the minmap level lb, whose
	 * minimum of a block is a look-up where its list is a cache miss. */
	FRS_GLOBAL const FRS_U32 *sval, *sidx, *soff, *bmin;
	FRS_U64 b;
	FRS_U32 lb;
	FRS_GLOBAL const FRS_U64 *thr;	/* per step k: tc at 2 k (frs_pass) */
	FRS_U32 nsteps;
	FRS_U64 lim;		/* values from it pass no step */
	FRS_U64 x0, y0;		/* the pixel's first window element */
	struct frs_tcache tc;
};

/* Each side's (frs.c; the kernels below): element (x, y) passes at step
 * `step`; and, Sorted with one step, the first k elements of the list
 * idx of the block of tile t at window element (x, y) pass. */
FRS_FN void frs_walk_put(struct frs_walk *w, FRS_U64 x, FRS_U64 y,
    FRS_U32 step);
FRS_FN void frs_walk_take(struct frs_walk *w, const struct frs_tile *t,
    FRS_GLOBAL const FRS_U32 *idx, FRS_U64 k, FRS_U64 x, FRS_U64 y);

/* Window element (x, y) of matrix value v, through every step's rule. */
FRS_FN void frs_emit(struct frs_walk *w, FRS_U64 x, FRS_U64 y, FRS_U64 v)
{
	FRS_U32 k = frs_step(w->thr, w->nsteps, v, w->win.seed,
	    y * w->win.sw + x);

	if (k < w->nsteps)
		frs_walk_put(w, x, y, k);
}

/* The minmap value of the level-l block whose first element is (x, y).
 * Plain tiles are the identity, taken here, in the innermost look-up of
 * Stack and Level N, and not in frs_tile_at and frs_block_index: taught
 * the same shortcut, those still cost Level 1 a fifth more time. */
FRS_FN FRS_U32 frs_minmap_at(struct frs_walk *w, FRS_U32 l, FRS_U64 x,
    FRS_U64 y)
{
	FRS_U64 lx, ly;
	const struct frs_tile *t;

	if (!w->win.tiles) {
		lx = frs_wrap(w->win.wx + x, w->win.mw);
		ly = frs_wrap(w->win.wy + y, w->win.mh);
		return w->lev[l][(ly >> l) * (w->win.mw >> l) + (lx >> l)];
	}
	t = frs_tile_at(&w->win, &w->tc, x, y, &lx, &ly);
	return w->lev[l][frs_block_index(&w->win, t, l, lx, ly)];
}

/* The k values of r from window column x of row y that pass the
 * pixel's limit, in order.  Their minimum first, in four independent
 * chains (or wide, where the compiler vectorises): most runs end there. */
FRS_FN void frs_naive_run(struct frs_walk *w, FRS_GLOBAL const FRS_U32 *r,
    FRS_U64 k, FRS_U64 x, FRS_U64 y)
{
	FRS_U32 lo[4];
	FRS_U64 j = 0;

	lo[0] = lo[1] = lo[2] = lo[3] = 0xffffffffu;
	for (; j + 4 <= k; j += 4)
		for (FRS_U32 c = 0; c < 4; c++)
			lo[c] = r[j + c] < lo[c] ? r[j + c] : lo[c];
	for (; j < k; j++)
		lo[0] = r[j] < lo[0] ? r[j] : lo[0];
	lo[0] = lo[1] < lo[0] ? lo[1] : lo[0];
	lo[2] = lo[3] < lo[2] ? lo[3] : lo[2];
	if ((lo[2] < lo[0] ? lo[2] : lo[0]) >= w->lim)
		return;
	for (j = 0; j < k; j++)
		if (r[j] < w->lim)
			frs_emit(w, x + j, y, r[j]);
}

/* Listing 5.2: every window element of the pixel, row by row, each row
 * in runs that do not wrap around the matrix; with shuffled tiles each
 * element through its tile's transform. */
FRS_FN void frs_walk_naive(struct frs_walk *w)
{
	FRS_U64 ns = w->win.ns, mw = w->win.mw;

	if (!w->win.tiles) {
		for (FRS_U64 y = w->y0; y < w->y0 + ns; y++) {
			FRS_GLOBAL const FRS_U32 *row = w->lev[0] +
			    frs_wrap(w->win.wy + y, w->win.mh) * mw;
			FRS_U64 mx = frs_wrap(w->win.wx + w->x0, mw), run;
			for (FRS_U64 k = 0; k < ns; k += run) {
				run = ns - k < mw - mx ? ns - k : mw - mx;
				frs_naive_run(w, row + mx, run, w->x0 + k, y);
				mx = mx + run == mw ? 0 : mx + run;
			}
		}
		return;
	}
	for (FRS_U64 y = w->y0; y < w->y0 + ns; y++)
		for (FRS_U64 x = w->x0; x < w->x0 + ns; x++) {
			FRS_U32 v = frs_minmap_at(w, 0, x, y);
			if (v < w->lim)
				frs_emit(w, x, y, v);
		}
}

/* A minmap block of the walk, inside the pixel: below n_s <= 2^31. */
struct frs_blk {
	FRS_U32 x, y, l;
};

FRS_FN void frs_push(struct frs_blk *st, int *top, FRS_U32 x, FRS_U32 y,
    FRS_U32 l)
{
	st[*top].x = x;
	st[*top].y = y;
	st[*top].l = l;
	(*top)++;
}

/* The four elements of the level-1 block at window element (x, y) in
 * the walk's order, straight: most blocks of a walk are of level 1, and
 * the stack cost Level 1 a quarter more time. */
FRS_FN void frs_walk_quad(struct frs_walk *w, FRS_U64 x, FRS_U64 y)
{
	for (FRS_U32 q = 0; q < 4; q++) {
		FRS_U64 ex = x + (q & 1), ey = y + (q >> 1);
		FRS_U32 v = frs_minmap_at(w, 0, ex, ey);
		if (v < w->lim)
			frs_emit(w, ex, ey, v);
	}
}

/* The same for a block of level 2: the bottom of every walk, and Level
 * 2's blocks, whose stack cost it half again the time. */
FRS_FN void frs_walk_quad2(struct frs_walk *w, FRS_U64 x, FRS_U64 y)
{
	for (FRS_U32 q = 0; q < 4; q++) {
		FRS_U64 bx = x + 2 * (q & 1), by = y + 2 * (q >> 1);
		if (frs_minmap_at(w, 1, bx, by) < w->lim)
			frs_walk_quad(w, bx, by);
	}
}

/* Listing 5.4 (Stack) and 5.5 (Level N) in one: the depth-first visit
 * of the quadrants of the block of level l at window element (x, y) in
 * the order (0,0), (1,0), (0,1), (1,1), on an explicit stack (OpenCL has
 * no recursion). */
FRS_FN void frs_walk_block(struct frs_walk *w, FRS_U64 x, FRS_U64 y,
    FRS_U32 l)
{
	struct frs_blk st[3 * 32 + 4];
	int top = 0;

	frs_push(st, &top, (FRS_U32)(x - w->x0), (FRS_U32)(y - w->y0), l);
	while (top > 0) {
		struct frs_blk e = st[--top];
		FRS_U32 v, h;
		x = w->x0 + e.x;
		y = w->y0 + e.y;
		if ((v = frs_minmap_at(w, e.l, x, y)) >= w->lim)
			continue;
		if (e.l == 0) {
			frs_emit(w, x, y, v);
			continue;
		}
		if (e.l <= 2) {
			if (e.l == 1)
				frs_walk_quad(w, x, y);
			else
				frs_walk_quad2(w, x, y);
			continue;
		}
		h = 1u << (e.l - 1);
		frs_push(st, &top, e.x + h, e.y + h, e.l - 1);
		frs_push(st, &top, e.x, e.y + h, e.l - 1);
		frs_push(st, &top, e.x + h, e.y, e.l - 1);
		frs_push(st, &top, e.x, e.y, e.l - 1);
	}
}

/* The walk of the pixel from its blocks of level L, in row order; those
 * of Level 1 and 2 straight, without the stack. */
FRS_FN void frs_walk_minmap(struct frs_walk *w, FRS_U32 L)
{
	FRS_U64 b = (FRS_U64)1 << L, nb = w->win.ns / b;

	for (FRS_U64 y = w->y0; y < w->y0 + nb * b; y += b)
		for (FRS_U64 x = w->x0; x < w->x0 + nb * b; x += b) {
			if (L == 0 || L > 2)
				frs_walk_block(w, x, y, L);
			else if (frs_minmap_at(w, L, x, y) >= w->lim)
				continue;
			else if (L == 1)
				frs_walk_quad(w, x, y);
			else
				frs_walk_quad2(w, x, y);
		}
}

/* Listing 5.11 with one step: how many of the first values of a block's
 * list (values val, in-block places idx, len of them) pass, the block at
 * window element (x, y) of tile t.  The values below the limit by
 * bisection, the last of them through its coin if it needs one (a list's
 * values are distinct, so only it can); the others pass as they are. */
FRS_FN FRS_U64 frs_sorted_cut(struct frs_walk *w, const struct frs_tile *t,
    FRS_GLOBAL const FRS_U32 *val, FRS_GLOBAL const FRS_U32 *idx,
    FRS_U64 len, FRS_U64 x, FRS_U64 y)
{
	FRS_U64 lo = 0, hi = len, ex, ey;

	if (len == 0 || val[0] >= w->lim)
		return 0;
	while (lo < hi) {
		FRS_U64 mid = lo + (hi - lo) / 2;
		if (val[mid] < w->lim)
			lo = mid + 1;
		else
			hi = mid;
	}
	if (lo > 0) {
		frs_block_elem(t, w->b, w->lb, idx[lo - 1], x, y, &ex, &ey);
		if (!frs_pass(w->thr, val[lo - 1], w->win.seed,
		    ey * w->win.sw + ex))
			lo--;
	}
	return lo;
}

/* Listing 5.11: the sorted list of the pixel's block at window element
 * (x, y), until a value is too large.  This is the hot loop of the
 * fastest implementation. */
FRS_FN void frs_sorted_block(struct frs_walk *w, FRS_U64 x, FRS_U64 y)
{
	FRS_U64 lx, ly, blk, len, k;
	FRS_GLOBAL const FRS_U32 *val, *idx;
	const struct frs_tile *t = frs_tile_at(&w->win, &w->tc, x, y, &lx,
	    &ly);

	blk = frs_block_index(&w->win, t, w->lb, lx, ly);
	if (w->bmin != 0 && w->bmin[blk] >= w->lim)
		return;
	val = w->sval + w->soff[blk];
	idx = w->sidx + w->soff[blk];
	len = w->soff[blk + 1] - w->soff[blk];
	if (w->nsteps == 1) {
		if ((k = frs_sorted_cut(w, t, val, idx, len, x, y)) > 0)
			frs_walk_take(w, t, idx, k, x, y);
		return;
	}
	for (k = 0; k < len && val[k] < w->lim; k++) {
		FRS_U64 ex, ey;
		frs_block_elem(t, w->b, w->lb, idx[k], x, y, &ex, &ey);
		frs_emit(w, ex, ey, val[k]);
	}
}

/* Every block of the pixel, row by row. */
FRS_FN void frs_walk_sorted(struct frs_walk *w)
{
	FRS_U64 nb = w->win.ns / w->b;

	for (FRS_U64 by = 0; by < nb; by++)
		for (FRS_U64 bx = 0; bx < nb; bx++)
			frs_sorted_block(w, w->x0 + bx * w->b,
			    w->y0 + by * w->b);
}

#ifdef __OPENCL_VERSION__
/* A work-item's pixel: the walk first, as the hooks take it. */
struct pix {
	struct frs_walk w;
	ulong count;
	int write;
	__global uint *out;	/* at the pixel's offset */
};

static void frs_walk_put(struct frs_walk *w, ulong x, ulong y, uint step)
{
	struct pix *p = (struct pix *)w;

	if (p->write) {
		__global uint *o = p->out + 3 * p->count;
		o[0] = (uint)x;
		o[1] = (uint)y;
		o[2] = step;
	}
	p->count++;
}

static void frs_walk_take(struct frs_walk *w, const struct frs_tile *t,
    __global const uint *idx, ulong k, ulong x, ulong y)
{
	struct pix *p = (struct pix *)w;

	if (!p->write) {
		p->count += k;
		return;
	}
	for (ulong j = 0; j < k; j++) {
		ulong ex, ey;
		frs_block_elem(t, w->b, w->lb, idx[j], x, y, &ex, &ey);
		frs_walk_put(w, ex, ey, 0);
	}
}

/* The walk of active pixel i: the run from the setup words, the pixel
 * from its record; minmap level l from lev + loff[l] (loff 0: lev is
 * the matrix alone). */
static void walk_init(struct frs_walk *w, __global const ulong *setup,
    __global const ulong *thr, ulong i, __global const uint *lev,
    __global const ulong *loff)
{
	__global const ulong *th = thr + i * FRSCL_RECORD(setup[FRSCL_NSTEPS]);
	ulong px = th[FRSCL_REC_PIXEL];

	w->win.mw = setup[FRSCL_MW];
	w->win.mh = setup[FRSCL_MH];
	w->win.wx = setup[FRSCL_WX];
	w->win.wy = setup[FRSCL_WY];
	w->win.sw = setup[FRSCL_SW];
	w->win.ns = setup[FRSCL_NS];
	w->win.seed = setup[FRSCL_SEED];
	w->win.tiles = (uint)setup[FRSCL_TILES];
	frs_win_shifts(&w->win);
	for (uint l = 0; l < 32; l++)
		w->lev[l] = loff != 0 ? lev + loff[l] : lev;
	w->sval = w->sidx = w->soff = w->bmin = 0;
	w->b = 1;
	w->lb = 0;
	w->thr = th + FRSCL_REC_TF(0);
	w->nsteps = (uint)setup[FRSCL_NSTEPS];
	w->lim = th[FRSCL_REC_LIM];
	w->x0 = (px & 0xffffffffUL) * w->win.ns;
	w->y0 = (px >> 32) * w->win.ns;
	frs_tcache_init(&w->tc);
}

static void pix_init(struct pix *p, __global const ulong *setup,
    __global const ulong *thr, ulong i, __global const uint *lev,
    __global const ulong *loff, __global const ulong *off,
    __global uint *out, int write)
{
	walk_init(&p->w, setup, thr, i, lev, loff);
	p->count = 0;
	p->write = write;
	p->out = write ? out + 3 * off[i] : out;
}

/* Listing 5.2. */
__kernel void frs_naive(__global const ulong *setup, __global const ulong *thr,
    __global const uint *mat, __global ulong *cnt, __global const ulong *off,
    __global uint *out, int write)
{
	ulong i = get_global_id(0);
	struct pix p;

	if (i >= setup[FRSCL_NACT])
		return;
	pix_init(&p, setup, thr, i, mat, 0, off, out, write);
	frs_walk_naive(&p.w);
	if (!write)
		cnt[i] = p.count;
}

/* Listing 5.4 (Stack) and 5.5 (Level N): from start blocks of level
 * setup[FRSCL_START]. */
__kernel void frs_minmap(__global const ulong *setup, __global const ulong *thr,
    __global const uint *lev, __global const ulong *loff,
    __global ulong *cnt, __global const ulong *off, __global uint *out,
    int write)
{
	ulong i = get_global_id(0);
	struct pix p;

	if (i >= setup[FRSCL_NACT])
		return;
	pix_init(&p, setup, thr, i, lev, loff, off, out, write);
	frs_walk_minmap(&p.w, (uint)setup[FRSCL_START]);
	if (!write)
		cnt[i] = p.count;
}

/* Listing 5.11: the sorted values of each block of b x b
 * (setup[FRSCL_START]). */
__kernel void frs_sorted(__global const ulong *setup, __global const ulong *thr,
    __global const uint *sval, __global const uint *sidx,
    __global const uint *soff, __global ulong *cnt, __global const ulong *off,
    __global uint *out, int write)
{
	ulong i = get_global_id(0);
	struct pix p;

	if (i >= setup[FRSCL_NACT])
		return;
	pix_init(&p, setup, thr, i, sval, 0, off, out, write);
	p.w.sval = sval;
	p.w.sidx = sidx;
	p.w.soff = soff;
	p.w.b = setup[FRSCL_START];
	p.w.lb = frs_log2(p.w.b);
	frs_walk_sorted(&p.w);
	if (!write)
		cnt[i] = p.count;
}

/*
 * Flat 1 (thesis Sec. 5.4).  Candidates are uint triples (active pixel,
 * x, y inside the pixel).  frs_flat_init makes the start blocks (level
 * setup[FRSCL_START]) whose minimum is below the pixel's limit, per pixel;
 * frs_flat_refine, launched once per level l >= 1, keeps the children
 * (level l - 1) of each candidate whose minimum passes; frs_flat_final
 * tests the elements of level 0 and writes the samples.  Each runs with
 * write = 0 to count per item (cnt) and with write = 1 to write at the
 * offsets the host made from the counts: every list is sized exactly.
 * The order is that of Stack from the same start level.
 */

/* Candidate (pixel pi, x, y) at o[3 n] when writing; n + 1. */
static ulong cand(__global uint *o, int write, ulong n, uint pi, uint x,
    uint y)
{
	if (write) {
		o[3 * n] = pi;
		o[3 * n + 1] = x;
		o[3 * n + 2] = y;
	}
	return n + 1;
}

__kernel void frs_flat_init(__global const ulong *setup,
    __global const ulong *thr, __global const uint *lev,
    __global const ulong *loff, __global ulong *cnt,
    __global const ulong *off, __global uint *cand_out, int write)
{
	ulong i = get_global_id(0);
	ulong b, nb, n = 0;
	uint L;
	__global uint *o;
	struct frs_walk w;

	if (i >= setup[FRSCL_NACT])
		return;
	walk_init(&w, setup, thr, i, lev, loff);
	L = (uint)setup[FRSCL_START];
	b = (ulong)1 << L;
	nb = w.win.ns / b;
	o = write ? cand_out + 3 * off[i] : cand_out;
	for (ulong by = 0; by < nb; by++)
		for (ulong bx = 0; bx < nb; bx++)
			if (frs_minmap_at(&w, L, w.x0 + bx * b, w.y0 + by * b) <
			    w.lim)
				n = cand(o, write, n, (uint)i, (uint)(bx * b),
				    (uint)(by * b));
	if (!write)
		cnt[i] = n;
}

__kernel void frs_flat_refine(__global const ulong *setup,
    __global const ulong *thr, __global const uint *lev,
    __global const ulong *loff, __global const uint *cin, ulong ncand,
    uint l, __global uint *cnt, __global const ulong *off,
    __global uint *cout, int write)
{
	ulong i = get_global_id(0), n = 0;
	uint pi, cx, cy, h;
	__global uint *o;
	struct frs_walk w;

	if (i >= ncand)
		return;
	pi = cin[3 * i];
	cx = cin[3 * i + 1];
	cy = cin[3 * i + 2];
	walk_init(&w, setup, thr, pi, lev, loff);
	h = 1u << (l - 1);
	o = write ? cout + 3 * off[i] : cout;
	for (uint q = 0; q < 4; q++) {
		uint x = cx + (q & 1) * h, y = cy + (q >> 1) * h;
		if (frs_minmap_at(&w, l - 1, w.x0 + x, w.y0 + y) < w.lim)
			n = cand(o, write, n, pi, x, y);
	}
	if (!write)
		cnt[i] = (uint)n;
}

__kernel void frs_flat_final(__global const ulong *setup,
    __global const ulong *thr, __global const uint *mat,
    __global const uint *cin, ulong ncand, __global uint *cnt,
    __global const ulong *off, __global uint *out, int write)
{
	ulong i = get_global_id(0), x, y;
	struct pix p;

	if (i >= ncand)
		return;
	pix_init(&p, setup, thr, cin[3 * i], mat, 0, off, out, 0);
	x = p.w.x0 + cin[3 * i + 1];
	y = p.w.y0 + cin[3 * i + 2];
	p.write = write;
	p.out = write ? out + 3 * off[i] : out;
	frs_emit(&p.w, x, y, frs_minmap_at(&p.w, 0, x, y));
	if (!write)
		cnt[i] = (uint)p.count;
}
#endif
