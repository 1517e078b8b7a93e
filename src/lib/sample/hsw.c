/*
 * Hierarchical Sample Warping: see hsw.h.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/err.h"
#include "sample/frscore.h"
#include "base/mem.h"
#include "base/num.h"
#include "sample/hsw.h"
#include "base/wide.h"
#include "base/par.h"
#include "base/rng.h"

/* BELOW_ONE, hsw_split, hsw_place and the descent of one point: one
 * definition with the kernel. */
#include "../../../cl/hsw.cl"

static uint64_t level_offset(unsigned l)
{
	return (((uint64_t)1 << (2 * l)) - 1) / 3;
}

/* Interleave the bits of x (even) and y (odd). */
static uint64_t morton(uint32_t x, uint32_t y)
{
	uint64_t r = 0;
	for (unsigned b = 0; b < 32 && (x >> b | y >> b); b++)
		r |= (uint64_t)(x >> b & 1) << (2 * b) |
		    (uint64_t)(y >> b & 1) << (2 * b + 1);
	return r;
}

/*
 * The power of two that the leaves are scaled by: 1 unless the largest
 * value lies outside [2^-900, 2^900], where the sums would overflow (a
 * map of 1e308) or the splits u (a + b) < a would round on a few bits of
 * denormals; only ratios matter, and scaling by a power of two keeps
 * them.  -1 with a message naming the first non-finite pixel.
 */
static int leaf_scale(const struct frs_imap *m, double *scale)
{
	double mx = 0.0;
	int e;

	for (uint64_t i = 0; i < (uint64_t)m->w * m->h; i++) {
		double v = m->v[i];
		if (!isfinite(v))
			return frs_fail("pixel (%llu, %llu) is %s",
			    (unsigned long long)(i % m->w),
			    (unsigned long long)(i / m->w),
			    isnan(v) ? "NaN" : "infinite");
		mx = v > mx ? v : mx;
	}
	*scale = 1.0;
	if (mx > 0.0 && !(mx >= 0x1p-900 && mx <= 0x1p900)) {
		e = -ilogb(mx);
		*scale = ldexp(1.0, e < 1023 ? e : 1023);
	}
	return 0;
}

int hsw_build(struct hsw_tree *t, const struct frs_imap *m)
{
	uint32_t side = m->w > m->h ? m->w : m->h;
	unsigned L = 0;
	uint64_t leaves, off;
	double *s, scale = 1.0;

	memset(t, 0, sizeof *t);
	while (((uint64_t)1 << L) < side)
		L++;
	leaves = (uint64_t)1 << (2 * L);
	if (leaves > HSW_MAX_PIXELS)
		return frs_fail("map %ux%u: the padded %llux%llu quadtree is "
		    "too large (at most 2^28 pixels)", m->w, m->h,
		    (unsigned long long)1 << L, (unsigned long long)1 << L);
	if (leaf_scale(m, &scale) < 0)
		return -1;
	if ((s = mem_calloc("quadtree", level_offset(L + 1), sizeof *s)) == NULL)
		return -1;
	off = level_offset(L);
	for (uint32_t j = 0; j < m->h; j++)
		for (uint32_t i = 0; i < m->w; i++) {
			double v = m->v[(uint64_t)j * m->w + i];
			s[off + morton(i, j)] = v > 0 ? v * scale : 0;
		}
	for (unsigned l = L; l > 0; l--) {
		uint64_t lo = level_offset(l), up = level_offset(l - 1);
		uint64_t nodes = (uint64_t)1 << (2 * (l - 1));
		for (uint64_t k = 0; k < nodes; k++) {
			const double *c = s + lo + 4 * k;
			s[up + k] = (c[0] + c[2]) + (c[1] + c[3]);
		}
	}
	if (!(s[0] > 0)) {
		free(s);
		return frs_fail("importance is zero everywhere");
	}
	t->w = m->w;
	t->h = m->h;
	t->size = (uint32_t)1 << L;
	t->levels = L;
	t->sum = s;
	t->total = s[0] / scale;	/* the map's own sum */
	return 0;
}

void hsw_free(struct hsw_tree *t)
{
	free(t->sum);
	memset(t, 0, sizeof *t);
}

uint64_t hsw_warp(const struct hsw_tree *t, double *x, double *y)
{
	return hsw_descend(t->sum, t->levels, t->w, t->h, x, y);
}

/* Points per chunk of frs_parallel: the unit handed to a thread. */
#define CHUNK 16384

/* Points per piece of input made at once inside a chunk: small enough
 * for the first-level cache. */
