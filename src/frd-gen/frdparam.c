/* The generators' parameters and the laws that follow (frdparam.h). */
#define _POSIX_C_SOURCE 200809L
#include "frd-gen/frdparam.h"
#include "frs.h"	/* frs_rand01, frs_rand64x */
#include "cli/cli.h"
#include "../../cl/defs.cl"	/* FRS_STREAM_FRD_* */

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define DEFAULT_TOL 1e-2
#define DEFAULT_REACH 3.0
#define DEFAULT_CAP (1.0 / 3.0)

/* ---- parameters --------------------------------------------------- */

void frdgen_defaults(struct frdgen_params *pr)
{
	memset(pr, 0, sizeof *pr);
	pr->dims = 2;
	pr->p = 0.5;
	pr->force = FRDGEN_FORCE_POWER;
	pr->s = 1.0;
	pr->q = 4.0;
	pr->tol = DEFAULT_TOL;
	pr->reach = DEFAULT_REACH;
	pr->cap = DEFAULT_CAP;
	pr->taper = 1;
	pr->field = FRDGEN_FIELD_DOUBLE;
	pr->seed = 1;
	pr->checkpoint_every = 60.0;
}

int frdgen_check_size(unsigned dims, uint32_t w, uint32_t h, uint32_t d)
{
	uint64_t n = (uint64_t)w * h * d;

	if (dims != 2 && dims != 3)
		return cli_fail("%u dimensions: a matrix has 2 or 3", dims);
	if (w < 2 || h < 2 || d < 1 || (dims == 3 && d < 2) ||
	    (dims == 2 && d != 1))
		return cli_fail("a matrix needs at least 2 cells per side");
	if (n > UINT32_MAX)
		return cli_fail("%llu cells are more than 2^32 - 1 values",
		    (unsigned long long)n);
	return 0;
}

int frdgen_check(const struct frdgen_params *pr)
{
	if (frdgen_check_size(pr->dims, pr->w, pr->h, pr->d) < 0)
		return -1;
	if (!(pr->p > 0.0 && pr->p <= 1.0))
		return cli_fail("the share p = %g is outside (0, 1]", pr->p);
	if (pr->force != FRDGEN_FORCE_EXP && pr->force != FRDGEN_FORCE_POWER)
		return cli_fail("unknown force kind %d", (int)pr->force);
	if (!(pr->s > 0.0 && isfinite(pr->s)) || !(pr->q > 0.0 &&
	    isfinite(pr->q)))
		return cli_fail("force parameters s and q must be positive");
	if (!(pr->tol >= 0.0 && pr->tol < 1.0))
		return cli_fail("the force tolerance %g is outside [0, 1)", pr->tol);
	if (!(pr->reach >= 0.0 && isfinite(pr->reach)))
		return cli_fail("the reach %g is negative", pr->reach);
	if (!(pr->cap >= 0.0 && isfinite(pr->cap)))
		return cli_fail("the reach cap %g is negative", pr->cap);
	if (pr->field != FRDGEN_FIELD_DOUBLE && pr->field != FRDGEN_FIELD_INT32)
		return cli_fail("unknown field kind %d", (int)pr->field);
	return 0;
}

/* The shortest side: the authors' S. */
static uint32_t shortest_side(const struct frdgen_params *pr)
{
	uint32_t m = pr->w < pr->h ? pr->w : pr->h;
	return pr->dims == 3 && pr->d < m ? pr->d : m;
}

double frdgen_int_scale(const struct frdgen_params *pr)
{
	double half = (double)(shortest_side(pr) / 2);
	return fmin((double)(INT_MAX / 20), 1.0 / exp(-sqrt(2.0 * half)));
}

double frdgen_force(const struct frdgen_params *pr, double r)
{
	if (pr->field == FRDGEN_FIELD_INT32)
		return (double)(int32_t)(frdgen_int_scale(pr) *
		    exp(-sqrt(2.0 * r)));
	if (pr->force == FRDGEN_FORCE_POWER)
		return pow(1.0 + r / pr->s, -pr->q);
	return exp(-pow(r / pr->s, pr->q));
}

double frdgen_radius(const struct frdgen_params *pr)
{
	if (pr->field == FRDGEN_FIELD_INT32) {
		/* scale exp(-sqrt(2 r)) >= 1 up to r = ln(scale)^2 / 2; the
		 * margin only adds cells that get 0. */
		double l = log(frdgen_int_scale(pr));
		return l * l / 2.0 * (1.0 + 1e-9) + 1e-9;
	}
	if (pr->tol <= 0.0)
		return INFINITY;
	if (pr->force == FRDGEN_FORCE_POWER)
		return pr->s * (pow(pr->tol, -1.0 / pr->q) - 1.0);
	return pr->s * pow(log(1.0 / pr->tol), 1.0 / pr->q);
}

