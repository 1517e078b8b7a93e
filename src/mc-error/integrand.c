#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>

#include "mc-error/integrand.h"
#include "cli/cli.h"

#define GAUSS_SIGMA 0.15
#define DISC_R 0.35

static double f_gauss(const struct frs_imap *env, double x, double y)
{
	double dx = x - 0.5, dy = y - 0.5;

	(void)env;
	return exp(-(dx * dx + dy * dy) / (2 * GAUSS_SIGMA * GAUSS_SIGMA));
}

static double f_disc(const struct frs_imap *env, double x, double y)
{
	double dx = x - 0.5, dy = y - 0.5;

	(void)env;
	return dx * dx + dy * dy < DISC_R * DISC_R ? 1.0 : 0.0;
}

/* The half-plane below the line from (0, 0.2) to (1, 0.7). */
static double f_step(const struct frs_imap *env, double x, double y)
{
	(void)env;
	return y < 0.2 + 0.5 * x ? 1.0 : 0.0;
}

static double exact_gauss(const struct frs_imap *env)
{
	/* int_0^1 exp(-(x-1/2)^2 / (2 s^2)) dx, squared */
	double s = GAUSS_SIGMA;
	double one = s * sqrt(2 * NUM_PI) * erf(0.5 / (s * sqrt(2.0)));

	(void)env;
	return one * one;
}

static double exact_disc(const struct frs_imap *env)
{
	(void)env;
	return NUM_PI * DISC_R * DISC_R;
}

static double exact_step(const struct frs_imap *env)
{
	(void)env;
	return 0.2 + 0.5 / 2;
}

/*
 * The irradiance of an upward-facing diffuse surface: (u, v) is the
 * direction phi = 2 pi u, theta = pi v, and 2 pi^2 sin(theta) the
 * Jacobian from the unit square to the sphere.  L is piecewise constant,
 * the pixel containing (u, v).
 */
static double f_env(const struct frs_imap *env, double u, double v)
{
	double c = cos(NUM_PI * v);
	size_t x = (size_t)(u * env->w), y = (size_t)(v * env->h);

	if (!(c > 0))
		return 0.0;
	if (x >= env->w)
		x = env->w - 1;
	if (y >= env->h)
		y = env->h - 1;
	return env->v[y * env->w + x] * c * sin(NUM_PI * v) * 2 * NUM_PI * NUM_PI;
}

/*
 * The exact integral of f_env over row y's band [a, b] of v, b clipped to
 * 1/2, per unit of L averaged over the row: 2 pi^2 int_a^b cos sin dv =
 * pi (sin^2(pi b) - sin^2(pi a)) = pi sin(pi (b - a)) sin(pi (a + b)),
 * the last form free of cancellation.
 */
static double env_row_weight(uint32_t y, uint32_t h)
{
	double a = (double)y / h, b = (double)(y + 1) / h;

	if (a >= 0.5)
		return 0.0;
	if (b > 0.5)
		b = 0.5;
	return NUM_PI * sin(NUM_PI * (b - a)) * sin(NUM_PI * (a + b));
}

/* The sum over pixels of L times its row's weight, in long double. */
static double exact_env(const struct frs_imap *env)
{
	long double total = 0;

	for (uint32_t y = 0; y < env->h; y++) {
		long double row = 0;
		double wgt = env_row_weight(y, env->h);
		if (wgt == 0)
			break;
		for (uint32_t x = 0; x < env->w; x++)
			row += env->v[(size_t)y * env->w + x];
		total += row / env->w * wgt;
	}
	return (double)total;
}

const struct integrand integrands[INTEGRANDS] = {
	{ "gauss", f_gauss, exact_gauss },
	{ "disc", f_disc, exact_disc },
	{ "step", f_step, exact_step },
	{ "env", f_env, exact_env },
};

double integrand_estimate(const struct integrand *g,
    const struct frs_imap *env, const double *xy, const double *w, size_t n)
{
	double sum = 0;

	for (size_t i = 0; i < n; i++) {
		double v = g->f(env, xy[2 * i], xy[2 * i + 1]);
		sum += w ? v / w[i] : v;
	}
	return sum / (double)n;
}

void map_pdf_init(struct map_pdf *p, const struct frs_imap *map)
{
	struct frs_imap_stats st;

	frs_imap_stats(map, &st);
	p->map = map;
	p->mean = st.mean;
}

double map_pdf_at(const struct map_pdf *p, double x, double y,
    size_t pixel[2])
{
	uint64_t i = frs_imap_pixel_of(p->map, x, y);

	pixel[0] = (size_t)(i % p->map->w);
	pixel[1] = (size_t)(i / p->map->w);
	return p->map->v[i] / p->mean;
}
