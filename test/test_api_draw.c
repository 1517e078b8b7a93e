/*
 * The public API's samples (frs_draw_progressive, frs_draw_each,
 * frs_count, frs_sampler_info) against the oracle and frs-sample, bit
 * for bit: the defaults, each option as its flag, progressive steps,
 * float maps and strides, threads, the direct path and growing lists.
 * The helpers and the oracle: apiutil.h.
 */
#include "apiutil.h"

/* ---- the same samples as frs-sample ------------------------------------ */

static void test_const_map(void **state)
{
	frs_sampler *s;
	struct frs_imap one;
	uint64_t n = 5000;

	(void)state;
	/* No map: importance 1 everywhere. */
	assert_int_equal(imap_alloc(&one, 128, 128), 0);
	for (size_t i = 0; i < (size_t)128 * 128; i++)
		one.v[i] = 1.0;
	assert_int_equal(frs_sampler_new(&s, mask, NULL, 128, 128, 0, NULL,
	    NULL), FRS_OK);
	compare(s, &one, NULL, &n, 1, 7, 0, "-i const");
	compare(s, &one, NULL, &n, 1, 7, 1, "-i const");
	frs_sampler_free(s);
	imap_free(&one);
}

static void test_blob_defaults(void **state)
{
	frs_sampler *s = sampler_f64(mask, &blob, NULL);
	uint64_t n[] = { 5000, 1, 100000 };

	(void)state;
	compare(s, &blob, NULL, &n[0], 1, 7, 0, "-i blob");
	compare(s, &blob, NULL, &n[0], 1, 1, 0, "-i blob");
	compare(s, &blob, NULL, &n[1], 1, 3, 1, "-i blob");
	compare(s, &blob, NULL, &n[2], 1, 9, 1, "-i blob");
	frs_sampler_free(s);
}

/* Each option as its frs-sample flag. */
static void test_options(void **state)
{
	static const struct {
		double sigma;
		enum frs_algorithm a;
		enum frs_jitter_mode j;
		enum frs_rule_mode r;
		int pdf;
		const char *args;
	} c[] = {
		{ 8, FRS_ALG_SORTED, FRS_JIT_RANDOM, FRS_RULE_UNBIASED, 1,
		    "--jitter random" },
		{ 8, FRS_ALG_SORTED, FRS_JIT_HALTON, FRS_RULE_UNBIASED, 0,
		    "--jitter halton" },
		{ 8, FRS_ALG_SORTED, FRS_JIT_NONE, FRS_RULE_THESIS, 1,
		    "--threshold thesis" },
		{ 4, FRS_ALG_SORTED, FRS_JIT_NONE, FRS_RULE_UNBIASED, 0,
		    "--sigma 4" },
		{ 13.5, FRS_ALG_LEVEL2, FRS_JIT_RANDOM, FRS_RULE_THESIS, 1,
		    "--sigma 13.5 -a level2 --jitter random --threshold thesis" },
		{ 8, FRS_ALG_NAIVE, FRS_JIT_NONE, FRS_RULE_UNBIASED, 0,
		    "-a naive" },
		{ 8, FRS_ALG_STACK, FRS_JIT_NONE, FRS_RULE_UNBIASED, 0,
		    "-a stack" },
		{ 8, FRS_ALG_LEVEL1, FRS_JIT_HALTON, FRS_RULE_UNBIASED, 0,
		    "-a level1 --jitter halton" },
		{ 8, FRS_ALG_LEVEL2, FRS_JIT_NONE, FRS_RULE_UNBIASED, 1,
		    "-a level2" },
	};
	uint64_t n = 3000;
	char args[256];

	(void)state;
	for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
		struct frs_options o;
		frs_sampler *s;
		frs_options_init(&o);
		o.sigma = c[i].sigma;
		o.algorithm = c[i].a;
		o.jitter = c[i].j;
		o.rule = c[i].r;
		s = sampler_f64(mask, &blob, &o);
		/* Any thread count in the program: the same points. */
		snprintf(args, sizeof args, "-i blob %s -j %d", c[i].args,
		    1 + (int)(i % 2));
		compare(s, &blob, &o, &n, 1, 11 + i, c[i].pdf, args);
		frs_sampler_free(s);
	}
}

