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

/* frs_hsw_draw_each's batches, gathered. */
struct hsw_gather {
	double *xy, *pdf;
	size_t n, cap;
	int calls, stop_at;
};

static int hsw_gather(void *ctx, const double *xy, const double *pdf,
    const uint32_t *step, size_t k, uint64_t total)
{
	struct hsw_gather *g = ctx;

	assert_null(step);
	assert_true(total == g->cap && g->n + k <= g->cap && k > 0 &&
	    k <= (size_t)1 << 16);
	memcpy(g->xy + 2 * g->n, xy, 2 * k * sizeof *xy);
	if (g->pdf != NULL) {
		assert_non_null(pdf);
		memcpy(g->pdf + g->n, pdf, k * sizeof *pdf);
	} else {
		assert_null(pdf);
	}
	g->n += k;
	return ++g->calls == g->stop_at;
}

/* The callback form: frs_hsw_draw's points and densities for every input
 * set, and frs_hsw_warp's for the caller's points, in batches (70001
 * points: two of them), for 1 and 2 threads; a stop ends the run. */
static void test_hsw_each(void **state)
{
	size_t n = 70001;
	double *xy = malloc(2 * n * sizeof *xy), *pdf = malloc(n * sizeof *pdf);
	double *in = tu_rnd_points(n, 8);
	struct hsw_gather g = { malloc(2 * n * sizeof *xy),
	    malloc(n * sizeof *pdf), 0, n, 0, 0 };
	frs_hsw *hw;
	frs_error e;

	(void)state;
	assert_true(xy && pdf && g.xy && g.pdf);
	assert_int_equal(frs_hsw_new_f64(&hw, blob.v, blob.w, blob.h, 0, NULL),
	    FRS_OK);
	for (int k = FRS_HSW_RANDOM; k <= FRS_HSW_HAMMERSLEY; k++)
		for (int t = 1; t <= 2; t++) {
			assert_int_equal(frs_hsw_draw(hw, (enum frs_hsw_input)k, n, 4,
			    xy, pdf, 1, NULL), FRS_OK);
			g.n = 0;
			g.calls = 0;
			assert_int_equal(frs_hsw_draw_each(hw, (enum frs_hsw_input)k,
			    NULL, n, 4, 1, t, hsw_gather, &g, &e), FRS_OK);
			assert_int_equal(g.n, n);
			assert_int_equal(g.calls, 2);
			assert_memory_equal(g.xy, xy, 2 * n * sizeof *xy);
			assert_memory_equal(g.pdf, pdf, n * sizeof *pdf);
		}
	/* The caller's points; no densities asked for. */
	assert_int_equal(frs_hsw_warp(hw, in, xy, NULL, n, 1, NULL), FRS_OK);
	free(g.pdf);
	g.pdf = NULL;
	g.n = 0;
	assert_int_equal(frs_hsw_draw_each(hw, FRS_HSW_HALTON, in, n, 4, 0, 2,
	    hsw_gather, &g, &e), FRS_OK);
	assert_int_equal(g.n, n);
	assert_memory_equal(g.xy, xy, 2 * n * sizeof *xy);
	/* A callback that says stop. */
	g.n = 0;
	g.calls = 0;
	g.stop_at = 1;
	EXPECT(FRS_E_CALLBACK, frs_hsw_draw_each(hw, FRS_HSW_RANDOM, NULL, n,
	    4, 0, 1, hsw_gather, (g.n = 0, g.calls = 0, &g), E));
	assert_int_equal(g.calls, 1);
	frs_hsw_free(hw);
	free(g.xy);
	free(xy);
	free(pdf);
	free(in);
}

/* The radical inverse of i in base b, digit by digit. */
static double radical(uint64_t i, unsigned b)
{
	double r = 0.0, f = 1.0 / b;

	for (; i > 0; i /= b, f /= b)
		r += (double)(i % b) * f;
	return r;
}

/* The input sets before warping, against their definitions
 * (hsw-sample(1)): Halton of index i + 1 in bases 2 and 3, Hammersley
 * ((i + 1/2) / n, base 2 of i), the k x k cell centres in row order
 * with k = ceil(sqrt(n)), a jittered point inside its cell; the names
 * by value. */
