/*
 * Threshold matrices at the extremes of size: the smallest the generator
 * makes (2 cells a side), odd and prime sides, 3-D, and a 1024x1024 crop
 * of the shipped matrix; their preparation (minmap, sorted lists, .frp)
 * and Forced Random Sampling with them.  The oracles:
 *   - every matrix is a permutation of 0 .. N-1 (a table of seen values);
 *   - with p = 1 and exact forces each value goes to a free cell of least
 *     force (Listing 3.1), the force of the values before it summed here
 *     from f(r) = exp(-sqrt(2 r)), r the toroidal distance;
 *   - minmap levels and sorted lists by brute force;
 *   - a window of whole tiles gives floor(T) values of each tile plus a
 *     coin: exactly n for an integer T, binomial otherwise; every
 *     implementation gives the same elements.
 */
#include "testutil.h"
#include "frsutil.h"
#include "hard.h"
#include "frd-gen/frdgen.h"
#include "sample/frpio.h"

/* ---- permutations and the least-force rule -------------------------- */

static void perm_ok(const struct frs_matrix *m)
{
	tu_assert_permutation(m);
	assert_int_equal(frd_check_permutation(m, "m"), 0);
}

static void params(struct frdgen_params *pr, uint32_t w, uint32_t h,
    uint32_t d, double p, double tol, uint64_t seed)
{
	tu_frdgen_params(pr, w, h, d, p, tol, seed);
	/* The thesis's force, which least_force_ok sums. */
	pr->force = FRDGEN_FORCE_EXP;
	pr->s = pr->q = 0.5;
}

static double tdist(uint32_t a, uint32_t b, uint32_t n)
{
	uint32_t d = a > b ? a - b : b - a;
	return n - d < d ? n - d : d;
}

/* The force at cell c of the values below v: f(r) = exp(-sqrt(2 r)). */
static double force(const struct frs_matrix *m, const uint32_t *cell,
    uint32_t v, uint32_t c)
{
	uint32_t cx = c % m->w, cy = c / m->w % m->h, cz = c / m->w / m->h;
	long double f = 0;

	for (uint32_t k = 0; k < v; k++) {
		uint32_t o = cell[k];
		double dx = tdist(cx, o % m->w, m->w);
		double dy = tdist(cy, o / m->w % m->h, m->h);
		double dz = tdist(cz, o / m->w / m->h, m->d);
		f += expl(-sqrtl(2 * sqrtl(dx * dx + dy * dy + dz * dz)));
	}
	return (double)f;
}

/* p = 1, exact: value v sits on a free cell of least force. */
static void least_force_ok(const struct frs_matrix *m)
{
	uint32_t *cell = malloc(m->n * sizeof *cell);

	for (uint32_t c = 0; c < m->n; c++)
		cell[m->v[c]] = c;
	for (uint32_t v = 1; v < m->n; v++) {
		double got = force(m, cell, v, cell[v]), best = INFINITY;
		for (uint32_t w = v; w < m->n; w++)
			best = fmin(best, force(m, cell, v, cell[w]));
		if (!(got <= best + 1e-12 * (1 + best))) {
			print_error("%ux%ux%u: value %u has force %.17g, a free "
			    "cell %.17g\n", m->w, m->h, m->d, v, got, best);
			fail();
		}
	}
	free(cell);
}

static void tiny_matrices(void **state)
{
	static const uint32_t sz[][3] = { { 2, 2, 1 }, { 2, 3, 1 },
	    { 3, 2, 1 }, { 3, 3, 1 }, { 2, 17, 1 }, { 17, 2, 1 },
	    { 5, 7, 1 }, { 2, 2, 2 }, { 3, 2, 2 }, { 2, 5, 3 } };
	(void)state;

	for (size_t i = 0; i < sizeof sz / sizeof *sz; i++)
		for (uint64_t seed = 1; seed <= 4; seed++)
			for (int mode = 0; mode < 3; mode++) {
				struct frdgen_params pr;
				struct frs_matrix m;
				params(&pr, sz[i][0], sz[i][1], sz[i][2],
				    mode ? 1.0 : 0.5, mode == 2 ? 0.0 : 1e-3, seed);
				if (frdgen_run(&pr, &m, NULL) != 0)
					print_error("%s\n", frs_errmsg());
				assert_non_null(m.v);
				assert_true(m.w == sz[i][0] && m.h == sz[i][1] &&
				    m.d == sz[i][2] && m.n == (size_t)m.w * m.h * m.d);
				perm_ok(&m);
				if (mode == 2)
					least_force_ok(&m);
				frd_free(&m);
			}
}

