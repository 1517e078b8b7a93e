/*
 * The levels and the map helpers of API 2.0 (zeroed options,
 * frs_sampler_levels against frs-sample -v, frs_map_equirect) and
 * frs_set_progress.  The helpers: apiutil.h.
 */
#include "apiutil.h"

#include <pthread.h>

/* ---- the levels and the map helpers of API 2.0 ------------------------ */

/* A zeroed struct frs_options is an initialised one: the same samples,
 * bit for bit, on a map of several levels. */
static void test_zeroed_options(void **state)
{
	struct frs_options z, d;
	frs_sampler *a, *b;
	uint64_t n = 20000;

	(void)state;
	memset(&z, 0, sizeof z);
	frs_options_init(&d);
	a = sampler_f64(mask, &blob, &z);
	b = sampler_f64(mask, &blob, &d);
	same_draw(a, b, n, 3);
	frs_sampler_free(a);
	frs_sampler_free(b);
}

/* frs_sampler_levels: the levels frs-sample -v lists (level, n_s,
 * window, offset, pixels, tau), their pixels all the map's pixels of
 * non-zero importance, tau 4^l times level 0's (frs_sampler_info's);
 * cap and count; one level with plain tiles, level 0's setup. */
static void test_levels(void **state)
{
	const char *err = tu_path("lv.txt");
	struct frs_imap sky;
	frs_sampler *s;
	struct frs_level_info lv[FRS_LEVELS_MAX];
	struct frs_info in;
	struct frs_options o;
	char line[1024];
	unsigned n = 0, k = 0, c1 = 0;
	uint64_t cells = 0;
	FILE *fp;

	(void)state;
	assert_int_equal(imap_load("sky", 0, 0, 0, &sky), 0);
	s = sampler_f64(mask, &sky, NULL);
	assert_int_equal(frs_sampler_levels(s, 20000, 7, lv, FRS_LEVELS_MAX, &n,
	    NULL), FRS_OK);
	assert_int_equal(frs_sampler_info(s, 20000, 7, &in, NULL), FRS_OK);
	assert_true(n >= 3);
	prog("frs-sample -m %s -i sky -n 20000 -S 7 -v -o /dev/null 2>%s",
	    MATRIX, err);
	fp = fopen(err, "r");
	assert_non_null(fp);
	while (fgets(line, sizeof line, fp) != NULL) {
		unsigned l, ns;
		unsigned long long ww, wh, ox, oy, px;
		double tau;
		if (sscanf(line, "frs-sample:   level %u: n_s %u, window %llux%llu "
		    "at (%llu, %llu), tau %lg, %llu pixels", &l, &ns, &ww, &wh,
		    &ox, &oy, &tau, &px) != 8)
			continue;
		assert_true(k < n);
		assert_int_equal(lv[k].level, l);
		assert_int_equal(lv[k].ns, ns);
		assert_int_equal(lv[k].window[0], ww);
		assert_int_equal(lv[k].window[1], wh);
		assert_int_equal(lv[k].offset[0], ox);
		assert_int_equal(lv[k].offset[1], oy);
		assert_int_equal(lv[k].cells, px);
		assert_near(lv[k].tau, tau, 1e-8 * tau);
		assert_true(lv[k].tau == ldexp(in.tau, 2 * (int)l));
		assert_int_equal(lv[k].ns << l, in.ns);
		assert_true(k == 0 || lv[k].level > lv[k - 1].level);
		cells += lv[k].cells;
		k++;
	}
	fclose(fp);
	assert_int_equal(k, n);
	for (size_t i = 0; i < (size_t)sky.w * sky.h; i++)
		cells -= sky.v[i] > 0.0;
	assert_true(cells == 0);
	/* cap 1: one filled, the count still all; cap 0 with NULL */
	memset(lv, 0, sizeof lv);
	assert_int_equal(frs_sampler_levels(s, 20000, 7, lv, 1, &c1, NULL),
	    FRS_OK);
	assert_int_equal(c1, n);
	assert_true(lv[0].ns > 0 && lv[1].ns == 0);
	assert_int_equal(frs_sampler_levels(s, 20000, 7, NULL, 0, &c1, NULL),
	    FRS_OK);
	EXPECT(FRS_E_ARG, frs_sampler_levels(s, 20000, 7, NULL, 1, &c1, E));
	EXPECT(FRS_E_ARG, frs_sampler_levels(s, 20000, 7, lv, 1, NULL, E));
	EXPECT(FRS_E_ARG, frs_sampler_levels(NULL, 20000, 7, lv, 1, &c1, E));
	EXPECT(FRS_E_ARG, frs_sampler_levels(s, 0, 7, lv, 1, &c1, E));
	frs_sampler_free(s);
	frs_options_init(&o);
	o.tiling = FRS_TILING_PLAIN;
	s = sampler_f64(mask, &sky, &o);
	assert_int_equal(frs_sampler_levels(s, 20000, 7, lv, FRS_LEVELS_MAX, &n,
	    NULL), FRS_OK);
	assert_int_equal(n, 1);
	assert_int_equal(lv[0].level, 0);
	assert_int_equal(lv[0].ns, in.ns);
	assert_int_equal(lv[0].window[0], in.window_w);
	assert_true(lv[0].tau == in.tau);
	frs_sampler_free(s);
	imap_free(&sky);
}

