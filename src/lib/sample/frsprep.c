/*
 * The matrix prepared for the thresholding (frsprep.h): the minmap of
 * Stack, Level N and Flat 1, and the sorted lists of Sorted (Listing
 * 5.10), built by whichever sort suits the matrix and the values wanted.
 */
#define _POSIX_C_SOURCE 200809L
#include "sample/frsprep.h"
#include "base/err.h"
#include "base/mem.h"
#include "base/num.h"
#include "base/par.h"

#include <stdlib.h>
#include <string.h>

void frs_prep_free(struct frs_prep *p)
{
	for (unsigned l = 1; l < p->nlev; l++)
		free(p->lev[l]);
	MEM_FREE(p->sval, p->sidx, p->soff);
	memset(p, 0, sizeof *p);
}

/* One level of the minmap from the one below: rows [y0, y1) of up, of
 * width w, from lo, of width pw. */
struct halve {
	const uint32_t *lo;
	uint32_t *up;
	uint32_t w, pw;
};

static int halve_rows(void *ctx, uint64_t y0, uint64_t y1)
{
	const struct halve *hv = ctx;

	for (uint64_t y = y0; y < y1; y++)
		for (uint32_t x = 0; x < hv->w; x++) {
			const uint32_t *q = hv->lo + 2 * y * hv->pw + 2 * x;
			uint32_t a = q[0] < q[1] ? q[0] : q[1];
			uint32_t b = q[hv->pw] < q[hv->pw + 1] ? q[hv->pw] :
			    q[hv->pw + 1];
			hv->up[y * hv->w + x] = a < b ? a : b;
		}
	return 0;
}

/* The minmap, each level in parallel over rows of 2^16 minima or more
 * (level 1 of a 2048^2 matrix: 2.5 ms on one thread). */
static int make_minmap(struct frs_prep *p)
{
	const struct frs_matrix *m = p->m;

	p->lev[0] = m->v;
	p->nlev = 1;
	while ((m->w >> p->nlev) > 0 && (m->h >> p->nlev) > 0 && p->nlev < 32) {
		unsigned l = p->nlev;
		uint32_t w = m->w >> l, h = m->h >> l;
		struct halve hv = { p->lev[l - 1], NULL, w, m->w >> (l - 1) };
		if ((hv.up = malloc((size_t)w * h * sizeof *hv.up)) == NULL)
			return frs_fail("out of memory for the minmap");
		p->lev[l] = hv.up;	/* frs_prep_free's, whatever comes */
		p->nlev++;
		if (frs_parallel_if((uint64_t)w * h >= 65536, h, (65535 + w) / w,
		    halve_rows, &hv) < 0)
			return -1;
	}
	return 0;
}

/* The block lists by comparison sort: any matrix values. */
static void sort_blocks(struct frs_prep *p, struct num_vi *tmp)
{
	const struct frs_matrix *m = p->m;
	uint32_t b = p->block, bw = m->w / b, bh = m->h / b;
	size_t bb = (size_t)b * b;

	for (uint32_t by = 0; by < bh; by++)
		for (uint32_t bx = 0; bx < bw; bx++) {
			size_t base = ((size_t)by * bw + bx) * bb;
			for (uint32_t k = 0; k < bb; k++)
				tmp[k] = (struct num_vi){ m->v[((size_t)by * b + k / b) *
				    m->w + (size_t)bx * b + k % b], k };
			qsort(tmp, bb, sizeof *tmp, num_vi_cmp);
			for (size_t k = 0; k < bb; k++) {
				p->sval[base + k] = tmp[k].v;
				p->sidx[base + k] = tmp[k].i;
			}
		}
}

/* Whether the values are the permutation of 0 .. n - 1 that frd(5)
 * promises: frd_check_permutation's answer without its message. */
static int is_permutation(const struct frs_matrix *m)
{
	if (frd_check_permutation(m, "") == 0)
		return 1;
	frs_clearerr();
	return 0;
}

struct invert {
	const uint32_t *v;
	uint32_t *inv;
	uint64_t below;		/* values from it are left out */
	uint64_t span;		/* matrix elements per task */
	uint64_t *kept;		/* per task, the elements below */
};

