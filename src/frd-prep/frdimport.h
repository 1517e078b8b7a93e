/*
 * Foreign threshold matrices read into a struct frs_matrix (frs.h), for
 * frd-prep(1): raw 32-bit values and text.  The grey levels of a PNG
 * dither mask are the library's (frs_matrix_read_png).
 */
#ifndef FRS_FRDIMPORT_H
#define FRS_FRDIMPORT_H

#include <stdint.h>

#include "frs.h"

/* What an import returns besides 0: a failure (its message recorded,
 * cli_errmsg), one that -s WxH would mend (a count of raw32 values that
 * is no square), or one that --rank would (values that are no
 * permutation). */
enum { IMPORT_FAIL = -1, IMPORT_SIZE = -2, IMPORT_RANKS = -3 };

/* raw32: little-endian 32-bit values, W x H (0 x 0: a square from the
 * file length); text: one row per line, values separated by blanks.
 * Both must hold a permutation of 0..N-1 unless rank is set, which
 * replaces any values by their ranks (ties by position). */
int frd_import_raw32(const char *path, uint32_t w, uint32_t h, int rank,
    struct frs_matrix *m);
int frd_import_text(const char *path, int rank, struct frs_matrix *m);

#endif
