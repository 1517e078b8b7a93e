/* Exact predicates and double-double arithmetic (discrepancy/geom.h) against
 * 128-bit integer arithmetic: the inputs are integers scaled by powers of
 * two, so the integer results are the exact ones. */
#include "testutil.h"
#include "discrepancy/geom.h"

#define SCALE 0x1p-52		/* integers of up to 52 bits into [0, 1) */

static int sgn128(__int128 v)
{
	return (v > 0) - (v < 0);
}

/* A 52-bit integer of (seed, index). */
static int64_t rnd52(uint64_t seed, uint64_t i)
{
	return (int64_t)(frs_rand64(seed, FRS_STREAM_TEST, i) >> 12);
}

/* Random triples, half of them collinear up to a unit move of p: both
 * the exact function alone and the filtered one give the sign of the
 * integer determinant; swapping a and b negates it, a cyclic shift
 * keeps it. */
static void orient_signs(void **state)
{
	(void)state;
	for (uint64_t t = 0; t < 20000; t++) {
		int64_t ax = rnd52(1, 6 * t), ay = rnd52(1, 6 * t + 1);
		int64_t bx = rnd52(1, 6 * t + 2), by = rnd52(1, 6 * t + 3);
		int64_t px = rnd52(1, 6 * t + 4), py = rnd52(1, 6 * t + 5);
		double a[2], b[2], p[2];
		__int128 det;
		int s;
		if (t % 2) {
			/* p on the line through a and a + (dx, dy) */
			int64_t dx = (bx >> 40) + 1, dy = (by >> 40) - 2048;
			int64_t q = 1 + (int64_t)(t % 4000);
			bx = ax + dx * 4001;
			by = ay + dy * 4001;
			px = ax + dx * q + (int64_t)(t % 3) - 1;
			py = ay + dy * q;
		}
		a[0] = (double)ax * SCALE, a[1] = (double)ay * SCALE;
		b[0] = (double)bx * SCALE, b[1] = (double)by * SCALE;
		p[0] = (double)px * SCALE, p[1] = (double)py * SCALE;
		det = (__int128)(bx - ax) * (py - ay) -
		    (__int128)(by - ay) * (px - ax);
		s = sgn128(det);
		assert_int_equal(geom_orient_exact(a[0], a[1], b[0], b[1], p[0],
		    p[1]), s);
		assert_int_equal(geom_orient(a[0], a[1], b[0], b[1], p[0], p[1]), s);
		assert_int_equal(geom_orient(b[0], b[1], a[0], a[1], p[0], p[1]), -s);
		assert_int_equal(geom_orient(b[0], b[1], p[0], p[1], a[0], a[1]), s);
	}
}

/* x in units of 2^-60 (|x| < 2, a multiple of 2^-60: exact). */
static __int128 units(double x)
{
	assert_true(ldexp(x, 60) == floor(ldexp(x, 60)) && fabs(x) < 2.0);
	return (__int128)ldexp(x, 60);
}

/* A point of size about 2^-25 on the grid of 2^-60, and one of 2^-30
 * within [1/4, 1). */
static double rnd_small(uint64_t i)
{
	return ldexp((double)(rnd52(13, i) >> 17), -60);
}

static double rnd_large(uint64_t i)
{
	return 0.25 + ldexp((double)(rnd52(14, i) >> 24), -30) * 0.75;
}

/* Coordinates of two scales, p on the line a -> b rounded to a double
 * and then moved by an ulp: the differences are not exact in doubles,
 * so every term of the exact sum counts. */
static void orient_mixed_scales(void **state)
{
	(void)state;
	for (uint64_t t = 0; t < 20000; t++) {
		double ax = rnd_small(4 * t), ay = rnd_small(4 * t + 1);
		double bx = rnd_large(4 * t + 2), by = rnd_large(4 * t + 3);
		double q = (double)(1 + t % 7) / 8.0;
		double px = ax + q * (bx - ax), py = ay + q * (by - ay);
		__int128 det;
		if (t % 3 == 1)
			px = nextafter(px, 2.0);
		else if (t % 3 == 2)
			py = nextafter(py, -1.0);
		det = (units(bx) - units(ax)) * (units(py) - units(ay)) -
		    (units(by) - units(ay)) * (units(px) - units(ax));
		assert_int_equal(geom_orient_exact(ax, ay, bx, by, px, py),
		    sgn128(det));
		assert_int_equal(geom_orient(ax, ay, bx, by, px, py), sgn128(det));
	}
}

