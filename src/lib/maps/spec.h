/*
 * Procedural importance: maps and volumes given by name and parameters,
 * "name[:param=value,...]" (the first parameter may be given without its
 * name), evaluated at the size asked for.
 */
#ifndef FRS_SPEC_H
#define FRS_SPEC_H

#include <stdint.h>

#include "maps/imap.h"
#include "maps/vol.h"

/* Maps: const, blob, ramp, aniso, sky. */
int imap_spec(const char *spec, uint32_t w, uint32_t h, struct frs_imap *m);
/* Help text listing the specs and their parameters. */
const char *imap_spec_help(void);
/* 1 if the string names a procedural spec (by its name before ':'). */
int imap_is_spec(const char *src);

/* Volumes: const, blob3, ramp3, shell3 (see vol_spec_help), evaluated at
 * w x h x d (0: the default side). */
int vol_spec(const char *spec, uint32_t w, uint32_t h, uint32_t d,
    struct frs_vol *m);
int vol_is_spec(const char *src);
const char *vol_spec_help(void);

#endif