/* The thesis's threshold rule where it matters.  At n = 3000 the window
 * is the matrix once and no element sits at floor(T), so the two rules
 * give the same set; at 100000 the thesis's window (plain tiles) tiles it
 * 16 times and some do: there the thesis rule passes them all, the
 * unbiased rule by a coin.  (The levels, the default, through compare.) */
static void test_thesis_rule(void **state)
{
	uint64_t n = 100000;
	struct frs_options o;
	frs_sampler *thesis, *unbiased;
	struct drawn t, u;

	(void)state;
	frs_options_init(&o);
	o.rule = FRS_RULE_THESIS;
	thesis = sampler_f64(mask, &blob, &o);
	compare(thesis, &blob, &o, &n, 1, 5, 0, "-i blob --threshold thesis");
	frs_sampler_free(thesis);
	o.tiling = FRS_TILING_PLAIN;
	thesis = sampler_f64(mask, &blob, &o);
	o.rule = FRS_RULE_UNBIASED;
	unbiased = sampler_f64(mask, &blob, &o);
	t = draw(thesis, &n, 1, 5, 0);
	u = draw(unbiased, &n, 1, 5, 0);
	/* v < T passes every element v == floor(T): never fewer samples. */
	assert_true(t.n > u.n);
	drawn_free(&t);
	drawn_free(&u);
	frs_sampler_free(thesis);
	frs_sampler_free(unbiased);
}

static void test_progressive(void **state)
{
	static const uint64_t steps[] = { 1000, 3000, 5000 };
	static const uint64_t one[] = { 64, 20000 };
	struct frs_options o;
	frs_sampler *s = sampler_f64(mask, &blob, NULL);
	struct drawn d;

	(void)state;
	compare(s, &blob, NULL, steps, 3, 7, 1, "-i blob");
	compare(s, &blob, NULL, steps, 3, 8, 0, "-i blob");
	/* The steps come in order. */
	d = draw(s, steps, 3, 7, 0);
	for (size_t i = 1; i < d.n; i++)
		assert_true(d.step[i] >= d.step[i - 1]);
	assert_true(d.step[d.n - 1] <= 2);
	drawn_free(&d);
	frs_sampler_free(s);
	frs_options_init(&o);
	o.jitter = FRS_JIT_RANDOM;
	o.algorithm = FRS_ALG_STACK;
	s = sampler_f64(mask, &blob, &o);
	compare(s, &blob, &o, one, 2, 2, 1,
	    "-i blob -a stack --jitter random");
	frs_sampler_free(s);
}

/* A float map read from an EXR file by frs_map_load, and by frs-sample
 * from the same file. */
