/*
 * Forced Random Sampling, the numerical hard cases: importance from
 * 1e-30 to 1e30, double and float denormals, values near FLT_MAX and
 * DBL_MAX, a single bright pixel in a 2048^2 map, counts up to 2^34 (the
 * thesis authors' code lost every sample at 2^24 to a 32-bit product),
 * and degenerate maps.  The oracles: closed forms of the setup (Listing
 * 5.1 in long double), exact counts where the window covers whole matrix
 * tiles (each tile then gives floor(T) values and one coin), binomial
 * bounds for the share of a region, and invariance under scaling the map
 * by a power of two (only ratios of the importance matter).
 */
#include "testutil.h"
#include "frsutil.h"
#include "hard.h"
#include "maps/exrio.h"

#include <float.h>

/* ---- helpers ------------------------------------------------------- */

/* |count - n| within 5 standard deviations of a Poisson count. */
static void total_ok(const char *what, uint64_t count, uint64_t n)
{
	print_message("%s: %llu samples for n = %llu\n", what,
	    (unsigned long long)count, (unsigned long long)n);
	if (!(fabs((double)count - (double)n) <= 5.0 * sqrt((double)n) + 2.0)) {
		print_error("%s: %llu samples for n = %llu\n", what,
		    (unsigned long long)count, (unsigned long long)n);
		fail();
	}
}

/* Sample map and check every point; per-pixel counts into a new array. */
static double *sample_counts(const struct frs_imap *map,
    const struct frs_matrix *m, uint64_t n, uint64_t seed,
    struct frs_setup *s, uint64_t *count)
{
	struct frs_result r;
	double *in = calloc((size_t)map->w * map->h, sizeof *in);

	assert_non_null(in);
	hd_frs(map, m, n, seed, FRS_SORTED, 0, s, &r);
	assert_true(isfinite(s->tau) && s->tau > 0);
	hd_points(s, map, &r, in);
	*count = r.count;
	frs_result_free(&r);
	return in;
}

/* Samples on the pixels of mask, against the mask's share. */
static void region_ok(const char *what, const struct frs_imap *map,
    const double *in, const unsigned char *mask, uint64_t count)
{
	double got = 0;

	for (uint64_t i = 0; i < (uint64_t)map->w * map->h; i++)
		got += mask[i] ? in[i] : 0;
	hd_binom(what, got, (double)count, hd_share(map, mask));
}

/* ---- extreme importance ranges ------------------------------------- */

/*
 * 64x64: the left half holds every decade from 1e-30 to 1e20, the top
 * right quadrant 1e30, the bottom right 2.5e29 (4:1).  The left half has
 * a share of 1.6e-7 (0.003 samples expected of 20000): at most one may
 * land there; the right quadrants split 4:1.
 */
static void extreme_range(void **state)
{
	struct frs_matrix m;
	struct frs_imap map;
	struct frs_setup s;
	unsigned char left[4096], tr[4096], br[4096];
	uint64_t count;
	double *in, nl = 0;
	(void)state;

	tu_perm_matrix(&m, 256, 256, 11);
	assert_int_equal(imap_alloc(&map, 64, 64), 0);
	for (uint32_t j = 0; j < 64; j++)
		for (uint32_t i = 0; i < 64; i++) {
			uint32_t k = j * 64 + i;
			left[k] = i < 32;
			tr[k] = i >= 32 && j < 32;
			br[k] = i >= 32 && j >= 32;
			map.v[k] = left[k] ? pow(10.0, -30.0 + (j * 32 + i) % 51) :
			    tr[k] ? 1e30 : 2.5e29;
		}
	in = sample_counts(&map, &m, 20000, 3, &s, &count);
	total_ok("1e-30..1e30: count", count, 20000);
	for (int k = 0; k < 4096; k++)
		nl += left[k] ? in[k] : 0;
	print_message("left half (1e-30..1e20): %.0f samples\n", nl);
	assert_true(nl <= 1);
	region_ok("1e30 quadrant", &map, in, tr, count);
	region_ok("2.5e29 quadrant", &map, in, br, count);
	free(in);
	imap_free(&map);
	frd_free(&m);
}

