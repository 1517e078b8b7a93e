/*
 * What frdgen.c (CPU) and frdgencl.c (OpenCL) share, so that both make
 * the same matrix byte for byte: the sizes and window of an insertion,
 * the force table, the Fenwick tree of zero counts and the best-first
 * rank query.  Internal to the library.
 */
#ifndef FRS_FRDGENINT_H
#define FRS_FRDGENINT_H

#include <stddef.h>
#include <stdint.h>

#include "frd-gen/frdparam.h"

/* The sizes a run works with. */
struct frdgen_size {
	uint32_t w, h, d;
	size_t n;		/* cells */
	uint32_t hw, hh, hd;	/* largest toroidal offsets: w/2, h/2, d/2 */
	double rtol;		/* frdgen_radius */
	double rmax;		/* the largest toroidal distance */
};

/* The window of one insertion of radius r. */
struct frdgen_win {
	double r2;		/* r^2, INFINITY past rmax */
	uint32_t e;		/* floor(r), capped */
	uint32_t ey, ez;	/* reach in y and z */
	int fast;		/* 2e + 1 is two tiles (of tx) shorter than w:
				 * one contiguous run per tile row */
	double sub;		/* the taper: f(R), or 0 */
};

void frdgen_size(struct frdgen_size *z, const struct frdgen_params *pr);
void frdgen_window(const struct frdgen_params *pr,
    const struct frdgen_size *z, uint32_t tx, double r, struct frdgen_win *wd);
/* What a cell gets from a table entry t under the taper sub: t - sub, never
 * below 0 (R^2 may round below a cell's r^2).  Exact for sub = 0; the
 * kernel (cl/frdgen.cl) computes the same. */
static inline double frdgen_add(double t, double sub)
{
	double v = t - sub;
	return v > 0.0 ? v : 0.0;
}
/* The least l with 2^l >= v. */
unsigned frdgen_log2u(uint32_t v);
/* f by |dx|, |dy|, |dz| up to w/2, h/2, d/2 (x fastest); NULL (with the
 * error set) when out of memory. */
double *frdgen_table(const struct frdgen_params *pr);

/* Fenwick tree fen[1 .. n] of per-tile counts. */
void frdgen_fen_add(uint64_t *fen, size_t n, size_t t, int64_t d);
uint64_t frdgen_fen_total(const uint64_t *fen, size_t n);
/* The tile holding count number r (0-based); r becomes its rank inside. */
size_t frdgen_fen_find(const uint64_t *fen, size_t n, uint64_t *r);

/* An entry of the rank query: a node (lev >= 0) or a cell (lev < 0). */
struct frdgen_item {
	double v;
	int lev;
	uint32_t idx;
};

/* The rank query's heap, its output and the tie keys, reused. */
struct frdgen_sel {
	struct frdgen_item *heap, *emit;
	size_t nheap, hcap, nemit, ecap;
	uint64_t *keys;
	size_t kcap;
};

/* Push the children of node (lev, idx) with frdgen_push. */
typedef int frdgen_expand_fn(void *ctx, int lev, uint32_t idx);

int frdgen_push(struct frdgen_sel *s, double v, int lev, uint32_t idx);
/* The k-th smallest free cell in the order (force, tie key, cell) under
 * root, best-first; the tie keys are those of step. */
int frdgen_select(struct frdgen_sel *s, const struct frdgen_params *pr,
    uint64_t step, uint64_t k, struct frdgen_item root,
    frdgen_expand_fn *expand, void *ctx, uint32_t *c);
void frdgen_sel_free(struct frdgen_sel *s);

#endif
