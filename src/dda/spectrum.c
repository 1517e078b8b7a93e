/*
 * Fourier spectra of point sets: the exact periodogram as a blocked real
 * matrix product of separable factors, an approximate one by a Gaussian
 * gridding NUFFT, radial mean and anisotropy, and the PNG picture.
 * See spectrum.h for the mathematics and the error bounds.
 */
#define _POSIX_C_SOURCE 200809L
#include "dda/spectrum.h"
#include "cli/cli.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>


/* ---- images -------------------------------------------------------- */

int spec_img_alloc(struct spec_img *im, uint32_t half, double scale)
{
	size_t side = 2 * (size_t)half + 1;

	im->half = half;
	im->scale = scale;
	im->v = NULL;
	if (!(scale > 0.0) || !isfinite(scale))
		return cli_fail("spectrum image: scale %g is not finite and "
		    "positive", scale);
	if (half > SPEC_MAX_HALF)
		return cli_fail("spectrum image: half side %u is more than "
		    "%u", half, SPEC_MAX_HALF);
	im->v = cli_calloc("spectrum image", side * side, sizeof *im->v);
	return 0;
}

void spec_img_free(struct spec_img *im)
{
	free(im->v);
	im->v = NULL;
}

static int check_input(const double *xy, size_t n,
    const struct spec_img *im, const char *what)
{
	if (im == NULL || im->v == NULL)
		return cli_fail("%s: no image", what);
	if (im->scale != 1.0)
		return cli_fail("%s: the image's scale is %g, not 1 (integer "
		    "frequencies)", what, im->scale);
	if (n == 0 || xy == NULL)
		return cli_fail("%s: no points", what);
	for (size_t i = 0; i < 2 * n; i++)
		if (!isfinite(xy[i]))
			return cli_fail("%s: point %zu: coordinate %c is not "
			    "finite", what, i / 2, i % 2 ? 'y' : 'x');
	return 0;
}

/* ---- exact --------------------------------------------------------- */

/*
 * G = X Y^T over blocks of EX_NB points.  X (rows: cos 0..K, sin 1..K of
 * 2 pi k x) is packed in panels of MR rows, point-major within a panel:
 * X[r][p] at xp[((r / MR) * nb + p) * MR + r % MR]; Y likewise with NR.
 * The micro-kernel keeps an MR x NR block of G in registers over EX_KC
 * points.  Every entry of G is summed in point order, blocks of EX_KC
 * added in turn: the same for any split of the panels among threads.
 */
#define MR 4
#define NR 4
#define EX_KC 256
#define EX_NB 2048

struct exact {
	const double *xy;
	size_t n0, nb;		/* first point of the block, its size */
	uint32_t K;
	size_t rows;		/* 2K + 1 */
	size_t mp, np;		/* panels of X and Y */
	size_t ldg;		/* np * NR */
	double *xp, *yp, *g;
	int first;		/* first block: store, not add */
	double inv_n;
	struct spec_img *im;
};

/* Row r of the factor panels of point p. */
#define PUT(buf, R, nb, p, r, val) \
	((buf)[(((r) / (R)) * (nb) + (p)) * (R) + (r) % (R)] = (val))

#define EX_PTS 64	/* points per factor chunk */

/*
 * c = cos 2 pi t, s = sin 2 pi t for t in [0, 1): t = q/4 + u with
 * q = round(4t) in 0..4 and |u| <= 1/8 (exact), Taylor series of x = 2 pi u
 * (|x| <= pi/4; the first omitted terms are below 5e-17), then a rotation
 * by q quarter turns, cos(pi q/2) and sin(pi q/2) as exact polynomials in
 * d = q - 2.  Within 1e-15 of the libm values; branch-free, so that the
 * compiler vectorises it.
 */
