/*
 * Discrepancy: the driver, the star and rectangle classes.
 *
 * D2 of star and rect, on a grid or over the continuum, expands the mean
 * of (C/n - area)^2 into three sums (Warnock 1972; the same algebra on the
 * grid): sum of C^2 over the shapes, which is a sum over point pairs of
 * the number of shapes holding both; sum of C * area, one term per point;
 * and sum of area^2, a constant.  The pair sum has the form
 *   sum_{i,j} ux(min x) vx(max x) uy(min y) vy(max y)
 * and takes O(n log n) with a sweep in x and Fenwick trees over y ranks.
 * The three sums are O(1) each and cancel to O(1/n), so they are carried
 * in double-double.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "discrepancy/disc.h"
#include "discrepancy/discint.h"
#include "cli/cli.h"
#include "discrepancy/geom.h"

static const char *const names[] = { "star", "rect", "quad", "half",
    "circle" };

int disc_parse_class(const char *s, enum disc_class *c)
{
	for (int i = 0; i < 5; i++)
		if (strcmp(s, names[i]) == 0) {
			*c = (enum disc_class)i;
			return 0;
		}
	if (strcmp(s, "rectangle") == 0 || strcmp(s, "quadrilateral") == 0 ||
	    strcmp(s, "halfspace") == 0) {
		*c = s[0] == 'r' ? DISC_RECT : s[0] == 'q' ? DISC_QUAD :
		    DISC_HALF;
		return 0;
	}
	return cli_fail("unknown class '%s' (star, rect, quad, half or "
	    "circle)", s);
}

const char *disc_class_name(enum disc_class c)
{
	return names[c];
}

int disc_has_exact_d2(enum disc_class c)
{
	return c == DISC_STAR || c == DISC_RECT;
}

int disc_has_exact_dinf(enum disc_class c)
{
	return c == DISC_STAR || c == DISC_RECT;
}

double disc_tests(const struct disc_opts *o)
{
	double s = o->grid;

	switch (o->cls) {
	case DISC_STAR: return s * s;
	case DISC_RECT: return (s * (s - 1) / 2) * (s * (s - 1) / 2);
	case DISC_HALF: return 6 * s * s;
	default: return (double)o->shapes;
	}
}

/* ---- the pair sum --------------------------------------------------- */

/* The two Fenwick trees of pair_sum in one array: a prefix query and an
 * update walk the same nodes of both, so one walk serves the two (half
 * the cache misses at large n). */
struct fnode {
	struct dd f, g;
};

/* The pair sum of the file comment; u, v hold ux, vx, uy, vy for each
 * point, 4 per point.  Points in x order; for point k, f sums ux uy and
 * g ux vy of the points before it by y rank, so that its pairs with
 * them are vx(k) (vy(k) f(below) + uy(k) g(above)). */
static int pair_sum(const double *xy, size_t n, const double *u,
    struct dd *out)
{
	uint32_t *ox = malloc(2 * n * sizeof *ox), *rank = malloc(n *
	    sizeof *rank);
	struct fnode *t = calloc(n + 1, sizeof *t);
	struct dd tot, diag, gall;

	if (ox == NULL || rank == NULL || t == NULL) {
		free(ox), free(rank), free(t);
		return cli_fail("no memory for %zu points", n);
	}
	if (disc_order(xy, n, 2, ox) < 0 || disc_order(xy + 1, n, 2,
	    ox + n) < 0) {
		free(ox), free(rank), free(t);
		return -1;
	}
	for (size_t r = 0; r < n; r++)
		rank[ox[n + r]] = (uint32_t)r;
	tot = diag = gall = dd_from(0.0);
	for (size_t k = 0; k < n; k++) {
		const double *w = u + 4 * (size_t)ox[k];
		size_t r = rank[ox[k]];
		struct dd below = dd_from(0.0), gbelow = dd_from(0.0), a;
		for (size_t q = r; q > 0; q &= q - 1) {
			below = dd_add(below, t[q].f);
			gbelow = dd_add(gbelow, t[q].g);
		}
		a = dd_add(gall, dd_mul_d(gbelow, -1.0));
		a = dd_add(dd_mul_d(below, w[3]), dd_mul_d(a, w[2]));
		tot = dd_add(tot, dd_mul_d(a, w[1]));
		diag = dd_add(diag, dd_mul_d(dd_prod(w[0] * w[1], w[2]),
		    w[3]));
		for (size_t q = r + 1; q <= n; q += q & (~q + 1)) {
			t[q].f = dd_add_d(t[q].f, w[0] * w[2]);
			t[q].g = dd_add_d(t[q].g, w[0] * w[3]);
		}
		gall = dd_add_d(gall, w[0] * w[3]);
	}
	*out = dd_add(dd_mul_d(tot, 2.0), diag);
	free(ox), free(rank), free(t);
	return 0;
}

