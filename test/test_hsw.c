/* Hierarchical Sample Warping against independent oracles: identity on a
 * constant map, moments of the warped set against the map's, points only
 * where the importance is positive, padding, exact counts, thread
 * independence. */
#include "testutil.h"
#include "sample/hsw.h"
#include "maps/imap.h"
#include "maps/mapload.h"
#include "moments.h"
#include "base/par.h"
#include "base/rng.h"

/* n halton points warped by map m into a new array. */
static double *warp(const struct frs_imap *m, uint64_t n, enum hsw_input in)
{
	struct hsw_tree t;
	double *p = malloc(2 * n * sizeof *p);

	assert_non_null(p);
	assert_int_equal(hsw_build(&t, m), 0);
	hsw_input_make(in, n, 1, p);
	assert_int_equal(hsw_warp_points(&t, p, p, n), 0);
	hsw_free(&t);
	for (uint64_t i = 0; i < 2 * n; i++) {
		assert_true(p[i] >= 0.0);
		assert_true(p[i] < 1.0);
	}
	return p;
}

static double pix(const struct frs_imap *m, double x, double y)
{
	uint32_t i = (uint32_t)(x * m->w), j = (uint32_t)(y * m->h);
	assert_true(i < m->w && j < m->h);
	return m->v[(uint64_t)j * m->w + i];
}

static void test_identity(void **state)
{
	struct frs_imap m;
	uint64_t n = 20000;
	double *in = malloc(2 * n * sizeof *in), *out;

	(void)state;
	assert_int_equal(imap_load("const", 64, 64, 0, &m), 0);
	for (int k = HSW_RANDOM; k <= HSW_HAMMERSLEY; k++) {
		out = warp(&m, n, (enum hsw_input)k);
		hsw_input_make((enum hsw_input)k, n, 1, in);
		for (uint64_t i = 0; i < 2 * n; i++)
			assert_near(out[i], in[i], 1e-12);
		free(out);
	}
	free(in);
	imap_free(&m);
}

/* Centroid within 0.1 pixel and standard deviation within 1%. */
static void moments(const char *spec)
{
	struct frs_imap map;
	struct moments m = { 0 };
	uint64_t n = 100000;
	double *p;

	assert_int_equal(imap_load(spec, 128, 128, 0, &map), 0);
	p = warp(&map, n, HSW_HALTON);
	for (uint64_t i = 0; i < n; i++)
		mom_add(&m, p[2 * i], p[2 * i + 1]);
	mom_check(&map, &m, spec);
	free(p);
	imap_free(&map);
}

static void test_moments_blob(void **state)
{
	(void)state;
	moments("blob:x=0.35,y=0.6,sigma=0.12");
}

static void test_moments_ramp(void **state)
{
	(void)state;
	moments("ramp:angle=30");
}

static void test_hot_pixel(void **state)
{
	struct frs_imap m;
	uint64_t n = 10000;
	double *p;

	(void)state;
	assert_int_equal(imap_alloc(&m, 32, 32), 0);
	memset(m.v, 0, 32 * 32 * sizeof *m.v);
	m.v[17 * 32 + 5] = 3.0;
	for (int k = HSW_RANDOM; k <= HSW_HAMMERSLEY; k++) {
		p = warp(&m, n, (enum hsw_input)k);
		for (uint64_t i = 0; i < n; i++) {
			assert_int_equal((int)(p[2 * i] * 32), 5);
			assert_int_equal((int)(p[2 * i + 1] * 32), 17);
		}
		free(p);
	}
	imap_free(&m);
}

