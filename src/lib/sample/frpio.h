/*
 * Prepared matrices, the .frp files of frd-prep(1): a matrix with its
 * minmap and sorted lists (frscore.h's frs_prep), written once so that
 * sampling need not prepare them again.
 *
 * The .frp format (see frd(5)), little-endian:
 *   0   8  magic "\211FRP\r\n\032\n"
 *   8   4  version 1
 *   12  4  width, 16 4 height
 *   20  4  flags: 1 minmap, 2 sorted lists
 *   24  8  checksum of the matrix (frd_checksum)
 *   32  4  number of sorted block sizes, 36 4 reserved (0)
 *   40     the matrix values; then minmap levels 1, 2, ... while both
 *          sides are at least 1; then per block size B: B, 0 (8 bytes),
 *          the sorted values and their in-block indices, uint32 each.
 */
#ifndef FRS_FRPIO_H
#define FRS_FRPIO_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "formats/frdio.h"
#include "sample/frscore.h"

#define FRP_MAGIC "\211FRP\r\n\032\n"

/* Write m with its minmap (if minmap) and the sorted lists of the given
 * block sizes to fp (name in messages about writing); src names the
 * matrix in messages about it (one that cannot be prepared). */
int frp_write(FILE *fp, const char *name, const char *src,
    const struct frs_matrix *m, int minmap, const uint32_t *blocks,
    unsigned nblocks);
/* Read a .frp: the matrix, the minmap when present, and the sorted lists
 * of block size "block" when present (p->block = 0 if not).  The
 * checksum must match the matrix read, and the file must hold all that
 * its header announces (a regular file: by its length; a pipe: read to
 * its end). */
int frp_read(const char *path, struct frs_matrix *m, struct frs_prep *p,
    uint32_t block);
/* The same from fp, of which the first npre bytes (pre) were read
 * already. */
int frp_read_pre(FILE *fp, const char *name, const unsigned char *pre,
    size_t npre, struct frs_matrix *m, struct frs_prep *p, uint32_t block);
/* frp_read of a file read before for the matrix known, from fp (kept
 * open since, read again from its start) or, when fp is NULL, from path
 * opened again: when its values are known's and known->perm, they are
 * not checked again. */
int frp_read_known(FILE *fp, const char *path,
    const struct frs_matrix *known, struct frs_matrix *m, struct frs_prep *p,
    uint32_t block);
/* The twin .frp at path of the 2-D matrix m (a .frd's), opened once: 0
 * with its minmap in p (p->m = m; no sorted lists) and in *keep the
 * file, left open for its lists when it is a regular file (else NULL);
 * 1 when it is none (not there, not a .frp: nothing to say); 2 when it
 * is stale (made from another matrix); -1 when damaged (the message). */
int frp_read_twin(const char *path, const struct frs_matrix *m,
    struct frs_prep *p, FILE **keep);
/* What frp_check_fp found in a valid .frp. */
struct frp_summary {
	uint32_t w, h;
	uint64_t sum;
	int minmap;
	unsigned nblocks;
	uint32_t blocks[32];	/* the block sizes of its sets, in order */
};
/* Read a whole .frp from fp, of which the first npre bytes (pre) were
 * read already, and check all of it: the length, the checksum, the
 * permutation, every minmap level and every set of sorted lists. */
int frp_check_fp(FILE *fp, const char *name, const unsigned char *pre,
    size_t npre, struct frp_summary *s);
/* The size and checksum recorded in a .frp. */
int frp_info(const char *path, uint32_t *w, uint32_t *h, uint64_t *sum);
/* 1 if the file starts with the .frp magic, 0 if not, -1 if unreadable. */
int frp_is(const char *path);

#endif
