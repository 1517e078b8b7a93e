/*
 * Density rho and radial distribution function (see density.h for the
 * formulas and the search bounds).
 */
#define _POSIX_C_SOURCE 200809L
#include <float.h>
#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>

#include "frs.h"
#include "dda/density.h"
#include "cli/cli.h"

#define CHUNK 2048		/* sorted points per parallel chunk */
#define MAX_BINS ((size_t)1 << 24)

double dens_spacing(double n)
{
	return sqrt(2 / (sqrt(3.0) * n));
}

double dens_rho(double dmin, size_t n)
{
	return dmin / dens_spacing((double)n);
}

/* ---- input checks ---------------------------------------------------- */

static int check_point(const double *xy, size_t i)
{
	double x = xy[2 * i], y = xy[2 * i + 1];

	if (!(x >= 0 && x < 1 && y >= 0 && y < 1))
		return cli_fail("point %zu (%.17g, %.17g) is outside [0, 1)^2",
		    i, x, y);
	return 0;
}

static size_t pixel_of(double x, uint32_t w)
{
	size_t i = (size_t)(x * (double)w);
	return i < w ? i : (size_t)w - 1;
}

int dens_scales(const double *xy, size_t n, const struct frs_imap *map,
    double *f)
{
	struct num_sum sum = { 0.0, 0.0 };
	double mean;
	size_t np;

	if (n > 0 && (xy == NULL || f == NULL))
		return cli_fail("density scales: no points or no output");
	for (size_t i = 0; i < n; i++)
		if (check_point(xy, i) < 0)
			return -1;
	if (map == NULL) {
		for (size_t i = 0; i < n; i++)
			f[i] = 1;
		return 0;
	}
	if (map->w == 0 || map->h == 0 || map->v == NULL)
		return cli_fail("importance map is empty");
	np = (size_t)map->w * map->h;
	for (size_t k = 0; k < np; k++) {
		double v = map->v[k];
		if (!isfinite(v))
			return cli_fail("importance map: pixel (%zu, %zu) is "
			    "%g", k % map->w, k / map->w, v);
		num_add(&sum, v);
	}
	mean = num_total(&sum) / (double)np;
	if (!(mean > 0) || !isfinite(mean))
		return cli_fail("importance map: mean importance %g is not "
		    "positive and finite", mean);
	for (size_t i = 0; i < n; i++) {
		size_t px = pixel_of(xy[2 * i], map->w);
		size_t py = pixel_of(xy[2 * i + 1], map->h);
		double v = map->v[py * map->w + px];
		if (!(v > 0))
			return cli_fail("point %zu (%.17g, %.17g) lies on pixel "
			    "(%zu, %zu) of importance %g: no local spacing",
			    i, xy[2 * i], xy[2 * i + 1], px, py, v);
		f[i] = sqrt(v / mean);
	}
	return 0;
}

/* ---- the cell grid ----------------------------------------------------- */

struct pt {
	double x, y, f;
	size_t cx, cy;
};

/* Counting sort into cells: counts in start[c + 1] become the first
 * slot of each cell (prefix sums); filling then uses start[c] as a
 * cursor, which cells_unshift turns back into the first slots. */
static void cells_prefix(size_t *start, size_t cells)
{
	for (size_t c = 0; c < cells; c++)
		start[c + 1] += start[c];
}

static void cells_unshift(size_t *start, size_t cells)
{
	for (size_t c = cells; c > 0; c--)
		start[c] = start[c - 1];
	start[0] = 0;
}

/* A coordinate difference, folded to [0, 1/2] on the torus (exact). */
static inline double fold(double d, int torus)
{
	if (torus) {
		d = fabs(d);
		if (d > 0.5)
			d = 1 - d;
	}
	return d;
}

struct grid {
	size_t n, g;
	int torus;
	enum dens_rule rule;	/* the scale of a pair's key */
	size_t *start;		/* g * g + 1 offsets into p */
	struct pt *p;		/* sorted by cell, then input index */
};

static void grid_free(struct grid *gr)
{
	free(gr->start);
	free(gr->p);
}

static size_t cell_of(double x, size_t g)
{
	size_t c = (size_t)(x * (double)g);
	return c < g ? c : g - 1;
}

