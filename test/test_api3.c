/*
 * The public API in three dimensions (frs_sampler3_*, frs_draw3_*,
 * frs_count3) against an oracle of the library's 3-D stages (frs3_setup,
 * frs3_sample, frs3_point) and frs-sample, bit for bit; its errors; its
 * exact counts.  The 2-D helpers: apiutil.h.
 */
#include "apiutil.h"

/* ---- three dimensions ------------------------------------------------ */

/* frs_draw3_progressive sized by a call with no room; records in
 * frs-sample's layout (x, y, z [, pdf] [, step + 1]). */
static double *draw3(const frs_sampler3 *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, int pdf, size_t *n)
{
	size_t k = 3 + (size_t)pdf + (nsteps > 1), cnt = 0;
	double *xyz, *pd, *rec;
	uint32_t *st;
	frs_error e;

	assert_int_equal(frs_draw3_progressive(s, steps, nsteps, seed, NULL,
	    NULL, NULL, 0, n, &e), FRS_E_BUFFER);
	assert_true(*n > 0);
	xyz = malloc(3 * *n * sizeof *xyz);
	pd = malloc(*n * sizeof *pd);
	st = malloc(*n * sizeof *st);
	rec = malloc(k * *n * sizeof *rec);
	assert_true(xyz && pd && st && rec);
	assert_int_equal(frs_draw3_progressive(s, steps, nsteps, seed, xyz,
	    pdf ? pd : NULL, st, *n, &cnt, &e), FRS_OK);
	assert_int_equal(cnt, *n);
	for (size_t i = 0; i < *n; i++) {
		double *r = rec + i * k;
		memcpy(r, xyz + 3 * i, 3 * sizeof *r);
		if (pdf)
			r[3] = pd[i];
		if (nsteps > 1)
			r[3 + pdf] = (double)(st[i] + 1);
	}
	free(xyz);
	free(pd);
	free(st);
	return rec;
}

/* frs_draw3_each's batches gathered into records in draw3's layout. */
struct gather3 {
	double *rec;
	size_t n, cap, k;
	int calls;
};

static int gather3(void *ctx, const double *xyz, const double *pdf,
    const uint32_t *step, size_t k, uint64_t total)
{
	struct gather3 *g = ctx;

	if (g->rec == NULL) {
		g->cap = (size_t)total;
		g->rec = malloc((g->cap + 1) * g->k * sizeof *g->rec);
		assert_non_null(g->rec);
	}
	assert_true(total == g->cap && g->n + k <= g->cap);
	for (size_t i = 0; i < k; i++, g->n++) {
		double *r = g->rec + g->n * g->k;
		size_t c = 3;
		memcpy(r, xyz + 3 * i, 3 * sizeof *r);
		if (pdf != NULL)
			r[c++] = pdf[i];
		if (step != NULL)
			r[c++] = (double)(step[i] + 1);
		assert_int_equal(c, g->k);
	}
	g->calls++;
	return 0;
}

static int stop3(void *ctx, const double *xyz, const double *pdf,
    const uint32_t *step, size_t k, uint64_t total)
{
	(void)xyz, (void)pdf, (void)step, (void)k, (void)total;
	return ++*(int *)ctx;
}

/* One record of oracle3: frs3_point, the density I / mean, the step. */
struct oracle3 {
	const struct frs3_setup *su;
	const struct frs_vol *vol;
	double *rec;
	size_t n, k;
	int pdf, steps;
};

static int put3(void *ctx, const struct frs3_elem *e)
{
	struct oracle3 *o = ctx;
	double *q = o->rec + o->n++ * o->k;
	uint32_t ns = o->su->ns;

	frs3_point(o->su, e, q);
	if (o->pdf)
		q[3] = o->vol->v[((size_t)(e->z / ns) * o->vol->h + e->y / ns) *
		    o->vol->w + e->x / ns] / o->su->mean;
	if (o->steps)
		q[3 + o->pdf] = (double)(e->step + 1);
	return 0;
}

/* oracle_draw in 3-D, as records in frs-sample's layout: frs3_setup with
 * the options, its levels (octree levels over voxels, as in 2-D), the
 * same implementation's elements of each level in the order of frs.h
 * (frs3_each, level by level), each by put3.  Exact counts: the search
 * of frs_exact_taus over the levels' Naive counts.  (Steps in turn over
 * the levels: compared as sets with progressive steps.) */
