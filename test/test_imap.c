/* Importance maps in memory: statistics, validation, area-weighted
 * resampling and the equirectangular weight, against closed forms. */
#include "testutil.h"
#include "maps/imap.h"
#include "maps/exrio.h"
#include "maps/mapload.h"

#include <math.h>


static void fill(struct frs_imap *m, uint32_t w, uint32_t h,
    double (*f)(uint32_t, uint32_t))
{
	assert_int_equal(imap_alloc(m, w, h), 0);
	for (uint32_t y = 0; y < h; y++)
		for (uint32_t x = 0; x < w; x++)
			m->v[(size_t)y * w + x] = f(x, y);
}

static double f_xy(uint32_t x, uint32_t y) { return x + 10.0 * y + 1.0; }
static double f_one(uint32_t x, uint32_t y) { (void)x; (void)y; return 1.0; }

static void stats(void **state)
{
	struct frs_imap m;
	struct frs_imap_stats s;
	(void)state;

	/* 1e16 + 4094 ones - 1e16: a naive sum loses every one. */
	assert_int_equal(imap_alloc(&m, 64, 64), 0);
	m.v[0] = 1e16;
	for (int i = 1; i < 4095; i++)
		m.v[i] = 1.0;
	m.v[4095] = -1e16;
	imap_stats(&m, &s);
	assert_true(s.sum == 4094.0);
	assert_int_equal(s.negatives, 1);
	assert_true(s.min_negative == -1e16);
	assert_int_equal(s.neg_x, 63);
	assert_int_equal(s.neg_y, 63);
	m.v[5] = 0.0;
	m.v[70] = NAN;
	imap_stats(&m, &s);
	assert_int_equal(s.zeros, 1);
	assert_int_equal(s.nonfinite, 1);
	assert_int_equal(s.bad_x, 6);
	assert_int_equal(s.bad_y, 1);
	assert_true(s.min_positive == 1.0);
	imap_free(&m);
}

static void validate(void **state)
{
	struct frs_imap m;
	unsigned long w0;
	(void)state;

	fill(&m, 8, 4, f_one);
	m.v[2 * 8 + 3] = NAN;
	assert_int_equal(imap_validate(&m, "map.exr", 0), -1);
	assert_err_has("map.exr", "pixel (3, 2)", "NaN");
	m.v[2 * 8 + 3] = -INFINITY;
	assert_int_equal(imap_validate(&m, "map.exr", 0), -1);
	assert_err_has("pixel (3, 2)", "infinite");
	m.v[2 * 8 + 3] = -0.5;
	m.v[7] = -0.25;
	assert_int_equal(imap_validate(&m, "map.exr", FRS_MAP_STRICT), -1);
	assert_err_has("pixel (7, 0)", "negative", "2 negative", "-0.5");
	frs_set_quiet(1);
	w0 = frs_warn_count();
	assert_int_equal(imap_validate(&m, "map.exr", 0), 0);
	assert_int_equal(frs_warn_count(), w0 + 1);	/* one warning */
	assert_true(m.v[7] == 0.0 && m.v[19] == 0.0);
	for (size_t i = 0; i < 32; i++)
		m.v[i] = 0.0;
	assert_int_equal(imap_validate(&m, "map.exr", 0), -1);
	assert_err_has("map.exr", "zero everywhere");
	assert_int_equal(imap_validate(&m, "map.exr", FRS_MAP_ALLOW_ZERO), 0);
	imap_free(&m);
	assert_int_equal(imap_alloc(&m, 0, 5), -1);
	assert_int_equal(imap_alloc(&m, 70000, 1), -1);
}

/* Integer factors: each target pixel is the mean of its source block. */
static void resample_blocks(void **state)
{
	struct frs_imap a, b;
	(void)state;

	fill(&a, 8, 6, f_xy);
	assert_int_equal(imap_resample(&a, 4, 2, &b), 0);
	for (uint32_t y = 0; y < 2; y++)
		for (uint32_t x = 0; x < 4; x++) {
			double s = 0.0;
			for (uint32_t j = 0; j < 3; j++)
				for (uint32_t i = 0; i < 2; i++)
					s += f_xy(2 * x + i, 3 * y + j);
			assert_double_equal(b.v[y * 4 + x], s / 6.0, 1e-12);
		}
	imap_free(&b);
	/* Upsampling by 3 repeats each pixel. */
	assert_int_equal(imap_resample(&a, 24, 18, &b), 0);
	for (uint32_t y = 0; y < 18; y++)
		for (uint32_t x = 0; x < 24; x++)
			assert_double_equal(b.v[y * 24 + x], f_xy(x / 3, y / 3),
			    1e-12);
	imap_free(&b);
	imap_free(&a);
}

