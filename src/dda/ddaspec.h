/*
 * Differential domain analysis (DDA) of 2-D point sets, uniform and
 * adaptive (Wei and Wang, "Differential domain analysis for non-uniform
 * sampling", ACM TOG 30(4), 2011; thesis Sec. 2.2 and 6.3, Fig. 2.3,
 * 4.4-4.6, 6.10-6.12: Gaussian kernel, neighbourhood eps = 12).
 *
 * The DDA is a histogram of the pairwise differentials x_j - x_i, each
 * measured in the local sample spacing, so that sets adapted to different
 * importance maps can be compared with one picture.
 *
 * Units.  n points in [0,1)^2; the mean spacing of n points is
 *   r_u = sqrt(2 / (sqrt(3) n))
 * (the spacing of a hexagonal packing of n points in the unit square).  An
 * importance map I gives per-point scales f_i = sqrt(I(x_i) / mean I): the
 * local spacing at x_i is r_u / f_i.  f = NULL means f_i = 1 for all points
 * (uniform sets; bit for bit the same as passing all ones).
 *
 * Differentials.  For every ordered pair i != j
 *   d_ij = (x_j - x_i) sqrt(f_i f_j) / r_u                           (1)
 * in units of r_u (the geometric mean of the two local scales: d_ji = -d_ij
 * exactly).  A pair is kept when |d_ij| < eps.
 *
 * Image.  side = 2 half + 1 pixels a side, pixel size h = eps / half (r_u
 * units); pixel (c, r), stored at acc[r * side + c], is centred at
 *   d(c, r) = ((c - half) h, (r - half) h)                            (2)
 * so row 0 (top) is the most negative y and y grows downward as in point
 * images; the centre pixel (half, half) is d = 0.
 *
 * Splat.  A kept pair at pixel coordinates u = d_ij / h + half is spread
 * with a separable Gaussian of sigma_px pixels: per axis the taps k with
 * |k - u| <= 3 sigma_px (and always the nearest pixel round(u)), weights
 *   g_k = exp(-(k - u)^2 / (2 sigma_px^2)) / sum_k g_k                 (3)
 * so that the weights of one pair sum to 1; the 2-D weight is g_k g_l.
 * sigma_px = 0 puts the whole pair into the nearest pixel.  Taps outside
 * the image are dropped (only pairs within 3 sigma_px pixels of the image
 * border lose a little mass; with sigma_px < 1/3 nothing is lost, since
 * |d_ij| < eps keeps the nearest pixel inside).  The weights are rounded
 * to multiples of 2^-s per axis, the rounding residue going to the
 * nearest tap, so each pair adds exactly 1; s = 20, or for more than 2048
 * points s = min(20, floor((62 - bits(P)) / 2)) with P the number of kept
 * ordered pairs (counted first), so that no pixel can exceed 2^62.  The
 * masses are summed as integers, which makes the result independent of
 * the thread count and of the point order, bit for bit.  The kernel is
 * computed once per unordered pair and mirrored for (j, i); it is built
 * sign-symmetrically (-u gives the mirrored weights exactly), so the image
 * is exactly point-symmetric.
 *
 * Normalisation: a Poisson (binomial) process with the same intensity has
 * expectation 1 in every pixel.  Given x_i, the other n - 1 points have
 * density f^2 (f^2 averages 1 over the domain), so the expected number of
 * them whose differential (1) falls into the pixel, a square of side
 * h r_u / f_i at x_i, is (n - 1) f_i^2 (h r_u / f_i)^2 = (n - 1) (h r_u)^2,
 * when that square lies in the domain.  Summed over i:
 *   D(c, r) = M(c, r) / ((n - 1) (h r_u)^2 E(c, r))                    (4)
 * with M the splatted mass and the edge correction
 *   E(d) = ( #{i : x_i + d r_u / f_i in [0,1)^2}
 *          + #{i : x_i - d r_u / f_i in [0,1)^2} ) / 2                 (5)
 * the number of points whose neighbourhood at offset d lies inside the
 * domain (for a uniform set about n (1 - |d_x| r_u)(1 - |d_y| r_u)),
 * averaged over d and -d (both are unbiased; the mean keeps D exactly
 * point-symmetric, like M).  E is found for all pixels at once: the
 * offsets d for which x_i + d r_u / f_i lies in [0,1)^2 form a box
 * [-x_i f_i / r_u, (1 - x_i) f_i / r_u) x [...), added to a 2-D difference
 * array, O(n + pixels).  Pixels with E = 0 are left unchanged.
 *
 * Pair search.  Points are binned into a G x G cell grid (about 4 points
 * a cell).  |d_ij| < eps means |x_j - x_i| < eps r_u / sqrt(f_i f_j), so
 * point i looks no farther than eps r_u / sqrt(f_i f_min) (f_min the
 * smallest scale of the set: the largest scale ratio bounds the search),
 * and skips every cell whose box distance b from x_i has
 * b^2 f_i f_min(cell) >= (eps r_u)^2, f_min(cell) the smallest scale in
 * the cell.  Only cells that can hold a kept pair are visited; each
 * candidate is then tested exactly with (1).
 *
 * Cost: O(n + pairs within eps (2 ceil(3 sigma_px) + 1)^2 + half^2) time
 * (10 sets of 1024 points, eps 12, half 128, sigma 1: about 0.25 s on one
 * core), (threads + 2) (2 half + 1)^2 64-bit words of memory.
 */
#ifndef FRS_DDASPEC_H
#define FRS_DDASPEC_H

#include <stddef.h>
#include <stdint.h>

/* The thesis' parameters (Wei and Wang's tool). */
#define DDA_EPS 12.0
#define DDA_HALF 128u
#define DDA_SIGMA_PX 1.0
#define DDA_MAX_HALF 4096u

/* Add one set's DDA (4) to acc, an image of side 2*half+1 (row-major,
 * (2*half+1)^2 doubles, pixel (c, r) centred at the differential
 * ((c - half) * eps / half, (r - half) * eps / half) in units of the mean
 * spacing r_u = sqrt(2/(sqrt(3) n)); row 0 at the top is the most
 * negative y, y growing downward as in point images).  xy: n points, x
 * and y interleaved, in [0,1)^2; f: n positive finite scales
 * sqrt(I(x_i)/mean I), or NULL for a uniform set.  eps > 0 (r_u units),
 * 1 <= half <= DDA_MAX_HALF, sigma_px >= 0 (pixels).  par: run on the
 * threads of frs_set_threads (the result is the same either way, bit for
 * bit).  To average m sets, add each and divide acc by m.  Returns 0, or
 * -1 with cli_fail (acc unchanged) for bad arguments or no memory. */
int dda_add(const double *xy, size_t n, const double *f, double eps,
    uint32_t half, double sigma_px, int par, double *acc);

#endif
