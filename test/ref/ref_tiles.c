/*
 * ref_tiles: the measures of tiling (issue: no visible repetition on HDR
 * maps), for the tests and scripts/bench-frs.sh.  Points are window
 * elements: without jitter a point lies at the centre of element
 * (floor(x W), floor(y H)) of the W x H window (frs-sample -v prints it).
 *
 *   ref_tiles repeat W H FILE
 *       the share of samples whose neighbourhood recurs: the difference
 *       vectors (in elements) to its 4 nearest neighbours (and any tied
 *       with the 4th) equal another sample's up to the 8 symmetries of
 *       the square, at any displacement
 *   ref_tiles seams W H MW MH WX WY FILE
 *       nearest-neighbour distances in local spacings, sqrt(W H / (n
 *       pdf)) from the third column (frs-sample --pdf), of the samples
 *       within half a spacing of a border of the MW x MH tiles of the
 *       window at offset (WX, WY), against the others: counts, 1st
 *       percentiles and their ratio
 *   ref_tiles chi2 BX BY MAP [--equirect] FILE
 *       the counts of BX x BY blocks of [0,1)^2 against n I / sum I of
 *       the map (bins below 5 expected pooled): chi-square, df, p
 *       (Wilson-Hilferty)
 *   ref_tiles band Y0 Y1 FILE...
 *       the lattice of the dark parts of a map: per file, the m samples
 *       with Y0 < y < Y1, their band rescaled to the unit square (y' =
 *       (y - Y0) / (Y1 - Y0)), and the largest value of their periodogram
 *       P(k) = |sum_j exp(-2 pi i k.x_j)|^2 / m over the integer
 *       frequencies |kx|, |ky| <= 64 with |k| >= 3 (below, the density of
 *       the band shows), and where it is:
 *           FILE m M pmax P k KX KY
 *       (pmax 0 when m is 0).  A lattice gives about m, hundreds; blue
 *       noise 10 to 40, white noise about 10 (the largest of some 8000
 *       exponentials of mean 1): it tells a lattice from noise, nn tells
 *       blue noise from white.  Made for some 10^3 samples in the band
 *       (16384 on a sunset, rows 0.6 to 0.9): with 10^4 and more, the
 *       band's own density grows past 100 at |k| of 3 or 4, and a lattice
 *       finer than 64 a band falls outside; k tells which
 *   ref_tiles nn MAP [--equirect] [-s WxH] [--level-col NAME] FILE...
 *       per file, nearest-neighbour distances in local spacings: with the
 *       map of W x H pixels (its own size or -s WxH; loaded as chi2 does),
 *       the pixel coordinates q = (x W, y H) and the expected samples per
 *       pixel at the sample's pixel, dens = n I / sum I,
 *       r = |q - q_nn| sqrt(dens); its 1st, 5th and 10th percentiles (the
 *       value at floor(p (n - 1)) sorted, as seams takes them) and mean:
 *           FILE n N p1 A p5 B p10 C mean D
 *       With --level-col NAME, an extra column of the file (the level of
 *       a multi-level window), the line goes on with the "seam" samples,
 *       which have a neighbour of another value of NAME within 1.5 local
 *       spacings (1.5 / sqrt(dens) pixels; none in a pixel of zero
 *       importance), and the others: count, 1st and 5th percentiles
 *           ... seam N p1 A p5 B other N p1 A p5 B
 *       (nan for an empty group)
 *   ref_tiles pdf MAP [--equirect] [-s WxH] FILE...
 *       every sample's pdf column (frs-sample --pdf) against I / mean I
 *       of the map at the sample's pixel: FILE n N worst D, the largest
 *       relative difference; exit 1 when it passes 1e-12
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/err.h"
#include "base/num.h"
#include "base/parse.h"
#include "maps/imap.h"
#include "maps/mapload.h"
#include "cli/ptsio.h"

static void die(const char *msg)
{
	fprintf(stderr, "ref_tiles: %s\n", msg);
	exit(1);
}

static void *xcalloc(size_t n, size_t s)
{
	void *p = calloc(n ? n : 1, s);
	if (p == NULL)
		die("out of memory");
	return p;
}

static void load(const char *path, struct frs_points *s)
{
	if (pts_read(path, s) < 0) {
		fprintf(stderr, "ref_tiles: %s\n", frs_errmsg());
		exit(1);
	}
	if (s->dims != 2)
		die("2-D points only");
}

/* ---- a grid of points for neighbour queries ------------------------- */

