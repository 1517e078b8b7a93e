/*
 * Shortest round-trip formatting of doubles.
 *
 * frs_dtoa(v, buf) writes the shortest decimal string that strtod reads
 * back to exactly v; where several strings of that length do, the one
 * nearest to v (ties to an even last digit).  The algorithm is Schubfach
 * (R. Giulietti, "The Schubfach way to render doubles", 2020) with exact
 * 128-bit powers of ten where they exist; see dtoa.c.
 *
 * Form, chosen as printf's %.17g chooses it so that every reader of the
 * old output (strtod, awk, gnuplot) reads the new: with the decimal
 * exponent x of the first significant digit (v = d.ddd * 10^x),
 *   -4 <= x < 17   plain: "0.000123", "123.5", "100" (no trailing point)
 *   otherwise      scientific with a signed exponent of at least two
 *                  digits: "1.5e-07", "1e+20", "5e-324"
 * "0" and "-0" for zeros, "nan", "inf" and "-inf" otherwise.  Only
 * '0'-'9', '-', '+', '.', 'e' and the letters of nan/inf appear; the
 * output does not depend on the locale.
 */
#ifndef FRS_DTOA_H
#define FRS_DTOA_H

#include <stddef.h>

/* Room frs_dtoa needs: 24 characters at most ("-1.2345678901234567e-308"
 * is 24) and the terminating NUL. */
#define FRS_DTOA_BUF 32

/* The string and a NUL into buf (FRS_DTOA_BUF bytes); returns its length. */
size_t frs_dtoa(double v, char *buf);

/* The same result by search through snprintf and strtod: the path for
 * the cases the fast one cannot decide (none are known), and the tests'
 * second opinion.  Slow (microseconds). */
size_t frs_dtoa_slow(double v, char *buf);

#endif
