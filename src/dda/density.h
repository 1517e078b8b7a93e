/*
 * Spatial statistics of point sets for dda(1): the density rho (thesis
 * Eq. 6.21-6.22, Lagae and Dutre 2008; Wei and Wang 2011 for non-uniform
 * sets) and the radial distribution function (the normalisation of PSA,
 * Heck et al. 2013).
 *
 * Points are 2 * n doubles (x0, y0, x1, y1, ...) in [0, 1)^2; a point
 * outside, NaN or infinite, is an error naming it.
 *
 * Distances.  For points i, j let dx = x_i - x_j, dy = y_i - y_j.  Plain:
 * as they are.  Torus (--torus, for periodic sets): each difference taken
 * mod 1 to [-1/2, 1/2), computed as a = |dx|, a > 1/2 ? 1 - a : a (exact
 * for a > 1/2).  The squared distance is d2 = dx*dx + dy*dy, each product
 * rounded on its own (no fused multiply-add), and with per-point scales f
 * (Wei-Wang, below) the pair's key is
 *     k_ij = d2 * (f_i * f_j),        d_ij = sqrt(k_ij),
 * i.e. the transformed distance |x_i - x_j| sqrt(f_i f_j); without scales
 * k_ij = d2.  k_ij = k_ji bit for bit, and the functions below return what
 * a brute-force loop over the pairs computing these expressions returns.
 *
 * The searches use a uniform grid of G x G cells, G = floor(sqrt(n / 2))
 * (about 2 points a cell, at least 1), the points counting-sorted by cell.
 * A point's cell is floor(x G) as computed in double, so a point may lie up
 * to 2^-53 outside its cell; every bound below allows 2^-49.  Cells at
 * Chebyshev ring r >= 1 around a point's cell (r = max(|ox|, |oy|) of the
 * cell offset, wrapped for the torus, each cell once) hold only points at
 * plain or toroidal distance >= L_r = (r - 1)/G - 2^-49 in one coordinate.
 *
 * Scales and the bound.  Since k_ij = d2 f_i f_j >= d2 min(f_i, f_j)^2,
 * every pair is examined from its endpoint of smaller scale (on equal
 * scales from the one first in cell order; this also counts every pair
 * exactly once for the RDF), and that endpoint's search may stop at ring r
 * once L_r^2 f_i^2 (1 - 2^-45) exceeds the key sought: the pair's own key
 * is at least that.  The bound thus uses the point's own scale, the smaller
 * of the pair; a single global bound would need the smallest scale of all
 * (the largest local spacing r_u / f), which makes points in dense regions
 * search far too many cells.  Expected work O(n) for sets whose local
 * density varies moderately; a set whose density varies by a factor q
 * puts ~2q points in the densest cells and costs O(n q).
 *
 * Parallel loops (par != 0) cut the sorted points into fixed chunks;
 * minima and integer pair counts do not depend on the order of the
 * points or the number of threads.
 */
#ifndef FRS_DENSITY_H
#define FRS_DENSITY_H

#include <stddef.h>

struct frs_imap;

/* r_u(n) = sqrt(2 / (sqrt(3) n)): the spacing of n points in a hexagonal
 * packing of the unit square (the largest possible minimum distance, up to
 * the boundary). */
double dens_spacing(double n);

/*
 * Per-point scale of the Wei-Wang transform: f_i = sqrt(I(x_i) / mean I),
 * I the importance map (pixel (i, j) covers [i/W, (i+1)/W) x [j/H, (j+1)/H),
 * row 0 at the top; a point's importance is its pixel's value, pixel
 * index floor(x W) clamped to W - 1; the mean is over all W H pixels,
 * compensated sum); map NULL: all 1.  The local spacing is r(x) = r_u / f.
 * -1 with cli_fail for a point on a pixel of zero (or negative, non-finite)
 * importance, naming the point index and the pixel, for a point outside
 * [0, 1)^2, or an all-zero or non-finite map.
 */
int dens_scales(const double *xy, size_t n, const struct frs_imap *map,
    double *f);

/*
 * *dmin = min over pairs i != j of d_ij (see above: plain or torus,
 * transformed by f unless f is NULL), exactly the brute-force minimum.
 * Ring search on the cell grid, O(n) expected; 0 for duplicate points.
 * n >= 2; f, when given, positive and finite.
 */
int dens_min_distance(const double *xy, size_t n, const double *f, int torus,
    int par, double *dmin);

/*
 * The scale of a pair's key.  DENS_GEOMETRIC: f_i f_j, the key above (the
 * distance in the geometric mean of the two points' local spacings; what
 * dens_min_distance uses).  DENS_MAX: max(f_i, f_j)^2, i.e.
 * k_ij = d2 * (m * m), m = max(f_i, f_j): the distance in the local
 * spacing of the denser point (the larger scale), never smaller than the
 * geometric one.  Eq. 6.21 of the thesis leaves the choice open.  The
 * search bound above holds for both (each key >= d2 min(f_i, f_j)^2).
 */