static void cos_sin_2pi(const double *restrict t, double *restrict c,
    double *restrict s)
{
	for (int p = 0; p < EX_PTS; p++) {
		double q = (double)(int)(4.0 * t[p] + 0.5);
		double x = 2.0 * NUM_PI * (t[p] - 0.25 * q), z = x * x;
		double d = q - 2.0, d2 = d * d;
		double cq = (d2 * (7.0 - d2) - 6.0) / 6.0;
		double sq = d * (d2 - 4.0) / 3.0;
		double sn = x * (1.0 + z * (-1.0 / 6 + z * (1.0 / 120 +
		    z * (-1.0 / 5040 + z * (1.0 / 362880 +
		    z * (-1.0 / 39916800 + z * (1.0 / 6227020800.0 +
		    z * (-1.0 / 1307674368000.0))))))));
		double cn = 1.0 + z * (-0.5 + z * (1.0 / 24 + z * (-1.0 / 720 +
		    z * (1.0 / 40320 + z * (-1.0 / 3628800 +
		    z * (1.0 / 479001600 + z * (-1.0 / 87178291200.0 +
		    z * (1.0 / 20922789888000.0))))))));
		c[p] = cn * cq - sn * sq;
		s[p] = sn * cq + cn * sq;
	}
}

/* Factors of the points [b, e) of the block (at most EX_PTS). */
static int exact_factors(void *ctx, uint64_t b, uint64_t e)
{
	struct exact *c = ctx;
	size_t K = c->K, nb = c->nb, m = (size_t)(e - b);
	double f[2][EX_PTS], t[EX_PTS], cv[EX_PTS], sv[EX_PTS];

	for (size_t p = 0; p < EX_PTS; p++)
		for (int a = 0; a < 2; a++) {
			double v = p < m ?
			    c->xy[2 * (c->n0 + b + p) + (size_t)a] : 0.0;
			f[a][p] = v - floor(v);	/* [0, 1], 1 acts as 0 */
		}
	for (size_t p = b; p < e; p++) {
		PUT(c->xp, MR, nb, p, 0, 1.0);
		PUT(c->yp, NR, nb, p, 0, 1.0);
		for (size_t r = c->rows; r < c->mp * MR; r++)
			PUT(c->xp, MR, nb, p, r, 0.0);
		for (size_t r = c->rows; r < c->np * NR; r++)
			PUT(c->yp, NR, nb, p, r, 0.0);
	}
	for (size_t k = 1; k <= K; k++)
		for (int a = 0; a < 2; a++) {
			for (size_t p = 0; p < EX_PTS; p++) {
				double v = (double)k * f[a][p];
				t[p] = v - (double)(int)v;
			}
			cos_sin_2pi(t, cv, sv);
			for (size_t p = 0; p < m; p++) {
				if (a == 0) {
					PUT(c->xp, MR, nb, b + p, k, cv[p]);
					PUT(c->xp, MR, nb, b + p, K + k, sv[p]);
				} else {
					PUT(c->yp, NR, nb, b + p, k, cv[p]);
					PUT(c->yp, NR, nb, b + p, K + k, sv[p]);
				}
			}
		}
	return 0;
}

/* g[i][j] (+)= sum_p a[p][i] b[p][j], i < MR, j < NR, p < kc. */
static void micro(size_t kc, const double *restrict a,
    const double *restrict b, double *restrict g, size_t ldg, int store)
{
	double c00 = 0, c01 = 0, c02 = 0, c03 = 0;
	double c10 = 0, c11 = 0, c12 = 0, c13 = 0;
	double c20 = 0, c21 = 0, c22 = 0, c23 = 0;
	double c30 = 0, c31 = 0, c32 = 0, c33 = 0;

	for (size_t p = 0; p < kc; p++, a += MR, b += NR) {
		double b0 = b[0], b1 = b[1], b2 = b[2], b3 = b[3];
		double a0 = a[0], a1 = a[1], a2 = a[2], a3 = a[3];
		c00 += a0 * b0; c01 += a0 * b1; c02 += a0 * b2; c03 += a0 * b3;
		c10 += a1 * b0; c11 += a1 * b1; c12 += a1 * b2; c13 += a1 * b3;
		c20 += a2 * b0; c21 += a2 * b1; c22 += a2 * b2; c23 += a2 * b3;
		c30 += a3 * b0; c31 += a3 * b1; c32 += a3 * b2; c33 += a3 * b3;
	}
	if (store) {
		g[0] = c00; g[1] = c01; g[2] = c02; g[3] = c03; g += ldg;
		g[0] = c10; g[1] = c11; g[2] = c12; g[3] = c13; g += ldg;
		g[0] = c20; g[1] = c21; g[2] = c22; g[3] = c23; g += ldg;
		g[0] = c30; g[1] = c31; g[2] = c32; g[3] = c33;
	} else {
		g[0] += c00; g[1] += c01; g[2] += c02; g[3] += c03; g += ldg;
		g[0] += c10; g[1] += c11; g[2] += c12; g[3] += c13; g += ldg;
		g[0] += c20; g[1] += c21; g[2] += c22; g[3] += c23; g += ldg;
		g[0] += c30; g[1] += c31; g[2] += c32; g[3] += c33;
	}
}