/* The same for circles: a small centre, a large radius, p near the
 * circle at (0.6, 0.8) r from the centre. */
static void incircle_mixed_scales(void **state)
{
	(void)state;
	for (uint64_t t = 0; t < 20000; t++) {
		double ex = rnd_small(3 * t), ey = rnd_small(3 * t + 1);
		double r = 0.5 * rnd_large(3 * t + 2);
		double px = ex + 0.6 * r, py = ey + 0.8 * r;
		__int128 dx, dy, det;
		if (t % 3 == 1)
			px = nextafter(px, 2.0);
		else if (t % 3 == 2)
			py = nextafter(py, -1.0);
		dx = units(px) - units(ex);
		dy = units(py) - units(ey);
		det = units(r) * units(r) - dx * dx - dy * dy;
		assert_int_equal(geom_incircle_exact(ex, ey, r, px, py),
		    sgn128(det));
		assert_int_equal(geom_incircle(ex, ey, r, px, py), sgn128(det));
	}
}

/* Points on circles (Pythagorean triples), then moved by one unit, and
 * random points: the sign of r^2 - |p - e|^2 in integers. */
static void incircle_signs(void **state)
{
	static const int64_t tri[][3] = { { 3, 4, 5 }, { 5, 12, 13 },
	    { 8, 15, 17 }, { 0, 1, 1 } };

	(void)state;
	for (uint64_t t = 0; t < 20000; t++) {
		const int64_t *pt = tri[t % 4];
		int64_t k = (rnd52(2, 4 * t) >> 24) + 1;
		int64_t ex = ((int64_t)1 << 50) + (rnd52(2, 4 * t + 1) >> 2);
		int64_t ey = ((int64_t)1 << 50) + (rnd52(2, 4 * t + 2) >> 2);
		int64_t r = pt[2] * k, px, py;
		__int128 det;
		if (t % 5 == 4) {
			px = rnd52(2, 4 * t + 3);
			py = rnd52(3, t);
		} else {
			px = ex + pt[0] * k * (t & 1 ? 1 : -1) + (int64_t)(t % 3) - 1;
			py = ey + pt[1] * k * (t & 2 ? 1 : -1);
		}
		det = (__int128)r * r - (__int128)(px - ex) * (px - ex) -
		    (__int128)(py - ey) * (py - ey);
		assert_int_equal(geom_incircle_exact((double)ex * SCALE,
		    (double)ey * SCALE, (double)r * SCALE, (double)px * SCALE,
		    (double)py * SCALE), sgn128(det));
		assert_int_equal(geom_incircle((double)ex * SCALE,
		    (double)ey * SCALE, (double)r * SCALE, (double)px * SCALE,
		    (double)py * SCALE), sgn128(det));
	}
}

/* The boundary rule: a line and its reverse split every point, on the
 * line or off it, exactly once; on a circle the left half and the bottom
 * point belong to it, the right half and the top point do not. */
static void boundary_splits(void **state)
{
	(void)state;
	for (uint64_t t = 0; t < 5000; t++) {
		double ax = (double)(rnd52(4, 4 * t) >> 40) / 4096.0;
		double ay = (double)(rnd52(4, 4 * t + 1) >> 40) / 4096.0;
		double dx = (double)((int64_t)(t % 7) - 3) / 64.0;
		double dy = (double)((int64_t)(t % 5) - 2) / 64.0;
		double q = (double)(t % 9) / 8.0;
		double px = ax + q * dx, py = ay + q * dy;
		if (dx == 0.0 && dy == 0.0)
			continue;
		if (t % 4 == 3)
			py += 1.0 / 4096.0;
		assert_int_equal(geom_left(ax, ay, ax + dx, ay + dy, px, py) +
		    geom_left(ax + dx, ay + dy, ax, ay, px, py), 1);
	}
	for (int i = 0; i < 4; i++) {
		/* (3, 4, 5) points around e = (0.5, 0.5), r = 5/64 */
		double sx = i & 1 ? 1.0 : -1.0, sy = i & 2 ? 1.0 : -1.0;
		double px = 0.5 + sx * 3.0 / 64.0, py = 0.5 + sy * 4.0 / 64.0;
		assert_int_equal(geom_incircle(0.5, 0.5, 5.0 / 64.0, px, py), 0);
		assert_int_equal(geom_in_circle(0.5, 0.5, 5.0 / 64.0, px, py),
		    sx < 0);
	}
	assert_true(geom_in_circle(0.5, 0.5, 0.25, 0.5, 0.25));
	assert_false(geom_in_circle(0.5, 0.5, 0.25, 0.5, 0.75));
	assert_true(geom_edge_closed(1.0, 1.0, 0.0, 0.0));	/* downwards */
	assert_true(geom_edge_closed(0.0, 0.5, 1.0, 0.5));	/* to the right */
	assert_false(geom_edge_closed(1.0, 0.5, 0.0, 0.5));
	assert_false(geom_edge_closed(0.0, 0.0, 0.0, 1.0));
}