static void test_float_map(void **state)
{
	const char *path = write_exr("blob.exr", &blob);
	struct frs_imap f64, r64;
	frs_sampler *s;
	float *map;
	uint32_t w = 0, h = 0;
	uint64_t n = 6000;
	frs_error e;

	(void)state;
	assert_int_equal(frs_map_load(path, 0, 0, &map, &w, &h, &e), FRS_OK);
	assert_int_equal(w, 128);
	assert_int_equal(h, 128);
	assert_int_equal(imap_load(path, 0, 0, 0, &f64), 0);
	for (size_t i = 0; i < (size_t)w * h; i++)
		assert_true((double)map[i] == f64.v[i]);
	assert_int_equal(frs_sampler_new(&s, mask, map, w, h, 0, NULL, &e),
	    FRS_OK);
	{
		char args[600];
		snprintf(args, sizeof args, "-i %s", path);
		compare(s, &f64, NULL, &n, 1, 4, 1, args);
	}
	frs_sampler_free(s);
	frs_map_free(map);
	/* Resampled on loading: the values frs-sample would use, rounded. */
	assert_int_equal(frs_map_load(path, 48, 20, &map, &w, &h, NULL),
	    FRS_OK);
	assert_int_equal(w, 48);
	assert_int_equal(h, 20);
	assert_int_equal(imap_load(path, 48, 20, 0, &r64), 0);
	for (size_t i = 0; i < (size_t)w * h; i++)
		assert_true(map[i] == (float)r64.v[i]);
	frs_map_free(map);
	/* A spec, as frs-sample evaluates it, rounded to float. */
	assert_int_equal(frs_map_load("blob", 0, 0, &map, &w, &h, NULL),
	    FRS_OK);
	assert_int_equal(w, 128);
	for (size_t i = 0; i < (size_t)w * h; i++)
		assert_true(map[i] == (float)blob.v[i]);
	frs_map_free(map);
	imap_free(&r64);
	imap_free(&f64);
}

/* frs_imap_load against what is known without it: the file's values
 * (written as floats), the float load, frs_map_equirect_f64 on the
 * unweighted map, the mean a resampling by area keeps, negative values
 * clamped or refused. */
static void test_imap_load(void **state)
{
	const char *path = write_exr("blob.exr", &blob);
	struct frs_imap m, eq, r, neg;
	double sum = 0.0, rsum = 0.0;
	float *map;
	uint32_t w, h;

	(void)state;
	assert_int_equal(frs_imap_load(&m, path, 0, 0, 0, NULL), FRS_OK);
	assert_int_equal(frs_map_load(path, 0, 0, &map, &w, &h, NULL), FRS_OK);
	assert_true(m.w == w && m.h == h && w == blob.w && h == blob.h);
	for (size_t i = 0; i < (size_t)w * h; i++) {
		assert_true(m.v[i] == (double)(float)blob.v[i]);
		assert_true((float)m.v[i] == map[i]);
		sum += m.v[i];
	}
	frs_map_free(map);
	assert_int_equal(frs_imap_load(&eq, path, 0, 0, FRS_MAP_EQUIRECT,
	    NULL), FRS_OK);
	frs_map_equirect_f64(m.v, m.w, m.h, 0);
	assert_memory_equal(eq.v, m.v, (size_t)w * h * sizeof *m.v);
	assert_int_equal(frs_imap_load(&r, path, 48, 20, 0, NULL), FRS_OK);
	assert_true(r.w == 48 && r.h == 20);
	for (size_t i = 0; i < 48 * 20; i++)
		rsum += r.v[i];
	assert_true(fabs(rsum / (48 * 20) - sum / (128 * 128)) <=
	    1e-12 * sum / (128 * 128));
	/* A negative pixel: clamped to zero, or refused under strict. */
	assert_int_equal(imap_alloc(&neg, 4, 2), 0);
	for (int i = 0; i < 8; i++)
		neg.v[i] = i == 5 ? -2.0 : 1.0 + i;
	path = write_exr("neg.exr", &neg);
	imap_free(&neg);
	assert_int_equal(frs_imap_load(&neg, path, 0, 0, FRS_MAP_STRICT, NULL),
	    FRS_E_MAP);
	assert_null(neg.v);
	assert_int_equal(frs_imap_load(&neg, path, 0, 0, 0, NULL), FRS_OK);
	for (int i = 0; i < 8; i++)
		assert_true(neg.v[i] == (i == 5 ? 0.0 : 1.0 + i));
	frs_imap_free(&neg);
	frs_imap_free(&r);
	frs_imap_free(&eq);
	frs_imap_free(&m);
}

/* A row stride: the values between the rows are never read (NaN there
 * would be FRS_E_MAP). */