/*
 * One pixel of 1e-20 in a 2048x2048 map of zeros, n = 5000, a 256^2
 * matrix.  Listing 5.1: max/mean = 2^22, w_min = ceil(8 sqrt(5000 2^22))
 * = 1158524, n_s = 1024, the window 2^21 a side, and the pixel's
 * threshold T = n S_M^2 / n_s^2 = 312.5 over (1024/256)^2 = 16 whole
 * tiles: 16 * 312 samples plus 16 coins, 4992 to 5008, every one inside
 * the pixel.  Naive finds the same elements.
 */
static void single_pixel_large_map(void **state)
{
	struct frs_matrix m;
	struct frs_imap map;
	struct frs_setup s;
	struct frs_result r, nv;
	double *in;
	uint64_t count;
	(void)state;

	tu_perm_matrix(&m, 256, 256, 12);
	hd_map(&map, 2048, 2048, 0.0);
	map.v[(size_t)1717 * 2048 + 1234] = 1e-20;
	in = sample_counts(&map, &m, 5000, 4, &s, &count);
	assert_int_equal(s.ns, 1024);
	assert_true(s.sw == (uint64_t)1 << 21 && s.sh == (uint64_t)1 << 21);
	assert_near(s.tau * 1e-20, 312.5, 1e-9);
	print_message("single pixel: %llu samples\n", (unsigned long long)count);
	assert_true(count >= 4992 && count <= 5008);
	assert_true(in[(size_t)1717 * 2048 + 1234] == (double)count);
	free(in);
	hd_frs(&map, &m, 5000, 4, FRS_SORTED, 0, &s, &r);
	hd_frs(&map, &m, 5000, 4, FRS_NAIVE, 0, &s, &nv);
	tu_same_set(&r, &nv);
	frs_result_free(&r);
	frs_result_free(&nv);
	imap_free(&map);
	frd_free(&m);
}

/*
 * Almost everything tiny.  (a) 256x256 of 1e-12 with a 4x4 block of 1:
 * the tiny part has a share of 4e-9, no sample may land there.  (b)
 * 65535 pixels of 1e-3 and one of 1: together the dim pixels outweigh it
 * 65.5 to 1.  With n_s = 256 = S_M every pixel covers one whole tile, so
 * the bright pixel gets floor(T) or floor(T) + 1 samples, T = n / 66.535.
 */
static void almost_all_tiny(void **state)
{
	struct frs_matrix m;
	struct frs_imap map;
	struct frs_setup s;
	uint64_t count, hot = (uint64_t)77 * 256 + 201;
	long double t;
	double *in, out = 0;
	(void)state;

	tu_perm_matrix(&m, 256, 256, 13);
	hd_map(&map, 256, 256, 1e-12);
	for (uint32_t j = 37; j < 41; j++)
		for (uint32_t i = 100; i < 104; i++)
			map.v[j * 256 + i] = 1.0;
	in = sample_counts(&map, &m, 5000, 5, &s, &count);
	total_ok("4x4 block among 1e-12: count", count, 5000);
	for (uint32_t j = 0; j < 256; j++)
		for (uint32_t i = 0; i < 256; i++)
			if (!(j >= 37 && j < 41 && i >= 100 && i < 104))
				out += in[j * 256 + i];
	assert_true(out == 0);
	free(in);
	imap_free(&map);

	hd_map(&map, 256, 256, 1e-3);
	map.v[hot] = 1.0;
	in = sample_counts(&map, &m, 20000, 6, &s, &count);
	assert_int_equal(s.ns, 256);
	total_ok("one pixel among 1e-3: count", count, 20000);
	t = 20000.0L / (1.0L + 65535.0L * (long double)1e-3);
	print_message("bright pixel: %.0f samples, T = %.6Lf\n", in[hot], t);
	assert_true(in[hot] == floorl(t) || in[hot] == floorl(t) + 1);
	free(in);
	imap_free(&map);
	frd_free(&m);
}

