/*
 * Every error code of the public API that bad arguments reach, with and
 * without an frs_error (EXPECT, apiutil.h): masks, maps, samplers,
 * draws, counts far too large, short buffers, the callback form, memory
 * limits and NULL handles.
 */
#include "apiutil.h"

#include <signal.h>
#include <sys/wait.h>

static void test_code_names(void **state)
{
	static const char *const names[] = { "FRS_OK", "FRS_E_ARG",
	    "FRS_E_MAP", "FRS_E_BUFFER", "FRS_E_NOMEM", "FRS_E_IO",
	    "FRS_E_FORMAT", "FRS_E_LIMIT", "FRS_E_CALLBACK" };
	const char *v = frs_library_version();
	int a, b, c;

	(void)state;
	assert_int_equal(FRS_OK, 0);
	assert_int_equal(FRS_E_CALLBACK, 8);
	for (int i = 0; i <= FRS_E_CALLBACK; i++)
		assert_string_equal(frs_code_name(i), names[i]);
	/* Not a code: a name all the same, none of the above. */
	for (int i = -1; i < 200; i += 50) {
		const char *n = frs_code_name(i > 8 ? i : -1);
		assert_non_null(n);
		for (int k = 0; k <= FRS_E_CALLBACK; k++)
			assert_string_not_equal(n, names[k]);
	}
	assert_non_null(v);
	assert_int_equal(sscanf(v, "%d.%d.%d", &a, &b, &c), 3);
	assert_int_equal(FRS_API_VERSION_MAJOR, 2);
}

static void test_mask_errors(void **state)
{
	const char *junk = tu_path("junk.frd");
	static const uint32_t dup[16] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11,
	    12, 13, 14, 14 };
	static const uint32_t big[16] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11,
	    12, 13, 14, 16 };
	static const uint32_t v12[12] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10,
	    11 };
	frs_mask *mk = NULL;

	(void)state;
	tu_write(junk, "this is no matrix at all\n", 25);
	EXPECT(FRS_E_ARG, frs_mask_load(NULL, MATRIX, E));
	EXPECT(FRS_E_ARG, frs_mask_load(&mk, NULL, E));
	EXPECT(FRS_E_IO, frs_mask_load(&mk, tu_path("missing.frd"), E));
	EXPECT(FRS_E_IO, frs_mask_load(&mk, tu_dir(), E));
	EXPECT(FRS_E_FORMAT, frs_mask_load(&mk, junk, E));
	EXPECT(FRS_E_FORMAT, frs_mask_load(&mk, "data/sunset.exr", E));
	EXPECT(FRS_E_ARG, frs_mask_wrap(NULL, dup, 4, 4, E));
	EXPECT(FRS_E_ARG, frs_mask_wrap(&mk, NULL, 4, 4, E));
	EXPECT(FRS_E_ARG, frs_mask_wrap(&mk, dup, 4, 4, E));
	EXPECT(FRS_E_ARG, frs_mask_wrap(&mk, big, 4, 4, E));
	EXPECT(FRS_E_ARG, frs_mask_wrap(&mk, v12, 4, 3, E));
	EXPECT(FRS_E_ARG, frs_mask_wrap(&mk, v12, 3, 4, E));
	EXPECT(FRS_E_ARG, frs_mask_wrap(&mk, v12, 0, 4, E));
	EXPECT(FRS_E_ARG, frs_mask_wrap(&mk, v12, 4, 0, E));
	/* Nothing was made; freeing NULL is harmless. */
	frs_mask_free(NULL);
	frs_mask_size(NULL, NULL, NULL);
}

/* frs_default_matrix: FRS_MATRIX, then FRS_DATA alone, else the
 * directories of datadir.h (the source tree among them here). */