static int grid_build(struct grid *gr, const double *xy, size_t n,
    const double *f, int torus)
{
	size_t g = (size_t)floor(sqrt((double)n / 2)), cells;
	size_t *cnt;

	gr->start = NULL;
	gr->p = NULL;
	if (xy == NULL)
		return cli_fail("no points");
	for (size_t i = 0; i < n; i++) {
		if (check_point(xy, i) < 0)
			return -1;
		if (f != NULL && !(f[i] > 0 && f[i] <= DBL_MAX))
			return cli_fail("point %zu: scale %g is not positive "
			    "and finite", i, f[i]);
	}
	if (g < 1)
		g = 1;
	gr->n = n;
	gr->g = g;
	gr->torus = torus != 0;
	gr->rule = DENS_GEOMETRIC;
	cells = g * g;
	gr->start = calloc(cells + 1, sizeof *gr->start);
	gr->p = malloc(n * sizeof *gr->p);
	cnt = gr->start;
	if (gr->start == NULL || gr->p == NULL) {
		grid_free(gr);
		return cli_fail("no memory for the cell grid of %zu points", n);
	}
	for (size_t i = 0; i < n; i++) {
		size_t c = cell_of(xy[2 * i + 1], g) * g + cell_of(xy[2 * i], g);
		cnt[c + 1]++;
	}
	cells_prefix(cnt, cells);
	/* start[c] is now the first slot of cell c; fill with a cursor kept
	 * in start[c] and shift back afterwards. */
	for (size_t i = 0; i < n; i++) {
		size_t cx = cell_of(xy[2 * i], g), cy = cell_of(xy[2 * i + 1], g);
		struct pt *q = &gr->p[gr->start[cy * g + cx]++];
		q->x = xy[2 * i];
		q->y = xy[2 * i + 1];
		q->f = f != NULL ? f[i] : 1.0;
		q->cx = cx;
		q->cy = cy;
	}
	cells_unshift(gr->start, cells);
	return 0;
}

/* The pair key k_ij of density.h: each product rounded on its own;
 * under DENS_MAX the larger scale squared instead of f_i f_j. */
static inline double pair_key(const struct pt *a, const struct pt *b,
    int torus, enum dens_rule rule)
{
	double dx = fold(a->x - b->x, torus), dy = fold(a->y - b->y, torus);
	double xx, yy, d2, ff, fm;

	xx = dx * dx;
	yy = dy * dy;
	d2 = xx + yy;
	if (rule == DENS_MAX) {
		fm = a->f > b->f ? a->f : b->f;
		ff = fm * fm;
	} else
		ff = a->f * b->f;
	return d2 * ff;
}

/* Pair (s, t) of sorted points is examined from s. */
static inline int owns(const struct pt *p, size_t s, size_t t)
{
	return p[s].f < p[t].f || (p[s].f == p[t].f && s < t);
}

/* Lower bound on the key of a pair owned by a point of scale fs whose
 * partner lies at Chebyshev ring >= r; 0 when no bound holds. */
static double ring_bound(size_t r, size_t g, double fs)
{
	double l, b;

	if (r < 2)
		return 0;
	l = (double)(r - 1) / (double)g - 0x1p-49;
	if (l <= 0)
		return 0;
	b = l * l;
	b = b * (fs * fs);
	b = b * (1 - 0x1p-45);
	return b >= 0x1p-900 ? b : 0;
}

/* Largest ring around (cx, cy) that holds a cell, and the offset window. */
static size_t ring_limit(const struct grid *gr, size_t cx, size_t cy)
{
	size_t g = gr->g, m;

	if (gr->torus)
		return g / 2;
	m = cx > g - 1 - cx ? cx : g - 1 - cx;
	if (cy > m)
		m = cy;
	if (g - 1 - cy > m)
		m = g - 1 - cy;
	return m;
}

/* Offsets [lo, hi] along one axis of g cells allowed around cell c (the
 * 2-D grid and the 3-D cells alike). */
static void axis_window(size_t g_, int torus, size_t c, long long *lo,
    long long *hi)
{
	long long g = (long long)g_;

	if (torus) {
		*lo = -(g / 2);
		*hi = g - 1 - g / 2;
	} else {
		*lo = -(long long)c;
		*hi = g - 1 - (long long)c;
	}
}

/* Cell c + o of an axis of g cells, on the torus. */
static size_t wrap(size_t g_, size_t c, long long o)
{
	long long g = (long long)g_, v = (long long)c + o;

	return (size_t)(v < 0 ? v + g : v >= g ? v - g : v);
}

/* What a search does with the pairs it finds. */
struct visit {
	const struct grid *gr;
	double best;		/* min: smallest key so far */
	double kmax;		/* rdf: keys below it count */
	double w;		/* rdf: bin width */
	size_t nbins;
	uint64_t *hist;		/* rdf: NULL for min */
};

