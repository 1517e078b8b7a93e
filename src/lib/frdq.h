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
 * thesis's Fig. 3.1 at 97.5 %); take the power spectrum of that pattern, normalised by the dot count so
 * that white noise is 1 everywhere.  The figure is the mean power at
 * frequencies below half the principal frequency sqrt(dots) over the mean
 * power of the plateau between 1.5 and 2.5 times it.  White noise gives
 * about 1; blue noise far less.  2-D, power-of-two sizes.
 */
#ifndef FRS_FRDQ_H
#define FRS_FRDQ_H

#include <stdint.h>

#include "frdio.h"

double frdq_spread(const struct frs_matrix *m, uint32_t c);
/* -1 with frs_fail when the matrix is not 2-D with power-of-two sides. */
int frdq_lowpass(const struct frs_matrix *m, double from, double to,
    double *ratio);
/* The same, and the peak: the highest radially averaged power between 0.5
 * and 3 times the principal frequency over the plateau mean.  Blue noise
 * has a low, broad peak (about 1.5 to 2); a lattice has sharp rings. */
int frdq_spectrum(const struct frs_matrix *m, double from, double to,
    double *ratio, double *peak);

#endif
