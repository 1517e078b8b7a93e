/*
 * PNG importance maps through libpng: any PNG read as a map (grey, or RGB
 * as Rec. 709 luminance), and the 16-bit grey PNG that imap(1) writes.
 */
#ifndef FRS_PNGIO_H
#define FRS_PNGIO_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "maps/imap.h"

/* PNG: 1-16 bit grey, grey+alpha, RGB, RGBA, palette, interlaced; values
 * scaled to [0, 1]; alpha ignored. */
int imap_read_png_mem(const unsigned char *buf, size_t len, const char *name,
    int srgb, struct frs_imap *m);
/* 16-bit grey PNG, the map scaled so that its maximum is 65535. */
int imap_write_png16(FILE *fp, const char *name, const struct frs_imap *m);

/* A PNG of w x h pixels, depth 8 or 16 bits, channels 1 (grey) or 3
 * (RGB): row(ctx, y, buf) gives row y, made in buf (room for one row)
 * or found elsewhere. */
typedef const unsigned char *(*pngio_row_fn)(const void *ctx, uint32_t y,
    unsigned char *buf);
int pngio_write(FILE *fp, const char *name, uint32_t w, uint32_t h,
    int depth, int channels, pngio_row_fn row, const void *rctx);

#endif
