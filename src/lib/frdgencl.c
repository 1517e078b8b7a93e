/*
 * Forced Random Dithering with OpenCL: the host side of cl/frdgen.cl.
 *
 * What has to match frdgen.c bit for bit, and how:
 * - the field: the kernel adds, per insertion and cell, at most one entry
 *   of the same force table (built here with the same expression as
 *   frdgen.c's make_table), to the same cells (the window rules of
 *   add_force are repeated in the kernel), in insertion order: so every
 *   cell holds the same double as on the CPU;
 * - the selection: the K-th smallest free cell in the order (force, tie
 *   key, cell), K = frdgen_rank, found here best-first over a min-tree of
 *   the tile minima that the kernel returns; while some cell holds
 *   exactly 0, the frdgen_zerorank-th zero cell in the order of
 *   frdgen_cellorder, through a Fenwick tree of the tiles' zero counts.
 * One transfer per insertion brings back the minima, zero counts and
 * cells of the tiles the kernel touched: the host's copy of the field is
 * always current, and the selection needs no further round trip (a round
 * trip to the device costs far more than the bytes).
 */
#define _POSIX_C_SOURCE 200809L
#include "frdgencl.h"
#include "err.h"
#include "progress.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct citem {
	double v;
	int64_t id;		/* >= 0: node of the min-tree; < 0: cell -id-1 */
};

struct clgen {
	const struct frdgen_params *pr;
	struct ocl *o;
	uint32_t w, h, d;
	size_t n;
	uint32_t hw, hh, hd;
	double rtol, rmax;
	uint32_t ts3[3], lg[3], nt[3];
	size_t ts, ntiles, leaves;
	double *table;
	size_t ntab;
	double *cache;		/* the field as the device has it, tile by tile */
	uint32_t *zc;		/* zero cells per tile */
	uint64_t *fen;		/* Fenwick tree of zc */
	double *seg;		/* min-tree over the tiles, leaves at [leaves] */
	double *outh;
	struct citem *heap, *emit;
	size_t nheap, hcap, nemit, ecap;
	uint64_t *keys;
	size_t kcap;
	cl_program prog;
	cl_kernel k;
	cl_mem field, tab, out;
	uint64_t step;
};

/* ---- what frdgen.c computes, repeated with the same expressions ---- */

static void tile_shape(unsigned dims, uint32_t t[3])
{
	t[0] = dims == 2 ? 16 : 8;
	t[1] = dims == 2 ? 8 : 4;
	t[2] = dims == 2 ? 1 : 4;
}

static double spacing(const struct clgen *g, uint64_t n)
{
	double vol = (double)g->w * g->h * g->d;

	if (g->pr->dims == 2)
		return sqrt(2.0 * vol / (sqrt(3.0) * (double)n));
	return cbrt(sqrt(2.0) * vol / (double)n);
}

static double radius_after(const struct clgen *g, uint64_t inserted)
{
	double r = g->rtol;

	if (g->pr->reach > 0.0) {
		double adapt = g->pr->reach * spacing(g, inserted);
		r = adapt > r ? adapt : r;
	}
	return r;
}

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