/* Zero rows and columns: a left half of zeros, and stripes. */
static void test_zero_regions(void **state)
{
	struct frs_imap m;
	uint64_t n = 50000;
	double *p;

	(void)state;
	assert_int_equal(imap_alloc(&m, 64, 64), 0);
	for (uint32_t j = 0; j < 64; j++)
		for (uint32_t i = 0; i < 64; i++)
			m.v[j * 64 + i] = i < 32 ? 0.0 : 1.0 + (i + j) % 5;
	p = warp(&m, n, HSW_HALTON);
	for (uint64_t i = 0; i < n; i++)
		assert_true(pix(&m, p[2 * i], p[2 * i + 1]) > 0);
	free(p);
	/* every third row and every fourth column empty, one dim pixel */
	for (uint32_t j = 0; j < 64; j++)
		for (uint32_t i = 0; i < 64; i++)
			m.v[j * 64 + i] = (j % 3 == 0 || i % 4 == 1) ? 0.0 : 1.0;
	m.v[2 * 64 + 2] = 1e-300;
	p = warp(&m, n, HSW_RANDOM);
	for (uint64_t i = 0; i < n; i++)
		assert_true(pix(&m, p[2 * i], p[2 * i + 1]) > 0);
	free(p);
	imap_free(&m);
}

/* 100x60 pads to 128x128: points only in the map, proportional. */
static void test_padding(void **state)
{
	struct frs_imap m;
	struct hsw_tree t;
	uint64_t n = 100000, left = 0, top = 0;
	double wl = 0, wt = 0, w = 0, *p;

	(void)state;
	assert_int_equal(imap_alloc(&m, 100, 60), 0);
	for (uint32_t j = 0; j < 60; j++)
		for (uint32_t i = 0; i < 100; i++) {
			double v = 1.0 + i * 0.05 + (j < 20 ? 2.0 : 0.0);
			m.v[j * 100 + i] = v;
			w += v;
			wl += i < 50 ? v : 0;
			wt += j < 30 ? v : 0;
		}
	assert_int_equal(hsw_build(&t, &m), 0);
	assert_int_equal(t.size, 128);
	assert_int_equal(t.levels, 7);
	hsw_free(&t);
	p = warp(&m, n, HSW_HALTON);
	for (uint64_t i = 0; i < n; i++) {
		assert_true(pix(&m, p[2 * i], p[2 * i + 1]) > 0);
		left += p[2 * i] < 0.5;
		top += p[2 * i + 1] < 0.5;
	}
	assert_near((double)left / n, wl / w, 0.02 * wl / w);
	assert_near((double)top / n, wt / w, 0.02 * wt / w);
	free(p);
	imap_free(&m);
}

static void test_count_and_threads(void **state)
{
	struct frs_imap m;
	uint64_t n = 123457;
	double *a, *b;

	(void)state;
	assert_int_equal(imap_load("blob", 128, 128, 0, &m), 0);
	frs_set_threads(1);
	a = warp(&m, n, HSW_JITTERED);
	frs_set_threads(4);
	b = warp(&m, n, HSW_JITTERED);
	assert_memory_equal(a, b, 2 * n * sizeof *a);
	/* one point at a time gives the same (the grouped path and the
	 * single path agree) */
	{
		struct hsw_tree t;
		double *c = malloc(2 * n * sizeof *c);
		assert_int_equal(hsw_build(&t, &m), 0);
		hsw_input_make(HSW_JITTERED, n, 1, c);
		for (uint64_t i = 0; i < n; i++) {
			double x = c[2 * i], y = c[2 * i + 1];
			uint64_t k = hsw_warp(&t, &x, &y);
			assert_true(x == a[2 * i] && y == a[2 * i + 1]);
			assert_int_equal(k, (uint64_t)(y * 128) * 128 +
			    (uint64_t)(x * 128));
		}
		hsw_free(&t);
		free(c);
	}
	free(a);
	free(b);
	imap_free(&m);
}