static void visit_cell(struct visit *v, size_t s, size_t cell)
{
	const struct grid *gr = v->gr;
	const struct pt *p = gr->p;
	size_t e = gr->start[cell + 1];

	for (size_t t = gr->start[cell]; t < e; t++) {
		double k;
		if (t == s || !owns(p, s, t))
			continue;
		k = pair_key(&p[s], &p[t], gr->torus, gr->rule);
		if (v->hist == NULL) {
			if (k < v->best)
				v->best = k;
		} else if (k < v->kmax) {
			size_t b = (size_t)(sqrt(k) / v->w);
			v->hist[b < v->nbins ? b : v->nbins - 1]++;
		}
	}
}

/* All pairs owned by sorted point s with a key below the target: v->best
 * (shrinking as pairs are found) or v->kmax. */
static void search(struct visit *v, size_t s)
{
	const struct grid *gr = v->gr;
	const struct pt *q = &gr->p[s];
	size_t g = gr->g, rmax = ring_limit(gr, q->cx, q->cy);
	long long xlo, xhi, ylo, yhi;

	axis_window(gr->g, gr->torus, q->cx, &xlo, &xhi);
	axis_window(gr->g, gr->torus, q->cy, &ylo, &yhi);
	for (size_t r = 0; r <= rmax; r++) {
		long long rr = (long long)r;
		long long oy0 = -rr > ylo ? -rr : ylo, oy1 = rr < yhi ? rr : yhi;
		long long ox0 = -rr > xlo ? -rr : xlo, ox1 = rr < xhi ? rr : xhi;
		double lb = ring_bound(r, g, q->f);

		if (v->hist == NULL ? lb > v->best : lb >= v->kmax)
			break;
		for (long long oy = oy0; oy <= oy1; oy++) {
			size_t row = wrap(gr->g, q->cy, oy) * g;
			if (oy == -rr || oy == rr) {
				for (long long ox = ox0; ox <= ox1; ox++)
					visit_cell(v, s, row + wrap(gr->g, q->cx, ox));
				continue;
			}
			if (-rr >= xlo)
				visit_cell(v, s, row + wrap(gr->g, q->cx, -rr));
			if (rr <= xhi && rr != 0)
				visit_cell(v, s, row + wrap(gr->g, q->cx, rr));
		}
	}
}

/* dens_min_distance's and dens_min_distance3's arguments. */
static int min_args(size_t n, const double *dmin)
{
	if (n < 2)
		return cli_fail("minimum distance: %zu point%s, at least 2 "
		    "needed", n, n == 1 ? "" : "s");
	if (dmin == NULL)
		return cli_fail("minimum distance: no output");
	return 0;
}

/* The minimum distance, 2-D or 3-D: fn leaves the least key of chunk
 * b / CHUNK in (*best)[b / CHUNK], an array made here; start bounds
 * them all.  *dmin the square root of the least. */
static int min_chunks(size_t n, int (*fn)(void *, uint64_t, uint64_t),
    void *job, double **best, double start, int par, double *dmin)
{
	size_t nchunks = (n + CHUNK - 1) / CHUNK;
	double m = start;
	int rc;

	if ((*best = malloc(nchunks * sizeof **best)) == NULL)
		return cli_fail("no memory for %zu chunks", nchunks);
	for (size_t c = 0; c < nchunks; c++)
		(*best)[c] = start;
	rc = cli_parallel_if(par, n, CHUNK, fn, job);
	for (size_t c = 0; rc == 0 && c < nchunks; c++)
		m = (*best)[c] < m ? (*best)[c] : m;
	free(*best);
	*best = NULL;
	if (rc < 0)
		return -1;
	*dmin = sqrt(m);
	return 0;
}

/* ---- minimum distance -------------------------------------------------- */

struct min_job {
	const struct grid *gr;
	double start;		/* key of some pair: an upper bound */
	double *best;		/* per chunk */
};

static int min_chunk(void *ctx, uint64_t b, uint64_t e)
{
	struct min_job *j = ctx;
	struct visit v = { .gr = j->gr, .best = j->start };

	for (uint64_t s = b; s < e && v.best > 0; s++)
		search(&v, (size_t)s);
	j->best[b / CHUNK] = v.best;
	return 0;
}

int dens_min_distance(const double *xy, size_t n, const double *f, int torus,
    int par, double *dmin)
{
	return dens_min_distance_rule(xy, n, f, DENS_GEOMETRIC, torus, par,
	    dmin);
}

