/*
 * Hierarchical Sample Warping: see hsw.h.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "err.h"
#include "mem.h"
#include "hsw.h"
#include "par.h"
#include "rng.h"

/* The largest double below 1. */
#define BELOW_ONE 0x1.fffffffffffffp-1

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

/* Split u in [0,1) between parts of weight a and b: returns 0 (first) or
 * 1, u rescaled to [0,1) of that part.  The test u < a / (a + b) is done
 * as u (a + b) < a, and the selection without branches (the choice is a
 * coin toss the processor cannot predict).  A zero part is never chosen:
 * b = 0 keeps to the first, a = 0 gives u (a + b) >= a always. */
static inline unsigned split(double a, double b, double *u)
{
	double t = *u * (a + b), num, den, v, f;
	unsigned c = (t >= a) & (b > 0);

	/* Arithmetic, not branches: the processor cannot predict the coin.
	 * 1 * x + 0 * y is exactly x for finite x and y. */
	f = (double)c;
	num = t - f * a;
	den = f * b + (1.0 - f) * a;
	v = num / den;
	*u = v < BELOW_ONE ? v : BELOW_ONE;
	return c;
}

/* (i + u) / n inside pixel i of n: rounding may not move it out. */
static inline double place(uint32_t i, double u, uint32_t n)
{
	double x = ((double)i + u) / (double)n;

	while (x * (double)n >= (double)i + 1.0 || x >= 1.0)
		x = nextafter(x, 0.0);
	while (x * (double)n < (double)i)
		x = nextafter(x, 1.0);
	return x;
}

uint64_t hsw_warp(const struct hsw_tree *t, double *x, double *y)
{
	const double *s = t->sum;
	uint64_t k = 0, off = 0;
	uint32_t i = 0, j = 0;
	double u = *x, v = *y;

	for (unsigned l = 0; l < t->levels; l++) {
		const double *c;
		unsigned cx, cy;

		off += (uint64_t)1 << (2 * l);	/* start of level l + 1 */
		c = s + off + 4 * k;
		cx = split(c[0] + c[2], c[1] + c[3], &u);
		cy = split(c[cx], c[cx + 2], &v);
		k = 4 * k + 2 * cy + cx;
		i = 2 * i + cx;
		j = 2 * j + cy;
	}
	*x = place(i, u, t->w);
	*y = place(j, v, t->h);
	return (uint64_t)j * t->w + i;
}

struct warp_job {
	const struct hsw_tree *t;
	const double *in;
	double *out;
};

/* Points in groups of GROUP, level by level: their descents are
 * independent chains of divisions that the processor overlaps. */
#define GROUP 16

static int warp_task(void *ctx, uint64_t begin, uint64_t end)
{
	const struct warp_job *job = ctx;
	const struct hsw_tree *t = job->t;
	uint64_t p = begin;

	for (; p + GROUP <= end; p += GROUP) {
		double u[GROUP], v[GROUP];
		uint64_t k[GROUP], off = 0;
		uint32_t i[GROUP], j[GROUP];

		for (unsigned q = 0; q < GROUP; q++) {
			u[q] = job->in[2 * (p + q)];
			v[q] = job->in[2 * (p + q) + 1];
			k[q] = 0;
			i[q] = j[q] = 0;
		}
		for (unsigned l = 0; l < t->levels; l++) {
			off += (uint64_t)1 << (2 * l);
			for (unsigned q = 0; q < GROUP; q++) {
				const double *c = t->sum + off + 4 * k[q];
				unsigned cx = split(c[0] + c[2], c[1] + c[3], &u[q]);
				unsigned cy = split(c[cx], c[cx + 2], &v[q]);
				k[q] = 4 * k[q] + 2 * cy + cx;
				i[q] = 2 * i[q] + cx;
				j[q] = 2 * j[q] + cy;
			}
		}
		for (unsigned q = 0; q < GROUP; q++) {
			job->out[2 * (p + q)] = place(i[q], u[q], t->w);
			job->out[2 * (p + q) + 1] = place(j[q], v[q], t->h);
		}
	}
	for (; p < end; p++) {
		double x = job->in[2 * p], y = job->in[2 * p + 1];
		hsw_warp(t, &x, &y);
		job->out[2 * p] = x;
		job->out[2 * p + 1] = y;
	}
	return 0;
}

int hsw_warp_points(const struct hsw_tree *t, const double *in, double *out,
    uint64_t n)
{
	struct warp_job job = { t, in, out };

	return frs_parallel(n, 16384, warp_task, &job, NULL);
}

int hsw_input_parse(const char *name)
{
	static const char *const names[] = { "random", "regular", "jittered",
	    "halton", "hammersley" };

	for (int k = 0; k < 5; k++)
		if (strcmp(name, names[k]) == 0)
			return k;
	return -1;
}

double hsw_radical_inverse(uint64_t i, unsigned b)
{
	double inv = 1.0 / b, f = inv, r = 0;

	while (i > 0) {
		r += (double)(i % b) * f;
		i /= b;
		f *= inv;
	}
	return r < 1.0 ? r : BELOW_ONE;
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

void hsw_input_make(enum hsw_input kind, uint64_t n, uint64_t seed,
    double *out)
{
	uint64_t k = grid_side(n);

	for (uint64_t i = 0; i < n; i++) {
		double x = 0, y = 0;
		switch (kind) {
		case HSW_RANDOM:
			x = frs_rand01(seed, FRS_STREAM_HSW, 2 * i);
			y = frs_rand01(seed, FRS_STREAM_HSW, 2 * i + 1);
			break;
		case HSW_REGULAR:
		case HSW_JITTERED: {
			double ox = 0.5, oy = 0.5;
			if (kind == HSW_JITTERED) {
				ox = frs_rand01(seed, FRS_STREAM_HSW, 2 * i);
				oy = frs_rand01(seed, FRS_STREAM_HSW, 2 * i + 1);
			}
			x = ((double)(i % k) + ox) / (double)k;
			y = ((double)(i / k) + oy) / (double)k;
			break;
		}
		case HSW_HALTON:
			x = hsw_radical_inverse(i + 1, 2);
			y = hsw_radical_inverse(i + 1, 3);
			break;
		case HSW_HAMMERSLEY:
			x = ((double)i + 0.5) / (double)n;
			y = hsw_radical_inverse(i, 2);
			break;
		}
		out[2 * i] = x < 1.0 ? x : BELOW_ONE;
		out[2 * i + 1] = y < 1.0 ? y : BELOW_ONE;
	}
}