/* Panels [b, e) of X against all of Y. */
static int exact_gemm(void *ctx, uint64_t b, uint64_t e)
{
	struct exact *c = ctx;

	for (size_t k0 = 0; k0 < c->nb; k0 += EX_KC) {
		size_t kc = c->nb - k0 < EX_KC ? c->nb - k0 : EX_KC;
		int store = c->first && k0 == 0;
		for (size_t i = (size_t)b; i < (size_t)e; i++) {
			const double *a = c->xp + (i * c->nb + k0) * MR;
			double *g = c->g + i * MR * c->ldg;
			for (size_t j = 0; j < c->np; j++)
				micro(kc, a, c->yp + (j * c->nb + k0) * NR,
				    g + j * NR, c->ldg, store);
		}
	}
	return 0;
}

/* Image rows [b, e) from G. */
static int exact_pixels(void *ctx, uint64_t b, uint64_t e)
{
	struct exact *c = ctx;
	long K = (long)c->K;
	size_t side = 2 * (size_t)K + 1, ld = c->ldg;
	const double *g = c->g;

	for (size_t r = (size_t)b; r < (size_t)e; r++) {
		long ky = (long)r - K;
		size_t ay = (size_t)labs(ky);
		double *out = c->im->v + r * side;
		for (size_t col = 0; col < side; col++) {
			long kx = (long)col - K;
			size_t ax = (size_t)labs(kx);
			double cc = g[ax * ld + ay];
			double ss = ax && ay ? g[(c->K + ax) * ld + c->K + ay] : 0;
			double cs = ay ? g[ax * ld + c->K + ay] : 0.0;
			double sc = ax ? g[(c->K + ax) * ld + ay] : 0.0;
			double re, im;
			if ((kx >= 0) == (ky >= 0)) {
				re = cc - ss;
				im = cs + sc;
			} else {
				re = cc + ss;
				im = cs - sc;
			}
			out[col] += (re * re + im * im) * c->inv_n;
		}
	}
	return 0;
}

int spec_fourier_exact(const double *xy, size_t n, int par,
    struct spec_img *im)
{
	struct exact c;
	size_t nbmax;
	int rc = 0;

	if (check_input(xy, n, im, "exact Fourier spectrum") < 0)
		return -1;
	c = (struct exact){ .xy = xy, .K = im->half, .im = im,
	    .inv_n = 1.0 / (double)n, .rows = 2 * (size_t)im->half + 1 };
	c.mp = (c.rows + MR - 1) / MR;
	c.np = (c.rows + NR - 1) / NR;
	c.ldg = c.np * NR;
	nbmax = n < EX_NB ? n : EX_NB;
	c.xp = malloc(c.mp * MR * nbmax * sizeof *c.xp);
	c.yp = malloc(c.np * NR * nbmax * sizeof *c.yp);
	c.g = malloc(c.mp * MR * c.ldg * sizeof *c.g);
	if (c.xp == NULL || c.yp == NULL || c.g == NULL) {
		rc = cli_fail("exact Fourier spectrum: no memory for K = %u",
		    c.K);
		goto out;
	}
	for (size_t n0 = 0; n0 < n && rc == 0; n0 += EX_NB) {
		c.n0 = n0;
		c.nb = n - n0 < EX_NB ? n - n0 : EX_NB;
		c.first = n0 == 0;
		rc = cli_parallel_if(par, c.nb, EX_PTS, exact_factors, &c);
		if (rc == 0)
			rc = cli_parallel_if(par, c.mp, 2, exact_gemm, &c);
	}
	if (rc == 0)
		rc = cli_parallel_if(par, c.rows, 16, exact_pixels, &c);
out:
	free(c.xp);
	free(c.yp);
	free(c.g);
	return rc;
}