/*
 * Denormals.  Float denormals are normal doubles; double denormals
 * (2^-1074 and 2^-1073) made tau = n S_M^2 / (S_W^2 mean) overflow to
 * infinity, and every window element passed.  Halves in the ratio 1:2,
 * and a constant map of 2^-1074 that must give the elements of the
 * constant map of 1 (scaling by a power of two changes no threshold).
 */
static void halves(const char *what, const struct frs_matrix *m, double a,
    double b)
{
	struct frs_imap map;
	struct frs_setup s;
	unsigned char mask[64 * 64];
	uint64_t count;
	double *in;

	assert_int_equal(imap_alloc(&map, 64, 64), 0);
	for (uint32_t k = 0; k < 64 * 64; k++) {
		mask[k] = k % 64 < 32;
		map.v[k] = mask[k] ? a : b;
	}
	in = sample_counts(&map, m, 10000, 7, &s, &count);
	total_ok(what, count, 10000);
	region_ok(what, &map, in, mask, count);
	free(in);
	imap_free(&map);
}

/* The elements of const v and const 1 are the same. */
static void same_as_const1(const struct frs_matrix *m, double v,
    uint64_t n, uint64_t want)
{
	struct frs_imap a, b;
	struct frs_setup sa, sb;
	struct frs_result ra, rb;

	hd_map(&a, 128, 128, v);
	hd_map(&b, 128, 128, 1.0);
	hd_frs(&a, m, n, 8, FRS_SORTED, 0, &sa, &ra);
	hd_frs(&b, m, n, 8, FRS_SORTED, 0, &sb, &rb);
	print_message("const %g: %llu samples, const 1: %llu\n", v,
	    (unsigned long long)ra.count, (unsigned long long)rb.count);
	assert_true(isfinite(sa.tau));
	assert_true(rb.count == want);
	assert_true(ra.count == rb.count);
	for (uint64_t c = 0; c < ra.nchunk; c++)
		assert_memory_equal(ra.chunk[c].e, rb.chunk[c].e,
		    ra.chunk[c].n * sizeof *ra.chunk[c].e);
	hd_points(&sa, &a, &ra, NULL);
	frs_result_free(&ra);
	frs_result_free(&rb);
	imap_free(&a);
	imap_free(&b);
}

static void denormals(void **state)
{
	struct frs_matrix m;
	struct frs_imap map;
	struct frs_setup s;
	uint64_t count;
	double *in;
	(void)state;

	tu_perm_matrix(&m, 256, 256, 14);
	halves("float denormals 1:2", &m, FLT_TRUE_MIN, 2.0 * FLT_TRUE_MIN);
	halves("double denormals 1:2", &m, 0x1p-1074, 0x1p-1073);
	halves("denormal and normal 1:3", &m, 0x1p-1060, 0x3p-1060);
	/* n = 1024 at 128^2, n_s 2: one 256^2 tile, T = 1024 exactly */
	same_as_const1(&m, 0x1p-1074, 1024, 1024);
	same_as_const1(&m, FLT_TRUE_MIN, 1024, 1024);
	/* one pixel of 1 among denormals: all samples on it */
	hd_map(&map, 64, 64, 0x1p-1074);
	map.v[100] = 1.0;
	in = sample_counts(&map, &m, 3000, 9, &s, &count);
	total_ok("1 among denormals", count, 3000);
	assert_true(in[100] == (double)count);
	free(in);
	imap_free(&map);
	frd_free(&m);
}

/* Near FLT_MAX and DBL_MAX: a double sum of 4096 values of 1e308
 * overflows; only the ratios matter. */
