/*
 * Exact counts (FRS_RULE_EXACT, frs-sample --exact-count): exactly n in
 * frs_count and frs_draw, the same set for every algorithm and as
 * frs-sample's, and against a brute-force oracle of every window
 * element's key.  The helpers: apiutil.h.
 */
#include "apiutil.h"

/* ---- exact counts (FRS_RULE_EXACT, frs-sample --exact-count) ---------- */

static frs_sampler *exact_sampler(const struct frs_imap *m,
    enum frs_algorithm a, int threads, enum frs_rule_mode rule)
{
	struct frs_options o;

	frs_options_init(&o);
	o.algorithm = a;
	o.threads = threads;
	o.rule = rule;
	return sampler_f64(mask, m, &o);
}

/* The points of d, sorted (jitter none: one point per element). */
static double *sorted_xy(const struct drawn *d)
{
	double *xy = malloc((2 * d->n + 1) * sizeof *xy);

	assert_non_null(xy);
	memcpy(xy, d->xy, 2 * d->n * sizeof *xy);
	qsort(xy, d->n, 2 * sizeof *xy, pair_cmp);
	return xy;
}

/* frs_draw of n, also when it makes no samples (about n: n 1 may). */
static struct drawn draw_any(const frs_sampler *s, uint64_t n, uint64_t seed)
{
	struct drawn d = { 0, NULL, NULL, NULL };
	uint64_t c = 0;
	size_t cnt = 0;
	frs_error e;

	assert_int_equal(frs_count(s, n, seed, &c, &e), FRS_OK);
	d.xy = malloc((2 * c + 1) * sizeof *d.xy);
	assert_non_null(d.xy);
	assert_int_equal(frs_draw(s, n, seed, d.xy, NULL, (size_t)c, &cnt, &e),
	    FRS_OK);
	assert_int_equal(cnt, c);
	d.n = cnt;
	return d;
}

/* Whether every point of the sorted set a (na) is in the sorted b. */
static int subset(const double *a, size_t na, const double *b, size_t nb)
{
	size_t j = 0;

	for (size_t i = 0; i < na; i++) {
		while (j < nb && pair_cmp(&b[2 * j], &a[2 * i]) < 0)
			j++;
		if (j == nb || pair_cmp(&b[2 * j], &a[2 * i]) != 0)
			return 0;
	}
	return 1;
}

/* Exactly n for several maps, seeds and counts, in frs_count and
 * frs_draw; the exact set nests with the default one (a subset of it
 * when the default has more, else a superset). */
static void test_exact_counts(void **state)
{
	static const char *const maps[] = { "blob", "ramp", "sky", "const" };
	static const uint64_t ns[] = { 1, 37, 1024, 4099 };

	(void)state;
	for (size_t mi = 0; mi < 4; mi++) {
		struct frs_imap m;
		frs_sampler *ex, *def;
		assert_int_equal(imap_load(maps[mi], 0, 0, 0, &m), 0);
		ex = exact_sampler(&m, FRS_ALG_SORTED, 1, FRS_RULE_EXACT);
		def = exact_sampler(&m, FRS_ALG_SORTED, 1, FRS_RULE_UNBIASED);
		for (size_t ni = 0; ni < 4; ni++)
			for (uint64_t seed = 1; seed <= 3; seed++) {
				uint64_t n = ns[ni], c = 0;
				struct drawn de, dd;
				double *a, *b;
				frs_error e;
				assert_int_equal(frs_count(ex, n, seed, &c, &e),
				    FRS_OK);
				if (c != n)
					print_error("%s n %llu seed %llu: %llu\n",
					    maps[mi], (unsigned long long)n,
					    (unsigned long long)seed,
					    (unsigned long long)c);
				assert_int_equal(c, n);
				de = draw(ex, &n, 1, seed, 0);
				dd = draw_any(def, n, seed);
				assert_int_equal(de.n, n);
				a = sorted_xy(&de);
				b = sorted_xy(&dd);
				if (dd.n >= n)
					assert_true(subset(a, de.n, b, dd.n));
				else
					assert_true(subset(b, dd.n, a, de.n));
				free(a);
				free(b);
				drawn_free(&de);
				drawn_free(&dd);
			}
		frs_sampler_free(ex);
		frs_sampler_free(def);
		imap_free(&m);
	}
}