/* No element of the matrix has this value (indices stay below 2^31). */
#define NO_ELEM UINT32_MAX

/* inv[v[i]] = i over [b, e): blind stores, distinct for a permutation,
 * so tasks may run side by side. */
static int invert_task(void *ctx, uint64_t b, uint64_t e)
{
	const struct invert *iv = ctx;

	for (uint64_t i = b; i < e; i++)
		iv->inv[iv->v[i]] = (uint32_t)i;
	return 0;
}

/* The same for the values below iv->below only, into an inv of that
 * many entries set to NO_ELEM: one read of the matrix, rare stores.
 * Repeated values store twice but count twice, which
 * distinct_values then sees. */
static int invert_below_task(void *ctx, uint64_t b, uint64_t e)
{
	const struct invert *iv = ctx;
	uint64_t kept = 0;

	for (uint64_t i = b; i < e; i++)
		if (iv->v[i] < iv->below) {
			iv->inv[iv->v[i]] = (uint32_t)i;
			kept++;
		}
	iv->kept[b / iv->span] = kept;
	return 0;
}

/* Counting sort over the inverse permutation, in parallel over ranges
 * of values: a first pass counts each range's values per block, the
 * prefix sums over ranges then give every range its place in each
 * block's list, and a second pass puts them there.  Each pass reads its
 * range of inv once; no thread reads what another one does. */
struct scatter {
	struct frs_prep *p;
	const uint32_t *inv;	/* NO_ELEM: a value the matrix lacks */
	uint64_t nv;		/* values 0 .. nv - 1 */
	uint64_t span;		/* values per range */
	uint64_t nblk;		/* blocks */
	uint64_t *fill;		/* per range and block: count, then place */
};

/* The block of matrix index i (lb = log2 block, lw = log2 width). */
static uint64_t block_of(const struct frs_matrix *m, uint32_t i, unsigned lb,
    unsigned lw)
{
	return (uint64_t)((i >> lw) >> lb) * (m->w >> lb) + ((i & (m->w - 1)) >> lb);
}

static int count_task(void *ctx, uint64_t b, uint64_t e)
{
	const struct scatter *sc = ctx;
	const struct frs_matrix *m = sc->p->m;
	unsigned lb = num_log2_ceil(sc->p->block), lw = num_log2_ceil(m->w);

	for (uint64_t r = b; r < e; r++) {
		uint64_t *cnt = sc->fill + r * sc->nblk, v1 = (r + 1) * sc->span;
		for (uint64_t v = r * sc->span; v < v1 && v < sc->nv; v++)
			if (sc->inv[v] != NO_ELEM)
				cnt[block_of(m, sc->inv[v], lb, lw)]++;
	}
	return 0;
}

/* Entries gathered per block before they go to its list: one cache
 * line of values and one of indices, written whole, where single stores
 * to many lists at once would each fetch a line first. */
#define GATHER 16

struct gather {
	uint32_t v[GATHER], i[GATHER];
};

static void put_run(struct frs_prep *p, uint64_t *at, const struct gather *g,
    unsigned n)
{
	memcpy(p->sval + *at, g->v, n * sizeof *g->v);
	memcpy(p->sidx + *at, g->i, n * sizeof *g->i);
	*at += n;
}

static int place_task(void *ctx, uint64_t b, uint64_t e)
{
	const struct scatter *sc = ctx;
	struct frs_prep *p = sc->p;
	const struct frs_matrix *m = p->m;
	uint32_t blk = p->block;
	unsigned lb = num_log2_ceil(blk), lw = num_log2_ceil(m->w);
	struct gather *g = malloc(sc->nblk * sizeof *g);
	unsigned char *ng = calloc(sc->nblk, 1);

	if (g == NULL || ng == NULL) {
		free(g);
		free(ng);
		return frs_fail("out of memory for the sorted lists");
	}
	for (uint64_t r = b; r < e; r++) {
		uint64_t *at = sc->fill + r * sc->nblk, v1 = (r + 1) * sc->span;
		for (uint64_t v = r * sc->span; v < v1 && v < sc->nv; v++) {
			uint32_t i = sc->inv[v], x = i & (m->w - 1), y = i >> lw;
			uint64_t k;
			if (i == NO_ELEM)
				continue;
			k = block_of(m, i, lb, lw);
			g[k].v[ng[k]] = (uint32_t)v;
			g[k].i[ng[k]] = ((y & (blk - 1)) << lb) | (x & (blk - 1));
			if (++ng[k] == GATHER) {
				put_run(p, &at[k], &g[k], GATHER);
				ng[k] = 0;
			}
		}
		for (uint64_t k = 0; k < sc->nblk; k++) {
			put_run(p, &at[k], &g[k], ng[k]);
			ng[k] = 0;
		}
	}
	free(g);
	free(ng);
	return 0;
}

