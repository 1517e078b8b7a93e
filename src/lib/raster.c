#define _POSIX_C_SOURCE 200809L
#include "raster.h"
#include "err.h"

#include <errno.h>
#include <math.h>
#include <png.h>
#include <stdlib.h>
#include <string.h>

int raster_alloc(struct frs_raster *r, uint32_t w, uint32_t h,
    unsigned channels)
{
	size_t n;

	memset(r, 0, sizeof *r);
	if (channels != 1 && channels != 3)
		return frs_fail("raster: %u channels (1 or 3)", channels);
	if (w < 1 || h < 1 || w > IMAP_MAX_SIDE || h > IMAP_MAX_SIDE ||
	    (uint64_t)w * h > IMAP_MAX_PIXELS)
		return frs_fail("raster: size %ux%u is impossible (sides 1 to "
		    "%u, at most %llu pixels)", w, h, IMAP_MAX_SIDE,
		    (unsigned long long)IMAP_MAX_PIXELS);
	n = (size_t)w * h * channels;
	r->px = malloc(n);
	if (r->px == NULL)
		return frs_fail("raster: out of memory for %ux%u pixels", w, h);
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

/* Integral of sqrt(r^2 - u^2) over [a, b], u outside [-r, r] giving 0. */
static double chord_area(double a, double b, double rad)
{
	return chord_integral(b, rad) - chord_integral(a, rad);
}

/*
 * G(x) = integral over y in [y0, y1] of clamp(x, -s(y), s(y)), where
 * s(y) = sqrt(r^2 - y^2) is the half-chord of the disc at height y (0
 * outside it).  The disc's part of the pixel is G(x1) - G(x0), since the
 * length of [x0, x1] within [-s, s] is clamp(x1) - clamp(x0).
 */
static double strip_integral(double x, double y0, double y1, double rad)
{
	double t, a, b, inner;

	if (x < 0.0)
		return -strip_integral(-x, y0, y1, rad);
	if (x >= rad)
		return chord_area(y0, y1, rad);
	/* min(x, s(y)) is x where |y| <= t, s(y) elsewhere. */
	t = sqrt(rad * rad - x * x);
	a = y0 > -t ? y0 : -t;
	b = y1 < t ? y1 : t;
	inner = b > a ? b - a : 0.0;
	return x * inner + chord_area(y0, y1, rad) -
	    (inner > 0.0 ? chord_area(a, b, rad) : 0.0);
}

double raster_coverage(double x0, double y0, double x1, double y1,
    double rad)
{
	double area = (x1 - x0) * (y1 - y0), c;

	if (!(rad > 0.0) || !(area > 0.0))
		return 0.0;
	c = (strip_integral(x1, y0, y1, rad) - strip_integral(x0, y0, y1,
	    rad)) / area;
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

void raster_disc(struct frs_raster *r, double cx, double cy, double rad,
    const uint8_t *color)
{
	double flo_x, fhi_x, flo_y, fhi_y, r2 = rad * rad;
	uint32_t i0, i1, j0, j1;

	if (!(rad > 0.0) || !isfinite(cx) || !isfinite(cy) || !isfinite(rad))
		return;
	flo_x = floor(cx - rad);
	fhi_x = floor(cx + rad);
	flo_y = floor(cy - rad);
	fhi_y = floor(cy + rad);
	if (fhi_x < 0.0 || fhi_y < 0.0 || flo_x >= (double)r->w ||
	    flo_y >= (double)r->h)
		return;
	i0 = flo_x < 0.0 ? 0 : (uint32_t)flo_x;
	j0 = flo_y < 0.0 ? 0 : (uint32_t)flo_y;
	i1 = fhi_x >= (double)r->w ? r->w - 1 : (uint32_t)fhi_x;
	j1 = fhi_y >= (double)r->h ? r->h - 1 : (uint32_t)fhi_y;
	for (uint32_t j = j0; j <= j1; j++) {
		double y0 = (double)j - cy, y1 = y0 + 1.0;
		double ny = nearest(y0, y1), fy = farthest(y0, y1);
		uint8_t *row = r->px + (size_t)j * r->w * r->channels;

		for (uint32_t i = i0; i <= i1; i++) {
			double x0 = (double)i - cx, x1 = x0 + 1.0;
			double nx = nearest(x0, x1), fx = farthest(x0, x1);
			double c;
			uint8_t *p = row + (size_t)i * r->channels;

			if (nx * nx + ny * ny >= r2)
				continue;
			if (fx * fx + fy * fy <= r2)
				c = 1.0;
			else
				c = raster_coverage(x0, y0, x1, y1, rad);
			if (c <= 0.0)
				continue;
			for (unsigned k = 0; k < r->channels; k++) {
				double v = p[k] * (1.0 - c) + color[k] * c;
				p[k] = (uint8_t)lround(v < 0.0 ? 0.0 :
				    v > 255.0 ? 255.0 : v);
			}
		}
	}
}

double raster_default_radius(uint32_t w)
{
	double rad = 1.5 * (double)w / 512.0;

	return rad < 0.7 ? 0.7 : rad;
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

/* libpng reports errors through a callback that must not return: keep
 * the message for ours and jump back. */
struct raster_pngerr {
	char msg[256];
};

static void png_on_error(png_structp png, png_const_charp msg)
{
	struct raster_pngerr *e = png_get_error_ptr(png);

	snprintf(e->msg, sizeof e->msg, "%s", msg);
	png_longjmp(png, 1);
}

static void png_on_warning(png_structp png, png_const_charp msg)
{
	(void)png;
	(void)msg;
}

int raster_write_png(FILE *fp, const char *name, const struct frs_raster *r)
{
	struct raster_pngerr err = { "" };
	png_structp png;
	png_infop info = NULL;
	size_t stride = (size_t)r->w * r->channels;

	if (r->px == NULL || (r->channels != 1 && r->channels != 3))
		return frs_fail("%s: internal error: no raster to write", name);
	png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &err,
	    png_on_error, png_on_warning);
	if (png == NULL || (info = png_create_info_struct(png)) == NULL) {
		png_destroy_write_struct(&png, NULL);
		return frs_fail("%s: out of memory", name);
	}
	errno = 0;
	if (setjmp(png_jmpbuf(png))) {
		int saved = errno;

		png_destroy_write_struct(&png, &info);
		if (ferror(fp)) {
			errno = saved;
			return frs_fail_errno("%s: write error", name);
		}
		return frs_fail("%s: cannot write PNG: %s", name, err.msg);
	}
	png_init_io(png, fp);
	png_set_IHDR(png, info, r->w, r->h, 8, r->channels == 1 ?
	    PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
	    PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
	png_write_info(png, info);
	for (uint32_t y = 0; y < r->h; y++)
		png_write_row(png, r->px + (size_t)y * stride);
	png_write_end(png, NULL);
	png_destroy_write_struct(&png, &info);
	if (ferror(fp))
		return frs_fail_errno("%s: write error", name);
	return 0;
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
