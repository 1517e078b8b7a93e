/*
 * Exact geometric predicates and double-double sums for the discrepancy
 * tests.
 *
 * A point on the boundary of a shape is decided by one rule for every
 * shape class: it belongs to the shape when a move by an infinitesimal
 * step in the direction (1, eta), eta > 0 infinitesimally small, takes it
 * inside.  For an axis-parallel box this is the half-open [E, F) of the
 * thesis (Eq. 6.5, 6.8): left and bottom edges closed, right and top
 * open.  Because the rule is the same everywhere, a shape and its
 * complement split every point set exactly, and the answer never depends
 * on how an expression happens to round.
 *
 * Signs are exact for all finite double inputs whose products do not
 * underflow (coordinates 0 or above about 1e-150): a floating-point filter
 * answers almost every call, the rest is settled by expansion arithmetic
 * (Shewchuk, "Adaptive precision floating-point arithmetic and fast
 * robust geometric predicates", 1997).
 */
#ifndef FRS_GEOM_H
#define FRS_GEOM_H

#include <math.h>

/* Error bounds of the floating-point filters: ccwerrboundA of Shewchuk
 * is (3 + 16 eps) eps = 3.33e-16; the circle expression has at most five
 * roundings on each side. */
#define GEOM_ORIENT_BOUND 4e-16
#define GEOM_CIRCLE_BOUND 8e-16

/* Sign (-1, 0, 1) of the orientation of (a, b, p): positive when p lies
 * to the left of the directed line a -> b. */
int geom_orient_exact(double ax, double ay, double bx, double by, double px,
    double py);
static inline int geom_orient(double ax, double ay, double bx, double by,
    double px, double py)
{
	double l = (bx - ax) * (py - ay), r = (by - ay) * (px - ax);
	double det = l - r, bound = GEOM_ORIENT_BOUND * (fabs(l) + fabs(r));

	if (det > bound)
		return 1;
	if (-det > bound)
		return -1;
	return geom_orient_exact(ax, ay, bx, by, px, py);
}
/* Sign of r^2 - |p - e|^2: positive when p is strictly inside the circle
 * of centre e and radius r. */
int geom_incircle_exact(double ex, double ey, double r, double px,
    double py);
static inline int geom_incircle(double ex, double ey, double r, double px,
    double py)
{
	double dx = px - ex, dy = py - ey, q = dx * dx + dy * dy, r2 = r * r;
	double det = r2 - q, bound = GEOM_CIRCLE_BOUND * (q + r2);

	if (det > bound)
		return 1;
	if (-det > bound)
		return -1;
	return geom_incircle_exact(ex, ey, r, px, py);
}

/* The boundary rule for a point on the directed line a -> b (interior on
 * the left): 1 if it belongs to the left side. */
static inline int geom_edge_closed(double ax, double ay, double bx, double by)
{
	return by < ay || (by == ay && bx > ax);
}

/* p inside the left side of a -> b, boundary by the rule above. */
static inline int geom_left(double ax, double ay, double bx, double by,
    double px, double py)
{
	int o = geom_orient(ax, ay, bx, by, px, py);
	return o > 0 || (o == 0 && geom_edge_closed(ax, ay, bx, by));
}

/* p inside the circle (e, r), boundary by the rule above: a point on the
 * circle belongs to it when it lies on the left half, or at the bottom. */
static inline int geom_in_circle(double ex, double ey, double r, double px,
    double py)
{
	int s = geom_incircle(ex, ey, r, px, py);
	return s > 0 || (s == 0 && (px < ex || (px == ex && py < ey)));
}

/* Double-double numbers: hi + lo with |lo| <= ulp(hi)/2, about 106 bits. */
struct dd {
	double hi, lo;
};

static inline struct dd dd_two_sum(double a, double b)
{
	double s = a + b, bb = s - a;
	struct dd r = { s, (a - (s - bb)) + (b - bb) };
	return r;
}

static inline struct dd dd_add(struct dd a, struct dd b)
{
	struct dd s = dd_two_sum(a.hi, b.hi), t = dd_two_sum(a.lo, b.lo);
	s.lo += t.hi;
	s = dd_two_sum(s.hi, s.lo);
	s.lo += t.lo;
	return dd_two_sum(s.hi, s.lo);
}

static inline struct dd dd_add_d(struct dd a, double b)
{
	struct dd s = dd_two_sum(a.hi, b);
	s.lo += a.lo;
	return dd_two_sum(s.hi, s.lo);
}

/* a * b for doubles, exactly (fma gives the rounding error). */
static inline struct dd dd_prod(double a, double b)
{
	double p = a * b;
	struct dd r = { p, fma(a, b, -p) };
	return r;
}

static inline struct dd dd_mul_d(struct dd a, double b)
{
	struct dd p = dd_prod(a.hi, b);
	p.lo += a.lo * b;
	return dd_two_sum(p.hi, p.lo);
}

static inline struct dd dd_mul(struct dd a, struct dd b)
{
	struct dd p = dd_prod(a.hi, b.hi);
	p.lo += a.hi * b.lo + a.lo * b.hi;
	return dd_two_sum(p.hi, p.lo);
}

/* a / b to double-double accuracy. */
static inline struct dd dd_div_d(struct dd a, double b)
{
	double q1 = a.hi / b;
	struct dd r = dd_add(a, dd_mul_d(dd_prod(q1, b), -1.0));
	return dd_two_sum(q1, r.hi / b);
}

static inline struct dd dd_from(double a)
{
	struct dd r = { a, 0.0 };
	return r;
}

static inline double dd_value(struct dd a)
{
	return a.hi + a.lo;
}

#endif