/* Radix sort (LSD, 11-bit digits, stable) of n keys with their
 * payloads, from (k, i) through (tk, ti); the result ends in (k, i). */
static void radix_pairs(uint32_t *k, uint32_t *i, uint32_t *tk, uint32_t *ti,
    size_t n, uint32_t max)
{
	for (unsigned sh = 0; sh < 32 && (sh == 0 || (max >> sh) != 0); sh += 11) {
		size_t cnt[2048] = { 0 }, sum = 0;
		for (size_t j = 0; j < n; j++)
			cnt[(k[j] >> sh) & 2047]++;
		for (size_t d = 0; d < 2048; d++) {
			size_t c = cnt[d];
			cnt[d] = sum;
			sum += c;
		}
		for (size_t j = 0; j < n; j++) {
			size_t at = cnt[(k[j] >> sh) & 2047]++;
			tk[at] = k[j];
			ti[at] = i[j];
		}
		memcpy(k, tk, n * sizeof *k);
		memcpy(i, ti, n * sizeof *i);
	}
}

/* More blocks than this: complete lists by bands, no global inverse. */
#define ONE_PASS_BLOCKS 4096

/* The lists by counting over inv: count, place each range, put. */
static int count_sort(struct frs_prep *p, const uint32_t *inv, uint64_t nv)
{
	const struct frs_matrix *m = p->m;
	uint64_t nt = (uint64_t)frs_threads(), bb = (uint64_t)p->block * p->block;
	struct scatter sc = { p, inv, nv, 0, 0, NULL };
	int rc;

	nt = nt < 1 ? 1 : nt;
	sc.span = (nv + nt - 1) / nt;
	sc.nblk = m->n / bb;
	if ((sc.fill = calloc(nt * sc.nblk, sizeof *sc.fill)) == NULL)
		return frs_fail("out of memory for the sorted lists");
	rc = frs_parallel(nt, 1, count_task, &sc, NULL);
	for (uint64_t k = 0, at = 0; rc == 0 && k < sc.nblk; k++) {
		p->soff[k] = (uint32_t)at;
		for (uint64_t r = 0; r < nt; r++) {
			uint64_t c = sc.fill[r * sc.nblk + k];
			sc.fill[r * sc.nblk + k] = at;
			at += c;
		}
		p->soff[k + 1] = (uint32_t)at;
	}
	if (rc == 0)
		rc = frs_parallel(nt, 1, place_task, &sc, NULL);
	free(sc.fill);
	return rc;
}

/* Fewer values than this, or many small blocks: deal_below, whose one
 * pass over them costs less than count_sort's arrays of every block
 * (frscore.h). */
uint64_t frs_deal_below = (uint64_t)1 << 20;

/* The values in order, counted per block, then each appended to its
 * block's list: the lists come out sorted. */
static int deal_below(struct frs_prep *p, const uint32_t *inv, uint64_t nv)
{
	const struct frs_matrix *m = p->m;
	uint32_t blk = p->block;
	unsigned lb = num_log2_ceil(blk), lw = num_log2_ceil(m->w);
	uint64_t nblk = m->n / ((uint64_t)blk * blk);
	uint32_t *fill = calloc(nblk, sizeof *fill);

	if (fill == NULL)
		return frs_fail("out of memory for the sorted lists");
	for (uint64_t v = 0; v < nv; v++)
		if (inv[v] != NO_ELEM)
			fill[block_of(m, inv[v], lb, lw)]++;
	p->soff[0] = 0;
	for (uint64_t k = 0; k < nblk; k++) {
		p->soff[k + 1] = p->soff[k] + fill[k];
		fill[k] = p->soff[k];
	}
	for (uint64_t v = 0; v < nv; v++) {
		uint32_t i = inv[v], x = i & (m->w - 1), y = i >> lw, at;
		if (i == NO_ELEM)
			continue;
		at = fill[block_of(m, i, lb, lw)]++;
		p->sval[at] = (uint32_t)v;
		p->sidx[at] = ((y & (blk - 1)) << lb) | (x & (blk - 1));
	}
	free(fill);
	return 0;
}