static void test_default_matrix(void **state)
{
	char path[4096], want[4200];
	frs_mask *mk = NULL;
	uint32_t w, h, d;
	frs_error e;

	(void)state;
	unsetenv("FRS_MATRIX");
	unsetenv("FRS_MATRIX3");
	setenv("FRS_DATA", "data", 1);
	assert_int_equal(frs_default_matrix(&mk, 2, path, sizeof path, &e),
	    FRS_OK);
	assert_string_equal(path, "data/default.frd");
	assert_string_equal(e.message, "");
	frs_mask_size(mk, &w, &h);
	assert_int_equal(w, 2048);
	assert_int_equal(h, 2048);
	assert_int_equal(frs_mask_dims(mk), 2);
	frs_mask_free(mk);
	assert_int_equal(frs_default_matrix(&mk, 3, NULL, 0, &e), FRS_OK);
	frs_mask_size3(mk, &w, &h, &d);
	assert_int_equal(frs_mask_dims(mk), 3);
	assert_int_equal(d, 64);
	frs_mask_free(mk);
	/* Only the path. */
	EXPECT(FRS_OK, frs_default_matrix(NULL, 3, path, sizeof path, E));
	assert_string_equal(path, "data/default3.frd");
	/* The path does not fit: nothing loaded. */
	mk = (frs_mask *)1;
	EXPECT(FRS_E_BUFFER, frs_default_matrix(&mk, 2, path, 16, E));
	assert_null(mk);
	EXPECT(FRS_OK, frs_default_matrix(NULL, 2, path, 17, E));
	EXPECT(FRS_E_ARG, frs_default_matrix(&mk, 1, NULL, 0, E));
	EXPECT(FRS_E_ARG, frs_default_matrix(&mk, 4, NULL, 0, E));
	EXPECT(FRS_E_ARG, frs_default_matrix(&mk, 2, path, 0, E));
	/* FRS_DATA is the only place looked at. */
	setenv("FRS_DATA", tu_dir(), 1);
	EXPECT(FRS_E_IO, frs_default_matrix(&mk, 2, NULL, 0, E));
	assert_int_equal(frs_default_matrix(&mk, 2, path, sizeof path, &e),
	    FRS_E_IO);
	assert_null(mk);
	snprintf(want, sizeof want, "no default matrix (looked for "
	    "%s/default.frd; FRS_DATA is set)", tu_dir());
	assert_string_equal(e.message, want);
	assert_string_equal(path, "");
	/* FRS_MATRIX wins, as it is: its path, then the load's error. */
	setenv("FRS_MATRIX", tu_path("missing.frd"), 1);
	EXPECT(FRS_E_IO, frs_default_matrix(&mk, 2, path, sizeof path, E));
	assert_string_equal(path, tu_path("missing.frd"));
	EXPECT(FRS_OK, frs_default_matrix(NULL, 2, path, sizeof path, E));
	setenv("FRS_MATRIX3", "data/default3.frd", 1);
	assert_int_equal(frs_default_matrix(&mk, 3, NULL, 0, &e), FRS_OK);
	assert_int_equal(frs_mask_dims(mk), 3);
	frs_mask_free(mk);
	unsetenv("FRS_MATRIX");
	unsetenv("FRS_MATRIX3");
	/* An empty FRS_DATA is unset: found without it (the source tree). */
	setenv("FRS_DATA", "", 1);
	EXPECT(FRS_OK, frs_default_matrix(NULL, 2, path, sizeof path, E));
	assert_true(strlen(path) > 12 &&
	    strcmp(path + strlen(path) - 12, "/default.frd") == 0);
	unsetenv("FRS_DATA");
}

static void test_map_errors(void **state)
{
	const char *junk = tu_path("junk.png");
	float *map = NULL;
	uint32_t w, h;

	(void)state;
	tu_write(junk, "\x89PNG\r\n\x1a\n but no more", 21);
	EXPECT(FRS_E_ARG, frs_map_load(NULL, 0, 0, &map, &w, &h, E));
	EXPECT(FRS_E_ARG, frs_map_load("blob", 0, 0, NULL, &w, &h, E));
	EXPECT(FRS_E_ARG, frs_map_load("blob", 0, 0, &map, NULL, &h, E));
	EXPECT(FRS_E_ARG, frs_map_load("blob", 0, 0, &map, &w, NULL, E));
	EXPECT(FRS_E_ARG, frs_map_load("blob", 16, 0, &map, &w, &h, E));
	EXPECT(FRS_E_ARG, frs_map_load("blob", 0, 16, &map, &w, &h, E));
	EXPECT(FRS_E_IO, frs_map_load(tu_path("missing.exr"), 0, 0, &map, &w,
	    &h, E));
	EXPECT(FRS_E_FORMAT, frs_map_load(junk, 0, 0, &map, &w, &h, E));
	EXPECT(FRS_E_FORMAT, frs_map_load(MATRIX, 0, 0, &map, &w, &h, E));
	frs_map_free(NULL);
}

/* frs_matrix_write's bytes are frd(5)'s layout (the format is the
 * contract), frs_matrix_read gives them back, 2-D and 3-D; a value seen
 * twice, a missing file, a stream that cannot be written, a parameter
 * text too long: their codes. */
static uint32_t le32(const unsigned char *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
	    (uint32_t)p[3] << 24;
}

