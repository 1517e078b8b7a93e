/*
 * Hierarchical Sample Warping, the numerical hard cases: importance from
 * 1e-30 to 1e30, denormals, values near FLT_MAX and DBL_MAX (whose sums
 * overflow), a single pixel in a 2048^2 map, 1x1 maps and strips,
 * non-finite pixels.  The oracles:
 *   - the warp of a constant power-of-two map is the identity (hsw(1));
 *   - with one pixel of positive importance every split sends the point
 *     to it with its coordinate unchanged, so a point lands at
 *     ((i + u) / W, (j + v) / H) for its input (u, v);
 *   - the points of a pixel are those of the input in one box of the
 *     input square (each split cuts an interval), whose area is the
 *     pixel's share: for Hammersley input of n points a box holds its
 *     area times n within 4 (log2 n + 1), four times a bound of the star
 *     discrepancy of the set.
 */
#include "testutil.h"
#include "hard.h"
#include "sample/hsw.h"

#include <float.h>

/* Warp n points of input kind over map; the output, checked to be finite
 * and in [0,1)^2 and on pixels of positive importance (counted in in). */
static double *warp(const struct frs_imap *m, uint64_t n,
    enum hsw_input kind, double *in)
{
	struct hsw_tree t;
	double *p = malloc(2 * n * sizeof *p);

	assert_non_null(p);
	if (hsw_build(&t, m) != 0)
		print_error("hsw_build: %s\n", frs_errmsg());
	assert_non_null(t.sum);
	hsw_input_make(kind, n, 1, p);
	assert_int_equal(hsw_warp_points(&t, p, p, n), 0);
	hsw_free(&t);
	for (uint64_t i = 0; i < n; i++) {
		double x = p[2 * i], y = p[2 * i + 1];
		uint64_t px, py;
		assert_true(isfinite(x) && isfinite(y));
		assert_true(x >= 0 && x < 1 && y >= 0 && y < 1);
		px = (uint64_t)(x * m->w);
		py = (uint64_t)(y * m->h);
		assert_true(m->v[py * m->w + px] > 0);
		if (in != NULL)
			in[py * m->w + px] += 1;
	}
	return p;
}

/* The Hammersley bound of a box of the given share. */
static void box_ok(const char *what, double got, double n, double share)
{
	double tol = 4.0 * (log2(n) + 1.0);

	print_message("%s: %.0f, expected %.6g +- %.3g\n", what, got, n * share,
	    tol);
	if (!(fabs(got - n * share) <= tol)) {
		print_error("%s: %.0f points, expected %.17g\n", what, got,
		    n * share);
		fail();
	}
}

/* Hammersley points over map: each region of mask against its share. */
static void shares_ok(const char *what, const struct frs_imap *m,
    const unsigned char *mask, uint64_t n)
{
	double *in = calloc((size_t)m->w * m->h, sizeof *in), got = 0;

	assert_non_null(in);
	free(warp(m, n, HSW_HAMMERSLEY, in));
	for (uint64_t i = 0; i < (uint64_t)m->w * m->h; i++)
		got += mask[i] ? in[i] : 0;
	box_ok(what, got, (double)n, hd_share(m, mask));
	free(in);
}

/* The warp of map is the identity on n points of every input kind. */
static void identity_ok(const struct frs_imap *m, uint64_t n)
{
	double *in = malloc(2 * n * sizeof *in);

	assert_non_null(in);
	for (int k = HSW_RANDOM; k <= HSW_HAMMERSLEY; k++) {
		double *out = warp(m, n, (enum hsw_input)k, NULL);
		hsw_input_make((enum hsw_input)k, n, 1, in);
		for (uint64_t i = 0; i < 2 * n; i++)
			if (!(fabs(out[i] - in[i]) <= 1e-12)) {
				print_error("input %d, coordinate %llu: %.17g -> "
				    "%.17g\n", k, (unsigned long long)i, in[i],
				    out[i]);
				fail();
			}
		free(out);
	}
	free(in);
}

/* ---- extreme ranges -------------------------------------------------- */