/* ---- approximate: Gaussian gridding NUFFT ------------------------- */

#define NU_W SPEC_NUFFT_W
#define NU_STRIP 8		/* grid rows per spreading chunk */

struct nufft {
	size_t n;
	uint32_t K;
	size_t N;		/* grid side, a power of two */
	double s2;		/* kernel variance in grid cells^2 */
	double e3[2 * NU_W];	/* exp(-l^2 / (2 s2)), l = -W+1..W */
	size_t *start;		/* N + 1 bucket starts (by grid row) */
	double *u;		/* points in grid units, sorted by bucket */
	double *grid;		/* N x N real */
	double *h;		/* N x (K+1) complex: rows transformed */
	double *dec;		/* K+1 deconvolution factors */
	double inv_n;
	struct spec_img *im;
};

/* w[l + W - 1] = exp(-(l - d)^2 / (2 s2)), l = -W+1..W, as
 * exp(-d^2/(2 s2)) exp(l d / s2) exp(-l^2 / (2 s2)). */
static void nu_weights(const struct nufft *c, double d, double *w)
{
	double e1 = exp(-d * d / (2.0 * c->s2)), e2 = exp(d / c->s2);
	double e2i = 1.0 / e2, pw = e1;

	for (int l = 0; l <= NU_W; l++, pw *= e2)
		w[l + NU_W - 1] = pw * c->e3[l + NU_W - 1];
	pw = e1 * e2i;
	for (int l = -1; l > -NU_W; l--, pw *= e2i)
		w[l + NU_W - 1] = pw * c->e3[l + NU_W - 1];
}

/* Grid rows [b, e): every point whose footprint reaches them, bucket by
 * bucket in a fixed order.  The buckets visited, NU_STRIP + 2W - 1 of them,
 * are fewer than N (>= 4W), so none is visited twice. */
static int nu_spread(void *ctx, uint64_t b, uint64_t e)
{
	struct nufft *c = ctx;
	long r0 = (long)b, r1 = (long)e, N = (long)c->N;
	size_t mask = c->N - 1;
	double wx[2 * NU_W], wy[2 * NU_W];

	memset(c->grid + b * c->N, 0, (size_t)(e - b) * c->N *
	    sizeof *c->grid);
	for (long m = r0 - NU_W; m <= r1 + NU_W - 2; m++) {
		size_t bk = (size_t)((m % N + N) % N);
		long lo = r0 - m > 1 - NU_W ? r0 - m : 1 - NU_W;
		long hi = r1 - 1 - m < NU_W ? r1 - 1 - m : NU_W;
		for (size_t i = c->start[bk]; i < c->start[bk + 1]; i++) {
			double ux = c->u[2 * i], uy = c->u[2 * i + 1];
			double fx = floor(ux);
			size_t mx = (size_t)fx;
			nu_weights(c, ux - fx, wx);
			nu_weights(c, uy - (double)bk, wy);
			for (long l = lo; l <= hi; l++) {
				double *row = c->grid + (size_t)(m + l) * c->N;
				double f = wy[l + NU_W - 1];
				size_t x0 = mx + c->N - (NU_W - 1);
				for (size_t t = 0; t < 2 * NU_W; t++)
					row[(x0 + t) & mask] += f * wx[t];
			}
		}
	}
	return 0;
}

