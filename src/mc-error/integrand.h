/*
 * Test integrands over [0,1)^2 with known integrals, for the Monte Carlo
 * error of point sets (mc-error(1)): a Gaussian bump, a disc, a
 * half-plane step, and the irradiance of an upward-facing diffuse
 * surface under an equirectangular environment map.
 */
#ifndef FRS_INTEGRAND_H
#define FRS_INTEGRAND_H

#include <stddef.h>

#include "frs.h"

struct integrand {
	const char *name;
	/* The value at (x, y); env, the environment map (row 0 at the
	 * zenith), is read by env alone. */
	double (*f)(const struct frs_imap *env, double x, double y);
	/* The integral over the unit square. */
	double (*exact)(const struct frs_imap *env);
};

/* gauss, disc, step, env, in that order. */
extern const struct integrand integrands[];
#define INTEGRANDS 4
#define INTEGRAND_ENV 3		/* the one that needs a map */

/* The estimate of the integral from n points xy (pairs): the mean of f,
 * or where w is not NULL, of f / w (w the points' densities). */
double integrand_estimate(const struct integrand *g,
    const struct frs_imap *env, const double *xy, const double *w, size_t n);

/* A map as a density (mc-error --pdf-map): a pixel's value over the
 * map's mean, made once. */
struct map_pdf {
	const struct frs_imap *map;
	double mean;
};
void map_pdf_init(struct map_pdf *p, const struct frs_imap *map);
/* The density at point (x, y), its pixel in pixel[2]. */
double map_pdf_at(const struct map_pdf *p, double x, double y,
    size_t pixel[2]);

#endif
