/*
 * Forced Random Sampling on OpenCL (thesis Ch. 5): Naive, Stack, Level N,
 * Sorted with one work-item per active map pixel, and Flat 1 (Sec. 5.4)
 * with one kernel launch per minmap level over a list of candidate blocks.
 *
 * The host (src/lib/sample/frscl.c) does the setup and turns each pixel's
 * thresholds into integers, so no floating point happens here and every
 * device agrees with src/lib/sample/frs.c bit for bit.  The records of
 * the active pixels and the words of the setup (the first argument) are
 * laid out as cl/defs.cl says.
 *
 * Every per-pixel kernel runs twice: with write = 0 it stores the number
 * of elements of each pixel in cnt; with write = 1 it writes them as
 * (x, y, step) uint triples from out[3 off[p]], in the order in which
 * src/lib/sample/frs.c emits them.  All window coordinates are 64-bit.
 */

/* src/lib/sample/frs.c tile_at(): the transform of the last tile met. */
struct tcache {
	ulong tx, ty;
	int valid;
	struct frs_tile t;
};

/* The tile of window element (x, y), the element's place in it in
 * (*lx, *ly). */
static void tile_at(__global const ulong *setup, struct tcache *c, ulong x,
    ulong y, ulong *lx, ulong *ly)
{
	ulong mw = setup[FRSCL_MW], mh = setup[FRSCL_MH];
	ulong X = setup[FRSCL_WX] + x, Y = setup[FRSCL_WY] + y;
	ulong tx = X / mw, ty = Y / mh;

	*lx = X - tx * mw;
	*ly = Y - ty * mh;
	if (!c->valid || c->tx != tx || c->ty != ty) {
		ulong m[3];
		m[0] = mw;
		m[1] = mh;
		m[2] = 1;
		if (setup[FRSCL_TILES])
			frs_tile_make(&c->t, setup[FRSCL_SEED], 2, m, tx,
			    ty, 0);
		else
			frs_tile_plain(&c->t);
		c->tx = tx;
		c->ty = ty;
		c->valid = 1;
	}
}

/* src/lib/sample/frs.c block_index(). */
static ulong block_index(__global const ulong *setup, const struct frs_tile *t,
    uint l, ulong lx, ulong ly)
{
	ulong m[3], u[2], v[2];

	m[0] = setup[FRSCL_MW];
	m[1] = setup[FRSCL_MH];
	m[2] = 1;
	u[0] = lx >> l;
	u[1] = ly >> l;
	frs_tile_block(t, 2, m, l, u, v);
	return v[1] * (setup[FRSCL_MW] >> l) + v[0];
}

/* src/lib/sample/frs.c inblock(). */
static void inblock(const struct frs_tile *t, ulong b, uint lb, uint k,
    ulong x, ulong y, ulong *ex, ulong *ey)
{
	ulong w[2], u[2];

	w[0] = k & (b - 1);
	w[1] = k >> lb;
	frs_tile_inblock(t, 2, b, w, u);
	*ex = x + u[0];
	*ey = y + u[1];
}

struct pix {
	__global const ulong *th;	/* the pixel's record */
	ulong seed, sw;
	uint nsteps;
	ulong lim;
	ulong x0, y0;			/* the pixel's first window element */
	ulong count;
	int write;
	__global uint *out;		/* at the pixel's offset */
};

static ulong wrapn(ulong v, ulong n)
{
	return (n & (n - 1)) == 0 ? v & (n - 1) : v % n;
}

/* src/lib/sample/frs.c passes() with integer thresholds. */
static int passes_k(const struct pix *p, uint k, ulong v, ulong x, ulong y)
{
	ulong tf = p->th[FRSCL_REC_TF(k)], c = p->th[FRSCL_REC_COIN(k)];

	if (v < tf)
		return 1;
	return v == tf && c > 0 &&
	    frs_rand53(p->seed, FRS_STREAM_COIN, y * p->sw + x) < c;
}

