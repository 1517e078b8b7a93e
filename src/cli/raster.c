#define _POSIX_C_SOURCE 200809L
#include "cli/raster.h"
#include "base/err.h"
#include "base/mem.h"
#include "maps/imap.h"
#include "maps/pngio.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int raster_alloc(struct frs_raster *r, uint32_t w, uint32_t h,
    unsigned channels)
{
	size_t n;

	memset(r, 0, sizeof *r);
	if (channels != 1 && channels != 3)
		return frs_fail("raster: %u channels (1 or 3)", channels);
	if (w < 1 || h < 1 || w > FRS_MAP_MAX_SIDE || h > FRS_MAP_MAX_SIDE ||
	    (uint64_t)w * h > FRS_MAP_MAX_PIXELS)
		return frs_fail("raster: size %ux%u is impossible (sides 1 to "
		    "%u, at most %llu pixels)", w, h, FRS_MAP_MAX_SIDE,
		    (unsigned long long)FRS_MAP_MAX_PIXELS);
	n = (size_t)w * h * channels;
	if ((r->px = mem_calloc("raster", n, 1)) == NULL)
		return -1;
	memset(r->px, 255, n);
	r->w = w;
	r->h = h;
	r->channels = channels;
	return 0;
}

void raster_free(struct frs_raster *r)
{
	free(r->px);
	memset(r, 0, sizeof *r);
}

void raster_fill(struct frs_raster *r, const uint8_t *color)
{
	size_t n = (size_t)r->w * r->h;

	for (size_t i = 0; i < n; i++)
		memcpy(r->px + i * r->channels, color, r->channels);
}

int raster_fill_imap(struct frs_raster *r, const struct frs_imap *m,
    int logscale)
{
	struct frs_imap_stats s;
	size_t n = (size_t)r->w * r->h;
	double lo = 0.0, span = 0.0;

	if (m->w != r->w || m->h != r->h)
		return frs_fail("raster: internal error: map %ux%u for a %ux%u "
		    "raster", m->w, m->h, r->w, r->h);
	imap_stats(m, &s);
	if (logscale && s.min_positive > 0.0) {
		lo = log10(s.min_positive);
		span = log10(s.max) - lo;
	}
	for (size_t i = 0; i < n; i++) {
		double v = m->v[i], f;
		long g;

		if (!(v > 0.0) || !(s.max > 0.0))
			g = 255;
		else if (logscale) {
			f = span > 0.0 ? (log10(v) - lo) / span : 1.0;
			f = f < 0.0 ? 0.0 : f > 1.0 ? 1.0 : f;
			g = 254 - lround((RASTER_BG_RANGE - 1) * f);
		} else {
			f = v / s.max;
			f = f > 1.0 ? 1.0 : f;
			g = 255 - lround(RASTER_BG_RANGE * f);
		}
		memset(r->px + i * r->channels, (int)g, r->channels);
	}
	return 0;
}

/* Integral of sqrt(r^2 - u^2) from 0 to y, y clamped to [-r, r]. */
static double chord_integral(double y, double rad)
{
	double yc = y < -rad ? -rad : y > rad ? rad : y;
	double q = rad * rad - yc * yc;

	return 0.5 * (yc * sqrt(q > 0.0 ? q : 0.0) + rad * rad *
	    asin(yc / rad));
}

/*
 * The disc of radius rad around the origin within the horizontal strip
 * y0 <= y <= y1.  With s(y) = sqrt(r^2 - y^2) its half-chord at height y
 * (0 outside the disc), the length of [x0, x1] within [-s, s] is
 * clamp(x1, -s, s) - clamp(x0, -s, s), so the area of the disc within
 * [x0, x1] x [y0, y1] is G(x1) - G(x0) with
 *
 *   G(x) = integral over [y0, y1] of clamp(x, -s(y), s(y)) dy,
 *
 * an odd function of x.  For 0 <= x < r, min(x, s(y)) is x where
 * |y| <= t = sqrt(r^2 - x^2) and s(y) elsewhere, which gives G in closed
 * form from the integrals C(y) of s at y0, y1 and +-t.  Pixels of a row
 * share their edges' G, and C(y0), C(y1) are the row's.
 */
struct strip {
	double y0, y1, c0, c1, rad;
};

static void strip_init(struct strip *st, double y0, double y1, double rad)
{
	st->y0 = y0;
	st->y1 = y1;
	st->rad = rad;
	st->c0 = chord_integral(y0, rad);
	st->c1 = chord_integral(y1, rad);
}