int dens_min_distance_rule(const double *xy, size_t n, const double *f,
    enum dens_rule rule, int torus, int par, double *dmin)
{
	struct grid gr;
	struct min_job j;
	int rc;

	if (min_args(n, dmin) < 0)
		return -1;
	if (rule != DENS_GEOMETRIC && rule != DENS_MAX)
		return cli_fail("minimum distance: unknown pair rule %d",
		    (int)rule);
	if (grid_build(&gr, xy, n, f, torus) < 0)
		return -1;
	gr.rule = rule;
	/* Start from the smallest key of neighbours in cell order: any
	 * pair's key bounds the minimum from above. */
	j.gr = &gr;
	j.start = HUGE_VAL;
	for (size_t s = 1; s < n; s++) {
		double k = pair_key(&gr.p[s - 1], &gr.p[s], gr.torus, gr.rule);
		if (k < j.start)
			j.start = k;
	}
	rc = min_chunks(n, min_chunk, &j, &j.best, j.start, par, dmin);
	grid_free(&gr);
	return rc;
}

/* ---- 3-D sets: minimum distance ----------------------------------------- */

double dens_spacing3(double n)
{
	return cbrt(sqrt(2.0) / n);
}

double dens_rho3(double dmin, size_t n)
{
	return dmin / dens_spacing3((double)n);
}

struct pt3 {
	double x[3];
	size_t c[3];		/* cell per axis */
};

struct cells3 {
	size_t n, g;
	int torus;
	size_t *start;		/* g^3 + 1 offsets into p */
	struct pt3 *p;		/* sorted by cell (x fastest), then index */
};

static void cells3_free(struct cells3 *gr)
{
	free(gr->start);
	free(gr->p);
}

static size_t cell3_index(const size_t c[3], size_t g)
{
	return (c[2] * g + c[1]) * g + c[0];
}

static int check_point3(const double *xyz, size_t i)
{
	const double *p = &xyz[3 * i];

	if (!(p[0] >= 0 && p[0] < 1 && p[1] >= 0 && p[1] < 1 && p[2] >= 0 &&
	    p[2] < 1))
		return cli_fail("point %zu (%.17g, %.17g, %.17g) is outside "
		    "[0, 1)^3", i, p[0], p[1], p[2]);
	return 0;
}

/* G = floor(cbrt(n / 2)) cells per axis (about 2 points a cell), the
 * points counting-sorted by cell. */
static int cells3_build(struct cells3 *gr, const double *xyz, size_t n,
    int torus)
{
	size_t g = (size_t)floor(cbrt((double)n / 2)), cells;

	gr->start = NULL;
	gr->p = NULL;
	if (xyz == NULL)
		return cli_fail("no points");
	for (size_t i = 0; i < n; i++)
		if (check_point3(xyz, i) < 0)
			return -1;
	g = g < 1 ? 1 : g;
	gr->n = n, gr->g = g, gr->torus = torus != 0;
	cells = g * g * g;
	gr->start = calloc(cells + 1, sizeof *gr->start);
	gr->p = malloc(n * sizeof *gr->p);
	if (gr->start == NULL || gr->p == NULL) {
		cells3_free(gr);
		return cli_fail("no memory for the cell grid of %zu points", n);
	}
	for (size_t i = 0; i < n; i++) {
		struct pt3 q;
		for (int a = 0; a < 3; a++)
			q.c[a] = cell_of(xyz[3 * i + (size_t)a], g);
		gr->start[cell3_index(q.c, g) + 1]++;
	}
	cells_prefix(gr->start, cells);
	/* a cursor in start[c], shifted back afterwards (as in 2-D) */
	for (size_t i = 0; i < n; i++) {
		struct pt3 q;
		for (int a = 0; a < 3; a++) {
			q.x[a] = xyz[3 * i + (size_t)a];
			q.c[a] = cell_of(q.x[a], g);
		}
		gr->p[gr->start[cell3_index(q.c, g)]++] = q;
	}
	cells_unshift(gr->start, cells);
	return 0;
}

/* The key of density.h in 3-D: (xx + yy) + zz, each product rounded on
 * its own, differences folded on the torus. */
static inline double pair_key3(const struct pt3 *a, const struct pt3 *b,
    int torus)
{
	double sq[3];

	for (int k = 0; k < 3; k++) {
		double d = fold(a->x[k] - b->x[k], torus);
		sq[k] = d * d;
	}
	return (sq[0] + sq[1]) + sq[2];
}


