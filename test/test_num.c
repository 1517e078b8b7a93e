/* base/num.h: the compensated sum against exact sums, the radical
 * inverse against the closed form, digits reversed over b^m. */
#include "testutil.h"
#include "base/num.h"

#include <float.h>

/* The loop every sum of the library was before num.h (disc.c's
 * disc_sum): num_sum must give its bits. */
static double old_sum(const double *v, size_t k)
{
	double s = 0.0, c = 0.0;

	for (size_t i = 0; i < k; i++) {
		double t = s + v[i];
		c += fabs(s) >= fabs(v[i]) ? (s - t) + v[i] : (v[i] - t) + s;
		s = t;
	}
	return s + c;
}

/* Cancellations a plain sum loses entirely, and Kahan's sum too (the
 * 1e100 ones: Kahan's compensation assumes the running sum is larger). */
static void sum_cancellations(void **state)
{
	const double a[] = { 1e16, 1.0, -1e16 };
	const double b[] = { 1.0, 1e100, 1.0, -1e100 };
	const double c[] = { 0x1p53, 1.0, 1.0, 1.0, -0x1p53 };
	const double d[] = { 1e308, 1e308, -1e308 };
	struct num_sum s = { 0.0, 0.0 };

	(void)state;
	assert_true(num_sum(a, 3) == 1.0);
	assert_true(num_sum(b, 4) == 2.0);
	assert_true(num_sum(c, 5) == 3.0);
	assert_true(num_sum(a, 0) == 0.0);
	/* The running sum overflows: the total is not finite, as before. */
	assert_false(isfinite(num_sum(d, 3)));
	for (int i = 0; i < 3; i++)
		num_add(&s, a[i]);
	assert_true(num_total(&s) == 1.0);
}

/*
 * Random values k 2^e with integer k < 2^20 and e in [-20, 10], signs
 * mixed: every partial sum is an integer multiple of 2^-20 below 2^62
 * in magnitude, exact in int64_t.  Neumaier's bound (Higham, Accuracy
 * and Stability, 4.3): |total - S| <= u |S| + 2 n u^2 sum |v|, u = 2^-53.
 */
static void sum_exact(void **state)
{
	enum { N = 4096 };
	double *v = malloc(N * sizeof *v);

	(void)state;
	assert_non_null(v);
	for (uint64_t t = 0; t < 200; t++) {
		size_t n = 1 + (size_t)(frs_rand64(t, FRS_STREAM_TEST, 0) % N);
		int64_t exact = 0;
		double abs = 0.0, got, err, bound;
		for (size_t i = 0; i < n; i++) {
			uint64_t r = frs_rand64(t, FRS_STREAM_TEST, i + 1);
			int64_t k = (int64_t)(r & 0xfffff);
			int64_t e = (int64_t)(r >> 20 & 63) % 31 - 20;
			if (t % 2 == 0 && i % 3 == 0)
				e = 10;	/* large values among small ones */
			if (r >> 63)
				k = -k;
			v[i] = ldexp((double)k, (int)e);
			exact += k * ((int64_t)1 << (e + 20));
			abs += fabs(v[i]);
		}
		got = num_sum(v, n);
		err = fabs((double)((long double)got - ldexpl((long double)exact, -20)));
		bound = 0x1p-53 * fabs(ldexp((double)exact, -20)) +
		    2.0 * (double)n * 0x1p-106 * abs;
		assert_true(err <= bound);
		assert_true(got == old_sum(v, n));
	}
	free(v);
}

/* The closed form: i's digits in base b reversed as an integer over
 * b^m, in long double (64-bit significand: num and den exact, the
 * quotient within 2^-64). */
static long double closed_form(uint64_t i, unsigned b, unsigned *digits)
{
	uint64_t num = 0, den = 1;

	*digits = 0;
	while (i > 0) {
		num = num * b + i % b;
		den *= b;
		i /= b;
		(*digits)++;
	}
	return (long double)num / (long double)den;
}

/* Indices from 1 to past 2^32, small ones, ones around 2^32, random ones
 * up to b^m < 2^64 (the closed form's limit), and all-top-digit ones. */
static uint64_t index_at(uint64_t k, unsigned b)
{
	uint64_t top = b == 2 ? (uint64_t)1 << 62 : b == 3 ? 4052555153018976267u
	    : 1490116119384765625u;	/* 3^39, 5^26 */

	if (k < 20000)
		return k;
	if (k < 21000)
		return ((uint64_t)1 << 32) - 500 + (k - 20000);
	if (k < 21060)
		return ((uint64_t)1 << (k - 21000 + 1)) - 1;
	return frs_rand64(k, FRS_STREAM_TEST, b) % top;
}

