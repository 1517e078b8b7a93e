/*
 * A small 8-bit raster for pictures of point sets: grey or RGB pixels,
 * row 0 at the top, pixel (i, j) covering [i, i+1) x [j, j+1) in pixel
 * units.  An importance map can be its background, anti-aliased discs
 * are blended over it, and it is written as an 8-bit PNG.
 */
#ifndef FRS_RASTER_H
#define FRS_RASTER_H

#include <stdint.h>
#include <stdio.h>

struct frs_imap;

struct frs_raster {
	uint32_t w, h;
	unsigned channels;	/* 1 (grey) or 3 (RGB) */
	uint8_t *px;		/* w * h * channels bytes, row-major */
};

/* Grey levels of an importance map shown as background: importance 0 is
 * white (255), the maximum is 255 - RASTER_BG_RANGE, so that black dots
 * stay visible over it. */
#define RASTER_BG_RANGE 80

/* Sides 1 to FRS_MAP_MAX_SIDE, at most FRS_MAP_MAX_PIXELS pixels; filled
 * with white. */
int raster_alloc(struct frs_raster *r, uint32_t w, uint32_t h,
    unsigned channels);
void raster_free(struct frs_raster *r);

/* Fill every pixel with one colour (channels values). */
void raster_fill(struct frs_raster *r, const uint8_t *color);

/*
 * The importance map m, of the raster's size, as grey background.
 * Linear: grey = 255 - round(RASTER_BG_RANGE * v / max).
 * logscale: log10 of the positive values, from the smallest positive one
 * to the maximum, onto 254 .. 255 - RASTER_BG_RANGE, so that every
 * positive value is darker than zero.
 * Zero is white in both; an all-zero map gives a white raster.
 */
int raster_fill_imap(struct frs_raster *r, const struct frs_imap *m,
    int logscale);

/* Fraction of the pixel [x0, x1] x [y0, y1] (relative to the centre)
 * covered by the disc of radius rad around the origin: exact up to
 * rounding (closed form). */
double raster_coverage(double x0, double y0, double x1, double y1,
    double rad);

/*
 * Blend a disc of radius rad pixels centred at (cx, cy) in pixel units
 * over the raster: each channel becomes bg * (1 - c) + color * c, with c
 * the exact fraction of the pixel the disc covers, rounded to 8 bits.
 * Parts outside the raster are clipped.  color has channels values.
 */
void raster_disc(struct frs_raster *r, double cx, double cy, double rad,
    const uint8_t *color);
/* The same with opacity alpha in [0, 1]: c becomes alpha * c, so that a
 * pixel the disc covers whole becomes bg * (1 - alpha) + color * alpha.
 * alpha 1 is raster_disc, byte for byte. */
void raster_disc_alpha(struct frs_raster *r, double cx, double cy,
    double rad, const uint8_t *color, double alpha);

/* The default dot radius for a raster w pixels wide:
 * 1.5 * w / 512, at least 0.7. */
double raster_default_radius(uint32_t w);

/*
 * Dot radii that follow the local spacing of a point set, so that dots
 * shrink where the points are dense instead of merging into a solid
 * blob (pts-render without -r), while denser still looks darker.
 *
 * The density rho at a point, points per square pixel, is that of its
 * nearest points: the squares of pixels centred on its pixel, 1, 3, 5,
 * ... pixels across and clipped to the picture, grow until one holds at
 * least RASTER_SPACING_COUNT points, and rho is that count over the
 * area at which the squares reach it, linear in the count between that
 * square and the one before (the whole square when it is the first).
 * So it is local wherever the points are dense, and a pile of points
 * counts as no more than the count for the points around it.  Where no
 * square up to the area of that count at the spacing that makes a dot
 * of R holds that many, the points are sparse: rho is the count in that
 * square over its area.  The local spacing is
 * s = 1 / sqrt(rho), and the radius, with R = raster_default_radius(w),
 *
 *     min(R, RASTER_SPACING_FRACTION * s + RASTER_SPACING_MIN)
 *
 * (R where rho is 0).  The dots then cover pi (1/3 + 1/(2 s))^2 of the
 * area, which grows as the spacing shrinks: about 1.1 at a spacing of
 * 2 pixels and 2.2 at 1 pixel, dark, but their arrangement shows where
 * they lie several pixels apart.
 */
#define RASTER_SPACING_COUNT 16
#define RASTER_SPACING_FRACTION (1.0 / 3.0)
#define RASTER_SPACING_MIN 0.5

struct raster_spacing {
	uint32_t w, h;		/* the picture, pixels */
	double rmax;		/* R */
	uint32_t *sum;		/* (w + 1) * (h + 1) counts of the points
				 * left of and above each pixel corner */
};

/* The counts of n points of ncol values each (x: n * ncol doubles),
 * coordinates ax (across) and ay (down) in [0,1), drawn on a w x h
 * picture.  -1 with the library's message when out of memory or n is
 * 2^32 or more. */
int raster_spacing_init(struct raster_spacing *s, const double *x,
    size_t n, size_t ncol, unsigned ax, unsigned ay, uint32_t w,
    uint32_t h);
/* The radius for a dot centred at (px, py), pixel units. */
double raster_spacing_radius(const struct raster_spacing *s, double px,
    double py);
void raster_spacing_free(struct raster_spacing *s);

/* The colour of dot k of n for --color: a ramp from blue (first) to red
 * (last), R = round(255 t), G = 0, B = 255 - R with t = k / (n - 1). */
void raster_ramp(uint64_t k, uint64_t n, uint8_t rgb[3]);

/* 8-bit grey or RGB PNG, non-interlaced.  name is used in messages. */
int raster_write_png(FILE *fp, const char *name, const struct frs_raster *r);
/* Binary netpbm: PGM (P5) for grey, PPM (P6) for RGB, maxval 255; the
 * header is "P5\nW H\n255\n", then the pixels, row 0 first. */
int raster_write_pnm(FILE *fp, const char *name, const struct frs_raster *r);

#endif
