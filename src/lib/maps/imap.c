#define _POSIX_C_SOURCE 200809L
#include "maps/imap.h"
#include "base/err.h"
#include "base/mem.h"
#include "base/num.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


int imap_alloc(struct frs_imap *m, uint32_t w, uint32_t h)
{
	char what[48];

	memset(m, 0, sizeof *m);
	if (w == 0 || h == 0)
		return frs_fail("impossible map size %ux%u", w, h);
	if (w > FRS_MAP_MAX_SIDE || h > FRS_MAP_MAX_SIDE ||
	    (uint64_t)w * h > FRS_MAP_MAX_PIXELS)
		return frs_fail("map size %ux%u is too large (at most %u on a "
		    "side and %llu pixels)", w, h, FRS_MAP_MAX_SIDE,
		    (unsigned long long)FRS_MAP_MAX_PIXELS);
	snprintf(what, sizeof what, "%ux%u map", w, h);
	if ((m->v = mem_calloc(what, (uint64_t)w * h, sizeof *m->v)) == NULL)
		return -1;
	m->w = w;
	m->h = h;
	return 0;
}

void imap_free(struct frs_imap *m)
{
	free(m->v);
	memset(m, 0, sizeof *m);
}

void imap_stats(const struct frs_imap *m, struct frs_imap_stats *s)
{
	double c = 0.0;	/* Kahan-Babuska compensation */
	uint64_t finite = 0;

	memset(s, 0, sizeof *s);
	s->count = (uint64_t)m->w * m->h;
	s->min = INFINITY;
	s->max = -INFINITY;
	for (uint64_t i = 0; i < s->count; i++) {
		double v = m->v[i], t;
		if (!isfinite(v)) {
			if (s->nonfinite++ == 0) {
				s->bad_x = (uint32_t)(i % m->w);
				s->bad_y = (uint32_t)(i / m->w);
				s->bad_value = v;
			}
			continue;
		}
		finite++;
		if (v == 0.0)
			s->zeros++;
		if (v > 0.0 && (s->min_positive == 0.0 || v < s->min_positive))
			s->min_positive = v;
		if (v < 0.0) {
			if (s->negatives++ == 0) {
				s->neg_x = (uint32_t)(i % m->w);
				s->neg_y = (uint32_t)(i / m->w);
				s->min_negative = v;
			}
			if (v < s->min_negative)
				s->min_negative = v;
		}
		s->min = v < s->min ? v : s->min;
		s->max = v > s->max ? v : s->max;
		t = s->sum + v;
		if (fabs(s->sum) >= fabs(v))
			c += (s->sum - t) + v;
		else
			c += (v - t) + s->sum;
		s->sum = t;
	}
	s->sum += c;
	s->mean = finite ? s->sum / (double)finite : 0.0;
	if (finite == 0)
		s->min = s->max = 0.0;
}

int imap_clamp(struct frs_imap *m, struct frs_imap_stats *s,
    const char *name, const char *what, int flags)
{
	uint64_t n = (uint64_t)m->w * m->h;

	if (s->negatives) {
		frs_warn("%s: %llu negative %s clamped to zero (smallest "
		    "%.6g)", name, (unsigned long long)s->negatives, what,
		    s->min_negative);
		for (uint64_t i = 0; i < n; i++)
			if (m->v[i] < 0.0)
				m->v[i] = 0.0;
		imap_stats(m, s);
	}
	if (!(flags & FRS_MAP_ALLOW_ZERO) && s->max <= 0.0)
		return frs_fail("%s: importance is zero everywhere", name);
	return 0;
}

static int validate(struct frs_imap *m, const char *name, int flags,
    struct frs_imap_stats *s)
{
	imap_stats(m, s);
	if (s->nonfinite)
		return frs_fail("%s: pixel (%u, %u) is %s (%llu non-finite "
		    "pixels)", name, s->bad_x, s->bad_y, isnan(s->bad_value) ?
		    "NaN" : "infinite", (unsigned long long)s->nonfinite);
	if (s->negatives && (flags & FRS_MAP_STRICT))
		return frs_fail("%s: pixel (%u, %u) is negative (%.6g); "
		    "%llu negative pixels, smallest %.6g", name, s->neg_x,
		    s->neg_y, m->v[(size_t)s->neg_y * m->w + s->neg_x],
		    (unsigned long long)s->negatives, s->min_negative);
	return imap_clamp(m, s, name, "pixels", flags);
}

