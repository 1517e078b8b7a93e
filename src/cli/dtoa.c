/*
 * Shortest round-trip formatting of doubles (see dtoa.h).
 *
 * The method is Schubfach (R. Giulietti, "The Schubfach way to render
 * doubles", 2020), written here from the published mathematics:
 *
 * A finite positive double is v = c 2^q with an integer c (2^52 <= c < 2^53
 * for normal numbers, q = -1074 and c < 2^52 for subnormal ones).  strtod
 * reads back v from every decimal in its rounding interval R, the points
 * nearer to v than to its neighbours: R = [(c - 1/2) 2^q, (c + 1/2) 2^q],
 * except at the bottom of a binade (c = 2^52, q > -1074), where the lower
 * neighbour is only 2^(q-1) away and R = [(c - 1/4) 2^q, (c + 1/2) 2^q].
 * The bounds belong to R when c is even (strtod rounds ties to even).
 *
 * Pick the decimal exponent k with 1 <= |R| 10^-k < 10, i.e.
 * k = floor(log10 |R|) = floor(log10 2^q) (or floor(log10(3/4 2^q)) in the
 * asymmetric case).  In units of 10^k the interval is at least 1 wide, so
 * it holds a multiple of 10^k, and less than 10 wide, so it holds at most
 * one multiple of 10^(k+1).  Hence, with s = floor(v 10^-k):
 *   - if R holds a multiple of 10^(k+1), it is the only one and the
 *     shortest answer (one with still fewer digits is such a multiple
 *     too); it can only be 10 floor(s/10) or that plus 10;
 *   - otherwise every decimal in R is d 10^k with the same number of
 *     digits, and the nearest to v is s or s + 1 (v 10^-k lies in
 *     [s, s + 1)); at least one of them is in R; if both are, take the
 *     nearer, on a tie the even one.
 *
 * All that is needed are the three scaled values X = b 2^q 10^-k for b in
 * {4c - 2 (or 4c - 1), 4c, 4c + 2} (the bounds and v, times 4), each as
 * floor(X) with the lowest bit set when X is not an integer ("round to
 * odd"): compared with 4s, 4s + 2 or 4(s + 1) this decides every
 * inequality above exactly, including equality.
 *
 * X is computed as Y = b g / 2^sh with g(k) = 10^-k 2^(127 - e10), e10 =
 * floor(log2 10^-k), a 128-bit integer in [2^127, 2^128) from the table
 * dtoa_tab.h (scripts/gen-dtoa-table.py):
 *   - for -55 <= k <= 0, 10^-k = 5^-k 2^-k with 5^-k < 2^128, g is exact,
 *     Y = X and the 192-bit product gives floor and remainder exactly;
 *   - otherwise g is rounded up: 0 < Y - X < b / 2^sh = Y / g < 2^-68
 *     (Y < 2^59).  When Y's fraction is at least b / 2^sh, X lies in
 *     (floor Y, floor Y + 1): not an integer, same floor.  Otherwise X is
 *     within 2^-68 of the integer floor(Y).  For 1 <= k <= 28,
 *     X = b 2^(q-k) / 5^k is an integer or at least 5^-k >= 5^-28 > 2^-65
 *     away from one, so X = floor(Y) exactly.  For the other k, X is never
 *     an integer (5^29 > b, resp. 2^(|q| - |k|) > b for k <= -56); the
 *     published analysis of Schubfach (and Adams's of Ryu, with 125-bit
 *     powers) finds no double whose X comes that close to an integer, but
 *     rather than rely on it frs_dtoa_slow then decides by search.
 */
#define _POSIX_C_SOURCE 200809L
#include "cli/dtoa.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/dtoa_tab.h"

__extension__ typedef unsigned __int128 u128;

#define C_MIN ((uint64_t)1 << 52)
#define Q_MIN (-1074)

static const char digits2[201] =
	"00010203040506070809101112131415161718192021222324"
	"25262728293031323334353637383940414243444546474849"
	"50515253545556575859606162636465666768697071727374"
	"75767778798081828384858687888990919293949596979899";

/* floor(x / 2^n) for either sign (>> of a negative value is
 * implementation-defined in C). */
static int floor_shift(int64_t x, unsigned n)
{
	int64_t d = (int64_t)1 << n;

	return (int)(x >= 0 ? x / d : -((-x + d - 1) / d));
}

