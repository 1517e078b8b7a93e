/* The release of the toolchain and of libfrs (frs_version(3), every
 * program's --version); the Makefile reads it for frs.pc. */
#ifndef FRS_VERSION_H
#define FRS_VERSION_H

#define FRS_VERSION "0.6.0"

#endif
