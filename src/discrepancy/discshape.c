/*
 * Random convex quadrilaterals and circles (thesis Eq. 6.11-6.20).
 *
 * Shape k is a function of (seed, k) only.  A quadrilateral takes four
 * uniform corners E, F, G, H and is kept when its diagonals EG and FH
 * cross properly (a convex quadrilateral in that order); a clockwise one
 * is turned around.  Points are counted with the exact predicates of
 * geom.h.  The points of a set are kept by cell of a grid; a shape
 * counts the cells that lie wholly inside it by their totals and tests
 * only the points of the cells its boundary crosses: O(sqrt n) tests per
 * shape instead of O(n area).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "discrepancy/disc.h"
#include "discrepancy/discint.h"
#include "discrepancy/discshape.h"
#include "cli/cli.h"
#include "discrepancy/geom.h"
#include "frs.h"	/* frs_philox4x32_10 */
#include "../../cl/defs.cl"	/* FRS_STREAM_SHAPES */

/* Two uniform doubles in [0, 1) with 53 bits each from one Philox block
 * at (seed, k, class, draw). */
static void draw2(uint64_t seed, uint64_t k, uint32_t sub, double *a,
    double *b)
{
	uint32_t ctr[4] = { (uint32_t)k, (uint32_t)(k >> 32),
	    FRS_STREAM_SHAPES, sub };
	uint32_t key[2] = { (uint32_t)seed, (uint32_t)(seed >> 32) };
	uint32_t out[4];

	frs_philox4x32_10(ctr, key, out);
	*a = (double)((((uint64_t)out[1] << 32) | out[0]) >> 11) * 0x1p-53;
	*b = (double)((((uint64_t)out[3] << 32) | out[2]) >> 11) * 0x1p-53;
}

unsigned disc_quad_shape(uint64_t seed, uint64_t k, double q[8])
{
	for (uint32_t t = 0;; t++) {
		int a, b, c, d;
		for (uint32_t i = 0; i < 4; i++)
			draw2(seed, k, (1u << 24) | (4 * t + i), &q[2 * i],
			    &q[2 * i + 1]);
		/* EG against F and H, FH against E and G */
		a = geom_orient(q[0], q[1], q[4], q[5], q[2], q[3]);
		b = geom_orient(q[0], q[1], q[4], q[5], q[6], q[7]);
		c = geom_orient(q[2], q[3], q[6], q[7], q[0], q[1]);
		d = geom_orient(q[2], q[3], q[6], q[7], q[4], q[5]);
		if (a * b < 0 && c * d < 0) {
			if (a > 0) {	/* F left of EG: clockwise */
				double x = q[2], y = q[3];
				q[2] = q[6], q[3] = q[7];
				q[6] = x, q[7] = y;
			}
			return t + 1;
		}
	}
}

void disc_circle_shape(uint64_t seed, uint64_t k, double c[3])
{
	double r1, r2, r3, unused, rmax;

	draw2(seed, k, 2u << 24, &r1, &r2);
	draw2(seed, k, (2u << 24) | 1, &r3, &unused);
	rmax = fmin(fmin(r1, 1.0 - r1), fmin(r2, 1.0 - r2));
	c[0] = r1, c[1] = r2, c[2] = r3 * rmax;
}

int disc_in_quad(const double q[8], double px, double py)
{
	for (int i = 0; i < 4; i++) {
		int j = (i + 1) & 3;
		if (!geom_left(q[2 * i], q[2 * i + 1], q[2 * j], q[2 * j + 1],
		    px, py))
			return 0;
	}
	return 1;
}

/* The two triangles EFG and EGH of Eq. 6.11-6.13. */
double disc_quad_area(const double q[8])
{
	double e0 = q[2] - q[0], e1 = q[3] - q[1];
	double f0 = q[4] - q[0], f1 = q[5] - q[1];
	double g0 = q[6] - q[0], g1 = q[7] - q[1];
	return 0.5 * (fabs(e0 * f1 - f0 * e1) + fabs(f0 * g1 - g0 * f1));
}

/* Points by cell of a g x g grid, row by row: the cells of one row are
 * contiguous, so a run of cells counts its points by two lookups. */