static void radical_closed_form(void **state)
{
	static const unsigned base[3] = { 2, 3, 5 };

	(void)state;
	for (int a = 0; a < 3; a++) {
		unsigned b = base[a];
		for (uint64_t k = 0; k < 60000; k++) {
			uint64_t i = index_at(k, b);
			unsigned m;
			long double x = closed_form(i, b, &m);
			double r = num_radical_inverse(i, b);
			long double err = fabsl((long double)r - x);
			if (b == 2 && i < ((uint64_t)1 << 53))
				assert_true((long double)r == x);
			/* (m + 2) ulps of 1, and the 2^-64 of the closed form. */
			assert_true(err <= (long double)(m + 2) * 0x1p-53L + 0x1p-63L);
			assert_true(r <= 1.0);
		}
	}
	/* Hand values: 1/2, 3/8, 2/3 + 1/9, 1/5 + 4/25; 2^32 in base 2. */
	assert_true(num_radical_inverse(1, 2) == 0.5);
	assert_true(num_radical_inverse(6, 2) == 0.375);
	assert_true(fabs(num_radical_inverse(5, 3) - (2.0 / 3 + 1.0 / 9)) <
	    1e-15);
	assert_true(fabs(num_radical_inverse(21, 5) - (1.0 / 5 + 4.0 / 25)) <
	    1e-15);
	assert_true(num_radical_inverse((uint64_t)1 << 32, 2) == 0x1p-33);
	assert_true(num_radical_inverse(0, 3) == 0.0);
}

/* num_radical_inverse_n: the bits of num_radical_inverse for every
 * count (groups of 32 and tails), for indices of 1 to 32 bits (the
 * vector paths), a group with one index past 2^32 or past 2^53 (the
 * scalar ones), and a base without a vector path. */
static void radical_n_bits(void **state)
{
	enum { N = 100 };
	uint64_t idx[N];
	double r[N];
	unsigned bases[] = { 2, 3, 5 };

	(void)state;
	for (int kind = 0; kind < 3; kind++) {
		uint64_t x = 88172645463325252u;
		for (size_t q = 0; q < N; q++) {
			x ^= x << 13;
			x ^= x >> 7;
			x ^= x << 17;
			idx[q] = x >> (32 + q % 32);	/* 1 to 32 bits */
		}
		idx[3] = 0;
		idx[4] = UINT32_MAX;
		if (kind == 1)
			idx[40] = (uint64_t)1 << 32;
		if (kind == 2)
			idx[70] = ((uint64_t)1 << 53) + 1;
		for (size_t b = 0; b < 3; b++)
			for (size_t n = 0; n <= N; n += n < 40 ? 1 : 29) {
				num_radical_inverse_n(idx, n, bases[b], r);
				for (size_t q = 0; q < n; q++) {
					double o = num_radical_inverse(idx[q],
					    bases[b]);
					assert_true(memcmp(&r[q], &o, sizeof o) == 0);
				}
			}
	}
}

/* num_radical3 within 3 ulps of the exact inverse (the mirrored digits
 * as an integer over a power of 3, in long double), and
 * num_radical3_n its bits for every count, groups below 2^32 (vectors)
 * and groups with a larger index (the scalar path). */
static void radical3_table(void **state)
{
	enum { N = 100 };
	uint64_t idx[N], x = 88172645463325252u;
	double r[N];
	static const uint64_t edge[] = { 0, 1, 2, 2186, 2187, 4782968, 4782969,
	    UINT32_MAX, (uint64_t)1 << 32, ((uint64_t)1 << 40) + 5,
	    10460353202u, UINT64_MAX };

	(void)state;
	for (size_t q = 0; q < N; q++) {
		x ^= x << 13;
		x ^= x >> 7;
		x ^= x << 17;
		idx[q] = q < 12 ? edge[q] : x >> (32 + q % 32);
	}
	for (size_t q = 0; q < N; q++) {
		uint64_t m = 0, v = idx[q];
		long double den = 1.0L, exact;
		double got = num_radical3(idx[q]), ulp;
		for (; v > 0; v /= 3, den *= 3.0L)
			m = 3 * m + v % 3;
		exact = idx[q] == 0 ? 0.0L : (long double)m / den;
		if (idx[q] == UINT64_MAX)	/* m overflows: 41 digits */
			continue;
		ulp = ldexp(1.0, ilogb(got > 0 ? got : 1.0) - 52);
		assert_true(fabsl((long double)got - exact) <= 3.0L * ulp);
	}
	for (int big = 0; big < 2; big++) {
		if (big)
			idx[50] = ((uint64_t)1 << 33) + 7;	/* group 1 scalar */
		else
			for (size_t q = 0; q < 12; q++)
				idx[q] = idx[q] >> 32 ? 5 : idx[q];
		for (size_t n = 0; n <= N; n += n < 40 ? 1 : 29) {
			num_radical3_n(idx, n, r);
			for (size_t q = 0; q < n; q++) {
				double o = num_radical3(idx[q]);
				assert_true(memcmp(&r[q], &o, sizeof o) == 0);
			}
		}
	}
}

/* num_u53 is the conversion, at the edges of its two parts and between. */
static void u53_exact(void **state)
{
	uint64_t v[] = { 0, 1, ((uint64_t)1 << 52) - 1, (uint64_t)1 << 52,
	    ((uint64_t)1 << 52) + 1, ((uint64_t)1 << 53) - 1,
	    0x12345678abcdeu };

	(void)state;
	for (size_t i = 0; i < sizeof v / sizeof *v; i++)
		assert_true(num_u53(v[i]) == (double)v[i]);
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(sum_cancellations),
	cmocka_unit_test(sum_exact),
	cmocka_unit_test(radical_closed_form),
	cmocka_unit_test(radical_n_bits),
	cmocka_unit_test(radical3_table),
	cmocka_unit_test(u53_exact))
