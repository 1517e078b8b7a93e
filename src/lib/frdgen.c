#define _POSIX_C_SOURCE 200809L
#include "frdgen.h"
#include "err.h"
#include "io.h"
#include "outfile.h"
#include "par.h"
#include "progress.h"
#include "rng.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAXLEV 40
#define DEFAULT_TOL 1e-4
#define DEFAULT_REACH 3.0
/* Above this many cells a window is split over threads. */
#define PAR_CELLS 65536

/* One level of the min-pyramid: level 0 holds the minimum of each tile of
 * cells, level L+1 the minimum of 2x2x2 nodes of level L. */
struct level {
	uint32_t nx, ny, nz;
	double *min;
	uint64_t *stamp;	/* last step that queued the node */
};

struct item {			/* a heap entry of the rank query */
	double v;
	int lev;		/* -1: a cell */
	uint32_t idx;
};

struct gen {
	const struct frdgen_params *pr;
	uint32_t w, h, d;
	size_t n;
	double *field;		/* +inf marks a taken cell */
	uint32_t *val;
	double *table;		/* f by |dx|, |dy|, |dz| */
	uint32_t hw, hh, hd;	/* largest toroidal offsets: w/2, h/2, d/2 */
	double rtol, rmax;
	uint32_t tx, ty, tz;	/* tile size */
	int nlev;
	struct level lev[MAXLEV];
	uint32_t *dirty[2];
	uint32_t *ax[3];	/* tiles per axis of the current window */
	size_t ndirty[2], dcap;
	struct item *heap;
	size_t nheap, hcap;
	struct item *emit;
	size_t nemit, ecap;
	/* window of the current insertion, for the parallel add */
	uint32_t cx, cy, cz;
	double r;
	uint64_t step;
};

/* ---- parameters --------------------------------------------------- */

void frdgen_defaults(struct frdgen_params *pr)
{
	memset(pr, 0, sizeof *pr);
	pr->dims = 2;
	pr->p = 0.5;
	pr->s = 0.5;
	pr->q = 0.5;
	pr->tol = DEFAULT_TOL;
	pr->reach = DEFAULT_REACH;
	pr->seed = 1;
	pr->checkpoint_every = 60.0;
}

int frdgen_check(const struct frdgen_params *pr)
{
	uint64_t n = (uint64_t)pr->w * pr->h * pr->d;

	if (pr->dims != 2 && pr->dims != 3)
		return frs_fail("-k: %u dimensions (2 or 3)", pr->dims);
	if (pr->w < 2 || pr->h < 2 || pr->d < 1 ||
	    (pr->dims == 3 && pr->d < 2) || (pr->dims == 2 && pr->d != 1))
		return frs_fail("-s: a matrix needs at least 2 cells per side");
	if (n > UINT32_MAX)
		return frs_fail("-s: %llu cells is more than 2^32 - 1 values",
		    (unsigned long long)n);
	if (!(pr->p > 0.0 && pr->p <= 1.0))
		return frs_fail("-p: %g is outside (0, 1]", pr->p);
	if (!(pr->s > 0.0 && isfinite(pr->s)) || !(pr->q > 0.0 &&
	    isfinite(pr->q)))
		return frs_fail("force parameters s and q must be positive");
	if (!(pr->tol >= 0.0 && pr->tol < 1.0))
		return frs_fail("--tol: %g is outside [0, 1)", pr->tol);
	if (!(pr->reach >= 0.0 && isfinite(pr->reach)))
		return frs_fail("--reach: %g is negative", pr->reach);
	return 0;
}

double frdgen_force(const struct frdgen_params *pr, double r)
{
	return exp(-pow(r / pr->s, pr->q));
}

double frdgen_radius(const struct frdgen_params *pr)
{
	if (pr->tol <= 0.0)
		return INFINITY;
	return pr->s * pow(log(1.0 / pr->tol), 1.0 / pr->q);
}

uint64_t frdgen_memory(const struct frdgen_params *pr)
{
	uint64_t n = (uint64_t)pr->w * pr->h * pr->d;
	uint64_t t = ((uint64_t)pr->w / 2 + 1) * (pr->h / 2 + 1) *
	    (pr->d / 2 + 1);
	/* field, values (twice: the output), table, tiles and pyramid */
	return n * 8 + n * 4 * 2 + t * 8 + n / 4 + (1 << 20);
}