struct cpt {
	uint32_t cell;
	double x, y;
};

static int cpt_cmp(const void *a, const void *b)
{
	const struct cpt *p = a, *q = b;

	return p->cell != q->cell ? NUM_CMP(p->cell, q->cell) :
	    p->y != q->y ? NUM_CMP(p->y, q->y) : NUM_CMP(p->x, q->x);
}

int disc_cols_make(struct disc_cols *c, const double *xy, size_t n)
{
	struct cpt *p = malloc(n * sizeof *p);
	size_t ncell;

	/* about two points a cell */
	c->g = (uint32_t)sqrt((double)n / 2);
	c->g = c->g ? c->g : 1;
	ncell = (size_t)c->g * c->g;
	c->start = calloc(ncell + 1, sizeof *c->start);
	c->x = malloc(2 * n * sizeof *c->x);
	if (p == NULL || c->start == NULL || c->x == NULL) {
		free(p), free(c->start), free(c->x);
		return cli_fail("no memory for %zu points", n);
	}
	c->y = c->x + n;
	for (size_t i = 0; i < n; i++) {
		p[i].x = xy[2 * i], p[i].y = xy[2 * i + 1];
		p[i].cell = disc_col(c, p[i].y) * c->g + disc_col(c, p[i].x);
		c->start[p[i].cell + 1]++;
	}
	qsort(p, n, sizeof *p, cpt_cmp);
	for (size_t k = 0; k < ncell; k++)
		c->start[k + 1] += c->start[k];
	for (size_t i = 0; i < n; i++)
		c->x[i] = p[i].x, c->y[i] = p[i].y;
	free(p);
	return 0;
}

void disc_cols_free(struct disc_cols *c)
{
	free(c->start);
	free(c->x);
	c->start = NULL;
	c->x = c->y = NULL;
}

/* Cells judged wholly inside keep this distance from the boundary, far
 * more than the rounding of the chords below; every other point is
 * decided by the exact predicates. */
#define CELL_MARGIN 1e-9

/* The x extent of the convex quadrilateral on the line at height y. */
static int chord(const double q[8], double y, double *l, double *r)
{
	int found = 0;
	for (int i = 0; i < 4; i++) {
		int j = (i + 1) & 3;
		double ax = q[2 * i], ay = q[2 * i + 1];
		double bx = q[2 * j], by = q[2 * j + 1], x;
		if ((y < ay && y < by) || (y > ay && y > by))
			continue;
		x = ay == by ? (ax < bx ? ax : bx) : ax + (y - ay) * (bx - ax) /
		    (by - ay);
		if (!found || x < *l)
			*l = x;
		x = ay == by ? (ax > bx ? ax : bx) : x;
		if (!found || x > *r)
			*r = x;
		found = 1;
	}
	return found;
}

/* Cells [fl, fr) of a row whose x range lies in [lo, hi]. */
static void full_cells(const struct disc_cols *c, double lo, double hi,
    uint32_t *fl, uint32_t *fr)
{
	double a = ceil(lo * c->g), b = floor(hi * c->g);
	*fl = *fr = 0;
	if (!(a < b))
		return;
	*fl = a < 0 ? 0 : (uint32_t)a;
	*fr = b > c->g ? c->g : (uint32_t)b;
	if (*fl > *fr)
		*fl = *fr;
}

/* Points of row r in columns [c0, c1], those in [fl, fr) counted whole,
 * the others by the membership test. */
#define ROW_COUNT(c, r, c0, c1, fl, fr, test) do {			\
	const uint32_t *st_ = (c)->start + (size_t)(r) * (c)->g;	\
	if ((fl) < (fr))						\
		cnt += st_[fr] - st_[fl];				\
	for (uint32_t b_ = (c0); b_ <= (c1); b_++) {			\
		if (b_ >= (fl) && b_ < (fr))				\
			continue;					\
		for (uint32_t i_ = st_[b_]; i_ < st_[b_ + 1]; i_++)	\
			cnt += (uint64_t)(test);			\
	}								\
} while (0)

