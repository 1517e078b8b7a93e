#define _POSIX_C_SOURCE 200809L
#include "frdq.h"
#include "err.h"
#include "fft.h"

#include <math.h>
#include <stdlib.h>

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
		return frs_fail("the spectrum needs a 2-D matrix with "
		    "power-of-two sides");
	img = calloc(2 * w * h, sizeof *img);
	if (img == NULL)
		return frs_fail("out of memory for the spectrum");
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
		return frs_fail("too few dots (%zu) for the spectrum", dots);
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