/* The same samples for every algorithm (as sets; in order for every
 * thread count) and as frs-sample --exact-count, also progressive, each
 * step exact and nested. */
static void test_exact_same(void **state)
{
	static const enum frs_algorithm algs[] = { FRS_ALG_SORTED,
	    FRS_ALG_NAIVE, FRS_ALG_STACK, FRS_ALG_LEVEL1, FRS_ALG_LEVEL2 };
	static const uint64_t steps[] = { 100, 1000, 3000 };
	uint64_t n = 3000;
	struct drawn d0, d;
	double *a, *b;
	frs_sampler *s;
	struct frs_options xo;

	(void)state;
	frs_options_init(&xo);
	xo.rule = FRS_RULE_EXACT;
	s = exact_sampler(&blob, FRS_ALG_SORTED, 1, FRS_RULE_EXACT);
	compare(s, &blob, &xo, &n, 1, 5, 1, "-i blob --exact-count");
	compare(s, &blob, &xo, steps, 3, 6, 0,
	    "-i blob --exact-count -j 2");
	d0 = draw(s, &n, 1, 5, 0);
	assert_int_equal(d0.n, n);
	a = sorted_xy(&d0);
	/* Progressive: each step exactly, the last the set of n. */
	d = draw(s, steps, 3, 5, 0);
	assert_int_equal(d.n, 3000);
	for (size_t i = 0; i < d.n; i++)
		assert_true(d.step[i] == (i < 100 ? 0u : i < 1000 ? 1u : 2u));
	b = sorted_xy(&d);
	assert_memory_equal(a, b, 2 * n * sizeof *a);
	free(b);
	drawn_free(&d);
	frs_sampler_free(s);
	for (size_t ai = 0; ai < 5; ai++) {
		struct drawn d1;
		s = exact_sampler(&blob, algs[ai], 1, FRS_RULE_EXACT);
		d1 = draw(s, &n, 1, 5, 0);
		frs_sampler_free(s);
		s = exact_sampler(&blob, algs[ai], 3, FRS_RULE_EXACT);
		d = draw(s, &n, 1, 5, 0);
		frs_sampler_free(s);
		assert_int_equal(d.n, n);
		assert_int_equal(d1.n, n);
		assert_memory_equal(d.xy, d1.xy, 2 * n * sizeof *d.xy);
		b = sorted_xy(&d);
		assert_memory_equal(a, b, 2 * n * sizeof *a);
		free(b);
		drawn_free(&d);
		drawn_free(&d1);
	}
	free(a);
	drawn_free(&d0);
}

/* A brute-force oracle: on a small matrix and map, every window
 * element's key (v + u) / (4^l I) over every level l (one with plain
 * tiles), u its coin, sorted; the n smallest are the exact set. */
struct keyed {
	double key;
	uint64_t l, x, y;
};

static int key_cmp(const void *a, const void *b)
{
	const struct keyed *p = a, *q = b;

	return p->key < q->key ? -1 : p->key > q->key;
}

static int elem_cmp(const void *a, const void *b)
{
	const uint64_t *p = a, *q = b;

	for (int i = 0; i < 3; i++)
		if (p[i] != q[i])
			return p[i] < q[i] ? -1 : 1;
	return 0;
}

/* Every window element of every level of lv over the 8 x 6 map m of the
 * matrix values v, keyed; their number. */
static uint64_t all_keys(const struct olev *lv, const struct frs_imap *m,
    const uint32_t *v, struct keyed *k)
{
	uint64_t nk = 0;

	for (unsigned i = 0; i < lv->n; i++) {
		const struct frs_setup *su = &lv->su[i];
		for (uint64_t y = 0; y < su->sh; y++)
			for (uint64_t x = 0; x < su->sw; x++) {
				uint64_t p = (y / su->ns) * 8 + x / su->ns;
				double imp = m->v[p];
				double u = frs_rand01(su->seed, FRS_STREAM_COIN,
				    y * su->sw + x);
				if (imp > 0.0 && frs_cell_here(su->lev, su->level, p))
					k[nk++] = (struct keyed){ ((double)v[
					    frs_matrix_index(su, x, y)] + u) /
					    (su->lfac * imp * su->iscale), i, x, y };
			}
	}
	return nk;
}

