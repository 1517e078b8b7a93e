/*
 * Fourier spectra of 2-D point sets (thesis Sec. 2.2 and 6.3), the core of
 * dda --fourier.
 *
 * The periodogram of a set of n points x_j in the unit torus is
 *   P(k) = |F(k)|^2 / n,   F(k) = sum_j exp(-2 pi i k . x_j),
 * on the integer frequencies k = (kx, ky), |kx|, |ky| <= K.  P(0) = n;
 * for uniform random points E P(k) = 1 at every k != 0, so 1 (0 dB) is
 * the level of white noise.  Coordinates need not lie in [0, 1): only
 * their fractional parts matter.  P(-k) = P(k) for real points.
 *
 * The functions add one set's periodogram to an image, so that the caller
 * sums the sets and divides by their number (or scales as it likes).
 * Image layout (struct spec_img): pixel (c, r) holds frequency
 * (kx, ky) = (c - half, r - half), DC at the centre (half, half); row 0,
 * at the top of the PNG, is ky = -half (y grows downward, as in the
 * point images).
 *
 * Both methods split their work with cli_parallel (when par is not 0;
 * otherwise the same chunks run in order on the calling thread) over
 * fixed chunks: the result is the same bit for bit for any thread count
 * and either par.  Errors: -1 with cli_fail (no points, a non-finite
 * coordinate, an image whose scale is not 1, out of memory); bad input
 * is found before the image is touched, but running out of memory half
 * way may leave it partly updated.
 */
#ifndef FRS_SPECTRUM_H
#define FRS_SPECTRUM_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* Largest half side of an image: side 2 * 8191 + 1 = 16383 pixels, under
 * FRS_MAP_MAX_PIXELS (so that every image can be written as a PNG). */
#define SPEC_MAX_HALF 8191u

/* An image centred on the origin: side 2*half+1 pixels, pixel (c, r) at
 * offset ((c - half) * scale, (r - half) * scale); row 0 at the top is the
 * most negative y offset (y grows downward, as in point images).
 * v: row-major, v[r * (2*half+1) + c]. */
struct spec_img {
	uint32_t half;
	double scale;
	double *v;
};

/* Zeroed image; half <= SPEC_MAX_HALF, scale finite and > 0 (-1 with
 * cli_fail otherwise); within the memory ceiling, else the program ends
 * with its message (cli_calloc). */
int spec_img_alloc(struct spec_img *im, uint32_t half, double scale);
void spec_img_free(struct spec_img *im);

/*
 * Add one set's periodogram |sum_j exp(-2 pi i (kx x_j + ky y_j))|^2 / n at
 * every integer frequency |kx|, |ky| <= K = im->half to im->v; im->scale
 * must be 1.  xy: n points, x and y interleaved.
 *
 * Exact, by direct summation in O(n K^2), separable: per point the 1-D
 * factors cos and sin of 2 pi frac(k x) and 2 pi frac(k y), k = 0..K, each
 * from its own reduced argument (no recurrence; a branch-free sincos of
 * 2 pi t, t in [0, 1), within 1e-15 of libm's, that the compiler
 * vectorises), then one real matrix product over the points,
 * G = X Y^T with X, Y the (2K+1) x n factor matrices (cos rows, then sin
 * rows), packed in panels and blocked for the cache (4 x 4 register
 * blocks, 256 points per pass).  The four products CC, SS, CS, SC of G give
 *   F(kx, ky) = CC - SS - i (CS + SC),  F(-kx, ky) = CC + SS + i (SC - CS)
 * for kx, ky >= 0, and P(-k) = P(k) gives the other half: (2K+1)^2
 * multiply-adds per point, half of what the complex product over the half
 * plane takes.  P(k) and P(-k) come out of the same operations, so they
 * are equal bit for bit.  Accuracy: within 2e-13 of a naive sum of
 * complex exponentials, relative to max(P, 1) (sums in double, in point
 * order).  Memory: 2 (2K+1) * 2048 doubles of factors (points go in
 * blocks of 2048), (2K+1)^2 of products.
 *
 * Time (AMD EPYC, -O2, SSE2): 10 sets of 1024 points at K = 128
 * (257 x 257 frequencies) in 0.06 s with 2 threads, 0.10 s with one.
 */
int spec_fourier_exact(const double *xy, size_t n, int par,
    struct spec_img *im);