static void matrix_round(unsigned dims, uint32_t w, uint32_t h, uint32_t d)
{
	const char *path = tu_path("m.frd");
	uint32_t v[64];
	struct frs_matrix m = { dims, w, h, d, (size_t)w * h * d, "k=v\n", v,
	    0 }, r;
	unsigned char b[32 + 4 + 4 * 64];
	FILE *fp;

	for (size_t i = 0; i < m.n; i++)
		v[i] = (uint32_t)((i * 7) % m.n);	/* 7 is prime to n */
	assert_non_null(fp = fopen(path, "wb"));
	assert_int_equal(frs_matrix_write(&m, fp, path, NULL), FRS_OK);
	assert_int_equal(fclose(fp), 0);
	assert_non_null(fp = fopen(path, "rb"));
	assert_int_equal(fread(b, 1, sizeof b, fp), 32 + 4 + 4 * m.n);
	fclose(fp);
	assert_memory_equal(b, "\211FRD\r\n\032\n", 8);
	assert_true(le32(b + 8) == 1 && le32(b + 12) == dims &&
	    le32(b + 16) == w && le32(b + 20) == h && le32(b + 24) == d &&
	    le32(b + 28) == 4);
	assert_memory_equal(b + 32, "k=v\n", 4);
	for (size_t i = 0; i < m.n; i++)
		assert_int_equal(le32(b + 36 + 4 * i), v[i]);
	assert_int_equal(frs_matrix_read(&r, path, NULL), FRS_OK);
	assert_true(r.dims == dims && r.w == w && r.h == h && r.d == d &&
	    r.n == m.n);
	assert_string_equal(r.params, "k=v\n");
	assert_memory_equal(r.v, v, m.n * sizeof *v);
	frs_matrix_free(&r);
	assert_null(r.v);
}

static void test_matrix_io(void **state)
{
	const char *path = tu_path("m.frd");
	char *longp = malloc(70000);
	uint32_t v[16];
	struct frs_matrix m = { 2, 4, 4, 1, 16, "", v, 0 }, r = { 0 };
	FILE *fp;

	(void)state;
	matrix_round(2, 8, 4, 1);
	matrix_round(3, 4, 4, 2);
	for (int i = 0; i < 16; i++)
		v[i] = (uint32_t)(i == 9 ? 3 : i);	/* 3 twice, no 9 */
	assert_non_null(fp = fopen(path, "wb"));
	assert_int_equal(frs_matrix_write(&m, fp, path, NULL), FRS_OK);
	fclose(fp);
	EXPECT(FRS_E_FORMAT, frs_matrix_read(&r, path, E));
	assert_null(r.v);
	EXPECT(FRS_E_IO, frs_matrix_read(&r, tu_path("missing.frd"), E));
	EXPECT(FRS_E_ARG, frs_matrix_read(NULL, path, E));
	EXPECT(FRS_E_ARG, frs_matrix_read(&r, NULL, E));
	assert_non_null(fp = fopen(path, "rb"));	/* not for writing */
	EXPECT(FRS_E_IO, frs_matrix_write(&m, fp, path, E));
	fclose(fp);
	assert_non_null(longp);
	memset(longp, 'x', 69999);
	longp[69999] = '\0';
	m.params = longp;
	assert_non_null(fp = fopen(path, "wb"));
	EXPECT(FRS_E_ARG, frs_matrix_write(&m, fp, path, E));
	EXPECT(FRS_E_ARG, frs_matrix_write(NULL, fp, path, E));
	fclose(fp);
	free(longp);
	frs_matrix_free(NULL);
}

/* frs_names: the programs' words by the enums' values. */
static void test_names(void **state)
{
	(void)state;
	assert_string_equal(frs_names(FRS_NAMES_ALGORITHM)[FRS_ALG_SORTED],
	    "sorted");
	assert_string_equal(frs_names(FRS_NAMES_ALGORITHM)[FRS_ALG_LEVEL2],
	    "level2");
	assert_null(frs_names(FRS_NAMES_ALGORITHM)[FRS_ALG_LEVEL2 + 1]);
	assert_string_equal(frs_names(FRS_NAMES_JITTER)[FRS_JIT_HALTON],
	    "halton");
	assert_null(frs_names(FRS_NAMES_JITTER)[FRS_JIT_RANDOM + 1]);
	assert_string_equal(frs_names(FRS_NAMES_RULE)[FRS_RULE_THESIS],
	    "thesis");
	assert_null(frs_names(FRS_NAMES_RULE)[FRS_RULE_EXACT]);
	assert_string_equal(frs_names(FRS_NAMES_TILING)[FRS_TILING_PLAIN],
	    "plain");
	assert_null(frs_names(FRS_NAMES_TILING)[FRS_TILING_PLAIN + 1]);
	assert_null(frs_names((enum frs_names)99));
}