struct olev3 {
	unsigned n;
	struct frs3_setup su[FRS_LEVELS_MAX];
	struct frs_levels plan;
	const struct frs_vol *vol;
	struct frs3_prep none;
};

static int naive_count3(void *ctx, double tau, uint64_t *count)
{
	struct olev3 *lv = ctx;
	struct frs3_result r;

	*count = 0;
	for (unsigned i = 0; i < lv->n; i++) {
		struct frs3_setup *su = &lv->su[i];
		su->exact = (struct frs_xtau){ .n = 1, .steps = { su->n },
		    .tau = { tau } };
		if (frs3_sample(su, lv->vol, &lv->none, FRS_NAIVE, &su->n, 1, 1,
		    &r) < 0)
			return -1;
		*count += r.count;
		frs3_result_free(&r);
	}
	return 0;
}

static void oracle_levels3(const struct frs_vol *vol,
    const struct frs_options *o, const struct frs3_setup *s0,
    struct olev3 *lv)
{
	const uint32_t side[3] = { vol->w, vol->h, vol->d };
	uint32_t longest = vol->w > vol->h ? vol->w : vol->h;
	double blur;
	unsigned top = 0;

	longest = vol->d > longest ? vol->d : longest;
	blur = o->level_blur > 0.0 ? o->level_blur : (double)longest / 8.0;
	memset(lv, 0, sizeof *lv);
	lv->vol = vol;
	lv->none.m = &mat3;
	lv->n = 1;
	lv->su[0] = *s0;
	const uint32_t msz[3] = { s0->mw, s0->mh, s0->md };

	top = oracle_top(s0->ns, side, msz, 3);
	if (o->tiling != FRS_TILING_LEVELS || top == 0)
		return;
	assert_int_equal(frs_levels_plan(&lv->plan, 3, side, vol->v,
	    s0->tau * s0->iscale, top, (double)mat3.w * mat3.h * mat3.d,
	    s0->sigma, blur), 0);
	if (frs_levels_used(&lv->plan) == 1 && lv->plan.cells[0] > 0)
		return;
	lv->n = 0;
	for (unsigned l = 0; l <= top; l++) {
		struct frs3_setup *su = &lv->su[lv->n];
		if (lv->plan.cells[l] == 0)
			continue;
		if (l == 0)
			*su = *s0;
		else
			frs3_level_setup(su, s0, l, lv->plan.max[l]);
		su->max = lv->plan.max[l];
		su->lev = lv->plan.lev;
		su->cell0 = 0;
		su->cell1 = (uint64_t)vol->w * vol->h * vol->d;
		lv->n++;
	}
}

static double *oracle3(const struct frs_vol *vol, const struct frs_options *o,
    const uint64_t *steps, unsigned nsteps, uint64_t seed, int pdf, size_t *n)
{
	enum frs_impl a = o->algorithm == FRS_ALG_NAIVE ? FRS_NAIVE : FRS_SORTED;
	size_t k = 3 + (size_t)pdf + (nsteps > 1);
	struct frs3_setup s0;
	struct olev3 lv;
	struct frs3_result r[FRS_LEVELS_MAX];
	struct oracle3 o3 = { NULL, vol, NULL, 0, k, pdf, nsteps > 1 };
	uint64_t count = 0;

	if (mat3.v == NULL)
		assert_int_equal(frd_read(MATRIX3, &mat3), 0);
	assert_int_equal(frs3_setup(&s0, vol, &mat3, steps[nsteps - 1],
	    o->sigma, seed), 0);
	s0.rule = rule_of(o);
	s0.jitter = jitter_of(o);
	s0.tiles = tiling_of(o, FRS_TILES_PLAIN);
	oracle_levels3(vol, o, &s0, &lv);
	if (o->rule == FRS_RULE_EXACT) {
		struct frs_xtau x;
		double tau0[16];
		unsigned passes;
		uint64_t most = 0;
		for (unsigned i = 0; i < nsteps; i++)
			tau0[i] = frs3_tau(&s0, steps[i]);
		for (unsigned i = 0; i < lv.n; i++)
			for (uint64_t c = 0; c < (uint64_t)vol->w * vol->h * vol->d;
			    c++)
				most += vol->v[c] > 0.0 && frs_cell_here(lv.su[i].lev,
				    lv.su[i].level, c) ? (uint64_t)lv.su[i].ns *
				    lv.su[i].ns * lv.su[i].ns : 0;
		assert_int_equal(frs_exact_taus(steps, nsteps, tau0, most,
		    naive_count3, &lv, &x, &passes), 0);
		for (unsigned i = 0; i < lv.n; i++) {
			lv.su[i].exact = x;
			lv.su[i].tau = frs3_tau(&lv.su[i], lv.su[i].n);
		}
	}
	frs_set_threads(1);
	for (unsigned i = 0; i < lv.n; i++) {
		struct frs3_prep p;
		assert_int_equal(frs3_prepare(&p, &mat3, a == FRS_SORTED ?
		    frs3_block(&lv.su[i]) : 0), 0);
		assert_int_equal(frs3_sample(&lv.su[i], vol, &p, a, steps, nsteps,
		    0, &r[i]), 0);
		frs3_prep_free(&p);
		count += r[i].count;
	}
	o3.rec = malloc((count + 1) * k * sizeof *o3.rec);
	assert_non_null(o3.rec);
	for (unsigned i = 0; i < lv.n; i++) {
		o3.su = &lv.su[i];
		frs3_each(&r[i], nsteps, put3, &o3);
		frs3_result_free(&r[i]);
	}
	*n = o3.n;
	assert_true(*n == count);
	frs_levels_free(&lv.plan);
	return o3.rec;
}

