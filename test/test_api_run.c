/*
 * The run of a sampler (frs_run_*), the mask's loading with its header's
 * dimensions and its made lists, a sampler taking a map over
 * (frs_sampler_take) and frs_draw_bytes, against the public API's own
 * answers (frs_sampler_info, frs_sampler_levels, frs_draw) and
 * independent counts: the pixels of each level found one by one, tiles
 * and plain tiles' matrix elements by their formulas.
 * The helpers: apiutil.h.
 */
#include "apiutil.h"

/* Tiles of the mask (side m) that a window of n elements at offset o
 * touches on an axis: from tile o / m to tile (o + n - 1) / m. */
static uint64_t tiles_of(uint64_t o, uint64_t n, uint64_t m)
{
	return (o + n - 1) / m - o / m + 1;
}

static frs_sampler *blob_sampler(enum frs_tiling_mode t, enum frs_rule_mode r)
{
	struct frs_options o;

	frs_options_init(&o);
	o.tiling = t;
	o.rule = r;
	return sampler_f64(mask, &blob, &o);
}

/* The run's level 0 and levels are frs_sampler_info's and
 * frs_sampler_levels'; the tiles follow from the window. */
static void test_info_levels(void **state)
{
	static const enum frs_tiling_mode tilings[] = { FRS_TILING_LEVELS,
	    FRS_TILING_PLAIN, FRS_TILING_SHUFFLED };
	uint64_t n = 300000;
	uint32_t mw, mh;

	(void)state;
	frs_mask_size(mask, &mw, &mh);
	for (size_t t = 0; t < 3; t++) {
		frs_sampler *s = blob_sampler(tilings[t], FRS_RULE_UNBIASED);
		struct frs_level_info lv[FRS_LEVELS_MAX];
		struct frs_run_info f;
		struct frs_info si;
		frs_run *r;
		unsigned nl = 0;

		EXPECT(FRS_OK, frs_sampler_info(s, n, 3, &si, E));
		EXPECT(FRS_OK, frs_sampler_levels(s, n, 3, lv, FRS_LEVELS_MAX,
		    &nl, E));
		assert_int_equal(frs_run_new(&r, s, &n, 1, 3, 0, NULL), FRS_OK);
		EXPECT(FRS_OK, frs_run_info(r, &f, E));
		assert_true(f.matrix[0] == mw && f.matrix[1] == mh &&
		    f.matrix[2] == 1);
		assert_true(f.dims == 2 && f.n == n && f.ns == si.ns &&
		    f.window[0] == si.window_w && f.window[1] == si.window_h &&
		    f.offset[0] == si.offset_x && f.offset[1] == si.offset_y);
		assert_true(f.tau == si.tau && f.tau_plain == si.tau &&
		    f.passes == 0 && f.mean == si.mean && f.max == si.max &&
		    f.unique == si.unique);
		assert_true(f.tiles[0] == tiles_of(f.offset[0], f.window[0], mw) &&
		    f.tiles[1] == tiles_of(f.offset[1], f.window[1], mh) &&
		    f.tiles[2] == 1);
		assert_int_equal(f.shuffled, tilings[t] == FRS_TILING_SHUFFLED);
		assert_int_equal(f.levels, nl);
		assert_int_equal(f.planned, tilings[t] == FRS_TILING_LEVELS);
		for (unsigned i = 0; i < nl; i++) {
			struct frs_run_level l;
			EXPECT(FRS_OK, frs_run_level(r, i, &l, E));
			assert_memory_equal(&l.info, &lv[i], sizeof lv[i]);
			assert_true(l.map[0] == blob.w && l.map[1] == blob.h &&
			    l.map[2] == 1);
		}
		EXPECT(FRS_OK, frs_run_prepare(r, E));
		frs_run_free(r);
		frs_sampler_free(s);
	}
}

/* Each pixel's level by frs_run_level_of at its centre: the levels'
 * pixel counts are theirs, each pixel lies in its level's box, and they
 * add up to the pixels of non-zero importance. */