/* Any factor keeps the integral (mean) and a constant map constant. */
static void resample_mass(void **state)
{
	struct frs_imap a, b;
	struct frs_imap_stats sa, sb;
	static const uint32_t sz[][2] = { { 5, 3 }, { 7, 11 }, { 1, 1 },
	    { 13, 2 }, { 100, 37 } };
	(void)state;

	fill(&a, 17, 9, f_xy);
	imap_stats(&a, &sa);
	for (size_t k = 0; k < sizeof sz / sizeof sz[0]; k++) {
		assert_int_equal(imap_resample(&a, sz[k][0], sz[k][1], &b), 0);
		imap_stats(&b, &sb);
		assert_double_equal(sb.mean, sa.mean, 1e-12 * sa.mean);
		assert_true(sb.min >= sa.min - 1e-12 && sb.max <= sa.max + 1e-12);
		imap_free(&b);
	}
	imap_free(&a);
	fill(&a, 7, 3, f_one);
	assert_int_equal(imap_resample(&a, 5, 4, &b), 0);
	for (size_t i = 0; i < 20; i++)
		assert_double_equal(b.v[i], 1.0, 1e-14);
	imap_free(&b);
	imap_free(&a);
}

/* Row weights are the mean of sin(theta) over each row; over the whole
 * sphere they average 2 / pi. */
static void equirect(void **state)
{
	struct frs_imap m;
	struct frs_imap_stats s;
	(void)state;

	fill(&m, 4, 8, f_one);
	imap_equirect(&m);
	for (uint32_t y = 0; y < 8; y++) {
		double t0 = PI * y / 8, t1 = PI * (y + 1) / 8;
		double want = (cos(t0) - cos(t1)) / (t1 - t0);
		assert_double_equal(m.v[y * 4 + 1], want, 1e-14);
	}
	assert_true(m.v[0] == m.v[7 * 4]);	/* symmetric about the equator */
	imap_stats(&m, &s);
	assert_double_equal(s.mean, 2.0 / PI, 1e-14);
	imap_free(&m);
}

/* Loading dispatches by magic and resamples on request; a file's NaN is
 * reported at the file's own pixel. */
static void load(void **state)
{
	struct frs_imap a, b;
	const char *p = tu_path("m.exr");
	FILE *fp;
	(void)state;

	fill(&a, 16, 8, f_xy);
	a.v[5 * 16 + 9] = NAN;
	fp = fopen(p, "wb");
	assert_int_equal(imap_write_exr(fp, p, &a), 0);
	fclose(fp);
	assert_int_equal(imap_load(p, 4, 4, 0, &b), -1);
	assert_err_has(p, "pixel (9, 5)", "NaN");
	a.v[5 * 16 + 9] = 1.0;
	fp = fopen(p, "wb");
	assert_int_equal(imap_write_exr(fp, p, &a), 0);
	fclose(fp);
	assert_int_equal(imap_load(p, 8, 4, 0, &b), 0);
	assert_int_equal(b.w, 8);
	assert_int_equal(b.h, 4);
	imap_free(&b);
	assert_int_equal(imap_load(p, 0, 0, 0, &b), 0);
	assert_int_equal(b.w, 16);
	assert_double_equal(b.v[3 * 16 + 2], f_xy(2, 3), 1e-6);
	imap_free(&b);
	tu_write(tu_path("junk.bin"), "hello world", 11);
	assert_int_equal(imap_load(tu_path("junk.bin"), 0, 0, 0, &b), -1);
	assert_err_has("junk.bin", "not a PNG or OpenEXR");
	tu_write(tu_path("empty.png"), "", 0);
	assert_int_equal(imap_load(tu_path("empty.png"), 0, 0, 0, &b), -1);
	assert_err_has("empty.png", "empty file");
	assert_int_equal(imap_load("nosuchmap", 0, 0, 0, &b), -1);
	assert_err_has("nosuchmap", "no such file");
	assert_int_equal(imap_load("const:0", 0, 0, 0, &b), -1);
	assert_err_has("const:0", "zero everywhere");
	imap_free(&a);
}

TU_MAIN(NULL, tu_teardown,
	cmocka_unit_test(stats),
	cmocka_unit_test(validate),
	cmocka_unit_test(resample_blocks),
	cmocka_unit_test(resample_mass),
	cmocka_unit_test(equirect),
	cmocka_unit_test(load))