/*
 * The map of test_hard_frs: every decade from 1e-30 to 1e20 on the left
 * half (a share of 1.6e-7), 1e30 and 2.5e29 on the right quadrants.  The
 * root's split sends x < 1.6e-7 left; the smallest Hammersley x is
 * 0.5 / n, so no point goes there.
 */
static void extreme_range(void **state)
{
	struct frs_imap m;
	unsigned char tr[4096], br[4096];
	double *in = calloc(4096, sizeof *in), nl = 0;
	const uint64_t n = 8192;
	(void)state;

	assert_int_equal(imap_alloc(&m, 64, 64), 0);
	for (uint32_t j = 0; j < 64; j++)
		for (uint32_t i = 0; i < 64; i++) {
			uint32_t k = j * 64 + i;
			tr[k] = i >= 32 && j < 32;
			br[k] = i >= 32 && j >= 32;
			m.v[k] = i < 32 ? pow(10.0, -30.0 + (j * 32 + i) % 51) :
			    tr[k] ? 1e30 : 2.5e29;
		}
	free(warp(&m, n, HSW_HAMMERSLEY, in));
	for (uint32_t k = 0; k < 4096; k++)
		nl += k % 64 < 32 ? in[k] : 0;
	assert_true(nl == 0);
	shares_ok("1e30 quadrant", &m, tr, n);
	shares_ok("2.5e29 quadrant", &m, br, n);
	free(in);
	imap_free(&m);
}

/*
 * One pixel of 1e-20 in a 2048x2048 map: every point in it, at its
 * input's place inside the pixel.
 */
static void single_pixel_large_map(void **state)
{
	struct frs_imap m;
	const uint64_t n = 5000, px = 1234, py = 1717;
	double *out, *in = malloc(2 * n * sizeof *in);
	(void)state;

	hd_map(&m, 2048, 2048, 0.0);
	m.v[py * 2048 + px] = 1e-20;
	out = warp(&m, n, HSW_HALTON, NULL);
	hsw_input_make(HSW_HALTON, n, 1, in);
	for (uint64_t i = 0; i < n; i++) {
		assert_near(out[2 * i] * 2048 - (double)px, in[2 * i], 1e-9);
		assert_near(out[2 * i + 1] * 2048 - (double)py, in[2 * i + 1],
		    1e-9);
	}
	free(in);
	free(out);
	imap_free(&m);
}

/*
 * Almost everything tiny: 65535 pixels of 1e-3 and one of 1 (a share of
 * 1/66.535), and 1e-12 everywhere but a 4x4 block of 1 (nothing
 * outside: the rest has a share of 4e-9, and a point would need a
 * coordinate below about 1e-9 at some split).
 */
static void almost_all_tiny(void **state)
{
	struct frs_imap m;
	unsigned char *mask = calloc(65536, 1);
	double *in = calloc(65536, sizeof *in), out = 0;
	const uint64_t n = 16384;
	(void)state;

	hd_map(&m, 256, 256, 1e-3);
	m.v[77 * 256 + 201] = 1.0;
	mask[77 * 256 + 201] = 1;
	shares_ok("one pixel of 1 among 1e-3", &m, mask, n);
	for (uint32_t k = 0; k < 65536; k++) {
		uint32_t i = k % 256, j = k / 256;
		mask[k] = j >= 37 && j < 41 && i >= 100 && i < 104;
		m.v[k] = mask[k] ? 1.0 : 1e-12;
	}
	/* Halton: the first Hammersley point has y = 0, which every split
	 * sends to its top part however small, here row 0 */
	free(warp(&m, n, HSW_HALTON, in));
	for (uint32_t k = 0; k < 65536; k++)
		out += mask[k] ? 0 : in[k];
	assert_true(out == 0);
	free(in);
	free(mask);
	imap_free(&m);
}

/* ---- denormals and huge values ----------------------------------------- */

/* Left half a, right half b, Hammersley shares. */
static void halves(const char *what, double a, double b)
{
	struct frs_imap m;
	unsigned char mask[64 * 64];

	assert_int_equal(imap_alloc(&m, 64, 64), 0);
	for (uint32_t k = 0; k < 64 * 64; k++) {
		mask[k] = k % 64 < 32;
		m.v[k] = mask[k] ? a : b;
	}
	shares_ok(what, &m, mask, 8192);
	imap_free(&m);
}