static void test_level_of(void **state)
{
	frs_sampler *s = blob_sampler(FRS_TILING_LEVELS, FRS_RULE_UNBIASED);
	struct frs_run_level lv[FRS_LEVELS_MAX];
	struct frs_run_info f;
	uint64_t n = 300000, count[FRS_LEVELS_MAX] = { 0 }, nonzero = 0, all = 0;
	frs_run *r;

	(void)state;
	assert_int_equal(frs_run_new(&r, s, &n, 1, 3, 0, NULL), FRS_OK);
	EXPECT(FRS_OK, frs_run_info(r, &f, E));
	assert_true(f.levels >= 3);	/* blob at 300000: a few levels */
	for (unsigned i = 0; i < f.levels; i++) {
		EXPECT(FRS_OK, frs_run_level(r, i, &lv[i], E));
		assert_true(lv[i].side[0] == blob.w && lv[i].side[1] == blob.h);
	}
	for (uint32_t y = 0; y < blob.h; y++)
		for (uint32_t x = 0; x < blob.w; x++) {
			double p[2] = { (x + 0.5) / blob.w, (y + 0.5) / blob.h };
			unsigned i = frs_run_level_of(r, p);
			if (!(blob.v[(size_t)y * blob.w + x] > 0.0))
				continue;
			nonzero++;
			assert_true(i < f.levels);
			count[i]++;
			assert_true(x >= lv[i].lo[0] && x <= lv[i].hi[0] &&
			    y >= lv[i].lo[1] && y <= lv[i].hi[1]);
		}
	for (unsigned i = 0; i < f.levels; i++) {
		assert_int_equal(count[i], lv[i].info.cells);
		all += count[i];
	}
	assert_int_equal(all, nonzero);
	frs_run_free(r);
	frs_sampler_free(s);
}

/* Plain tiles: the element under point p of level 0's window is the
 * mask's at the window offset plus p's element, modulo the mask. */
static void test_element(void **state)
{
	frs_sampler *s = blob_sampler(FRS_TILING_PLAIN, FRS_RULE_UNBIASED);
	struct frs_run_info f;
	double *pts = tu_rnd_points(1000, 4);
	uint64_t n = 300000;
	uint32_t mw, mh;
	frs_run *r;

	(void)state;
	frs_mask_size(mask, &mw, &mh);
	assert_int_equal(frs_run_new(&r, s, &n, 1, 3, 0, NULL), FRS_OK);
	EXPECT(FRS_OK, frs_run_info(r, &f, E));
	for (size_t k = 0; k < 1000; k++) {
		const double *p = pts + 2 * k;
		uint64_t x = (f.offset[0] + (uint64_t)(p[0] * (double)f.window[0]))
		    % mw, y = (f.offset[1] + (uint64_t)(p[1] *
		    (double)f.window[1])) % mh;
		assert_int_equal(frs_run_element(r, 0, p), y * mw + x);
	}
	assert_true(frs_run_element(r, 1, pts) == UINT64_MAX);
	frs_run_free(r);
	frs_sampler_free(s);
	free(pts);
}

/* FRS_RUN_EXACT: the exact rule's tau, the one frs_sampler_info finds,
 * after count passes; without it the unbiased rule's. */
static void test_exact(void **state)
{
	frs_sampler *s = blob_sampler(FRS_TILING_LEVELS, FRS_RULE_EXACT);
	struct frs_run_info f, g;
	struct frs_info si;
	uint64_t n = 20000;
	frs_run *r;

	(void)state;
	EXPECT(FRS_OK, frs_sampler_info(s, n, 2, &si, E));
	assert_int_equal(frs_run_new(&r, s, &n, 1, 2, FRS_RUN_EXACT, NULL),
	    FRS_OK);
	EXPECT(FRS_OK, frs_run_info(r, &f, E));
	frs_run_free(r);
	assert_int_equal(frs_run_new(&r, s, &n, 1, 2, 0, NULL), FRS_OK);
	EXPECT(FRS_OK, frs_run_info(r, &g, E));
	frs_run_free(r);
	assert_true(f.tau == si.tau && f.passes > 0 && f.tau != f.tau_plain);
	assert_true(g.passes == 0 && g.tau == g.tau_plain &&
	    g.tau_plain == f.tau_plain);
	frs_sampler_free(s);
}

/* A 3-D run: frs_sampler3_levels' levels, three axes of tiles, no
 * elements. */