/* frs_imap_load's codes, and the map zeroed after each failure. */
static void test_imap_errors(void **state)
{
	const char *junk = tu_path("junk.png");
	struct frs_imap m = { 1, 1, NULL };

	(void)state;
	tu_write(junk, "\x89PNG\r\n\x1a\n but no more", 21);
	EXPECT(FRS_E_ARG, frs_imap_load(NULL, "blob", 0, 0, 0, E));
	EXPECT(FRS_E_ARG, frs_imap_load(&m, NULL, 0, 0, 0, E));
	assert_int_equal(m.w, 0);
	EXPECT(FRS_E_ARG, frs_imap_load(&m, "blob", 16, 0, 0, E));
	EXPECT(FRS_E_ARG, frs_imap_load(&m, "blob:sigma=x", 0, 0, 0, E));
	EXPECT(FRS_E_IO, frs_imap_load(&m, tu_path("missing.exr"), 0, 0, 0,
	    E));
	EXPECT(FRS_E_IO, frs_imap_load(&m, tu_path(""), 0, 0, 0, E));
	EXPECT(FRS_E_FORMAT, frs_imap_load(&m, junk, 0, 0, 0, E));
	EXPECT(FRS_E_FORMAT, frs_imap_load(&m, MATRIX, 0, 0, 0, E));
	assert_null(m.v);
	assert_int_equal(m.h, 0);
	frs_imap_free(NULL);
	frs_imap_free(&m);
}

/* Maps whose values are refused: NaN, infinity, a negative value, all
 * zero; as float and as double. */
static void test_bad_maps(void **state)
{
	static const double bad[] = { NAN, INFINITY, -INFINITY, -1.0, 0.0 };
	double d[64];
	float f[64];
	frs_sampler *s = NULL;
	frs_hsw *hw = NULL;

	(void)state;
	for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
		for (int i = 0; i < 64; i++) {
			/* one bad pixel, or (for 0) all of them */
			d[i] = bad[k] == 0.0 || i == 37 ? bad[k] : 1.0;
			f[i] = (float)d[i];
		}
		EXPECT(FRS_E_MAP, frs_sampler_new_f64(&s, mask, d, 8, 8, 0, NULL,
		    E));
		EXPECT(FRS_E_MAP, frs_sampler_new(&s, mask, f, 8, 8, 0, NULL,
		    E));
		/* HSW: negative values count as zero, the rest is refused. */
		if (bad[k] == -1.0) {
			/* Not EXPECT: it calls twice, which would leak. */
			assert_int_equal(frs_hsw_new_f64(&hw, d, 8, 8, 0, NULL),
			    FRS_OK);
			frs_hsw_free(hw);
			assert_int_equal(frs_hsw_new(&hw, f, 8, 8, 0, NULL),
			    FRS_OK);
			frs_hsw_free(hw);
		} else {
			EXPECT(FRS_E_MAP, frs_hsw_new_f64(&hw, d, 8, 8, 0, E));
			EXPECT(FRS_E_MAP, frs_hsw_new(&hw, f, 8, 8, 0, E));
		}
	}
	/* Only negative and zero values: nothing to sample. */
	for (int i = 0; i < 64; i++)
		d[i] = i % 2 ? -1.0 : 0.0;
	EXPECT(FRS_E_MAP, frs_hsw_new_f64(&hw, d, 8, 8, 0, E));
	/* The map files: any code but FRS_OK; see the report for which. */
	for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
		struct frs_imap m;
		const char *path;
		float *map = NULL;
		uint32_t w, h;
		frs_error e;
		int rc, q;
		assert_int_equal(imap_alloc(&m, 8, 8), 0);
		for (int i = 0; i < 64; i++)
			m.v[i] = bad[k] == 0.0 || i == 37 ? bad[k] : 1.0;
		path = write_exr("bad.exr", &m);
		q = quiet_begin();
		rc = frs_map_load(path, 0, 0, &map, &w, &h, &e);
		quiet_end(q, "frs_map_load");
		if (bad[k] == -1.0 && rc == FRS_OK) {
			/* Clamped to zero, as frs-sample does. */
			for (int i = 0; i < 64; i++)
				assert_true(map[i] == (i == 37 ? 0.0f : 1.0f));
			frs_map_free(map);
		} else if (rc != FRS_E_MAP) {
			print_error("frs_map_load of a map with %g: %s\n", bad[k],
			    frs_code_name(rc));
			fail();
		} else {
			assert_null(map);
		}
		imap_free(&m);
	}
}

static frs_sampler *blob_sampler(void)
{
	return sampler_f64(mask, &blob, NULL);
}

/* frs_sampler_new with the default options but FIELD = VALUE: FRS_E_ARG
 * (EXPECT). */