void frdgen_describe(const struct frdgen_params *pr, char *buf, size_t n)
{
	snprintf(buf, n, "generator=frd-gen\nk=%u\nsize=%ux%ux%u\np=%.17g\n"
	    "s=%.17g\nq=%.17g\ntol=%.17g\nreach=%.17g\nseed=%llu\n", pr->dims,
	    pr->w, pr->h, pr->d, pr->p, pr->s, pr->q, pr->tol, pr->reach,
	    (unsigned long long)pr->seed);
}

uint64_t frdgen_rank(const struct frdgen_params *pr, uint64_t step,
    uint64_t free)
{
	double u, lq, tail, k;

	if (pr->p >= 1.0 || free <= 1)
		return 1;
	/* Inverse CDF of Geometric(p) conditioned on K <= free: the minimum
	 * of a Bernoulli(p) subset, given that the subset is not empty. */
	u = frs_rand01(pr->seed, FRS_STREAM_FRD_COIN, step);
	lq = log1p(-pr->p);
	tail = exp((double)free * lq);
	k = 1.0 + floor(log1p(-u * (1.0 - tail)) / lq);
	if (!(k >= 1.0))
		return 1;
	return k > (double)free ? free : (uint64_t)k;
}

uint64_t frdgen_tiekey(const struct frdgen_params *pr, uint64_t step,
    uint32_t c)
{
	return frs_rand64x(pr->seed, FRS_STREAM_FRD_TIE, step, c);
}

/* ---- setup -------------------------------------------------------- */

static int make_table(struct gen *g)
{
	size_t nt = (size_t)(g->hw + 1) * (g->hh + 1) * (g->hd + 1);

	g->table = malloc(nt * sizeof *g->table);
	if (g->table == NULL)
		return frs_fail("out of memory for the force table");
	for (uint32_t z = 0; z <= g->hd; z++)
		for (uint32_t y = 0; y <= g->hh; y++)
			for (uint32_t x = 0; x <= g->hw; x++) {
				double r = sqrt((double)x * x + (double)y * y +
				    (double)z * z);
				g->table[((size_t)z * (g->hh + 1) + y) *
				    (g->hw + 1) + x] = frdgen_force(g->pr, r);
			}
	return 0;
}

static int make_levels(struct gen *g)
{
	uint32_t nx = (g->w + g->tx - 1) / g->tx;
	uint32_t ny = (g->h + g->ty - 1) / g->ty;
	uint32_t nz = (g->d + g->tz - 1) / g->tz;
	size_t total = 0;

	for (g->nlev = 0; g->nlev < MAXLEV; g->nlev++) {
		struct level *l = &g->lev[g->nlev];
		size_t cnt = (size_t)nx * ny * nz;
		l->nx = nx;
		l->ny = ny;
		l->nz = nz;
		l->min = malloc(cnt * sizeof *l->min);
		l->stamp = calloc(cnt, sizeof *l->stamp);
		if (l->min == NULL || l->stamp == NULL)
			return frs_fail("out of memory for the min-pyramid");
		total += cnt;
		if (cnt == 1) {
			g->nlev++;
			break;
		}
		nx = (nx + 1) / 2;
		ny = (ny + 1) / 2;
		nz = (nz + 1) / 2;
	}
	g->dcap = total;
	g->ax[0] = malloc(g->lev[0].nx * sizeof(uint32_t));
	g->ax[1] = malloc(g->lev[0].ny * sizeof(uint32_t));
	g->ax[2] = malloc(g->lev[0].nz * sizeof(uint32_t));
	if (g->ax[0] == NULL || g->ax[1] == NULL || g->ax[2] == NULL)
		return frs_fail("out of memory for the min-pyramid");
	g->dirty[0] = malloc(total * sizeof(uint32_t));
	g->dirty[1] = malloc(total * sizeof(uint32_t));
	if (g->dirty[0] == NULL || g->dirty[1] == NULL)
		return frs_fail("out of memory for the min-pyramid");
	return 0;
}