/* Row pairs [b, e): rows 2q and 2q+1 as one complex FFT along x; keep
 * kx = 0..K of each. */
static int nu_rows(void *ctx, uint64_t b, uint64_t e)
{
	struct nufft *c = ctx;
	size_t N = c->N, K1 = (size_t)c->K + 1;
	double *z = malloc(2 * N * sizeof *z);

	if (z == NULL)
		return cli_fail("approximate Fourier spectrum: no memory");
	for (size_t q = (size_t)b; q < (size_t)e; q++) {
		const double *g0 = c->grid + 2 * q * N, *g1 = g0 + N;
		double *h0 = c->h + 2 * (2 * q * K1), *h1 = h0 + 2 * K1;
		for (size_t m = 0; m < N; m++) {
			z[2 * m] = g0[m];
			z[2 * m + 1] = g1[m];
		}
		fft1(z, N, 1, -1);
		for (size_t k = 0; k < K1; k++) {
			size_t j = (N - k) & (N - 1);
			double ar = z[2 * k], ai = z[2 * k + 1];
			double br = z[2 * j], bi = -z[2 * j + 1];	/* conj */
			/* A = (Z_k + conj Z_-k) / 2, B = (Z_k - conj Z_-k) / 2i */
			h0[2 * k] = 0.5 * (ar + br);
			h0[2 * k + 1] = 0.5 * (ai + bi);
			h1[2 * k] = 0.5 * (ai - bi);
			h1[2 * k + 1] = -0.5 * (ar - br);
		}
	}
	free(z);
	return 0;
}

/* Columns kx in [b, e): FFT along y, deconvolve, add P at (kx, ky) and,
 * for kx > 0, at (-kx, -ky). */
static int nu_cols(void *ctx, uint64_t b, uint64_t e)
{
	struct nufft *c = ctx;
	size_t N = c->N, K = c->K, K1 = K + 1, side = 2 * K + 1;
	double *z = malloc(2 * N * sizeof *z);

	if (z == NULL)
		return cli_fail("approximate Fourier spectrum: no memory");
	for (size_t kx = (size_t)b; kx < (size_t)e; kx++) {
		for (size_t m = 0; m < N; m++) {
			z[2 * m] = c->h[2 * (m * K1 + kx)];
			z[2 * m + 1] = c->h[2 * (m * K1 + kx) + 1];
		}
		fft1(z, N, 1, -1);
		for (size_t r = 0; r < side; r++) {
			size_t aky = r > K ? r - K : K - r;
			size_t j = (r + N - K) & (N - 1);	/* ky mod N */
			double f = c->dec[kx] * c->dec[aky];
			double re = z[2 * j] * f, im = z[2 * j + 1] * f;
			double p = (re * re + im * im) * c->inv_n;
			c->im->v[r * side + K + kx] += p;
			if (kx > 0)
				c->im->v[(side - 1 - r) * side + K - kx] += p;
		}
	}
	free(z);
	return 0;
}

int spec_fourier_approx(const double *xy, size_t n, int par,
    struct spec_img *im)
{
	struct nufft c;
	size_t *pos = NULL;
	double rho;
	int rc = 0;