#define PIECE 256

/* num_radical_inverse (num.h), kept below 1. */
double hsw_radical_inverse(uint64_t i, unsigned b)
{
	return frs_below_one(num_radical_inverse(i, b));
}

/* Base-3 digits of a 64-bit integer. */
#define DIGITS3 41
/* The low digits whose part of the sum comes from a table: 3^6 = 729
 * sums (6 KiB, for the first-level cache). */
#define LOW3 6
#define LOW3N 729

/*
 * hsw_radical_inverse(i, 3) is r = 0 + d0 w0 + d1 w1 + ... in this order,
 * with weights w_k the rounded powers (1/3) (1/3) ...; a missing high
 * digit adds 0, which leaves r as it is.  The sum over the low LOW3
 * digits depends on i mod 3^LOW3 only (the table low), and the terms of
 * the high digits are the same over a run of 3^LOW3 indices: a run is a
 * copy from the table and a few additions of constants, vectorised, and
 * gives the loop's bits.
 */
struct base3 {
	double w[DIGITS3];
	double low[LOW3N];
};

static void base3_init(struct base3 *b)
{
	double inv = 1.0 / 3, f = inv;

	for (unsigned k = 0; k < DIGITS3; k++) {
		b->w[k] = f;
		f *= inv;
	}
	for (unsigned x = 0; x < LOW3N; x++) {
		double r = 0;
		for (unsigned k = 0, y = x; k < LOW3; k++, y /= 3)
			r += (double)(y % 3) * b->w[k];
		b->low[x] = r;
	}
}

/* hsw_radical_inverse(i, 3) for i = first .. first + m - 1 (m <= PIECE)
 * into out[0], out[2], ... */
FRS_WIDE static void radical_inverse3(const struct base3 *b, uint64_t first, size_t m,
    double *out)
{
	uint64_t hi = first / LOW3N;
	size_t lo = (size_t)(first % LOW3N);
	double r[PIECE];

	for (size_t q = 0; q < m; hi++, lo = 0) {
		size_t len = m - q < LOW3N - lo ? m - q : LOW3N - lo;
		double c[DIGITS3];
		unsigned nc = 0;

		for (uint64_t h = hi; h > 0; h /= 3, nc++)
			c[nc] = (double)(h % 3) * b->w[LOW3 + nc];
		for (size_t s = 0; s < len; s++)
			r[q + s] = b->low[lo + s];
		for (unsigned k = 0; k < nc; k++)
			for (size_t s = 0; s < len; s++)
				r[q + s] += c[k];
		q += len;
	}
	for (size_t q = 0; q < m; q++)
		out[2 * q] = r[q] < 1.0 ? r[q] : BELOW_ONE;
}

static uint64_t grid_side(uint64_t n)
{
	uint64_t k = (uint64_t)sqrt((double)n);

	while (k * k < n)
		k++;
	while (k > 1 && (k - 1) * (k - 1) >= n)
		k--;
	return k;
}

/* Cell centres (ox = oy = 0.5) or jittered points of the k x k grid for
 * indices begin .. end - 1: column and row counted, not divided. */
static void grid_range(int jitter, uint64_t n, uint64_t seed, uint64_t begin,
    uint64_t end, double *out)
{
	uint64_t k = grid_side(n), col = begin % k, row = begin / k;
	double dk = (double)k;

	for (uint64_t i = begin; i < end; i++) {
		double ox = 0.5, oy = 0.5;
		if (jitter) {
			ox = frs_rand01(seed, FRS_STREAM_HSW, 2 * i);
			oy = frs_rand01(seed, FRS_STREAM_HSW, 2 * i + 1);
		}
		out[0] = ((double)col + ox) / dk;
		out[1] = ((double)row + oy) / dk;
		out += 2;
		if (++col == k) {
			col = 0;
			row++;
		}
	}
}

/* The input points begin .. end - 1, in vectors as wide as the processor
 * has. */
FRS_WIDE static void piece_range(const struct base3 *b3, enum hsw_input kind,
    uint64_t n, uint64_t seed, uint64_t begin, uint64_t end, double *out)
{
	uint64_t m = end - begin;

	switch (kind) {
	case HSW_RANDOM:
		for (uint64_t i = begin; i < end; i++, out += 2) {
			out[0] = frs_rand01(seed, FRS_STREAM_HSW, 2 * i);
			out[1] = frs_rand01(seed, FRS_STREAM_HSW, 2 * i + 1);
		}
		return;
	case HSW_REGULAR:
	case HSW_JITTERED:
		grid_range(kind == HSW_JITTERED, n, seed, begin, end, out);
		return;
	case HSW_HALTON:
		for (uint64_t q = 0; q < m; q++)
			out[2 * q] = num_radical2(begin + q + 1);
		radical_inverse3(b3, begin + 1, (size_t)m, out + 1);
		return;
	case HSW_HAMMERSLEY:
		for (uint64_t q = 0; q < m; q++) {
			out[2 * q] = ((double)(begin + q) + 0.5) / (double)n;
			out[2 * q + 1] = num_radical2(begin + q);
		}
		return;
	}
}

