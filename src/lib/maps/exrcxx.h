/* OpenEXR decoding through the C++ library, for compressions that the
 * installed C core cannot decode (DWAA and DWAB in OpenEXR 3.1). */
#ifndef FRS_EXRCXX_H
#define FRS_EXRCXX_H

#include <stddef.h>

struct frs_imap;
int exr_cxx_read(const unsigned char *buf, size_t len, const char *name,
    struct frs_imap *m);

#endif