/* Columns [*c0, *c1] that may hold points inside x in [lo, hi]. */
static void outer_cells(const struct disc_cols *c, double lo, double hi,
    uint32_t *c0, uint32_t *c1)
{
	*c0 = disc_col(c, lo - CELL_MARGIN);
	*c1 = disc_col(c, hi + CELL_MARGIN);
}

static inline double dmin(double a, double b)
{
	return a < b ? a : b;
}

static inline double dmax(double a, double b)
{
	return a > b ? a : b;
}

uint64_t disc_count_quad(const struct disc_cols *c, const double q[8])
{
	double y0 = dmin(dmin(q[1], q[3]), dmin(q[5], q[7]));
	double y1 = dmax(dmax(q[1], q[3]), dmax(q[5], q[7]));
	uint32_t r0 = disc_col(c, y0), r1 = disc_col(c, y1);
	uint64_t cnt = 0;
	double l0, h0, l1, h1;
	int a = chord(q, (double)r0 / c->g, &l0, &h0), b;

	for (uint32_t r = r0; r <= r1; r++, a = b, l0 = l1, h0 = h1) {
		double ylo = (double)r / c->g, yhi = (double)(r + 1) / c->g;
		double ol = 2, oh = -1;
		uint32_t fl = 0, fr = 0, c0, c1;
		b = chord(q, yhi, &l1, &h1);
		if (a && b)
			full_cells(c, dmax(l0, l1) + CELL_MARGIN,
			    dmin(h0, h1) - CELL_MARGIN, &fl, &fr);
		/* the quadrilateral's extent within the row */
		if (a)
			ol = l0, oh = h0;
		if (b)
			ol = dmin(ol, l1), oh = dmax(oh, h1);
		for (int v = 0; v < 4; v++)
			if (q[2 * v + 1] >= ylo && q[2 * v + 1] <= yhi)
				ol = dmin(ol, q[2 * v]), oh = dmax(oh, q[2 * v]);
		if (ol > oh)
			continue;
		outer_cells(c, ol, oh, &c0, &c1);
		ROW_COUNT(c, r, c0, c1, fl, fr,
		    disc_in_quad(q, c->x[i_], c->y[i_]));
	}
	return cnt;
}

uint64_t disc_count_circle(const struct disc_cols *c, const double e[3])
{
	/* rows widened by more than the rounding of e +- r */
	double pad = e[2] + 0x1p-50;
	uint32_t r0 = disc_col(c, e[1] - pad), r1 = disc_col(c, e[1] + pad);
	uint64_t cnt = 0;

	for (uint32_t r = r0; r <= r1; r++) {
		double ylo = (double)r / c->g, yhi = (double)(r + 1) / c->g;
		double far = fmax(fabs(ylo - e[1]), fabs(yhi - e[1]));
		double near = ylo <= e[1] && e[1] <= yhi ? 0.0 :
		    fmin(fabs(ylo - e[1]), fabs(yhi - e[1]));
		uint32_t fl = 0, fr = 0, c0, c1;
		double w;
		if (far < e[2]) {
			w = sqrt(e[2] * e[2] - far * far) - CELL_MARGIN;
			full_cells(c, e[0] - w, e[0] + w, &fl, &fr);
		}
		if (near > pad)
			continue;
		w = near < e[2] ? sqrt(e[2] * e[2] - near * near) : 0.0;
		outer_cells(c, e[0] - w, e[0] + w, &c0, &c1);
		ROW_COUNT(c, r, c0, c1, fl, fr,
		    geom_in_circle(e[0], e[1], e[2], c->x[i_], c->y[i_]));
	}
	return cnt;
}

/* Shapes drawn once per run, up to DISC_CACHE of them; the rest are drawn
 * again for each set. */
#define DISC_CACHE ((uint64_t)1 << 21)

struct disc_shapes {
	enum disc_class cls;
	uint64_t k, cached, seed;
	double *v;		/* 8 (quad) or 3 (circle) per shape */
};

static unsigned shape_len(enum disc_class c)
{
	return c == DISC_QUAD ? 8 : 3;
}

