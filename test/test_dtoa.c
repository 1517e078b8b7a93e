/* frs_dtoa: round trip, shortness and nearness against a brute-force
 * oracle built on printf's correct rounding, and the output form. */
#include "testutil.h"
#include "cli/dtoa.h"

#include <float.h>

/* splitmix64: fast enough for a million draws under ASan. */
static uint64_t mix(uint64_t *s)
{
	uint64_t z = (*s += 0x9e3779b97f4a7c15u);

	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
	return z ^ (z >> 31);
}

static double from_bits(uint64_t b)
{
	double v;

	memcpy(&v, &b, sizeof v);
	return v;
}

static int same_bits(double a, double b)
{
	return memcmp(&a, &b, sizeof a) == 0;
}

/* frs_dtoa(v) and back, bit for bit; a failure names v. */
static void roundtrip1(double v)
{
	char buf[FRS_DTOA_BUF];
	size_t n = frs_dtoa(v, buf);

	assert_int_equal(n, strlen(buf));
	assert_true(n <= 24);
	if (!same_bits(strtod(buf, NULL), v)) {
		print_error("%a gave %s\n", v, buf);
		fail();
	}
}

/* Edge cases and their neighbours. */
static const double edges[] = {
	0.0, 1.0, 2.0, 10.0, 0.1, 0.2, 0.3, 1.0 / 3, 2.0 / 3, 0.5, 0.25,
	0x1.fffffffffffffp-1, 0x1.ffffffffffffep-1, 0x1p-1074, 0x1p-1073,
	0x0.fffffffffffffp-1022, DBL_MIN, DBL_MAX, DBL_EPSILON, 5e-324,
	1e23, 9007199254740992.0, 9007199254740993.0, 4503599627370496.5,
	562949953421312.25, 18014398509481988.0, 1e16, 1e17, 1e21, 1e22, 123456789012345680000.0,
	2.2250738585072011e-308, 1.7976931348623157e308, 0.000123, 1.5e-7,
};

/*
 * Doubles v = c 2^q whose rounding interval ends exactly on a decimal
 * with K fewer digits: (2c +- 1) 2^(q-1) = r 5^K 2^(q-1) is a multiple of
 * 10^K for q > K.  Where that bound belongs to the interval (c even) or
 * not (c odd) decides between two candidates; r odd gives both parities.
 */
static size_t bound_values(double *out, uint64_t *seed)
{
	size_t n = 0;

	for (int q = 2; q <= 80; q++) {
		int k = (int)floor(q * log10(2.0));
		for (int kk = k > 1 ? k - 1 : 0; kk <= k + 1 && kk < q; kk++) {
			uint64_t p5 = 1;
			for (int i = 0; i < kk; i++)
				p5 *= 5;
			uint64_t lo = ((uint64_t)1 << 53) / p5 + 1;
			uint64_t hi = ((uint64_t)1 << 54) / p5 - 1;
			if (hi <= lo)
				continue;
			for (int j = 0; j < 4; j++) {
				uint64_t r = (lo + mix(seed) % (hi - lo)) | 1;
				/* 2c + 1 = r 5^K, and 2c - 1 = r 5^K */
				out[n++] = ldexp((double)((r * p5 - 1) / 2), q);
				out[n++] = ldexp((double)((r * p5 + 1) / 2), q);
			}
		}
	}
	return n;
}

/* Values the tests sweep besides random ones: every power of 2 and of
 * 10, the edges, the interval bounds above, and the neighbours of all of
 * them, with both signs. */
static size_t special_values(double *out, size_t cap)
{
	uint64_t seed = 99;
	size_t n = 0;

	for (int e = -1074; e <= 1023; e++)
		out[n++] = ldexp(1.0, e);
	for (int e = -323; e <= 308; e++) {
		char t[16];
		snprintf(t, sizeof t, "1e%d", e);
		out[n++] = strtod(t, NULL);
	}
	for (size_t i = 0; i < sizeof edges / sizeof edges[0]; i++)
		out[n++] = edges[i];
	n += bound_values(out + n, &seed);
	for (size_t i = 0, m = n; i < m; i++) {
		out[n++] = nextafter(out[i], 0.0);
		out[n++] = nextafter(out[i], INFINITY);
	}
	for (size_t i = 0, m = n; i < m; i++)
		out[n++] = -out[i];
	assert_true(n <= cap);
	return n;
}

#define NSPECIAL 40000