/* frs_map_equirect: row j times the mean of sin over its band, in
 * closed form ((cos t0 - cos t1) / (t1 - t0)); the float and double
 * forms alike, stride kept; and frs-sample --equirect's samples are
 * those of a sampler of the weighted map. */
static void test_equirect(void **state)
{
	float f[3 * 5];
	double d[3 * 4];
	struct frs_imap m;
	frs_sampler *s;
	uint64_t n = 3000;

	(void)state;
	for (int i = 0; i < 15; i++)
		f[i] = 2.0f;
	for (int i = 0; i < 12; i++)
		d[i] = 1.0;
	frs_map_equirect(f, 4, 3, 5);
	frs_map_equirect_f64(d, 4, 3, 0);
	for (int j = 0; j < 3; j++) {
		double t0 = PI * j / 3, t1 = PI * (j + 1) / 3;
		double w = (cos(t0) - cos(t1)) / (t1 - t0);
		for (int i = 0; i < 4; i++) {
			assert_near(d[j * 4 + i], w, 1e-15);
			assert_near(f[j * 5 + i], 2.0 * w, 1e-6);
		}
		assert_true(f[j * 5 + 4] == 2.0f);	/* past the width */
	}
	/* (at the map's own size: --equirect weights it before resampling) */
	assert_int_equal(imap_load("data/sunset.exr", 0, 0, 0, &m), 0);
	frs_map_equirect_f64(m.v, m.w, m.h, 0);
	s = sampler_f64(mask, &m, NULL);
	prog("frs-sample -q -m %s -i data/sunset.exr --equirect -n 3000 -S 2 "
	    "-o %s", MATRIX, tu_path("eq.pts"));
	{
		struct drawn dr = draw(s, &n, 1, 2, 0);
		double *rec = records(&dr, 0, 0);
		same_as_file(tu_path("eq.pts"), rec, dr.n, 0);
		free(rec);
		drawn_free(&dr);
	}
	frs_sampler_free(s);
	imap_free(&m);
}

/* ---- progress ---------------------------------------------------------- */

struct prog_log {
	size_t calls;
	int bad;		/* a call out of order */
	uint64_t last, total;
	char what[32];
};

static void prog_record(void *ctx, const char *what, uint64_t done,
    uint64_t total)
{
	struct prog_log *l = ctx;

	if (l->calls == 0) {
		snprintf(l->what, sizeof l->what, "%s", what);
		l->total = total;
		l->bad |= done != 0;
	} else {
		/* Increasing, below total until the one last call. */
		l->bad |= done <= l->last || l->last == l->total ||
		    total != l->total || strcmp(what, l->what) != 0;
	}
	l->last = done;
	l->calls++;
}

static void *load_ramp(void *arg)
{
	float *map = NULL;
	uint32_t w, h;

	(void)arg;
	if (frs_map_load("ramp", 64, 1024, &map, &w, &h, NULL) != FRS_OK)
		return arg;
	frs_map_free(map);
	return NULL;
}

/* frs_set_progress: off by default; once set, a procedural map's rows
 * are reported, from 0 up to the last call at the total, in this thread
 * only. */
static void test_progress(void **state)
{
	struct prog_log l = { 0, 0, 0, 0, "" };
	float *map = NULL;
	uint32_t w, h;
	pthread_t t;
	void *res = &l;
	(void)state;

	assert_null(load_ramp(NULL));	/* nothing set: nothing to call */
	frs_set_progress(prog_record, &l);
	assert_int_equal(frs_map_load("ramp", 64, 1024, &map, &w, &h, NULL),
	    FRS_OK);
	frs_map_free(map);
	assert_string_equal(l.what, "ramp");
	assert_int_equal(l.total, 1024);
	assert_int_equal(l.last, 1024);
	assert_false(l.bad);
	assert_true(l.calls >= 3);	/* start, some rows, end */
	/* Another thread's work is not this thread's progress. */
	l = (struct prog_log){ 0, 0, 0, 0, "" };
	assert_int_equal(pthread_create(&t, NULL, load_ramp, NULL), 0);
	assert_int_equal(pthread_join(t, &res), 0);
	assert_null(res);
	assert_int_equal(l.calls, 0);
	/* Unset: silent again. */
	frs_set_progress(NULL, &l);
	assert_null(load_ramp(NULL));
	assert_int_equal(l.calls, 0);
}

TU_MAIN(setup, teardown,
	cmocka_unit_test(test_zeroed_options),
	cmocka_unit_test(test_levels),
	cmocka_unit_test(test_equirect),
	cmocka_unit_test(test_progress))
