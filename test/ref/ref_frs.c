/*
 * ref_frs: Forced Random Sampling by brute force, written from the
 * thesis's definitions and not from src/lib/sample/frs.c, as the oracle
 * that every implementation (Naive, Stack, Level 1 and 2, Sorted, on the
 * CPU and the device) is checked against by test/t_ref_frs.sh.
 *
 *   ref_frs setup [-s WxH] [--equirect] MATRIX MAP N SIGMA
 *       Listing 5.1 with the power-of-two phi (Eq. 5.3) and one n_s for
 *       both axes (frs-sample(1)): with the map's mean mu and maximum m
 *       (negative pixels count as 0), a = large / small side,
 *       w_min = ceil(sigma sqrt(N m / (mu a))), n_s the smallest power of
 *       two with n_s small >= w_min, the window S_W = n_s S_I and
 *       tau = N S_M,x S_M,y / (S_W,x S_W,y mu):
 *           ns NS window W H tau TAU
 *   ref_frs pass [-s WxH] [--equirect] [--thesis] [-S SEED] MATRIX MAP W H
 *       WX WY TAU
 *       every element (x, y) of the W x H window over the plainly tiled
 *       matrix at offset (WX, WY), value v = M[(WY + y) mod S_M,y]
 *       [(WX + x) mod S_M,x], in the pixel (x / n_s, y / n_s) with
 *       T = TAU I: under the unbiased rule v passes when v < floor(T),
 *       or v = floor(T) with probability frac(T), by the coin
 *       frs_rand01(SEED, stream 5, y W + x) < frac(T) (frs-sample(1));
 *       under --thesis when v < T (Eq. 4.14).  T is capped at 2^33 (a
 *       32-bit value always passes there).  One line "x y" per element
 *       that passes, rows from the top, x ascending.
 *
 * The map is loaded as frs-sample loads it (a file at its own size or
 * -s WxH, a spec at -s WxH, default 128x128; --equirect weights rows by
 * sin theta); maps whose maximum lies
 * outside [2^-900, 2^900], which frs-sample rescales, are refused.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/err.h"
#include "base/rng.h"
#include "formats/frdio.h"
#include "maps/imap.h"
#include "maps/mapload.h"

/* The coin's stream (cl/defs.cl's FRS_STREAM_COIN), a fixed part of
 * frs-sample's output contract. */
#define STREAM_COIN 5

static void die(const char *what, const char *msg)
{
	fprintf(stderr, "ref_frs: %s: %s\n", what, msg);
	exit(1);
}

static uint64_t num(const char *s)
{
	char *end;
	unsigned long long v = strtoull(s, &end, 10);

	if (*s == '\0' || *end != '\0')
		die(s, "not a number");
	return (uint64_t)v;
}

static double real(const char *s)
{
	char *end;
	double v = strtod(s, &end);

	if (*s == '\0' || *end != '\0' || !isfinite(v))
		die(s, "not a number");
	return v;
}

static void load(const char *mpath, const char *map, uint32_t w, uint32_t h,
    int flags, struct frs_matrix *m, struct frs_imap *im)
{
	if (frd_read(mpath, m) < 0)
		die(mpath, frs_errmsg());
	if (m->d != 1)
		die(mpath, "a 2-D matrix only");
	if (imap_load(map, w, h, flags, im) < 0)
		die(map, frs_errmsg());
}

static double pixel(const struct frs_imap *im, uint64_t i)
{
	return im->v[i] > 0.0 ? im->v[i] : 0.0;
}