static void test_stride(void **state)
{
	struct frs_imap m;
	size_t stride = 128;
	double *wide;
	float *wf, *cf;
	frs_sampler *s, *t;
	uint64_t n = 4000;

	(void)state;
	assert_int_equal(imap_load("blob", 100, 60, 0, &m), 0);
	wide = malloc(stride * m.h * sizeof *wide);
	wf = malloc(stride * m.h * sizeof *wf);
	cf = malloc((size_t)m.w * m.h * sizeof *cf);
	assert_non_null(wide);
	assert_non_null(wf);
	assert_non_null(cf);
	for (size_t i = 0; i < stride * m.h; i++) {
		wide[i] = NAN;
		wf[i] = NAN;
	}
	for (uint32_t y = 0; y < m.h; y++)
		for (uint32_t x = 0; x < m.w; x++) {
			wide[y * stride + x] = m.v[(size_t)y * m.w + x];
			wf[y * stride + x] = (float)m.v[(size_t)y * m.w + x];
			cf[(size_t)y * m.w + x] = wf[y * stride + x];
		}
	assert_int_equal(frs_sampler_new_f64(&s, mask, wide, m.w, m.h, stride,
	    NULL, NULL), FRS_OK);
	compare(s, &m, NULL, &n, 1, 6, 1, "-i blob -s 100x60");
	frs_sampler_free(s);
	assert_int_equal(frs_sampler_new(&s, mask, wf, m.w, m.h, stride,
	    NULL, NULL), FRS_OK);
	assert_int_equal(frs_sampler_new(&t, mask, cf, m.w, m.h, m.w, NULL,
	    NULL), FRS_OK);
	/* The map is copied: changing it afterwards changes nothing. */
	for (size_t i = 0; i < (size_t)m.w * m.h; i++)
		cf[i] = -1.0f;
	same_draw(s, t, n, 6);
	frs_sampler_free(s);
	frs_sampler_free(t);
	free(wide);
	free(wf);
	free(cf);
	imap_free(&m);
}

/* options.threads: the same bytes for 0, 1, 2 and 3 threads. */
static void test_threads_option(void **state)
{
	struct drawn d[4];
	uint64_t n = 30000;

	(void)state;
	for (int t = 0; t < 4; t++) {
		struct frs_options o;
		frs_sampler *s;
		frs_options_init(&o);
		o.threads = t;
		o.jitter = FRS_JIT_RANDOM;
		s = sampler_f64(mask, &blob, &o);
		d[t] = draw(s, &n, 1, 5, 1);
		frs_sampler_free(s);
	}
	for (int t = 1; t < 4; t++) {
		assert_int_equal(d[t].n, d[0].n);
		assert_memory_equal(d[t].xy, d[0].xy, 2 * d[0].n * sizeof(double));
		assert_memory_equal(d[t].pdf, d[0].pdf, d[0].n * sizeof(double));
	}
	for (int t = 0; t < 4; t++)
		drawn_free(&d[t]);
}

/* frs_draw_each's batches, gathered. */
struct wave_gather {
	double *xy, *pdf;
	size_t n, cap;
};

static int wave_gather(void *ctx, const double *xy, const double *pdf,
    const uint32_t *step, size_t k, uint64_t total)
{
	struct wave_gather *g = ctx;

	assert_null(step);
	if (g->cap == 0) {
		g->cap = (size_t)total;
		g->xy = malloc(2 * g->cap * sizeof *g->xy);
		g->pdf = malloc(g->cap * sizeof *g->pdf);
		assert_non_null(g->xy);
		assert_non_null(g->pdf);
	}
	assert_true(g->n + k <= g->cap && total == g->cap);
	memcpy(g->xy + 2 * g->n, xy, 2 * k * sizeof *xy);
	memcpy(g->pdf + g->n, pdf, k * sizeof *pdf);
	g->n += k;
	return 0;
}

/* The records (x, y, pdf) of d in increasing order. */
static double *sorted_records(const struct drawn *d)
{
	double *r = records(d, 1, 0), *q = sort_recs(r, d->n, 3);

	free(r);
	return q;
}