static double strip_g(const struct strip *st, double x)
{
	double ax = fabs(x), rad = st->rad, t, ct, a, b, ca, cb, g;

	if (ax >= rad) {
		g = st->c1 - st->c0;
	} else {
		t = sqrt(rad * rad - ax * ax);
		a = st->y0 > -t ? st->y0 : -t;
		b = st->y1 < t ? st->y1 : t;
		if (b <= a) {
			g = st->c1 - st->c0;
		} else {
			/* C(t) = (t |x| + r^2 acos(|x| / r)) / 2, C odd. */
			ct = a == st->y0 && b == st->y1 ? 0.0 :
			    0.5 * (t * ax + rad * rad * acos(ax / rad));
			ca = a == st->y0 ? st->c0 : -ct;
			cb = b == st->y1 ? st->c1 : ct;
			g = ax * (b - a) + (st->c1 - st->c0) - (cb - ca);
		}
	}
	return x < 0.0 ? -g : g;
}

double raster_coverage(double x0, double y0, double x1, double y1,
    double rad)
{
	double area = (x1 - x0) * (y1 - y0), c;
	struct strip st;

	if (!(rad > 0.0) || !(area > 0.0))
		return 0.0;
	strip_init(&st, y0, y1, rad);
	c = (strip_g(&st, x1) - strip_g(&st, x0)) / area;
	return c < 0.0 ? 0.0 : c > 1.0 ? 1.0 : c;
}

/* Distance from 0 to the nearest and farthest point of [a, b]. */
static double nearest(double a, double b)
{
	return a > 0.0 ? a : b < 0.0 ? -b : 0.0;
}

static double farthest(double a, double b)
{
	return fabs(a) > fabs(b) ? fabs(a) : fabs(b);
}

static void blend(uint8_t *p, unsigned channels, const uint8_t *color,
    double c)
{
	for (unsigned k = 0; k < channels; k++) {
		double v = p[k] * (1.0 - c) + color[k] * c;
		/* v is in [0, 255]: adding 1/2 and truncating rounds. */
		p[k] = (uint8_t)(v <= 0.0 ? 0.0 : v >= 255.0 ? 255.0 : v + 0.5);
	}
}

/* Pixel range [lo, hi] of a row from real bounds, clipped to [0, w). */
static int span(double lo, double hi, uint32_t w, uint32_t *a, uint32_t *b)
{
	if (!(hi >= lo) || hi < 0.0 || lo >= (double)w)
		return 0;
	*a = lo < 0.0 ? 0 : (uint32_t)lo;
	*b = hi >= (double)w ? w - 1 : (uint32_t)hi;
	return 1;
}

void raster_disc(struct frs_raster *r, double cx, double cy, double rad,
    const uint8_t *color)
{
	raster_disc_alpha(r, cx, cy, rad, color, 1.0);
}

void raster_disc_alpha(struct frs_raster *r, double cx, double cy,
    double rad, const uint8_t *color, double alpha)
{
	double r2 = rad * rad;
	uint32_t j0, j1;
	unsigned ch = r->channels;

	if (!(rad > 0.0) || !isfinite(cx) || !isfinite(cy) || !isfinite(rad) ||
	    !span(floor(cy - rad), floor(cy + rad), r->h, &j0, &j1) ||
	    floor(cx + rad) < 0.0 || floor(cx - rad) >= (double)r->w)
		return;
	for (uint32_t j = j0; j <= j1; j++) {
		double y0 = (double)j - cy, y1 = (double)j + 1.0 - cy;
		double ny = nearest(y0, y1), fy = farthest(y0, y1);
		double ht, gprev = 0.0;
		uint32_t t0, t1, f0 = 1, f1 = 0, iprev = UINT32_MAX;
		uint8_t *row = r->px + (size_t)j * r->w * ch;
		struct strip st;
		int have_strip = 0;

		if (ny * ny >= r2)
			continue;
		/* Pixels the disc touches: |x - cx| < ht somewhere in them. */
		ht = sqrt(r2 - ny * ny);
		if (!span(floor(cx - ht), floor(cx + ht), r->w, &t0, &t1))
			continue;
		/* Pixels it covers whole: i - cx >= -hf and i + 1 - cx <= hf. */
		if (fy * fy < r2) {
			double hf = sqrt(r2 - fy * fy);
			if (!span(ceil(cx - hf), floor(cx + hf) - 1.0, r->w, &f0,
			    &f1)) {
				f0 = 1;
				f1 = 0;
			}
		}
		for (uint32_t i = t0; i <= t1; i++) {
			double g0, g1, c;

			if (i >= f0 && i <= f1 && alpha < 1.0) {
				for (uint32_t k = i; k <= f1; k++)
					blend(row + (size_t)k * ch, ch, color,
					    alpha);
				i = f1;
				continue;
			}
			if (i >= f0 && i <= f1) {
				if (ch == 1)
					memset(row + i, color[0], f1 - i + 1);
				else
					for (uint32_t k = i; k <= f1; k++) {
						uint8_t *p = row + (size_t)k * 3;
						p[0] = color[0];
						p[1] = color[1];
						p[2] = color[2];
					}
				i = f1;
				continue;
			}
			if (!have_strip) {
				strip_init(&st, y0, y1, rad);
				have_strip = 1;
			}
			g0 = iprev == i ? gprev : strip_g(&st, (double)i - cx);
			g1 = strip_g(&st, (double)i + 1.0 - cx);
			gprev = g1;
			iprev = i + 1;
			c = g1 - g0;
			if (c > 0.0)
				blend(row + (size_t)i * ch, ch, color,
				    (c > 1.0 ? 1.0 : c) * alpha);
		}
	}
}

