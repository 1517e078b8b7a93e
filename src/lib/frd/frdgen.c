#define _POSIX_C_SOURCE 200809L
#include "frd/frdgen.h"
#include "frd/frdgenint.h"
#include "base/err.h"
#include "base/mem.h"
#include "base/io.h"
#include "base/outfile.h"
#include "base/par.h"
#include "base/progress.h"
#include "base/rng.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* frd_toff, frd_tgap and frd_extent: one definition with the kernel. */
#include "../../../cl/frdgen.cl"

#define MAXLEV 40
#define DEFAULT_TOL 1e-2
#define DEFAULT_REACH 3.0
#define DEFAULT_CAP (1.0 / 3.0)

/* One level of the min-pyramid: level 0 holds the minimum of each tile of
 * cells, level L+1 the minimum of 2x2x2 nodes of level L. */
struct level {
	uint32_t nx, ny, nz;
	double *min;
	uint64_t *stamp;	/* last step that queued the node */
	unsigned char *arg;	/* level 0: where in its tile the minimum is */
};

struct gen {
	const struct frdgen_params *pr;
	struct frdgen_size sz;
	/* The field is stored tile by tile: each tile of tx*ty*tz cells is
	 * one contiguous block (one cache line per tile row in 2-D), so that
	 * adding a force and finding the new minimum of a tile work on the
	 * same few lines.  Cells past the matrix edge pad the last tiles and
	 * hold +inf, like taken cells. */
	double *field;
	uint32_t *val;
	double *table;		/* f by |dx|, |dy|, |dz| */
	uint32_t tx, ty, tz;	/* tile size */
	unsigned lx, ly, lz;	/* their log2 */
	uint32_t ntx, nty, ntz;	/* tiles per axis */
	size_t ts;		/* cells per tile */
	uint32_t *tlist;	/* tiles of the current window */
	unsigned char *changed;	/* per entry of tlist: its minimum moved */
	int32_t *ext;		/* x reach per window row */
	uint32_t *zc;		/* per tile: cells of force exactly 0 */
	uint32_t *zf;		/* what the Fenwick tree holds for each tile */
	uint64_t *fen;		/* Fenwick tree of zf over the tiles */
	size_t ntiles;
	int nlev;
	struct level lev[MAXLEV];
	uint32_t *dirty[2];
	uint32_t *ax[3];	/* tiles per axis of the current window */
	size_t ndirty[2], dcap;
	struct frdgen_sel sel;	/* the rank query */
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
	pr->force = FRDGEN_FORCE_POWER;
	pr->s = 1.0;
	pr->q = 4.0;
	pr->tol = DEFAULT_TOL;
	pr->reach = DEFAULT_REACH;
	pr->cap = DEFAULT_CAP;
	pr->taper = 1;
	pr->field = FRDGEN_FIELD_DOUBLE;
	pr->seed = 1;
	pr->checkpoint_every = 60.0;
}

int frdgen_check_size(unsigned dims, uint32_t w, uint32_t h, uint32_t d)
{
	uint64_t n = (uint64_t)w * h * d;

	if (dims != 2 && dims != 3)
		return frs_fail("%u dimensions: a matrix has 2 or 3", dims);
	if (w < 2 || h < 2 || d < 1 || (dims == 3 && d < 2) ||
	    (dims == 2 && d != 1))
		return frs_fail("a matrix needs at least 2 cells per side");
	if (n > UINT32_MAX)
		return frs_fail("%llu cells are more than 2^32 - 1 values",
		    (unsigned long long)n);
	return 0;
}

int frdgen_check(const struct frdgen_params *pr)
{
	if (frdgen_check_size(pr->dims, pr->w, pr->h, pr->d) < 0)
		return -1;
	if (!(pr->p > 0.0 && pr->p <= 1.0))
		return frs_fail("the share p = %g is outside (0, 1]", pr->p);
	if (pr->force != FRDGEN_FORCE_EXP && pr->force != FRDGEN_FORCE_POWER)
		return frs_fail("unknown force kind %d", (int)pr->force);
	if (!(pr->s > 0.0 && isfinite(pr->s)) || !(pr->q > 0.0 &&
	    isfinite(pr->q)))
		return frs_fail("force parameters s and q must be positive");
	if (!(pr->tol >= 0.0 && pr->tol < 1.0))
		return frs_fail("the force tolerance %g is outside [0, 1)", pr->tol);
	if (!(pr->reach >= 0.0 && isfinite(pr->reach)))
		return frs_fail("the reach %g is negative", pr->reach);
	if (!(pr->cap >= 0.0 && isfinite(pr->cap)))
		return frs_fail("the reach cap %g is negative", pr->cap);
	if (pr->field != FRDGEN_FIELD_DOUBLE && pr->field != FRDGEN_FIELD_INT32)
		return frs_fail("unknown field kind %d", (int)pr->field);
	return 0;
}