/* The exact value of a double-double whose parts are integers. */
static __int128 dd_int(struct dd a)
{
	assert_true(a.hi == floor(a.hi) && a.lo == floor(a.lo));
	assert_true(fabs(a.lo) <= 0.5 * (nextafter(fabs(a.hi), INFINITY) -
	    fabs(a.hi)));
	return (__int128)a.hi + (__int128)a.lo;
}

/* A double-double of an integer below 2^100 in magnitude (exact: 53 +
 * 47 bits). */
static struct dd dd_of(__int128 v)
{
	double hi = (double)v;
	return dd_two_sum(hi, (double)(v - (__int128)hi));
}

static __int128 rnd_int(uint64_t seed, uint64_t i, int bits)
{
	unsigned __int128 u = ((unsigned __int128)frs_rand64(seed,
	    FRS_STREAM_TEST, 2 * i) << 64) | frs_rand64(seed, FRS_STREAM_TEST,
	    2 * i + 1);
	__int128 v = (__int128)(u >> (128 - bits));
	return i % 2 ? -v : v;
}

static double rel_err(__int128 exact, __int128 got)
{
	__int128 d = exact - got;
	return exact == 0 ? (double)d : fabs((double)d / (double)exact);
}

/* two_sum and prod are exact; add and mul of double-doubles within
 * 2^-100 of the exact results (about 106 bits); div_d within 2^-100 of
 * the quotient. */
static void dd_arithmetic(void **state)
{
	(void)state;
	for (uint64_t t = 0; t < 20000; t++) {
		__int128 a = rnd_int(5, t, 53), b = rnd_int(6, t, 20 + t % 33);
		__int128 x = rnd_int(7, t, 99), y = rnd_int(8, t, 60);
		__int128 z = rnd_int(9, t, 99), c = rnd_int(10, t, 40) | 1;
		struct dd s, q;
		double fa = (double)a, fb = (double)b;

		s = dd_two_sum(fa, fb);
		assert_true(dd_int(s) == a + b);
		assert_true(s.hi == fa + fb);
		s = dd_prod((double)(a >> 1), fb);
		assert_true(dd_int(s) == (a >> 1) * b);
		assert_true(dd_int(dd_from(fa)) == a);
		assert_true(dd_value(dd_of(x)) == (double)x);
		assert_true(rel_err(x + z, dd_int(dd_add(dd_of(x), dd_of(z)))) <=
		    0x1p-100);
		assert_true(rel_err(x + a, dd_int(dd_add_d(dd_of(x), fa))) <=
		    0x1p-100);
		y >>= 1;
		assert_true(rel_err(y * (y >> 20),
		    dd_int(dd_mul(dd_of(y), dd_of(y >> 20)))) <= 0x1p-100);
		assert_true(rel_err((x >> 40) * b, dd_int(dd_mul_d(dd_of(x >> 40),
		    fb))) <= 0x1p-100);
		/* q c = c k + r, |k| >= 2^57 so that q.hi is a whole number:
		 * the residual's integer part in integers, the rest by one
		 * fma */
		{
			__int128 k = rnd_int(11, t, 56), r = rnd_int(12, t, 30) % c;
			__int128 num;
			k += k < 0 ? -((__int128)1 << 57) : (__int128)1 << 57;
			num = c * k + r;
			double cd = (double)c;
			q = dd_div_d(dd_of(num), cd);
			assert_true(q.hi == floor(q.hi));
			assert_true(fabs(fma(-q.lo, cd, (double)(num -
			    (__int128)q.hi * c))) <= ldexp(fabs((double)num), -100));
		}
	}
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(orient_signs),
	cmocka_unit_test(incircle_signs),
	cmocka_unit_test(orient_mixed_scales),
	cmocka_unit_test(incircle_mixed_scales),
	cmocka_unit_test(boundary_splits),
	cmocka_unit_test(dd_arithmetic))
