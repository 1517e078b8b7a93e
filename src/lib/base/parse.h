/*
 * Strict number parsing: the whole string must be one number, with no
 * junk before or after it, no NaN or infinity, no overflow, and within
 * the range asked for.  On failure the functions record a message that
 * names the option or field given as "what" and return -1.
 */
#ifndef FRS_PARSE_H
#define FRS_PARSE_H

#include <stdint.h>

int parse_ll(const char *what, const char *s, long long min, long long max,
    long long *out);
int parse_u64(const char *what, const char *s, uint64_t min, uint64_t max,
    uint64_t *out);
/* Finite doubles in [min, max]. */
int parse_double(const char *what, const char *s, double min, double max,
    double *out);
/* Finite doubles in (min, max]: min itself is out of range too. */
int parse_double_above(const char *what, const char *s, double min,
    double max, double *out);
/* "N" (square) or "WxH", each side in [1, max]. */
int parse_size(const char *what, const char *s, uint32_t max, uint32_t *w,
    uint32_t *h);

#endif
