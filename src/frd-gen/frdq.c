#define _POSIX_C_SOURCE 200809L
#include "frd-gen/frdq.h"
#include "cli/cli.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static double torus_d2(const uint32_t *a, const uint32_t *b,
    const uint32_t *size)
{
	double s = 0.0;
	for (int i = 0; i < 3; i++) {
		uint32_t d = a[i] > b[i] ? a[i] - b[i] : b[i] - a[i];
		if (size[i] - d < d)
			d = size[i] - d;
		s += (double)d * d;
	}
	return s;
}

double frdq_spread(const struct frs_matrix *m, uint32_t c)
{
	uint32_t size[3] = { m->w, m->h, m->d };
	uint32_t (*pos)[3];
	double best = INFINITY, vol = (double)m->w * m->h * m->d, ideal;

	if (c < 2 || c > m->n)
		return NAN;
	pos = malloc((size_t)c * sizeof *pos);
	if (pos == NULL)
		return NAN;
	for (size_t i = 0; i < m->n; i++)
		if (m->v[i] < c) {
			pos[m->v[i]][0] = (uint32_t)(i % m->w);
			pos[m->v[i]][1] = (uint32_t)(i / m->w % m->h);
			pos[m->v[i]][2] = (uint32_t)(i / m->w / m->h);
		}
	for (uint32_t i = 0; i < c; i++)
		for (uint32_t j = i + 1; j < c; j++) {
			double d2 = torus_d2(pos[i], pos[j], size);
			best = d2 < best ? d2 : best;
		}
	free(pos);
	ideal = m->dims == 2 ? sqrt(2.0 * vol / (sqrt(3.0) * c)) :
	    cbrt(sqrt(2.0) * vol / c);
	return sqrt(best) / ideal;
}

int frdq_lowpass(const struct frs_matrix *m, double from, double to,
    double *ratio)
{
	double peak;
	return frdq_spectrum(m, from, to, ratio, &peak);
}

#define NBINS 64

int frdq_spectrum(const struct frs_matrix *m, double from, double to,
    double *ratio, double *peak)
{
	double bin[NBINS] = { 0 };
	size_t nbin[NBINS] = { 0 };
	size_t w = m->w, h = m->h;
	double *img, lo = 0.0, hi = 0.0, fp;
	size_t nlo = 0, nhi = 0, dots = 0;
	uint64_t lo_v = (uint64_t)(from * (double)m->n);
	uint64_t hi_v = (uint64_t)(to * (double)m->n);

	if (m->dims != 2 || !fft_is_pow2(w) || !fft_is_pow2(h))
		return cli_fail("the spectrum needs a 2-D matrix with "
		    "power-of-two sides");
	img = calloc(2 * w * h, sizeof *img);
	if (img == NULL)
		return cli_fail("out of memory for the spectrum");
	for (size_t i = 0; i < m->n; i++)
		if (m->v[i] >= lo_v && m->v[i] < hi_v) {
			img[2 * i] = 1.0;
			dots++;
		}
	fft2(img, w, h, -1);
	fp = sqrt((double)dots);
	for (size_t y = 0; y < h; y++)
		for (size_t x = 0; x < w; x++) {
			/* Frequencies in cycles per matrix side, scaled so that
			 * the plane is isotropic for non-square matrices. */
			double fx = (double)(x <= w / 2 ? (long)x : (long)x - (long)w);
			double fy = (double)(y <= h / 2 ? (long)y : (long)y - (long)h);
			double f = sqrt(fx * fx * ((double)h / (double)w) +
			    fy * fy * ((double)w / (double)h));
			double pw = (img[2 * (y * w + x)] * img[2 * (y * w + x)] +
			    img[2 * (y * w + x) + 1] * img[2 * (y * w + x) + 1]) /
			    (double)dots;
			if (f >= 0.5 * fp && f < 3.0 * fp) {
				size_t b = (size_t)((f - 0.5 * fp) / (2.5 * fp) * NBINS);
				b = b < NBINS ? b : NBINS - 1;	/* rounding at 3 fp */
				bin[b] += pw;
				nbin[b]++;
			}
			if (f > 0.0 && f < 0.5 * fp) {
				lo += pw;
				nlo++;
			} else if (f >= 1.5 * fp && f < 2.5 * fp) {
				hi += pw;
				nhi++;
			}
		}
	free(img);
	if (nlo == 0 || nhi == 0 || hi == 0.0)
		return cli_fail("too few dots (%zu) for the spectrum", dots);
	*ratio = (lo / (double)nlo) / (hi / (double)nhi);
	/* The highest radial mean: about 1.5 for blue noise, far more for
	 * the rings of a lattice. */
	*peak = 0.0;
	for (size_t b = 0; b < NBINS; b++)
		if (nbin[b] >= 8 && bin[b] / (double)nbin[b] > *peak)
			*peak = bin[b] / (double)nbin[b];
	*peak /= hi / (double)nhi;
	return 0;
}