/* The shortest side: the authors' S. */
static uint32_t shortest_side(const struct frdgen_params *pr)
{
	uint32_t m = pr->w < pr->h ? pr->w : pr->h;
	return pr->dims == 3 && pr->d < m ? pr->d : m;
}

double frdgen_int_scale(const struct frdgen_params *pr)
{
	double half = (double)(shortest_side(pr) / 2);
	return fmin((double)(INT_MAX / 20), 1.0 / exp(-sqrt(2.0 * half)));
}

double frdgen_force(const struct frdgen_params *pr, double r)
{
	if (pr->field == FRDGEN_FIELD_INT32)
		return (double)(int32_t)(frdgen_int_scale(pr) *
		    exp(-sqrt(2.0 * r)));
	if (pr->force == FRDGEN_FORCE_POWER)
		return pow(1.0 + r / pr->s, -pr->q);
	return exp(-pow(r / pr->s, pr->q));
}

double frdgen_radius(const struct frdgen_params *pr)
{
	if (pr->field == FRDGEN_FIELD_INT32) {
		/* scale exp(-sqrt(2 r)) >= 1 up to r = ln(scale)^2 / 2; the
		 * margin only adds cells that get 0. */
		double l = log(frdgen_int_scale(pr));
		return l * l / 2.0 * (1.0 + 1e-9) + 1e-9;
	}
	if (pr->tol <= 0.0)
		return INFINITY;
	if (pr->force == FRDGEN_FORCE_POWER)
		return pr->s * (pow(pr->tol, -1.0 / pr->q) - 1.0);
	return pr->s * pow(log(1.0 / pr->tol), 1.0 / pr->q);
}

uint64_t frdgen_memory(const struct frdgen_params *pr)
{
	uint64_t n = (uint64_t)pr->w * pr->h * pr->d;
	uint64_t t = ((uint64_t)pr->w / 2 + 1) * (pr->h / 2 + 1) *
	    (pr->d / 2 + 1);
	/* field (with the padding of partial tiles), values, table, tiles
	 * and pyramid */
	uint64_t pad = ((uint64_t)pr->w + 8) * (pr->h + 8) * (pr->d + 4);
	return pad * 8 + n * 4 + t * 8 + n / 4 + (1 << 20);
}