/* sqrt((pairs/n^2 - 2 single/n + cnst) / shapes), never negative. */
static double l2_combine(struct dd pairs, struct dd single, struct dd cnst,
    double shapes, size_t n)
{
	double nn = (double)n;
	struct dd t = dd_div_d(dd_div_d(pairs, nn), nn);

	t = dd_add(t, dd_mul_d(dd_div_d(single, nn), -2.0));
	t = dd_add(t, cnst);
	double v = dd_value(t) / shapes;
	return v > 0.0 ? sqrt(v) : 0.0;
}

/* Point (x, y)'s corner values of the pair sums into u[0..3], and its
 * single term: the star's and the rectangles' closed forms. */
static struct dd star_corners(double x, double y, double *u)
{
	u[0] = 1.0, u[1] = 1.0 - x;
	u[2] = 1.0, u[3] = 1.0 - y;
	return dd_mul_d(dd_prod(1.0 - x * x, 1.0 - y * y), 0.25);
}

static struct dd rect_corners(double x, double y, double *u)
{
	u[0] = 2.0 * x, u[1] = 1.0 - x;
	u[2] = 2.0 * y, u[3] = 1.0 - y;
	return dd_prod(x * (1.0 - x), y * (1.0 - y));
}

/* The pair and single sums of an exact L2 discrepancy, corners giving
 * each point's terms. */
static int l2_sums(const double *xy, size_t n,
    struct dd (*corners)(double x, double y, double *u), struct dd *pairs,
    struct dd *single)
{
	double *u = malloc(4 * n * sizeof *u);
	int rc;

	if (u == NULL)
		return cli_fail("no memory for %zu points", n);
	*single = dd_from(0.0);
	for (size_t i = 0; i < n; i++)
		*single = dd_add(*single, corners(xy[2 * i], xy[2 * i + 1],
		    u + 4 * i));
	rc = pair_sum(xy, n, u, pairs);
	free(u);
	return rc;
}

double disc_star_l2_exact(const double *xy, size_t n)
{
	struct dd pairs, single;

	if (l2_sums(xy, n, star_corners, &pairs, &single) < 0)
		return -1.0;
	return l2_combine(pairs, single, dd_div_d(dd_from(1.0), 9.0), 1.0, n);
}

double disc_rect_l2_exact(const double *xy, size_t n)
{
	struct dd pairs, single;

	if (l2_sums(xy, n, rect_corners, &pairs, &single) < 0)
		return -1.0;
	/* E[area^2] = (E|u - v|^2)^2 = 1/36 */
	return l2_combine(pairs, single, dd_div_d(dd_from(1.0), 36.0), 1.0, n);
}

/* Grid star: a point at bin k (lines 1..k at or below it) lies in the
 * boxes with corner index i > k: s - k of them per axis, and the sum of
 * their corner coordinates is (s(s+1)/2 - k(k+1)/2)/s. */
