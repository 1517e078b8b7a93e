/*
 * What a matrix generator is asked for (struct frdgen_params), and the
 * laws that follow from it, shared by the CPU generator (frdgen.c), the
 * OpenCL one (frdgencl.c) and the tests: the force and its reach, the
 * radius of each insertion, the random choices of each step and the
 * order in which zero cells are counted.  frdgen.h tells the method.
 */
#ifndef FRS_FRDPARAM_H
#define FRS_FRDPARAM_H

#include <stddef.h>
#include <stdint.h>

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
/* Tile size per axis: 16 x 8 x 1 in 2-D, 8 x 4 x 4 in 3-D. */
void frdgen_tile_shape(unsigned dims, uint32_t t[3]);

#endif
