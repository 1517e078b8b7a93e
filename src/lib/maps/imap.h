/*
 * Importance maps: one in-memory form for PNG, OpenEXR and procedural
 * sources, struct frs_imap, which is public (frs.h: the programs and the
 * API's users hold maps in it, and the FRS_MAP_ flags and limits with
 * it, and since 2.2 struct frs_imap_stats and frs_imap_pixel_of; this
 * stage includes frs.h for those alone).  Pixel (i, j)
 * covers [i/W, (i+1)/W) x [j/H, (j+1)/H) of the unit square, row j
 * counted from the top of the image; values are linear, non-negative
 * importance in double.  RGB becomes Rec. 709 luminance.
 */
#ifndef FRS_IMAP_H
#define FRS_IMAP_H

#include <stdint.h>

#include "frs.h"

/* struct frs_imap_stats is public (frs.h, since 2.2). */

int imap_alloc(struct frs_imap *m, uint32_t w, uint32_t h);
void imap_free(struct frs_imap *m);
void imap_stats(const struct frs_imap *m, struct frs_imap_stats *s);

/*
 * Reject NaN and infinity (naming the pixel) and, unless FRS_MAP_ALLOW_ZERO,
 * an all-zero map; clamp negative values to zero with one warning giving
 * their count and the smallest value, or fail under FRS_MAP_STRICT.
 */
int imap_validate(struct frs_imap *m, const char *name, int flags);
/* The same, and the statistics of the values it leaves into s (what a
 * sampler needs of them, without another pass). */
int imap_validate_stats(struct frs_imap *m, const char *name, int flags,
    struct frs_imap_stats *s);
/* imap_validate's and vol_validate's last part, on m's values (a
 * volume's through vol_as_map) with their stats s, once the non-finite
 * and the strict cases are refused: negatives clamped (the warning
 * counting them as what: "pixels", "voxels"), s made again, then the
 * all-zero check. */
int imap_clamp(struct frs_imap *m, struct frs_imap_stats *s,
    const char *name, const char *what, int flags);

/* Area-weighted resampling to w x h (box filter, exact overlaps). */
int imap_resample(const struct frs_imap *in, uint32_t w, uint32_t h,
    struct frs_imap *out);
/* Multiply row j by the mean of sin(theta) over it, theta = pi * y, so that
 * an equirectangular environment map becomes an importance over the unit
 * square proportional to solid angle. */
void imap_equirect(struct frs_imap *m);
/* That weight of row j of h. */
double imap_equirect_weight(uint32_t j, uint32_t h);

/* imap_pixel_of is public: frs_imap_pixel_of (frs.h). */

/* Rec. 709 luminance of linear RGB. */
static inline double imap_luma(double r, double g, double b)
{
	return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}

#endif