/*
 * Lists a band of blocks (b rows of the matrix) at a time, in parallel
 * over bands: a band's values below lim gathered in the order of the
 * matrix, sorted by value (radix_pairs, stable: equal values keep that
 * order) and dealt to its blocks, whose lists lie side by side from
 * soff.  Each band's work stays in cache, where dealing the values in
 * order over the whole matrix (the inverse permutation) stores to every
 * block's list at once.  Complete lists keep every value (lim 2^32);
 * partial ones count each block's values below first (count_band).
 */
struct bands {
	struct frs_prep *p;
	uint64_t lim;		/* the values below it */
	uint64_t most;		/* the most values of a band */
};

static int count_band(void *ctx, uint64_t r0, uint64_t r1)
{
	const struct bands *bd = ctx;
	const struct frs_matrix *m = bd->p->m;
	uint32_t b = bd->p->block, bw = m->w / b, *cnt = bd->p->soff + 1;

	for (uint64_t r = r0; r < r1; r++)
		for (uint64_t y = r * b; y < (r + 1) * b; y++) {
			const uint32_t *row = m->v + y * m->w;
			for (uint32_t bx = 0; bx < bw; bx++) {
				uint32_t c = 0;
				for (uint32_t x = bx * b; x < (bx + 1) * b; x++)
					c += row[x] < bd->lim;
				cnt[r * bw + bx] += c;
			}
		}
	return 0;
}

/* Sort n (key, payload) pairs by key: insertion for a few, else radix
 * through the room (tk, ti). */
static void sort_pairs(uint32_t *k, uint32_t *i, uint32_t *tk, uint32_t *ti,
    size_t n, uint32_t max)
{
	if (n > 48) {
		radix_pairs(k, i, tk, ti, n, max);
		return;
	}
	for (size_t a = 1; a < n; a++) {
		uint32_t kk = k[a], ii = i[a];
		size_t j = a;
		for (; j > 0 && k[j - 1] > kk; j--) {
			k[j] = k[j - 1];
			i[j] = i[j - 1];
		}
		k[j] = kk;
		i[j] = ii;
	}
}

static int place_band(void *ctx, uint64_t r0, uint64_t r1)
{
	const struct bands *bd = ctx;
	struct frs_prep *p = bd->p;
	const struct frs_matrix *m = p->m;
	uint32_t b = p->block, bw = m->w / b;
	unsigned lb = num_log2_ceil(b), lw = num_log2_ceil(m->w);
	uint32_t *t = malloc(4 * (bd->most + 1) * sizeof *t);
	uint32_t *fill = malloc(bw * sizeof *fill);

	if (t == NULL || fill == NULL) {
		free(t);
		free(fill);
		return frs_fail("out of memory for the sorted lists");
	}
	for (uint64_t r = r0; r < r1; r++) {
		uint32_t *tk = t, *ti = t + bd->most + 1, max = 0;
		size_t n = 0;
		for (uint32_t y = 0; y < b; y++) {
			const uint32_t *row = m->v + (r * b + y) * m->w;
			for (uint32_t x = 0; x < m->w; x++) {
				int keep = row[x] < bd->lim;
				tk[n] = row[x];	/* kept when below: no branch */
				ti[n] = y << lw | x;
				max = keep && row[x] > max ? row[x] : max;
				n += (size_t)keep;
			}
		}
		sort_pairs(tk, ti, ti + bd->most + 1, ti + 2 * (bd->most + 1), n,
		    max);
		memcpy(fill, p->soff + r * bw, bw * sizeof *fill);
		for (size_t j = 0; j < n; j++) {
			uint32_t x = ti[j] & (m->w - 1), y = ti[j] >> lw;
			uint32_t at = fill[x >> lb]++;
			p->sval[at] = tk[j];
			p->sidx[at] = y << lb | (x & (b - 1));
		}
	}
	free(t);
	free(fill);
	return 0;
}