	if (check_input(xy, n, im, "approximate Fourier spectrum") < 0)
		return -1;
	c = (struct nufft){ .n = n, .K = im->half, .im = im,
	    .inv_n = 1.0 / (double)n };
	for (c.N = 16; c.N < 4 * (size_t)c.K || c.N < 4 * NU_W; c.N *= 2)
		;
	rho = (double)c.K / (double)c.N;
	c.s2 = NU_W / (2.0 * NUM_PI * (1.0 - rho));
	for (int l = 1 - NU_W; l <= NU_W; l++)
		c.e3[l + NU_W - 1] = exp(-(double)(l * l) / (2.0 * c.s2));
	c.start = calloc(c.N + 1, sizeof *c.start);
	pos = malloc(n * sizeof *pos);
	c.u = malloc(2 * n * sizeof *c.u);
	c.grid = malloc(c.N * c.N * sizeof *c.grid);
	c.h = malloc(2 * c.N * ((size_t)c.K + 1) * sizeof *c.h);
	c.dec = malloc(((size_t)c.K + 1) * sizeof *c.dec);
	if (c.start == NULL || pos == NULL || c.u == NULL || c.grid == NULL ||
	    c.h == NULL || c.dec == NULL) {
		rc = cli_fail("approximate Fourier spectrum: no memory for a "
		    "%zu x %zu grid", c.N, c.N);
		goto out;
	}
	/* Points in grid units [0, N), bucketed by row, stable. */
	for (size_t i = 0; i < n; i++) {
		double uy = (xy[2 * i + 1] - floor(xy[2 * i + 1])) *
		    (double)c.N;
		size_t my;
		if (uy >= (double)c.N)
			uy -= (double)c.N;
		my = (size_t)uy;
		pos[i] = my;
		c.start[my + 1]++;
	}
	for (size_t m = 0; m < c.N; m++)
		c.start[m + 1] += c.start[m];
	for (size_t i = 0; i < n; i++) {
		size_t at = c.start[pos[i]]++;
		double ux = (xy[2 * i] - floor(xy[2 * i])) * (double)c.N;
		double uy = (xy[2 * i + 1] - floor(xy[2 * i + 1])) *
		    (double)c.N;
		c.u[2 * at] = ux >= (double)c.N ? ux - (double)c.N : ux;
		c.u[2 * at + 1] = uy >= (double)c.N ? uy - (double)c.N : uy;
	}
	for (size_t m = c.N; m > 0; m--)
		c.start[m] = c.start[m - 1];
	c.start[0] = 0;
	/* 1 / (N^2 ghat(kx) ghat(ky)) = dec[kx] dec[ky], ghat the kernel's
	 * transform s/N sqrt(2 pi) exp(-2 pi^2 s2 k^2 / N^2). */
	for (size_t k = 0; k <= c.K; k++) {
		double t = (double)k / (double)c.N;
		c.dec[k] = exp(2.0 * NUM_PI * NUM_PI * c.s2 * t * t) /
		    sqrt(2.0 * NUM_PI * c.s2);
	}
	rc = cli_parallel_if(par, c.N, NU_STRIP, nu_spread, &c);
	if (rc == 0)
		rc = cli_parallel_if(par, c.N / 2, 8, nu_rows, &c);
	if (rc == 0)
		rc = cli_parallel_if(par, (uint64_t)c.K + 1, 4, nu_cols, &c);
out:
	free(c.start), free(pos), free(c.u);
	free(c.grid), free(c.h), free(c.dec);
	return rc;
}

/* ---- radial statistics -------------------------------------------- */

void spec_radial_free(struct spec_radial *r)
{
	free(r->lo), free(r->mean), free(r->aniso), free(r->count);
	memset(r, 0, sizeof *r);
}

/* Annulus of distance d, or nb when outside the reported ones. */
static size_t annulus(double d, double bin, size_t nb)
{
	double q = floor(d / bin);
	size_t i;

	if (!(q < (double)nb))
		return nb;
	i = (size_t)q;
	if (i > 0 && (double)i * bin > d)
		i--;
	else if ((double)(i + 1) * bin <= d)
		i++;
	return i;
}