static void put(struct pix *p, ulong x, ulong y, uint step)
{
	if (p->write) {
		__global uint *o = p->out + 3 * p->count;
		o[0] = (uint)x;
		o[1] = (uint)y;
		o[2] = step;
	}
	p->count++;
}

/* src/lib/sample/frs.c emit(). */
static void emit(struct pix *p, ulong x, ulong y, uint v)
{
	uint k, last = p->nsteps - 1;

	if (!passes_k(p, last, v, x, y))
		return;
	for (k = 0; k < last && !passes_k(p, k, v, x, y); k++)
		;
	put(p, x, y, k);
}

/* The record of active pixel i; its first window element in (*x0, *y0). */
static __global const ulong *record(__global const ulong *setup,
    __global const ulong *thr, ulong i, ulong *x0, ulong *y0)
{
	__global const ulong *th = thr + i * FRSCL_RECORD(setup[FRSCL_NSTEPS]);
	ulong px = th[FRSCL_REC_PIXEL];

	*x0 = (px & 0xffffffffUL) * setup[FRSCL_NS];
	*y0 = (px >> 32) * setup[FRSCL_NS];
	return th;
}

static void pix_init(struct pix *p, __global const ulong *setup,
    __global const ulong *thr, ulong i, __global const ulong *off,
    __global uint *out, int write)
{
	p->th = record(setup, thr, i, &p->x0, &p->y0);
	p->seed = setup[FRSCL_SEED];
	p->sw = setup[FRSCL_SW];
	p->nsteps = (uint)setup[FRSCL_NSTEPS];
	p->lim = p->th[FRSCL_REC_LIM];
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
	ulong ns, mw, mh, wx, wy;
	struct pix p;

	if (i >= setup[FRSCL_NACT])
		return;
	pix_init(&p, setup, thr, i, off, out, write);
	ns = setup[FRSCL_NS];
	mw = setup[FRSCL_MW];
	mh = setup[FRSCL_MH];
	wx = setup[FRSCL_WX];
	wy = setup[FRSCL_WY];
	if (setup[FRSCL_TILES]) {
		struct tcache tc;
		tc.valid = 0;
		for (ulong y = p.y0; y < p.y0 + ns; y++)
			for (ulong x = p.x0; x < p.x0 + ns; x++) {
				ulong lx, ly;
				uint v;
				tile_at(setup, &tc, x, y, &lx, &ly);
				v = mat[block_index(setup, &tc.t, 0, lx, ly)];
				if (v < p.lim)
					emit(&p, x, y, v);
			}
	} else {
		for (ulong sy = 0; sy < ns; sy++) {
			ulong y = p.y0 + sy;
			__global const uint *row = mat + wrapn(wy + y, mh) * mw;
			ulong mx = wrapn(wx + p.x0, mw);
			for (ulong sx = 0; sx < ns; sx++) {
				uint v = row[mx];
				if (v < p.lim)
					emit(&p, p.x0 + sx, y, v);
				if (++mx == mw)
					mx = 0;
			}
		}
	}
	if (!write)
		cnt[i] = p.count;
}

/* The minmap value of the level-l block whose first element is (x, y);
 * lev holds every level, level l from lev[loff[l]]. */
static uint minmap_at(__global const ulong *setup, __global const uint *lev,
    __global const ulong *loff, struct tcache *tc, uint l, ulong x, ulong y)
{
	ulong lx, ly;

	tile_at(setup, tc, x, y, &lx, &ly);
	return lev[loff[l] + block_index(setup, &tc->t, l, lx, ly)];
}

struct blk {
	uint x, y;	/* inside the pixel: below n_s <= 2^31 */
	uint l;
};

/* Listing 5.4 (Stack) and 5.5 (Level N) in one: the same depth-first
 * visit of the quadrants in the order (0,0), (1,0), (0,1), (1,1) from
 * start blocks of level setup[FRSCL_START] in row order. */