static void gen_free(struct gen *g)
{
	free(g->field);
	free(g->table);
	for (int i = 0; i < g->nlev; i++) {
		free(g->lev[i].min);
		free(g->lev[i].stamp);
	}
	free(g->dirty[0]);
	free(g->dirty[1]);
	for (int i = 0; i < 3; i++)
		free(g->ax[i]);
	free(g->heap);
	free(g->emit);
}

static int gen_init(struct gen *g, const struct frdgen_params *pr,
    struct frs_matrix *out)
{
	char params[512];

	memset(g, 0, sizeof *g);
	g->pr = pr;
	g->w = pr->w;
	g->h = pr->h;
	g->d = pr->d;
	g->n = (size_t)pr->w * pr->h * pr->d;
	g->hw = g->w / 2;
	g->hh = g->h / 2;
	g->hd = g->d / 2;
	g->rtol = frdgen_radius(pr);
	g->rmax = sqrt((double)g->hw * g->hw + (double)g->hh * g->hh +
	    (double)g->hd * g->hd);
	if (pr->dims == 2) {
		g->tx = g->ty = 8;
		g->tz = 1;
	} else {
		g->tx = g->ty = g->tz = 4;
	}
	frdgen_describe(pr, params, sizeof params);
	if (frd_alloc(out, pr->dims, g->w, g->h, g->d, params) < 0)
		return -1;
	g->val = out->v;
	g->field = calloc(g->n, sizeof *g->field);
	if (g->field == NULL)
		return frs_fail("out of memory for a %zu-cell force field", g->n);
	if (make_table(g) < 0 || make_levels(g) < 0)
		return -1;
	return 0;
}

/* ---- the min-pyramid ---------------------------------------------- */

static double tile_min(const struct gen *g, uint32_t tx, uint32_t ty,
    uint32_t tz)
{
	uint32_t x1 = (tx + 1) * g->tx < g->w ? (tx + 1) * g->tx : g->w;
	uint32_t y1 = (ty + 1) * g->ty < g->h ? (ty + 1) * g->ty : g->h;
	uint32_t z1 = (tz + 1) * g->tz < g->d ? (tz + 1) * g->tz : g->d;
	double m = INFINITY;

	for (uint32_t z = tz * g->tz; z < z1; z++)
		for (uint32_t y = ty * g->ty; y < y1; y++) {
			const double *row = g->field + ((size_t)z * g->h + y) * g->w;
			for (uint32_t x = tx * g->tx; x < x1; x++)
				m = row[x] < m ? row[x] : m;
		}
	return m;
}

static double node_min(const struct gen *g, int l, uint32_t x, uint32_t y,
    uint32_t z)
{
	const struct level *c = &g->lev[l - 1];
	double m = INFINITY;

	for (uint32_t k = 2 * z; k < 2 * z + 2 && k < c->nz; k++)
		for (uint32_t j = 2 * y; j < 2 * y + 2 && j < c->ny; j++)
			for (uint32_t i = 2 * x; i < 2 * x + 2 && i < c->nx; i++) {
				double v = c->min[((size_t)k * c->ny + j) * c->nx + i];
				m = v < m ? v : m;
			}
	return m;
}

static int tiles_rows(void *ctx, uint64_t b, uint64_t e)
{
	struct gen *g = ctx;
	struct level *l = &g->lev[0];

	for (uint64_t r = b; r < e; r++) {
		uint32_t ty = (uint32_t)(r % l->ny), tz = (uint32_t)(r / l->ny);
		for (uint32_t tx = 0; tx < l->nx; tx++)
			l->min[((size_t)tz * l->ny + ty) * l->nx + tx] =
			    tile_min(g, tx, ty, tz);
	}
	return 0;
}

/* Recompute every tile and level (start, resume, full-torus windows). */
static void rebuild_all(struct gen *g)
{
	frs_parallel((uint64_t)g->lev[0].ny * g->lev[0].nz, 4, tiles_rows, g,
	    NULL);
	for (int l = 1; l < g->nlev; l++) {
		struct level *v = &g->lev[l];
		for (uint32_t z = 0; z < v->nz; z++)
			for (uint32_t y = 0; y < v->ny; y++)
				for (uint32_t x = 0; x < v->nx; x++)
					v->min[((size_t)z * v->ny + y) * v->nx + x] =
					    node_min(g, l, x, y, z);
	}
}

