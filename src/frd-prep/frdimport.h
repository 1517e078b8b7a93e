/*
 * Foreign threshold matrices read into the .frd form (frdio.h), for
 * frd-prep(1): raw 32-bit values, text, and the grey values of a PNG
 * dither mask.
 */
#ifndef FRS_FRDIMPORT_H
#define FRS_FRDIMPORT_H

#include <stdint.h>

#include "formats/frdio.h"

/* raw32: little-endian 32-bit values, W x H (0 x 0: a square from the
 * file length); text: one row per line, values separated by blanks;
 * png16: the grey values of a PNG dither mask, as ranks.  raw32 and text must hold a permutation of 0..N-1 unless rank is
 * set, which replaces any values by their ranks (ties by position). */
int frd_import_raw32(const char *path, uint32_t w, uint32_t h, int rank,
    struct frs_matrix *m);
int frd_import_text(const char *path, int rank, struct frs_matrix *m);
int frd_import_png(const char *path, struct frs_matrix *m);
/* Replace the values by their ranks, ties in order of position. */
int frd_rank(struct frs_matrix *m);

#endif