struct grid {
	int64_t *x, *y;		/* element coordinates */
	size_t n;
	int64_t cell;
	size_t gw, gh;
	size_t *start, *item;	/* points of cell c: item[start[c]..start[c+1]) */
};

static void grid_make(struct grid *g, int64_t cell, int64_t w, int64_t h)
{
	size_t *cnt;

	g->cell = cell;
	g->gw = (size_t)(w / cell + 1);
	g->gh = (size_t)(h / cell + 1);
	g->start = xcalloc(g->gw * g->gh + 1, sizeof *g->start);
	g->item = xcalloc(g->n, sizeof *g->item);
	cnt = xcalloc(g->gw * g->gh, sizeof *cnt);
	for (size_t i = 0; i < g->n; i++)
		cnt[(size_t)(g->y[i] / cell) * g->gw + (size_t)(g->x[i] / cell)]++;
	for (size_t c = 0; c < g->gw * g->gh; c++)
		g->start[c + 1] = g->start[c] + cnt[c];
	memset(cnt, 0, g->gw * g->gh * sizeof *cnt);
	for (size_t i = 0; i < g->n; i++) {
		size_t c = (size_t)(g->y[i] / cell) * g->gw + (size_t)(g->x[i] / cell);
		g->item[g->start[c] + cnt[c]++] = i;
	}
	free(cnt);
}

/* The k nearest other points of point i (squared distances d2, indices
 * nb), k <= 16, searching rings of cells until the k-th is certain. */
static size_t grid_knn(const struct grid *g, size_t i, size_t k, int64_t *d2,
    size_t *nb)
{
	int64_t cx = g->x[i] / g->cell, cy = g->y[i] / g->cell;
	size_t m = 0;

	for (int64_t r = 0; r < (int64_t)(g->gw + g->gh); r++) {
		for (int64_t yy = cy - r; yy <= cy + r; yy++)
			for (int64_t xx = cx - r; xx <= cx + r; xx++) {
				size_t c;
				if ((yy != cy - r && yy != cy + r && xx != cx - r &&
				    xx != cx + r) || xx < 0 || yy < 0 ||
				    xx >= (int64_t)g->gw || yy >= (int64_t)g->gh)
					continue;
				c = (size_t)yy * g->gw + (size_t)xx;
				for (size_t q = g->start[c]; q < g->start[c + 1]; q++) {
					size_t j = g->item[q], p;
					int64_t dx = g->x[j] - g->x[i], dy = g->y[j] - g->y[i];
					int64_t dd = dx * dx + dy * dy;
					if (j == i)
						continue;
					/* insertion into the sorted k best */
					if (m == k && dd >= d2[k - 1])
						continue;
					p = m < k ? m++ : k - 1;
					while (p > 0 && d2[p - 1] > dd) {
						d2[p] = d2[p - 1];
						nb[p] = nb[p - 1];
						p--;
					}
					d2[p] = dd;
					nb[p] = j;
				}
			}
		/* every point outside the rings seen is at least r cells away */
		if (m == k && d2[k - 1] <= (r * g->cell) * (r * g->cell))
			break;
	}
	return m;
}

/* Whether a point within distance rad (elements) of point i has another
 * value in v (one per point): a scan of the cells the disc touches. */
