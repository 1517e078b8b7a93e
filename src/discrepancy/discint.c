/*
 * The pieces that the discrepancy modules (disc*.c) share: the chunked
 * loops, the compensated sum, the order of coordinates, the grid bins and
 * the points grouped by bin (discint.h).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "discrepancy/discint.h"
#include "cli/cli.h"

/* ---- loops and sums ------------------------------------------------- */

static const char *disc_label;

void disc_set_progress(const char *label)
{
	disc_label = label;
}

int disc_run_chunks(uint64_t n, uint64_t chunk,
    int (*fn)(void *, uint64_t, uint64_t), void *ctx, int par)
{
	if (par) {
		struct cli_task *t = disc_label != NULL ?
		    cli_task_begin(disc_label, n) : NULL;
		int rc = cli_parallel(n, chunk, fn, ctx, t);

		cli_task_end(t);
		return rc;
	}
	return cli_parallel_if(0, n, chunk, fn, ctx);
}

/* ---- sorting -------------------------------------------------------- */

/* A key whose unsigned order is the order of the doubles: the sign bit
 * flipped for non-negative values, every bit for negative ones; + 0.0
 * makes -0 equal to +0. */
static uint64_t order_key(double v)
{
	uint64_t b;

	v += 0.0;
	memcpy(&b, &v, sizeof b);
	return b >> 63 ? ~b : b | (uint64_t)1 << 63;
}

struct rkey {
	uint64_t k;
	uint32_t i;
};

#define RADIX_BITS 11
#define RADIX_PASSES 6		/* 66 bits */
#define RADIX (1u << RADIX_BITS)

/* Stable: equal keys keep the order of their indices. */
static void insertion_sort(struct rkey *a, size_t n)
{
	for (size_t i = 1; i < n; i++) {
		struct rkey t = a[i];
		size_t j = i;
		for (; j > 0 && a[j - 1].k > t.k; j--)
			a[j] = a[j - 1];
		a[j] = t;
	}
}

/* LSD radix sort, 11 bits a pass, the histograms of every pass counted
 * at once; a pass whose digit is the same for every key is skipped (the
 * exponents of coordinates in [0,1) share most of their bits).  It is
 * stable, so the order is that of qsort by (value, index), in O(n). */
static void radix_sort(struct rkey *a, struct rkey *b, size_t n,
    size_t (*h)[RADIX], struct rkey **out)
{
	for (size_t i = 0; i < n; i++)
		for (int p = 0; p < RADIX_PASSES; p++)
			h[p][(a[i].k >> (RADIX_BITS * p)) & (RADIX - 1)]++;
	for (int p = 0; p < RADIX_PASSES; p++) {
		size_t run = 0, *c = h[p];
		struct rkey *t;
		if (c[(a[0].k >> (RADIX_BITS * p)) & (RADIX - 1)] == n)
			continue;
		for (size_t d = 0; d < RADIX; d++) {
			size_t m = c[d];
			c[d] = run, run += m;
		}
		for (size_t i = 0; i < n; i++)
			b[c[(a[i].k >> (RADIX_BITS * p)) & (RADIX - 1)]++] = a[i];
		t = a, a = b, b = t;
	}
	*out = a;
}

int disc_order(const double *v, size_t n, size_t stride, uint32_t *ord)
{
	struct rkey *a = malloc(2 * (n ? n : 1) * sizeof *a), *s = a;
	size_t (*h)[RADIX] = NULL;

	if (a == NULL)
		return cli_fail("no memory for %zu points", n);
	for (size_t i = 0; i < n; i++)
		a[i].k = order_key(v[i * stride]), a[i].i = (uint32_t)i;
	if (n < 256)
		insertion_sort(a, n);
	else if ((h = calloc(RADIX_PASSES, sizeof *h)) == NULL) {
		free(a);
		return cli_fail("no memory for %zu points", n);
	} else
		radix_sort(a, a + n, n, h, &s);
	for (size_t i = 0; i < n; i++)
		ord[i] = s[i].i;
	free(a), free(h);
	return 0;
}

/* ---- grid bins ------------------------------------------------------ */

double disc_star_line(uint32_t i, uint32_t s)
{
	return (double)i / (double)s;
}

double disc_rect_line(uint32_t a, uint32_t s)
{
	return (double)a / (double)(s - 1);
}

/* Number of lines line(i), i = lo..hi, at or below v (lines increase). */
static uint32_t lines_le(double v, uint32_t lo, uint32_t hi, uint32_t s,
    double (*line)(uint32_t, uint32_t), double scale)
{
	double f = floor(v * scale);
	int64_t k = f < (double)lo ? (int64_t)lo - 1 :
	    f > (double)hi ? (int64_t)hi : (int64_t)f;

	while (k + 1 <= (int64_t)hi && line((uint32_t)(k + 1), s) <= v)
		k++;
	while (k >= (int64_t)lo && line((uint32_t)k, s) > v)
		k--;
	return (uint32_t)(k - (int64_t)lo + 1);
}

uint32_t disc_star_bin(double v, uint32_t s)
{
	return lines_le(v, 1, s, s, disc_star_line, (double)s);
}

uint32_t disc_rect_bin(double v, uint32_t s)
{
	return lines_le(v, 0, s - 1, s, disc_rect_line, (double)(s - 1)) - 1;
}

/* ---- points by bin -------------------------------------------------- */

int disc_rows_make(struct disc_rows *r, const uint32_t *bin, size_t n,
    uint32_t nbins)
{
	r->start = calloc((size_t)nbins + 1, sizeof *r->start);
	r->idx = malloc((n ? n : 1) * sizeof *r->idx);
	if (r->start == NULL || r->idx == NULL) {
		disc_rows_free(r);
		return cli_fail("no memory for a grid of %u rows", nbins);
	}
	for (size_t i = 0; i < n; i++)
		r->start[bin[i] + 1]++;
	for (uint32_t b = 0; b < nbins; b++)
		r->start[b + 1] += r->start[b];
	for (size_t i = 0; i < n; i++)
		r->idx[r->start[bin[i]]++] = (uint32_t)i;
	for (uint32_t b = nbins; b > 0; b--)
		r->start[b] = r->start[b - 1];
	r->start[0] = 0;
	return 0;
}

void disc_rows_free(struct disc_rows *r)
{
	free(r->start);
	free(r->idx);
	r->start = r->idx = NULL;
}
