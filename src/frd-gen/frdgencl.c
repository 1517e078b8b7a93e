/*
 * Forced Random Dithering with OpenCL: the host side of cl/frdgen.cl.
 *
 * What has to match frdgen.c bit for bit, and how:
 * - the field: the kernel adds, per insertion and cell, at most one entry
 *   of the same force table (frdgen_table), to the same cells (the window
 *   of frdgen_window; the rules of frdgen.c's add_force are repeated in
 *   the kernel), in insertion order: so every cell holds the same double
 *   as on the CPU;
 * - the selection: the K-th smallest free cell in the order (force, tie
 *   key, cell), K = frdgen_rank, found by the CPU's frdgen_select
 *   best-first over a min-tree of the tile minima that the kernel
 *   returns; while some cell holds exactly 0, the frdgen_zerorank-th
 *   zero cell in the order of frdgen_cellorder, through a Fenwick tree
 *   of the tiles' zero counts.
 * One transfer per insertion brings back the minima, zero counts and
 * cells of the tiles the kernel touched: the host's copy of the field is
 * always current, and the selection needs no further round trip (a round
 * trip to the device costs far more than the bytes).
 */
#define _POSIX_C_SOURCE 200809L
#include "frd-gen/frdgencl.h"
#include "frd-gen/frdgenint.h"
#include "cli/cli.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct clgen {
	const struct frdgen_params *pr;
	struct ocl *o;
	struct frdgen_size sz;
	uint32_t ts3[3], lg[3], nt[3];
	size_t ts, ntiles, leaves;
	double *table;
	size_t ntab;
	double *cache;		/* the field as the device has it, tile by tile */
	uint32_t *zc;		/* zero cells per tile */
	uint64_t *fen;		/* Fenwick tree of zc */
	double *seg;		/* min-tree over the tiles, leaves at [leaves] */
	double *outh;
	struct frdgen_sel sel;	/* nodes: lev 0, idx the min-tree node */
	cl_program prog;
	cl_kernel k;
	cl_mem field, tab, out;
	uint64_t step;
};

/* ---- the tiles of one insertion ---------------------------------- */

static uint32_t umin(uint32_t a, uint32_t b)
{
	return a < b ? a : b;
}

/* The tiles along one axis that frdgen.c's axis_tiles lists, as a run
 * (first + i) mod nt, i < cnt. */
static void axis_run(uint32_t c, uint32_t ext, uint32_t size, uint32_t ts,
    uint32_t *first, uint32_t *cnt)
{
	uint32_t nt = (size + ts - 1) / ts, f, l;

	if (2 * (uint64_t)ext + 1 < size) {
		f = (c + size - ext) % size / ts;
		l = (c + ext) % size / ts;
		if (f <= l && (c + size - ext) % size <= (c + ext) % size) {
			*first = f;
			*cnt = l - f + 1;
			return;
		}
		if (l < f) {
			*first = f;
			*cnt = nt - f + l + 1;
			return;
		}
	}
	*first = 0;
	*cnt = nt;
}

/* ---- host structures ---------------------------------------------- */

static void set_zero_count(struct clgen *g, size_t t, uint32_t z)
{
	if (g->zc[t] != z) {
		frdgen_fen_add(g->fen, g->ntiles, t,
		    (int64_t)z - (int64_t)g->zc[t]);
		g->zc[t] = z;
	}
}

static void seg_set(struct clgen *g, size_t t, double v)
{
	size_t i = g->leaves + t;

	g->seg[i] = v;
	for (i /= 2; i > 0; i /= 2) {
		double a = g->seg[2 * i], b = g->seg[2 * i + 1];
		double m = b < a ? b : a;
		if (g->seg[i] == m)
			break;
		g->seg[i] = m;
	}
}

/* The cell (matrix index) of entry i of tile t, or -1 for padding. */
static int64_t tile_cell(const struct clgen *g, size_t t, size_t i)
{
	uint32_t tx = (uint32_t)(t % g->nt[0]);
	uint32_t ty = (uint32_t)(t / g->nt[0] % g->nt[1]);
	uint32_t tz = (uint32_t)(t / g->nt[0] / g->nt[1]);
	uint32_t x = tx * g->ts3[0] + (uint32_t)(i & (g->ts3[0] - 1));
	uint32_t y = ty * g->ts3[1] + (uint32_t)(i >> g->lg[0] &
	    (g->ts3[1] - 1));
	uint32_t z = tz * g->ts3[2] + (uint32_t)(i >> (g->lg[0] + g->lg[1]));

	if (x >= g->sz.w || y >= g->sz.h || z >= g->sz.d)
		return -1;
	return (int64_t)(((uint64_t)z * g->sz.h + y) * g->sz.w + x);
}