/* Tiles along one axis that a window [c - neg, c + pos] touches. */
static uint32_t axis_tiles(uint32_t c, uint32_t neg, uint32_t pos,
    uint32_t size, uint32_t ts, uint32_t *out)
{
	uint32_t nt = (size + ts - 1) / ts, k = 0, first, last;

	if (neg + pos + 1 < size) {
		first = (c + size - neg) % size / ts;
		last = (c + pos) % size / ts;
		if (first <= last && (c + size - neg) % size <= (c + pos) % size) {
			for (uint32_t t = first; t <= last; t++)
				out[k++] = t;
			return k;
		}
		if (last < first) {	/* wraps around the torus */
			for (uint32_t t = 0; t <= last; t++)
				out[k++] = t;
			for (uint32_t t = first; t < nt; t++)
				out[k++] = t;
			return k;
		}
	}
	for (uint32_t t = 0; t < nt; t++)
		out[k++] = t;
	return k;
}

static void push_dirty(struct gen *g, int side, int l, uint32_t idx)
{
	if (g->lev[l].stamp[idx] == g->step + 1)
		return;
	g->lev[l].stamp[idx] = g->step + 1;
	g->dirty[side][g->ndirty[side]++] = idx;
}

/* After a window add: recompute its tiles, then their ancestors. */
static void update_window(struct gen *g, uint32_t ext[3][2])
{
	uint32_t **ax = g->ax, cnt[3], c[3] = { g->cx, g->cy, g->cz };
	uint32_t size[3] = { g->w, g->h, g->d }, ts[3] = { g->tx, g->ty, g->tz };
	struct level *l0 = &g->lev[0];
	int side = 0;

	for (int i = 0; i < 3; i++)
		cnt[i] = axis_tiles(c[i], ext[i][0], ext[i][1], size[i], ts[i],
		    ax[i]);
	g->ndirty[0] = 0;
	for (uint32_t k = 0; k < cnt[2]; k++)
		for (uint32_t j = 0; j < cnt[1]; j++)
			for (uint32_t i = 0; i < cnt[0]; i++) {
				uint32_t idx = (ax[2][k] * l0->ny + ax[1][j]) *
				    l0->nx + ax[0][i];
				l0->min[idx] = tile_min(g, ax[0][i], ax[1][j],
				    ax[2][k]);
				g->dirty[0][g->ndirty[0]++] = idx;
			}
	for (int l = 1; l < g->nlev; l++) {
		struct level *lo = &g->lev[l - 1], *up = &g->lev[l];
		g->ndirty[!side] = 0;
		for (size_t t = 0; t < g->ndirty[side]; t++) {
			uint32_t idx = g->dirty[side][t];
			uint32_t x = idx % lo->nx, y = idx / lo->nx % lo->ny;
			uint32_t z = idx / lo->nx / lo->ny;
			push_dirty(g, !side, l, ((z / 2) * up->ny + y / 2) * up->nx +
			    x / 2);
		}
		side = !side;
		for (size_t t = 0; t < g->ndirty[side]; t++) {
			uint32_t idx = g->dirty[side][t];
			up->min[idx] = node_min(g, l, idx % up->nx,
			    idx / up->nx % up->ny, idx / up->nx / up->ny);
		}
	}
}

/* ---- adding the force of one insertion ---------------------------- */

static uint32_t umin(uint32_t a, uint32_t b)
{
	return a < b ? a : b;
}

/* Largest e with e^2 <= rr, capped at cap. */
static uint32_t extent(double rr, uint32_t cap)
{
	double e;

	if (rr < 0.0)
		return 0;
	if (rr >= (double)cap * cap)
		return cap;
	e = floor(sqrt(rr));
	while ((e + 1) * (e + 1) <= rr)
		e += 1;
	while (e * e > rr)
		e -= 1;
	return (uint32_t)e;
}

