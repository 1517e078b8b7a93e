/*
 * OpenEXR importance maps: reading through the OpenEXR C core (and the
 * C++ library, exrcxx.h, for the codecs the core lacks), and writing the
 * single-channel float map that imap(1) writes.
 */
#ifndef FRS_EXRIO_H
#define FRS_EXRIO_H

#include <stddef.h>
#include <stdio.h>

#include "maps/imap.h"

/* OpenEXR, scanline or tiled, half/float/uint: channel "Y", else R, G, B
 * (matched by name) as Rec. 709 luminance.  The first part only. */
int imap_read_exr_mem(const unsigned char *buf, size_t len, const char *name,
    struct frs_imap *m);
/* Single-channel float "Y" scanline EXR, ZIP compressed. */
int imap_write_exr(FILE *fp, const char *name, const struct frs_imap *m);

#endif