/* hsw_input_range with the table of base 3 made (Halton only). */
static void input_range(const struct base3 *b3, enum hsw_input kind,
    uint64_t n, uint64_t seed, uint64_t begin, uint64_t end, double *out)
{
	for (uint64_t p = begin; p < end; p += PIECE) {
		uint64_t e = end - p < PIECE ? end : p + PIECE;
		double *o = out + 2 * (p - begin);

		piece_range(b3, kind, n, seed, p, e, o);
		/* The sets' formulas may round up to 1 (a cell centre of a
		 * huge grid, say): the largest double below it instead. */
		for (uint64_t q = 0; q < 2 * (e - p); q++)
			o[q] = o[q] < 1.0 ? o[q] : BELOW_ONE;
	}
}

void hsw_input_range(enum hsw_input kind, uint64_t n, uint64_t seed,
    uint64_t begin, uint64_t end, double *out)
{
	struct base3 b3;

	if (kind == HSW_HALTON)
		base3_init(&b3);
	input_range(&b3, kind, n, seed, begin, end, out);
}

struct input_job {
	enum hsw_input kind;
	uint64_t n, seed;
	double *out;
};

static int input_task(void *ctx, uint64_t begin, uint64_t end)
{
	const struct input_job *job = ctx;

	hsw_input_range(job->kind, job->n, job->seed, begin, end,
	    job->out + 2 * begin);
	return 0;
}

void hsw_input_make(enum hsw_input kind, uint64_t n, uint64_t seed,
    double *out)
{
	struct input_job job = { kind, n, seed, out };

	frs_parallel(n, CHUNK, input_task, &job, NULL);
}

/*
 * The warp of many points, written to be vectorised: points in groups of
 * GROUP, level by level (their descents are independent chains of
 * divisions that the processor overlaps, or that one vector instruction
 * does together), no branch on a choice.  The results are split's and
 * place's, bit for bit: with f = 0 or 1 and sums finite and not negative,
 * split's t - f a is exactly t or t - a, and f b + (1 - f) a exactly a or
 * b, which pick chooses; the second split's c[cx] + c[cx + 2] is the
 * first split's a or b.
 */
#define GROUP 16

/* x where c is 1, y where c is 0, by the bits: neither a branch on a
 * coin toss, which a scalar build would make of a select, nor
 * arithmetic. */
static inline double pick(int c, double x, double y)
{
	uint64_t m = (uint64_t)0 - (uint64_t)c, bx, by;
	double r;

	memcpy(&bx, &x, sizeof bx);
	memcpy(&by, &y, sizeof by);
	bx = (bx & m) | (by & ~m);
	memcpy(&r, &bx, sizeof r);
	return r;
}

FRS_WIDE static void descend_group(const struct hsw_tree *t, double *restrict u,
    double *restrict v, uint32_t *restrict i, uint32_t *restrict j)
{
	uint32_t k[GROUP];
	const double *c = t->sum;

	for (unsigned q = 0; q < GROUP; q++)
		k[q] = i[q] = j[q] = 0;
	for (unsigned l = 0; l < t->levels; l++) {
		double c0[GROUP], c1[GROUP], c2[GROUP], c3[GROUP];

		c += (size_t)1 << (2 * l);	/* start of level l + 1 */
		/* The loads apart (a gather), the arithmetic on arrays: a
		 * loop the compiler vectorises. */
		for (unsigned q = 0; q < GROUP; q++) {
			const double *n = c + 4 * (size_t)k[q];
			c0[q] = n[0];
			c1[q] = n[1];
			c2[q] = n[2];
			c3[q] = n[3];
		}
		for (unsigned q = 0; q < GROUP; q++) {
			double a = c0[q] + c2[q], b = c1[q] + c3[q];
			double tu = u[q] * (a + b);
			int cx = (tu >= a) & (b > 0);
			double den = pick(cx, b, a);
			double nu = pick(cx, tu - a, tu) / den;
			double a2 = pick(cx, c1[q], c0[q]);
			double b2 = pick(cx, c3[q], c2[q]);
			double tv = v[q] * den;
			int cy = (tv >= a2) & (b2 > 0);
			double nv = pick(cy, tv - a2, tv) / pick(cy, b2, a2);

			u[q] = nu < BELOW_ONE ? nu : BELOW_ONE;
			v[q] = nv < BELOW_ONE ? nv : BELOW_ONE;
			k[q] = 4 * k[q] + 2 * (uint32_t)cy + (uint32_t)cx;
			i[q] = 2 * i[q] + (uint32_t)cx;
			j[q] = 2 * j[q] + (uint32_t)cy;
		}
	}
}