static void huge_values(void **state)
{
	struct frs_matrix m;
	(void)state;

	tu_perm_matrix(&m, 256, 256, 15);
	halves("FLT_MAX 2:1", &m, FLT_MAX, FLT_MAX / 2);
	halves("1e308 2:1", &m, 1e308, 5e307);
	halves("DBL_MAX and 1 (1 gets nothing)", &m, DBL_MAX, 1.0);
	same_as_const1(&m, 0x1p1023, 1024, 1024);
	same_as_const1(&m, (double)FLT_MAX, 1024, 1024);
	frd_free(&m);
}

/* ---- huge counts and 64-bit window math ----------------------------- */

/*
 * Listing 5.1 in long double against frs_setup, n = 2^0 .. 2^40 and up to
 * 2^63, for a square, a peaked and a 1x4096 map with a 2048^2 matrix
 * (setup reads only the matrix's size): n_s the smallest power of two
 * with n_s * side >= w_min, tau = n S_M^2 / (S_W^2 mean) finite and
 * exact to 1e-12.  At the maximum T = S_M^2 X / (n_s side)^2, X = n m /
 * (mu a), so that n_s side >= w_min >= sigma sqrt X gives T <= S_M^2 /
 * sigma^2, and (n_s / 2) side < w_min < q + 1, q = sigma sqrt X, gives T
 * > S_M^2 / (4 sigma^2) (q / (q + 1))^2 once n_s > 1.  Offsets are
 * multiples of min(n_s, S_M).  A window past 2^31 elements per pixel side
 * is refused, by name.
 */
static void setup_closed_form(const struct frs_imap *map, uint64_t n)
{
	struct frs_matrix m = { .dims = 2, .w = 2048, .h = 2048, .d = 1,
	    .n = (size_t)2048 * 2048 };
	struct frs_imap_stats st;
	struct frs_setup s;
	long double x, q, tau, tmax, cap = 2048.0L * 2048 / 64;
	uint32_t small = map->w < map->h ? map->w : map->h;
	uint32_t large = map->w < map->h ? map->h : map->w;
	uint64_t ns = 1, u;

	imap_stats(map, &st);
	x = (long double)n * st.max / (st.mean * ((long double)large / small));
	q = 8.0L * sqrtl(x);
	while ((long double)ns * small < ceill(q))
		ns *= 2;
	if (ns > (uint64_t)1 << 31) {
		assert_int_equal(frs_setup(&s, map, &m, n, 8.0, n + 1), -1);
		assert_err_has("2^31");
		return;
	}
	assert_int_equal(frs_setup(&s, map, &m, n, 8.0, n + 1), 0);
	assert_true(s.ns == ns);
	assert_true(s.sw == ns * map->w && s.sh == ns * map->h);
	tau = (long double)n * 2048 * 2048 / ((long double)s.sw * s.sh *
	    st.mean);
	assert_true(isfinite(s.tau) && s.tau > 0);
	assert_true(fabsl(s.tau / tau - 1) < 1e-12L);
	tmax = tau * st.max;
	assert_true(tmax <= cap * (1 + 1e-12L));
	assert_true(ns == 1 || tmax > cap / 4 * (q / (q + 1)) * (q / (q + 1)));
	u = ns < 2048 ? ns : 2048;
	assert_true(s.wx % u == 0 && s.wx < 2048 && s.wy % u == 0 &&
	    s.wy < 2048);
	assert_int_equal(s.level0, ns < 8 ? (unsigned)log2((double)ns) : 3);
}

static void huge_setup(void **state)
{
	static const char *specs[] = { "const", "blob:sigma=0.02",
	    "ramp:from=1,to=5,angle=90", "const" };
	static const uint32_t sz[][2] = { { 128, 128 }, { 128, 128 },
	    { 1, 4096 }, { 1, 1 } };
	(void)state;

	for (int k = 0; k < 4; k++) {
		struct frs_imap map;
		tu_map_of(specs[k], sz[k][0], sz[k][1], &map);
		for (unsigned e = 0; e <= 63; e++)
			setup_closed_form(&map, (uint64_t)1 << e);
		setup_closed_form(&map, ((uint64_t)1 << 24) + 1);
		setup_closed_form(&map, UINT64_MAX);
		imap_free(&map);
	}
}

