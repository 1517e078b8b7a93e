/*
 * Discrepancy of 2-D point sets (thesis Sec. 6.2, Eq. 6.1-6.20), and
 * the star discrepancy of 3-D sets.
 *
 * For a set X of n points and a class of shapes A, the local discrepancy
 * of a shape is d(A) = |#(X in A)/n - area(A)|.  D2 is the root of the
 * mean of d^2 over the shapes tested, Dinf its maximum.  Membership of
 * points on a shape's boundary follows geom.h: the half-open rule of the
 * thesis' boxes, extended to every class.
 *
 * Methods, per class:
 *   star    grid: corners (i/s, j/s), i, j = 1..s (s^2 anchored boxes);
 *                 D2 over the grid in O(n log n) by expanding the square,
 *                 Dinf from a summed-area sweep in O(s^2).
 *           exact: Warnock's closed form for D2 in O(n log n); Dinf over
 *                 the critical boxes in O(n^1.5).
 *   rect    grid: lines a/(s-1), a = 0..s-1, every box with a < b, c < d,
 *                 (s(s-1)/2)^2 boxes; D2 in O(n log n), Dinf in
 *                 O(s^2 min(s, n)).
 *           exact: D2 over boxes spanned by two uniform corners, closed
 *                 form in O(n log n); Dinf over all boxes in O(n^3).
 *   quad    K random convex quadrilaterals (uniform corners, rejection of
 *           non-convex orders, Sec. 6.2).
 *   half    lines through s points per border side, (i + 1/2)/s, between
 *           every two sides: 6 s^2 halfplanes, O(s n log s).
 *   circle  K random circles, centre uniform, radius r3 * rmax (Eq. 6.18).
 * Random shapes are a function of (seed, shape index): the same for every
 * set and thread count.
 *
 * 3-D sets (3 coordinates in [0,1)^3) have the star class only: boxes
 * [0,a) x [0,b) x [0,c), half-open as above, of volume abc.
 *   grid:  corners (i/s, j/s, l/s), i, j, l = 1..s (s^3 boxes; default
 *          s = DISC3_STAR_GRID, at most DISC3_MAX_GRID); D2 and Dinf from
 *          one sweep over the planes i with a summed-volume table of the
 *          plane, O(s^3 + n) time, O(s^2) memory per thread.
 *   exact: D2 by Warnock's closed form in k dimensions,
 *            D2^2 = 3^-k - 2^(1-k)/n sum_i prod_d (1 - x_id^2)
 *                   + 1/n^2 sum_i sum_j prod_d (1 - max(x_id, x_jd)),
 *          the pair sum by divide and conquer over x blocks with a
 *          Fenwick tree over z positions, O(n log^2 n) in double-double
 *          (disc3.c; 2^20 points in about 5 s), at most
 *          DISC3_MAX_EXACT_D2 points (32-bit ranks).
 *          Dinf, the supremum of |count/n - abc| over all half-open
 *          boxes, as in 2-D over the critical corners (a, b, c), each
 *          coordinate a point coordinate of its axis or 1:
 *            Dinf = max over them of max(abc - open/n, closed/n - abc),
 *          open = #{x < a, y < b, z < c}, closed = #{x <= a, y <= b,
 *          z <= c}.  (A closed corner with a coordinate 1 never beats the
 *          one at the largest point coordinate of that axis: the same
 *          count, a smaller volume; so the excess is read at point
 *          coordinates only, as in 2-D.)  A sweep over the x values keeps
 *          the counts of every (b, c) in a table of (m_y + 2)(m_z + 2)
 *          16-bit integers, m the distinct values of an axis, with bounds
 *          that skip the blocks of corners that cannot beat the best so
 *          far: O(n^3) time at worst, O(n^2) memory per thread, at most
 *          DISC3_MAX_EXACT_N points (random n = 1024: 0.04 s, 4096: 2 s;
 *          Halton 4096: 3.8 s, one thread; see discrepancy(1)).
 */
#ifndef FRS_DISC_H
#define FRS_DISC_H

#include <stddef.h>
#include <stdint.h>

enum disc_class { DISC_STAR, DISC_RECT, DISC_QUAD, DISC_HALF, DISC_CIRCLE };

#define DISC_STAR_GRID 3000	/* thesis parameters */
#define DISC_RECT_GRID 500
#define DISC_HALF_GRID 3000
#define DISC_SHAPES 9000000	/* 3000^2 quadrilaterals or circles */
#define DISC_MAX_GRID 1000000
#define DISC_MAX_RECT_GRID 100000
#define DISC3_STAR_GRID 100	/* 10^6 boxes */
#define DISC3_MAX_GRID 1000	/* 10^9 boxes */
#define DISC3_MAX_EXACT_N 4096	/* exact Dinf, O(n^3) */
#define DISC3_MAX_EXACT_D2 ((size_t)UINT32_MAX)	/* closed-form D2 */