double raster_default_radius(uint32_t w)
{
	double rad = 1.5 * (double)w / 512.0;

	return rad < 0.7 ? 0.7 : rad;
}

/* ---- radii from the local spacing ---------------------------------- */

/* The pixel of coordinate v on a side of n pixels, clamped. */
static uint32_t pixel_of(double v, uint32_t n)
{
	double c = floor(v);

	return !(c >= 0.0) ? 0 : c >= (double)n ? n - 1 : (uint32_t)c;
}

int raster_spacing_init(struct raster_spacing *s, const double *x,
    size_t n, size_t ncol, unsigned ax, unsigned ay, uint32_t w,
    uint32_t h)
{
	size_t stride = (size_t)w + 1;
	uint32_t *sum;

	memset(s, 0, sizeof *s);
	if ((uint64_t)n > UINT32_MAX)
		return frs_fail("dot radii: %llu points, more than %lu",
		    (unsigned long long)n, (unsigned long)UINT32_MAX);
	sum = mem_calloc("dot radii", (uint64_t)stride * ((uint64_t)h + 1),
	    sizeof *sum);
	if (sum == NULL)
		return -1;
	/* Counts per pixel at (i + 1, j + 1), then summed over rows and
	 * columns: sum[j][i] counts the points in pixels < i across and
	 * < j down. */
	for (size_t k = 0; k < n; k++) {
		const double *p = x + k * ncol;
		uint32_t i = pixel_of(p[ax] * w, w), j = pixel_of(p[ay] * h, h);

		sum[(j + 1) * stride + i + 1]++;
	}
	for (size_t j = 1; j <= h; j++)
		for (size_t i = 1; i <= w; i++)
			sum[j * stride + i] += sum[j * stride + i - 1] +
			    sum[(j - 1) * stride + i] -
			    sum[(j - 1) * stride + i - 1];
	s->w = w;
	s->h = h;
	s->rmax = raster_default_radius(w);
	s->sum = sum;
	return 0;
}

/* The square of pixels b around pixel (i, j) each way, clipped. */
struct box {
	uint32_t x0, y0, x1, y1;	/* pixel corners, x1 and y1 past */
};

static struct box box_around(const struct raster_spacing *s, uint32_t i,
    uint32_t j, uint32_t b)
{
	struct box q;

	q.x0 = i > b ? i - b : 0;
	q.y0 = j > b ? j - b : 0;
	q.x1 = s->w - i > b ? i + b + 1 : s->w;
	q.y1 = s->h - j > b ? j + b + 1 : s->h;
	return q;
}

static uint32_t box_count(const struct raster_spacing *s, struct box q)
{
	size_t stride = (size_t)s->w + 1;
	const uint32_t *t = s->sum;

	return t[q.y1 * stride + q.x1] - t[q.y0 * stride + q.x1] -
	    t[q.y1 * stride + q.x0] + t[q.y0 * stride + q.x0];
}