/* ---- the figures of a level ---------------------------------------- */

static uint32_t side_of(const struct frs_matrix *m, int i)
{
	return i == 0 ? m->w : i == 1 ? m->h : m->d;
}

/* The side of a square (cube) of the matrix's area (volume): frequencies
 * scaled by it over each side make a non-square matrix isotropic. */
static double mean_side(const struct frs_matrix *m)
{
	return m->dims == 2 ? sqrt((double)m->w * m->h) :
	    cbrt((double)m->w * m->h * m->d);
}

/* Grid cells per axis, their product about c: the powers of two of c
 * handed round the axes (x first), or c^(1/k) scaled by the sides. */
static void strata_grid(const struct frs_matrix *m, uint64_t c, uint64_t g[3])
{
	unsigned k = m->dims;
	double gm = mean_side(m);

	g[0] = g[1] = g[2] = 1;
	if (fft_is_pow2(c)) {
		for (unsigned i = 0; c > 1; i = (i + 1) % k) {
			if (g[i] * 2 > side_of(m, (int)i)) {
				int full = 1;
				for (unsigned j = 0; j < k; j++)
					full &= g[j] * 2 > side_of(m, (int)j);
				if (full)
					break;
				continue;
			}
			g[i] *= 2;
			c /= 2;
		}
		return;
	}
	for (unsigned i = 0; i < k; i++) {
		double v = round(pow((double)c, 1.0 / k) * side_of(m, (int)i) / gm);
		g[i] = v < 1.0 ? 1 : v > side_of(m, (int)i) ?
		    side_of(m, (int)i) : (uint64_t)v;
	}
}

double frdq_strata(const struct frs_matrix *m, uint64_t lo, uint64_t hi)
{
	uint64_t g[3], cells, one = 0;
	uint32_t *cnt;

	if (hi <= lo)
		return NAN;
	strata_grid(m, hi - lo, g);
	cells = g[0] * g[1] * g[2];
	cnt = calloc(cells, sizeof *cnt);
	if (cnt == NULL)
		return NAN;
	for (size_t i = 0; i < m->n; i++)
		if (m->v[i] >= lo && m->v[i] < hi) {
			uint64_t x = i % m->w, y = i / m->w % m->h, z = i / m->w / m->h;
			uint64_t cx = x * g[0] / m->w, cy = y * g[1] / m->h;
			uint64_t cz = z * g[2] / m->d;
			cnt[(cz * g[1] + cy) * g[0] + cx]++;
		}
	for (uint64_t i = 0; i < cells; i++)
		one += cnt[i] == 1;
	free(cnt);
	return (double)one / (double)cells;
}

/* Annulus sums of the periodogram. */
struct radial {
	double *sum, *sum2;
	size_t *cnt, nb;
	double width, fp;
};

/* The periodogram of the dots (in img, transformed), its maximum and the
 * annulus sums. */
