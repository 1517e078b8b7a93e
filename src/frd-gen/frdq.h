/*
 * Quality figures of a threshold matrix (thesis Sec. 3.1-3.2).
 *
 * spread: the cells holding the first c values should be spread evenly.
 * rho_c = (smallest toroidal distance between two of them) / (the spacing
 * of c points in a hexagonal packing of the matrix area, sqrt(2A /
 * (sqrt(3) c)); face-centred cubic in 3-D).  Near 1 is perfect, a random
 * set of c points has rho ~ 1 / sqrt(c).
 *
 * lowpass: the cells whose values lie in [from * N, to * N) are dots (from
 * = 0: the first values, the dots of a dither of a (1 - to) grey; to = 1:
 * the last values, the black dots of a dither of a "from" grey as in the
 * thesis's Fig. 3.1 at 97.5 %); take the power spectrum of that pattern,
 * normalised by the dot count so that white noise is 1 everywhere.  The
 * figure is the mean power at frequencies below half the principal
 * frequency sqrt(dots) over the mean power of the plateau between 1.5 and
 * 2.5 times it.  White noise gives about 1; blue noise far less.  2-D,
 * power-of-two sizes.
 *
 * Both reward a lattice: its spread is near 1 and its low frequencies are
 * empty.  The figures of a level (frdq_level) catch it:
 * - pmax: the periodogram maximum |sum_x exp(-2 pi i k.x)|^2 / c over all
 *   integer k != 0 of the c dots.  A lattice puts c at its lattice
 *   frequencies; blue and white noise about ln(number of frequencies),
 *   10 to 20 (exponential values at the plateau, a little more on the
 *   peak of blue noise).
 * - strata: the share of the cells of a grid of c cells (sqrt c x sqrt c,
 *   the powers of two split over the axes) holding exactly one dot.  A
 *   lattice or a jittered grid: 1; white noise e^-1 = 0.37; blue noise
 *   0.6 to 0.8.
 * - peak, ring, aniso: the radial mean of that periodogram in annuli of
 *   fp / 16 (at least 1), fp = c^(1/k) the principal frequency: its
 *   highest value between 0.5 and 3 fp (peak), the highest at 1.5 times
 *   the peak's frequency or beyond (ring: the rings of a lattice or of a
 *   cut-off), and the largest anisotropy 10 log10(variance / mean^2) of an
 *   annulus between 0.5 and 3 fp (0 dB for one isotropic set, far more for
 *   the spikes of a lattice).
 * Frequencies are scaled so that a non-square matrix is isotropic.
 */
#ifndef FRS_FRDQ_H
#define FRS_FRDQ_H

#include <stdint.h>

#include "frs.h"	/* struct frs_matrix */

double frdq_spread(const struct frs_matrix *m, uint32_t c);
/* -1 with cli_fail when the matrix is not 2-D with power-of-two sides. */
int frdq_lowpass(const struct frs_matrix *m, double from, double to,
    double *ratio);
/* The same, and the peak: the highest radially averaged power between 0.5
 * and 3 times the principal frequency over the plateau mean.  Blue noise
 * has a low, broad peak (about 1.5 to 2); a lattice has sharp rings. */
int frdq_spectrum(const struct frs_matrix *m, double from, double to,
    double *ratio, double *peak);

/* The figures of the dots whose values lie in [lo, hi). */
struct frdq_level {
	uint64_t lo, hi, dots;
	double strata;
	int spectral;		/* the rest is set: power-of-two sides */
	double pmax, pmax_f;	/* _f: frequency over fp */
	double peak, peak_f;
	double ring, ring_f;
	double aniso;		/* dB */
};

/* The strata figure for any size; the spectral ones where every side is a
 * power of two (spectral = 0 otherwise).  -1 with cli_fail when out of
 * memory or with no dots. */
int frdq_level(const struct frs_matrix *m, uint64_t lo, uint64_t hi,
    struct frdq_level *q);
double frdq_strata(const struct frs_matrix *m, uint64_t lo, uint64_t hi);

#endif
