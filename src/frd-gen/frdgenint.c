/* What the CPU and OpenCL generators share (frdgenint.h). */
#define _POSIX_C_SOURCE 200809L
#include "frd-gen/frdgenint.h"
#include "cli/cli.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

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

double *frdgen_table(const struct frdgen_params *pr)
{
	uint32_t hw = pr->w / 2, hh = pr->h / 2, hd = pr->d / 2;
	size_t nt = (size_t)(hw + 1) * (hh + 1) * (hd + 1);
	double *t = malloc(nt * sizeof *t);

	if (t == NULL) {
		cli_fail("out of memory for the force table");
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

unsigned frdgen_log2u(uint32_t v)
{
	unsigned l = 0;
	while ((1u << l) < v)
		l++;
	return l;
}

/* ---- zero cells: counts per tile in a Fenwick tree ----------------- */

void frdgen_fen_add(uint64_t *fen, size_t n, size_t t, int64_t d)
{
	for (size_t i = t + 1; i <= n; i += i & (~i + 1))
		fen[i] = (uint64_t)((int64_t)fen[i] + d);
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

/* ---- the window of one insertion --------------------------------- */

void frdgen_window(const struct frdgen_params *pr,
    const struct frdgen_size *z, uint32_t tx, double r, struct frdgen_win *wd)
{
	wd->e = r >= (double)UINT32_MAX ? UINT32_MAX : (uint32_t)floor(r);
	wd->r2 = r >= z->rmax ? INFINITY : r * r;
	/* The taper: f(R) off every force inside R (none past the torus). */
	wd->sub = pr->field == FRDGEN_FIELD_DOUBLE && pr->taper &&
	    wd->r2 < INFINITY ? frdgen_force(pr, r) : 0.0;
	wd->fast = 2 * (uint64_t)wd->e + 1 + 2 * tx <= z->w;
	wd->ey = (wd->e < z->hh ? wd->e : z->hh);
	wd->ez = (wd->e < z->hd ? wd->e : z->hd);
}

/* ---- the rank query: the K-th smallest free cell ------------------ */

/* Room for one more item in a growing array. */
static int item_room(struct frdgen_item **a, size_t n, size_t *cap)
{
	if (n == *cap) {
		size_t ncap = *cap ? 2 * *cap : 256;
		struct frdgen_item *na = realloc(*a, ncap * sizeof *na);
		if (na == NULL)
			return cli_fail("out of memory in the rank query");
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
			return cli_fail("out of memory in the rank query");
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
		return cli_fail("internal error: %zu free cells found, rank %llu",
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