static void test_hsw_input(void **state)
{
	size_t n = 10, k = 4;
	double xy[2 * 10], reg[2 * 10];
	const char *const *w = frs_names(FRS_NAMES_HSW_INPUT);
	static const char *const words[] = { "random", "regular", "jittered",
	    "halton", "hammersley" };

	(void)state;
	for (int i = 0; i < 5; i++)
		assert_string_equal(w[i], words[i]);
	assert_null(w[5]);
	assert_int_equal(frs_hsw_input(FRS_HSW_HALTON, n, 1, xy, NULL), FRS_OK);
	for (size_t i = 0; i < n; i++) {
		assert_near(xy[2 * i], radical(i + 1, 2), 1e-15);
		assert_near(xy[2 * i + 1], radical(i + 1, 3), 1e-15);
	}
	assert_int_equal(frs_hsw_input(FRS_HSW_HAMMERSLEY, n, 1, xy, NULL),
	    FRS_OK);
	for (size_t i = 0; i < n; i++) {
		assert_near(xy[2 * i], ((double)i + 0.5) / (double)n, 1e-15);
		assert_near(xy[2 * i + 1], radical(i, 2), 1e-15);
	}
	assert_int_equal(frs_hsw_input(FRS_HSW_REGULAR, n, 1, reg, NULL),
	    FRS_OK);
	assert_int_equal(frs_hsw_input(FRS_HSW_JITTERED, n, 7, xy, NULL),
	    FRS_OK);
	for (size_t i = 0; i < n; i++) {
		double cx = ((double)(i % k) + 0.5) / (double)k,
		    cy = ((double)(i / k) + 0.5) / (double)k;
		assert_near(reg[2 * i], cx, 1e-15);
		assert_near(reg[2 * i + 1], cy, 1e-15);
		assert_true(fabs(xy[2 * i] - cx) <= 0.5 / (double)k &&
		    fabs(xy[2 * i + 1] - cy) <= 0.5 / (double)k);
	}
	EXPECT(FRS_E_ARG, frs_hsw_input((enum frs_hsw_input)5, n, 1, xy, E));
	EXPECT(FRS_E_ARG, frs_hsw_input(FRS_HSW_RANDOM, n, 1, NULL, E));
	EXPECT(FRS_OK, frs_hsw_input(FRS_HSW_RANDOM, 0, 1, NULL, E));
}

/* The index of pixel (x, y) among the 4^L leaves in Morton order:
 * y's bits above x's, level by level. */
static size_t morton(uint32_t x, uint32_t y, unsigned levels)
{
	size_t m = 0;

	for (unsigned b = levels; b-- > 0;)
		m = m << 2 | (size_t)((y >> b & 1) << 1 | (x >> b & 1));
	return m;
}

/* The quadtree of a 5 x 3 map of small integers (sums exact): padded to
 * 8 x 8, three levels below the root, the pixels as leaves in Morton
 * order with zeros in the padding, every node the sum of its four
 * children; the densities I / mean at points in chosen pixels. */