static int grid_mixed(const struct grid *g, size_t i, double rad,
    const double *v)
{
	double r2 = rad * rad;
	/* no point lies farther than the grid reaches */
	double far = (double)(g->gw + g->gh) * (double)g->cell;
	int64_t d = (int64_t)ceil(fmin(rad, far));
	int64_t x0 = (g->x[i] - d) / g->cell, x1 = (g->x[i] + d) / g->cell;
	int64_t y0 = (g->y[i] - d) / g->cell, y1 = (g->y[i] + d) / g->cell;

	x0 = x0 < 0 ? 0 : x0;
	y0 = y0 < 0 ? 0 : y0;
	x1 = x1 < (int64_t)g->gw ? x1 : (int64_t)g->gw - 1;
	y1 = y1 < (int64_t)g->gh ? y1 : (int64_t)g->gh - 1;
	for (int64_t yy = y0; yy <= y1; yy++)
		for (int64_t xx = x0; xx <= x1; xx++) {
			size_t c = (size_t)yy * g->gw + (size_t)xx;
			for (size_t q = g->start[c]; q < g->start[c + 1]; q++) {
				size_t j = g->item[q];
				double dx = (double)(g->x[j] - g->x[i]);
				double dy = (double)(g->y[j] - g->y[i]);
				if (v[j] != v[i] && dx * dx + dy * dy <= r2)
					return 1;
			}
		}
	return 0;
}

static void grid_free(struct grid *g)
{
	free(g->start);
	free(g->item);
}

/* Points of set 0 as elements of the W x H window. */
static void to_elems(const struct frs_points *s, int64_t w, int64_t h,
    struct grid *g)
{
	g->n = s->n;
	g->x = xcalloc(g->n, sizeof *g->x);
	g->y = xcalloc(g->n, sizeof *g->y);
	for (size_t i = 0; i < g->n; i++) {
		const double *r = s->x + i * (s->dims + s->extra);
		g->x[i] = (int64_t)floor(r[0] * (double)w);
		g->y[i] = (int64_t)floor(r[1] * (double)h);
	}
}

/* The points of path as elements of the W x H window, at least min of
 * them (what names the mode), in a grid of cells of about a spacing. */
static void load_grid(const char *path, int64_t w, int64_t h, size_t min,
    const char *what, struct frs_points *s, struct grid *g)
{
	char msg[64];

	load(path, s);
	to_elems(s, w, h, g);
	if (g->n < min) {
		snprintf(msg, sizeof msg, "%s: fewer than %zu points", what, min);
		die(msg);
	}
	grid_make(g, (int64_t)fmax(1.0, sqrt((double)w * (double)h /
	    (double)g->n)), w, h);
}

static void grid_done(struct grid *g, struct frs_points *s)
{
	grid_free(g);
	free(g->x);
	free(g->y);
	pts_free(s);
}

/* ---- repeat ------------------------------------------------------- */

#define KEYLEN 16	/* up to 8 neighbours (4 and ties), dx dy each */

struct key {
	int64_t v[KEYLEN];
	size_t i;
};

static int vec_cmp(const void *a, const void *b)
{
	const int64_t *x = a, *y = b;

	return x[0] != y[0] ? NUM_CMP(x[0], y[0]) : NUM_CMP(x[1], y[1]);
}

static int key_cmp(const void *a, const void *b)
{
	const struct key *x = a, *y = b;
	for (int k = 0; k < KEYLEN; k++)
		if (x->v[k] != y->v[k])
			return x->v[k] < y->v[k] ? -1 : 1;
	return 0;
}

/* The canonical key of m difference vectors: the least, over the 8
 * symmetries, of the sorted transformed vectors. */
static void canon(const int64_t *d, size_t m, struct key *out)
{
	int64_t best[KEYLEN], t[KEYLEN];

	for (int s = 0; s < 8; s++) {
		memset(t, 0, sizeof t);
		for (size_t j = 0; j < m; j++) {
			int64_t x = d[2 * j], y = d[2 * j + 1], u;
			if (s & 4) {
				u = x;
				x = y;
				y = u;
			}
			t[2 * j] = (s & 1) ? -x : x;
			t[2 * j + 1] = (s & 2) ? -y : y;
		}
		qsort(t, m, 2 * sizeof *t, vec_cmp);
		if (s == 0 || memcmp(t, best, sizeof t) < 0) {
			/* memcmp order is only a tie-break; any fixed total
			 * order gives a canonical key */
			memcpy(best, t, sizeof t);
		}
	}
	for (size_t j = m; j < KEYLEN / 2; j++)
		best[2 * j] = best[2 * j + 1] = INT64_MIN;
	memcpy(out->v, best, sizeof best);
}