struct disc_opts {
	enum disc_class cls;
	int exact_d2;		/* closed-form D2 (star, rect) */
	int exact_dinf;		/* Dinf over critical boxes (star, rect) */
	uint32_t grid;		/* s of the grid methods */
	uint64_t shapes;	/* K of the random-shape methods */
	uint64_t seed;
	int no_d2, no_dinf;	/* leave out D2 / Dinf (NAN in the result);
				 * only star and rect save the time, and 3-D
				 * --exact (the grid gives both at once) */
};

struct disc_result {
	double d2, dinf;
};

int disc_parse_class(const char *s, enum disc_class *c);
const char *disc_class_name(enum disc_class c);
/* Geometry tests per set of the grid or random method (0 for a closed
 * form over the whole class). */
double disc_tests(const struct disc_opts *o);
/* Whether the class has a closed-form D2 / an exact Dinf. */
int disc_has_exact_d2(enum disc_class c);
int disc_has_exact_dinf(enum disc_class c);

/* Shared state of a run: random shapes drawn once for all sets. */
struct disc_ctx;
struct disc_ctx *disc_ctx_new(const struct disc_opts *o);
void disc_ctx_free(struct disc_ctx *c);
/* One set of n >= 1 points in [0,1)^2; par: use the thread team inside
 * (results are the same either way). */
int disc_set(struct disc_ctx *c, const double *xy, size_t n, int par,
    struct disc_result *r);

/* Sets of dims coordinates (2 or 3) and n points: whether the options
 * can measure them (3-D: star only, the limits above); -1 with a message
 * otherwise.  disc_set_dims checks it too; a program calls it for every
 * set before it starts, so that a bad set stops the run at once. */
int disc_check(const struct disc_opts *o, unsigned dims, size_t n);
/* disc_set for points of dims coordinates, packed. */
int disc_set_dims(struct disc_ctx *c, const double *x, size_t n,
    unsigned dims, int par, struct disc_result *r);
/* disc_tests for sets of dims coordinates: s^3 for the 3-D grid. */
double disc_tests_dims(const struct disc_opts *o, unsigned dims);

/* The pieces, for tests and benchmarks.  L2 values are D2 (not squared). */
double disc_star_l2_exact(const double *xy, size_t n);
double disc_rect_l2_exact(const double *xy, size_t n);
double disc_star_l2_grid(const double *xy, size_t n, uint32_t s);
double disc_rect_l2_grid(const double *xy, size_t n, uint32_t s);
int disc_star_dinf_exact(const double *xy, size_t n, double *dinf);
int disc_star_dinf_grid(const double *xy, size_t n, uint32_t s, int par,
    double *dinf);
int disc_rect_dinf_grid(const double *xy, size_t n, uint32_t s, int par,
    double *dinf);
int disc_rect_dinf_exact(const double *xy, size_t n, int par, double *dinf);
int disc_half(const double *xy, size_t n, uint32_t s, int par,
    struct disc_result *r);
/* The random-shape classes (quad, circle): k shapes drawn once. */
struct disc_shapes;
struct disc_shapes *disc_shapes_new(enum disc_class cls, uint64_t k,
    uint64_t seed);
void disc_shapes_free(struct disc_shapes *sh);
int disc_shapes_run(const struct disc_shapes *sh, const double *xy, size_t n,
    int par, struct disc_result *res);

/* 3-D star pieces: Warnock's D2 for points of k >= 1 coordinates
 * (k = 3 in O(n log^2 n); any other k by the O(n^2) sum over pairs, so
 * that k = 2 is disc_star_l2_exact by another route), the exact Dinf
 * and the grid's D2 and Dinf for k = 3.  par: the thread team. */
double disc_star_l2_exact_k(const double *x, size_t n, unsigned k, int par);
int disc3_star_dinf_exact(const double *xyz, size_t n, int par,
    double *dinf);
int disc3_star_grid(const double *xyz, size_t n, uint32_t s, int par,
    struct disc_result *r);

/* Grid lines as the methods define them (star and rect: discint.h). */
double disc_half_pos(uint32_t i, uint32_t s);	/* (i + 1/2)/s */
/* Border point i of side 0 bottom, 1 right, 2 top, 3 left (counter-
 * clockwise), and the area left of the directed line e -> f through two
 * border points on sides a < b. */
void disc_half_point(int side, uint32_t i, uint32_t s, double *x, double *y);
double disc_half_area(int a, double ex, double ey, int b, double fx,
    double fy);

/* Random shape k: a convex quadrilateral, counter-clockwise, in q[0..7]
 * (returns the number of draws it took), or a circle (x, y, r). */
unsigned disc_quad_shape(uint64_t seed, uint64_t k, double q[8]);
void disc_circle_shape(uint64_t seed, uint64_t k, double c[3]);
int disc_in_quad(const double q[8], double px, double py);
double disc_quad_area(const double q[8]);

#endif