/*
 * Denormal sums have few bits: with 2^-1074 everywhere the split u (a +
 * b) < a rounded u to a multiple of 1/2 and sent 3/4 of the points to one
 * side.  The map is scaled by a power of two first, so the constant maps
 * are the identity again.
 */
static void denormals(void **state)
{
	struct frs_imap m;
	(void)state;

	hd_map(&m, 64, 64, 0x1p-1074);
	identity_ok(&m, 5000);
	imap_free(&m);
	hd_map(&m, 64, 64, FLT_TRUE_MIN);
	identity_ok(&m, 5000);
	imap_free(&m);
	halves("double denormals 1:2", 0x1p-1074, 0x1p-1073);
	halves("double denormals 3:5", 0x3p-1074, 0x5p-1074);
	halves("float denormals 1:2", FLT_TRUE_MIN, 2.0 * FLT_TRUE_MIN);
}

/* Sums of 4096 values near DBL_MAX overflowed to infinity, and every
 * split gave NaN. */
static void huge_values(void **state)
{
	struct frs_imap m;
	struct hsw_tree t;
	(void)state;

	hd_map(&m, 64, 64, DBL_MAX);
	identity_ok(&m, 5000);
	/* the total is the map's sum: here beyond DBL_MAX */
	assert_int_equal(hsw_build(&t, &m), 0);
	assert_true(isinf(t.total));
	hsw_free(&t);
	imap_free(&m);
	hd_map(&m, 64, 64, FLT_MAX);
	identity_ok(&m, 5000);
	assert_int_equal(hsw_build(&t, &m), 0);
	assert_near(t.total / (4096.0 * FLT_MAX), 1.0, 1e-15);
	hsw_free(&t);
	imap_free(&m);
	halves("1e308 2:1", 1e308, 5e307);
	halves("FLT_MAX 1:3", FLT_MAX / 3, FLT_MAX);
	halves("DBL_MAX and 1e-300", DBL_MAX, 1e-300);
}

/* ---- degenerate maps --------------------------------------------------- */

/* NaN and infinity are refused by name; an all-zero map too; negative
 * values count as zero. */
static void degenerate(void **state)
{
	struct frs_imap m;
	struct hsw_tree t;
	double *in = calloc(64, sizeof *in);
	(void)state;

	hd_map(&m, 8, 8, 1.0);
	m.v[2 * 8 + 5] = NAN;
	assert_int_equal(hsw_build(&t, &m), -1);
	assert_err_has("pixel (5, 2)", "NaN");
	m.v[2 * 8 + 5] = -INFINITY;
	assert_int_equal(hsw_build(&t, &m), -1);
	assert_err_has("pixel (5, 2)", "infinite");
	m.v[2 * 8 + 5] = INFINITY;
	assert_int_equal(hsw_build(&t, &m), -1);
	assert_err_has("pixel (5, 2)", "infinite");
	for (int k = 0; k < 64; k++)
		m.v[k] = k % 3 ? -1.0 : -0.0;
	assert_int_equal(hsw_build(&t, &m), -1);
	assert_err_has("zero everywhere");
	m.v[9] = 1e-300;
	free(warp(&m, 1000, HSW_RANDOM, in));
	assert_true(in[9] == 1000);
	free(in);
	imap_free(&m);
}

/*
 * 1x1: the identity.  Strips: 1x3 (1, 2, 5) pads to 4x4, 5x1 (1, 0, 3,
 * 0, 4) to 8x8, 1x1024 (a ramp) to 1024x1024: each pixel's share, no
 * point in the padding (warp checks that every point lies on the map).
 */