static void test_inputs(void **state)
{
	double p[2 * 10];

	(void)state;
	/* The names hsw-sample's --input takes, by value. */
	assert_string_equal(frs_names(FRS_NAMES_HSW_INPUT)[HSW_HALTON],
	    "halton");
	assert_string_equal(frs_names(FRS_NAMES_HSW_INPUT)[HSW_HAMMERSLEY],
	    "hammersley");
	assert_null(frs_names(FRS_NAMES_HSW_INPUT)[HSW_HAMMERSLEY + 1]);
	assert_near(hsw_radical_inverse(1, 2), 0.5, 0);
	assert_near(hsw_radical_inverse(6, 2), 0.375, 0);
	assert_near(hsw_radical_inverse(5, 3), 2.0 / 3 + 1.0 / 9, 1e-15);
	/* regular: a 4x4 grid for 10 points, row order */
	hsw_input_make(HSW_REGULAR, 10, 1, p);
	assert_near(p[0], 0.125, 0);
	assert_near(p[1], 0.125, 0);
	assert_near(p[2 * 5], 0.375, 0);
	assert_near(p[2 * 5 + 1], 0.375, 0);
	hsw_input_make(HSW_HAMMERSLEY, 4, 1, p);
	assert_near(p[2 * 3], 3.5 / 4, 0);
	assert_near(p[2 * 3 + 1], 0.75, 0);
}

/* The input sets by their defining formulas, one index at a time: the
 * oracle of the chunked, table-driven hsw_input_range. */
static void input_oracle(enum hsw_input kind, uint64_t n, uint64_t seed,
    uint64_t i, double *x, double *y)
{
	uint64_t k = 1;

	while (k * k < n)
		k++;
	switch (kind) {
	case HSW_RANDOM:
		*x = frs_rand01(seed, FRS_STREAM_HSW, 2 * i);
		*y = frs_rand01(seed, FRS_STREAM_HSW, 2 * i + 1);
		break;
	case HSW_REGULAR:
		*x = ((double)(i % k) + 0.5) / (double)k;
		*y = ((double)(i / k) + 0.5) / (double)k;
		break;
	case HSW_JITTERED:
		*x = ((double)(i % k) + frs_rand01(seed, FRS_STREAM_HSW, 2 * i)) /
		    (double)k;
		*y = ((double)(i / k) +
		    frs_rand01(seed, FRS_STREAM_HSW, 2 * i + 1)) / (double)k;
		break;
	case HSW_HALTON:
		*x = hsw_radical_inverse(i + 1, 2);
		*y = hsw_radical_inverse(i + 1, 3);
		break;
	case HSW_HAMMERSLEY:
		*x = ((double)i + 0.5) / (double)n;
		*y = hsw_radical_inverse(i, 2);
		break;
	}
	*x = *x < 1.0 ? *x : nextafter(1.0, 0.0);
	*y = *y < 1.0 ? *y : nextafter(1.0, 0.0);
}

/* Ranges anywhere in the index space, across the table's 3^6 and the
 * digits' 3^k boundaries and up to 2^36, give the oracle's bits. */
static void test_input_ranges(void **state)
{
	static const uint64_t starts[] = { 0, 1, 700, 728, 2186, 59040,
	    43046700, 3486784390, 68719476000 };
	uint64_t n = (uint64_t)1 << 36, m = 600;
	double *p = malloc(2 * m * sizeof *p);

	(void)state;
	assert_non_null(p);
	for (int kind = HSW_RANDOM; kind <= HSW_HAMMERSLEY; kind++)
		for (size_t s = 0; s < sizeof starts / sizeof *starts; s++) {
			uint64_t b = starts[s];
			hsw_input_range((enum hsw_input)kind, n, 3, b, b + m, p);
			for (uint64_t q = 0; q < m; q++) {
				double x, y;
				input_oracle((enum hsw_input)kind, n, 3, b + q, &x, &y);
				if (x != p[2 * q] || y != p[2 * q + 1])
					fail_msg("kind %d, index %llu: (%a, %a), "
					    "oracle (%a, %a)", kind,
					    (unsigned long long)(b + q), p[2 * q],
					    p[2 * q + 1], x, y);
			}
		}
	/* and hsw_input_make from 0 */
	hsw_input_make(HSW_HALTON, m, 1, p);
	for (uint64_t q = 0; q < m; q++) {
		double x, y;
		input_oracle(HSW_HALTON, m, 1, q, &x, &y);
		assert_true(x == p[2 * q] && y == p[2 * q + 1]);
	}
	free(p);
}