static void repeat(int64_t w, int64_t h, const char *path)
{
	struct frs_points s;
	struct grid g;
	struct key *key;
	size_t rep = 0;

	load_grid(path, w, h, 6, "repeat", &s, &g);
	key = xcalloc(g.n, sizeof *key);
	for (size_t i = 0; i < g.n; i++) {
		int64_t d2[8], d[KEYLEN];
		size_t nb[8], m = grid_knn(&g, i, 8, d2, nb), k = 4;
		while (k < m && d2[k] == d2[3])
			k++;	/* ties with the 4th */
		for (size_t j = 0; j < k; j++) {
			d[2 * j] = g.x[nb[j]] - g.x[i];
			d[2 * j + 1] = g.y[nb[j]] - g.y[i];
		}
		canon(d, k, &key[i]);
		key[i].i = i;
	}
	qsort(key, g.n, sizeof *key, key_cmp);
	for (size_t i = 0; i < g.n; i++)
		if ((i > 0 && key_cmp(&key[i - 1], &key[i]) == 0) ||
		    (i + 1 < g.n && key_cmp(&key[i + 1], &key[i]) == 0))
			rep++;
	printf("n %zu repeated %zu share %.6f\n", g.n, rep,
	    (double)rep / (double)g.n);
	free(key);
	grid_done(&g, &s);
}

/* ---- seams -------------------------------------------------------- */