static void roundtrip(void **state)
{
	static double sp[NSPECIAL];
	size_t nsp = special_values(sp, NSPECIAL);
	uint64_t seed = 20260101;
	(void)state;

	for (size_t i = 0; i < nsp; i++)
		if (isfinite(sp[i]))
			roundtrip1(sp[i]);
	/* A million random bit patterns: every exponent, both signs. */
	for (int i = 0; i < 1000000; i++) {
		double v = from_bits(mix(&seed));
		if (isfinite(v))
			roundtrip1(v);
	}
}

/* The mantissa digits of a finite frs_dtoa string, and the decimal
 * exponent e of its last digit (value = m 10^e). */
static void parse_dec(const char *s, uint64_t *m, int *e, int *ndig)
{
	int frac = 0, seen_point = 0, nd = 0;
	uint64_t v = 0;
	const char *p = s;

	if (*p == '-')
		p++;
	for (; *p && *p != 'e'; p++) {
		if (*p == '.') {
			seen_point = 1;
			continue;
		}
		assert_true(*p >= '0' && *p <= '9');
		if (v > 0 || *p != '0')
			nd++;
		v = 10 * v + (uint64_t)(*p - '0');
		frac += seen_point;
	}
	*e = (*p == 'e' ? atoi(p + 1) : 0) - frac;
	while (v > 0 && v % 10 == 0) {	/* trailing integer zeros */
		v /= 10;
		(*e)++;
		nd--;
	}
	*m = v;
	*ndig = nd;
}

static int oracle_reads_back(uint64_t m, int e, double v)
{
	char t[48];

	snprintf(t, sizeof t, "%llue%d", (unsigned long long)m, e);
	return same_bits(strtod(t, NULL), v);
}

/*
 * The oracle for v > 0 at p digits: printf's correctly rounded p-digit
 * M 10^e (the nearest) when it reads back (*nearest 1), else the
 * neighbour that does, which only the asymmetric interval at a power of
 * two allows; 0 when no p-digit decimal reads back.
 */
static int oracle_at(double v, int p, uint64_t *mo, int *eo, int *nearest)
{
	char t[48], *q;
	uint64_t m = 0;

	snprintf(t, sizeof t, "%.*e", p - 1, v);
	for (q = t; *q != 'e'; q++)
		if (*q >= '0' && *q <= '9')
			m = 10 * m + (uint64_t)(*q - '0');
	int e = atoi(q + 1) - (p - 1);
	*eo = e;
	*nearest = 1;
	if (oracle_reads_back(m, e, v)) {
		*mo = m;
		return 1;
	}
	*nearest = 0;
	for (int d = -1; d <= 1; d += 2)
		if (oracle_reads_back(m + (uint64_t)d, e, v)) {
			*mo = m + (uint64_t)d;
			return 1;
		}
	return 0;
}

/*
 * Shortness and nearness: the digit count is the least p for which a
 * p-digit decimal reads back (found from 17 down: if p digits do, p + 1
 * do), and where the nearest p-digit decimal reads back the digits are
 * exactly its.
 */
static void check_short(double v)
{
	char buf[FRS_DTOA_BUF];
	uint64_t m, om = 0, pm = 0;
	int e, nd, oe = 0, pe = 0, near = 0, pnear = 0, p;

	v = fabs(v);
	frs_dtoa(v, buf);
	parse_dec(buf, &m, &e, &nd);
	for (p = 17; p >= 1 && oracle_at(v, p, &om, &oe, &near); p--) {
		pm = om;
		pe = oe;
		pnear = near;
	}
	p++;
	while (pm > 0 && pm % 10 == 0) {	/* same value, same digits */
		pm /= 10;
		pe++;
	}
	if (nd != p || (pnear && (m != pm || e != pe)) ||
	    !oracle_reads_back(m, e, v)) {
		print_error("%a: %s (%d digits), oracle %llue%d (%d digits)\n",
		    v, buf, nd, (unsigned long long)pm, pe, p);
		fail();
	}
}

/* Random values of three kinds: bit patterns (every exponent), uniform
 * in [0, 1) as the point files hold, and short decimals (few digits, any
 * exponent), where shortness is what is tested. */
static void shortest(void **state)
{
	static double sp[NSPECIAL];
	size_t nsp = special_values(sp, NSPECIAL);
	uint64_t seed = 777;
	(void)state;

	for (size_t i = 0; i < nsp; i++)
		if (isfinite(sp[i]) && sp[i] != 0)
			check_short(sp[i]);
	for (int i = 0; i < 100000; i++) {
		uint64_t r = mix(&seed);
		double v;
		char t[48];
		switch (i % 3) {
		case 0:
			v = from_bits(r);
			break;
		case 1:
			v = (double)(r >> 11) * 0x1p-53;
			break;
		default:	/* 1 to 8 digits, exponent -330 .. 310 */
			snprintf(t, sizeof t, "%llue%d",
			    (unsigned long long)(mix(&seed) %
			    (uint64_t)pow(10, (double)(1 + r % 8))),
			    (int)(r >> 32) % 640 - 330);
			v = strtod(t, NULL);
			break;
		}
		if (isfinite(v) && v != 0)
			check_short(v);
	}
}