static void add_row(struct gen *g, int dz, int dy, uint32_t en, uint32_t ep)
{
	uint32_t zz = (uint32_t)(((int64_t)g->cz + dz + g->d) % g->d);
	uint32_t yy = (uint32_t)(((int64_t)g->cy + dy + g->h) % g->h);
	double *row = g->field + ((size_t)zz * g->h + yy) * g->w;
	const double *t = g->table + ((size_t)(dz < 0 ? -dz : dz) * (g->hh + 1) +
	    (size_t)(dy < 0 ? -dy : dy)) * (g->hw + 1);
	uint32_t cx = g->cx, w = g->w;

	/* dx = 0 .. ep, then -1 .. -en, each cut where the torus wraps. */
	if (cx + ep < w) {
		for (uint32_t dx = 0; dx <= ep; dx++)
			row[cx + dx] += t[dx];
	} else {
		for (uint32_t dx = 0; dx < w - cx; dx++)
			row[cx + dx] += t[dx];
		for (uint32_t dx = w - cx; dx <= ep; dx++)
			row[cx + dx - w] += t[dx];
	}
	if (en <= cx) {
		for (uint32_t dx = 1; dx <= en; dx++)
			row[cx - dx] += t[dx];
	} else {
		for (uint32_t dx = 1; dx <= cx; dx++)
			row[cx - dx] += t[dx];
		for (uint32_t dx = cx + 1; dx <= en; dx++)
			row[cx + w - dx] += t[dx];
	}
}

struct window {
	uint32_t ext[3][2];	/* negative and positive extent per axis */
	double r2;
};

static void window_row(struct gen *g, const struct window *wd, uint64_t r)
{
	uint32_t ny = wd->ext[1][0] + wd->ext[1][1] + 1;
	int dy = (int)(r % ny) - (int)wd->ext[1][0];
	int dz = (int)(r / ny) - (int)wd->ext[2][0];
	double rr = wd->r2 - (double)dy * dy - (double)dz * dz;

	if (rr < 0.0)
		return;
	add_row(g, dz, dy, extent(rr, wd->ext[0][0]), extent(rr, wd->ext[0][1]));
}

struct rowjob {
	struct gen *g;
	const struct window *wd;
};

static int rows_task(void *ctx, uint64_t b, uint64_t e)
{
	struct rowjob *j = ctx;
	for (uint64_t r = b; r < e; r++)
		window_row(j->g, j->wd, r);
	return 0;
}

/* Add the force of the value just inserted at (cx, cy, cz) within radius
 * r, then bring the pyramid up to date. */
static void add_force(struct gen *g, double r)
{
	struct window wd;
	uint32_t size[3] = { g->w, g->h, g->d }, full = r >= g->rmax;
	uint64_t nrows, cells;

	for (int i = 0; i < 3; i++) {
		uint32_t cap = full ? size[i] : (uint32_t)umin((uint32_t)
		    fmin(floor(r), (double)size[i]), size[i]);
		wd.ext[i][0] = umin(cap, (size[i] - 1) / 2);
		wd.ext[i][1] = umin(cap, size[i] / 2);
	}
	wd.r2 = full ? INFINITY : r * r;
	nrows = (uint64_t)(wd.ext[1][0] + wd.ext[1][1] + 1) *
	    (wd.ext[2][0] + wd.ext[2][1] + 1);
	cells = nrows * (wd.ext[0][0] + wd.ext[0][1] + 1);
	if (cells >= PAR_CELLS && frs_threads() > 1) {
		struct rowjob j = { g, &wd };
		frs_parallel(nrows, 8, rows_task, &j, NULL);
	} else {
		for (uint64_t k = 0; k < nrows; k++)
			window_row(g, &wd, k);
	}
	if (full && frs_threads() > 1)
		rebuild_all(g);
	else
		update_window(g, wd.ext);
}

/* ---- the rank query: the K-th smallest free cell ------------------ */

static int heap_push(struct gen *g, double v, int lev, uint32_t idx)
{
	size_t i;

	if (g->nheap == g->hcap) {
		size_t ncap = g->hcap ? 2 * g->hcap : 256;
		struct item *nh = realloc(g->heap, ncap * sizeof *nh);
		if (nh == NULL)
			return frs_fail("out of memory in the rank query");
		g->heap = nh;
		g->hcap = ncap;
	}
	i = g->nheap++;
	while (i > 0 && g->heap[(i - 1) / 2].v > v) {
		g->heap[i] = g->heap[(i - 1) / 2];
		i = (i - 1) / 2;
	}
	g->heap[i] = (struct item){ v, lev, idx };
	return 0;
}

static struct item heap_pop(struct gen *g)
{
	struct item top = g->heap[0], last = g->heap[--g->nheap];
	size_t i = 0;