/* Whether the lists of the values below `below` in blocks of b come
 * faster by bands than through the inverse (sorted_below): from a 32nd
 * of the values on, in 8 bands or more (fewer keep threads idle and sort
 * more than fits a cache).  On a 2048^2 matrix, 2-core x86-64, b 16 and
 * 2^20 values: 18 ms by the inverse, 11 by bands (12.6 and 6 on two
 * threads); below 2^17 values the inverse's one read of the matrix
 * wins. */
static int by_bands(const struct frs_matrix *m, uint32_t b, uint64_t below)
{
	return below >= m->n / 32 && below > 0 && m->h / b >= 8;
}

/* The lists of the values below `below` (at least 1, at most half the
 * matrix's values) by bands.  0, or -1 after frs_fail. */
static int bands_below(struct frs_prep *p, uint64_t below)
{
	const struct frs_matrix *m = p->m;
	uint32_t b = p->block, bw = m->w / b, nband = m->h / b;
	struct bands bd = { p, below, 0 };
	uint64_t nblk = (uint64_t)bw * nband;

	memset(p->soff, 0, (nblk + 1) * sizeof *p->soff);
	if (frs_parallel(nband, 1, count_band, &bd, NULL) < 0)
		return -1;
	for (uint64_t k = 0; k < nblk; k++)
		p->soff[k + 1] += p->soff[k];
	for (uint64_t r = 0; r < nband; r++) {
		uint64_t c = p->soff[(r + 1) * bw] - p->soff[r * bw];
		bd.most = c > bd.most ? c : bd.most;
	}
	p->sval = malloc((p->soff[nblk] + 1) * sizeof *p->sval);
	p->sidx = malloc((p->soff[nblk] + 1) * sizeof *p->sidx);
	if (p->sval == NULL || p->sidx == NULL)
		return frs_fail("out of memory for the sorted lists");
	return frs_parallel(nband, 1, place_band, &bd, NULL);
}

/* Lists of the values below `below` alone, by counting over an inverse
 * of that many values; 1 when the values below repeat (the complete
 * lists then sort them), 0 done, -1 failed. */
static int sorted_below(struct frs_prep *p, uint64_t below)
{
	const struct frs_matrix *m = p->m;
	uint64_t nt = (uint64_t)frs_threads(), kept = 0, distinct = 0;
	struct invert iv = { m->v, NULL, below, 0, NULL };
	int rc;

	nt = nt < 1 ? 1 : nt;
	iv.span = (m->n + nt - 1) / nt;
	iv.inv = malloc((size_t)(below + 1) * sizeof *iv.inv);
	iv.kept = calloc(nt, sizeof *iv.kept);
	if (iv.inv == NULL || iv.kept == NULL) {
		free(iv.inv);
		free(iv.kept);
		return frs_fail("out of memory for the sorted lists");
	}
	memset(iv.inv, 0xff, (size_t)below * sizeof *iv.inv);	/* NO_ELEM */
	rc = frs_parallel(m->n, iv.span, invert_below_task, &iv, NULL);
	for (uint64_t t = 0; t < nt; t++)
		kept += iv.kept[t];
	for (uint64_t v = 0; v < below; v++)
		distinct += iv.inv[v] != NO_ELEM;
	if (rc == 0 && kept != distinct)
		rc = 1;
	else if (rc == 0 && (below < frs_deal_below ||
	    m->n / ((uint64_t)p->block * p->block) > ONE_PASS_BLOCKS))
		rc = deal_below(p, iv.inv, below);
	else if (rc == 0)
		rc = count_sort(p, iv.inv, below);
	free(iv.inv);
	free(iv.kept);
	return rc;
}