/* The limit itself: a 1x1 map needs n_s = 2^31 at n = 2^56 (w_min =
 * 8 2^28) and one step more at 2^56 + 2^40 (2^56 + 1 is 2^56 in
 * double). */
static void huge_setup_limit(void **state)
{
	struct frs_matrix m = { .dims = 2, .w = 2048, .h = 2048, .d = 1,
	    .n = (size_t)2048 * 2048 };
	struct frs_imap map;
	struct frs_setup s;
	(void)state;

	hd_map(&map, 1, 1, 1.0);
	assert_int_equal(frs_setup(&s, &map, &m, (uint64_t)1 << 56, 8.0, 1), 0);
	assert_true(s.ns == (uint64_t)1 << 31);
	assert_int_equal(frs_setup(&s, &map, &m, ((uint64_t)1 << 56) +
	    ((uint64_t)1 << 40), 8.0, 1), -1);
	assert_err_has("2^31");
	imap_free(&map);
}

/*
 * Counts without points, 512^2 matrix, constant 128^2 map: n = 2^24 has
 * n_s = 256 and T = 2^24 2^18 / 2^30 = 4096, n = 2^30 and 2^34 have
 * windows of whole tiles with T = 4096 again: the count is n exactly.
 * A blob at 2^24 is within 5 sqrt(n).  The window of 2^34 is 2^20 a side,
 * 2^40 elements.
 */
static void huge_counts(void **state)
{
	static const unsigned ex[] = { 24, 30, 34 };
	struct frs_matrix m;
	struct frs_imap map;
	struct frs_setup s;
	struct frs_result r;
	uint64_t n;
	(void)state;

	tu_perm_matrix(&m, 512, 512, 16);
	hd_map(&map, 128, 128, 1.0);
	for (int k = 0; k < 3; k++) {
		n = (uint64_t)1 << ex[k];
		hd_frs(&map, &m, n, 17, FRS_SORTED, 1, &s, &r);
		print_message("const, n = 2^%u: %llu, tau %.17g\n", ex[k],
		    (unsigned long long)r.count, s.tau);
		assert_true(isfinite(s.tau));
		assert_near(s.tau, 4096.0, 1e-9);
		assert_true(r.count == n);
		frs_result_free(&r);
	}
	imap_free(&map);
	tu_map_of("blob", 128, 128, &map);
	n = (uint64_t)1 << 24;
	hd_frs(&map, &m, n, 18, FRS_SORTED, 1, &s, &r);
	total_ok("blob, n = 2^24", r.count, n);
	frs_result_free(&r);
	/* Points at 2^20: every one finite and inside its pixel. */
	n = (uint64_t)1 << 20;
	hd_frs(&map, &m, n, 19, FRS_SORTED, 0, &s, &r);
	total_ok("blob, n = 2^20, points", r.count, n);
	hd_points(&s, &map, &r, NULL);
	frs_result_free(&r);
	imap_free(&map);
	frd_free(&m);
}

/* ---- degenerate maps ------------------------------------------------ */