/* The API's samples for a 3-D mask (s made from vol with the options o,
 * NULL: the defaults) are the oracle's and frs-sample's, bit for bit. */
static void compare3(const frs_sampler3 *s, const struct frs_vol *vol,
    const struct frs_options *o, const uint64_t *steps, unsigned nsteps,
    uint64_t seed, int pdf, const char *args)
{
	const char *out = tu_path("frs3.pts");
	size_t n, nref, k = 3 + (size_t)pdf + (nsteps > 1);
	double *rec, *ref;
	struct frs_points p;
	struct frs_options dflt;

	o = o != NULL ? o : (frs_options_init(&dflt), &dflt);
	frs_sample_prog(MATRIX3, args, steps, nsteps, seed, pdf, out);
	rec = draw3(s, steps, nsteps, seed, pdf, &n);
	ref = oracle3(vol, o, steps, nsteps, seed, pdf, &nref);
	assert_int_equal(n, nref);
	/* The callback form: the same records in the same order; a
	 * callback that says stop ends the run at once. */
	{
		struct gather3 g = { NULL, 0, 0, k, 0 };
		frs_error e;
		int calls = 0;
		assert_int_equal(frs_draw3_each(s, steps, nsteps, seed, pdf,
		    gather3, &g, &e), FRS_OK);
		assert_int_equal(g.n, n);
		assert_memory_equal(g.rec, rec, n * k * sizeof *rec);
		free(g.rec);
		assert_int_equal(frs_draw3_each(s, steps, nsteps, seed, pdf,
		    stop3, &calls, &e), FRS_E_CALLBACK);
		assert_int_equal(calls, 1);
	}
	if (nsteps == 1) {
		assert_memory_equal(rec, ref, n * k * sizeof *rec);
	} else {	/* the oracle gives the levels' steps in turn */
		double *a = sort_recs(rec, n, k), *b = sort_recs(ref, n, k);
		assert_memory_equal(a, b, n * k * sizeof *rec);
		free(a);
		free(b);
	}
	assert_int_equal(pts_read(out, &p), 0);
	assert_int_equal(p.dims, 3);
	assert_int_equal(p.n, n);
	assert_int_equal(p.dims + p.extra, k);
	assert_memory_equal(p.x, rec, n * k * sizeof *rec);
	pts_free(&p);
	free(ref);
	free(rec);
}