/* Pairs (s, t > s) with t in the cell at offset o of s's cell. */
static double visit3(const struct cells3 *gr, size_t s, const long long o[3],
    double best)
{
	const struct pt3 *q = &gr->p[s];
	size_t c[3], cell, e;

	for (int a = 0; a < 3; a++)
		c[a] = wrap(gr->g, q->c[a], o[a]);
	cell = cell3_index(c, gr->g);
	e = gr->start[cell + 1];
	for (size_t t = gr->start[cell]; t < e; t++)
		if (t > s) {
			double k = pair_key3(q, &gr->p[t], gr->torus);
			best = k < best ? k : best;
		}
	return best;
}

/* The cells of Chebyshev ring r around point s (each once, clipped to
 * the windows); best shrinks as pairs are found. */
static double ring3(const struct cells3 *gr, size_t s, long long r,
    const long long lo[3], const long long hi[3], double best)
{
	long long o[3], b0[3], b1[3];

	for (int a = 0; a < 3; a++)
		b0[a] = -r > lo[a] ? -r : lo[a], b1[a] = r < hi[a] ? r : hi[a];
	for (o[2] = b0[2]; o[2] <= b1[2]; o[2]++)
		for (o[1] = b0[1]; o[1] <= b1[1]; o[1]++) {
			if (o[2] == -r || o[2] == r || o[1] == -r || o[1] == r) {
				for (o[0] = b0[0]; o[0] <= b1[0]; o[0]++)
					best = visit3(gr, s, o, best);
				continue;
			}
			if ((o[0] = -r) >= lo[0])
				best = visit3(gr, s, o, best);
			if ((o[0] = r) <= hi[0] && r != 0)
				best = visit3(gr, s, o, best);
		}
	return best;
}

/* Smallest key of the pairs of sorted point s with later points, if
 * below best: rings outward until their bound (as in 2-D: a cell at
 * ring r lies (r - 1)/G away in one coordinate) passes best. */
static double search3(const struct cells3 *gr, size_t s, double best)
{
	const struct pt3 *q = &gr->p[s];
	long long lo[3], hi[3], rmax = 0;

	for (int a = 0; a < 3; a++) {
		axis_window(gr->g, gr->torus, q->c[a], &lo[a], &hi[a]);
		rmax = -lo[a] > rmax ? -lo[a] : rmax;
		rmax = hi[a] > rmax ? hi[a] : rmax;
	}
	for (long long r = 0; r <= rmax; r++) {
		if (ring_bound((size_t)r, gr->g, 1.0) > best)
			break;
		best = ring3(gr, s, r, lo, hi, best);
	}
	return best;
}

struct min3_job {
	const struct cells3 *gr;
	double start;		/* key of some pair: an upper bound */
	double *best;		/* per chunk */
};

static int min3_chunk(void *ctx, uint64_t b, uint64_t e)
{
	struct min3_job *j = ctx;
	double best = j->start;

	for (uint64_t s = b; s < e && best > 0; s++)
		best = search3(j->gr, (size_t)s, best);
	j->best[b / CHUNK] = best;
	return 0;
}

int dens_min_distance3(const double *xyz, size_t n, int torus, int par,
    double *dmin)
{
	struct cells3 gr;
	struct min3_job j;
	int rc;

	if (min_args(n, dmin) < 0)
		return -1;
	if (cells3_build(&gr, xyz, n, torus) < 0)
		return -1;
	/* neighbours in cell order: an upper bound to start from */
	j.gr = &gr;
	j.start = HUGE_VAL;
	for (size_t s = 1; s < n; s++) {
		double k = pair_key3(&gr.p[s - 1], &gr.p[s], gr.torus);
		j.start = k < j.start ? k : j.start;
	}
	rc = min_chunks(n, min3_chunk, &j, &j.best, j.start, par, dmin);
	cells3_free(&gr);
	return rc;
}

/* ---- pair distance distribution of uniform points ---------------------- */

double dens_rdf_limit(int torus)
{
	return torus ? sqrt(0.5) : sqrt(2.0);
}

static double cdf_outer(double r, int torus)
{
	if (torus) {
		double r2 = r * r;
		return NUM_PI * r2 - 4 * (r2 * acos(0.5 / r) - 0.5 *
		    sqrt(r2 - 0.25));
	} else {
		double r2 = r * r, s = sqrt(r2 - 1), s2 = s * s, s3 = s2 * s;
		return 2 * s - s2 + 2 * r2 * (2 * asin(1 / r) - NUM_PI / 2) -
		    4.0 / 3 * (1 - s3) - r2 + 1.0 / 6 + 2 * r2 * (s - s2 / 2) -
		    2.0 / 3 * s3 + 0.5 * s2 * s2;
	}
}

