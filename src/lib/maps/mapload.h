/*
 * Loading importance maps and volumes by source: the one place that picks
 * a reader, a PNG or OpenEXR file by its magic, a .frv volume, or a
 * procedural spec (spec.h) when no such file exists.
 */
#ifndef FRS_MAPLOAD_H
#define FRS_MAPLOAD_H

#include <stdint.h>

#include "maps/imap.h"
#include "maps/vol.h"

/*
 * Load an importance map from a PNG or OpenEXR file (detected by magic;
 * "-" reads standard input) or, when no such file exists, a procedural
 * spec (see imap_spec).  w, h: requested size, 0 for the file's own size
 * (and 128x128 for specs); a file of another size is resampled by area.
 * Then imap_validate.  flags: IMAP_* of imap.h.
 */
int imap_load(const char *src, uint32_t w, uint32_t h, int flags,
    struct frs_imap *m);

/* The source as it is, without checks or clamping: a file at its own
 * size (w, h ignored), a spec at w x h (0: 128x128). */
int imap_load_raw(const char *src, uint32_t w, uint32_t h, int flags,
    struct frs_imap *m);

/* A .frv file or a spec that only volumes have (const is both). */
int vol_is_volume(const char *src);

/*
 * A .frv file (at its own size: w, h, d must be 0 or equal to it) or a
 * procedural spec, then vol_validate.  IMAP_STRICT and IMAP_ALLOW_ZERO
 * of imap.h apply.
 */
int vol_load(const char *src, uint32_t w, uint32_t h, uint32_t d, int flags,
    struct frs_vol *m);

#endif