static void test_sampler3(void **state)
{
	static const uint64_t steps[] = { 300, 1200, 4000 };
	struct frs_vol v, one;
	struct frs_options o;
	frs_mask *m3;
	frs_sampler3 *s;
	frs_error e;
	uint32_t w, h, d;
	uint64_t n = 3000, c1 = 0, c2 = 0;

	(void)state;
	assert_int_equal(frs_mask_load(&m3, MATRIX3, &e), FRS_OK);
	assert_int_equal(frs_mask_dims(m3), 3);
	assert_int_equal(frs_mask_dims(mask), 2);
	frs_mask_size3(m3, &w, &h, &d);
	assert_true(w == 64 && h == 64 && d == 64);
	frs_mask_size3(mask, &w, &h, &d);
	assert_true(w == 2048 && d == 1);
	assert_int_equal(vol_load("blob3:sigma=0.2", 16, 16, 16, 0, &v), 0);
	/* The default options, then each option as its flag. */
	assert_int_equal(frs_sampler3_new_f64(&s, m3, v.v, 16, 16, 16, NULL,
	    &e), FRS_OK);
	compare3(s, &v, NULL, &n, 1, 5, 1, "-i blob3:sigma=0.2 -s 16");
	compare3(s, &v, NULL, steps, 3, 2, 0, "-i blob3:sigma=0.2 -s 16");
	assert_int_equal(frs_count3(s, n, 5, &c1, &e), FRS_OK);
	frs_sampler3_free(s);
	frs_options_init(&o);
	o.sigma = 4;
	o.jitter = FRS_JIT_HALTON;
	o.algorithm = FRS_ALG_NAIVE;
	o.threads = 2;
	assert_int_equal(frs_sampler3_new_f64(&s, m3, v.v, 16, 16, 16, &o, &e),
	    FRS_OK);
	compare3(s, &v, &o, &n, 1, 5, 0, "-i blob3:sigma=0.2 -s 16 --sigma 4 "
	    "--jitter halton -a naive");
	frs_sampler3_free(s);
	/* A float volume and a constant one (NULL). */
	{
		float *f = malloc(16 * 16 * 16 * sizeof *f);
		assert_non_null(f);
		for (size_t i = 0; i < 16 * 16 * 16; i++)
			f[i] = (float)v.v[i];
		assert_int_equal(frs_sampler3_new(&s, m3, f, 16, 16, 16, NULL,
		    &e), FRS_OK);
		assert_int_equal(frs_count3(s, n, 5, &c2, &e), FRS_OK);
		assert_true(c2 > n * 9 / 10 && c2 < n * 11 / 10);
		frs_sampler3_free(s);
		free(f);
	}
	assert_true(c1 > n * 9 / 10 && c1 < n * 11 / 10);
	assert_int_equal(frs_sampler3_new(&s, m3, NULL, 8, 8, 8, NULL, &e),
	    FRS_OK);
	/* No volume: importance 1 everywhere. */
	assert_int_equal(vol_alloc(&one, 8, 8, 8), 0);
	for (size_t i = 0; i < 8 * 8 * 8; i++)
		one.v[i] = 1.0;
	compare3(s, &one, NULL, &n, 1, 3, 1, "-s 8");
	frs_sampler3_free(s);
	vol_free(&one);
	vol_free(&v);
	frs_mask_free(m3);
}

/* Every error the 3-D functions reach. */
static void test_sampler3_errors(void **state)
{
	struct frs_options o;
	frs_mask *m3;
	frs_sampler3 *s = NULL;
	frs_sampler *s2 = NULL;
	frs_error e;
	double bad[8] = { 1, 1, 1, 1, 1, 1, 1, 0 };
	double xyz[3];
	size_t cnt;
	uint64_t c;

	(void)state;
	assert_int_equal(frs_mask_load(&m3, MATRIX3, &e), FRS_OK);
	/* The mask's dimension must fit the sampler. */
	assert_int_equal(frs_sampler3_new(&s, mask, NULL, 4, 4, 4, NULL, &e),
	    FRS_E_ARG);
	assert_non_null(strstr(e.message, "2-D mask"));
	assert_null(s);
	assert_int_equal(frs_sampler_new(&s2, m3, NULL, 4, 4, 0, NULL, &e),
	    FRS_E_ARG);
	assert_non_null(strstr(e.message, "3-D mask"));
	assert_null(s2);
	/* Arguments, options and values. */
	assert_int_equal(frs_sampler3_new(NULL, m3, NULL, 4, 4, 4, NULL, &e),
	    FRS_E_ARG);
	assert_int_equal(frs_sampler3_new(&s, m3, NULL, 4, 0, 4, NULL, &e),
	    FRS_E_ARG);
	frs_options_init(&o);
	o.algorithm = FRS_ALG_STACK;
	assert_int_equal(frs_sampler3_new(&s, m3, NULL, 4, 4, 4, &o, &e),
	    FRS_E_ARG);
	assert_non_null(strstr(e.message, "naive and sorted"));
	bad[3] = NAN;
	assert_int_equal(frs_sampler3_new_f64(&s, m3, bad, 2, 2, 2, NULL, &e),
	    FRS_E_MAP);
	assert_non_null(strstr(e.message, "voxel (1, 1, 0)"));
	bad[3] = -1;
	assert_int_equal(frs_sampler3_new_f64(&s, m3, bad, 2, 2, 2, NULL, &e),
	    FRS_E_MAP);
	memset(bad, 0, sizeof bad);
	assert_int_equal(frs_sampler3_new_f64(&s, m3, bad, 2, 2, 2, NULL, &e),
	    FRS_E_MAP);
	assert_null(s);
	/* Draws: no sampler, bad counts, too small a buffer, a count too
	 * large to visit. */
	assert_int_equal(frs_draw3(NULL, 10, 1, xyz, NULL, 1, &cnt, &e),
	    FRS_E_ARG);
	assert_int_equal(frs_sampler3_new(&s, m3, NULL, 2, 2, 2, NULL, &e),
	    FRS_OK);
	assert_int_equal(frs_draw3(s, 0, 1, xyz, NULL, 1, &cnt, &e), FRS_E_ARG);
	assert_int_equal(frs_draw3(s, 100, 1, xyz, NULL, 1, &cnt, &e),
	    FRS_E_BUFFER);
	assert_true(cnt > 50);
	assert_int_equal(frs_count3(s, (uint64_t)1 << 41, 1, &c, &e),
	    FRS_E_LIMIT);
	frs_sampler3_free(s);
	/* 2^40 samples at sigma 16 from 8 voxels: 2^36 blocks to visit. */
	frs_options_init(&o);
	o.sigma = 16;
	assert_int_equal(frs_sampler3_new(&s, m3, NULL, 2, 2, 2, &o, &e),
	    FRS_OK);
	assert_int_equal(frs_count3(s, (uint64_t)1 << 40, 1, &c, &e),
	    FRS_E_LIMIT);
	assert_non_null(strstr(e.message, "larger matrix"));
	assert_int_equal(frs_count3(s, 100, 1, NULL, &e), FRS_E_ARG);
	frs_sampler3_free(s);
	frs_sampler3_free(NULL);
	frs_mask_free(m3);
}