__kernel void frs_minmap(__global const ulong *setup, __global const ulong *thr,
    __global const uint *lev, __global const ulong *loff,
    __global ulong *cnt, __global const ulong *off, __global uint *out,
    int write)
{
	ulong i = get_global_id(0);
	uint L;
	ulong b, nb;
	struct pix p;
	struct blk st[3 * 32 + 4];
	struct tcache tc;

	if (i >= setup[FRSCL_NACT])
		return;
	tc.valid = 0;
	pix_init(&p, setup, thr, i, off, out, write);
	L = (uint)setup[FRSCL_START];
	b = (ulong)1 << L;
	nb = setup[FRSCL_NS] / b;
	for (ulong by = 0; by < nb; by++)
		for (ulong bx = 0; bx < nb; bx++) {
			int top = 0;
			st[top].x = (uint)(bx * b);
			st[top].y = (uint)(by * b);
			st[top++].l = L;
			while (top > 0) {
				struct blk e = st[--top];
				ulong x = p.x0 + e.x, y = p.y0 + e.y;
				uint v = minmap_at(setup, lev, loff, &tc,
				    e.l, x, y);
				uint h;
				if (v >= p.lim)
					continue;
				if (e.l == 0) {
					emit(&p, x, y, v);
					continue;
				}
				h = 1u << (e.l - 1);
				st[top].x = e.x + h; st[top].y = e.y + h;
				st[top++].l = e.l - 1;
				st[top].x = e.x; st[top].y = e.y + h;
				st[top++].l = e.l - 1;
				st[top].x = e.x + h; st[top].y = e.y;
				st[top++].l = e.l - 1;
				st[top].x = e.x; st[top].y = e.y;
				st[top++].l = e.l - 1;
			}
		}
	if (!write)
		cnt[i] = p.count;
}

/* Listing 5.11: the sorted values of each block of b x b
 * (setup[FRSCL_START]), as take_block / pix_sorted of src/lib/sample/frs.c. */