/* Sorted with one step goes from the thresholding straight to the
 * caller (frs_draw) or in waves to the callback (frs_draw_each): the
 * samples of Naive through the store of the whole run (Sorted gives a
 * block's samples in value order, Naive in row order), and the same
 * bytes for 1 and 3 threads and waves of 1 to 2^20 samples (many chunks
 * to a wave, a chunk to a wave, chunks larger than a wave). */
static void test_direct_path(void **state)
{
	uint64_t n = 20000, waves[] = { (uint64_t)1 << 20, 1, 700, 5000 };
	struct frs_options o;
	struct drawn ref, first = { 0, NULL, NULL, NULL };
	frs_sampler *s;
	double *a, *b;

	(void)state;
	frs_options_init(&o);
	o.algorithm = FRS_ALG_NAIVE;
	o.jitter = FRS_JIT_RANDOM;
	s = sampler_f64(mask, &blob, &o);
	ref = draw(s, &n, 1, 3, 1);
	frs_sampler_free(s);
	o.algorithm = FRS_ALG_SORTED;
	for (int t = 1; t <= 3; t += 2)
		for (size_t w = 0; w < sizeof waves / sizeof *waves; w++) {
			struct wave_gather g = { NULL, NULL, 0, 0 };
			struct drawn d;
			frs_error e;
			o.threads = t;
			api_wave = waves[w];
			s = sampler_f64(mask, &blob, &o);
			d = draw(s, &n, 1, 3, 1);
			assert_int_equal(frs_draw_each(s, &n, 1, 3, 1, wave_gather,
			    &g, &e), FRS_OK);
			frs_sampler_free(s);
			if (first.n == 0)
				first = d;
			assert_int_equal(d.n, ref.n);
			assert_int_equal(g.n, ref.n);
			assert_memory_equal(d.xy, first.xy, 2 * ref.n * sizeof(double));
			assert_memory_equal(d.pdf, first.pdf, ref.n * sizeof(double));
			assert_memory_equal(g.xy, first.xy, 2 * ref.n * sizeof(double));
			assert_memory_equal(g.pdf, first.pdf, ref.n * sizeof(double));
			free(g.xy);
			free(g.pdf);
			if (d.xy != first.xy)
				drawn_free(&d);
		}
	api_wave = (uint64_t)1 << 20;
	a = sorted_records(&ref);
	b = sorted_records(&first);
	assert_memory_equal(a, b, 3 * ref.n * sizeof *a);
	free(a);
	free(b);
	drawn_free(&first);
	drawn_free(&ref);
}

/* s's draw of steps: a fresh mask's, whose lists are made for it. */
static void same_as_fresh(const frs_sampler *s, const uint64_t *steps,
    unsigned nsteps, const struct frs_options *o)
{
	frs_mask *fresh;
	frs_sampler *f;
	struct drawn d, r;

	assert_int_equal(frs_mask_load(&fresh, MATRIX, NULL), FRS_OK);
	f = sampler_f64(fresh, &blob, o);
	d = draw(s, steps, nsteps, 5, 1);
	r = draw(f, steps, nsteps, 5, 1);
	assert_int_equal(d.n, r.n);
	assert_memory_equal(d.xy, r.xy, 2 * d.n * sizeof(double));
	drawn_free(&d);
	drawn_free(&r);
	frs_sampler_free(f);
	frs_mask_free(fresh);
}

/* One sampler's draws of growing and shrinking counts: each as a fresh
 * sampler's (its lists, made for the values the first draw reaches,
 * grow to the complete ones when a later draw needs more), and the
 * progressive draw nested in them. */
