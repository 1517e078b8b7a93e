/* Hierarchical Sample Warping on the OpenCL device (PoCL in make check)
 * against the CPU warp: the same points, bit for bit and in the same
 * order, for the maps const, blob, ramp and sky, a non-power-of-two map,
 * a sparse map with zeros, halton, random and dart input, n = 1, 1000,
 * 100000, in place and in chunks; a device without fp64 is refused. */
#include "testutil.h"
#include "oclutil.h"
#include "sample/hsw.h"
#include "hsw-sample/hswcl.h"
#include "maps/imap.h"
#include "maps/mapload.h"
#include "cli/refsamp.h"
#include "base/progress.h"

#define NMAX 100000
static const uint64_t counts[] = { 1, 1000, NMAX };
enum { IN_HALTON, IN_RANDOM, IN_DART, IN_EDGES, NIN };
static const char *const in_names[NIN] = { "halton", "random", "dart",
    "edges" };
static double *inputs[NIN];	/* NMAX points each (dart: dart_n) */
static uint64_t in_n[NIN];

/* Points at the edges of the square and of the halves: 0, the largest
 * double below 1, dyadic fractions and their neighbours. */
static void edge_points(double *p, uint64_t n)
{
	static const double v[] = { 0.0, 0x1.fffffffffffffp-1, 0.5,
	    0x1.fffffffffffffp-2, 0x1.0000000000001p-1, 0.25, 0.75,
	    0x1p-1074, 0x1p-53, 1.0 / 3.0, 2.0 / 3.0, 0.125, 0.875 };
	const uint64_t m = sizeof v / sizeof v[0];

	for (uint64_t i = 0; i < n; i++) {
		p[2 * i] = v[i % m];
		p[2 * i + 1] = v[(i / m) % m];
	}
}

static int setup(void **state)
{
	uint64_t placed = 0;
	if (tu_ocl_setup(state) != 0)
		return -1;
	for (int k = 0; k < NIN; k++) {
		inputs[k] = malloc(2 * NMAX * sizeof(double));
		if (inputs[k] == NULL)
			return -1;
		in_n[k] = NMAX;
	}
	hsw_input_make(HSW_HALTON, NMAX, 1, inputs[IN_HALTON]);
	hsw_input_make(HSW_RANDOM, NMAX, 7, inputs[IN_RANDOM]);
	if (refsamp_gen(REFSAMP_DART, NMAX, 3, REFSAMP_DART_FAILURES,
	    inputs[IN_DART], &placed) < 0)
		return -1;
	in_n[IN_DART] = placed;
	edge_points(inputs[IN_EDGES], NMAX);
	return 0;
}

static int teardown(void **state)
{
	for (int k = 0; k < NIN; k++)
		free(inputs[k]);
	return tu_ocl_teardown(state);
}

/* The first differing coordinate of two arrays of 2n doubles, or -1. */
static int64_t first_diff(const double *a, const double *b, uint64_t n)
{
	if (memcmp(a, b, 2 * n * sizeof *a) == 0)
		return -1;
	for (uint64_t i = 0; i < 2 * n; i++)
		if (memcmp(a + i, b + i, sizeof *a) != 0)
			return (int64_t)i;
	return -1;
}

/* The tree as frs_hsw_info describes it to the device. */
static const struct frs_hsw_info *info_of(const struct hsw_tree *t)
{
	static struct frs_hsw_info ti;

	ti = (struct frs_hsw_info){ t->w, t->h, t->size, t->levels, t->total,
	    0.0, t->sum };
	return &ti;
}

/* Every input and count through map m on the CPU and the device. */
static void same_points(const struct frs_imap *m, const char *what)
{
	struct hsw_tree t;
	struct hswcl h;
	double *cpu = malloc(2 * NMAX * sizeof *cpu);
	double *dev = malloc(2 * NMAX * sizeof *dev);

	assert_non_null(cpu);
	assert_non_null(dev);
	assert_int_equal(hsw_build(&t, m), 0);
	assert_int_equal(hswcl_init(&h, &tu_ocl, info_of(&t)), 0);
	for (int k = 0; k < NIN; k++)
		for (size_t c = 0; c < sizeof counts / sizeof counts[0]; c++) {
			uint64_t n = counts[c] < in_n[k] ? counts[c] : in_n[k];
			int64_t d;
			memset(dev, 0xff, 2 * n * sizeof *dev);
			assert_int_equal(hsw_warp_points(&t, inputs[k], cpu, n), 0);
			assert_int_equal(hswcl_warp_points(&h, inputs[k], dev, n),
			    0);
			d = first_diff(cpu, dev, n);
			if (d >= 0)
				fail_msg("%s, %s input, n = %llu: point %lld "
				    "coordinate %d: cpu %a, device %a", what,
				    in_names[k], (unsigned long long)n,
				    (long long)(d / 2), (int)(d % 2), cpu[d],
				    dev[d]);
		}
	hswcl_free(&h);
	hsw_free(&t);
	free(cpu);
	free(dev);
}