static int dbl_cmp(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

static double pct(double *v, size_t n, double p)
{
	if (n == 0)
		return NAN;
	qsort(v, n, sizeof *v, dbl_cmp);
	return v[(size_t)(p * (double)(n - 1))];
}

/* Distance of coordinate c + 1/2 to the nearest multiple of m after the
 * offset o (a border of the tiles). */
static double border_dist(int64_t c, int64_t m, int64_t o)
{
	double r = fmod((double)(c + o) + 0.5, (double)m);
	return fmin(r, (double)m - r);
}

static void seams(int64_t w, int64_t h, int64_t mw, int64_t mh, int64_t wx,
    int64_t wy, const char *path)
{
	struct frs_points s;
	struct grid g;
	double *nearv, *farv;
	size_t nn = 0, nf = 0;

	load_grid(path, w, h, 2, "seams", &s, &g);
	if (s.extra < 1)
		die("seams: the file needs a pdf column (frs-sample --pdf)");
	nearv = xcalloc(g.n, sizeof *nearv);
	farv = xcalloc(g.n, sizeof *farv);
	for (size_t i = 0; i < g.n; i++) {
		double pdf = s.x[i * (s.dims + s.extra) + 2];
		double sp = sqrt((double)w * (double)h / ((double)g.n * pdf));
		double b = fmin(border_dist(g.x[i], mw, wx),
		    border_dist(g.y[i], mh, wy));
		int64_t d2 = 0;
		size_t nb;
		if (grid_knn(&g, i, 1, &d2, &nb) == 0)
			continue;	/* a lone point has no spacing */
		if (b < 0.5 * sp)
			nearv[nn++] = sqrt((double)d2) / sp;
		else
			farv[nf++] = sqrt((double)d2) / sp;
	}
	{
		double qn = pct(nearv, nn, 0.01), qf = pct(farv, nf, 0.01);
		printf("near %zu q01 %.4f far %zu q01 %.4f ratio %.4f\n", nn, qn,
		    nf, qf, qn / qf);
	}
	free(nearv);
	free(farv);
	grid_done(&g, &s);
}

/* ---- maps --------------------------------------------------------- */

/* The map at w x h (0 x 0: its own size); flags: IMAP_*. */
static void map_load(const char *map, uint32_t w, uint32_t h, int flags,
    struct frs_imap *m)
{
	if (imap_load(map, w, h, flags, m) < 0) {
		fprintf(stderr, "ref_tiles: %s\n", frs_errmsg());
		exit(1);
	}
}

/* Pixel value as importance: a negative one counts as none. */
static double imp(const struct frs_imap *m, size_t p)
{
	return m->v[p] > 0.0 ? m->v[p] : 0.0;
}

/* ---- chi2 --------------------------------------------------------- */

static void chi2(int bx, int by, const char *map, int flags, const char *path)
{
	struct frs_points s;
	struct frs_imap m;
	size_t nbin = (size_t)bx * (size_t)by, n, df = 0;
	double *e = xcalloc(nbin, sizeof *e), tot = 0.0, x2 = 0.0;
	double *o = xcalloc(nbin, sizeof *o), pe = 0.0, po = 0.0;

	load(path, &s);
	map_load(map, 0, 0, flags, &m);
	for (uint32_t y = 0; y < m.h; y++)
		for (uint32_t x = 0; x < m.w; x++) {
			size_t b = (size_t)((uint64_t)y * (uint64_t)by / m.h) * (size_t)bx +
			    (size_t)((uint64_t)x * (uint64_t)bx / m.w);
			double v = imp(&m, (size_t)y * m.w + x);
			e[b] += v;
			tot += v;
		}
	n = s.n;
	for (size_t i = 0; i < n; i++) {
		const double *r = s.x + i * (s.dims + s.extra);
		int cx = (int)(r[0] * bx), cy = (int)(r[1] * by);
		o[(size_t)(cy < by ? cy : by - 1) * (size_t)bx +
		    (size_t)(cx < bx ? cx : bx - 1)] += 1.0;
	}
	for (size_t b = 0; b < nbin; b++) {
		double ex = e[b] / tot * (double)n;
		if (ex < 5.0) {
			pe += ex;
			po += o[b];
			continue;
		}
		x2 += (o[b] - ex) * (o[b] - ex) / ex;
		df++;
	}
	if (pe > 0.0) {
		x2 += (po - pe) * (po - pe) / pe;
		df++;
	}
	df = df > 1 ? df - 1 : 1;
	{
		/* Wilson-Hilferty: (x2/df)^(1/3) is normal with mean
		 * 1 - 2/(9 df) and variance 2/(9 df). */
		double v = 2.0 / (9.0 * (double)df);
		double z = (cbrt(x2 / (double)df) - (1.0 - v)) / sqrt(v);
		printf("n %zu chi2 %.3f df %zu p %.3g\n", n, x2, df,
		    0.5 * erfc(z / sqrt(2.0)));
	}
	imap_free(&m);
	free(e);
	free(o);
	pts_free(&s);
}

/* ---- band --------------------------------------------------------- */

#define KMAX 64			/* frequencies |kx|, |ky| <= KMAX */
#define KN (2 * KMAX + 1)
#define KMIN2 9			/* |k| < 3: the band's density, not its
				 * structure */
#define BLK 32			/* points per block of the product */

/* f += sum over 4 points j of a_j b_j, over n complex values kept as
 * real and imaginary rows (b_j at b + j stride): four points a pass, so
 * that f is loaded and stored a quarter as often. */
static void cmadd4(double *restrict fr, double *restrict fi,
    const double *ar, const double *ai, const double *restrict br,
    const double *restrict bi, size_t stride, size_t n)
{
	const double *b0 = br, *b1 = br + stride, *b2 = br + 2 * stride;
	const double *b3 = br + 3 * stride, *c0 = bi, *c1 = bi + stride;
	const double *c2 = bi + 2 * stride, *c3 = bi + 3 * stride;

	for (size_t k = 0; k < n; k++) {
		fr[k] += ar[0] * b0[k] - ai[0] * c0[k] + ar[1] * b1[k] -
		    ai[1] * c1[k] + ar[2] * b2[k] - ai[2] * c2[k] +
		    ar[3] * b3[k] - ai[3] * c3[k];
		fi[k] += ar[0] * c0[k] + ai[0] * b0[k] + ar[1] * c1[k] +
		    ai[1] * b1[k] + ar[2] * c2[k] + ai[2] * b2[k] +
		    ar[3] * c3[k] + ai[3] * b3[k];
	}
}

/* exp(-2 pi i k t) for k = 0 .. KMAX into c, s (every stride-th): the
 * powers of one rotation, far cheaper than a cos and sin per k, at a
 * rounding error of about KMAX ulp. */
static void rot(double t, double *c, double *s, size_t stride)
{
	double wc = cos(2.0 * NUM_PI * t), ws = -sin(2.0 * NUM_PI * t);

	c[0] = 1.0;
	s[0] = 0.0;
	for (size_t k = 1; k <= KMAX; k++) {
		double pc = c[(k - 1) * stride], ps = s[(k - 1) * stride];
		c[k * stride] = pc * wc - ps * ws;
		s[k * stride] = pc * ws + ps * wc;
	}
}

/* F(ky, kx) += sum over the nb points (x, y) of a block of
 * exp(-2 pi i (kx x + ky y)), ky = 0 .. KMAX (P(-k) = P(k) for real
 * points), kx = -KMAX .. KMAX: the K x nb by nb x K product. */
static void band_block(const double *x, const double *y, size_t nb,
    double *fr, double *fi)
{
	static double ar[(KMAX + 1) * BLK], ai[(KMAX + 1) * BLK];
	static double br[BLK * KN], bi[BLK * KN];

	for (size_t j = 0; j < nb; j++) {
		double *c = br + j * KN + KMAX, *sn = bi + j * KN + KMAX;
		rot(y[j], ar + j, ai + j, BLK);
		rot(x[j], c, sn, 1);
		for (size_t k = 1; k <= KMAX; k++) {	/* conjugates */
			c[-(ptrdiff_t)k] = c[k];
			sn[-(ptrdiff_t)k] = -sn[k];
		}
	}
	/* pad to a multiple of 4 points of weight 0 */
	for (size_t j = nb; j % 4; j++) {
		for (size_t k = 0; k <= KMAX; k++)
			ar[k * BLK + j] = ai[k * BLK + j] = 0.0;
		memset(br + j * KN, 0, KN * sizeof *br);
		memset(bi + j * KN, 0, KN * sizeof *bi);
	}
	for (size_t ky = 0; ky <= KMAX; ky++)
		for (size_t j = 0; j < nb; j += 4)
			cmadd4(fr + ky * KN, fi + ky * KN, ar + ky * BLK + j,
			    ai + ky * BLK + j, br + j * KN, bi + j * KN, KN,
			    KN);
}

/* The samples with y0 < y < y1, the band rescaled to the unit square:
 * the largest periodogram value |F(k)|^2 / m over |k| >= 3. */
static void band(double y0, double y1, const char *path)
{
	struct frs_points s;
	double *fr = xcalloc((KMAX + 1) * KN, sizeof *fr);
	double *fi = xcalloc((KMAX + 1) * KN, sizeof *fi);
	double bx[BLK], by[BLK], best = 0.0;
	size_t m = 0, nb = 0;
	long kx = 0, ky = 0;

	load(path, &s);
	for (size_t i = 0; i < s.n; i++) {
		const double *r = s.x + i * (s.dims + s.extra);
		if (!(r[1] > y0 && r[1] < y1))
			continue;
		bx[nb] = r[0];
		by[nb++] = (r[1] - y0) / (y1 - y0);
		m++;
		if (nb == BLK) {
			band_block(bx, by, nb, fr, fi);
			nb = 0;
		}
	}
	band_block(bx, by, nb, fr, fi);
	for (long v = 0; v <= KMAX; v++)
		for (long u = -KMAX; u <= KMAX; u++) {
			size_t c = (size_t)v * KN + (size_t)(u + KMAX);
			double p = (fr[c] * fr[c] + fi[c] * fi[c]) /
			    (double)(m ? m : 1);
			if (u * u + v * v >= KMIN2 && p > best) {
				best = p;
				kx = u;
				ky = v;
			}
		}
	printf("%s m %zu pmax %.4g k %ld %ld\n", path, m, best, kx, ky);
	free(fr);
	free(fi);
	pts_free(&s);
}

/* ---- nn ----------------------------------------------------------- */

/* Grid elements per map pixel: fine enough for spacings far below a
 * pixel, coarse enough that squared distances fit int64. */
static int64_t nn_scale(const struct frs_imap *m)
{
	return ((int64_t)1 << 30) / (int64_t)(m->w > m->h ? m->w : m->h);
}

/* The map's expected samples per pixel at the pixel of record r, for n
 * samples over total importance tot. */
static double nn_dens(const struct frs_imap *m, double tot, size_t n,
    const double *r)
{
	size_t px = (size_t)(r[0] * m->w), py = (size_t)(r[1] * m->h);

	px = px < m->w ? px : m->w - 1;
	py = py < m->h ? py : m->h - 1;
	return (double)n * imp(m, py * m->w + px) / tot;
}

static void print_pcts(const char *what, double *v, size_t n)
{
	printf(" %s %zu p1 %.4f p5 %.4f", what, n, pct(v, n, 0.01),
	    pct(v, n, 0.05));
}

/* Nearest-neighbour distances in local spacings, r = |q - q_nn|
 * sqrt(dens) in pixels q of the map m (total importance tot); with a
 * column col, apart for the samples with another value of it within 1.5
 * local spacings (seams between levels) and the others. */
static void nn(const struct frs_imap *m, double tot, const char *col,
    const char *path)
{
	struct frs_points s;
	struct grid g;
	int64_t f = nn_scale(m);
	double *r, *lv = NULL, *seam = NULL, *other = NULL, sum = 0.0;
	size_t ns = 0, no = 0;
	int c = -1;

	load_grid(path, (int64_t)m->w * f, (int64_t)m->h * f, 2, "nn", &s, &g);
	if (col != NULL && (c = pts_column(&s, col)) < 0) {
		fprintf(stderr, "ref_tiles: %s: no column %s\n", path, col);
		exit(1);
	}
	r = xcalloc(g.n, sizeof *r);
	if (c >= 0) {
		lv = xcalloc(g.n, sizeof *lv);
		seam = xcalloc(g.n, sizeof *seam);
		other = xcalloc(g.n, sizeof *other);
		for (size_t i = 0; i < g.n; i++)
			lv[i] = s.x[i * (s.dims + s.extra) + (size_t)c];
	}
	for (size_t i = 0; i < g.n; i++) {
		const double *rec = s.x + i * (s.dims + s.extra);
		double dens = nn_dens(m, tot, g.n, rec);
		int64_t d2 = 0;
		size_t nb;
		grid_knn(&g, i, 1, &d2, &nb);
		r[i] = sqrt((double)d2) / (double)f * sqrt(dens);
		sum += r[i];
		if (c < 0)
			continue;
		/* in a pixel of no importance there is no spacing */
		if (dens > 0.0 && grid_mixed(&g, i, 1.5 / sqrt(dens) *
		    (double)f, lv))
			seam[ns++] = r[i];
		else
			other[no++] = r[i];
	}
	printf("%s n %zu p1 %.4f p5 %.4f p10 %.4f mean %.4f", path, g.n,
	    pct(r, g.n, 0.01), pct(r, g.n, 0.05), pct(r, g.n, 0.10),
	    sum / (double)g.n);
	if (c >= 0) {
		print_pcts("seam", seam, ns);
		print_pcts("other", other, no);
	}
	printf("\n");
	free(r);
	free(lv);
	free(seam);
	free(other);
	grid_done(&g, &s);
}

/* Every sample's pdf column against I / mean I of the map m (total
 * importance tot) at its pixel: the largest relative difference; exit 1
 * past 1e-12. */
static void pdfcheck(const struct frs_imap *m, double tot, const char *path)
{
	struct frs_points s;
	double mean = tot / ((double)m->w * m->h), worst = 0.0;
	int c;

	load(path, &s);
	if ((c = pts_column(&s, "pdf")) < 0) {
		fprintf(stderr, "ref_tiles: %s: no column pdf\n", path);
		exit(1);
	}
	for (size_t i = 0; i < s.n; i++) {
		const double *rec = s.x + i * (s.dims + s.extra);
		size_t px = (size_t)(rec[0] * m->w), py = (size_t)(rec[1] * m->h);
		double want = imp(m, py * m->w + px) / mean;
		double d = fabs(rec[c] - want) / (want > 1.0 ? want : 1.0);
		worst = d > worst ? d : worst;
	}
	printf("%s n %zu worst %.3g\n", path, s.n, worst);
	pts_free(&s);
	if (worst > 1e-12)
		exit(1);
}

/* ref_tiles nn|pdf MAP [--equirect] [-s WxH] [--level-col NAME] FILE... */
static void map_main(int argc, char **argv)
{
	struct frs_imap m;
	uint32_t w = 0, h = 0;
	const char *col = NULL;
	int flags = 0, a = 3;
	double tot = 0.0;

	for (; a < argc; a++) {
		if (strcmp(argv[a], "--equirect") == 0)
			flags |= FRS_MAP_EQUIRECT;
		else if (strcmp(argv[a], "-s") == 0 && a + 1 < argc) {
			if (parse_size("-s", argv[++a], FRS_MAP_MAX_SIDE, &w,
			    &h) < 0)
				die(frs_errmsg());
		} else if (strcmp(argv[a], "--level-col") == 0 && a + 1 < argc)
			col = argv[++a];
		else
			break;
	}
	if (a == argc)
		die("nn, pdf: no FILE");
	map_load(argv[2], w, h, flags, &m);
	for (size_t p = 0; p < (size_t)m.w * m.h; p++)
		tot += imp(&m, p);
	for (; a < argc; a++)
		if (strcmp(argv[1], "nn") == 0)
			nn(&m, tot, col, argv[a]);
		else
			pdfcheck(&m, tot, argv[a]);
	imap_free(&m);
}

static int64_t num(const char *s)
{
	char *end;
	long long v = strtoll(s, &end, 10);
	if (*s == '\0' || *end != '\0' || v < 0)
		die("bad number");
	return (int64_t)v;
}

int main(int argc, char **argv)
{
	if (argc == 5 && strcmp(argv[1], "repeat") == 0)
		repeat(num(argv[2]), num(argv[3]), argv[4]);
	else if (argc == 9 && strcmp(argv[1], "seams") == 0)
		seams(num(argv[2]), num(argv[3]), num(argv[4]), num(argv[5]),
		    num(argv[6]), num(argv[7]), argv[8]);
	else if ((argc == 6 || argc == 7) && strcmp(argv[1], "chi2") == 0)
		chi2((int)num(argv[2]), (int)num(argv[3]), argv[4],
		    argc == 7 && strcmp(argv[5], "--equirect") == 0 ?
		    FRS_MAP_EQUIRECT : 0, argv[argc - 1]);
	else if (argc >= 5 && strcmp(argv[1], "band") == 0) {
		double y0, y1;
		if (parse_double("Y0", argv[2], 0.0, 1.0, &y0) < 0 ||
		    parse_double("Y1", argv[3], 0.0, 1.0, &y1) < 0 || y1 <= y0)
			die("band: need 0 <= Y0 < Y1 <= 1");
		for (int a = 4; a < argc; a++)
			band(y0, y1, argv[a]);
	} else if (argc >= 4 && (strcmp(argv[1], "nn") == 0 ||
	    strcmp(argv[1], "pdf") == 0))
		map_main(argc, argv);
	else
		die("usage: ref_tiles repeat W H FILE | seams W H MW MH WX WY "
		    "FILE | chi2 BX BY MAP [--equirect] FILE | band Y0 Y1 "
		    "FILE... | nn MAP [--equirect] [-s WxH] [--level-col NAME] "
		    "FILE... | pdf MAP [--equirect] [-s WxH] FILE...");
	return 0;
}