/* The current cells of tile t. */
static const double *tile_get(const struct clgen *g, size_t t)
{
	return g->cache + t * g->ts;
}

/* ---- selection ---------------------------------------------------- */

/* Push the children of min-tree node idx: nodes, or the cells of a tile. */
static int expand(void *ctx, int lev, uint32_t idx)
{
	struct clgen *g = ctx;
	size_t t = idx - g->leaves;
	const double *b;

	(void)lev;
	if (idx < g->leaves) {
		for (uint32_t c = 2 * idx; c < 2 * idx + 2; c++)
			if (g->seg[c] < INFINITY &&
			    frdgen_push(&g->sel, g->seg[c], 0, c) < 0)
				return -1;
		return 0;
	}
	b = tile_get(g, t);
	for (size_t i = 0; i < g->ts; i++) {
		int64_t c;
		if (!(b[i] < INFINITY) || (c = tile_cell(g, t, i)) < 0)
			continue;
		if (frdgen_push(&g->sel, b[i], -1, (uint32_t)c) < 0)
			return -1;
	}
	return 0;
}

/* The r-th zero cell in the order of frdgen_cellorder. */
static int zero_cell(struct clgen *g, uint64_t r, uint32_t *c)
{
	size_t t = frdgen_fen_find(g->fen, g->ntiles, &r);
	const double *b;

	if (t >= g->ntiles)
		return cli_fail("internal error: zero count");
	b = tile_get(g, t);
	for (size_t i = 0; i < g->ts; i++)
		if (b[i] == 0.0 && r-- == 0) {
			int64_t cc = tile_cell(g, t, i);
			if (cc < 0)
				break;
			*c = (uint32_t)cc;
			return 0;
		}
	return cli_fail("internal error: zero cell not found in tile %zu", t);
}

/* The k-th smallest free cell in the order (force, tie key, cell). */
static int select_cell(struct clgen *g, uint64_t k, uint32_t *c)
{
	struct frdgen_item root = { g->seg[1], 0, 1 };

	if (g->seg[1] == 0.0) {
		uint64_t z = frdgen_fen_total(g->fen, g->ntiles);
		if (k <= z)
			return zero_cell(g, frdgen_zerorank(g->pr, g->step, z),
			    c);
	}
	return frdgen_select(&g->sel, g->pr, g->step, k, root, expand, g, c);
}

/* ---- setup -------------------------------------------------------- */

static void gen_free(struct clgen *g)
{
	ocl_release_kernel(&g->k);
	ocl_release_program(&g->prog);
	ocl_release_mem(&g->field);
	ocl_release_mem(&g->tab);
	ocl_release_mem(&g->out);
	free(g->table), free(g->cache), free(g->zc);
	free(g->fen), free(g->seg), free(g->outh);
	frdgen_sel_free(&g->sel);
}

static int gen_init(struct clgen *g, const struct frdgen_params *pr,
    struct ocl *o, struct frs_matrix *out)
{
	char params[512], opts[64];
	frs_error ferr;
	size_t cells, wg = 0;
	cl_int err;

	memset(g, 0, sizeof *g);
	g->pr = pr;
	g->o = o;
	frdgen_size(&g->sz, pr);
	frdgen_tile_shape(pr->dims, g->ts3);
	g->ts = 1;
	for (int i = 0; i < 3; i++) {
		uint32_t size = i == 0 ? g->sz.w : i == 1 ? g->sz.h : g->sz.d;
		g->lg[i] = frdgen_log2u(g->ts3[i]);
		g->nt[i] = (size + g->ts3[i] - 1) / g->ts3[i];
		g->ts *= g->ts3[i];
	}
	g->ntiles = (size_t)g->nt[0] * g->nt[1] * g->nt[2];
	for (g->leaves = 1; g->leaves < g->ntiles; g->leaves *= 2)
		;
	frdgen_describe(pr, params, sizeof params);
	if (frs_matrix_alloc(out, pr->dims, g->sz.w, g->sz.h, g->sz.d,
	    params, &ferr) != FRS_OK)
		return cli_fail("%s", ferr.message);
	cells = g->ntiles * g->ts;
	g->cache = malloc(cells * sizeof *g->cache);
	g->zc = calloc(g->ntiles, sizeof *g->zc);
	g->fen = calloc(g->ntiles + 1, sizeof *g->fen);
	g->seg = malloc(2 * g->leaves * sizeof *g->seg);
	g->outh = malloc((2 + g->ts) * g->ntiles * sizeof *g->outh);
	if (!g->cache || !g->zc || !g->fen || !g->seg || !g->outh)
		return cli_fail("out of memory for a %zu-cell force field",
		    g->sz.n);
	g->ntab = (size_t)(g->sz.hw + 1) * (g->sz.hh + 1) * (g->sz.hd + 1);
	g->table = frdgen_table(pr);
	if (g->table == NULL)
		return -1;