double disc_star_l2_grid(const double *xy, size_t n, uint32_t s)
{
	double *u = malloc(4 * n * sizeof *u), ds = (double)s;
	struct dd pairs, single = dd_from(0.0), sq = dd_from(0.0);

	if (u == NULL)
		return cli_fail("no memory for %zu points", n), -1.0;
	for (size_t i = 0; i < n; i++) {
		double kx = disc_star_bin(xy[2 * i], s);
		double ky = disc_star_bin(xy[2 * i + 1], s);
		double gx = (ds * (ds + 1) - kx * (kx + 1)) / 2;
		double gy = (ds * (ds + 1) - ky * (ky + 1)) / 2;
		u[4 * i] = 1.0, u[4 * i + 1] = ds - kx;
		u[4 * i + 2] = 1.0, u[4 * i + 3] = ds - ky;
		single = dd_add(single, dd_prod(gx, gy));	/* times s^2 */
	}
	if (pair_sum(xy, n, u, &pairs) < 0) {
		free(u);
		return -1.0;
	}
	free(u);
	single = dd_div_d(dd_div_d(single, ds), ds);
	/* (sum of (i/s)^2)^2, i = 1..s */
	sq = dd_from(ds * (ds + 1) * (2 * ds + 1) / 6);
	sq = dd_div_d(dd_div_d(sq, ds), ds);
	sq = dd_mul(sq, sq);
	return l2_combine(pairs, single, sq, ds * ds, n);
}

/* Grid rect: lines 0..l-1 lie at or below the point (l >= 1), l..s-1
 * above; the boxes holding it per axis: l (s - l), and the sum of their
 * widths times (s-1): l (sum of b >= l) - (s - l)(sum of a < l). */
double disc_rect_l2_grid(const double *xy, size_t n, uint32_t s)
{
	double *u = malloc(4 * n * sizeof *u), ds = (double)s, m = ds - 1;
	struct dd pairs, single = dd_from(0.0), sq = dd_from(0.0);

	if (u == NULL)
		return cli_fail("no memory for %zu points", n), -1.0;
	for (size_t i = 0; i < n; i++) {
		double w[2];
		for (int c = 0; c < 2; c++) {
			double l = disc_rect_bin(xy[2 * i + (size_t)c], s) + 1;
			double lo = l * (l - 1) / 2, hi = ds * m / 2 - lo;
			w[c] = l * hi - (ds - l) * lo;
			u[4 * i + 2 * (size_t)c] = l;
			u[4 * i + 2 * (size_t)c + 1] = ds - l;
		}
		single = dd_add(single, dd_prod(w[0], w[1]));
	}
	if (pair_sum(xy, n, u, &pairs) < 0) {
		free(u);
		return -1.0;
	}
	free(u);
	single = dd_div_d(dd_div_d(single, m), m);
	/* sum over a < b of (b - a)^2 = sum_d (s - d) d^2, exact in double
	 * for s <= DISC_MAX_RECT_GRID */
	for (uint32_t d = 1; d < s; d++)
		sq = dd_add(sq, dd_prod((double)(s - d), (double)d * d));
	sq = dd_div_d(sq, m * m);
	sq = dd_mul(sq, sq);
	return l2_combine(pairs, single, sq,
	    (ds * m / 2) * (ds * m / 2), n);
}

struct disc_ctx {
	struct disc_opts o;
	struct disc_shapes *sh;
};

struct disc_ctx *disc_ctx_new(const struct disc_opts *o)
{
	struct disc_ctx *c = calloc(1, sizeof *c);

	if (c == NULL) {
		cli_fail("no memory");
		return NULL;
	}
	c->o = *o;
	if (o->cls == DISC_QUAD || o->cls == DISC_CIRCLE) {
		c->sh = disc_shapes_new(o->cls, o->shapes, o->seed);
		if (c->sh == NULL) {
			free(c);
			return NULL;
		}
	}
	return c;
}

void disc_ctx_free(struct disc_ctx *c)
{
	if (c != NULL)
		disc_shapes_free(c->sh);
	free(c);
}

/* D2 and Dinf of star or rect, each unless left out. */
static int set_box(const struct disc_opts *o, const double *xy, size_t n,
    int par, struct disc_result *r)
{
	int star = o->cls == DISC_STAR;

	if (!o->no_d2) {
		r->d2 = o->exact_d2 ? (star ? disc_star_l2_exact(xy, n) :
		    disc_rect_l2_exact(xy, n)) : (star ?
		    disc_star_l2_grid(xy, n, o->grid) :
		    disc_rect_l2_grid(xy, n, o->grid));
		if (r->d2 < 0)
			return -1;
	}
	if (o->no_dinf)
		return 0;
	if (o->exact_dinf)
		return star ? disc_star_dinf_exact(xy, n, &r->dinf) :
		    disc_rect_dinf_exact(xy, n, par, &r->dinf);
	return star ? disc_star_dinf_grid(xy, n, o->grid, par, &r->dinf) :
	    disc_rect_dinf_grid(xy, n, o->grid, par, &r->dinf);
}