static void test_run3(void **state)
{
	struct frs_level_info lv[FRS_LEVELS_MAX];
	double *v = malloc(16 * 16 * 16 * sizeof *v), p[3] = { 0.5, 0.5, 0.5 };
	struct frs_run_info f;
	uint64_t n = 50000;
	frs_sampler3 *s;
	frs_mask *m3;
	frs_run *r;
	unsigned nl;

	(void)state;
	assert_non_null(v);
	for (int i = 0; i < 16 * 16 * 16; i++)
		v[i] = 1.0 + (i % 7 == 0 ? 500.0 : 0.0);
	assert_int_equal(frs_mask_load(&m3, MATRIX3, NULL), FRS_OK);
	assert_int_equal(frs_sampler3_new_f64(&s, m3, v, 16, 16, 16, NULL,
	    NULL), FRS_OK);
	EXPECT(FRS_OK, frs_sampler3_levels(s, n, 1, lv, FRS_LEVELS_MAX, &nl,
	    E));
	assert_int_equal(frs_run3_new(&r, s, &n, 1, 1, 0, NULL), FRS_OK);
	EXPECT(FRS_OK, frs_run_info(r, &f, E));
	assert_true(f.dims == 3 && f.levels == nl && f.tiles[2] >= 1);
	for (unsigned i = 0; i < nl; i++) {
		struct frs_run_level l;
		EXPECT(FRS_OK, frs_run_level(r, i, &l, E));
		assert_memory_equal(&l.info, &lv[i], sizeof lv[i]);
		assert_int_equal(l.map[2], 16);
	}
	assert_true(frs_run_level_of(r, p) < nl);
	assert_true(frs_run_element(r, 0, p) == UINT64_MAX);
	EXPECT(FRS_OK, frs_run_prepare(r, E));
	frs_run_free(r);
	frs_sampler3_free(s);
	frs_mask_free(m3);
	free(v);
}

/* A sampler that takes its map draws what one that copies it draws;
 * the map is the sampler's (zeroed), or released when refused. */
static void test_take(void **state)
{
	struct frs_imap m, bad;
	struct frs_imap_stats st;
	frs_sampler *s, *t;
	frs_error e;

	(void)state;
	assert_int_equal(frs_imap_load(&m, "blob", 0, 0, 0, NULL), FRS_OK);
	frs_imap_stats(&m, &st);
	s = sampler_f64(mask, &m, NULL);
	assert_int_equal(frs_sampler_take(&t, mask, &m, &st, NULL, &e), FRS_OK);
	assert_null(m.v);
	same_draw(s, t, 20000, 7);
	frs_sampler_free(t);
	/* No statistics: checked here, as frs_sampler_new checks. */
	assert_int_equal(frs_imap_load(&m, "blob", 0, 0, 0, NULL), FRS_OK);
	assert_int_equal(frs_sampler_take(&t, mask, &m, NULL, NULL, &e), FRS_OK);
	same_draw(s, t, 20000, 7);
	frs_sampler_free(t);
	frs_sampler_free(s);
	assert_int_equal(frs_imap_load(&bad, "blob", 0, 0, 0, NULL), FRS_OK);
	bad.v[5] = -1.0;
	assert_int_equal(frs_sampler_take(&t, mask, &bad, NULL, NULL, &e),
	    FRS_E_MAP);
	assert_null(t);
	assert_null(bad.v);
	EXPECT(FRS_E_ARG, frs_sampler_take(&t, mask, NULL, NULL, NULL, E));
}

/* The header's dimensions, also when the load fails after it; the lists
 * a .frp lacked, made by a draw, and the file that lacked them. */