static void setup(const struct frs_matrix *m, const struct frs_imap *im,
    uint64_t n, double sigma)
{
	double sum = 0.0, mx = 0.0, mu, a, wmin, tau;
	uint32_t small = im->w < im->h ? im->w : im->h;
	uint32_t large = im->w < im->h ? im->h : im->w;
	uint64_t ns = 1, sw, sh;

	for (uint64_t i = 0; i < (uint64_t)im->w * im->h; i++) {
		sum += pixel(im, i);
		mx = pixel(im, i) > mx ? pixel(im, i) : mx;
	}
	if (!(mx >= 0x1p-900 && mx <= 0x1p900))
		die("map", "maximum outside [2^-900, 2^900]");
	mu = sum / ((double)im->w * im->h);
	a = (double)large / small;
	wmin = ceil(sigma * sqrt((double)n * mx / (mu * a)));
	while ((double)(ns * small) < wmin)
		ns *= 2;
	sw = ns * im->w;
	sh = ns * im->h;
	tau = (double)n * m->w * m->h / ((double)sw * (double)sh * mu);
	printf("ns %llu window %llu %llu tau %.17g\n", (unsigned long long)ns,
	    (unsigned long long)sw, (unsigned long long)sh, tau);
}

/* Whether value v passes the threshold t of element id. */
static int passes(uint32_t v, double t, int thesis, uint64_t seed,
    uint64_t id)
{
	double f;

	if (t > 0x1p33)
		t = 0x1p33;
	if (thesis)
		return (double)v < t;
	f = floor(t);
	if ((double)v < f)
		return 1;
	return (double)v == f && t > f &&
	    frs_rand01(seed, STREAM_COIN, id) < t - f;
}

static void pass(const struct frs_matrix *m, const struct frs_imap *im,
    uint64_t sw, uint64_t sh, uint64_t wx, uint64_t wy, double tau,
    int thesis, uint64_t seed)
{
	uint64_t ns = sw / im->w;

	if (ns == 0 || ns * im->w != sw || ns * im->h != sh)
		die("window", "not n_s times the map in both axes");
	for (uint64_t y = 0; y < sh; y++)
		for (uint64_t x = 0; x < sw; x++) {
			uint32_t v = m->v[((wy + y) % m->h) * m->w +
			    (wx + x) % m->w];
			double t = tau * pixel(im, (y / ns) * im->w + x / ns);
			if (passes(v, t, thesis, seed, y * sw + x))
				printf("%llu %llu\n", (unsigned long long)x,
				    (unsigned long long)y);
		}
}

int main(int argc, char **argv)
{
	uint32_t w = 0, h = 0;	/* a file at its own size, a spec at 128x128 */
	uint64_t seed = 1;
	int thesis = 0, flags = 0, i = 2;
	struct frs_matrix m;
	struct frs_imap im;

	if (argc < 2)
		die("usage", "ref_frs setup|pass [options] MATRIX MAP ...");
	for (; i < argc && argv[i][0] == '-' && argv[i][1] != '\0'; i++) {
		if (strcmp(argv[i], "--thesis") == 0)
			thesis = 1;
		else if (strcmp(argv[i], "--equirect") == 0)
			flags |= FRS_MAP_EQUIRECT;
		else if (strcmp(argv[i], "-S") == 0 && i + 1 < argc)
			seed = num(argv[++i]);
		else if (strcmp(argv[i], "-s") == 0 && i + 1 < argc) {
			if (sscanf(argv[++i], "%ux%u", &w, &h) != 2)
				die(argv[i], "not WxH");
		} else
			die(argv[i], "unknown option");
	}
	if (strcmp(argv[1], "setup") == 0 && argc - i == 4) {
		load(argv[i], argv[i + 1], w, h, flags, &m, &im);
		setup(&m, &im, num(argv[i + 2]), real(argv[i + 3]));
	} else if (strcmp(argv[1], "pass") == 0 && argc - i == 7) {
		load(argv[i], argv[i + 1], w, h, flags, &m, &im);
		pass(&m, &im, num(argv[i + 2]), num(argv[i + 3]),
		    num(argv[i + 4]), num(argv[i + 5]), real(argv[i + 6]),
		    thesis, seed);
	} else
		die("usage", "ref_frs setup|pass [options] MATRIX MAP ...");
	frd_free(&m);
	imap_free(&im);
	return 0;
}