static double box_area(struct box q)
{
	return (double)(q.x1 - q.x0) * (double)(q.y1 - q.y0);
}

static int box_whole(const struct raster_spacing *s, struct box q)
{
	return q.x0 == 0 && q.y0 == 0 && q.x1 == s->w && q.y1 == s->h;
}

/* Points per square pixel around pixel (i, j): see raster.h. */
static double spacing_rho(const struct raster_spacing *s, uint32_t i,
    uint32_t j)
{
	/* The spacing at which the radius reaches R: fewer than the count
	 * in an area of count * sparse^2 means a dot of R. */
	double sparse = (s->rmax - RASTER_SPACING_MIN) /
	    RASTER_SPACING_FRACTION;
	double enough = RASTER_SPACING_COUNT * sparse * sparse;
	double c0 = 0.0, a0 = 0.0, c1, a1;
	uint32_t lo = 0, hi = 0, top = s->w > s->h ? s->w : s->h;
	struct box q = box_around(s, i, j, 0);

	/* Grow until the square holds the count or is large enough to say
	 * the points are sparse; then the smallest that holds it. */
	while (box_count(s, q) < RASTER_SPACING_COUNT) {
		if (box_whole(s, q) || box_area(q) >= enough || hi >= top)
			return box_count(s, q) / box_area(q);
		lo = hi + 1;
		hi = 2 * hi + 1;
		q = box_around(s, i, j, hi);
	}
	while (lo < hi) {
		uint32_t mid = lo + (hi - lo) / 2;

		if (box_count(s, box_around(s, i, j, mid)) >=
		    RASTER_SPACING_COUNT)
			hi = mid;
		else
			lo = mid + 1;
	}
	q = box_around(s, i, j, hi);
	c1 = box_count(s, q);
	a1 = box_area(q);
	if (hi > 0) {
		q = box_around(s, i, j, hi - 1);
		c0 = box_count(s, q);
		a0 = box_area(q);
	}
	/* The area at which the count reaches RASTER_SPACING_COUNT,
	 * linear between the two squares: a pile in the larger one counts
	 * as no more than that, so it does not spill onto its neighbours. */
	return RASTER_SPACING_COUNT / (a0 + (RASTER_SPACING_COUNT - c0) /
	    (c1 - c0) * (a1 - a0));
}

double raster_spacing_radius(const struct raster_spacing *s, double px,
    double py)
{
	double rho = spacing_rho(s, pixel_of(px, s->w), pixel_of(py, s->h));
	double rad;

	if (!(rho > 0.0))
		return s->rmax;
	rad = RASTER_SPACING_FRACTION / sqrt(rho) + RASTER_SPACING_MIN;
	return rad > s->rmax ? s->rmax : rad;
}

void raster_spacing_free(struct raster_spacing *s)
{
	free(s->sum);
	s->sum = NULL;
}

void raster_ramp(uint64_t k, uint64_t n, uint8_t rgb[3])
{
	double t = n > 1 ? (double)k / (double)(n - 1) : 0.0;
	long red;

	t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
	red = lround(255.0 * t);
	rgb[0] = (uint8_t)red;
	rgb[1] = 0;
	rgb[2] = (uint8_t)(255 - red);
}

/* ---- PNG output -------------------------------------------------------- */

/* Row y of the raster, in place. */
static const unsigned char *raster_row(const void *ctx, uint32_t y,
    unsigned char *buf)
{
	const struct frs_raster *r = ctx;

	(void)buf;
	return r->px + (size_t)y * r->w * r->channels;
}

int raster_write_png(FILE *fp, const char *name, const struct frs_raster *r)
{
	if (r->px == NULL || (r->channels != 1 && r->channels != 3))
		return frs_fail("%s: internal error: no raster to write", name);
	return pngio_write(fp, name, r->w, r->h, 8, (int)r->channels,
	    raster_row, r);
}

int raster_write_pnm(FILE *fp, const char *name, const struct frs_raster *r)
{
	size_t n = (size_t)r->w * r->h * r->channels;

	if (r->px == NULL || (r->channels != 1 && r->channels != 3))
		return frs_fail("%s: internal error: no raster to write", name);
	if (fprintf(fp, "P%c\n%u %u\n255\n", r->channels == 1 ? '5' : '6',
	    r->w, r->h) < 0 || fwrite(r->px, 1, n, fp) != n || ferror(fp))
		return frs_fail_errno("%s: write error", name);
	return 0;
}
