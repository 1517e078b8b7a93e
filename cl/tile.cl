/*
 * Tile transforms: one definition for the CPU (src/lib/sample/tile.h includes
 * this file) and for OpenCL (built after defs.cl and rng.cl, before every
 * kernel).
 *
 * A window larger than the matrix tiles it (thesis Sec. 4.5).  Plain
 * tiling repeats the matrix exactly: where only a tile's first values
 * pass, every tile gives the same points at the same place, a lattice of
 * the tile's period.  Shuffled tiling shows each tile through its own
 * transform, drawn from (seed, tile): a symmetry of the matrix (any
 * permutation of equal-sized axes, any flips: the 8 symmetries of a
 * square, 48 of a cube, 4 of a non-square rectangle) and a toroidal
 * offset, a multiple of the step g per axis.
 *
 * Why the step: the minmap and the sorted lists describe aligned blocks
 * of 2^l elements.  A flip or an axis permutation maps aligned blocks to
 * aligned blocks of the same level, and an offset that is a multiple of
 * 2^l does too, so every block of side at most g keeps its minimum and
 * its sorted list; only the element order inside a block changes, which
 * frs_tile_inblock undoes.  Level-l block coordinates map as elements
 * do, on the grid of the matrix shifted right by l:
 *   v_i = flip_i(u_perm[i]) + off_i / 2^l  (mod m_i / 2^l),
 * where flip_i(x) = m_i / 2^l - 1 - x when axis i is flipped.
 */
/* The offset step: small enough for many offsets (64^2 x 8 transforms of
 * a 2048^2 matrix), large enough for the sorted blocks used (frs-sample
 * takes blocks of min(n_s, g)). */
#define FRS_TILE_STEP 32u

struct frs_tile {
	FRS_U32 perm[3];	/* matrix axis i shows window axis perm[i] */
	FRS_U32 flip;		/* bit i: matrix axis i reversed */
	FRS_U64 off[3];	/* toroidal offset, a multiple of the step */
};

/* The step of an axis of m elements: the largest power of two dividing
 * m, at most FRS_TILE_STEP. */
FRS_FN FRS_U64 frs_tile_step(FRS_U64 m)
{
	FRS_U64 g = 1;

	while (g < FRS_TILE_STEP && m % (2 * g) == 0)
		g *= 2;
	return g;
}

FRS_FN void frs_tile_plain(struct frs_tile *t)
{
	for (FRS_U32 i = 0; i < 3; i++) {
		t->perm[i] = i;
		t->off[i] = 0;
	}
	t->flip = 0;
}

/* Permutation k (0..5) of three axes: k / 2 first, then the other two in
 * order, swapped for odd k. */
FRS_FN void frs_tile_perm(FRS_U32 k, FRS_U32 *p)
{
	FRS_U32 a = k >> 1, r0 = a == 0 ? 1u : 0u, r1 = a == 2 ? 1u : 2u;

	p[0] = a;
	p[1] = (k & 1) ? r1 : r0;
	p[2] = (k & 1) ? r0 : r1;
}

/* The transform of tile (t0, t1, t2) for a matrix of dims axes of sizes
 * m[] (m[2] = 1 in 2-D). */
FRS_FN void frs_tile_make(struct frs_tile *t, FRS_U64 seed, FRS_U32 dims,
    const FRS_U64 *m, FRS_U64 t0, FRS_U64 t1, FRS_U64 t2)
{
	FRS_U64 idx = (t0 & 0xffffffffu) | t1 << 32;
	FRS_U64 r = frs_rand64x(seed, FRS_STREAM_TILE, idx, (FRS_U32)t2 * 2u);
	FRS_U64 r2 = frs_rand64x(seed, FRS_STREAM_TILE, idx,
	    (FRS_U32)t2 * 2u + 1u);
	FRS_U32 n = 0, ok[6], p[3];

	/* Permutations that keep every axis size: those with
	 * m[p[i]] == m[i] (and the third axis fixed in 2-D). */
	for (FRS_U32 k = 0; k < 6; k++) {
		frs_tile_perm(k, p);
		if (m[p[0]] == m[0] && m[p[1]] == m[1] && m[p[2]] == m[2] &&
		    (dims == 3 || p[2] == 2))
			ok[n++] = k;
	}
	frs_tile_perm(ok[(r & 0xffu) % n], t->perm);
	t->flip = (FRS_U32)(r >> 8) & ((1u << dims) - 1u);
	for (FRS_U32 i = 0; i < 3; i++) {
		FRS_U64 g = frs_tile_step(m[i]);
		t->off[i] = i < dims ? (r2 >> (21 * i) & 0x1fffff) % (m[i] / g) * g
		    : 0;
	}
}

/* Matrix block coordinates v[] of the level-l block u[] of a tile (both
 * on the grid of m[i] >> l; 2^l at most the step). */
FRS_FN void frs_tile_block(const struct frs_tile *t, FRS_U32 dims,
    const FRS_U64 *m, FRS_U32 l, const FRS_U64 *u, FRS_U64 *v)
{
	for (FRS_U32 i = 0; i < dims; i++) {
		FRS_U64 mi = m[i] >> l, x = u[t->perm[i]];
		if (t->flip >> i & 1u)
			x = mi - 1 - x;
		x += t->off[i] >> l;
		v[i] = x >= mi ? x - mi : x;
	}
}

/* The window position u[] inside a block of side b of the element at
 * w[] inside the matrix block. */
FRS_FN void frs_tile_inblock(const struct frs_tile *t, FRS_U32 dims,
    FRS_U64 b, const FRS_U64 *w, FRS_U64 *u)
{
	for (FRS_U32 i = 0; i < dims; i++)
		u[t->perm[i]] = (t->flip >> i & 1u) ? b - 1 - w[i] : w[i];
}