	for (;;) {
		size_t c = 2 * i + 1;
		if (c >= g->nheap)
			break;
		if (c + 1 < g->nheap && g->heap[c + 1].v < g->heap[c].v)
			c++;
		if (g->heap[c].v >= last.v)
			break;
		g->heap[i] = g->heap[c];
		i = c;
	}
	if (g->nheap > 0)
		g->heap[i] = last;
	return top;
}

/* Push the children of a node: nodes of the level below, or cells. */
static int expand(struct gen *g, int lev, uint32_t idx)
{
	const struct level *l = &g->lev[lev];
	uint32_t x = idx % l->nx, y = idx / l->nx % l->ny, z = idx / l->nx / l->ny;

	if (lev == 0) {
		for (uint32_t k = z * g->tz; k < umin((z + 1) * g->tz, g->d); k++)
			for (uint32_t j = y * g->ty; j < umin((y + 1) * g->ty, g->h);
			    j++)
				for (uint32_t i = x * g->tx;
				    i < umin((x + 1) * g->tx, g->w); i++) {
					uint32_t c = (k * g->h + j) * g->w + i;
					if (g->field[c] < INFINITY &&
					    heap_push(g, g->field[c], -1, c) < 0)
						return -1;
				}
		return 0;
	}
	l = &g->lev[lev - 1];
	for (uint32_t k = 2 * z; k < umin(2 * z + 2, l->nz); k++)
		for (uint32_t j = 2 * y; j < umin(2 * y + 2, l->ny); j++)
			for (uint32_t i = 2 * x; i < umin(2 * x + 2, l->nx); i++) {
				uint32_t ci = (k * l->ny + j) * l->nx + i;
				if (l->min[ci] < INFINITY &&
				    heap_push(g, l->min[ci], lev - 1, ci) < 0)
					return -1;
			}
	return 0;
}

static int emit(struct gen *g, struct item it)
{
	if (g->nemit == g->ecap) {
		size_t ncap = g->ecap ? 2 * g->ecap : 64;
		struct item *ne = realloc(g->emit, ncap * sizeof *ne);
		if (ne == NULL)
			return frs_fail("out of memory in the rank query");
		g->emit = ne;
		g->ecap = ncap;
	}
	g->emit[g->nemit++] = it;
	return 0;
}

/* Up to this many cells of equal force are gathered in memory; a larger
 * tie (the all-zero field before the first insertion) is streamed. */
#define TIECAP 4096

/* Bounded max-heap of keys: the m smallest (key, cell) pairs seen. */
struct keyheap {
	uint64_t *key;
	uint32_t *cell;
	size_t n, m;
};

static int key_less(uint64_t ka, uint32_t ca, uint64_t kb, uint32_t cb)
{
	return ka < kb || (ka == kb && ca < cb);
}

static void keyheap_offer(struct keyheap *h, uint64_t k, uint32_t c)
{
	size_t i;

	if (h->n == h->m) {
		if (!key_less(k, c, h->key[0], h->cell[0]))
			return;
		/* Replace the largest and sift down. */
		i = 0;
		for (;;) {
			size_t ch = 2 * i + 1;
			if (ch >= h->n)
				break;
			if (ch + 1 < h->n && key_less(h->key[ch], h->cell[ch],
			    h->key[ch + 1], h->cell[ch + 1]))
				ch++;
			if (!key_less(k, c, h->key[ch], h->cell[ch]))
				break;
			h->key[i] = h->key[ch];
			h->cell[i] = h->cell[ch];
			i = ch;
		}
		h->key[i] = k;
		h->cell[i] = c;
		return;
	}
	i = h->n++;
	while (i > 0 && key_less(h->key[(i - 1) / 2], h->cell[(i - 1) / 2], k, c)) {
		h->key[i] = h->key[(i - 1) / 2];
		h->cell[i] = h->cell[(i - 1) / 2];
		i = (i - 1) / 2;
	}
	h->key[i] = k;
	h->cell[i] = c;
}

/* Every free cell whose force equals v, in depth-first order; offer each
 * to the key heap. */
