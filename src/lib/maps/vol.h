/*
 * Importance volumes for 3-D Forced Random Sampling: voxel (i, j, l) of a
 * W x H x D volume covers [i/W, (i+1)/W) x [j/H, (j+1)/H) x [l/D, (l+1)/D)
 * of the unit cube; values are linear, non-negative importance in double,
 * x fastest, then y, then z.
 *
 * The .frv file (see frv(5)), little-endian:
 *   0   8  magic "\211FRV\r\n\032\n"
 *   8   4  version 1
 *   12  12 sizes W, H, D
 *   24  8  reserved, 0
 *   32     W H D float32 values, x fastest, then y, then z
 * Nothing follows the values.
 *
 * A volume is also a W x (H D) map (slices stacked downwards), which is
 * how the statistics of imap.h see it.
 */
#ifndef FRS_VOL_H
#define FRS_VOL_H

#include <stdint.h>
#include <stdio.h>

#include "maps/imap.h"

#define FRV_MAGIC "\211FRV\r\n\032\n"
#define FRV_VERSION 1
#define FRV_HEADER 32
/* Largest side and voxel count a volume may have. */
#define VOL_MAX_SIDE 65536u
#define VOL_MAX_VOXELS ((uint64_t)1 << 28)
/* Side at which procedural volumes are evaluated by default. */
#define VOL_DEFAULT_SIDE 32u

/* struct frs_vol is public (frs.h, since 2.2). */

int vol_alloc(struct frs_vol *m, uint32_t w, uint32_t h, uint32_t d);
void vol_free(struct frs_vol *m);
/* The volume as a W x (H D) map sharing its values. */
struct frs_imap vol_as_map(const struct frs_vol *m);

/* 1 if the file starts with the .frv magic, 0 if not, -1 if unreadable. */
int vol_is_file(const char *path);
int vol_read(const char *path, struct frs_vol *m);
/* The same from fp, after the npre bytes pre that a peek took. */
int vol_read_pre(FILE *fp, const char *name, const unsigned char *pre,
    size_t npre, struct frs_vol *m);
int vol_write(FILE *fp, const char *name, const struct frs_vol *m);

/* NaN and infinity are errors naming the voxel; negative values are
 * clamped with one warning (an error under FRS_MAP_STRICT); an all-zero
 * volume is an error unless FRS_MAP_ALLOW_ZERO. */
int vol_validate(struct frs_vol *m, const char *name, int flags);

#endif