int spec_radial(const struct spec_img *im, double bin, struct spec_radial *r)
{
	size_t side, nb;
	double rmax;
	struct num_sum *s = NULL;
	int rc = 0;

	memset(r, 0, sizeof *r);
	if (im == NULL || im->v == NULL)
		return cli_fail("radial statistics: no image");
	if (!(bin > 0.0) || !isfinite(bin))
		return cli_fail("radial statistics: annulus width %g is not "
		    "finite and positive", bin);
	side = 2 * (size_t)im->half + 1;
	rmax = (double)im->half * im->scale;
	if (rmax / bin > (double)(1 << 24))
		return cli_fail("radial statistics: annulus width %g gives "
		    "more than 2^24 annuli", bin);
	nb = (size_t)floor(rmax / bin);
	while ((double)(nb + 1) * bin <= rmax)
		nb++;
	while (nb > 0 && (double)nb * bin > rmax)
		nb--;
	if (nb == 0)
		return cli_fail("radial statistics: annulus width %g is more "
		    "than the image's radius %g", bin, rmax);
	for (size_t i = 0; i < side * side; i++)
		if (!isfinite(im->v[i]))
			return cli_fail("radial statistics: pixel (%zu, %zu) "
			    "is not finite", i % side, i / side);
	r->nbins = nb;
	r->lo = malloc(nb * sizeof *r->lo);
	r->mean = malloc(nb * sizeof *r->mean);
	r->aniso = malloc(nb * sizeof *r->aniso);
	r->count = calloc(nb, sizeof *r->count);
	s = calloc(nb, sizeof *s);
	if (r->lo == NULL || r->mean == NULL || r->aniso == NULL ||
	    r->count == NULL || s == NULL) {
		rc = cli_fail("radial statistics: no memory for %zu annuli",
		    nb);
		spec_radial_free(r);
		goto out;
	}
	/* Pass 1: counts and means; pass 2: squared deviations. */
	for (int pass = 0; pass < 2; pass++) {
		for (size_t row = 0; row < side; row++) {
			double dy = (double)row - (double)im->half;
			for (size_t col = 0; col < side; col++) {
				double dx = (double)col - (double)im->half;
				double d = sqrt(dx * dx + dy * dy) * im->scale;
				double v = im->v[row * side + col];
				size_t i = annulus(d, bin, nb);
				if (i >= nb)
					continue;
				if (pass == 0) {
					r->count[i]++;
					num_add(&s[i], v);
				} else {
					double dv = v - r->mean[i];
					num_add(&s[i], dv * dv);
				}
			}
		}
		if (pass == 1)
			break;
		for (size_t i = 0; i < nb; i++) {
			r->mean[i] = r->count[i] ?
			    num_total(&s[i]) / (double)r->count[i] : 0.0;
			s[i] = (struct num_sum){ 0.0, 0.0 };
		}
	}
	for (size_t i = 0; i < nb; i++) {
		double var;
		r->lo[i] = (double)i * bin;
		if (r->count[i] < 2 || r->mean[i] == 0.0) {
			r->count[i] = 0;
			r->mean[i] = r->aniso[i] = 0.0;
			continue;
		}
		var = num_total(&s[i]) / (double)(r->count[i] - 1);
		r->aniso[i] = var > 0.0 ? 10.0 * log10(var) -
		    20.0 * log10(fabs(r->mean[i])) : -INFINITY;
	}
out:
	free(s);
	return rc;
}

/* ---- picture -------------------------------------------------------- */

uint8_t spec_grey(double v, double lo_db, double hi_db)
{
	double t = 0.0;

	if (v > 0.0) {
		t = (10.0 * log10(v) - lo_db) / (hi_db - lo_db);
		t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
	}
	return (uint8_t)lround(255.0 * t);
}

int spec_write_png(FILE *fp, const char *name, const struct spec_img *im,
    double lo_db, double hi_db)
{
	struct frs_raster r;
	size_t side;
	int rc;

	if (im == NULL || im->v == NULL)
		return cli_fail("%s: no spectrum image", name);
	if (!isfinite(lo_db) || !isfinite(hi_db) || !(lo_db < hi_db))
		return cli_fail("%s: colour scale %g dB to %g dB is not an "
		    "increasing finite range", name, lo_db, hi_db);
	side = 2 * (size_t)im->half + 1;
	if (raster_alloc(&r, (uint32_t)side, (uint32_t)side, 1) < 0)
		return cli_fail_context(name);
	for (size_t i = 0; i < side * side; i++)
		r.px[i] = spec_grey(im->v[i], lo_db, hi_db);
	rc = raster_write_png(fp, name, &r);
	raster_free(&r);
	return rc;
}
