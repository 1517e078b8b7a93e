/*
 * Threshold matrices, the .frd format (see frd(5)).
 *
 *   offset  size  field
 *   0       8     magic "\211FRD\r\n\032\n"
 *   8       4     format version (1)
 *   12      4     dimension count k (2 or 3)
 *   16      12    sizes W, H, D (D = 1 when k = 2)
 *   28      4     length L of the parameter text
 *   32      L     generator parameters, text "key=value" lines, no NUL
 *   32+L    4N    values, uint32, x fastest, then y, then z; N = W*H*D
 *
 * All fields little-endian.  The values are the last 4N bytes of the file.
 */
#ifndef FRS_FRDIO_H
#define FRS_FRDIO_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "frs.h"	/* struct frs_matrix, public */

#define FRD_MAGIC "\211FRD\r\n\032\n"
#define FRD_VERSION 1
#define FRD_HEADER 32
#define FRD_MAX_PARAMS 65536
/* Largest element count a reader accepts: 2^32 values would not be
 * distinct uint32 thresholds. */
#define FRD_MAX_ELEMS ((uint64_t)1 << 32)

/* Allocate a matrix of the given sizes with zeroed values. */
int frd_alloc(struct frs_matrix *m, unsigned dims, uint32_t w, uint32_t h,
    uint32_t d, const char *params);
void frd_free(struct frs_matrix *m);

/* Read and validate magic, version, sizes against the file length, and
 * that every value is below n.  path "-" is standard input. */
int frd_read(const char *path, struct frs_matrix *m);
/* The same, the values checked to be a permutation in the one pass. */
int frd_read_perm(const char *path, struct frs_matrix *m);
int frd_read_fp(FILE *fp, const char *name, struct frs_matrix *m);
/* What the pass that checks the values learns beyond their range:
 * nothing, whether they are a permutation (m->perm: 1 if so, 0 if not
 * or when it could not tell; frd_check_permutation says why), or that
 * they must be one (a read that fails as frd_check_permutation would:
 * the file read and checked in one pass). */
enum frd_perm { FRD_PERM_NO, FRD_PERM_FIND, FRD_PERM_NEED };
/* The same for a stream of which the first npre bytes (pre) were read
 * already, learning perm (enum frd_perm). */
int frd_read_pre(FILE *fp, const char *name, const unsigned char *pre,
    size_t npre, struct frs_matrix *m, int perm);
int frd_write(FILE *fp, const char *name, const struct frs_matrix *m);

/* Check that the values are a permutation of 0..n-1 (at once when
 * m->perm says so); the message names the first repeated value and
 * where it is. */
int frd_check_permutation(const struct frs_matrix *m, const char *name);

/* Replace the values by their ranks, ties in order of position (an
 * import's values made a permutation); m->perm is left as it was. */
int frd_rank(struct frs_matrix *m);

/* 64-bit FNV-1a of the sizes and values, to tie prepared data to its
 * source matrix. */
uint64_t frd_checksum(const struct frs_matrix *m);
/* frd_checksum compared with want and, unless m->perm, the check of
 * frd_check_permutation, in one pass over the values.  0; -1 after
 * frs_fail: a checksum other than want (a damaged file) first. */
int frd_check_sum(const struct frs_matrix *m, const char *name,
    uint64_t want);

#endif