static void shape_get(const struct disc_shapes *sh, uint64_t k, double *q)
{
	unsigned len = shape_len(sh->cls);
	if (k < sh->cached) {
		for (unsigned i = 0; i < len; i++)
			q[i] = sh->v[k * len + i];
	} else if (sh->cls == DISC_QUAD)
		disc_quad_shape(sh->seed, k, q);
	else
		disc_circle_shape(sh->seed, k, q);
}

static int fill_chunk(void *ctx, uint64_t b, uint64_t e)
{
	struct disc_shapes *sh = ctx;
	unsigned len = shape_len(sh->cls);
	for (uint64_t k = b; k < e; k++) {
		if (sh->cls == DISC_QUAD)
			disc_quad_shape(sh->seed, k, sh->v + k * len);
		else
			disc_circle_shape(sh->seed, k, sh->v + k * len);
	}
	return 0;
}

struct disc_shapes *disc_shapes_new(enum disc_class cls, uint64_t k,
    uint64_t seed)
{
	struct disc_shapes *sh = calloc(1, sizeof *sh);

	if (sh == NULL) {
		cli_fail("no memory for the shapes");
		return NULL;
	}
	sh->cls = cls, sh->k = k, sh->seed = seed;
	sh->cached = k < DISC_CACHE ? k : DISC_CACHE;
	sh->v = malloc((sh->cached ? sh->cached : 1) * shape_len(cls) *
	    sizeof *sh->v);
	if (sh->v == NULL) {
		cli_fail("no memory for %llu shapes",
		    (unsigned long long)sh->cached);
		free(sh);
		return NULL;
	}
	if (disc_run_chunks(sh->cached, 4096, fill_chunk, sh, 1) < 0) {
		disc_shapes_free(sh);
		return NULL;
	}
	return sh;
}

void disc_shapes_free(struct disc_shapes *sh)
{
	if (sh != NULL)
		free(sh->v);
	free(sh);
}

#define SHAPE_CHUNK 4096

struct shaperun {
	const struct disc_shapes *sh;
	struct disc_cols cols;
	double n;
	double *sum, *best;	/* per chunk */
};

static int shape_chunk(void *ctx, uint64_t b, uint64_t e)
{
	struct shaperun *r = ctx;
	struct num_sum sum = { 0.0, 0.0 };
	double best = 0.0, q[8];

	for (uint64_t k = b; k < e; k++) {
		uint64_t cnt;
		double area, v;
		shape_get(r->sh, k, q);
		if (r->sh->cls == DISC_QUAD) {
			cnt = disc_count_quad(&r->cols, q);
			area = disc_quad_area(q);
		} else {
			cnt = disc_count_circle(&r->cols, q);
			area = NUM_PI * q[2] * q[2];
		}
		v = fabs((double)cnt / r->n - area);
		best = v > best ? v : best;
		num_add(&sum, v * v);
	}
	r->sum[b / SHAPE_CHUNK] = num_total(&sum);
	r->best[b / SHAPE_CHUNK] = best;
	return 0;
}

int disc_shapes_run(const struct disc_shapes *sh, const double *xy, size_t n,
    int par, struct disc_result *res)
{
	struct shaperun r = { .sh = sh, .n = (double)n };
	size_t nch = (size_t)((sh->k + SHAPE_CHUNK - 1) / SHAPE_CHUNK);
	int rc;

	r.sum = malloc(2 * (nch ? nch : 1) * sizeof *r.sum);
	if (r.sum == NULL)
		return cli_fail("no memory for %zu chunks", nch);
	r.best = r.sum + nch;
	if (disc_cols_make(&r.cols, xy, n) < 0) {
		free(r.sum);
		return -1;
	}
	rc = disc_run_chunks(sh->k, SHAPE_CHUNK, shape_chunk, &r, par);
	if (rc == 0) {
		double best = 0.0;
		for (size_t i = 0; i < nch; i++)
			best = r.best[i] > best ? r.best[i] : best;
		res->d2 = sqrt(num_sum(r.sum, nch) / (double)sh->k);
		res->dinf = best;
	}
	disc_cols_free(&r.cols);
	free(r.sum);
	return rc;
}