/* The integer logarithms, each checked for every q of a double (and every
 * k they give) by scripts/gen-dtoa-table.py: 315653 / 2^20 ~ log10 2,
 * 131237 / 2^20 ~ -log10(3/4), 1741647 / 2^19 ~ log2 10. */
static int floor_log10_pow2(int q)
{
	return floor_shift((int64_t)q * 315653, 20);
}

static int floor_log10_34pow2(int q)
{
	return floor_shift((int64_t)q * 315653 - 131237, 20);
}

static int floor_log2_pow10(int e)
{
	return floor_shift((int64_t)e * 1741647, 19);
}

struct scale {
	const uint64_t *g;	/* g(k), high and low 64 bits */
	unsigned sh;		/* Y = b g / 2^(64 + sh), 60 <= sh <= 63 */
	int k;
	int exact;		/* g = 10^-k 2^(127 - e10) exactly */
};

/*
 * X = b 2^q 10^-k rounded to odd (see the top of the file); *undecided
 * set where only the search can tell.
 */
static uint64_t rop(const struct scale *sc, uint64_t b, int *undecided)
{
	u128 lo = (u128)b * sc->g[1];
	u128 hi = (u128)b * sc->g[0] + (lo >> 64);	/* product >> 64 */
	uint64_t y = (uint64_t)(hi >> sc->sh);
	/* The fraction of Y, in units of 2^-(64 + sh): (fhi, flo). */
	uint64_t fhi = (uint64_t)hi & (((uint64_t)1 << sc->sh) - 1);
	uint64_t flo = (uint64_t)lo;

	if (sc->exact)
		return y | (fhi != 0 || flo != 0);
	if (fhi == 0 && flo < b) {	/* fraction below Y - X's bound */
		if (sc->k >= 1 && sc->k <= 28)
			return y;	/* X is the integer y */
		*undecided = 1;
	}
	return y | 1;
}

/* v = c 2^q > 0 as the decimal d 10^e of dtoa.h; -1 when undecided. */
static int to_decimal(uint64_t c, int q, uint64_t *d, int *e)
{
	int asym = c == C_MIN && q > Q_MIN;
	uint64_t cb = c << 2, cbl = asym ? cb - 1 : cb - 2, cbr = cb + 2;
	uint64_t out = c & 1;	/* the bounds are outside R for odd c */
	struct scale sc;
	int undecided = 0;

	sc.k = asym ? floor_log10_34pow2(q) : floor_log10_pow2(q);
	sc.g = dtoa_g[sc.k - DTOA_K_MIN];
	/* Y = b g 2^(q + e10 - 127): 124 <= 127 - q - e10 <= 127. */
	sc.sh = (unsigned)(127 - q - floor_log2_pow10(-sc.k) - 64);
	sc.exact = sc.k >= -55 && sc.k <= 0;

	uint64_t vbl = rop(&sc, cbl, &undecided);
	uint64_t vb = rop(&sc, cb, &undecided);
	uint64_t vbr = rop(&sc, cbr, &undecided);
	if (undecided)
		return -1;

	/* A multiple of 10^(k+1) in R: unique, and the shortest. */
	uint64_t s = vb >> 2;
	uint64_t sp = s / 10 * 10, tp = sp + 10;
	int upin = vbl + out <= sp << 2;	/* false for sp = 0: vbl > 0 */
	int wpin = (tp << 2) + out <= vbr;
	if (upin != wpin) {
		*d = upin ? sp : tp;
		*e = sc.k;
		return 0;
	}
	/* Else s or s + 1, the nearer when both are in R. */
	uint64_t t = s + 1;
	int uin = vbl + out <= s << 2;
	int win = (t << 2) + out <= vbr;
	if (uin != win)
		*d = uin ? s : t;
	else	/* v 10^-k against the midpoint s + 1/2 */
		*d = vb < 4 * s + 2 || (vb == 4 * s + 2 && (s & 1) == 0) ? s : t;
	*e = sc.k;
	return 0;
}

/*
 * d 10^e (d > 0) in the form of dtoa.h: x, the exponent of the first
 * digit, chooses plain or scientific as %.17g does.
 */