static int stream_ties(struct gen *g, double v, struct keyheap *kh)
{
	g->nheap = 0;
	if (heap_push(g, 0.0, g->nlev - 1, 0) < 0)
		return -1;
	while (g->nheap > 0) {
		struct item it = g->heap[--g->nheap];	/* used as a stack */
		if (it.lev < 0) {
			if (g->field[it.idx] == v)
				keyheap_offer(kh, frdgen_tiekey(g->pr, g->step,
				    it.idx), it.idx);
			continue;
		}
		if (g->lev[it.lev].min[it.idx] > v)
			continue;
		if (expand(g, it.lev, it.idx) < 0)
			return -1;
	}
	return 0;
}

static int cmp_key(const void *a, const void *b)
{
	const uint64_t *x = a, *y = b;
	if (x[0] != y[0])
		return x[0] < y[0] ? -1 : 1;
	return x[1] < y[1] ? -1 : x[1] > y[1];
}

/* Pick the (rank)-th (0-based) cell of a tie group by key. */
static int pick_in_group(struct gen *g, size_t a, size_t rank, uint32_t *c)
{
	size_t m = g->nemit - a;
	uint64_t *kc = malloc(2 * m * sizeof *kc);

	if (kc == NULL)
		return frs_fail("out of memory in the rank query");
	for (size_t i = 0; i < m; i++) {
		kc[2 * i] = frdgen_tiekey(g->pr, g->step, g->emit[a + i].idx);
		kc[2 * i + 1] = g->emit[a + i].idx;
	}
	qsort(kc, m, 2 * sizeof *kc, cmp_key);
	*c = (uint32_t)kc[2 * rank + 1];
	free(kc);
	return 0;
}

/* The K-th smallest free cell in the order (force, tie key). */
static int select_cell(struct gen *g, uint64_t k, uint32_t *c)
{
	double v;
	size_t a;

	g->nheap = g->nemit = 0;
	if (heap_push(g, g->lev[g->nlev - 1].min[0], g->nlev - 1, 0) < 0)
		return -1;
	/* Best-first: cells come out in nondecreasing force. */
	while (g->nheap > 0) {
		struct item it;
		if (g->nemit >= k && (g->heap[0].v > g->emit[k - 1].v ||
		    g->nemit >= k + TIECAP))
			break;
		it = heap_pop(g);
		if ((it.lev < 0 ? emit(g, it) : expand(g, it.lev, it.idx)) < 0)
			return -1;
	}
	if (g->nemit < k)
		return frs_fail("internal error: %zu free cells found, rank %llu",
		    g->nemit, (unsigned long long)k);
	v = g->emit[k - 1].v;
	for (a = k - 1; a > 0 && g->emit[a - 1].v == v; a--)
		;
	if (g->nheap == 0 || g->heap[0].v > v) {
		while (g->nemit > k && g->emit[g->nemit - 1].v > v)
			g->nemit--;
		return pick_in_group(g, a, k - 1 - a, c);
	}
	/* A tie too large to gather: stream it. */
	{
		struct keyheap kh = { NULL, NULL, 0, k - a };
		int rc;
		kh.key = malloc(kh.m * sizeof *kh.key);
		kh.cell = malloc(kh.m * sizeof *kh.cell);
		rc = kh.key && kh.cell ? stream_ties(g, v, &kh) :
		    frs_fail("out of memory in the rank query");
		if (rc == 0)
			*c = kh.cell[0];	/* the largest of the m smallest */
		free(kh.key);
		free(kh.cell);
		return rc;
	}
}

/* ---- checkpoints -------------------------------------------------- */

#define CKPT_MAGIC "FRDCKPT1"

/* The state after "step" insertions: parameters, step, values (free cells
 * UINT32_MAX) and the field; enough to go on with the same result. */
static int save_checkpoint(struct gen *g, uint64_t step)
{
	struct outfile o;
	char params[512];
	unsigned char h[8 + 4 + 8];
	uint32_t plen;
	int ok;

	frdgen_describe(g->pr, params, sizeof params);
	plen = (uint32_t)strlen(params);
	memcpy(h, CKPT_MAGIC, 8);
	io_put_u32(h + 8, plen);
	io_put_u64(h + 12, step);
	if (outfile_open(&o, g->pr->checkpoint, 1) < 0)
		return -1;
	ok = fwrite(h, 1, sizeof h, o.fp) == sizeof h &&
	    fwrite(params, 1, plen, o.fp) == plen &&
	    fwrite(g->val, 4, g->n, o.fp) == g->n &&
	    fwrite(g->field, 8, g->n, o.fp) == g->n;
	if (!ok) {
		frs_fail_errno("%s: write error", o.name);
		outfile_abort(&o);
		return -1;
	}
	return outfile_commit(&o);
}

