/* The CPU generator of Forced Random Dithering matrices (frdgen.h). */
#define _POSIX_C_SOURCE 200809L
#include "cli/cli.h"
#include "frd-gen/frdgen.h"
#include "frd-gen/frdgenint.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* frd_toff, frd_tgap and frd_extent: one definition with the kernel
 * (defs.cl: the common subset's FRS_FN). */
#include "../../cl/defs.cl"
#include "../../cl/frdgen.cl"

#define MAXLEV 40

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

static size_t fidx(const struct gen *g, uint32_t x, uint32_t y, uint32_t z)
{
	size_t t = ((size_t)(z >> g->lz) * g->nty + (y >> g->ly)) * g->ntx +
	    (x >> g->lx);
	return t * g->ts + (((z & (g->tz - 1)) << g->ly | (y & (g->ty - 1))) <<
	    g->lx | (x & (g->tx - 1)));
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
			return cli_fail("out of memory for the min-pyramid");
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
		return cli_fail("out of memory for the min-pyramid");
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
	free(g->dirty[0]), free(g->dirty[1]);
	free(g->ax[0]), free(g->ax[1]), free(g->ax[2]);
	free(g->tlist), free(g->changed), free(g->ext);
	free(g->zc), free(g->zf), free(g->fen);
	frdgen_sel_free(&g->sel);
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
	frs_error err;
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
	/* The memory ceiling is the caller's, for everything together
	 * before anything exists (frd-gen's check of frdgen_memory, the
	 * option -s named in its refusal). */
	frdgen_describe(pr, params, sizeof params);
	if (frs_matrix_alloc(out, pr->dims, g->sz.w, g->sz.h, g->sz.d,
	    params, &err) != FRS_OK)
		return cli_fail("%s", err.message);
	g->val = out->v;
	total = (size_t)g->ntx * g->nty * g->ntz * g->ts;
	g->field = malloc(total * sizeof *g->field);
	if (g->field == NULL)
		return cli_fail("out of memory for a %zu-cell force field", g->sz.n);
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

static void fen_sync(struct gen *g, size_t t)
{
	if (g->zc[t] != g->zf[t]) {
		frdgen_fen_add(g->fen, g->ntiles, t,
		    (int64_t)g->zc[t] - (int64_t)g->zf[t]);
		g->zf[t] = g->zc[t];
	}
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
	cli_parallel((uint64_t)g->ntx * g->nty * g->ntz, 256, tiles_task, g,
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
	if (nt >= 16 && cli_threads() > 1) {
		struct tilejob j = { g, &wd };
		cli_team_run(nt, nt >= 1024 ? 64 : 8, tiles_add_task, &j);
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

/*
 * The checkpoint, frd-gen's own file: magic CKPT_MAGIC, the parameter
 * text's length L (4 bytes) and the step (8), little-endian; the
 * parameter text, L bytes; the values and the field as the run holds
 * them (host order: a checkpoint goes on on the machine that wrote it).
 */
#define CKPT_MAGIC "FRDCKPT1"

static void ck_put(unsigned char *p, uint64_t v, int bytes)
{
	for (int i = 0; i < bytes; i++)
		p[i] = (unsigned char)(v >> (8 * i));
}

static uint64_t ck_get(const unsigned char *p, int bytes)
{
	uint64_t v = 0;

	for (int i = bytes - 1; i >= 0; i--)
		v = v << 8 | p[i];
	return v;
}

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
	ck_put(h + 8, plen, 4);
	ck_put(h + 12, step, 8);
	if (outfile_open(&o, g->pr->checkpoint, 1) < 0)
		return -1;
	ok = fwrite(h, 1, sizeof h, o.fp) == sizeof h &&
	    fwrite(params, 1, plen, o.fp) == plen &&
	    fwrite(g->val, 4, g->sz.n, o.fp) == g->sz.n &&
	    fwrite(g->field, 8, field_cells(g), o.fp) == field_cells(g);
	if (!ok) {
		cli_fail_errno("%s: write error", o.name);
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
	if (cli_read_exact(fp, name, h, sizeof h, "header") < 0)
		goto done;
	if (memcmp(h, CKPT_MAGIC, 8) != 0) {
		cli_fail("%s: not an frd-gen checkpoint", name);
		goto done;
	}
	plen = (uint32_t)ck_get(h + 8, 4);
	*step = ck_get(h + 12, 8);
	if (plen >= sizeof have || cli_read_exact(fp, name, have, plen,
	    "parameters") < 0) {
		cli_fail("%s: damaged checkpoint", name);
		goto done;
	}
	have[plen] = '\0';
	if (strcmp(have, params) != 0) {
		cli_fail("%s: checkpoint of another run (remove it to start "
		    "afresh)", name);
		goto done;
	}
	if (*step > g->sz.n || cli_read_exact(fp, name, g->val, g->sz.n * 4,
	    "values") < 0 || cli_read_exact(fp, name, g->field,
	    field_cells(g) * 8, "field") < 0)
		goto done;
	rc = 1;
done:
	fclose(fp);
	return rc;
}

/* ---- the generator ------------------------------------------------ */

int frdgen_run(const struct frdgen_params *par, struct frs_matrix *out,
    struct cli_task *task)
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
	if (cli_team_start() < 0)
		goto fail;
	last_save = cli_now();
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
		if (task != NULL && (g.step & 1023) == 0)
			cli_task_update(task, g.step);
		if (par->checkpoint != NULL && (g.step & 4095) == 0 &&
		    cli_now() - last_save >= par->checkpoint_every) {
			if (save_checkpoint(&g, g.step + 1) < 0)
				goto fail;
			last_save = cli_now();
		}
	}
	cli_team_stop();
	gen_free(&g);
	return 0;
fail:
	cli_team_stop();
	gen_free(&g);
	frs_matrix_free(out);
	return -1;
}