int imap_validate_stats(struct frs_imap *m, const char *name, int flags,
    struct frs_imap_stats *s)
{
	if (validate(m, name, flags, s) == 0)
		return 0;
	frs_set_errkind(FRS_ERRKIND_MAP);	/* the values, not the file */
	return -1;
}

int imap_validate(struct frs_imap *m, const char *name, int flags)
{
	struct frs_imap_stats s;

	return imap_validate_stats(m, name, flags, &s);
}

/* Overlap of [a0, a1) with [b0, b1). */
static double overlap(double a0, double a1, double b0, double b1)
{
	double lo = a0 > b0 ? a0 : b0, hi = a1 < b1 ? a1 : b1;
	return hi > lo ? hi - lo : 0.0;
}

/*
 * Weights of the 1-D box filter from n source cells onto m target cells,
 * in source-cell units: target t covers [t*n/m, (t+1)*n/m).  For each
 * target, first[t] is the first source cell and w[t*span + k] the weight
 * of source first[t] + k divided by the target's width.
 */
struct boxmap {
	uint32_t *first;
	double *w;
	uint32_t span;
};

static int boxmap_make(struct boxmap *b, uint32_t n, uint32_t m)
{
	double scale = (double)n / m;

	b->span = (uint32_t)ceil(scale) + 1;
	b->first = malloc(m * sizeof *b->first);
	b->w = calloc((size_t)m * b->span, sizeof *b->w);
	if (b->first == NULL || b->w == NULL)
		return frs_fail("out of memory for resampling");
	for (uint32_t t = 0; t < m; t++) {
		/* Integer arithmetic for the cell range avoids rounding
		 * drift: target t spans [t*n, (t+1)*n) in units of 1/m. */
		uint64_t lo = (uint64_t)t * n, hi = (uint64_t)(t + 1) * n;
		uint32_t s0 = (uint32_t)(lo / m);
		b->first[t] = s0;
		for (uint32_t k = 0; k < b->span && s0 + k < n; k++) {
			double o = overlap((double)lo, (double)hi,
			    (double)(s0 + k) * m, (double)(s0 + k + 1) * m);
			b->w[(size_t)t * b->span + k] = o / (double)(hi - lo);
		}
	}
	return 0;
}

static void boxmap_free(struct boxmap *b)
{
	free(b->first);
	free(b->w);
}

int imap_resample(const struct frs_imap *in, uint32_t w, uint32_t h,
    struct frs_imap *out)
{
	struct boxmap bx = { 0 }, by = { 0 };
	double *row = NULL;
	int rc = -1;

	if (imap_alloc(out, w, h) < 0)
		return -1;
	if (boxmap_make(&bx, in->w, w) < 0 || boxmap_make(&by, in->h, h) < 0)
		goto done;
	row = malloc(w * sizeof *row);
	if (row == NULL) {
		frs_fail("out of memory for resampling");
		goto done;
	}
	/* Separable: for each target row, mix source rows, then columns. */
	for (uint32_t ty = 0; ty < h; ty++) {
		for (uint32_t tx = 0; tx < w; tx++) {
			double acc = 0.0;
			for (uint32_t ky = 0; ky < by.span; ky++) {
				double wy = by.w[(size_t)ty * by.span + ky];
				const double *src;
				double racc = 0.0;
				if (wy == 0.0)
					continue;
				src = in->v + (size_t)(by.first[ty] + ky) * in->w;
				for (uint32_t kx = 0; kx < bx.span; kx++) {
					double wx = bx.w[(size_t)tx * bx.span + kx];
					if (wx != 0.0)
						racc += wx * src[bx.first[tx] + kx];
				}
				acc += wy * racc;
			}
			row[tx] = acc;
		}
		memcpy(out->v + (size_t)ty * w, row, w * sizeof *row);
	}
	rc = 0;
done:
	free(row);
	boxmap_free(&bx);
	boxmap_free(&by);
	if (rc < 0)
		imap_free(out);
	return rc;
}

double imap_equirect_weight(uint32_t j, uint32_t h)
{
	/* Mean of sin(theta) over the row's band of polar angles:
	 * (cos t0 - cos t1) / (t1 - t0). */
	double t0 = NUM_PI * j / h, t1 = NUM_PI * (j + 1) / h;

	return (cos(t0) - cos(t1)) / (t1 - t0);
}

void imap_equirect(struct frs_imap *m)
{
	for (uint32_t j = 0; j < m->h; j++) {
		double wgt = imap_equirect_weight(j, m->h);
		for (uint32_t i = 0; i < m->w; i++)
			m->v[(size_t)j * m->w + i] *= wgt;
	}
}