	/* Every cell free (0), padding +inf; tile minima and zero counts. */
	for (size_t i = 0; i < 2 * g->leaves; i++)
		g->seg[i] = INFINITY;
	for (size_t t = 0; t < g->ntiles; t++) {
		double m = INFINITY;
		uint32_t z = 0;
		for (size_t i = 0; i < g->ts; i++) {
			double v = tile_cell(g, t, i) < 0 ? INFINITY : 0.0;
			g->cache[t * g->ts + i] = v;
			m = v < m ? v : m;
			z += v == 0.0;
		}
		set_zero_count(g, t, z);
		g->seg[g->leaves + t] = m;
	}
	for (size_t i = g->leaves - 1; i > 0; i--)
		g->seg[i] = g->seg[2 * i + 1] < g->seg[2 * i] ?
		    g->seg[2 * i + 1] : g->seg[2 * i];

	snprintf(opts, sizeof opts, "-D FRD_TS=%zu -D FRD_ROWS=%zu", g->ts,
	    g->ts / g->ts3[0]);
	if (ocl_program(o, "frdgen", opts, &g->prog) < 0 ||
	    ocl_kernel(g->prog, "frd_add", &g->k) < 0)
		return -1;
	err = clGetKernelWorkGroupInfo(g->k, o->device,
	    CL_KERNEL_WORK_GROUP_SIZE, sizeof wg, &wg, NULL);
	if (err != CL_SUCCESS)
		return ocl_fail(err, "frd_add: work-group size");
	if (wg < g->ts / g->ts3[0])
		return cli_fail("OpenCL: %s runs at most %zu work-items per "
		    "group, the generator needs %zu", o->name, wg, g->ts / g->ts3[0]);
	if (ocl_buffer(o, CL_MEM_READ_WRITE, cells * sizeof(double), g->cache,
	    &g->field) < 0 ||
	    ocl_buffer(o, CL_MEM_READ_ONLY, g->ntab * sizeof(double), g->table,
	    &g->tab) < 0 ||
	    ocl_buffer(o, CL_MEM_READ_WRITE, (2 + g->ts) * g->ntiles *
	    sizeof(double), NULL, &g->out) < 0 ||
	    ocl_fill32(o, g->out, (2 + g->ts) * g->ntiles * sizeof(double),
	    0) < 0)
		return -1;
	return 0;
}

static cl_uint4 u4(uint32_t a, uint32_t b, uint32_t c, uint32_t d)
{
	cl_uint4 v;
	v.s[0] = a;
	v.s[1] = b;
	v.s[2] = c;
	v.s[3] = d;
	return v;
}

/* Take the cells, minima and zero counts of the nw tiles of the run
 * first .. first + cnt that the kernel sent back. */
static void take_tiles(struct clgen *g, const uint32_t first[3],
    const uint32_t cnt[3], size_t nw)
{
	for (size_t i = 0; i < nw; i++) {
		uint32_t gi = (uint32_t)(i % cnt[0]);
		uint32_t gj = (uint32_t)(i / cnt[0] % cnt[1]);
		uint32_t gk = (uint32_t)(i / cnt[0] / cnt[1]);
		size_t t = ((size_t)((first[2] + gk) % g->nt[2]) * g->nt[1] +
		    (first[1] + gj) % g->nt[1]) * g->nt[0] +
		    (first[0] + gi) % g->nt[0];
		memcpy(g->cache + t * g->ts, g->outh + 2 * nw + i * g->ts,
		    g->ts * sizeof *g->cache);
		set_zero_count(g, t, (uint32_t)g->outh[2 * i + 1]);
		seg_set(g, t, g->outh[2 * i]);
	}
}