enum dens_rule { DENS_GEOMETRIC, DENS_MAX };

/* dens_min_distance under RULE: exactly the brute-force minimum of the
 * keys of RULE; -1 with cli_fail for an unknown RULE. */
int dens_min_distance_rule(const double *xy, size_t n, const double *f,
    enum dens_rule rule, int torus, int par, double *dmin);

/* rho = dmin / r_u(n) (Eq. 6.21); the mean over m sets is Eq. 6.22. */
double dens_rho(double dmin, size_t n);

/*
 * 3-D sets: points are 3 * n doubles (x, y, z, ...) in [0, 1)^3.  The
 * key of a pair is d2 = (dx*dx + dy*dy) + dz*dz, each product rounded on
 * its own, plain or on the torus as above (no scales: 3-D sets are
 * uniform).  The search uses a grid of G^3 cells, G = floor(cbrt(n / 2))
 * (at least 1), and Chebyshev rings of cells with the bound L_r of 2-D:
 * O(n) expected, exactly the brute-force minimum, the same for any
 * thread count.
 *
 * r_u3(n) = (sqrt(2) / n)^(1/3): the nearest-neighbour distance of n
 * points in a face-centred cubic packing of the unit cube (4 points per
 * cubic cell of side a = (4/n)^(1/3), neighbours a / sqrt(2) apart), the
 * densest packing of spheres; rho = dmin / r_u3(n).  A regular m^3 grid
 * has rho = 2^(-1/6) = 0.891.  For uniform random points the closest
 * pair is Weibull distributed, P(dmin > d) = exp(-(2 pi / 3) n^2 d^3)
 * (pairs as a Poisson process, no edge effects), so
 *   E[rho] = Gamma(4/3) (3 / (2 pi))^(1/3) 2^(-1/6) n^(-1/3)
 *          = 0.622 n^(-1/3),
 * 0.0622 at n = 1000, with a standard deviation of 36 % of it.  As in 2-D
 * (where it falls as n^(-1/2)), rho of random sets depends on n: compare
 * sets of one size.
 */
double dens_spacing3(double n);
double dens_rho3(double dmin, size_t n);
int dens_min_distance3(const double *xyz, size_t n, int torus, int par,
    double *dmin);

/*
 * P(|x - y| < r) for two independent uniform points of the unit square
 * (torus = 0) or the unit torus (torus != 0); 0 for r <= 0, 1 beyond the
 * largest distance.
 *   torus, r <= 1/2:          pi r^2
 *   torus, 1/2 < r <= 1/sqrt2: pi r^2 - 4 (r^2 acos(1/(2r)) - sqrt(r^2 - 1/4)/2)
 *                             (the disc less the four segments outside the
 *                             square [-1/2, 1/2]^2)
 *   plain, r <= 1:            pi r^2 - 8/3 r^3 + 1/2 r^4
 *   plain, 1 < r <= sqrt2:    with s = sqrt(r^2 - 1),
 *       2s - s^2 + 2 r^2 (2 asin(1/r) - pi/2) - 4/3 (1 - s^3)
 *       - r^2 + 1/6 + 2 r^2 (s - s^2/2) - 2/3 s^3 + 1/2 s^4
 * The plain case integrates the density 4 (1 - u)(1 - v) of the absolute
 * coordinate differences (u, v) over the quarter disc u^2 + v^2 < r^2 in
 * [0, 1]^2; its derivative for r <= 1 is the distance density
 * 2 pi r - 8 r^2 + 2 r^3.
 */
double dens_pair_cdf(double r, int torus);

/* Largest rmax (unit-square distance) dens_rdf_add accepts: sqrt(2) plain,
 * 1/sqrt(2) on the torus. */
double dens_rdf_limit(int torus);

/*
 * Radial distribution function of one set: with R = rmax_ru r_u(n) and
 * w = R / nbins, the pairs with k_ij < R * R (every unordered pair once)
 * are counted in bin b = floor(d_ij / w) (clamped to nbins - 1), and
 *     acc[b] += count_b / (n (n - 1) / 2 * (P(b w + w) - P(b w)))
 * with P = dens_pair_cdf(., torus), the probability that a pair of uniform
 * random points falls in the annulus: a uniform random (Poisson) set gives
 * 1 in expectation in every bin.  For the torus P(b) - P(a) =
 * pi (b^2 - a^2); for plain distance the exact edge correction of the
 * square is built in (P integrated over the bin in closed form, computed
 * as (b - a) times a polynomial in a, b below r = 1 to avoid
 * cancellation).  With scales the distances are the transformed ones and
 * the normalisation is the uniform one (for an adaptive Poisson set the
 * transformed differentials are locally uniform, Wei and Wang 2011).
 * The caller sums sets into acc and divides by their number.
 * n >= 2, nbins in [1, 2^24], 0 < R <= dens_rdf_limit(torus).
 */
int dens_rdf_add(const double *xy, size_t n, const double *f, int torus,
    double rmax_ru, size_t nbins, int par, double *acc);

#endif