static size_t format(uint64_t d, int e, char *buf)
{
	char tmp[20], *end = tmp + sizeof tmp, *s = end, *p = buf;

	while (d % 10 == 0) {
		d /= 10;
		e++;
	}
	while (d >= 100) {
		s -= 2;
		memcpy(s, digits2 + 2 * (d % 100), 2);
		d /= 100;
	}
	if (d >= 10) {
		s -= 2;
		memcpy(s, digits2 + 2 * d, 2);
	} else {
		*--s = (char)('0' + d);
	}
	int n = (int)(end - s);
	int x = e + n - 1;

	if (x < -4 || x >= 17) {
		unsigned ax = (unsigned)(x < 0 ? -x : x);
		*p++ = s[0];
		if (n > 1) {
			*p++ = '.';
			memcpy(p, s + 1, (size_t)n - 1);
			p += n - 1;
		}
		*p++ = 'e';
		*p++ = x < 0 ? '-' : '+';
		if (ax >= 100) {
			*p++ = (char)('0' + ax / 100);
			ax %= 100;
		}
		memcpy(p, digits2 + 2 * ax, 2);
		p += 2;
	} else if (e >= 0) {		/* an integer, at most 17 digits */
		memcpy(p, s, (size_t)n);
		p += n;
		memset(p, '0', (size_t)e);
		p += e;
	} else if (x >= 0) {		/* the point among the digits */
		memcpy(p, s, (size_t)x + 1);
		p += x + 1;
		*p++ = '.';
		memcpy(p, s + x + 1, (size_t)(n - x - 1));
		p += n - x - 1;
	} else {			/* 0.000ddd */
		*p++ = '0';
		*p++ = '.';
		memset(p, '0', (size_t)(-x - 1));
		p += -x - 1;
		memcpy(p, s, (size_t)n);
		p += n;
	}
	*p = '\0';
	return (size_t)(p - buf);
}

/* NaN, infinities and zeros into buf: the length, or 0 for the others
 * (after a '-' for negative ones, *sign 1). */
static size_t special(double v, char *buf, size_t *sign)
{
	uint64_t bits;

	memcpy(&bits, &v, sizeof bits);
	*sign = 0;
	if (isnan(v)) {
		memcpy(buf, "nan", 4);
		return 3;
	}
	if (bits >> 63)
		buf[(*sign)++] = '-';
	if (isinf(v)) {
		memcpy(buf + *sign, "inf", 4);
		return *sign + 3;
	}
	if (v == 0) {
		memcpy(buf + *sign, "0", 2);
		return *sign + 1;
	}
	return 0;
}

size_t frs_dtoa(double v, char *buf)
{
	uint64_t bits, c, t;
	size_t sign, n = special(v, buf, &sign);
	unsigned be;
	uint64_t d;
	int e;

	if (n > 0)
		return n;
	memcpy(&bits, &v, sizeof bits);
	be = (unsigned)(bits >> 52) & 0x7ff;
	t = bits & (C_MIN - 1);
	c = be ? t | C_MIN : t;
	if (to_decimal(c, be ? (int)be - 1075 : Q_MIN, &d, &e) < 0)
		return frs_dtoa_slow(v, buf);
	return sign + format(d, e, buf + sign);
}

/* Whether m 10^e reads back as v (no decimal point: no locale). */
static int reads_back(uint64_t m, int e, double v)
{
	char t[48];

	snprintf(t, sizeof t, "%llue%d", (unsigned long long)m, e);
	return strtod(t, NULL) == v;
}

/*
 * The search: for p = 1, 2, ... digits, printf's correctly rounded p-digit
 * decimal M 10^e is the nearest to v; where it does not read back, the
 * only other p-digit candidate is its neighbour on the far side of v
 * (possible in the asymmetric interval), so M - 1 and M + 1 are tried.
 */
size_t frs_dtoa_slow(double v, char *buf)
{
	size_t sign, n = special(v, buf, &sign);
	double a = fabs(v);

	if (n > 0)
		return n;
	for (int p = 1; p <= 17; p++) {
		char t[48], *q;
		uint64_t m = 0;

		snprintf(t, sizeof t, "%.*e", p - 1, a);
		for (q = t; *q != 'e'; q++)
			if (*q >= '0' && *q <= '9')
				m = 10 * m + (uint64_t)(*q - '0');
		int e = (int)strtol(q + 1, NULL, 10) - (p - 1);
		const uint64_t cand[3] = { m, m - 1, m + 1 };
		for (int i = 0; i < 3; i++)
			if (cand[i] > 0 && reads_back(cand[i], e, a))
				return sign + format(cand[i], e, buf + sign);
	}
	return 0;	/* not reached: 17 digits always read back */
}
