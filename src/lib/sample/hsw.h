/*
 * Hierarchical Sample Warping (Clarberg, Jarosz, Akenine-Moller, Jensen,
 * "Wavelet importance sampling", SIGGRAPH 2005; thesis Sec. 2.3).
 *
 * The importance map becomes a probability quadtree: a mipmap of sums,
 * leaves the pixels.  A map whose sides are not one power of two is
 * padded with zero importance, at its right and bottom, up to the next
 * power-of-two square; the padding never receives points and positions
 * are given over the real map's unit square.
 *
 * A point in [0,1)^2 is warped from the root down: at each node it goes
 * to the left or right half by comparing x with pL = (left two children)
 * / (node), x rescaled to [0,1) of that half; then to the top or bottom
 * child of that column the same way with y.  At a leaf (a pixel) the
 * remaining coordinates place it inside the pixel.
 */
#ifndef FRS_HSW_H
#define FRS_HSW_H
#include <stddef.h>
#include <stdint.h>
#include "maps/imap.h"

struct hsw_tree {
	uint32_t w, h;		/* the real map */
	uint32_t size;		/* padded side, a power of two */
	unsigned levels;	/* log2(size) */
	double *sum;		/* levels 0..levels, Morton order: the four
				 * children of node k of a level are 4k..4k+3
				 * of the next (top-left, top-right,
				 * bottom-left, bottom-right) */
	double total;		/* sum of the map (the root / the scale) */
};

/* Largest padded square (pixels) hsw_build accepts. */
#define HSW_MAX_PIXELS ((uint64_t)1 << 28)

/* Negative values count as zero; NaN and infinity are refused, naming
 * the pixel.  A map whose maximum lies outside [2^-900, 2^900] is scaled
 * by a power of two in the tree (sum); total stays the map's sum. */
int hsw_build(struct hsw_tree *t, const struct frs_imap *m);
void hsw_free(struct hsw_tree *t);

/* Warp one point in place; returns its pixel, j * w + i, of the real map.
 * The result is in [0,1)^2 and inside that pixel. */
uint64_t hsw_warp(const struct hsw_tree *t, double *x, double *y);

/* Warp n points (pairs x, y) from in to out (may be the same array), in
 * parallel with frs_parallel; the same bytes for any thread count. */
int hsw_warp_points(const struct hsw_tree *t, const double *in, double *out,
    uint64_t n);

/* Input point sets over [0,1)^2. */
enum hsw_input {
	HSW_RANDOM,	/* frs_rand01, stream FRS_STREAM_HSW */
	HSW_REGULAR,	/* k x k cell centres, k = ceil(sqrt(n)), the first n
			 * in row order */
	HSW_JITTERED,	/* the same cells, a random point in each */
	HSW_HALTON,	/* bases 2 and 3, index i + 1 */
	HSW_HAMMERSLEY	/* ((i + 0.5) / n, radical inverse base 2 of i) */
};	/* frs.h's enum frs_hsw_input, value for value (api/hsw.c), whose
	 * names frs_names gives */
/* n pairs into out (2n doubles), in parallel with frs_parallel. */
void hsw_input_make(enum hsw_input kind, uint64_t n, uint64_t seed,
    double *out);
/* The pairs of indices begin .. end - 1 of the n-point set (2 (end -
 * begin) doubles): hsw_input_make's values, for a piece of the range. */
void hsw_input_range(enum hsw_input kind, uint64_t n, uint64_t seed,
    uint64_t begin, uint64_t end, double *out);
/* Radical inverse of i in base b, in [0, 1). */
double hsw_radical_inverse(uint64_t i, unsigned b);

/* Density I / mean I of the pixel of point (x, y), inside the map. */
static inline double hsw_pdf_at(const struct frs_imap *map, double mean,
    double x, double y)
{
	return map->v[frs_imap_pixel_of(map, x, y)] / mean;
}

/* The mean of the map the tree was built from, as hsw_pdf_at wants it. */
static inline double hsw_mean(const struct hsw_tree *t,
    const struct frs_imap *map)
{
	return t->total / ((double)map->w * (double)map->h);
}

/* The points to warp: the pairs of in, or, where in is NULL, the n-point
 * set kind made on the fly. */
struct hsw_source {
	enum hsw_input kind;
	uint64_t n, seed;
	const double *in;
};

/* Points begin .. end - 1 of src warped into xy[0 ..] (pairs) and,
 * where map (the tree's own map) and pdf are not NULL, their densities
 * (hsw_pdf_at) into pdf[0 ..], made with the points.  In parallel with
 * frs_parallel, in chunks of the index range; a point depends on its
 * index only, so the bytes are the same for any thread count and any
 * cut of the range. */
int hsw_sample(const struct hsw_tree *t, const struct hsw_source *src,
    const struct frs_imap *map, uint64_t begin, uint64_t end, double *xy,
    double *pdf);
#endif