/* A side of 1 is refused by name; so is a zero one. */
static void too_small(void **state)
{
	struct frdgen_params pr;
	(void)state;

	params(&pr, 1, 4, 1, 0.5, 1e-3, 1);
	assert_int_equal(frdgen_check(&pr), -1);
	params(&pr, 4, 0, 1, 0.5, 1e-3, 1);
	assert_int_equal(frdgen_check(&pr), -1);
	params(&pr, 2, 2, 1, 0.5, 1e-3, 1);
	assert_int_equal(frdgen_check(&pr), 0);
}

/* ---- preparation -------------------------------------------------------- */

/* Minmap levels and sorted lists against brute force. */
static void prep_ok(const struct frs_matrix *m, uint32_t block)
{
	struct frs_prep p;

	assert_int_equal(frs_prepare(&p, m, 1, block), 0);
	for (unsigned l = 1; l < p.nlev; l++) {
		uint32_t w = m->w >> l, h = m->h >> l, b = 1u << l;
		for (uint32_t y = 0; y < h; y++)
			for (uint32_t x = 0; x < w; x++) {
				uint32_t mn = UINT32_MAX;
				for (uint32_t j = 0; j < b; j++)
					for (uint32_t i = 0; i < b; i++) {
						uint32_t v = m->v[(y * b + j) * m->w +
						    x * b + i];
						mn = v < mn ? v : mn;
					}
				assert_int_equal(p.lev[l][y * w + x], mn);
			}
	}
	/* the levels go on while both sides are at least 1 */
	assert_true((m->w >> p.nlev) == 0 || (m->h >> p.nlev) == 0);
	for (uint32_t by = 0; by < m->h / block; by++)
		for (uint32_t bx = 0; bx < m->w / block; bx++) {
			size_t base = ((size_t)by * (m->w / block) + bx) * block *
			    block;
			for (uint32_t k = 0; k < block * block; k++) {
				uint32_t i = p.sidx[base + k];
				uint32_t v = m->v[(by * block + i / block) * m->w +
				    bx * block + i % block];
				assert_int_equal(p.sval[base + k], v);
				if (k > 0)
					assert_true(p.sval[base + k - 1] < v);
			}
		}
	frs_prep_free(&p);
}

static void tiny_prep(void **state)
{
	static const uint32_t sz[][3] = { { 2, 2, 2 }, { 2, 2, 1 }, { 4, 2, 2 },
	    { 2, 8, 2 }, { 8, 2, 1 }, { 4, 4, 4 }, { 1, 1, 1 } };
	struct frs_matrix m = { .dims = 2, .w = 2, .h = 2, .d = 1, .n = 4 };
	uint32_t v[4] = { 1, 3, 0, 2 };
	struct frs_prep p;
	(void)state;

	/* by hand: [1 3; 0 2], one level of minima, one sorted block */
	m.v = v;
	assert_int_equal(frs_prepare(&p, &m, 1, 2), 0);
	assert_int_equal(p.nlev, 2);
	assert_int_equal(p.lev[1][0], 0);
	assert_int_equal(p.sval[0], 0);
	assert_int_equal(p.sidx[0], 2);
	assert_int_equal(p.sval[3], 3);
	assert_int_equal(p.sidx[3], 1);
	frs_prep_free(&p);
	assert_int_equal(frs_prepare(&p, &m, 0, 4), -1);
	assert_err_has("do not fit");
	for (size_t i = 0; i < sizeof sz / sizeof *sz; i++) {
		struct frs_matrix r;
		tu_perm_matrix(&r, sz[i][0], sz[i][1], 40 + i);
		prep_ok(&r, sz[i][2]);
		frd_free(&r);
	}
	/* odd sides: no minmap, no lists, a message saying why */
	{
		struct frs_matrix r;
		tu_perm_matrix(&r, 3, 5, 47);
		assert_int_equal(frs_prepare(&p, &r, 1, 0), -1);
		assert_err_has("3x5", "power-of-two");
		assert_int_equal(frs_prepare(&p, &r, 0, 0), 0);
		frs_prep_free(&p);
		frd_free(&r);
	}
}

