#define _POSIX_C_SOURCE 200809L
#include "cli/fft.h"
#include "base/err.h"
#include "base/num.h"

#include <math.h>
#include <stdlib.h>


int fft_is_pow2(size_t n)
{
	return n > 0 && (n & (n - 1)) == 0;
}

int fft1(double *x, size_t n, size_t stride, int sign)
{
	if (!fft_is_pow2(n))
		return frs_fail("FFT size %zu is not a power of two", n);
	/* Bit reversal. */
	for (size_t i = 1, j = 0; i < n; i++) {
		size_t bit = n >> 1;
		for (; j & bit; bit >>= 1)
			j ^= bit;
		j ^= bit;
		if (i < j) {
			double *a = x + 2 * i * stride, *b = x + 2 * j * stride;
			double tr = a[0], ti = a[1];
			a[0] = b[0];
			a[1] = b[1];
			b[0] = tr;
			b[1] = ti;
		}
	}
	for (size_t len = 2; len <= n; len <<= 1) {
		double ang = sign * 2.0 * NUM_PI / (double)len;
		for (size_t k = 0; k < len / 2; k++) {
			/* Twiddles from sin/cos each time: exact enough, and
			 * no drift from recurrences. */
			double wr = cos(ang * (double)k), wi = sin(ang * (double)k);
			for (size_t i = k; i < n; i += len) {
				double *a = x + 2 * i * stride;
				double *b = x + 2 * (i + len / 2) * stride;
				double tr = b[0] * wr - b[1] * wi;
				double ti = b[0] * wi + b[1] * wr;
				b[0] = a[0] - tr;
				b[1] = a[1] - ti;
				a[0] += tr;
				a[1] += ti;
			}
		}
	}
	return 0;
}

int fft2(double *x, size_t w, size_t h, int sign)
{
	if (!fft_is_pow2(w) || !fft_is_pow2(h))
		return frs_fail("FFT size %zux%zu is not a power of two", w, h);
	for (size_t y = 0; y < h; y++)
		fft1(x + 2 * y * w, w, 1, sign);
	for (size_t xcol = 0; xcol < w; xcol++)
		fft1(x + 2 * xcol, h, w, sign);
	return 0;
}

int fft3(double *x, size_t w, size_t h, size_t d, int sign)
{
	if (!fft_is_pow2(d))
		return frs_fail("FFT size %zux%zux%zu is not a power of two", w,
		    h, d);
	for (size_t z = 0; z < d; z++)
		if (fft2(x + 2 * z * w * h, w, h, sign) < 0)
			return -1;
	if (d > 1)
		for (size_t i = 0; i < w * h; i++)
			fft1(x + 2 * i, d, w * h, sign);
	return 0;
}