/* Add the force of the value just taken at (cx, cy, cz) within r and
 * take the new minima and zero counts of the tiles it touched. */
static int add_force(struct clgen *g, uint32_t cx, uint32_t cy, uint32_t cz,
    double r)
{
	uint32_t size[3] = { g->sz.w, g->sz.h, g->sz.d }, c[3] = { cx, cy, cz };
	uint32_t first[3], cnt[3];
	cl_uint4 dim, half, nt, lg, cen, fi, cn, eyz;
	cl_double r2, sub;
	size_t nw, global, local = g->ts / g->ts3[0];
	struct frdgen_win wd;
	cl_int err;

	frdgen_window(g->pr, &g->sz, g->ts3[0], r, &wd);
	r2 = wd.r2;
	sub = wd.sub;
	for (int i = 0; i < 3; i++)
		axis_run(c[i], umin(wd.e, size[i]), size[i], g->ts3[i],
		    &first[i], &cnt[i]);
	nw = (size_t)cnt[0] * cnt[1] * cnt[2];
	global = nw * local;
	dim = u4(g->sz.w, g->sz.h, g->sz.d, 0);
	half = u4(g->sz.hw, g->sz.hh, g->sz.hd, 0);
	nt = u4(g->nt[0], g->nt[1], g->nt[2], 0);
	lg = u4(g->lg[0], g->lg[1], g->lg[2], 0);
	cen = u4(cx, cy, cz, 0);
	fi = u4(first[0], first[1], first[2], 0);
	cn = u4(cnt[0], cnt[1], cnt[2], 0);
	eyz = u4(wd.ey, wd.ez, (uint32_t)wd.fast, 0);
	if (ocl_args(g->k, 13, sizeof g->field, &g->field, sizeof g->tab,
	    &g->tab, sizeof g->out, &g->out, sizeof dim, &dim, sizeof half,
	    &half, sizeof nt, &nt, sizeof lg, &lg, sizeof cen, &cen, sizeof fi,
	    &fi, sizeof cn, &cn, sizeof eyz, &eyz, sizeof r2, &r2, sizeof sub,
	    &sub) < 0)
		return -1;
	err = clEnqueueNDRangeKernel(g->o->q, g->k, 1, NULL, &global, &local,
	    0, NULL, NULL);
	if (err != CL_SUCCESS)
		return ocl_fail(err, "frd_add");
	err = clEnqueueReadBuffer(g->o->q, g->out, CL_TRUE, 0,
	    (2 + g->ts) * nw * sizeof(double), g->outh, 0, NULL, NULL);
	if (err != CL_SUCCESS)
		return ocl_fail(err, "frd_add: reading the tile minima");
	take_tiles(g, first, cnt, nw);
	return 0;
}

int frdgen_run_cl(const struct frdgen_params *par, struct ocl *o,
    struct frs_matrix *out, struct cli_task *task)
{
	struct clgen g;

	memset(out, 0, sizeof *out);
	if (frdgen_check(par) < 0)
		return -1;
	if (par->checkpoint != NULL)
		return cli_fail("checkpoints are not available with OpenCL");
	if (!o->fp64)
		return cli_fail("OpenCL: %s has no double precision "
		    "(cl_khr_fp64), which the generator needs to give the "
		    "CPU's matrix", o->name);
	if (gen_init(&g, par, o, out) < 0)
		goto fail;
	memset(out->v, 0xff, g.sz.n * sizeof *out->v);
	for (g.step = 0; g.step < g.sz.n; g.step++) {
		uint32_t c = 0;
		uint64_t k = frdgen_rank(par, g.step, g.sz.n - g.step);
		if (select_cell(&g, k, &c) < 0)
			goto fail;
		out->v[c] = (uint32_t)g.step;
		if (add_force(&g, c % g.sz.w, c / g.sz.w % g.sz.h,
		    c / g.sz.w / g.sz.h,
		    frdgen_radius_after(par, g.sz.rtol, g.step + 1)) < 0)
			goto fail;
		if (task != NULL && (g.step & 1023) == 0)
			cli_task_update(task, g.step);
	}
	gen_free(&g);
	return 0;
fail:
	gen_free(&g);
	frs_matrix_free(out);
	return -1;
}