void frdgen_describe(const struct frdgen_params *pr, char *buf, size_t n)
{
	if (pr->field == FRDGEN_FIELD_INT32) {
		snprintf(buf, n, "generator=frd-gen\nk=%u\nsize=%ux%ux%u\n"
		    "field=int32\np=%.17g\nscale=%.17g\nseed=%llu\n", pr->dims,
		    pr->w, pr->h, pr->d, pr->p, frdgen_int_scale(pr),
		    (unsigned long long)pr->seed);
		return;
	}
	snprintf(buf, n, "generator=frd-gen\nk=%u\nsize=%ux%ux%u\n"
	    "field=double\nforce=%s\np=%.17g\ns=%.17g\nq=%.17g\n"
	    "tol=%.17g\nreach=%.17g\ncap=%.17g\ncutoff=%s\nseed=%llu\n",
	    pr->dims, pr->w, pr->h, pr->d,
	    pr->force == FRDGEN_FORCE_POWER ? "power" : "exp", pr->p, pr->s,
	    pr->q, pr->tol, pr->reach, pr->cap, pr->taper ? "taper" : "hard",
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

uint64_t frdgen_zerorank(const struct frdgen_params *pr, uint64_t step,
    uint64_t z)
{
	uint64_t r = (uint64_t)(frs_rand01(pr->seed, FRS_STREAM_FRD_DRAW, step) *
	    (double)z);
	return r < z ? r : z - 1;
}

void frdgen_tile_shape(unsigned dims, uint32_t t[3])
{
	/* Tile shapes measured fastest (16 x 8 beat 8x8, 32x4, 64x2 at
	 * 512^2 and 1024^2): rows long enough for vector adds, few enough
	 * rows for little loop overhead.  At most 256 cells (arg is a byte). */
	t[0] = dims == 2 ? 16 : 8;
	t[1] = dims == 2 ? 8 : 4;
	t[2] = dims == 2 ? 1 : 4;
}

uint64_t frdgen_cellorder(const struct frdgen_params *pr, uint32_t c)
{
	uint32_t t[3], x = c % pr->w, y = c / pr->w % pr->h, z = c / pr->w / pr->h;
	uint64_t ntx, nty, tile, local;

	frdgen_tile_shape(pr->dims, t);
	ntx = (pr->w + t[0] - 1) / t[0];
	nty = (pr->h + t[1] - 1) / t[1];
	tile = ((uint64_t)(z / t[2]) * nty + y / t[1]) * ntx + x / t[0];
	local = ((uint64_t)(z % t[2]) * t[1] + y % t[1]) * t[0] + x % t[0];
	return tile << 16 | local;
}

/* ---- setup -------------------------------------------------------- */

void frdgen_size(struct frdgen_size *z, const struct frdgen_params *pr)
{
	z->w = pr->w;
	z->h = pr->h;
	z->d = pr->d;
	z->n = (size_t)pr->w * pr->h * pr->d;
	z->hw = z->w / 2;
	z->hh = z->h / 2;
	z->hd = z->d / 2;
	z->rtol = frdgen_radius(pr);
	z->rmax = sqrt((double)z->hw * z->hw + (double)z->hh * z->hh +
	    (double)z->hd * z->hd);
}

static size_t fidx(const struct gen *g, uint32_t x, uint32_t y, uint32_t z)
{
	size_t t = ((size_t)(z >> g->lz) * g->nty + (y >> g->ly)) * g->ntx +
	    (x >> g->lx);
	return t * g->ts + (((z & (g->tz - 1)) << g->ly | (y & (g->ty - 1))) <<
	    g->lx | (x & (g->tx - 1)));
}

double *frdgen_table(const struct frdgen_params *pr)
{
	uint32_t hw = pr->w / 2, hh = pr->h / 2, hd = pr->d / 2;
	size_t nt = (size_t)(hw + 1) * (hh + 1) * (hd + 1);
	double *t = malloc(nt * sizeof *t);

	if (t == NULL) {
		frs_fail("out of memory for the force table");
		return NULL;
	}
	for (uint32_t z = 0; z <= hd; z++)
		for (uint32_t y = 0; y <= hh; y++)
			for (uint32_t x = 0; x <= hw; x++) {
				double r = sqrt((double)x * x + (double)y * y +
				    (double)z * z);
				t[((size_t)z * (hh + 1) + y) * (hw + 1) + x] =
				    frdgen_force(pr, r);
			}
	return t;
}

static int make_levels(struct gen *g)
{
	uint32_t nx = g->ntx, ny = g->nty, nz = g->ntz;
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
	g->dirty[0] = malloc(total * sizeof(uint32_t));
	g->dirty[1] = malloc(total * sizeof(uint32_t));
	g->lev[0].arg = calloc((size_t)g->ntx * g->nty * g->ntz, 1);
	g->tlist = malloc((size_t)g->ntx * g->nty * g->ntz * sizeof(uint32_t));
	g->changed = malloc((size_t)g->ntx * g->nty * g->ntz);
	g->ext = malloc((size_t)(2 * g->sz.hh + 1) * (2 * g->sz.hd + 1) *
	    sizeof *g->ext);
	g->ntiles = (size_t)g->ntx * g->nty * g->ntz;
	g->zc = calloc(g->ntiles, sizeof *g->zc);
	g->zf = calloc(g->ntiles, sizeof *g->zf);
	g->fen = calloc(g->ntiles + 1, sizeof *g->fen);
	g->ax[0] = malloc(g->ntx * sizeof(uint32_t));
	g->ax[1] = malloc(g->nty * sizeof(uint32_t));
	g->ax[2] = malloc(g->ntz * sizeof(uint32_t));
	if (g->dirty[0] == NULL || g->dirty[1] == NULL || !g->lev[0].arg ||
	    !g->tlist || !g->changed || !g->ax[0] || !g->ax[1] || !g->ax[2] ||
	    !g->ext || !g->zc || !g->zf || !g->fen)
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
		free(g->lev[i].arg);
	}
	MEM_FREE(g->dirty[0], g->dirty[1], g->ax[0], g->ax[1], g->ax[2],
	    g->tlist, g->changed, g->ext, g->zc, g->zf, g->fen);
	frdgen_sel_free(&g->sel);
}

unsigned frdgen_log2u(uint32_t v)
{
	unsigned l = 0;
	while ((1u << l) < v)
		l++;
	return l;
}

/* Every cell free (0), padding cells +inf. */
static void init_field(struct gen *g)
{
	size_t total = (size_t)g->ntx * g->nty * g->ntz * g->ts;

	for (size_t i = 0; i < total; i++)
		g->field[i] = INFINITY;
	for (uint32_t z = 0; z < g->sz.d; z++)
		for (uint32_t y = 0; y < g->sz.h; y++)
			for (uint32_t x = 0; x < g->sz.w; x++)
				g->field[fidx(g, x, y, z)] = 0.0;
}

static int gen_init(struct gen *g, const struct frdgen_params *pr,
    struct frs_matrix *out)
{
	char params[512];
	size_t total;

	memset(g, 0, sizeof *g);
	g->pr = pr;
	frdgen_size(&g->sz, pr);
	{
		uint32_t t[3];
		frdgen_tile_shape(pr->dims, t);
		g->tx = t[0];
		g->ty = t[1];
		g->tz = t[2];
	}
	g->lx = frdgen_log2u(g->tx);
	g->ly = frdgen_log2u(g->ty);
	g->lz = frdgen_log2u(g->tz);
	g->ts = (size_t)g->tx * g->ty * g->tz;
	g->ntx = (g->sz.w + g->tx - 1) / g->tx;
	g->nty = (g->sz.h + g->ty - 1) / g->ty;
	g->ntz = (g->sz.d + g->tz - 1) / g->tz;
	/* Everything together, before anything exists: an impossible size
	 * is refused with the figure it needs. */
	if (mem_check("matrix generation", frdgen_memory(pr), 1) < 0)
		return -1;
	frdgen_describe(pr, params, sizeof params);
	if (frd_alloc(out, pr->dims, g->sz.w, g->sz.h, g->sz.d, params) < 0)
		return -1;
	g->val = out->v;
	total = (size_t)g->ntx * g->nty * g->ntz * g->ts;
	g->field = malloc(total * sizeof *g->field);
	if (g->field == NULL)
		return frs_fail("out of memory for a %zu-cell force field", g->sz.n);
	g->table = frdgen_table(pr);
	if (g->table == NULL || make_levels(g) < 0)
		return -1;
	return 0;
}

/* ---- the min-pyramid ---------------------------------------------- */

/* Minimum of a tile and the first cell that holds it. */
static double block_min(const double *b, size_t n, unsigned char *arg)
{
	double m[8] = { INFINITY, INFINITY, INFINITY, INFINITY, INFINITY,
	    INFINITY, INFINITY, INFINITY }, best;
	size_t i;

	/* Eight running minima: vectorises, and the order of a minimum does
	 * not change its value. */
	for (i = 0; i + 8 <= n; i += 8)
		for (size_t k = 0; k < 8; k++)
			m[k] = b[i + k] < m[k] ? b[i + k] : m[k];
	for (; i < n; i++)
		m[0] = b[i] < m[0] ? b[i] : m[0];
	best = m[0];
	for (int k = 1; k < 8; k++)
		best = m[k] < best ? m[k] : best;
	for (i = 0; i < n && b[i] != best; i++)
		;
	*arg = (unsigned char)(i < n ? i : 0);
	return best;
}

static double tile_rescan(struct gen *g, size_t t)
{
	const double *b = g->field + t * g->ts;
	double m = block_min(b, g->ts, &g->lev[0].arg[t]);
	uint32_t z = 0;

	if (m == 0.0)
		for (size_t i = 0; i < g->ts; i++)
			z += b[i] == 0.0;
	g->zc[t] = z;
	return g->lev[0].min[t] = m;
}

/* ---- zero cells: counts per tile in a Fenwick tree ----------------- */

void frdgen_fen_add(uint64_t *fen, size_t n, size_t t, int64_t d)
{
	for (size_t i = t + 1; i <= n; i += i & (~i + 1))
		fen[i] = (uint64_t)((int64_t)fen[i] + d);
}

static void fen_sync(struct gen *g, size_t t)
{
	if (g->zc[t] != g->zf[t]) {
		frdgen_fen_add(g->fen, g->ntiles, t,
		    (int64_t)g->zc[t] - (int64_t)g->zf[t]);
		g->zf[t] = g->zc[t];
	}
}

uint64_t frdgen_fen_total(const uint64_t *fen, size_t n)
{
	uint64_t s = 0;
	for (size_t i = n; i > 0; i -= i & (~i + 1))
		s += fen[i];
	return s;
}

size_t frdgen_fen_find(const uint64_t *fen, size_t n, uint64_t *r)
{
	size_t pos = 0, step = 1;

	while (step * 2 <= n)
		step *= 2;
	for (; step > 0; step /= 2)
		if (pos + step <= n && fen[pos + step] <= *r) {
			pos += step;
			*r -= fen[pos];
		}
	return pos;
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

static int tiles_task(void *ctx, uint64_t b, uint64_t e)
{
	struct gen *g = ctx;
	for (uint64_t t = b; t < e; t++)
		tile_rescan(g, (size_t)t);
	return 0;
}

/* Recompute every tile and level (start, resume). */
static void rebuild_all(struct gen *g)
{
	frs_parallel((uint64_t)g->ntx * g->nty * g->ntz, 256, tiles_task, g,
	    NULL);
	for (size_t t = 0; t < g->ntiles; t++)
		fen_sync(g, t);
	for (int l = 1; l < g->nlev; l++) {
		struct level *v = &g->lev[l];
		for (uint32_t z = 0; z < v->nz; z++)
			for (uint32_t y = 0; y < v->ny; y++)
				for (uint32_t x = 0; x < v->nx; x++)
					v->min[((size_t)z * v->ny + y) * v->nx + x] =
					    node_min(g, l, x, y, z);
	}
}

/* Tiles along one axis that a window [c - ext, c + ext] touches. */
static uint32_t axis_tiles(uint32_t c, uint32_t ext, uint32_t size,
    uint32_t ts, uint32_t *out)
{
	uint32_t nt = (size + ts - 1) / ts, k = 0, first, last;

	if (2 * (uint64_t)ext + 1 < size) {
		first = (c + size - ext) % size / ts;
		last = (c + ext) % size / ts;
		if (first <= last && (c + size - ext) % size <= (c + ext) % size) {
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

/* Bring the levels above the changed tiles up to date. */
static void update_levels(struct gen *g)
{
	int side = 0;

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

void frdgen_window(const struct frdgen_params *pr,
    const struct frdgen_size *z, uint32_t tx, double r, struct frdgen_win *wd)
{
	wd->e = r >= (double)UINT32_MAX ? UINT32_MAX : (uint32_t)floor(r);
	wd->r2 = r >= z->rmax ? INFINITY : r * r;
	/* The taper: f(R) off every force inside R (none past the torus). */
	wd->sub = pr->field == FRDGEN_FIELD_DOUBLE && pr->taper &&
	    wd->r2 < INFINITY ? frdgen_force(pr, r) : 0.0;
	wd->fast = 2 * (uint64_t)wd->e + 1 + 2 * tx <= z->w;
	wd->ey = umin(wd->e, z->hh);
	wd->ez = umin(wd->e, z->hd);
}

/* The x reach of every row (dy, dz) of the window, once per insertion. */
static void window_extents(struct gen *g, struct frdgen_win *wd)
{
	uint32_t ny = 2 * wd->ey + 1;

	for (int64_t dz = -(int64_t)wd->ez; dz <= (int64_t)wd->ez; dz++)
		for (int64_t dy = -(int64_t)wd->ey; dy <= (int64_t)wd->ey; dy++) {
			double rr = wd->r2 - (double)(dy * dy) - (double)(dz * dz);
			g->ext[(size_t)(dz + wd->ez) * ny + (size_t)(dy + wd->ey)] =
			    rr < 0.0 ? -1 : (int32_t)frd_extent(rr, g->sz.hw);
		}
}

/* Add the row of forces at offsets dy, dz to cells x0 .. x1 of one tile
 * row. */
static void add_tile_row(struct gen *g, const struct frdgen_win *wd,
    double *row, uint32_t x0, uint32_t x1, int64_t dy, int64_t dz)
{
	const double *t;
	int64_t e, dx0, klo, khi, kmid;

	if ((dy < 0 ? -dy : dy) > (int64_t)wd->ey ||
	    (dz < 0 ? -dz : dz) > (int64_t)wd->ez)
		return;
	e = g->ext[(size_t)(dz + wd->ez) * (2 * wd->ey + 1) +
	    (size_t)(dy + wd->ey)];
	if (e < 0)
		return;
	t = g->table + ((size_t)(dz < 0 ? -dz : dz) * (g->sz.hh + 1) +
	    (size_t)(dy < 0 ? -dy : dy)) * (g->sz.hw + 1);
	if (!wd->fast) {
		for (uint32_t x = x0; x <= x1; x++) {
			int64_t dx = frd_toff(x, g->cx, g->sz.w);
			if ((dx < 0 ? -dx : dx) <= e)
				row[x - x0] += frdgen_add(t[dx < 0 ? -dx : dx],
				    wd->sub);
		}
		return;
	}
	/* Fast: the cells within reach are one run of offsets dx0 + k.  A
	 * seam of the torus inside the tile would break the run, but 2e + 1
	 * is two tiles shorter than the row, so cells past a seam are out of
	 * reach and fall outside [klo, khi]. */
	dx0 = frd_toff(x0, g->cx, g->sz.w);
	klo = -e - dx0 > 0 ? -e - dx0 : 0;
	khi = e - dx0 < (int64_t)(x1 - x0) ? e - dx0 : (int64_t)(x1 - x0);
	kmid = -dx0 < klo ? klo : -dx0 > khi + 1 ? khi + 1 : -dx0;
	for (int64_t k = klo; k < kmid; k++)
		row[k] += frdgen_add(t[-dx0 - k], wd->sub);
	for (int64_t k = kmid; k <= khi; k++)
		row[k] += frdgen_add(t[dx0 + k], wd->sub);
}

/* Add the force to one tile and report whether its minimum moved. */
static int add_tile(struct gen *g, const struct frdgen_win *wd, uint32_t t)
{
	uint32_t tx = t % g->ntx, ty = t / g->ntx % g->nty, tz = t / g->ntx / g->nty;
	uint32_t x0 = tx * g->tx, x1 = umin(x0 + g->tx, g->sz.w) - 1;
	uint32_t y0 = ty * g->ty, y1 = umin(y0 + g->ty, g->sz.h) - 1;
	uint32_t z0 = tz * g->tz, z1 = umin(z0 + g->tz, g->sz.d) - 1;
	uint32_t gx = frd_tgap(g->cx, x0, x1, g->sz.w);
	uint32_t gy = frd_tgap(g->cy, y0, y1, g->sz.h);
	uint32_t gz = frd_tgap(g->cz, z0, z1, g->sz.d);
	double *blk = g->field + (size_t)t * g->ts, old = g->lev[0].min[t];
	unsigned a = g->lev[0].arg[t];
	int64_t ax, ay, az;

	if ((double)gx * gx + (double)gy * gy + (double)gz * gz > wd->r2)
		return 0;	/* out of reach */
	for (uint32_t z = z0; z <= z1; z++)
		for (uint32_t y = y0; y <= y1; y++)
			add_tile_row(g, wd, blk + (((z - z0) << g->ly | (y - y0)) <<
			    g->lx), x0, x1, frd_toff(y, g->cy, g->sz.h),
			    frd_toff(z, g->cz, g->sz.d));
	/* Forces only grow: if the cell holding the minimum got nothing
	 * (and is not the one just taken), the minimum stays. */
	ax = frd_toff(x0 + (a & (g->tx - 1)), g->cx, g->sz.w);
	ay = frd_toff(y0 + (a >> g->lx & (g->ty - 1)), g->cy, g->sz.h);
	az = frd_toff(z0 + (a >> (g->lx + g->ly)), g->cz, g->sz.d);
	if ((double)(ax * ax + ay * ay + az * az) > wd->r2 && blk[a] == old &&
	    old != 0.0)	/* zero counts must stay exact */
		return 0;
	return tile_rescan(g, t) != old;
}

struct tilejob {
	struct gen *g;
	const struct frdgen_win *wd;
};

static int tiles_add_task(void *ctx, uint64_t b, uint64_t e)
{
	struct tilejob *j = ctx;
	for (uint64_t i = b; i < e; i++)
		j->g->changed[i] = (unsigned char)add_tile(j->g, j->wd,
		    j->g->tlist[i]);
	return 0;
}

/* Add the force of the value just inserted at (cx, cy, cz) within radius
 * r, then bring the pyramid up to date. */
static void add_force(struct gen *g, double r)
{
	struct frdgen_win wd;
	uint32_t size[3] = { g->sz.w, g->sz.h, g->sz.d };
	uint32_t ts[3] = { g->tx, g->ty, g->tz };
	uint32_t c[3] = { g->cx, g->cy, g->cz }, cnt[3];
	size_t nt = 0;

	frdgen_window(g->pr, &g->sz, g->tx, r, &wd);
	window_extents(g, &wd);
	for (int i = 0; i < 3; i++)
		cnt[i] = axis_tiles(c[i], umin(wd.e, size[i]), size[i], ts[i],
		    g->ax[i]);
	for (uint32_t k = 0; k < cnt[2]; k++)
		for (uint32_t j = 0; j < cnt[1]; j++)
			for (uint32_t i = 0; i < cnt[0]; i++)
				g->tlist[nt++] = (g->ax[2][k] * g->nty + g->ax[1][j]) *
				    g->ntx + g->ax[0][i];
	if (nt >= 16 && frs_threads() > 1) {
		struct tilejob j = { g, &wd };
		frs_team_run(nt, nt >= 1024 ? 64 : 8, tiles_add_task, &j);
	} else {
		for (size_t i = 0; i < nt; i++)
			g->changed[i] = (unsigned char)add_tile(g, &wd, g->tlist[i]);
	}
	g->ndirty[0] = 0;
	for (size_t i = 0; i < nt; i++) {
		fen_sync(g, g->tlist[i]);
		if (g->changed[i])
			push_dirty(g, 0, 0, g->tlist[i]);
	}
	update_levels(g);
}

/* ---- the rank query: the K-th smallest free cell ------------------ */

/* Room for one more item in a growing array. */
static int item_room(struct frdgen_item **a, size_t n, size_t *cap)
{
	if (n == *cap) {
		size_t ncap = *cap ? 2 * *cap : 256;
		struct frdgen_item *na = realloc(*a, ncap * sizeof *na);
		if (na == NULL)
			return frs_fail("out of memory in the rank query");
		*a = na;
		*cap = ncap;
	}
	return 0;
}

int frdgen_push(struct frdgen_sel *s, double v, int lev, uint32_t idx)
{
	size_t i;

	if (item_room(&s->heap, s->nheap, &s->hcap) < 0)
		return -1;
	i = s->nheap++;
	while (i > 0 && s->heap[(i - 1) / 2].v > v) {
		s->heap[i] = s->heap[(i - 1) / 2];
		i = (i - 1) / 2;
	}
	s->heap[i] = (struct frdgen_item){ v, lev, idx };
	return 0;
}

static struct frdgen_item heap_pop(struct frdgen_sel *s)
{
	struct frdgen_item top = s->heap[0], last = s->heap[--s->nheap];
	size_t i = 0;

	for (;;) {
		size_t c = 2 * i + 1;
		if (c >= s->nheap)
			break;
		if (c + 1 < s->nheap && s->heap[c + 1].v < s->heap[c].v)
			c++;
		if (s->heap[c].v >= last.v)
			break;
		s->heap[i] = s->heap[c];
		i = c;
	}
	if (s->nheap > 0)
		s->heap[i] = last;
	return top;
}

static int emit(struct frdgen_sel *s, struct frdgen_item it)
{
	if (item_room(&s->emit, s->nemit, &s->ecap) < 0)
		return -1;
	s->emit[s->nemit++] = it;
	return 0;
}

static int cmp_key(const void *a, const void *b)
{
	const uint64_t *x = a, *y = b;
	if (x[0] != y[0])
		return x[0] < y[0] ? -1 : 1;
	return x[1] < y[1] ? -1 : x[1] > y[1];
}

/* Pick the (rank)-th (0-based) cell of the tie group emit[a ..] by key. */
static int pick_in_group(struct frdgen_sel *s, const struct frdgen_params *pr,
    uint64_t step, size_t a, size_t rank, uint32_t *c)
{
	size_t m = s->nemit - a;

	if (m == 1) {
		*c = s->emit[a].idx;
		return 0;
	}
	if (2 * m > s->kcap) {
		uint64_t *nk = realloc(s->keys, 2 * m * sizeof *nk);
		if (nk == NULL)
			return frs_fail("out of memory in the rank query");
		s->keys = nk;
		s->kcap = 2 * m;
	}
	for (size_t i = 0; i < m; i++) {
		s->keys[2 * i] = frdgen_tiekey(pr, step, s->emit[a + i].idx);
		s->keys[2 * i + 1] = s->emit[a + i].idx;
	}
	qsort(s->keys, m, 2 * sizeof *s->keys, cmp_key);
	*c = (uint32_t)s->keys[2 * rank + 1];
	return 0;
}

int frdgen_select(struct frdgen_sel *s, const struct frdgen_params *pr,
    uint64_t step, uint64_t k, struct frdgen_item root,
    frdgen_expand_fn *expand, void *ctx, uint32_t *c)
{
	double v;
	size_t a;

	s->nheap = s->nemit = 0;
	if (frdgen_push(s, root.v, root.lev, root.idx) < 0)
		return -1;
	/* Best-first: cells come out in nondecreasing force. */
	while (s->nheap > 0) {
		struct frdgen_item it;
		if (s->nemit >= k && s->heap[0].v > s->emit[k - 1].v)
			break;
		it = heap_pop(s);
		if ((it.lev < 0 ? emit(s, it) : expand(ctx, it.lev, it.idx)) < 0)
			return -1;
	}
	if (s->nemit < k)
		return frs_fail("internal error: %zu free cells found, rank %llu",
		    s->nemit, (unsigned long long)k);
	v = s->emit[k - 1].v;
	for (a = k - 1; a > 0 && s->emit[a - 1].v == v; a--)
		;
	while (s->nemit > k && s->emit[s->nemit - 1].v > v)
		s->nemit--;
	return pick_in_group(s, pr, step, a, k - 1 - a, c);
}

void frdgen_sel_free(struct frdgen_sel *s)
{
	free(s->heap);
	free(s->emit);
	free(s->keys);
}

/* Push the children of a node: nodes of the level below, or cells. */
static int expand(void *ctx, int lev, uint32_t idx)
{
	struct gen *g = ctx;
	const struct level *l = &g->lev[lev];
	uint32_t x = idx % l->nx, y = idx / l->nx % l->ny, z = idx / l->nx / l->ny;

	if (lev == 0) {
		const double *blk = g->field + (size_t)idx * g->ts;
		uint32_t x0 = x * g->tx, y0 = y * g->ty, z0 = z * g->tz;
		for (uint32_t k = z0; k < umin(z0 + g->tz, g->sz.d); k++)
			for (uint32_t j = y0; j < umin(y0 + g->ty, g->sz.h); j++)
				for (uint32_t i = x0; i < umin(x0 + g->tx, g->sz.w); i++) {
					double v = blk[((k - z0) << g->ly | (j - y0)) <<
					    g->lx | (i - x0)];
					uint32_t c = (k * g->sz.h + j) * g->sz.w + i;
					if (v < INFINITY &&
					    frdgen_push(&g->sel, v, -1, c) < 0)
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
				    frdgen_push(&g->sel, l->min[ci], lev - 1, ci) < 0)
					return -1;
			}
	return 0;
}

/* The r-th zero cell of the matrix, in the order of frdgen_cellorder. */
static uint32_t zero_cell(const struct gen *g, uint64_t r)
{
	size_t t = frdgen_fen_find(g->fen, g->ntiles, &r);
	const double *b = g->field + t * g->ts;
	uint32_t tx = (uint32_t)(t % g->ntx), ty = (uint32_t)(t / g->ntx % g->nty);
	uint32_t tz = (uint32_t)(t / g->ntx / g->nty);

	for (size_t i = 0; i < g->ts; i++)
		if (b[i] == 0.0 && r-- == 0) {
			uint32_t x = tx * g->tx + (uint32_t)(i & (g->tx - 1));
			uint32_t y = ty * g->ty + (uint32_t)(i >> g->lx & (g->ty - 1));
			uint32_t z = tz * g->tz + (uint32_t)(i >> (g->lx + g->ly));
			return (z * g->sz.h + y) * g->sz.w + x;
		}
	return 0;	/* not reached: the counts are exact */
}

/* The K-th smallest free cell in the order (force, tie key). */
static int select_cell(struct gen *g, uint64_t k, uint32_t *c)
{
	const struct level *top = &g->lev[g->nlev - 1];
	struct frdgen_item root = { top->min[0], g->nlev - 1, 0 };

	/* Rank k among cells no force has reached: one of them, uniformly. */
	if (top->min[0] == 0.0) {
		uint64_t z = frdgen_fen_total(g->fen, g->ntiles);
		if (k <= z) {
			*c = zero_cell(g, frdgen_zerorank(g->pr, g->step, z));
			return 0;
		}
	}
	return frdgen_select(&g->sel, g->pr, g->step, k, root, expand, g, c);
}

/* ---- checkpoints -------------------------------------------------- */

/* The field in its tiled layout, padding included. */
static size_t field_cells(const struct gen *g)
{
	return (size_t)g->ntx * g->nty * g->ntz * g->ts;
}

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
	    fwrite(g->val, 4, g->sz.n, o.fp) == g->sz.n &&
	    fwrite(g->field, 8, field_cells(g), o.fp) == field_cells(g);
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
	if (*step > g->sz.n || io_read_exact(fp, name, g->val, g->sz.n * 4,
	    "values") < 0 || io_read_exact(fp, name, g->field,
	    field_cells(g) * 8, "field") < 0)
		goto done;
	rc = 1;
done:
	fclose(fp);
	return rc;
}

/* ---- the generator ------------------------------------------------ */

/* Expected spacing of n values spread evenly: hexagonal in 2-D,
 * face-centred cubic in 3-D. */
static double spacing(const struct frdgen_params *pr, uint64_t n)
{
	double vol = (double)pr->w * pr->h * pr->d;

	if (pr->dims == 2)
		return sqrt(2.0 * vol / (sqrt(3.0) * (double)n));
	return cbrt(sqrt(2.0) * vol / (double)n);
}

double frdgen_radius_after(const struct frdgen_params *pr, double rtol,
    uint64_t inserted)
{
	double r = rtol;

	if (pr->field == FRDGEN_FIELD_INT32)
		return r;
	if (pr->reach > 0.0) {
		double adapt = pr->reach * spacing(pr, inserted);
		r = adapt > r ? adapt : r;
	}
	if (pr->cap > 0.0) {
		double cap = pr->cap * (double)shortest_side(pr);
		r = r > cap ? fmax(cap, rtol) : r;
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
	if (start == 0) {
		memset(g.val, 0xff, g.sz.n * sizeof *g.val);
		init_field(&g);
	}
	rebuild_all(&g);
	if (frs_team_start() < 0)
		goto fail;
	last_save = progress_now();
	for (g.step = start; g.step < g.sz.n; g.step++) {
		uint32_t c = 0;
		uint64_t k = frdgen_rank(par, g.step, g.sz.n - g.step);
		if (select_cell(&g, k, &c) < 0)
			goto fail;
		g.val[c] = (uint32_t)g.step;
		g.cx = c % g.sz.w;
		g.cy = c / g.sz.w % g.sz.h;
		g.cz = c / g.sz.w / g.sz.h;
		g.field[fidx(&g, g.cx, g.cy, g.cz)] = INFINITY;
		add_force(&g, frdgen_radius_after(par, g.sz.rtol, g.step + 1));
		if (prog != NULL && (g.step & 1023) == 0)
			progress_update(prog, g.step);
		if (par->checkpoint != NULL && (g.step & 4095) == 0 &&
		    progress_now() - last_save >= par->checkpoint_every) {
			if (save_checkpoint(&g, g.step + 1) < 0)
				goto fail;
			last_save = progress_now();
		}
	}
	frs_team_stop();
	gen_free(&g);
	return 0;
fail:
	frs_team_stop();
	gen_free(&g);
	frd_free(out);
	return -1;
}