__kernel void frs_sorted(__global const ulong *setup, __global const ulong *thr,
    __global const uint *sval, __global const uint *sidx,
    __global const uint *soff, __global ulong *cnt, __global const ulong *off,
    __global uint *out, int write)
{
	ulong i = get_global_id(0);
	ulong b, nb;
	uint lb = 0;
	struct pix p;
	struct tcache tc;

	if (i >= setup[FRSCL_NACT])
		return;
	tc.valid = 0;
	pix_init(&p, setup, thr, i, off, out, write);
	b = setup[FRSCL_START];
	nb = setup[FRSCL_NS] / b;
	while (((ulong)1 << lb) < b)
		lb++;
	for (ulong by = 0; by < nb; by++)
		for (ulong bx = 0; bx < nb; bx++) {
			ulong x = p.x0 + bx * b, y = p.y0 + by * b;
			ulong lx, ly, blk, ex, ey;
			__global const uint *val, *idx;
			tile_at(setup, &tc, x, y, &lx, &ly);
			blk = block_index(setup, &tc.t, lb, lx, ly);
			val = sval + soff[blk];
			idx = sidx + soff[blk];
			if (p.nsteps == 1) {
				ulong lo = 0, hi = soff[blk + 1] - soff[blk], k;
				while (lo < hi) {
					ulong mid = lo + (hi - lo) / 2;
					if (val[mid] < p.lim)
						lo = mid + 1;
					else
						hi = mid;
				}
				k = lo;
				if (k > 0) {
					inblock(&tc.t, b, lb, idx[k - 1], x, y,
					    &ex, &ey);
					if (!passes_k(&p, 0, val[k - 1], ex,
					    ey))
						k--;
				}
				if (!p.write) {
					p.count += k;
					continue;
				}
				for (ulong j = 0; j < k; j++) {
					inblock(&tc.t, b, lb, idx[j], x, y, &ex,
					    &ey);
					put(&p, ex, ey, 0);
				}
				continue;
			}
			for (ulong k = 0; k < soff[blk + 1] - soff[blk] &&
			    val[k] < p.lim; k++) {
				inblock(&tc.t, b, lb, idx[k], x, y, &ex, &ey);
				emit(&p, ex, ey, val[k]);
			}
		}
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
__kernel void frs_flat_init(__global const ulong *setup,
    __global const ulong *thr, __global const uint *lev,
    __global const ulong *loff, __global ulong *cnt,
    __global const ulong *off, __global uint *cand, int write)
{
	ulong i = get_global_id(0);
	ulong b, nb, x0, y0, lim, n = 0;
	uint L;
	__global uint *o;
	struct tcache tc;

	if (i >= setup[FRSCL_NACT])
		return;
	tc.valid = 0;
	lim = record(setup, thr, i, &x0, &y0)[FRSCL_REC_LIM];
	L = (uint)setup[FRSCL_START];
	b = (ulong)1 << L;
	nb = setup[FRSCL_NS] / b;
	o = write ? cand + 3 * off[i] : cand;
	for (ulong by = 0; by < nb; by++)
		for (ulong bx = 0; bx < nb; bx++)
			if (minmap_at(setup, lev, loff, &tc, L, x0 + bx * b,
			    y0 + by * b) < lim) {
				if (write) {
					o[3 * n] = (uint)i;
					o[3 * n + 1] = (uint)(bx * b);
					o[3 * n + 2] = (uint)(by * b);
				}
				n++;
			}
	if (!write)
		cnt[i] = n;
}

__kernel void frs_flat_refine(__global const ulong *setup,
    __global const ulong *thr, __global const uint *lev,
    __global const ulong *loff, __global const uint *cin, ulong ncand,
    uint l, __global uint *cnt, __global const ulong *off,
    __global uint *cout, int write)
{
	ulong i = get_global_id(0);
	ulong x0, y0, lim;
	uint pi, cx, cy, h, n = 0;
	__global uint *o;
	struct tcache tc;

	if (i >= ncand)
		return;
	tc.valid = 0;
	pi = cin[3 * i];
	cx = cin[3 * i + 1];
	cy = cin[3 * i + 2];
	lim = record(setup, thr, pi, &x0, &y0)[FRSCL_REC_LIM];
	h = 1u << (l - 1);
	o = write ? cout + 3 * off[i] : cout;
	for (uint q = 0; q < 4; q++) {
		uint x = cx + (q & 1) * h, y = cy + (q >> 1) * h;
		if (minmap_at(setup, lev, loff, &tc, l - 1, x0 + x, y0 + y) <
		    lim) {
			if (write) {
				o[3 * n] = pi;
				o[3 * n + 1] = x;
				o[3 * n + 2] = y;
			}
			n++;
		}
	}
	if (!write)
		cnt[i] = n;
}

__kernel void frs_flat_final(__global const ulong *setup,
    __global const ulong *thr, __global const uint *mat,
    __global const uint *cin, ulong ncand, __global uint *cnt,
    __global const ulong *off, __global uint *out, int write)
{
	ulong i = get_global_id(0);
	struct pix p;
	struct tcache tc;
	uint pi;
	ulong x, y, lx, ly;

	if (i >= ncand)
		return;
	tc.valid = 0;
	pi = cin[3 * i];
	pix_init(&p, setup, thr, pi, off, out, 0);
	x = p.x0 + cin[3 * i + 1];
	y = p.y0 + cin[3 * i + 2];
	p.write = write;
	p.out = write ? out + 3 * off[i] : out;
	tile_at(setup, &tc, x, y, &lx, &ly);
	emit(&p, x, y, mat[block_index(setup, &tc.t, 0, lx, ly)]);
	if (!write)
		cnt[i] = (uint)p.count;
}