static void scan_spectrum(const struct frs_matrix *m, const double *img,
    double dots, struct radial *rd, struct frdq_level *q)
{
	double gm = mean_side(m);
	double sc[3] = { gm / m->w, gm / m->h, gm / m->d };

	for (size_t i = 0; i < m->n; i++) {
		size_t ix[3] = { i % m->w, i / m->w % m->h, i / m->w / m->h };
		double f2 = 0.0, p, f;
		size_t b;
		for (int a = 0; a < 3; a++) {
			uint32_t n = side_of(m, a);
			double k = ix[a] <= n / 2 ? (double)ix[a] :
			    (double)ix[a] - (double)n;
			f2 += k * k * sc[a] * sc[a];
		}
		if (f2 == 0.0)
			continue;
		p = (img[2 * i] * img[2 * i] + img[2 * i + 1] * img[2 * i + 1]) /
		    dots;
		f = sqrt(f2);
		if (p > q->pmax) {
			q->pmax = p;
			q->pmax_f = f / rd->fp;
		}
		b = (size_t)(f / rd->width);
		if (b < rd->nb) {
			rd->sum[b] += p;
			rd->sum2[b] += p * p;
			rd->cnt[b]++;
		}
	}
}

/* Peak, ring and anisotropy from the annulus sums. */
static void radial_figures(const struct radial *rd, struct frdq_level *q)
{
	for (size_t b = 0; b < rd->nb; b++) {
		double mean, var, fb = ((double)b + 0.5) * rd->width / rd->fp;
		if (rd->cnt[b] < 16 || fb < 0.5 || fb > 3.0)
			continue;
		mean = rd->sum[b] / (double)rd->cnt[b];
		var = (rd->sum2[b] - rd->sum[b] * mean) /
		    (double)(rd->cnt[b] - 1);
		if (mean > q->peak) {
			q->peak = mean;
			q->peak_f = fb;
		}
		if (mean > 0.0 && var > 0.0 && 10.0 * log10(var / (mean *
		    mean)) > q->aniso)
			q->aniso = 10.0 * log10(var / (mean * mean));
	}
	for (size_t b = 0; b < rd->nb; b++) {
		double mean, fb = ((double)b + 0.5) * rd->width / rd->fp;
		if (rd->cnt[b] < 16 || fb < 1.5 * q->peak_f || fb > 6.0)
			continue;
		mean = rd->sum[b] / (double)rd->cnt[b];
		if (mean > q->ring) {
			q->ring = mean;
			q->ring_f = fb;
		}
	}
}

static int spectral(const struct frs_matrix *m, struct frdq_level *q)
{
	struct radial rd;
	double *img, gm = mean_side(m);
	int rc;

	rd.fp = pow((double)q->dots, 1.0 / m->dims);
	rd.width = fmax(1.0, rd.fp / 16.0);
	rd.nb = (size_t)(gm * sqrt((double)m->dims) / 2.0 / rd.width) + 2;
	img = calloc(2 * m->n, sizeof *img);
	rd.sum = calloc(rd.nb, sizeof *rd.sum);
	rd.sum2 = calloc(rd.nb, sizeof *rd.sum2);
	rd.cnt = calloc(rd.nb, sizeof *rd.cnt);
	rc = img && rd.sum && rd.sum2 && rd.cnt ? 0 :
	    cli_fail("out of memory for the spectrum");
	if (rc == 0) {
		for (size_t i = 0; i < m->n; i++)
			img[2 * i] = m->v[i] >= q->lo && m->v[i] < q->hi;
		rc = fft3(img, m->w, m->h, m->d, -1);
	}
	if (rc == 0) {
		q->aniso = -INFINITY;
		scan_spectrum(m, img, (double)q->dots, &rd, q);
		radial_figures(&rd, q);
		q->spectral = 1;
	}
	free(img), free(rd.sum), free(rd.sum2), free(rd.cnt);
	return rc;
}

int frdq_level(const struct frs_matrix *m, uint64_t lo, uint64_t hi,
    struct frdq_level *q)
{
	memset(q, 0, sizeof *q);
	q->lo = lo;
	q->hi = hi > m->n ? m->n : hi;
	q->dots = q->hi > lo ? q->hi - lo : 0;
	if (q->dots == 0)
		return cli_fail("no values in [%llu, %llu)",
		    (unsigned long long)lo, (unsigned long long)hi);
	q->strata = frdq_strata(m, lo, q->hi);
	if (isnan(q->strata))
		return cli_fail("out of memory for the strata");
	if (!fft_is_pow2(m->w) || !fft_is_pow2(m->h) || !fft_is_pow2(m->d))
		return 0;
	return spectral(m, q);
}
