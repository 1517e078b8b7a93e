/*
 * Reference point sets: uniform samplers in [0,1)^2 and [0,1)^3 that
 * Forced Random Sampling (2-D, and 3-D with a 3-D matrix) is compared
 * against (see ref-sample(1)).
 *
 * Each generator fills an array of dims * count doubles (x0, y0, x1, y1,
 * ... or x0, y0, z0, x1, ...) and depends only on (kind, dims, n, seed,
 * options): the same arguments give the same bits.  Random numbers come
 * from frs_rand01 on FRS_STREAM_REF.
 */
#ifndef FRS_REFSAMP_H
#define FRS_REFSAMP_H

#include <stdint.h>

enum refsamp_kind {
	REFSAMP_RANDOM,
	REFSAMP_REGULAR,
	REFSAMP_JITTERED,
	REFSAMP_HALTON,
	REFSAMP_HAMMERSLEY,
	REFSAMP_SOBOL,
	REFSAMP_DART,
	REFSAMP_RELAXED_DART	/* adaptive, by an importance map */
};

struct frs_imap;

/* Largest n accepted by refsamp_gen (Sobol' uses 32-bit indices). */
#define REFSAMP_MAX_N ((uint64_t)1 << 32)
#define REFSAMP_DART_FAILURES 100000
/* Relaxed dart: consecutive failures before the radius shrinks. */
#define REFSAMP_RELAXED_FAILURES 1000
/* Relaxed dart: the factor r0 is multiplied by at each relaxation. */
#define REFSAMP_RELAX_FACTOR 0.9

/* Name to kind; -1 with a message for an unknown name. */
int refsamp_parse(const char *name, enum refsamp_kind *k);
const char *refsamp_name(enum refsamp_kind k);

/* Side of the grid of regular and jittered: round(sqrt(n)), at least 1. */
uint64_t refsamp_grid_side(uint64_t n);
/* Points made for n: k*k for regular and jittered, n otherwise (dart
 * may place fewer; refsamp_gen says how many). */
uint64_t refsamp_count(enum refsamp_kind k, uint64_t n);

/* Dart throwing radius for n points: 0.7 of the densest packing
 * distance sqrt(2 / (sqrt(3) n)) (Lagae and Dutre 2008). */
double refsamp_dart_radius(uint64_t n);

/* 3-D: side of the grid of regular and jittered, round(cbrt(n)), at
 * least 1 (n is taken as at most 2^60). */
uint64_t refsamp_cube_side(uint64_t n);
/* Dart throwing radius for n points in the unit cube: 0.7 of the
 * densest (FCC) packing distance cbrt(sqrt(2) / n). */
double refsamp_dart_radius3(uint64_t n);

/* 2-D Sobol' point i (Gray-code order) as 32-bit integers, Owen
 * scrambled by hashing with the given per-dimension keys (0, 0: none). */
void refsamp_sobol32(uint32_t i, uint32_t key_x, uint32_t key_y,
    uint32_t out[2]);
/* 3-D Sobol' point i: the two dimensions above and Joe and Kuo's third
 * (primitive polynomial x^2 + x + 1, m = 1, 3), each Owen scrambled by
 * its key (all three 0: none). */
void refsamp_sobol32_3(uint32_t i, const uint32_t key[3], uint32_t out[3]);

/* Fill xy with refsamp_count(k, n) points; *placed gets the number of
 * points made (fewer than the count only for dart, which stops after
 * max_failures consecutive rejected candidates).  -1 with a message on
 * bad arguments or no memory. */
int refsamp_gen(enum refsamp_kind k, uint64_t n, uint64_t seed,
    uint64_t max_failures, double *xy, uint64_t *placed);

/* The same in dims = 2 (refsamp_gen) or 3 dimensions.  In 3-D regular
 * and jittered use a cubic grid of refsamp_cube_side(n)^3 cells, halton
 * bases 2, 3, 5, hammersley ((i + 1/2) / n, phi2(i), phi3(i)), dart
 * refsamp_dart_radius3 on the torus; the first two coordinates of
 * halton, hammersley and sobol are those of the 2-D set of the same
 * seed.  x holds dims * refsamp_count_dims(k, n, dims) doubles.
 * relaxed-dart is 2-D only: -1 with a message in 3-D; so is any dims
 * other than 2 and 3. */
uint64_t refsamp_count_dims(enum refsamp_kind k, uint64_t n, unsigned dims);
int refsamp_gen_dims(enum refsamp_kind k, unsigned dims, uint64_t n,
    uint64_t seed, uint64_t max_failures, double *x, uint64_t *placed);

/*
 * Adaptive Poisson disk sampling by relaxation dart throwing (McCool and
 * Fiume, Graphics Interface 1992).  Candidates are drawn with density
 * proportional to the importance of map (NULL: constant): a pixel by
 * inverse CDF, then a uniform point inside it.  The local radius is
 * r(x) = r0 / sqrt(I(x) / mean I), I(x) the importance of x's pixel; a
 * candidate x is accepted when dist(x, q) >= max(r(x), r(q)) for every
 * accepted q (plain, non-toroidal distance).  r0 starts at twice
 * refsamp_dart_radius(n) and is multiplied by REFSAMP_RELAX_FACTOR after
 * max_failures consecutive rejections; exactly n points are made.
 * Zero-importance pixels get no points.  *r0_out (may be NULL) gets the
 * final r0.  -1 with a message on bad arguments, an all-zero or
 * non-finite map, or no memory.
 */
int refsamp_relaxed_dart(uint64_t n, uint64_t seed, uint64_t max_failures,
    const struct frs_imap *map, double *xy, double *r0_out);

#endif