static void test_lists_grow(void **state)
{
	uint64_t ns[] = { 50, 3000, 200, 60000, 50 }, steps[2] = { 50, 3000 };
	struct frs_options o;
	frs_sampler *s;
	frs_mask *mk;

	(void)state;
	frs_options_init(&o);
	assert_int_equal(frs_mask_load(&mk, MATRIX, NULL), FRS_OK);
	s = sampler_f64(mk, &blob, &o);
	for (size_t i = 0; i < sizeof ns / sizeof *ns; i++)
		same_as_fresh(s, &ns[i], 1, &o);
	same_as_fresh(s, steps, 2, &o);
	frs_sampler_free(s);
	frs_mask_free(mk);
}

/* frs_count: frs-sample --count-only, and what frs_draw makes. */
static void test_count(void **state)
{
	const char *out = tu_path("count.txt");
	frs_sampler *s = sampler_f64(mask, &blob, NULL);
	uint64_t c = 0, n = 5000;
	unsigned long long pc = 0;
	struct drawn d;
	FILE *fp;

	(void)state;
	prog("frs-sample -q -m %s -i blob -n 5000 -S 7 --count-only -o %s",
	    MATRIX, out);
	fp = fopen(out, "r");
	assert_non_null(fp);
	assert_int_equal(fscanf(fp, "%llu", &pc), 1);
	fclose(fp);
	assert_int_equal(frs_count(s, n, 7, &c, NULL), FRS_OK);
	assert_int_equal(c, pc);
	d = draw(s, &n, 1, 7, 0);
	assert_int_equal(d.n, c);
	drawn_free(&d);
	/* "About n": within a few per cent here. */
	assert_true(c > 4500 && c < 5500);
	frs_sampler_free(s);
}

/* frs_sampler_info: the setup frs-sample -v prints. */
static void test_info(void **state)
{
	const char *err = tu_path("v.txt");
	frs_sampler *s = sampler_f64(mask, &blob, NULL);
	struct frs_info in;
	char line[1024];
	unsigned ns = 0;
	unsigned long long ww, wh, ox, oy;
	double tau = 0;
	int found = 0;
	FILE *fp;

	(void)state;
	prog("frs-sample -m %s -i blob -n 5000 -S 7 -v -o /dev/null 2>%s",
	    MATRIX, err);
	fp = fopen(err, "r");
	assert_non_null(fp);
	while (fgets(line, sizeof line, fp) != NULL) {
		const char *p = strstr(line, "n_s ");
		/* the first: level 0's (the thesis's) window */
		if (!found && p != NULL && sscanf(p, "n_s %u, window %llux%llu at "
		    "(%llu, %llu), tau %lg", &ns, &ww, &wh, &ox, &oy, &tau) == 6)
			found = 1;
	}
	fclose(fp);
	if (!found) {
		print_error("no 'n_s ..., window ..., tau' line in frs-sample "
		    "-v\n");
		fail();
	}
	assert_int_equal(frs_sampler_info(s, 5000, 7, &in, NULL), FRS_OK);
	assert_int_equal(in.ns, ns);
	assert_int_equal(in.window_w, ww);
	assert_int_equal(in.window_h, wh);
	assert_int_equal(in.offset_x, ox);
	assert_int_equal(in.offset_y, oy);
	assert_near(in.tau, tau, 1e-8 * fabs(tau));
	{
		struct frs_imap_stats st;
		imap_stats(&blob, &st);
		assert_near(in.mean, st.mean, 1e-12 * st.mean);
		assert_true(in.max == st.max);
	}
	assert_true(in.unique > 0);
	frs_sampler_free(s);
}

TU_MAIN(setup, teardown,
	cmocka_unit_test(test_const_map),
	cmocka_unit_test(test_blob_defaults),
	cmocka_unit_test(test_options),
	cmocka_unit_test(test_thesis_rule),
	cmocka_unit_test(test_progressive),
	cmocka_unit_test(test_float_map),
	cmocka_unit_test(test_imap_load),
	cmocka_unit_test(test_stride),
	cmocka_unit_test(test_threads_option),
	cmocka_unit_test(test_direct_path),
	cmocka_unit_test(test_lists_grow),
	cmocka_unit_test(test_count),
	cmocka_unit_test(test_info))