/* hsw_sample: records of n points over several chunks (16384) and
 * pieces, with and without the density; one point at a time (hsw_warp,
 * hsw_pdf_at) is the oracle; 1 and 3 threads and a range cut at odd
 * places inside chunks give the same bytes; a given array (hsw_warp_points)
 * the same as the set made on the fly. */
static void test_sample_chunks(void **state)
{
	static const uint64_t cuts[] = { 0, 1, 255, 16383, 16400, 40001, 50000 };
	uint64_t n = 50000;
	struct frs_imap m;
	struct hsw_tree t;
	struct hsw_source src = { HSW_HALTON, 50000, 1, NULL };
	double *a = malloc(3 * n * sizeof *a), *b = malloc(3 * n * sizeof *b);
	double *in = malloc(2 * n * sizeof *in), mean;

	(void)state;
	assert_true(a != NULL && b != NULL && in != NULL);
	assert_int_equal(imap_load("blob", 100, 37, 0, &m), 0);
	assert_int_equal(hsw_build(&t, &m), 0);
	mean = hsw_mean(&t, &m);
	hsw_input_make(HSW_HALTON, n, 1, in);
	frs_set_threads(1);
	/* a: the pairs, a + 2n: the densities */
	assert_int_equal(hsw_sample(&t, &src, &m, 0, n, a, a + 2 * n), 0);
	for (uint64_t i = 0; i < n; i++) {
		double x = in[2 * i], y = in[2 * i + 1];
		hsw_warp(&t, &x, &y);
		if (x != a[2 * i] || y != a[2 * i + 1] ||
		    hsw_pdf_at(&m, mean, x, y) != a[2 * n + i])
			fail_msg("point %llu: (%a, %a), one at a time (%a, %a)",
			    (unsigned long long)i, a[2 * i], a[2 * i + 1], x, y);
	}
	frs_set_threads(3);
	memset(b, 0xff, 3 * n * sizeof *b);
	for (size_t c = 0; c + 1 < sizeof cuts / sizeof *cuts; c++)
		assert_int_equal(hsw_sample(&t, &src, &m, cuts[c], cuts[c + 1],
		    b + 2 * cuts[c], b + 2 * n + cuts[c]), 0);
	assert_memory_equal(a, b, 3 * n * sizeof *a);
	/* without the density, and from the array */
	memset(b, 0xff, 3 * n * sizeof *b);
	assert_int_equal(hsw_sample(&t, &src, &m, 0, n, b, NULL), 0);
	assert_memory_equal(a, b, 2 * n * sizeof *a);
	assert_true(b[2 * n] != b[2 * n]);	/* no density written: NaN */
	assert_int_equal(hsw_warp_points(&t, in, in, n), 0);
	assert_memory_equal(in, b, 2 * n * sizeof *b);
	frs_set_threads(1);
	hsw_free(&t);
	imap_free(&m);
	free(a);
	free(b);
	free(in);
}

static void test_all_zero(void **state)
{
	struct frs_imap m;
	struct hsw_tree t;

	(void)state;
	assert_int_equal(imap_alloc(&m, 8, 8), 0);
	memset(m.v, 0, 64 * sizeof *m.v);
	assert_int_equal(hsw_build(&t, &m), -1);
	assert_err_has("zero everywhere");
	imap_free(&m);
}

TU_MAIN(NULL, tu_teardown,
	cmocka_unit_test(test_identity),
	cmocka_unit_test(test_moments_blob),
	cmocka_unit_test(test_moments_ramp),
	cmocka_unit_test(test_hot_pixel),
	cmocka_unit_test(test_zero_regions),
	cmocka_unit_test(test_padding),
	cmocka_unit_test(test_count_and_threads),
	cmocka_unit_test(test_inputs),
	cmocka_unit_test(test_input_ranges),
	cmocka_unit_test(test_sample_chunks),
	cmocka_unit_test(test_all_zero))