uint64_t frdgen_memory(const struct frdgen_params *pr)
{
	uint64_t n = (uint64_t)pr->w * pr->h * pr->d;
	uint64_t t = ((uint64_t)pr->w / 2 + 1) * (pr->h / 2 + 1) *
	    (pr->d / 2 + 1);
	/* field (with the padding of partial tiles), values, table, tiles
	 * and pyramid */
	uint64_t pad = ((uint64_t)pr->w + 8) * (pr->h + 8) * (pr->d + 4);
	return pad * 8 + n * 4 + t * 8 + n / 4 + (1 << 20);
}

void frdgen_describe(const struct frdgen_params *pr, char *buf, size_t n)
{
	if (pr->field == FRDGEN_FIELD_INT32) {
		snprintf(buf, n, "generator=frd-gen\nk=%u\nsize=%ux%ux%u\n"
		    "field=int32\np=%.17g\nscale=%.17g\nseed=%llu\n", pr->dims,
		    pr->w, pr->h, pr->d, pr->p, frdgen_int_scale(pr),
		    (unsigned long long)pr->seed);
		return;
	}
	snprintf(buf, n, "generator=frd-gen\nk=%u\nsize=%ux%ux%u\n"
	    "field=double\nforce=%s\np=%.17g\ns=%.17g\nq=%.17g\n"
	    "tol=%.17g\nreach=%.17g\ncap=%.17g\ncutoff=%s\nseed=%llu\n",
	    pr->dims, pr->w, pr->h, pr->d,
	    pr->force == FRDGEN_FORCE_POWER ? "power" : "exp", pr->p, pr->s,
	    pr->q, pr->tol, pr->reach, pr->cap, pr->taper ? "taper" : "hard",
	    (unsigned long long)pr->seed);
}

uint64_t frdgen_rank(const struct frdgen_params *pr, uint64_t step,
    uint64_t free)
{
	double u, lq, tail, k;

	if (pr->p >= 1.0 || free <= 1)
		return 1;
	/* Inverse CDF of Geometric(p) conditioned on K <= free: the minimum
	 * of a Bernoulli(p) subset, given that the subset is not empty. */
	u = frs_rand01(pr->seed, FRS_STREAM_FRD_COIN, step);
	lq = log1p(-pr->p);
	tail = exp((double)free * lq);
	k = 1.0 + floor(log1p(-u * (1.0 - tail)) / lq);
	if (!(k >= 1.0))
		return 1;
	return k > (double)free ? free : (uint64_t)k;
}

uint64_t frdgen_tiekey(const struct frdgen_params *pr, uint64_t step,
    uint32_t c)
{
	return frs_rand64x(pr->seed, FRS_STREAM_FRD_TIE, step, c);
}

uint64_t frdgen_zerorank(const struct frdgen_params *pr, uint64_t step,
    uint64_t z)
{
	uint64_t r = (uint64_t)(frs_rand01(pr->seed, FRS_STREAM_FRD_DRAW, step) *
	    (double)z);
	return r < z ? r : z - 1;
}

void frdgen_tile_shape(unsigned dims, uint32_t t[3])
{
	/* Tile shapes measured fastest (16 x 8 beat 8x8, 32x4, 64x2 at
	 * 512^2 and 1024^2): rows long enough for vector adds, few enough
	 * rows for little loop overhead.  At most 256 cells (arg is a byte). */
	t[0] = dims == 2 ? 16 : 8;
	t[1] = dims == 2 ? 8 : 4;
	t[2] = dims == 2 ? 1 : 4;
}

uint64_t frdgen_cellorder(const struct frdgen_params *pr, uint32_t c)
{
	uint32_t t[3], x = c % pr->w, y = c / pr->w % pr->h, z = c / pr->w / pr->h;
	uint64_t ntx, nty, tile, local;

	frdgen_tile_shape(pr->dims, t);
	ntx = (pr->w + t[0] - 1) / t[0];
	nty = (pr->h + t[1] - 1) / t[1];
	tile = ((uint64_t)(z / t[2]) * nty + y / t[1]) * ntx + x / t[0];
	local = ((uint64_t)(z % t[2]) * t[1] + y % t[1]) * t[0] + x % t[0];
	return tile << 16 | local;
}

/* ---- the radius schedule ------------------------------------------ */

/* Expected spacing of n values spread evenly: hexagonal in 2-D,
 * face-centred cubic in 3-D. */
static double spacing(const struct frdgen_params *pr, uint64_t n)
{
	double vol = (double)pr->w * pr->h * pr->d;

	if (pr->dims == 2)
		return sqrt(2.0 * vol / (sqrt(3.0) * (double)n));
	return cbrt(sqrt(2.0) * vol / (double)n);
}

double frdgen_radius_after(const struct frdgen_params *pr, double rtol,
    uint64_t inserted)
{
	double r = rtol;

	if (pr->field == FRDGEN_FIELD_INT32)
		return r;
	if (pr->reach > 0.0) {
		double adapt = pr->reach * spacing(pr, inserted);
		r = adapt > r ? adapt : r;
	}
	if (pr->cap > 0.0) {
		double cap = pr->cap * (double)shortest_side(pr);
		r = r > cap ? fmax(cap, rtol) : r;
	}
	return r;
}