#define EXPECT_BAD_OPTION(field, value) do { \
	frs_options_init(&o); \
	o.field = (value); \
	EXPECT(FRS_E_ARG, frs_sampler_new(&s, mask, NULL, 8, 8, 0, &o, E)); \
} while (0)

static void test_sampler_errors(void **state)
{
	static const double one[16] = { 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1,
	    1, 1, 1 };
	frs_sampler *s = NULL;
	struct frs_options o;

	(void)state;
	EXPECT(FRS_E_ARG, frs_sampler_new(NULL, mask, NULL, 8, 8, 0, NULL, E));
	EXPECT(FRS_E_ARG, frs_sampler_new(&s, NULL, NULL, 8, 8, 0, NULL, E));
	EXPECT(FRS_E_ARG, frs_sampler_new(&s, mask, NULL, 0, 8, 0, NULL, E));
	EXPECT(FRS_E_ARG, frs_sampler_new(&s, mask, NULL, 8, 0, 0, NULL, E));
	EXPECT(FRS_E_ARG, frs_sampler_new_f64(NULL, mask, one, 4, 4, 0, NULL,
	    E));
	EXPECT(FRS_E_ARG, frs_sampler_new_f64(&s, NULL, one, 4, 4, 0, NULL, E));
	EXPECT(FRS_E_ARG, frs_sampler_new_f64(&s, mask, one, 0, 4, 0, NULL, E));
	EXPECT(FRS_E_ARG, frs_sampler_new_f64(&s, mask, one, 4, 0, 0, NULL, E));
	EXPECT(FRS_E_ARG, frs_sampler_new_f64(&s, mask, one, 4, 4, 3, NULL, E));
	EXPECT(FRS_E_ARG, frs_sampler_new_f64(&s, mask, one, 8, 2, 7, NULL, E));
	/* A size beyond what a map may have. */
	EXPECT(FRS_E_LIMIT, frs_sampler_new(&s, mask, NULL, 1u << 20, 1u << 20,
	    0, NULL, E));
	/* Options. */
	{
		static const double sig[] = { -1.0, 0.5, NAN, -INFINITY,
		    INFINITY, 1025.0 };
		for (size_t i = 0; i < sizeof sig / sizeof sig[0]; i++)
			EXPECT_BAD_OPTION(sigma, sig[i]);
	}
	EXPECT_BAD_OPTION(algorithm, (enum frs_algorithm)5);
	EXPECT_BAD_OPTION(algorithm, (enum frs_algorithm)-1);
	EXPECT_BAD_OPTION(jitter, (enum frs_jitter_mode)3);
	EXPECT_BAD_OPTION(rule, (enum frs_rule_mode)3);
	EXPECT_BAD_OPTION(threads, -1);
	EXPECT_BAD_OPTION(tiling, (enum frs_tiling_mode)3);
	EXPECT_BAD_OPTION(level_blur, -1.0);
	EXPECT_BAD_OPTION(level_blur, 1e4 + 1);
	EXPECT_BAD_OPTION(level_blur, NAN);
	/* The defaults, and a good call clears err. */
	frs_options_init(&o);
	assert_true(o.sigma == 8.0);
	assert_int_equal(o.algorithm, FRS_ALG_SORTED);
	assert_int_equal(o.jitter, FRS_JIT_NONE);
	assert_int_equal(o.rule, FRS_RULE_UNBIASED);
	assert_int_equal(o.threads, 1);
	assert_int_equal(o.tiling, FRS_TILING_LEVELS);
	assert_int_equal(FRS_TILING_LEVELS, 0);
	assert_true(o.level_blur == 0.0);
	EXPECT(FRS_OK, frs_sampler_new(&s, mask, NULL, 8, 8, 0, &o, E) ==
	    FRS_OK ? (frs_sampler_free(s), FRS_OK) : FRS_E_ARG);
	frs_sampler_free(NULL);
}