/* ---- exact counts in three dimensions ------------------------------- */

static int triple_cmp(const void *a, const void *b)
{
	const double *p = a, *q = b;
	int c = pair_cmp(a, b);

	return c != 0 ? c : p[2] < q[2] ? -1 : p[2] > q[2];
}

/* 3-D: exactly n, Naive's set is Sorted's, frs-sample's bytes. */
static void test_exact3(void **state)
{
	static const uint64_t steps[] = { 300, 1200, 4000 };
	struct frs_vol v;
	struct frs_options o;
	frs_mask *m3;
	frs_sampler3 *s, *sn;
	frs_error e;
	uint64_t n = 3000, c = 0;
	size_t k1, k2;
	double *r1, *r2;

	(void)state;
	assert_int_equal(frs_mask_load(&m3, MATRIX3, &e), FRS_OK);
	assert_int_equal(vol_load("blob3:sigma=0.2", 16, 16, 16, 0, &v), 0);
	frs_options_init(&o);
	o.rule = FRS_RULE_EXACT;
	assert_int_equal(frs_sampler3_new_f64(&s, m3, v.v, 16, 16, 16, &o, &e),
	    FRS_OK);
	for (uint64_t seed = 1; seed <= 3; seed++) {
		assert_int_equal(frs_count3(s, n, seed, &c, &e), FRS_OK);
		assert_int_equal(c, n);
	}
	compare3(s, &v, &o, &n, 1, 5, 1,
	    "-i blob3:sigma=0.2 -s 16 --exact-count");
	compare3(s, &v, &o, steps, 3, 2, 0,
	    "-i blob3:sigma=0.2 -s 16 --exact-count");
	o.algorithm = FRS_ALG_NAIVE;
	o.threads = 2;
	assert_int_equal(frs_sampler3_new_f64(&sn, m3, v.v, 16, 16, 16, &o,
	    &e), FRS_OK);
	r1 = draw3(s, &n, 1, 4, 0, &k1);
	r2 = draw3(sn, &n, 1, 4, 0, &k2);
	assert_int_equal(k1, n);
	assert_int_equal(k2, n);
	qsort(r1, n, 3 * sizeof *r1, triple_cmp);
	qsort(r2, n, 3 * sizeof *r2, triple_cmp);
	assert_memory_equal(r1, r2, 3 * n * sizeof *r1);
	free(r1);
	free(r2);
	frs_sampler3_free(s);
	frs_sampler3_free(sn);
	vol_free(&v);
	frs_mask_free(m3);
}

TU_MAIN(setup, teardown,
	cmocka_unit_test(test_sampler3),
	cmocka_unit_test(test_sampler3_errors),
	cmocka_unit_test(test_exact3))