/*
 * The same, approximately: a type-1 non-uniform FFT (Dutt and Rokhlin
 * 1993; Greengard and Lee 2004, "Accelerating the nonuniform fast Fourier
 * transform").  Each point is spread with a truncated Gaussian
 * exp(-d^2 / (2 s^2)) (d in grid cells, SPEC_NUFFT_W cells on each side:
 * a 2W x 2W footprint) onto a periodic N x N grid, N the smallest power of
 * two >= max(4K, 4W, 16) (oversampling N / (2K+1) >= about 2); the
 * grid is real, so its row FFTs are done two rows per complex FFT of
 * fft1 (src/lib/base/fft.h) and only the K+1 columns kx = 0..K are transformed
 * along y (F(-k) = conj F(k)); the kernel's Fourier transform
 * 2 pi s^2 exp(-2 pi^2 s^2 |k|^2 / N^2) is divided out.  With rho = K / N
 * (<= 1/4), s^2 = W / (2 pi (1 - rho)) balances the aliasing error
 * exp(-2 pi^2 s^2 (1 - 2 rho)) against the truncation error amplified by
 * the deconvolution, giving about exp(-pi W (1 - 2 rho) / (1 - rho)):
 * 1.2e-11 for W = 12 at the worst rho = 1/4.
 *
 * Error, measured against spec_fourier_exact: the amplitude
 * |F(k)| = sqrt(n P(k)) is within SPEC_NUFFT_ERR * n of the exact one at
 * every k, that is relative to the largest possible amplitude F(0) = n
 * (the usual NUFFT measure; a relative error per frequency means nothing
 * where F(k) is near 0).  The largest error seen was 2.5e-11, for sets
 * whose aliases add coherently (regular grids, a single point) at
 * K = N/4; random and jittered sets of 1024 points at K = 128 give about
 * 1e-12.  SPEC_NUFFT_ERR = 5e-11 is the bound the tests check
 * (test/test_spectrum.c).  For P this means
 *   |P - P_exact| <= 2 SPEC_NUFFT_ERR sqrt(n P_exact) + SPEC_NUFFT_ERR^2 n,
 * about 3e-9 at P = 1, n = 1024: far below what a picture or a radial
 * mean shows.
 *
 * Cost: O(n W^2 + N^2 log N): spreading 4 W^2 multiply-adds per point, and
 * FFTs independent of n.  It pays off for large n: at n = 1024, K = 128
 * the FFTs dominate and it takes 0.04 s for 10 sets with 2 threads
 * (0.055 s with one), little better than the exact sum; for one set of
 * n = 65536 it takes 0.026 s against 0.40 s.  Memory: N^2 doubles of
 * grid, N (K+1) complex values.
 */
#define SPEC_NUFFT_W 12
#define SPEC_NUFFT_ERR 5e-11
int spec_fourier_approx(const double *xy, size_t n, int par,
    struct spec_img *im);

/*
 * Radial statistics over annuli of width bin (in the image's units:
 * distance = pixel distance * scale).  Annulus i holds the pixels with
 * i*bin <= |offset| < (i+1)*bin, so DC is in annulus 0; only annuli that
 * lie wholly inside the image, (i+1)*bin <= half*scale, are reported
 * (pixels farther out, in the corners, are not used).  psa's convention
 * for a periodogram (scale 1) is bin = 2.
 *   lo[i]     i * bin, the annulus's lower edge;
 *   count[i]  pixels in the annulus;
 *   mean[i]   mean of their values (compensated sum);
 *   aniso[i]  10 log10(s^2 / mean^2) in dB, s^2 the unbiased variance
 *             (divisor count - 1) about the mean: for the average of m
 *             independent periodograms of a random process about
 *             10 log10(1/m), -10 dB for m = 10; a constant annulus gives
 *             -INFINITY.
 * An annulus with fewer than two pixels, or with a zero mean, has no
 * anisotropy: its count, mean and aniso are all set to 0, and writers skip
 * it (count 0).  The result never holds a NaN.
 * Errors: bin not finite or <= 0, bin larger than half*scale (no annulus),
 * more than 2^24 annuli, a non-finite pixel, out of memory.
 */
struct spec_radial {
	size_t nbins;
	double *lo, *mean, *aniso;
	uint64_t *count;
};

int spec_radial(const struct spec_img *im, double bin, struct spec_radial *r);
void spec_radial_free(struct spec_radial *r);

/*
 * 8-bit grey PNG of the image, side 2*half+1, row 0 at the top, DC in the
 * centre pixel (half, half):
 *   grey = round(255 * clamp((10 log10 v - lo_db) / (hi_db - lo_db), 0, 1)),
 * black for v <= 0 (and NaN).  The scale is logarithmic: lo_db and below
 * black, hi_db and above white, linear in dB between.  dda's defaults,
 * lo_db = -10 and hi_db = +10, make white noise (P = 1, 0 dB) mid grey
 * 128, a tenth of it black, and the DC peak (P = n) saturate white.
 * lo_db < hi_db, both finite.  name is used in messages.
 */
int spec_write_png(FILE *fp, const char *name, const struct spec_img *im,
    double lo_db, double hi_db);
/* The grey level of one value v in that scale (what spec_write_png
 * writes for it). */
uint8_t spec_grey(double v, double lo_db, double hi_db);

#endif