/* place for a group: the division for all, place's corrections only
 * where rounding left a point outside its pixel (rare). */
FRS_WIDE static void place_group(const uint32_t *i, const double *u, uint32_t n,
    double *x)
{
	double dn = (double)n;
	unsigned bad = 0;

	for (unsigned q = 0; q < GROUP; q++) {
		double di = (double)i[q], r = (di + u[q]) / dn;
		x[q] = r;
		bad |= (r * dn >= di + 1.0) | (r >= 1.0) | (r * dn < di);
	}
	if (bad)
		for (unsigned q = 0; q < GROUP; q++)
			x[q] = hsw_place(i[q], u[q], n);
}

/* m points (pairs) from in to m pairs in xy (which may be in) and,
 * where map is not NULL, the densities at their pixels into pdf
 * (hsw_pdf_at), while the points are at hand.  A short last group is
 * filled with (0, 0), a valid point, and not stored. */
static inline void warp_records(const struct hsw_tree *t, const double *in,
    size_t m, double *xy, double *pdf, const struct frs_imap *map,
    double mean)
{
	for (size_t p = 0; p < m; p += GROUP) {
		size_t g = m - p < GROUP ? m - p : GROUP;
		double u[GROUP], v[GROUP], x[GROUP], y[GROUP];
		uint32_t i[GROUP], j[GROUP];

		for (unsigned q = 0; q < GROUP; q++) {
			u[q] = q < g ? in[2 * (p + q)] : 0.0;
			v[q] = q < g ? in[2 * (p + q) + 1] : 0.0;
		}
		descend_group(t, u, v, i, j);
		place_group(i, u, t->w, x);
		place_group(j, v, t->h, y);
		for (unsigned q = 0; q < g; q++) {
			xy[2 * (p + q)] = x[q];
			xy[2 * (p + q) + 1] = y[q];
			if (map != NULL)
				pdf[p + q] = hsw_pdf_at(map, mean, x[q], y[q]);
		}
	}
}

struct sample_job {
	const struct hsw_tree *t;
	const struct hsw_source *src;
	const struct frs_imap *map;	/* NULL: no densities */
	double mean, *xy, *pdf;
	uint64_t base;
};

static int sample_task(void *ctx, uint64_t begin, uint64_t end)
{
	const struct sample_job *job = ctx;
	const struct hsw_source *src = job->src;
	double buf[2 * PIECE];
	struct base3 b3;

	if (src->in == NULL && src->kind == HSW_HALTON)
		base3_init(&b3);

	for (uint64_t p = begin; p < end; p += PIECE) {
		uint64_t m = end - p < PIECE ? end - p : PIECE, at = job->base + p;
		const double *in = buf;

		if (src->in != NULL)
			in = src->in + 2 * at;
		else
			input_range(&b3, src->kind, src->n, src->seed, at,
			    at + m, buf);
		warp_records(job->t, in, (size_t)m, job->xy + 2 * p,
		    job->map != NULL ? job->pdf + p : NULL, job->map, job->mean);
	}
	return 0;
}

int hsw_sample(const struct hsw_tree *t, const struct hsw_source *src,
    const struct frs_imap *map, uint64_t begin, uint64_t end, double *xy,
    double *pdf)
{
	struct sample_job job = { t, src, pdf != NULL ? map : NULL, 0.0, xy,
	    pdf, begin };

	if (job.map != NULL)
		job.mean = hsw_mean(t, map);
	return frs_parallel(end - begin, CHUNK, sample_task, &job, NULL);
}

int hsw_warp_points(const struct hsw_tree *t, const double *in, double *out,
    uint64_t n)
{
	struct hsw_source src = { HSW_HALTON, n, 0, in };
	struct sample_job job = { t, &src, NULL, 0.0, out, NULL, 0 };

	return frs_parallel(n, CHUNK, sample_task, &job, NULL);
}