static int make_table(struct clgen *g)
{
	g->ntab = (size_t)(g->hw + 1) * (g->hh + 1) * (g->hd + 1);
	g->table = malloc(g->ntab * sizeof *g->table);
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

/* ---- host structures ---------------------------------------------- */

static void fen_add(struct clgen *g, size_t t, int64_t d)
{
	for (size_t i = t + 1; i <= g->ntiles; i += i & (~i + 1))
		g->fen[i] = (uint64_t)((int64_t)g->fen[i] + d);
}

static void set_zero_count(struct clgen *g, size_t t, uint32_t z)
{
	if (g->zc[t] != z) {
		fen_add(g, t, (int64_t)z - (int64_t)g->zc[t]);
		g->zc[t] = z;
	}
}

static uint64_t fen_total(const struct clgen *g)
{
	uint64_t s = 0;
	for (size_t i = g->ntiles; i > 0; i -= i & (~i + 1))
		s += g->fen[i];
	return s;
}

static size_t fen_find(const struct clgen *g, uint64_t *r)
{
	size_t pos = 0, step = 1;

	while (step * 2 <= g->ntiles)
		step *= 2;
	for (; step > 0; step /= 2)
		if (pos + step <= g->ntiles && g->fen[pos + step] <= *r) {
			pos += step;
			*r -= g->fen[pos];
		}
	return pos;
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

	if (x >= g->w || y >= g->h || z >= g->d)
		return -1;
	return (int64_t)(((uint64_t)z * g->h + y) * g->w + x);
}

/* The current cells of tile t. */
static const double *tile_get(const struct clgen *g, size_t t)
{
	return g->cache + t * g->ts;
}

/* ---- selection ---------------------------------------------------- */

static int room(struct citem **a, size_t n, size_t *cap)
{
	if (n == *cap) {
		size_t ncap = *cap ? 2 * *cap : 256;
		struct citem *na = realloc(*a, ncap * sizeof *na);
		if (na == NULL)
			return frs_fail("out of memory in the rank query");
		*a = na;
		*cap = ncap;
	}
	return 0;
}

static int heap_push(struct clgen *g, double v, int64_t id)
{
	size_t i;

	if (room(&g->heap, g->nheap, &g->hcap) < 0)
		return -1;
	i = g->nheap++;
	while (i > 0 && g->heap[(i - 1) / 2].v > v) {
		g->heap[i] = g->heap[(i - 1) / 2];
		i = (i - 1) / 2;
	}
	g->heap[i] = (struct citem){ v, id };
	return 0;
}

static struct citem heap_pop(struct clgen *g)
{
	struct citem top = g->heap[0], last = g->heap[--g->nheap];
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

static int expand(struct clgen *g, int64_t node)
{
	size_t nd = (size_t)node;

	if (nd < g->leaves) {
		for (size_t c = 2 * nd; c < 2 * nd + 2; c++)
			if (g->seg[c] < INFINITY &&
			    heap_push(g, g->seg[c], (int64_t)c) < 0)
				return -1;
		return 0;
	}
	{
		size_t t = nd - g->leaves;
		const double *b = tile_get(g, t);
		for (size_t i = 0; i < g->ts; i++) {
			int64_t c;
			if (!(b[i] < INFINITY) || (c = tile_cell(g, t, i)) < 0)
				continue;
			if (heap_push(g, b[i], -c - 1) < 0)
				return -1;
		}
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

/* The r-th zero cell in the order of frdgen_cellorder. */
static int zero_cell(struct clgen *g, uint64_t r, uint32_t *c)
{
	size_t t = fen_find(g, &r);
	const double *b;

	if (t >= g->ntiles)
		return frs_fail("internal error: zero count");
	b = tile_get(g, t);
	for (size_t i = 0; i < g->ts; i++)
		if (b[i] == 0.0 && r-- == 0) {
			int64_t cc = tile_cell(g, t, i);
			if (cc < 0)
				break;
			*c = (uint32_t)cc;
			return 0;
		}
	return frs_fail("internal error: zero cell not found in tile %zu", t);
}

/* The k-th smallest free cell in the order (force, tie key, cell). */
static int select_cell(struct clgen *g, uint64_t k, uint32_t *c)
{
	double v;
	size_t a, m;

	if (g->seg[1] == 0.0)
		return zero_cell(g, frdgen_zerorank(g->pr, g->step,
		    fen_total(g)), c);
	g->nheap = g->nemit = 0;
	if (heap_push(g, g->seg[1], 1) < 0)
		return -1;
	while (g->nheap > 0) {
		struct citem it;
		if (g->nemit >= k && g->heap[0].v > g->emit[k - 1].v)
			break;
		it = heap_pop(g);
		if (it.id < 0) {
			if (room(&g->emit, g->nemit, &g->ecap) < 0)
				return -1;
			g->emit[g->nemit++] = it;
		} else if (expand(g, it.id) < 0) {
			return -1;
		}
	}
	if (g->nemit < k)
		return frs_fail("internal error: %zu free cells found, rank %llu",
		    g->nemit, (unsigned long long)k);
	v = g->emit[k - 1].v;
	for (a = k - 1; a > 0 && g->emit[a - 1].v == v; a--)
		;
	while (g->nemit > k && g->emit[g->nemit - 1].v > v)
		g->nemit--;
	m = g->nemit - a;
	if (m == 1) {
		*c = (uint32_t)(-g->emit[a].id - 1);
		return 0;
	}
	if (2 * m > g->kcap) {
		uint64_t *nk = realloc(g->keys, 2 * m * sizeof *nk);
		if (nk == NULL)
			return frs_fail("out of memory in the rank query");
		g->keys = nk;
		g->kcap = 2 * m;
	}
	for (size_t i = 0; i < m; i++) {
		uint32_t cell = (uint32_t)(-g->emit[a + i].id - 1);
		g->keys[2 * i] = frdgen_tiekey(g->pr, g->step, cell);
		g->keys[2 * i + 1] = cell;
	}
	qsort(g->keys, m, 2 * sizeof *g->keys, cmp_key);
	*c = (uint32_t)g->keys[2 * (k - 1 - a) + 1];
	return 0;
}

/* ---- setup -------------------------------------------------------- */

static unsigned log2u(uint32_t v)
{
	unsigned l = 0;
	while ((1u << l) < v)
		l++;
	return l;
}

static void gen_free(struct clgen *g)
{
	if (g->k != NULL)
		clReleaseKernel(g->k);
	if (g->prog != NULL)
		clReleaseProgram(g->prog);
	if (g->field != NULL)
		clReleaseMemObject(g->field);
	if (g->tab != NULL)
		clReleaseMemObject(g->tab);
	if (g->out != NULL)
		clReleaseMemObject(g->out);
	free(g->table);
	free(g->cache);
	free(g->zc);
	free(g->fen);
	free(g->seg);
	free(g->outh);
	free(g->heap);
	free(g->emit);
	free(g->keys);
}

static int gen_init(struct clgen *g, const struct frdgen_params *pr,
    struct ocl *o, struct frs_matrix *out)
{
	char params[512], opts[64];
	size_t cells, wg = 0;
	cl_int err;

	memset(g, 0, sizeof *g);
	g->pr = pr;
	g->o = o;
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
	tile_shape(pr->dims, g->ts3);
	g->ts = 1;
	for (int i = 0; i < 3; i++) {
		uint32_t size = i == 0 ? g->w : i == 1 ? g->h : g->d;
		g->lg[i] = log2u(g->ts3[i]);
		g->nt[i] = (size + g->ts3[i] - 1) / g->ts3[i];
		g->ts *= g->ts3[i];
	}
	g->ntiles = (size_t)g->nt[0] * g->nt[1] * g->nt[2];
	for (g->leaves = 1; g->leaves < g->ntiles; g->leaves *= 2)
		;
	frdgen_describe(pr, params, sizeof params);
	if (frd_alloc(out, pr->dims, g->w, g->h, g->d, params) < 0)
		return -1;
	cells = g->ntiles * g->ts;
	g->cache = malloc(cells * sizeof *g->cache);
	g->zc = calloc(g->ntiles, sizeof *g->zc);
	g->fen = calloc(g->ntiles + 1, sizeof *g->fen);
	g->seg = malloc(2 * g->leaves * sizeof *g->seg);
	g->outh = malloc((2 + g->ts) * g->ntiles * sizeof *g->outh);
	if (!g->cache || !g->zc || !g->fen || !g->seg || !g->outh)
		return frs_fail("out of memory for a %zu-cell force field", g->n);
	if (make_table(g) < 0)
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
		return frs_fail("OpenCL: %s runs at most %zu work-items per "
		    "group, frd-gen needs %zu", o->name, wg, g->ts / g->ts3[0]);
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

/* Add the force of the value just taken at (cx, cy, cz) within r and
 * take the new minima and zero counts of the tiles it touched. */
static int add_force(struct clgen *g, uint32_t cx, uint32_t cy, uint32_t cz,
    double r)
{
	uint32_t size[3] = { g->w, g->h, g->d }, c[3] = { cx, cy, cz };
	uint32_t first[3], cnt[3], e, ey, ez, fast;
	cl_uint4 dim, half, nt, lg, cen, fi, cn, eyz;
	cl_double r2;
	size_t nw, global, local = g->ts / g->ts3[0];
	cl_int err;

	e = r >= (double)UINT32_MAX ? UINT32_MAX : (uint32_t)floor(r);
	r2 = r >= g->rmax ? INFINITY : r * r;
	fast = 2 * (uint64_t)e + 1 + 2 * g->ts3[0] <= g->w;
	ey = umin(e, g->hh);
	ez = umin(e, g->hd);
	for (int i = 0; i < 3; i++)
		axis_run(c[i], umin(e, size[i]), size[i], g->ts3[i], &first[i],
		    &cnt[i]);
	nw = (size_t)cnt[0] * cnt[1] * cnt[2];
	global = nw * local;
	dim = u4(g->w, g->h, g->d, 0);
	half = u4(g->hw, g->hh, g->hd, 0);
	nt = u4(g->nt[0], g->nt[1], g->nt[2], 0);
	lg = u4(g->lg[0], g->lg[1], g->lg[2], 0);
	cen = u4(cx, cy, cz, 0);
	fi = u4(first[0], first[1], first[2], 0);
	cn = u4(cnt[0], cnt[1], cnt[2], 0);
	eyz = u4(ey, ez, fast, 0);
	if (ocl_args(g->k, 12, sizeof g->field, &g->field, sizeof g->tab,
	    &g->tab, sizeof g->out, &g->out, sizeof dim, &dim, sizeof half,
	    &half, sizeof nt, &nt, sizeof lg, &lg, sizeof cen, &cen, sizeof fi,
	    &fi, sizeof cn, &cn, sizeof eyz, &eyz, sizeof r2, &r2) < 0)
		return -1;
	err = clEnqueueNDRangeKernel(g->o->q, g->k, 1, NULL, &global, &local,
	    0, NULL, NULL);
	if (err != CL_SUCCESS)
		return ocl_fail(err, "frd_add");
	err = clEnqueueReadBuffer(g->o->q, g->out, CL_TRUE, 0,
	    (2 + g->ts) * nw * sizeof(double), g->outh, 0, NULL, NULL);
	if (err != CL_SUCCESS)
		return ocl_fail(err, "frd_add: reading the tile minima");
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
	return 0;
}

int frdgen_run_cl(const struct frdgen_params *par, struct ocl *o,
    struct frs_matrix *out, struct progress *prog)
{
	struct clgen g;

	memset(out, 0, sizeof *out);
	if (frdgen_check(par) < 0)
		return -1;
	if (par->checkpoint != NULL)
		return frs_fail("--checkpoint: not available with OpenCL");
	if (!o->fp64)
		return frs_fail("OpenCL: %s has no double precision "
		    "(cl_khr_fp64), which frd-gen needs to give the same "
		    "matrix as --device cpu", o->name);
	if (gen_init(&g, par, o, out) < 0)
		goto fail;
	memset(out->v, 0xff, g.n * sizeof *out->v);
	for (g.step = 0; g.step < g.n; g.step++) {
		uint32_t c = 0;
		uint64_t k = frdgen_rank(par, g.step, g.n - g.step);
		if (select_cell(&g, k, &c) < 0)
			goto fail;
		out->v[c] = (uint32_t)g.step;
		if (add_force(&g, c % g.w, c / g.w % g.h, c / g.w / g.h,
		    radius_after(&g, g.step + 1)) < 0)
			goto fail;
		if (prog != NULL && (g.step & 1023) == 0)
			progress_update(prog, g.step);
	}
	gen_free(&g);
	return 0;
fail:
	gen_free(&g);
	frd_free(out);
	return -1;
}