static void spec(const char *s, uint32_t w, uint32_t h)
{
	struct frs_imap m;

	assert_int_equal(imap_load(s, w, h, 0, &m), 0);
	same_points(&m, s);
	imap_free(&m);
}

static void test_const(void **state) { (void)state; spec("const", 128, 128); }
static void test_blob(void **state) { (void)state; spec("blob", 128, 128); }
static void test_ramp(void **state) { (void)state; spec("ramp", 128, 128); }
static void test_sky(void **state) { (void)state; spec("sky", 128, 128); }

/* Padding, pixel edges that rounding crosses, and a 1x1 map. */
static void test_odd_sizes(void **state)
{
	(void)state;
	spec("blob:x=0.3", 100, 60);
	spec("ramp", 3, 77);
	spec("const", 1, 1);
}

/* Zeros everywhere but a few pixels of wildly different weight. */
static void test_sparse(void **state)
{
	struct frs_imap m;
	(void)state;
	assert_int_equal(imap_alloc(&m, 37, 23), 0);
	for (uint64_t i = 0; i < 37 * 23; i++) {
		uint64_t r = frs_rand64x(5, FRS_STREAM_TEST, i, 0);
		m.v[i] = r % 5 == 0 ? ldexp((double)(r >> 40), -(int)(r % 60))
		    : 0.0;
	}
	same_points(&m, "sparse 37x23");
	imap_free(&m);
}

/* in == out, several chunks of an odd size, one program for many
 * calls. */
static void test_in_place_chunks(void **state)
{
	struct frs_imap m;
	struct hsw_tree t;
	struct hswcl h;
	uint64_t n = 10007;
	double *a = malloc(2 * n * sizeof *a), *b = malloc(2 * n * sizeof *b);
	double whole;
	(void)state;
	assert_non_null(a);
	assert_non_null(b);
	assert_int_equal(imap_load("blob:sigma=0.05", 64, 64, 0, &m), 0);
	assert_int_equal(hsw_build(&t, &m), 0);
	hsw_input_make(HSW_JITTERED, n, 9, a);
	memcpy(b, a, 2 * n * sizeof *a);
	assert_int_equal(hsw_warp_points(&t, a, a, n), 0);
	assert_int_equal(hswcl_init(&h, &tu_ocl, info_of(&t)), 0);
	h.max_chunk = 333;
	whole = progress_now();
	assert_int_equal(hswcl_warp_points(&h, b, b, n), 0);
	whole = progress_now() - whole;
	assert_true(first_diff(a, b, n) < 0);
	/* Each of the 31 chunks is written, run and read: every phase takes
	 * time, and together they fit in the call. */
	assert_true(h.t_write > 0 && h.t_kernel > 0 && h.t_read > 0);
	assert_true(h.t_write + h.t_kernel + h.t_read <= whole);
	hswcl_free(&h);
	/* The one-shot form. */
	hsw_input_make(HSW_JITTERED, n, 9, b);
	assert_int_equal(hswcl_warp(&tu_ocl, info_of(&t), b, b, n), 0);
	assert_true(first_diff(a, b, n) < 0);
	hsw_free(&t);
	imap_free(&m);
	free(a);
	free(b);
}

static void test_no_fp64(void **state)
{
	struct frs_imap m;
	struct hsw_tree t;
	struct hswcl h;
	struct ocl x = tu_ocl;
	(void)state;
	x.fp64 = 0;
	assert_int_equal(imap_load("blob", 16, 16, 0, &m), 0);
	assert_int_equal(hsw_build(&t, &m), 0);
	assert_int_equal(hswcl_init(&h, &x, info_of(&t)), -1);
	assert_err_has("no double precision", "cl_khr_fp64", "the CPU's points");
	hsw_free(&t);
	imap_free(&m);
}

TU_MAIN(setup, teardown,
	cmocka_unit_test(test_const),
	cmocka_unit_test(test_blob),
	cmocka_unit_test(test_ramp),
	cmocka_unit_test(test_sky),
	cmocka_unit_test(test_odd_sizes),
	cmocka_unit_test(test_sparse),
	cmocka_unit_test(test_in_place_chunks),
	cmocka_unit_test(test_no_fp64))