static void zero_and_nonfinite(void **state)
{
	struct frs_matrix m;
	struct frs_imap map;
	struct frs_setup s;
	(void)state;

	tu_perm_matrix(&m, 64, 64, 20);
	hd_map(&map, 16, 16, 0.0);
	assert_int_equal(imap_validate(&map, "zero.exr", 0), -1);
	assert_err_has("zero.exr", "zero everywhere");
	assert_int_equal(frs_setup(&s, &map, &m, 100, 8.0, 1), -1);
	assert_err_has("zero everywhere");
	assert_int_equal(imap_validate(&map, "zero.exr", FRS_MAP_ALLOW_ZERO), 0);
	/* NaN first in row-major order, then +inf, then -inf */
	map.v[9 * 16 + 7] = INFINITY;
	map.v[3 * 16 + 5] = NAN;
	map.v[15 * 16 + 15] = -INFINITY;
	map.v[0] = 1.0;
	assert_int_equal(imap_validate(&map, "bad.exr", 0), -1);
	assert_err_has("bad.exr", "pixel (5, 3)", "NaN", "3 non-finite");
	assert_int_equal(frs_setup(&s, &map, &m, 100, 8.0, 1), -1);
	map.v[3 * 16 + 5] = 1.0;
	assert_int_equal(imap_validate(&map, "bad.exr", 0), -1);
	assert_err_has("pixel (7, 9)", "infinite", "2 non-finite");
	map.v[9 * 16 + 7] = 1.0;
	assert_int_equal(imap_validate(&map, "bad.exr", 0), -1);
	assert_err_has("pixel (15, 15)", "infinite", "1 non-finite");
	assert_int_equal(frs_setup(&s, &map, &m, 100, 8.0, 1), -1);
	imap_free(&map);
	frd_free(&m);
}

/* Negative values: one warning with their count and the smallest, then
 * zero (no sample there); under FRS_MAP_STRICT an error naming the first.
 * -0.0 is not negative. */
static void negatives(void **state)
{
	struct frs_matrix m;
	struct frs_imap map;
	struct frs_setup s;
	uint64_t count;
	unsigned long w0;
	double *in;
	(void)state;

	tu_perm_matrix(&m, 256, 256, 21);
	hd_map(&map, 32, 32, 1.0);
	map.v[1 * 32 + 2] = -0.5;
	map.v[6 * 32 + 6] = -3.0;
	map.v[9 * 32 + 9] = -0.0;
	w0 = frs_warn_count();
	assert_int_equal(imap_validate(&map, "neg.exr", FRS_MAP_STRICT), -1);
	assert_err_has("neg.exr", "pixel (2, 1) is negative (-0.5)",
	    "2 negative pixels, smallest -3");
	assert_true(map.v[1 * 32 + 2] == -0.5);
	frs_set_quiet(1);
	assert_int_equal(imap_validate(&map, "neg.exr", 0), 0);
	frs_set_quiet(0);
	assert_true(frs_warn_count() == w0 + 1);
	assert_true(map.v[1 * 32 + 2] == 0.0 && map.v[6 * 32 + 6] == 0.0);
	w0 = frs_warn_count();
	assert_int_equal(imap_validate(&map, "neg.exr", FRS_MAP_STRICT), 0);
	assert_true(frs_warn_count() == w0);
	in = sample_counts(&map, &m, 20000, 22, &s, &count);
	total_ok("clamped map", count, 20000);
	assert_true(in[1 * 32 + 2] == 0 && in[6 * 32 + 6] == 0 &&
	    in[9 * 32 + 9] == 0);
	free(in);
	imap_free(&map);
	frd_free(&m);
}

/* 8000 samples of the w x h strip of values v (summing to 8), with the
 * seed: the count, each pixel's share v / 8; the counts per pixel. */
static double *strip(const struct frs_matrix *m, uint32_t w, uint32_t h,
    const double *v, uint64_t seed)
{
	struct frs_imap map;
	struct frs_setup s;
	uint64_t count;
	double *in;
	char what[2][32];

	snprintf(what[0], sizeof what[0], "%ux%u: count", w, h);
	snprintf(what[1], sizeof what[1], "%ux%u: pixel", w, h);
	assert_int_equal(imap_alloc(&map, w, h), 0);
	memcpy(map.v, v, (size_t)w * h * sizeof *v);
	in = sample_counts(&map, m, 8000, seed, &s, &count);
	total_ok(what[0], count, 8000);
	for (uint32_t k = 0; k < w * h; k++)
		hd_binom(what[1], in[k], (double)count, v[k] / 8);
	imap_free(&map);
	return in;
}

/*
 * 1x1: n = 1000 needs w_min = 253, n_s = 256, one whole tile of the 256^2
 * matrix with T = 1000: exactly 1000.  Strips 1x3 (1, 2, 5) and 5x1 (1, 0,
 * 3, 0, 4): each pixel's share, nothing on the zeros.
 */