/* Listing 5.10, keeping every element of a block (no n_t cap: the
 * thesis's cap 2 n_s^2 / sigma^2 is 0 for n_s < sigma and too small for
 * some blocks, and a sample lost there is a bias).  O(S_M^2) for any
 * block size, in parallel over block rows: many small blocks by
 * bands (place_band); few large ones of a permutation (every matrix read through
 * frd(5)) by counting over the inverse permutation; others by qsort.
 * The values below `below` alone, when they are fewer than half, in
 * lists of just those values: by bands (bands_below) or through their
 * inverse (sorted_below), as by_bands finds faster. */
static int make_sorted(struct frs_prep *p, uint32_t b, uint64_t below)
{
	const struct frs_matrix *m = p->m;
	uint64_t nblk = (uint64_t)(m->w / b) * (m->h / b), bb = (uint64_t)b * b;
	uint32_t *inv = NULL;
	struct num_vi *tmp = NULL;
	int rc = 0;

	p->block = b;
	p->below = FRS_ALL_VALUES;
	if ((p->soff = malloc((nblk + 1) * sizeof *p->soff)) == NULL)
		return frs_fail("out of memory for the sorted lists");
	if (below < m->n / 2 && by_bands(m, b, below)) {
		if ((rc = bands_below(p, below)) == 0)
			p->below = below;
		return rc;
	}
	if (below < m->n / 2) {
		p->sval = malloc((below + 1) * sizeof *p->sval);
		p->sidx = malloc((below + 1) * sizeof *p->sidx);
		if (p->sval == NULL || p->sidx == NULL)
			return frs_fail("out of memory for the sorted lists");
		if ((rc = sorted_below(p, below)) <= 0) {
			if (rc == 0)
				p->below = below;
			return rc;
		}
		free(p->sval);	/* repeated values: the complete lists */
		free(p->sidx);
		rc = 0;
	}
	p->sval = mem_big(m->n * sizeof *p->sval);
	p->sidx = mem_big(m->n * sizeof *p->sidx);
	if (p->sval == NULL || p->sidx == NULL)
		return frs_fail("out of memory for the sorted lists");
	for (uint64_t k = 0; k <= nblk; k++)
		p->soff[k] = (uint32_t)(k * bb);
	if (nblk > ONE_PASS_BLOCKS) {
		struct bands bd = { p, (uint64_t)1 << 32, (uint64_t)m->w * b };
		rc = frs_parallel(m->h / b, 1, place_band, &bd, NULL);
	} else if ((inv = mem_big(m->n * sizeof *inv)) == NULL)
		rc = frs_fail("out of memory for the sorted lists");
	else if (is_permutation(m)) {
		uint64_t nt = (uint64_t)frs_threads();
		struct invert iv = { m->v, inv, 0, 0, NULL };
		nt = nt < 1 ? 1 : nt;
		rc = frs_parallel(m->n, (m->n + nt - 1) / nt, invert_task, &iv,
		    NULL);
		if (rc == 0)
			rc = count_sort(p, inv, m->n);
	} else if ((tmp = malloc((size_t)b * b * sizeof *tmp)) == NULL)
		rc = frs_fail("out of memory for the sorted lists");
	else
		sort_blocks(p, tmp);
	free(inv);
	free(tmp);
	return rc;
}

int frs_prepare(struct frs_prep *p, const struct frs_matrix *m, int minmap,
    uint32_t block)
{
	return frs_prepare_below(p, m, minmap, block, FRS_ALL_VALUES);
}

int frs_prepare_below(struct frs_prep *p, const struct frs_matrix *m,
    int minmap, uint32_t block, uint64_t below)
{
	memset(p, 0, sizeof *p);
	p->m = m;
	p->lev[0] = m->v;
	p->nlev = 1;
	if ((minmap || block) && (!num_is_pow2(m->w) || !num_is_pow2(m->h)))
		return frs_fail("the matrix is %ux%u: the minmap and sorted "
		    "implementations need power-of-two sides (naive does not)",
		    m->w, m->h);
	if (block && (block > m->w || block > m->h || !num_is_pow2(block)))
		return frs_fail("sorted blocks of %u do not fit the %ux%u matrix",
		    block, m->w, m->h);
	if ((minmap && make_minmap(p) < 0) || (block && make_sorted(p, block, below) < 0)) {
		frs_prep_free(p);
		return -1;
	}
	return 0;
}