/* Where two shortest strings read back, the nearer: known answers. */
static void nearest(void **state)
{
	static const struct {
		double v;
		const char *s;
	} cases[] = {
		/* 17 digits: 9.88131291682493088e-324 is nearer than ...e-324 */
		{ 0x1p-1073, "1e-323" },
		{ 5e-324, "5e-324" },	/* 4.94e-324: 5 is nearer than 4 */
		{ 0x1p-1072, "2e-323" },
		/* A tie at 16 digits (v is ...312.25): the even digit */
		{ 562949953421312.25, "562949953421312.2" },
		{ 562949953421312.75, "562949953421312.8" },
		{ 2.0 / 3, "0.6666666666666666" },
		{ 0x1.fffffffffffffp-1, "0.9999999999999999" },
		{ DBL_MAX, "1.7976931348623157e+308" },
		{ DBL_MIN, "2.2250738585072014e-308" },
		{ 0x1p-1022 - 0x1p-1074, "2.225073858507201e-308" },
		{ 9007199254740993.0, "9007199254740992" },
		{ 1e23, "1e+23" },
	};
	(void)state;

	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		char buf[FRS_DTOA_BUF];
		frs_dtoa(cases[i].v, buf);
		assert_string_equal(buf, cases[i].s);
	}
}

/* The form: plain for first-digit exponents -4 .. 16, as %.17g. */
static void form(void **state)
{
	static const struct {
		double v;
		const char *s;
	} cases[] = {
		{ 0.0, "0" }, { -0.0, "-0" }, { 1.0, "1" }, { -2.5, "-2.5" },
		{ 100.0, "100" }, { 123.5, "123.5" }, { 0.1, "0.1" },
		{ 0.0001, "0.0001" }, { 0.000123, "0.000123" },
		{ 0.00001, "1e-05" }, { 1.5e-7, "1.5e-07" },
		{ 1e16, "10000000000000000" }, { 1.5e16, "15000000000000000" },
		{ 1e17, "1e+17" }, { 1e20, "1e+20" }, { -1e100, "-1e+100" },
		{ 1.25e-100, "1.25e-100" }, { 1.0 / 3, "0.3333333333333333" },
		{ 123456789012345680000.0, "1.2345678901234568e+20" },
		{ -(0x1p-1022 - 0x1p-1074), "-2.225073858507201e-308" },
		{ -5e-324, "-5e-324" }, { 0.5, "0.5" }, { 1e15 + 0.5,
		  "1000000000000000.5" },
	};
	char buf[FRS_DTOA_BUF];
	(void)state;

	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		assert_int_equal(frs_dtoa(cases[i].v, buf), strlen(cases[i].s));
		assert_string_equal(buf, cases[i].s);
	}
	frs_dtoa(NAN, buf);
	assert_string_equal(buf, "nan");
	frs_dtoa(-NAN, buf);
	assert_string_equal(buf, "nan");
	frs_dtoa(INFINITY, buf);
	assert_string_equal(buf, "inf");
	frs_dtoa(-INFINITY, buf);
	assert_string_equal(buf, "-inf");
	/* The longest form fits with room to spare. */
	assert_int_equal(frs_dtoa(-2.2250738585072014e-308, buf), 24);
}

/* The search path (used where the fast one cannot decide) agrees. */
static void slow_path(void **state)
{
	static double sp[NSPECIAL];
	size_t nsp = special_values(sp, NSPECIAL);
	uint64_t seed = 4242;
	char a[FRS_DTOA_BUF], b[FRS_DTOA_BUF];
	(void)state;

	for (size_t i = 0; i < nsp; i += 13) {
		frs_dtoa(sp[i], a);
		frs_dtoa_slow(sp[i], b);
		assert_string_equal(a, b);
	}
	for (int i = 0; i < 4000; i++) {
		double v = from_bits(mix(&seed));
		frs_dtoa(v, a);
		frs_dtoa_slow(v, b);
		assert_string_equal(a, b);
	}
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(form),
	cmocka_unit_test(nearest),
	cmocka_unit_test(roundtrip),
	cmocka_unit_test(shortest),
	cmocka_unit_test(slow_path))