static void test_mask_dims_made(void **state)
{
	unsigned char hdr[64];
	const char *file = NULL, *frp = tu_path("b1.frp");
	frs_mask *m = NULL;
	unsigned dims = 9;
	uint32_t one = 1;
	FILE *fp;

	(void)state;
	assert_int_equal(frs_mask_load_dims(&m, MATRIX3, &dims, NULL), FRS_OK);
	assert_int_equal(dims, 3);
	assert_int_equal(frs_mask_made(m, &file), 0);
	assert_string_equal(file, MATRIX3);
	frs_mask_free(m);
	/* The 3-D file cut after its header. */
	assert_non_null(fp = fopen(MATRIX3, "rb"));
	assert_int_equal(fread(hdr, 1, sizeof hdr, fp), sizeof hdr);
	assert_int_equal(fclose(fp), 0);
	assert_non_null(fp = fopen(tu_path("cut3.frd"), "wb"));
	assert_int_equal(fwrite(hdr, 1, sizeof hdr, fp), sizeof hdr);
	assert_int_equal(fclose(fp), 0);
	assert_int_equal(frs_mask_load_dims(&m, tu_path("cut3.frd"), &dims,
	    NULL), FRS_E_FORMAT);
	assert_int_equal(dims, 3);
	assert_null(m);
	assert_int_equal(frs_mask_load_dims(&m, "/nonexistent.frd", &dims,
	    NULL), FRS_E_IO);
	assert_int_equal(dims, 0);
	/* A .frp of a 64 x 64 matrix with lists of blocks of 1 only: a
	 * draw that reads most of its values with Sorted makes lists of
	 * larger blocks here. */
	{
		struct frs_matrix small;
		uint32_t rank = 0;
		assert_int_equal(frs_matrix_alloc(&small, 2, 64, 64, 1, "", NULL),
		    FRS_OK);
		for (size_t i = 0; i < small.n; i++)	/* a permutation */
			small.v[i] = rank = (rank + 1237) % 4096;
		assert_non_null(fp = fopen(frp, "wb"));
		assert_int_equal(frs_prepared_write(&small, fp, frp, "small", 1,
		    &one, 1, NULL), FRS_OK);
		assert_int_equal(fclose(fp), 0);
		frs_matrix_free(&small);
	}
	assert_int_equal(frs_mask_load(&m, frp, NULL), FRS_OK);
	assert_int_equal(frs_mask_made(m, NULL), 0);
	{
		struct frs_options o;
		frs_sampler *s;
		uint64_t c = 0;
		frs_options_init(&o);
		o.sigma = 1;	/* 40000 of a constant map: blocks of 2 */
		assert_int_equal(frs_sampler_new(&s, m, NULL, 128, 128, 0, &o,
		    NULL), FRS_OK);
		assert_int_equal(frs_count(s, 40000, 1, &c, NULL), FRS_OK);
		frs_sampler_free(s);
	}
	assert_int_equal(frs_mask_made(m, &file), 2);
	assert_string_equal(file, frp);
	frs_mask_free(m);
	assert_int_equal(frs_mask_made(NULL, &file), 0);
	assert_null(file);
	assert_true(frs_draw_bytes(2) > 0 && frs_draw_bytes(3) >
	    frs_draw_bytes(2) && frs_draw_bytes(1) == 0);
}

static void test_run_errors(void **state)
{
	frs_sampler *s = blob_sampler(FRS_TILING_LEVELS, FRS_RULE_UNBIASED);
	uint64_t n = 1000, bad[2] = { 500, 400 };
	struct frs_run_info f;
	struct frs_run_level l;
	frs_run *r = (frs_run *)&r;

	(void)state;
	EXPECT(FRS_E_ARG, frs_run_new(NULL, s, &n, 1, 1, 0, E));
	EXPECT(FRS_E_ARG, frs_run_new(&r, NULL, &n, 1, 1, 0, E));
	assert_null(r);
	EXPECT(FRS_E_ARG, frs_run3_new(&r, NULL, &n, 1, 1, 0, E));
	EXPECT(FRS_E_ARG, frs_run_new(&r, s, &n, 1, 1, 2, E));
	EXPECT(FRS_E_ARG, frs_run_new(&r, s, bad, 2, 1, 0, E));
	EXPECT(FRS_E_ARG, frs_run_new(&r, s, &n, 0, 1, 0, E));
	EXPECT(FRS_E_ARG, frs_run_info(NULL, &f, E));
	EXPECT(FRS_E_ARG, frs_run_prepare(NULL, E));
	assert_int_equal(frs_run_new(&r, s, &n, 1, 1, 0, NULL), FRS_OK);
	EXPECT(FRS_E_ARG, frs_run_info(r, NULL, E));
	EXPECT(FRS_E_ARG, frs_run_level(r, 0, NULL, E));
	EXPECT(FRS_E_ARG, frs_run_level(r, FRS_LEVELS_MAX, &l, E));
	frs_run_free(r);
	frs_run_free(NULL);
	frs_sampler_free(s);
}

TU_MAIN(setup, teardown,
	cmocka_unit_test(test_info_levels),
	cmocka_unit_test(test_level_of),
	cmocka_unit_test(test_element),
	cmocka_unit_test(test_exact),
	cmocka_unit_test(test_run3),
	cmocka_unit_test(test_take),
	cmocka_unit_test(test_mask_dims_made),
	cmocka_unit_test(test_run_errors))