/* Each pixel's share of n points on the w x h map of values v. */
static void pixel_shares_ok(const char *what, uint32_t w, uint32_t h,
    const double *v, uint64_t n)
{
	struct frs_imap m;
	unsigned char *mask = calloc((size_t)w * h, 1);
	assert_non_null(mask);
	assert_int_equal(imap_alloc(&m, w, h), 0);
	memcpy(m.v, v, (size_t)w * h * sizeof *v);
	for (size_t k = 0; k < (size_t)w * h; k++) {
		mask[k] = 1;
		shares_ok(what, &m, mask, n);
		mask[k] = 0;
	}
	imap_free(&m);
	free(mask);
}

static void tiny_maps(void **state)
{
	static const double col[3] = { 1, 2, 5 }, row[5] = { 1, 0, 3, 0, 4 };
	struct frs_imap m;
	unsigned char mask[1024];
	const uint64_t n = 8192;
	(void)state;

	hd_map(&m, 1, 1, 0.3);
	identity_ok(&m, 3000);
	imap_free(&m);
	pixel_shares_ok("1x3: pixel", 1, 3, col, n);
	pixel_shares_ok("5x1: pixel", 5, 1, row, n);
	assert_int_equal(imap_alloc(&m, 1, 1024), 0);
	for (int k = 0; k < 1024; k++) {
		m.v[k] = 1.0 + k;
		mask[k] = k < 300;
	}
	shares_ok("1x1024: top 300 rows", &m, mask, n);
	imap_free(&m);
}

/*
 * Inputs at the corners of the unit square, 0 and 1 - 2^-53, through maps
 * of odd sizes and extreme values: (i + u) / W rounds up to the next
 * pixel or to 1 unless the warp keeps it inside; every output must lie
 * in [0,1)^2 on a pixel of positive importance, and a constant map
 * (padded or not) keeps the corners in the corner pixels.  With only the
 * last pixel positive every split is one-sided and keeps u = 1 - 2^-53
 * as it is, and (W - 1 + u) / W rounds to 1.
 */
static void edge_inputs(void **state)
{
	static const uint32_t sz[][2] = { { 1, 1 }, { 3, 1 }, { 1, 7 },
	    { 100, 60 }, { 255, 257 }, { 64, 64 } };
	const double e = 0x1.fffffffffffffp-1;
	double in[2 * 8] = { 0, 0, e, e, e, 0, 0, e, 0.5, e, e, 0.5,
	    0x1p-60, e, e, 0x1p-60 }, out[2 * 8];
	(void)state;

	for (size_t k = 0; k < sizeof sz / sizeof *sz; k++)
		for (int v = 0; v < 4; v++) {
			struct frs_imap m;
			struct hsw_tree t;
			hd_map(&m, sz[k][0], sz[k][1], v == 0 ? 1.0 : v == 1 ?
			    0x1p-1074 : 1e308);
			if (v == 2)
				m.v[0] = 1e-300;	/* a pixel that takes nothing */
			if (v == 3) {
				for (size_t i = 0; i < (size_t)m.w * m.h; i++)
					m.v[i] = 0.0;
				m.v[(size_t)m.w * m.h - 1] = 3.0;
			}
			assert_int_equal(hsw_build(&t, &m), 0);
			assert_int_equal(hsw_warp_points(&t, in, out, 8), 0);
			for (int i = 0; i < 8; i++) {
				double x = out[2 * i], y = out[2 * i + 1];
				uint32_t px = (uint32_t)(x * m.w), py = (uint32_t)(y * m.h);
				assert_true(x >= 0 && x < 1 && y >= 0 && y < 1);
				assert_true(m.v[(size_t)py * m.w + px] > 0);
				if (v < 2 && i < 4) {
					assert_int_equal(px, in[2 * i] > 0.5 ? m.w - 1 : 0);
					assert_int_equal(py, in[2 * i + 1] > 0.5 ? m.h - 1 : 0);
				}
			}
			hsw_free(&t);
			imap_free(&m);
		}
}

TU_MAIN(hd_two_threads, tu_teardown,
	cmocka_unit_test(extreme_range),
	cmocka_unit_test(single_pixel_large_map),
	cmocka_unit_test(almost_all_tiny),
	cmocka_unit_test(denormals),
	cmocka_unit_test(huge_values),
	cmocka_unit_test(degenerate),
	cmocka_unit_test(tiny_maps),
	cmocka_unit_test(edge_inputs))