/* A .frp of a 2x2 matrix: written and read back, lists and checksum. */
static void tiny_frp(void **state)
{
	static const uint32_t blocks[2] = { 1, 2 };
	struct frs_matrix m, back;
	struct frs_prep p, q;
	const char *path = tu_path("t.frp");
	uint32_t w, h;
	uint64_t sum;
	FILE *fp;
	(void)state;

	tu_perm_matrix(&m, 2, 2, 48);
	fp = fopen(path, "wb");
	assert_non_null(fp);
	assert_int_equal(frp_write(fp, path, path, &m, 1, blocks, 2), 0);
	assert_int_equal(fclose(fp), 0);
	assert_int_equal(frp_is(path), 1);
	assert_int_equal(frp_info(path, &w, &h, &sum), 0);
	assert_true(w == 2 && h == 2 && sum == frd_checksum(&m));
	assert_int_equal(frp_read(path, &back, &q, 2), 0);
	assert_memory_equal(back.v, m.v, 4 * sizeof *m.v);
	assert_int_equal(frs_prepare(&p, &m, 1, 2), 0);
	assert_int_equal(q.block, 2);
	assert_true(q.nlev == p.nlev && q.lev[1][0] == p.lev[1][0]);
	assert_memory_equal(q.sval, p.sval, 4 * sizeof *p.sval);
	assert_memory_equal(q.sidx, p.sidx, 4 * sizeof *p.sidx);
	frs_prep_free(&p);
	frs_prep_free(&q);
	frd_free(&back);
	frd_free(&m);
}

/* ---- sampling with tiny and large matrices -------------------------- */

static int ecmp(const void *a, const void *b)
{
	const struct frs_elem *x = a, *y = b;
	if (x->y != y->y)
		return x->y < y->y ? -1 : 1;
	return x->x < y->x ? -1 : x->x > y->x;
}

static struct frs_elem *elems(const struct frs_result *r)
{
	struct frs_elem *e = malloc((r->count + 1) * sizeof *e);
	uint64_t k = 0;

	for (uint64_t c = 0; c < r->nchunk; c++)
		for (uint64_t i = 0; i < r->chunk[c].n; i++)
			e[k++] = r->chunk[c].e[i];
	qsort(e, k, sizeof *e, ecmp);
	return e;
}

/* Every implementation the matrix allows gives Sorted's elements. */
static void all_agree(const struct frs_imap *map, const struct frs_matrix *m,
    uint64_t n, uint64_t seed, uint64_t *count)
{
	struct frs_setup s;
	struct frs_result ref;
	struct frs_elem *re;
	int pow2 = !(m->w & (m->w - 1)) && !(m->h & (m->h - 1));

	hd_frs(map, m, n, seed, pow2 ? FRS_SORTED : FRS_NAIVE, 0, &s, &ref);
	hd_points(&s, map, &ref, NULL);
	re = elems(&ref);
	for (int a = 0; pow2 && a < FRS_NALGO; a++) {
		struct frs_result r;
		struct frs_elem *e;
		if (a == FRS_SORTED)
			continue;	/* the reference */
		hd_frs(map, m, n, seed, (enum frs_impl)a, 0, &s, &r);
		assert_true(r.count == ref.count);
		e = elems(&r);
		assert_memory_equal(e, re, r.count * sizeof *e);
		free(e);
		frs_result_free(&r);
	}
	*count = ref.count;
	free(re);
	frs_result_free(&ref);
}

/* |count - n| within 5 sqrt(n) + 2 and a bias of slack. */
static void about_n(const char *what, uint64_t count, double n, double slack)
{
	print_message("%s: %llu of %.0f\n", what, (unsigned long long)count, n);
	assert_true(fabs((double)count - n) <= 5 * sqrt(n) + 2 + slack);
}