static void test_draw_errors(void **state)
{
	frs_sampler *s = blob_sampler();
	static const uint64_t st_eq[] = { 500, 500 }, st_dn[] = { 900, 500 },
	    st_zero[] = { 0, 500 };
	uint64_t st17[17], c64;
	struct frs_info in;
	double xy[16];
	size_t c;
	uint32_t step[8];

	(void)state;
	for (int i = 0; i < 17; i++)
		st17[i] = 100 * (uint64_t)(i + 1);
	EXPECT(FRS_E_ARG, frs_draw(s, 100, 1, xy, NULL, 8, NULL, E));
	EXPECT(FRS_E_ARG, frs_draw(s, 100, 1, NULL, NULL, 8, &c, E));
	EXPECT(FRS_E_ARG, frs_draw(s, 0, 1, xy, NULL, 8, &c, E));
	EXPECT(FRS_E_ARG, frs_count(s, 100, 1, NULL, E));
	EXPECT(FRS_E_ARG, frs_count(s, 0, 1, &c64, E));
	EXPECT(FRS_E_ARG, frs_sampler_info(s, 100, 1, NULL, E));
	EXPECT(FRS_E_ARG, frs_sampler_info(s, 0, 1, &in, E));
	/* Steps. */
	EXPECT(FRS_E_ARG, frs_draw_progressive(s, NULL, 1, 1, xy, NULL, step,
	    8, &c, E));
	EXPECT(FRS_E_ARG, frs_draw_progressive(s, st17, 0, 1, xy, NULL, step,
	    8, &c, E));
	EXPECT(FRS_E_ARG, frs_draw_progressive(s, st17, 17, 1, xy, NULL, step,
	    8, &c, E));
	EXPECT(FRS_E_ARG, frs_draw_progressive(s, st_eq, 2, 1, xy, NULL, step,
	    8, &c, E));
	EXPECT(FRS_E_ARG, frs_draw_progressive(s, st_dn, 2, 1, xy, NULL, step,
	    8, &c, E));
	EXPECT(FRS_E_ARG, frs_draw_progressive(s, st_zero, 2, 1, xy, NULL,
	    step, 8, &c, E));
	EXPECT(FRS_E_ARG, frs_draw_progressive(s, st_eq, 2, 1, xy, NULL, step,
	    8, NULL, E));
	/* Sixteen steps are allowed (too many samples for 8 here). */
	EXPECT(FRS_E_BUFFER, frs_draw_progressive(s, st17, 16, 1, xy, NULL,
	    step, 8, &c, E));
	EXPECT(FRS_E_ARG, frs_draw_each(s, st17, 17, 1, 0, NULL, NULL, E));
	frs_sampler_free(s);
}

/* Run call(s, n) in a child process that must return one of the codes
 * want0, want1 within secs seconds: a call that would run for hours
 * fails the test instead of hanging it.  No cmocka in the child. */
static void in_child(const char *what, int (*call)(const frs_sampler *,
    uint64_t), const frs_sampler *s, uint64_t n, int want0, int want1)
{
	pid_t pid = fork();
	int st = 0;

	assert_true(pid >= 0);
	if (pid == 0) {
		int rc;
		alarm(10);
		rc = call(s, n);
		if (rc != want0 && rc != want1)
			fprintf(stderr, "%s of %llu: %s\n", what,
			    (unsigned long long)n, frs_code_name(rc));
		_exit(rc == want0 || rc == want1 ? 0 : 1);
	}
	assert_int_equal(waitpid(pid, &st, 0), pid);
	if (WIFSIGNALED(st) && WTERMSIG(st) == SIGALRM) {
		print_error("%s of %llu: still running after 10 s\n", what,
		    (unsigned long long)n);
		fail();
	}
	assert_true(WIFEXITED(st) && WEXITSTATUS(st) == 0);
}

static int huge_count(const frs_sampler *s, uint64_t n)
{
	uint64_t c;

	return frs_count(s, n, 1, &c, NULL);
}

static int huge_draw(const frs_sampler *s, uint64_t n)
{
	double xy[2];
	size_t c;
	frs_error e;
	int rc = frs_draw(s, n, 1, xy, NULL, 1, &c, &e);

	return e.code == (enum frs_code)rc ? rc : -1;
}

/* Counts far beyond any matrix: FRS_E_LIMIT (the draw may also say
 * FRS_E_NOMEM), soon. */
static void huge_n(uint64_t n)
{
	frs_sampler *s = blob_sampler();

	in_child("frs_count", huge_count, s, n, FRS_E_LIMIT, FRS_E_LIMIT);
	in_child("frs_draw", huge_draw, s, n, FRS_E_LIMIT, FRS_E_NOMEM);
	frs_sampler_free(s);
}

static void test_huge_n(void **state)
{
	(void)state;
	huge_n(UINT64_MAX);
	huge_n((uint64_t)1 << 62);
}

