/* In-place complex FFT, radix 2, for power-of-two sizes. */
#ifndef FRS_FFT_H
#define FRS_FFT_H

#include <stddef.h>

/* n complex values interleaved (re, im); n a power of two.  sign -1 is the
 * forward transform sum x_k exp(-2 pi i j k / n), no scaling. */
int fft1(double *x, size_t n, size_t stride, int sign);
/* Row-major w x h complex image, both powers of two. */
int fft2(double *x, size_t w, size_t h, int sign);
/* Row-major w x h x d complex volume (x fastest), all powers of two. */
int fft3(double *x, size_t w, size_t h, size_t d, int sign);
int fft_is_pow2(size_t n);

#endif