static void test_hsw_info_pdf(void **state)
{
	double map[15], total = 0.0, pdf[3];
	const double pts[6] = { 0.05, 0.1, 0.99, 0.99, 0.5, 0.5 };
	struct frs_hsw_info t;
	frs_hsw *hw;
	size_t first = 0;

	(void)state;
	for (int i = 0; i < 15; i++)
		total += map[i] = (double)(i * 7 % 11 + 1);
	assert_int_equal(frs_hsw_new_f64(&hw, map, 5, 3, 0, NULL), FRS_OK);
	EXPECT(FRS_OK, frs_hsw_info(hw, &t, E));
	assert_true(t.width == 5 && t.height == 3 && t.side == 8 &&
	    t.levels == 3);
	assert_true(t.total == total && t.mean == total / 15.0);
	assert_true(t.sums[0] == total);
	for (unsigned l = 0; l < t.levels; l++) {
		size_t nodes = (size_t)1 << 2 * l, next = first + nodes;
		for (size_t k = 0; k < nodes; k++)
			assert_true(t.sums[first + k] == t.sums[next + 4 * k] +
			    t.sums[next + 4 * k + 1] + t.sums[next + 4 * k + 2] +
			    t.sums[next + 4 * k + 3]);
		first = next;
	}
	for (uint32_t y = 0; y < 8; y++)
		for (uint32_t x = 0; x < 8; x++)
			assert_true(t.sums[first + morton(x, y, 3)] ==
			    (x < 5 && y < 3 ? map[y * 5 + x] : 0.0));
	EXPECT(FRS_OK, frs_hsw_pdf(hw, pts, pdf, 3, E));
	assert_true(pdf[0] == map[0] / t.mean);	/* pixel (0, 0) */
	assert_true(pdf[1] == map[14] / t.mean);	/* (4, 2) */
	assert_true(pdf[2] == map[7] / t.mean);	/* (2, 1) */
	EXPECT(FRS_E_ARG, frs_hsw_info(NULL, &t, E));
	EXPECT(FRS_E_ARG, frs_hsw_info(hw, NULL, E));
	EXPECT(FRS_E_ARG, frs_hsw_pdf(NULL, pts, pdf, 1, E));
	EXPECT(FRS_E_ARG, frs_hsw_pdf(hw, NULL, pdf, 1, E));
	EXPECT(FRS_E_ARG, frs_hsw_pdf(hw, pts, NULL, 1, E));
	EXPECT(FRS_E_ARG, frs_hsw_pdf(hw, (const double[]){ 0.5, 1.0 }, pdf, 1,
	    E));
	EXPECT(FRS_OK, frs_hsw_pdf(hw, NULL, NULL, 0, E));
	frs_hsw_free(hw);
}

/* A callback of the error checks: it must not be reached but by a run
 * with points (then it lets it go on). */
static int count_calls(void *ctx, const double *xy, const double *pdf,
    const uint32_t *step, size_t k, uint64_t total)
{
	(void)ctx, (void)xy, (void)pdf, (void)step, (void)k;
	assert_true(total > 0);
	return 0;
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
	EXPECT(FRS_E_ARG, frs_hsw_draw_each(NULL, FRS_HSW_HALTON, NULL, 4, 1, 0,
	    1, count_calls, NULL, E));
	EXPECT(FRS_E_ARG, frs_hsw_draw_each(hw, FRS_HSW_HALTON, NULL, 4, 1, 0,
	    1, NULL, NULL, E));
	EXPECT(FRS_E_ARG, frs_hsw_draw_each(hw, (enum frs_hsw_input)5, NULL, 4,
	    1, 0, 1, count_calls, NULL, E));
	EXPECT(FRS_E_ARG, frs_hsw_draw_each(hw, FRS_HSW_HALTON, NULL, 4, 1, 0,
	    1025, count_calls, NULL, E));
	in[0] = 0.5;	/* in[3] is 1.0: outside */
	EXPECT(FRS_E_ARG, frs_hsw_draw_each(hw, FRS_HSW_HALTON, in, 2, 1, 0, 1,
	    count_calls, NULL, E));
	EXPECT(FRS_OK, frs_hsw_draw_each(hw, (enum frs_hsw_input)5, in, 1, 1, 0,
	    1, count_calls, NULL, E));
	EXPECT(FRS_OK, frs_hsw_draw_each(hw, FRS_HSW_HALTON, NULL, 0, 1, 0, 1,
	    count_calls, NULL, E));
	frs_hsw_free(hw);
	frs_hsw_free(NULL);
}

TU_MAIN(setup, teardown,
	cmocka_unit_test(test_hsw_draw),
	cmocka_unit_test(test_hsw_warp),
	cmocka_unit_test(test_hsw_negative),
	cmocka_unit_test(test_hsw_each),
	cmocka_unit_test(test_hsw_input),
	cmocka_unit_test(test_hsw_info_pdf),
	cmocka_unit_test(test_hsw_errors))
