/*
 * Discrepancy of 2-D point sets (thesis Sec. 6.2, Eq. 6.1-6.20).
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

struct disc_opts {
	enum disc_class cls;
	int exact_d2;		/* closed-form D2 (star, rect) */
	int exact_dinf;		/* Dinf over critical boxes (star, rect) */
	uint32_t grid;		/* s of the grid methods */
	uint64_t shapes;	/* K of the random-shape methods */
	uint64_t seed;
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

/* A progress bar for the parallel loops inside one set (NULL: none). */
struct progress;
void disc_set_progress(struct progress *pr);

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

/* Grid lines as the methods define them. */
double disc_star_line(uint32_t i, uint32_t s);	/* i/s */
double disc_rect_line(uint32_t a, uint32_t s);	/* a/(s-1) */
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