/* The level index and window element of each drawn point, as (l, x, y). */
static void elems_of(const struct olev *lv, const struct drawn *d,
    uint64_t *got)
{
	for (size_t i = 0; i < d->n; i++) {
		uint64_t px = (uint64_t)(d->xy[2 * i] * 8.0);
		uint64_t py = (uint64_t)(d->xy[2 * i + 1] * 6.0), l = 0;
		while (!frs_cell_here(lv->su[l].lev, lv->su[l].level, py * 8 + px))
			l++;
		got[3 * i] = l;
		got[3 * i + 1] = (uint64_t)(d->xy[2 * i] * (double)lv->su[l].sw);
		got[3 * i + 2] = (uint64_t)(d->xy[2 * i + 1] *
		    (double)lv->su[l].sh);
	}
}

static void test_exact_oracle(void **state)
{
	static const uint64_t ns[] = { 1, 10, 50, 200, 1000 };
	uint32_t *v = malloc(64 * 64 * sizeof *v);
	struct frs_imap m;
	struct frs_rng r;
	frs_mask *mk;
	frs_error e;
	unsigned most = 0;

	(void)state;
	assert_non_null(v);
	for (uint32_t i = 0; i < 64 * 64; i++)
		v[i] = i;
	frs_rng_init(&r, 77, 0);
	for (uint32_t i = 64 * 64 - 1; i > 0; i--) {
		uint32_t j = (uint32_t)(frs_rng_next64(&r) % (i + 1)), t = v[i];
		v[i] = v[j];
		v[j] = t;
	}
	assert_int_equal(frs_mask_wrap(&mk, v, 64, 64, &e), FRS_OK);
	assert_int_equal(imap_alloc(&m, 8, 6), 0);
	for (uint32_t i = 0; i < 8 * 6; i++)	/* some zeros, one bright */
		m.v[i] = i % 7 == 3 ? 0.0 : i == 20 ? 9.0 :
		    0.05 + frs_rng_next01(&r);
	for (int levels = 0; levels < 2; levels++)
	for (size_t ni = 0; ni < 5; ni++)
		for (uint64_t seed = 1; seed <= 3; seed++) {
			struct frs_options o;
			struct frs_setup su;
			struct olev lv;
			struct drawn d;
			struct keyed *k;
			uint64_t n = ns[ni], nk, *got, *want;
			frs_sampler *s;
			frs_options_init(&o);
			o.rule = FRS_RULE_EXACT;
			o.level_blur = 0.25;	/* each pixel its own level */
			o.tiling = levels ? FRS_TILING_LEVELS : FRS_TILING_PLAIN;
			assert_int_equal(frs_sampler_new_f64(&s, mk, m.v, 8, 6, 0,
			    &o, &e), FRS_OK);
			assert_int_equal(api_setup(s, n, seed, &su), 0);
			oracle_levels_of(&m, &o, &su, 64.0 * 64.0, &lv);
			most = lv.n > most ? lv.n : most;
			k = malloc(lv.n * su.sw * su.sh * sizeof *k);
			assert_non_null(k);
			nk = all_keys(&lv, &m, v, k);
			qsort(k, nk, sizeof *k, key_cmp);
			assert_true(nk > n);
			want = malloc(3 * n * sizeof *want);
			got = malloc(3 * n * sizeof *got);
			assert_true(want && got);
			for (uint64_t i = 0; i < n; i++) {
				want[3 * i] = k[i].l;
				want[3 * i + 1] = k[i].x;
				want[3 * i + 2] = k[i].y;
			}
			d = draw(s, &n, 1, seed, 0);
			assert_int_equal(d.n, n);
			elems_of(&lv, &d, got);
			qsort(want, n, 3 * sizeof *want, elem_cmp);
			qsort(got, n, 3 * sizeof *got, elem_cmp);
			assert_memory_equal(want, got, 3 * n * sizeof *got);
			drawn_free(&d);
			frs_levels_free(&lv.plan);
			free(want);
			free(got);
			free(k);
			frs_sampler_free(s);
		}
	/* the levels were tried: several at some count */
	assert_true(most >= 3);
	imap_free(&m);
	frs_mask_free(mk);
	free(v);
}

TU_MAIN(setup, teardown,
	cmocka_unit_test(test_exact_counts),
	cmocka_unit_test(test_exact_same),
	cmocka_unit_test(test_exact_oracle))
