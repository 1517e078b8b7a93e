/*
 * The HSW sampler of the public API (frs_hsw_*) against hsw-sample, bit
 * for bit, and its errors.  The helpers: apiutil.h.
 */
#include "apiutil.h"

/* ---- HSW -------------------------------------------------------------- */

/* hsw-sample with ARGS, -n n and --pdf against the records of xy, pdf. */
static void compare_hsw(const double *xy, const double *pdf, size_t n,
    const char *args)
{
	const char *out = tu_path("hsw.pts");
	double *rec = malloc(3 * n * sizeof *rec);

	assert_non_null(rec);
	prog("hsw-sample -q %s -n %zu --pdf -o %s", args, n, out);
	for (size_t i = 0; i < n; i++) {
		rec[3 * i] = xy[2 * i];
		rec[3 * i + 1] = xy[2 * i + 1];
		rec[3 * i + 2] = pdf[i];
	}
	same_as_file(out, rec, n, 1);
	free(rec);
}

static void test_hsw_draw(void **state)
{
	static const char *const kinds[] = { "random", "regular", "jittered",
	    "halton", "hammersley" };
	size_t n = 777;
	double *xy = malloc(2 * n * sizeof *xy), *pdf = malloc(n * sizeof *pdf);
	double *xy2 = malloc(2 * n * sizeof *xy2);
	frs_hsw *hw, *hc;
	char args[256];

	(void)state;
	assert_non_null(xy);
	assert_non_null(pdf);
	assert_non_null(xy2);
	assert_int_equal(frs_hsw_new_f64(&hw, blob.v, blob.w, blob.h, 0, NULL),
	    FRS_OK);
	assert_int_equal(frs_hsw_new(&hc, NULL, 64, 64, 0, NULL), FRS_OK);
	for (int k = FRS_HSW_RANDOM; k <= FRS_HSW_HAMMERSLEY; k++) {
		assert_int_equal(frs_hsw_draw(hw, (enum frs_hsw_input)k, n, 3, xy,
		    pdf, 1, NULL), FRS_OK);
		snprintf(args, sizeof args, "-i blob --input %s -S 3", kinds[k]);
		compare_hsw(xy, pdf, n, args);
		/* Threads and no pdf: the same points. */
		assert_int_equal(frs_hsw_draw(hw, (enum frs_hsw_input)k, n, 3,
		    xy2, NULL, 2, NULL), FRS_OK);
		assert_memory_equal(xy, xy2, 2 * n * sizeof *xy);
		assert_int_equal(frs_hsw_draw(hc, (enum frs_hsw_input)k, n, 3, xy,
		    pdf, 0, NULL), FRS_OK);
		snprintf(args, sizeof args, "-i const -s 64x64 --input %s -S 3",
		    kinds[k]);
		compare_hsw(xy, pdf, n, args);
	}
	frs_hsw_free(hw);
	frs_hsw_free(hc);
	free(xy);
	free(xy2);
	free(pdf);
}

/* Given points: hsw-sample --input FILE; in place the same. */
static void test_hsw_warp(void **state)
{
	size_t n = 5000;
	double *in = tu_rnd_points(n, 5), *out = malloc(2 * n * sizeof *out);
	double *pdf = malloc(n * sizeof *pdf), *pdf2 = malloc(n * sizeof *pdf);
	const char *pin = tu_path("in.pts"), *exr = write_exr("hblob.exr",
	    &blob);
	struct frs_points p = { 2, 0, n, in, { "" }, 0 };
	frs_hsw *hw;
	float *map;
	uint32_t w, h;
	char args[700];
	FILE *fp;

	(void)state;
	assert_non_null(out);
	assert_non_null(pdf);
	assert_non_null(pdf2);
	fp = fopen(pin, "wb");
	assert_non_null(fp);
	assert_int_equal(pts_write(fp, pin, &p, 0), 0);
	assert_int_equal(fclose(fp), 0);
	assert_int_equal(frs_hsw_new_f64(&hw, blob.v, blob.w, blob.h, 0,
	    NULL), FRS_OK);
	assert_int_equal(frs_hsw_warp(hw, in, out, pdf, n, 1, NULL), FRS_OK);
	snprintf(args, sizeof args, "-i blob --input %s", pin);
	compare_hsw(out, pdf, n, args);
	assert_int_equal(frs_hsw_warp(hw, in, in, pdf2, n, 2, NULL), FRS_OK);
	assert_memory_equal(in, out, 2 * n * sizeof *in);
	assert_memory_equal(pdf, pdf2, n * sizeof *pdf);
	frs_hsw_free(hw);
	/* A float map from a file. */
	assert_int_equal(frs_map_load(exr, 0, 0, &map, &w, &h, NULL), FRS_OK);
	assert_int_equal(frs_hsw_new(&hw, map, w, h, 0, NULL), FRS_OK);
	assert_int_equal(frs_hsw_draw(hw, FRS_HSW_HALTON, n, 9, out, pdf, 1,
	    NULL), FRS_OK);
	snprintf(args, sizeof args, "-i %s --input halton -S 9", exr);
	compare_hsw(out, pdf, n, args);
	frs_hsw_free(hw);
	frs_map_free(map);
	free(in);
	free(out);
	free(pdf);
	free(pdf2);
}