/*
 * A 2x2 matrix, constant 128^2 map, n = 1024: n_s = 2, the window 256^2
 * is 128^2 whole tiles and T = 1024 * 4 / 256^2 = 1/16: each tile passes
 * its value 0 by a coin of 1/16, 16384 coins.  A 3x5 matrix (Naive only):
 * T = 15 n / 256^2, and the window holds parts of tiles at two of its
 * edges, up to 3/256 + 5/256 of n more or less.  A 4x2 matrix and a blob
 * (T at most 8/64): n in expectation.
 */
static void tiny_sampling(void **state)
{
	struct frs_matrix m;
	struct frs_imap map;
	uint64_t count;
	(void)state;

	frs_set_threads(2);
	hd_map(&map, 128, 128, 1.0);
	tu_perm_matrix(&m, 2, 2, 49);
	all_agree(&map, &m, 1024, 50, &count);
	hd_binom("2x2 matrix: tiles passing", (double)count, 16384, 1.0 / 16);
	frd_free(&m);
	tu_perm_matrix(&m, 3, 5, 51);
	all_agree(&map, &m, 1024, 52, &count);
	about_n("3x5 matrix", count, 1024, 1024 * 8.0 / 256);
	frd_free(&m);
	imap_free(&map);
	tu_map_of("blob:sigma=0.1", 64, 64, &map);
	tu_perm_matrix(&m, 4, 2, 53);
	all_agree(&map, &m, 3000, 54, &count);
	about_n("4x2 matrix, blob", count, 3000, 0);
	frd_free(&m);
	imap_free(&map);
}

/*
 * The top-left 1024x1024 of the shipped 2048^2 matrix, ranked: a
 * permutation that keeps the order of the values it holds.  Constant
 * 64^2 map, n = 2^14: w_min = 1024, n_s = 16, the window is the matrix,
 * T = 2^14: exactly 2^14 samples.  A blob: every implementation agrees.
 */
static void large_crop(void **state)
{
	struct frs_matrix full, m;
	struct frs_imap map;
	struct frs_setup s;
	struct frs_result r;
	uint64_t count;
	(void)state;

	if (frd_read("data/default.frd", &full) != 0) {
		print_error("%s\n", frs_errmsg());
		fail();
	}
	assert_true(full.w == 2048 && full.h == 2048);
	assert_int_equal(frd_alloc(&m, 2, 1024, 1024, 1, "crop"), 0);
	for (uint32_t y = 0; y < 1024; y++)
		memcpy(m.v + (size_t)y * 1024, full.v + (size_t)y * 2048,
		    1024 * sizeof *m.v);
	assert_int_equal(frs_matrix_rank(&m, NULL), FRS_OK);
	perm_ok(&m);
	for (uint64_t t = 0; t < 20000; t++) {
		uint32_t a = (uint32_t)(frs_rand64(55, 0, 2 * t) % m.n);
		uint32_t b = (uint32_t)(frs_rand64(55, 0, 2 * t + 1) % m.n);
		uint32_t fa = full.v[(size_t)(a / 1024) * 2048 + a % 1024];
		uint32_t fb = full.v[(size_t)(b / 1024) * 2048 + b % 1024];
		assert_true((m.v[a] < m.v[b]) == (fa < fb));
	}
	frd_free(&full);
	hd_map(&map, 64, 64, 1.0);
	hd_frs(&map, &m, 1 << 14, 56, FRS_SORTED, 0, &s, &r);
	assert_true(s.ns == 16 && s.sw == 1024);
	assert_true(r.count == 1 << 14);
	hd_points(&s, &map, &r, NULL);
	frs_result_free(&r);
	imap_free(&map);
	tu_map_of("blob", 64, 64, &map);
	all_agree(&map, &m, 4000, 57, &count);
	about_n("crop, blob", count, 4000, 0);
	imap_free(&map);
	frd_free(&m);
}

TU_MAIN(NULL, tu_teardown,
	cmocka_unit_test(tiny_matrices),
	cmocka_unit_test(too_small),
	cmocka_unit_test(tiny_prep),
	cmocka_unit_test(tiny_frp),
	cmocka_unit_test(tiny_sampling),
	cmocka_unit_test(large_crop))
