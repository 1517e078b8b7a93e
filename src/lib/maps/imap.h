/*
 * Importance maps: one in-memory form for PNG, OpenEXR and procedural
 * sources.  Pixel (i, j) covers [i/W, (i+1)/W) x [j/H, (j+1)/H) of the unit
 * square, row j counted from the top of the image; values are linear,
 * non-negative importance in double.  RGB becomes Rec. 709 luminance.
 */
#ifndef FRS_IMAP_H
#define FRS_IMAP_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

struct frs_imap {
	uint32_t w, h;
	double *v;	/* w * h values, row-major, row 0 at the top */
};

struct frs_imap_stats {
	uint64_t count;		/* w * h */
	uint64_t zeros, negatives, nonfinite;
	double min, max;	/* over finite values */
	double sum, mean;	/* over finite values, compensated sum */
	double min_negative;	/* smallest value when negatives > 0 */
	double min_positive;	/* smallest value > 0, 0 if none */
	uint32_t bad_x, bad_y;	/* first non-finite pixel */
	double bad_value;
	uint32_t neg_x, neg_y;	/* first negative pixel */
};

/* Largest side and pixel count a map may have. */
#define IMAP_MAX_SIDE 65536u
#define IMAP_MAX_PIXELS ((uint64_t)1 << 28)

int imap_alloc(struct frs_imap *m, uint32_t w, uint32_t h);
void imap_free(struct frs_imap *m);
void imap_stats(const struct frs_imap *m, struct frs_imap_stats *s);

/* What imap_load accepts and checks. */
enum {
	IMAP_SRGB = 1 << 0,	  /* decode 8/16-bit PNG from sRGB to linear */
	IMAP_STRICT = 1 << 1,	  /* negative values are an error */
	IMAP_EQUIRECT = 1 << 2,	  /* weight rows by sin(theta) */
	IMAP_ALLOW_ZERO = 1 << 3  /* an all-zero map is not an error */
};

/*
 * Load an importance map from a PNG or OpenEXR file (detected by magic;
 * "-" reads standard input) or, when no such file exists, a procedural
 * spec (see imap_spec).  w, h: requested size, 0 for the file's own size
 * (and 128x128 for specs); a file of another size is resampled by area.
 * Then imap_validate.
 */
int imap_load(const char *src, uint32_t w, uint32_t h, int flags,
    struct frs_imap *m);

/* The source as it is, without checks or clamping: a file at its own
 * size (w, h ignored), a spec at w x h (0: 128x128). */
int imap_load_raw(const char *src, uint32_t w, uint32_t h, int flags,
    struct frs_imap *m);

/*
 * Reject NaN and infinity (naming the pixel) and, unless IMAP_ALLOW_ZERO,
 * an all-zero map; clamp negative values to zero with one warning giving
 * their count and the smallest value, or fail under IMAP_STRICT.
 */
int imap_validate(struct frs_imap *m, const char *name, int flags);

/* Area-weighted resampling to w x h (box filter, exact overlaps). */
int imap_resample(const struct frs_imap *in, uint32_t w, uint32_t h,
    struct frs_imap *out);
/* Multiply row j by the mean of sin(theta) over it, theta = pi * y, so that
 * an equirectangular environment map becomes an importance over the unit
 * square proportional to solid angle. */
void imap_equirect(struct frs_imap *m);

/* Procedural maps: "name[:param=value,...]", the first parameter may be
 * given without its name.  Names: const, blob, ramp, aniso, sky. */
int imap_spec(const char *spec, uint32_t w, uint32_t h, struct frs_imap *m);
/* Help text listing the specs and their parameters. */
const char *imap_spec_help(void);
/* 1 if the string names a procedural spec (by its name before ':'). */
int imap_is_spec(const char *src);

/* PNG: 1-16 bit grey, grey+alpha, RGB, RGBA, palette, interlaced; values
 * scaled to [0, 1]; alpha ignored. */
int imap_read_png_mem(const unsigned char *buf, size_t len, const char *name,
    int srgb, struct frs_imap *m);
/* 16-bit grey PNG, the map scaled so that its maximum is 65535. */
int imap_write_png16(FILE *fp, const char *name, const struct frs_imap *m);

/* OpenEXR, scanline or tiled, half/float/uint: channel "Y", else R, G, B
 * (matched by name) as Rec. 709 luminance.  The first part only. */
int imap_read_exr_mem(const unsigned char *buf, size_t len, const char *name,
    struct frs_imap *m);
/* Single-channel float "Y" scanline EXR, ZIP compressed. */
int imap_write_exr(FILE *fp, const char *name, const struct frs_imap *m);

/* Rec. 709 luminance of linear RGB. */
static inline double imap_luma(double r, double g, double b)
{
	return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}

#endif