static void tiny_maps(void **state)
{
	static const double col[3] = { 1, 2, 5 }, row[5] = { 1, 0, 3, 0, 4 };
	struct frs_matrix m;
	struct frs_imap map;
	struct frs_setup s;
	uint64_t count;
	double *in;
	(void)state;

	tu_perm_matrix(&m, 256, 256, 23);
	hd_map(&map, 1, 1, 0.25);
	in = sample_counts(&map, &m, 1000, 24, &s, &count);
	assert_int_equal(s.ns, 256);
	assert_true(count == 1000 && in[0] == 1000);
	free(in);
	imap_free(&map);

	free(strip(&m, 1, 3, col, 25));
	in = strip(&m, 5, 1, row, 26);
	assert_true(in[1] == 0 && in[3] == 0);
	free(in);
	frd_free(&m);
}

/* ---- the programs on maps that must be refused or clamped ------------ */

static const char *bin(void)
{
	const char *b = getenv("BIN");
	return b != NULL && *b ? b : "build/san/bin";
}

/* A map file with one bad pixel, and what each program says of it. */
static void cli_bad_maps(void **state)
{
	struct frs_matrix m;
	struct frs_imap map;
	const char *mat = tu_path("m.frd"), *exr = tu_path("bad.exr");
	const char *out = tu_path("o.pts"), *err = tu_path("err");
	FILE *fp;
	(void)state;

	tu_perm_matrix(&m, 64, 64, 27);
	fp = fopen(mat, "wb");
	assert_int_equal(frd_write(fp, mat, &m), 0);
	fclose(fp);
	frd_free(&m);
	for (int k = 0; k < 3; k++) {
		static const char *want[3] = { "pixel (9, 5) is NaN",
		    "pixel (9, 5) is infinite", "pixel (9, 5) is negative" };
		hd_map(&map, 16, 8, 1.0);
		map.v[5 * 16 + 9] = k == 0 ? NAN : k == 1 ? INFINITY : -2.0;
		fp = fopen(exr, "wb");
		assert_int_equal(imap_write_exr(fp, exr, &map), 0);
		fclose(fp);
		imap_free(&map);
		assert_int_equal(hd_sh("'%s/frs-sample' -m '%s' -i '%s' -n 100 "
		    "--strict -o '%s' 2>'%s'", bin(), mat, exr, out, err), 1);
		assert_true(hd_file_has(err, want[k]) && hd_file_has(err, exr));
		assert_false(hd_exists(out));
		assert_int_equal(hd_sh("'%s/hsw-sample' -i '%s' -n 100 "
		    "%s -o '%s' 2>'%s'", bin(), exr, k == 2 ? "-q" : "", out,
		    err), k == 2 ? 0 : 1);
		if (k < 2) {
			assert_true(hd_file_has(err, want[k]));
			assert_false(hd_exists(out));
		}
		remove(out);
	}
	/* clamped: a warning naming the count and the smallest value */
	assert_int_equal(hd_sh("'%s/frs-sample' -m '%s' -i '%s' -n 100 -o '%s' "
	    "2>'%s'", bin(), mat, exr, out, err), 0);
	assert_true(hd_file_has(err, "1 negative pixels clamped to zero "
	    "(smallest -2)"));
	remove(out);
}

TU_MAIN(hd_two_threads, tu_teardown,
	cmocka_unit_test(extreme_range),
	cmocka_unit_test(single_pixel_large_map),
	cmocka_unit_test(almost_all_tiny),
	cmocka_unit_test(denormals),
	cmocka_unit_test(huge_values),
	cmocka_unit_test(huge_setup),
	cmocka_unit_test(huge_setup_limit),
	cmocka_unit_test(huge_counts),
	cmocka_unit_test(zero_and_nonfinite),
	cmocka_unit_test(negatives),
	cmocka_unit_test(tiny_maps),
	cmocka_unit_test(cli_bad_maps))