/* Negative values count as zero: the points of the map with zeros. */
static void test_hsw_negative(void **state)
{
	struct frs_imap m;
	frs_hsw *a, *b;
	size_t n = 3000;
	double *xa = malloc(2 * n * sizeof *xa), *xb = malloc(2 * n * sizeof *xb);
	double *pa = malloc(n * sizeof *pa), *pb = malloc(n * sizeof *pb);
	int q, rc;

	(void)state;
	assert_int_equal(imap_load("blob", 32, 32, 0, &m), 0);
	for (size_t i = 0; i < 1024; i += 3)
		m.v[i] = -0.5;
	q = quiet_begin();
	rc = frs_hsw_new_f64(&a, m.v, 32, 32, 0, NULL);
	quiet_end(q, "frs_hsw_new_f64");
	if (rc != FRS_OK) {
		print_error("frs_hsw_new_f64 refuses negative values\n");
		imap_free(&m);
		free(xa), free(xb), free(pa), free(pb);
		fail();
	}
	for (size_t i = 0; i < 1024; i += 3)
		m.v[i] = 0.0;
	assert_int_equal(frs_hsw_new_f64(&b, m.v, 32, 32, 0, NULL), FRS_OK);
	assert_int_equal(frs_hsw_draw(a, FRS_HSW_RANDOM, n, 1, xa, pa, 1,
	    NULL), FRS_OK);
	assert_int_equal(frs_hsw_draw(b, FRS_HSW_RANDOM, n, 1, xb, pb, 1,
	    NULL), FRS_OK);
	assert_memory_equal(xa, xb, 2 * n * sizeof *xa);
	assert_memory_equal(pa, pb, n * sizeof *pa);
	for (size_t i = 0; i < n; i++)
		assert_true(pa[i] > 0.0);
	frs_hsw_free(a);
	frs_hsw_free(b);
	imap_free(&m);
	free(xa);
	free(xb);
	free(pa);
	free(pb);
}

static void test_hsw_errors(void **state)
{
	double in[4] = { 0.5, 0.5, 0.25, 1.0 }, out[4], pdf[2], xy[8];
	double one[4] = { 1, 1, 1, 1 };
	frs_hsw *hw = NULL;

	(void)state;
	EXPECT(FRS_E_ARG, frs_hsw_new(NULL, NULL, 4, 4, 0, E));
	EXPECT(FRS_E_ARG, frs_hsw_new(&hw, NULL, 0, 4, 0, E));
	EXPECT(FRS_E_ARG, frs_hsw_new(&hw, NULL, 4, 0, 0, E));
	EXPECT(FRS_E_ARG, frs_hsw_new_f64(NULL, one, 2, 2, 0, E));
	EXPECT(FRS_E_ARG, frs_hsw_new_f64(&hw, one, 2, 2, 1, E));
	EXPECT(FRS_E_LIMIT, frs_hsw_new(&hw, NULL, 1u << 20, 1u << 20, 0, E));
	assert_int_equal(frs_hsw_new_f64(&hw, one, 2, 2, 0, NULL), FRS_OK);
	EXPECT(FRS_E_ARG, frs_hsw_warp(NULL, in, out, pdf, 1, 1, E));
	EXPECT(FRS_E_ARG, frs_hsw_warp(hw, NULL, out, pdf, 1, 1, E));
	EXPECT(FRS_E_ARG, frs_hsw_warp(hw, in, NULL, pdf, 1, 1, E));
	EXPECT(FRS_E_ARG, frs_hsw_warp(hw, in, out, pdf, 2, 1, E));
	EXPECT(FRS_E_ARG, frs_hsw_warp(hw, in, out, pdf, 1, -1, E));
	in[0] = NAN;
	EXPECT(FRS_E_ARG, frs_hsw_warp(hw, in, out, pdf, 1, 1, E));
	in[0] = -0.25;
	EXPECT(FRS_E_ARG, frs_hsw_warp(hw, in, out, pdf, 1, 1, E));
	EXPECT(FRS_OK, frs_hsw_warp(hw, in, out, pdf, 0, 1, E));
	EXPECT(FRS_E_ARG, frs_hsw_draw(NULL, FRS_HSW_HALTON, 4, 1, xy, NULL, 1,
	    E));
	EXPECT(FRS_E_ARG, frs_hsw_draw(hw, FRS_HSW_HALTON, 4, 1, NULL, NULL, 1,
	    E));
	EXPECT(FRS_E_ARG, frs_hsw_draw(hw, (enum frs_hsw_input)5, 4, 1, xy,
	    NULL, 1, E));
	EXPECT(FRS_E_ARG, frs_hsw_draw(hw, (enum frs_hsw_input)-1, 4, 1, xy,
	    NULL, 1, E));
	EXPECT(FRS_E_ARG, frs_hsw_draw(hw, FRS_HSW_HALTON, 4, 1, xy, NULL, -3,
	    E));
	EXPECT(FRS_OK, frs_hsw_draw(hw, FRS_HSW_HALTON, 4, 1, xy, NULL, 1, E));
	frs_hsw_free(hw);
	frs_hsw_free(NULL);
}

TU_MAIN(setup, teardown,
	cmocka_unit_test(test_hsw_draw),
	cmocka_unit_test(test_hsw_warp),
	cmocka_unit_test(test_hsw_negative),
	cmocka_unit_test(test_hsw_errors))