/* FRS_E_BUFFER: the count, nothing written; then that room is enough. */
static void test_buffer(void **state)
{
	frs_sampler *s = blob_sampler();
	uint64_t n = 2000, want = 0;
	size_t c = 0, c2 = 0;
	double *xy, *pdf, *xy2;
	frs_error e;

	(void)state;
	assert_int_equal(frs_count(s, n, 4, &want, NULL), FRS_OK);
	xy = malloc(2 * want * sizeof *xy);
	pdf = malloc(want * sizeof *pdf);
	xy2 = malloc(2 * want * sizeof *xy2);
	assert_non_null(xy);
	assert_non_null(pdf);
	assert_non_null(xy2);
	for (size_t i = 0; i < 2 * want; i++)
		xy[i] = 42.0;
	for (size_t i = 0; i < want; i++)
		pdf[i] = 42.0;
	EXPECT(FRS_E_BUFFER, frs_draw(s, n, 4, xy, pdf, want - 1, &c, E));
	assert_int_equal(c, want);
	for (size_t i = 0; i < 2 * want; i++)
		assert_true(xy[i] == 42.0);
	for (size_t i = 0; i < want; i++)
		assert_true(pdf[i] == 42.0);
	EXPECT(FRS_E_BUFFER, frs_draw(s, n, 4, xy, NULL, 10, &c, E));
	assert_int_equal(c, want);
	EXPECT(FRS_E_BUFFER, frs_draw(s, n, 4, NULL, NULL, 0, &c, E));
	assert_int_equal(c, want);
	assert_int_equal(frs_draw(s, n, 4, xy, pdf, c, &c2, &e), FRS_OK);
	assert_int_equal(c2, want);
	for (size_t i = 0; i < 2 * want; i++)
		assert_true(xy[i] >= 0.0 && xy[i] < 1.0);
	for (size_t i = 0; i < want; i++)
		assert_true(pdf[i] > 0.0);
	/* More room changes nothing; no pdf, the same points. */
	free(xy2);
	xy2 = malloc(2 * (want + 100) * sizeof *xy2);
	assert_non_null(xy2);
	assert_int_equal(frs_draw(s, n, 4, xy2, NULL, want + 100, &c2, NULL),
	    FRS_OK);
	assert_int_equal(c2, want);
	assert_memory_equal(xy, xy2, 2 * want * sizeof *xy);
	free(xy);
	free(xy2);
	free(pdf);
	frs_sampler_free(s);
}

/* The callback form: the batches make up frs_draw_progressive's output. */
struct gather {
	struct drawn d;
	size_t cap, calls, stop_at;
	uint64_t total;
	int want_pdf, steps, bad;
};

static int gather(void *ctx, const double *xy, const double *pdf,
    const uint32_t *step, size_t k, uint64_t total)
{
	struct gather *g = ctx;

	g->calls++;
	if (g->calls == 1)
		g->total = total;
	if (k == 0 || total != g->total || g->d.n + k > g->cap ||
	    (pdf != NULL) != g->want_pdf || (step != NULL) != g->steps)
		g->bad = 1;
	if (!g->bad) {
		memcpy(g->d.xy + 2 * g->d.n, xy, 2 * k * sizeof *xy);
		if (pdf)
			memcpy(g->d.pdf + g->d.n, pdf, k * sizeof *pdf);
		if (step)
			memcpy(g->d.step + g->d.n, step, k * sizeof *step);
		g->d.n += k;
	}
	return g->stop_at != 0 && g->calls == g->stop_at;
}

static void each_case(const frs_sampler *s, const uint64_t *steps,
    unsigned nsteps, int want_pdf)
{
	struct drawn ref = draw(s, steps, nsteps, 3, want_pdf);
	struct gather g;

	memset(&g, 0, sizeof g);
	g.cap = ref.n;
	g.want_pdf = want_pdf;
	g.steps = nsteps > 1;
	g.d.xy = malloc(2 * ref.n * sizeof(double));
	g.d.pdf = malloc(ref.n * sizeof(double));
	g.d.step = malloc(ref.n * sizeof(uint32_t));
	EXPECT(FRS_OK, (g.d.n = 0, g.calls = 0, frs_draw_each(s, steps, nsteps,
	    3, want_pdf, gather, &g, E)));
	assert_false(g.bad);
	assert_int_equal(g.d.n, ref.n);
	assert_int_equal(g.total, ref.n);
	assert_true(g.calls >= 1);
	assert_memory_equal(g.d.xy, ref.xy, 2 * ref.n * sizeof(double));
	if (want_pdf)
		assert_memory_equal(g.d.pdf, ref.pdf, ref.n * sizeof(double));
	if (nsteps > 1)
		assert_memory_equal(g.d.step, ref.step,
		    ref.n * sizeof(uint32_t));
	drawn_free(&g.d);
	drawn_free(&ref);
}