double dens_pair_cdf(double r, int torus)
{
	double t = torus ? 0.5 : 1.0;

	if (!(r > 0))
		return 0;
	if (r >= dens_rdf_limit(torus))
		return 1;
	if (r <= t)
		return torus ? NUM_PI * r * r :
		    r * r * (NUM_PI - 8.0 / 3 * r + 0.5 * r * r);
	return cdf_outer(r, torus);
}

/* P(b) - P(a), 0 <= a < b <= limit; below the break (b - a) factored out. */
static double cdf_diff(double a, double b, int torus)
{
	double t = torus ? 0.5 : 1.0, lo;

	if (a >= t)
		return dens_pair_cdf(b, torus) - dens_pair_cdf(a, torus);
	lo = b < t ? b : t;
	{
		double s = a + lo, q = a * a + a * lo + lo * lo;
		double d = torus ? NUM_PI * s :
		    NUM_PI * s - 8.0 / 3 * q + 0.5 * s * (a * a + lo * lo);
		d *= lo - a;
		if (b > t)
			d += dens_pair_cdf(b, torus) - dens_pair_cdf(t, torus);
		return d;
	}
}

/* ---- radial distribution function --------------------------------------- */

struct rdf_job {
	const struct grid *gr;
	double kmax, w;
	size_t nbins;
	atomic_uint_fast64_t *count;
};

static int rdf_chunk(void *ctx, uint64_t b, uint64_t e)
{
	struct rdf_job *j = ctx;
	struct visit v = { .gr = j->gr, .best = 0, .kmax = j->kmax, .w = j->w,
	    .nbins = j->nbins };

	v.hist = calloc(j->nbins, sizeof *v.hist);
	if (v.hist == NULL)
		return cli_fail("no memory for %zu bins", j->nbins);
	for (uint64_t s = b; s < e; s++)
		search(&v, (size_t)s);
	for (size_t k = 0; k < j->nbins; k++)
		if (v.hist[k] != 0)
			atomic_fetch_add(&j->count[k], v.hist[k]);
	free(v.hist);
	return 0;
}

int dens_rdf_add(const double *xy, size_t n, const double *f, int torus,
    double rmax_ru, size_t nbins, int par, double *acc)
{
	struct grid gr;
	struct rdf_job j;
	double rmax, npairs;
	int rc;

	if (n < 2)
		return cli_fail("radial distribution: %zu point%s, at least 2 "
		    "needed", n, n == 1 ? "" : "s");
	if (nbins < 1 || nbins > MAX_BINS)
		return cli_fail("radial distribution: %zu bins, 1 to %zu "
		    "allowed", nbins, MAX_BINS);
	if (acc == NULL)
		return cli_fail("radial distribution: no output");
	rmax = rmax_ru * dens_spacing((double)n);
	if (!(rmax > 0) || !(rmax <= dens_rdf_limit(torus)))
		return cli_fail("radial distribution: rmax %g r_u = %g is not "
		    "in (0, %g] (%s distance of %zu points)", rmax_ru, rmax,
		    dens_rdf_limit(torus), torus ? "toroidal" : "plain", n);
	if (grid_build(&gr, xy, n, f, torus) < 0)
		return -1;
	j.gr = &gr;
	j.kmax = rmax * rmax;
	j.w = rmax / (double)nbins;
	j.nbins = nbins;
	j.count = malloc(nbins * sizeof *j.count);
	if (j.count == NULL) {
		grid_free(&gr);
		return cli_fail("no memory for %zu bins", nbins);
	}
	for (size_t k = 0; k < nbins; k++)
		atomic_init(&j.count[k], 0);
	rc = cli_parallel_if(par, n, CHUNK, rdf_chunk, &j);
	grid_free(&gr);
	if (rc == 0) {
		npairs = (double)n * (double)(n - 1) / 2;
		for (size_t k = 0; k < nbins; k++) {
			double a = rmax * (double)k / (double)nbins;
			double b = k + 1 == nbins ? rmax :
			    rmax * (double)(k + 1) / (double)nbins;
			double e = npairs * cdf_diff(a, b, torus);
			acc[k] += (double)atomic_load(&j.count[k]) / e;
		}
	}
	free(j.count);
	return rc;
}