/* The values left out are NAN, also where they came for free. */
static void mask(const struct disc_opts *o, struct disc_result *r)
{
	if (o->no_d2)
		r->d2 = NAN;
	if (o->no_dinf)
		r->dinf = NAN;
}

int disc_set(struct disc_ctx *c, const double *xy, size_t n, int par,
    struct disc_result *r)
{
	const struct disc_opts *o = &c->o;
	int rc;

	if (n == 0)
		return cli_fail("no points");
	switch (o->cls) {
	case DISC_STAR:
	case DISC_RECT:
		rc = set_box(o, xy, n, par, r);
		break;
	case DISC_HALF:
		rc = disc_half(xy, n, o->grid, par, r);
		break;
	default:
		rc = disc_shapes_run(c->sh, xy, n, par, r);
	}
	mask(o, r);
	return rc;
}

/* Whether a 3-D set takes the grid: for a D2 or a Dinf that is wanted
 * and not exact. */
static int grid3_needed(const struct disc_opts *o)
{
	return (!o->no_d2 && !o->exact_d2) || (!o->no_dinf && !o->exact_dinf);
}

int disc_check(const struct disc_opts *o, unsigned dims, size_t n)
{
	if (n == 0)
		return cli_fail("no points");
	if (dims == 2)
		return 0;
	if (dims != 3)
		return cli_fail("%u-dimensional points; 2 or 3 are needed",
		    dims);
	if (o->cls != DISC_STAR)
		return cli_fail("class %s is 2-D only; 3-D sets take the star class",
		    disc_class_name(o->cls));
	if (o->exact_d2 && !o->no_d2 && n > DISC3_MAX_EXACT_D2)
		return cli_fail("%zu points: the closed-form 3-D D2 uses "
		    "32-bit ranks and is limited to %zu points", n,
		    DISC3_MAX_EXACT_D2);
	if (o->exact_dinf && !o->no_dinf && n > DISC3_MAX_EXACT_N)
		return cli_fail("%zu points: the exact 3-D Dinf takes O(n^3) "
		    "time and is limited to %d points", n, DISC3_MAX_EXACT_N);
	if (grid3_needed(o) && (o->grid < 2 || o->grid > DISC3_MAX_GRID))
		return cli_fail("grid %u: a 3-D grid has s^3 boxes and takes "
		    "O(s^3) time; 2 to %d allowed", o->grid, DISC3_MAX_GRID);
	return 0;
}

double disc_tests_dims(const struct disc_opts *o, unsigned dims)
{
	double s = o->grid;

	return dims == 3 ? s * s * s : disc_tests(o);
}

/* 3-D star: the grid gives D2 and Dinf in one sweep; --exact replaces
 * D2, and without a grid Dinf too; a value left out is not computed
 * unless the grid gives it anyway. */
static int set3(const struct disc_opts *o, const double *xyz, size_t n,
    int par, struct disc_result *r)
{
	if (grid3_needed(o) && disc3_star_grid(xyz, n, o->grid, par, r) < 0)
		return -1;
	if (o->exact_dinf && !o->no_dinf &&
	    disc3_star_dinf_exact(xyz, n, par, &r->dinf) < 0)
		return -1;
	if (o->exact_d2 && !o->no_d2 &&
	    (r->d2 = disc_star_l2_exact_k(xyz, n, 3, par)) < 0)
		return -1;
	mask(o, r);
	return 0;
}

int disc_set_dims(struct disc_ctx *c, const double *x, size_t n,
    unsigned dims, int par, struct disc_result *r)
{
	if (disc_check(&c->o, dims, n) < 0)
		return -1;
	return dims == 2 ? disc_set(c, x, n, par, r) :
	    set3(&c->o, x, n, par, r);
}