/* 1 and the step if a matching checkpoint exists, 0 if none. */
static int load_checkpoint(struct gen *g, uint64_t *step)
{
	char params[512], have[512];
	unsigned char h[20];
	const char *name;
	uint32_t plen;
	FILE *fp = fopen(g->pr->checkpoint, "rb");
	int rc = -1;

	if (fp == NULL)
		return 0;
	name = g->pr->checkpoint;
	frdgen_describe(g->pr, params, sizeof params);
	if (io_read_exact(fp, name, h, sizeof h, "header") < 0)
		goto done;
	if (memcmp(h, CKPT_MAGIC, 8) != 0) {
		frs_fail("%s: not an frd-gen checkpoint", name);
		goto done;
	}
	plen = io_get_u32(h + 8);
	*step = io_get_u64(h + 12);
	if (plen >= sizeof have || io_read_exact(fp, name, have, plen,
	    "parameters") < 0) {
		frs_fail("%s: damaged checkpoint", name);
		goto done;
	}
	have[plen] = '\0';
	if (strcmp(have, params) != 0) {
		frs_fail("%s: checkpoint of another run (remove it to start "
		    "afresh)", name);
		goto done;
	}
	if (*step > g->n || io_read_exact(fp, name, g->val, g->n * 4,
	    "values") < 0 || io_read_exact(fp, name, g->field, g->n * 8,
	    "field") < 0)
		goto done;
	rc = 1;
done:
	fclose(fp);
	return rc;
}

/* ---- the generator ------------------------------------------------ */

/* Expected spacing of n values spread evenly: hexagonal in 2-D,
 * face-centred cubic in 3-D. */
static double spacing(const struct gen *g, uint64_t n)
{
	double vol = (double)g->w * g->h * g->d;

	if (g->pr->dims == 2)
		return sqrt(2.0 * vol / (sqrt(3.0) * (double)n));
	return cbrt(sqrt(2.0) * vol / (double)n);
}

static double radius_after(const struct gen *g, uint64_t inserted)
{
	double r = g->rtol;

	if (g->pr->reach > 0.0) {
		double adapt = g->pr->reach * spacing(g, inserted);
		r = adapt > r ? adapt : r;
	}
	return r;
}

int frdgen_run(const struct frdgen_params *par, struct frs_matrix *out,
    struct progress *prog)
{
	struct gen g;
	uint64_t start = 0;
	double last_save;

	if (frdgen_check(par) < 0)
		return -1;
	memset(out, 0, sizeof *out);
	if (gen_init(&g, par, out) < 0)
		goto fail;
	if (par->checkpoint != NULL) {
		int rc = load_checkpoint(&g, &start);
		if (rc < 0)
			goto fail;
	}
	if (start == 0)
		memset(g.val, 0xff, g.n * sizeof *g.val);
	rebuild_all(&g);
	last_save = progress_now();
	for (g.step = start; g.step < g.n; g.step++) {
		uint32_t c = 0;
		uint64_t k = frdgen_rank(par, g.step, g.n - g.step);
		if (select_cell(&g, k, &c) < 0)
			goto fail;
		g.val[c] = (uint32_t)g.step;
		g.field[c] = INFINITY;
		g.cx = c % g.w;
		g.cy = c / g.w % g.h;
		g.cz = c / g.w / g.h;
		add_force(&g, radius_after(&g, g.step + 1));
		if (prog != NULL && (g.step & 1023) == 0)
			progress_update(prog, g.step);
		if (par->checkpoint != NULL && (g.step & 4095) == 0 &&
		    progress_now() - last_save >= par->checkpoint_every) {
			if (save_checkpoint(&g, g.step + 1) < 0)
				goto fail;
			last_save = progress_now();
		}
	}
	gen_free(&g);
	return 0;
fail:
	gen_free(&g);
	frd_free(out);
	return -1;
}