static void test_each(void **state)
{
	frs_sampler *s = blob_sampler();
	static const uint64_t steps[] = { 2000, 9000, 20000 };
	uint64_t n = 20000;
	struct gather g;

	(void)state;
	each_case(s, &n, 1, 0);
	each_case(s, &n, 1, 1);
	each_case(s, steps, 3, 1);
	each_case(s, steps, 3, 0);
	/* A callback that asks to stop: no call after that one. */
	memset(&g, 0, sizeof g);
	g.cap = 40000;
	g.d.xy = malloc(2 * g.cap * sizeof(double));
	g.d.pdf = malloc(g.cap * sizeof(double));
	g.d.step = malloc(g.cap * sizeof(uint32_t));
	g.stop_at = 2;
	EXPECT(FRS_E_CALLBACK, (g.calls = 0, g.d.n = 0, frs_draw_each(s, &n, 1,
	    3, 0, gather, &g, E)));
	assert_int_equal(g.calls, 2);
	g.stop_at = 1;
	EXPECT(FRS_E_CALLBACK, (g.calls = 0, g.d.n = 0, frs_draw_each(s, &n, 1,
	    3, 0, gather, &g, E)));
	assert_int_equal(g.calls, 1);
	drawn_free(&g.d);
	EXPECT(FRS_E_ARG, frs_draw_each(s, &n, 1, 3, 0, NULL, NULL, E));
	EXPECT(FRS_E_ARG, frs_draw_each(s, NULL, 1, 3, 0, gather, &g, E));
	frs_sampler_free(s);
}

/* FRS_MAX_MEM below what a load needs: FRS_E_NOMEM. */
static void test_nomem(void **state)
{
	frs_mask *mk = NULL;
	frs_sampler *s = NULL;
	frs_hsw *hw = NULL;
	float *map = NULL;
	uint32_t w, h;

	(void)state;
	assert_int_equal(setenv("FRS_MAX_MEM", "1k", 1), 0);
	EXPECT(FRS_E_NOMEM, frs_mask_load(&mk, MATRIX, E));
	EXPECT(FRS_E_NOMEM, frs_map_load("blob", 0, 0, &map, &w, &h, E));
	EXPECT(FRS_E_NOMEM, frs_map_load("data/sunset.exr", 0, 0, &map, &w, &h,
	    E));
	EXPECT(FRS_E_NOMEM, frs_sampler_new_f64(&s, mask, blob.v, blob.w,
	    blob.h, 0, NULL, E));
	EXPECT(FRS_E_NOMEM, frs_hsw_new_f64(&hw, blob.v, blob.w, blob.h, 0,
	    E));
	assert_int_equal(unsetenv("FRS_MAX_MEM"), 0);
	EXPECT(FRS_OK, frs_map_load("blob", 0, 0, &map, &w, &h, E) == FRS_OK ?
	    (frs_map_free(map), FRS_OK) : FRS_E_ARG);
}

static int unset_max_mem(void **state)
{
	(void)state;
	return unsetenv("FRS_MAX_MEM");
}

/* A NULL sampler or mask for every function that takes one (last: a
 * crash here would end the run). */
static void test_null_handles(void **state)
{
	uint64_t n = 100, c64;
	double xy[8], pdf[4];
	uint32_t step[4];
	struct frs_info in;
	size_t c;
	uint32_t w = 7, h = 7;

	(void)state;
	EXPECT(FRS_E_ARG, frs_draw(NULL, n, 1, xy, NULL, 4, &c, E));
	EXPECT(FRS_E_ARG, frs_draw_progressive(NULL, &n, 1, 1, xy, pdf, step,
	    4, &c, E));
	EXPECT(FRS_E_ARG, frs_count(NULL, n, 1, &c64, E));
	EXPECT(FRS_E_ARG, frs_sampler_info(NULL, n, 1, &in, E));
	EXPECT(FRS_E_ARG, frs_draw_each(NULL, &n, 1, 3, 0, gather, NULL, E));
	assert_null(frs_mask_note(NULL));
	frs_mask_size(NULL, &w, &h);
	assert_int_equal(w, 0);
	assert_int_equal(h, 0);
}

TU_MAIN(setup, teardown,
	cmocka_unit_test(test_code_names),
	cmocka_unit_test(test_mask_errors),
	cmocka_unit_test(test_default_matrix),
	cmocka_unit_test(test_map_errors),
	cmocka_unit_test(test_imap_errors),
	cmocka_unit_test(test_names),
	cmocka_unit_test(test_matrix_io),
	cmocka_unit_test(test_bad_maps),
	cmocka_unit_test(test_sampler_errors),
	cmocka_unit_test(test_draw_errors),
	cmocka_unit_test(test_huge_n),
	cmocka_unit_test(test_buffer),
	cmocka_unit_test(test_each),
	cmocka_unit_test_teardown(test_nomem, unset_max_mem),
	cmocka_unit_test(test_null_handles))
