/* Forced Random Sampling: setup against closed forms, every
 * implementation against Naive, and the statistics of what comes out. */
#include "testutil.h"
#include "frsutil.h"
#include "formats/frdio.h"
#include "sample/frscore.h"
#include "maps/imap.h"
#include "base/par.h"
#include "base/rng.h"

/* Listing 5.1 by hand: constant 128^2 map, n = 1024, sigma 8:
 * w_min = 8 sqrt(1024) = 256, n_s = 2, tau = 1024 * 2048^2 / 256^2. */
static void setup_closed_form(void **state)
{
	struct frs_matrix m = { .dims = 2, .w = 2048, .h = 2048, .d = 1,
	    .n = (size_t)2048 * 2048 };
	struct frs_imap map;
	struct frs_setup s;
	(void)state;

	tu_map_of("const", 128, 128, &map);
	assert_int_equal(frs_setup(&s, &map, &m, 1024, 8.0, 1), 0);
	assert_int_equal(s.ns, 2);
	assert_true(s.sw == 256 && s.sh == 256);
	assert_double_equal(s.tau, 65536.0, 1e-9);
	assert_int_equal(s.level0, 1);
	assert_true(s.wx % 2 == 0 && s.wx < 2048 && s.wy % 2 == 0);
	assert_double_equal(frs_unique(&s), 65536.0, 0);
	/* 2^34 samples: windows of 2^20 a side, 2^40 elements; 64-bit math
	 * keeps tau exact: 2^34 * 2^22 / 2^40. */
	assert_int_equal(frs_setup(&s, &map, &m, (uint64_t)1 << 34, 8.0, 1), 0);
	assert_int_equal(s.ns, 1 << 13);
	assert_true(s.sw == (uint64_t)1 << 20);
	assert_double_equal(s.tau, 65536.0, 1e-9);
	assert_int_equal(s.level0, 3);
	imap_free(&map);
	/* A 64 x 256 map: a = 4, the smaller side sets n_s. */
	tu_map_of("const", 64, 256, &map);
	assert_int_equal(frs_setup(&s, &map, &m, 4096, 8.0, 1), 0);
	/* w_min = 8 sqrt(4096 / 4) = 256 -> n_s = 4 */
	assert_int_equal(s.ns, 4);
	assert_true(s.sw == 256 && s.sh == 1024);
	imap_free(&map);
	/* The maximum over the mean widens the window (Eq. 4.9). */
	tu_map_of("ramp:from=0,to=2", 128, 128, &map);	/* mean 1, max ~2 */
	assert_int_equal(frs_setup(&s, &map, &m, 1024, 8.0, 1), 0);
	assert_int_equal(s.ns, 4);	/* 8 sqrt(1024 * 2) = 362 > 256 */
	imap_free(&map);
	tu_map_of("const", 16, 16, &map);
	assert_int_equal(frs_setup(&s, &map, &m, 0, 8.0, 1), -1);
	assert_int_equal(frs_setup(&s, &map, &m, 10, 0.5, 1), -1);
	imap_free(&map);
}

static void run(const struct frs_setup *s, const struct frs_imap *map,
    const struct frs_matrix *m, enum frs_impl a, const uint64_t *steps,
    unsigned nsteps, struct frs_result *r)
{
	struct frs_prep p;
	uint32_t b = s->ns < m->w ? s->ns : m->w, t = frs_tile_max_block(s);

	b = a == FRS_SORTED ? (b < t ? b : t) : 0;
	assert_int_equal(frs_prepare(&p, m, a != FRS_NAIVE && a != FRS_SORTED, b),
	    0);
	if (frs_sample(s, map, &p, a, steps, nsteps, 0, r) != 0)
		print_error("%s\n", frs_errmsg());
	assert_non_null(r->chunk);
	frs_prep_free(&p);
}

/* Case (mi, ni) of implementations_agree: its setup into s and Naive's
 * draw into ref, from the first seed from 7 + ni that draws any element:
 * at n = 1 some seeds draw none, and agreeing on none compares nothing. */
static void naive_case(size_t mi, size_t ni, const struct frs_imap *map,
    const struct frs_matrix *m, struct frs_setup *s, struct frs_result *ref)
{
	static const uint64_t ns[] = { 1, 37, 1000, 20000 };
	static const double sig[] = { 1, 2, 8, 16 };
	uint64_t n = ns[ni];

	for (uint64_t seed = 7 + ni;; seed++) {
		assert_true(seed < 7 + ni + 16);
		assert_int_equal(frs_setup(s, map, m, n, sig[(mi + ni) % 4],
		    seed), 0);
		s->rule = ni == 2 ? FRS_THESIS : FRS_UNBIASED;
		s->tiles = (mi + ni) % 2 ? FRS_TILES_SHUFFLE : FRS_TILES_PLAIN;
		frs_set_threads(1);
		run(s, map, m, FRS_NAIVE, &n, 1, ref);
		if (ref->count > 0)
			return;
		frs_result_free(ref);
	}
}

/* Every implementation, thread count, rule and tiling gives Naive's
 * elements. */
static void implementations_agree(void **state)
{
	static const char *maps[] = { "blob:x=0.3,sigma=0.1", "ramp", "const",
	    "sky", "aniso" };
	struct frs_matrix m;
	(void)state;

	tu_perm_matrix(&m, 256, 256, 3);
	for (size_t mi = 0; mi < 5; mi++)
		for (size_t ni = 0; ni < 4; ni++) {
			struct frs_imap map;
			struct frs_setup s;
			struct frs_result ref;
			struct frs_elem *re;
			uint64_t n;
			tu_map_of(maps[mi], 32 + 8 * (uint32_t)mi, 24, &map);
			naive_case(mi, ni, &map, &m, &s, &ref);
			n = s.n;
			re = tu_elems(&ref, 1);
			for (int a = 0; a < FRS_NALGO; a++) {
				struct frs_result r;
				struct frs_elem *e;
				if (a == FRS_NAIVE)
					continue;	/* the reference */
				frs_set_threads(1 + a % 3);
				run(&s, &map, &m, (enum frs_impl)a, &n, 1, &r);
				if (r.count != ref.count)
					print_error("%s %s n=%llu: %llu vs naive %llu\n",
					    frs_impl_name((enum frs_impl)a), maps[mi],
					    (unsigned long long)n,
					    (unsigned long long)r.count,
					    (unsigned long long)ref.count);
				assert_true(r.count == ref.count);
				e = tu_elems(&r, 1);
				assert_memory_equal(e, re, r.count * sizeof *e);
				free(e);
				frs_result_free(&r);
			}
			free(re);
			frs_result_free(&ref);
			imap_free(&map);
		}
	frd_free(&m);
	frs_set_threads(1);
}

/* Elements come in the same order for any thread count. */
static void thread_order(void **state)
{
	struct frs_matrix m;
	struct frs_imap map;
	struct frs_setup s;
	struct frs_result a, b;
	uint64_t n = 5000;
	(void)state;

	tu_perm_matrix(&m, 256, 256, 3);
	tu_map_of("blob", 64, 64, &map);
	assert_int_equal(frs_setup(&s, &map, &m, n, 8.0, 1), 0);
	frs_set_threads(1);
	run(&s, &map, &m, FRS_SORTED, &n, 1, &a);
	frs_set_threads(4);
	run(&s, &map, &m, FRS_SORTED, &n, 1, &b);
	assert_true(a.count == b.count);
	for (uint64_t c = 0; c < a.nchunk; c++) {
		assert_true(a.chunk[c].n == b.chunk[c].n);
		assert_memory_equal(a.chunk[c].e, b.chunk[c].e,
		    a.chunk[c].n * sizeof *a.chunk[c].e);
	}
	frs_result_free(&a);
	frs_result_free(&b);
	imap_free(&map);
	frd_free(&m);
	frs_set_threads(1);
}

/* Check the sorted lists of p (block b) against the definition: in
 * each block, values ascending, each the matrix value at its in-block
 * index, every index of the block once; with p->below, exactly the
 * elements of the block below it. */
static void check_lists(const struct frs_matrix *m, const struct frs_prep *p,
    uint32_t b)
{
	size_t bb = (size_t)b * b;
	unsigned char *seen = malloc(bb);

	assert_non_null(seen);
	for (uint32_t by = 0; by < m->h / b; by++)
		for (uint32_t bx = 0; bx < m->w / b; bx++) {
			size_t blk = (size_t)by * (m->w / b) + bx, base = p->soff[blk];
			size_t want = 0;
			for (size_t k = 0; k < bb; k++)
				want += m->v[((size_t)by * b + k / b) * m->w +
				    (size_t)bx * b + k % b] < p->below;
			assert_int_equal(p->soff[blk + 1] - base, want);
			memset(seen, 0, bb);
			for (size_t k = 0; k < want; k++) {
				uint32_t i = p->sidx[base + k];
				size_t at = ((size_t)by * b + i / b) * m->w +
				    (size_t)bx * b + i % b;
				assert_true(i < bb && !seen[i]);
				seen[i] = 1;
				assert_int_equal(p->sval[base + k], m->v[at]);
				if (k > 0)
					assert_true(p->sval[base + k - 1] <=
					    p->sval[base + k]);
			}
		}
	free(seen);
}

/* The block lists hold what they must for every block size of a
 * non-square matrix, on 1 and 3 threads: many small blocks (radix sorts
 * of block rows), few large ones (counting over the inverse of a
 * permutation, qsort of values with repeats). */
static void sorted_lists(void **state)
{
	struct frs_matrix m;
	(void)state;

	tu_perm_matrix(&m, 256, 128, 9);	/* b <= 2: more than 4096 blocks */
	for (int pass = 0; pass < 2; pass++) {
		for (uint32_t b = 1; b <= 128; b *= 2)
			for (int t = 1; t <= 3; t += 2) {
				struct frs_prep p;
				frs_set_threads(t);
				assert_int_equal(frs_prepare(&p, &m, 0, b), 0);
				check_lists(&m, &p, b);
				frs_prep_free(&p);
			}
		for (size_t i = 0; i < m.n; i++)	/* repeats: not a permutation */
			m.v[i] /= 3;
	}
	frs_set_threads(1);
	frd_free(&m);
}

/* The minmap: level l holds the least value of each 2^l x 2^l block,
 * against a brute-force minimum, on 1 and 3 threads, on a matrix whose
 * first levels are built in parallel (2^16 minima and more). */
static void minmap_levels(void **state)
{
	struct frs_matrix m;
	(void)state;

	tu_perm_matrix(&m, 1024, 512, 7);
	for (int t = 1; t <= 3; t += 2) {
		struct frs_prep p;
		frs_set_threads(t);
		assert_int_equal(frs_prepare(&p, &m, 1, 0), 0);
		assert_int_equal(p.nlev, 10);	/* down to 2 x 1 */
		for (unsigned l = 1; l < p.nlev; l++) {
			uint32_t w = m.w >> l, h = m.h >> l, s = 1u << l;
			for (uint32_t y = 0; y < h; y += 1 + h / 37)
				for (uint32_t x = 0; x < w; x += 1 + w / 41) {
					uint32_t lo = UINT32_MAX;
					for (uint32_t k = 0; k < s * s; k++) {
						uint32_t v = m.v[(size_t)(y * s + k / s) *
						    m.w + x * s + k % s];
						lo = v < lo ? v : lo;
					}
					assert_int_equal(p.lev[l][(size_t)y * w + x],
					    lo);
				}
		}
		frs_prep_free(&p);
	}
	frs_set_threads(1);
	frd_free(&m);
}

/* Lists of the values below a bound: exactly those elements, on 1 and 3
 * threads, for every block size, through the inverse (few values) and
 * by bands (a 32nd of them and more, 8 bands or more); complete lists
 * from half the values on, and when the values below repeat, lists of
 * either kind. */
static void lists_below(void **state)
{
	static const uint64_t below[] = { 0, 1, 37, 1000, 4000, 16383, 16384 };
	struct frs_matrix m;
	(void)state;

	tu_perm_matrix(&m, 256, 128, 5);
	for (int pass = 0; pass < 4; pass++) {
		frs_deal_below = pass % 2 ? 0 : (uint64_t)1 << 20;
		for (uint32_t b = 1; b <= 128; b *= 4)
			for (size_t i = 0; i < 7; i++) {
				struct frs_prep p;
				uint64_t want = below[i] < m.n / 2 ? below[i] :
				    FRS_ALL_VALUES;
				frs_set_threads(1 + 2 * (int)(i % 2));
				assert_int_equal(frs_prepare_below(&p, &m, 0, b,
				    below[i]), 0);
				assert_true(p.below == want || (pass >= 2 &&
				    below[i] > 0 && p.below == FRS_ALL_VALUES));
				check_lists(&m, &p, b);
				frs_prep_free(&p);
			}
		if (pass == 1)	/* 0 and 1 twice */
			for (size_t i = 0; i < m.n; i++)
				m.v[i] = m.v[i] < 4 ? m.v[i] / 2 : m.v[i];
	}
	frs_deal_below = (uint64_t)1 << 20;
	frs_set_threads(1);
	frd_free(&m);
}

/* Sorted over lists of the values its thresholds reach (frs_lim_most)
 * gives Naive's elements, progressive steps too; lists one value short
 * are refused. */
static void sorted_below(void **state)
{
	static const char *maps[] = { "blob", "ramp", "sky" };
	uint64_t steps[2] = { 300, 3000 };
	struct frs_matrix m;
	(void)state;

	tu_perm_matrix(&m, 256, 256, 3);
	for (size_t mi = 0; mi < 3; mi++)
		for (unsigned ns = 1; ns <= 2; ns++) {
			struct frs_imap map;
			struct frs_setup s;
			struct frs_result ref, r;
			struct frs_prep p;
			uint64_t lim;
			uint32_t blk;
			tu_map_of(maps[mi], 32, 32, &map);
			assert_int_equal(frs_setup(&s, &map, &m, steps[ns - 1], 4.0,
			    11), 0);
			run(&s, &map, &m, FRS_NAIVE, steps, ns, &ref);
			lim = frs_lim_most(&s, frs_tau(&s, steps[ns - 1]));
			blk = s.ns < m.w ? s.ns : m.w;
			assert_true(lim > 1 && lim < m.n / 2);
			assert_int_equal(frs_prepare_below(&p, &m, 0, blk, lim), 0);
			assert_true(p.below == lim);
			assert_int_equal(frs_sample(&s, &map, &p, FRS_SORTED, steps,
			    ns, 0, &r), 0);
			tu_same_set(&ref, &r);
			frs_result_free(&r);
			p.below = lim - 1;
			assert_int_equal(frs_sample(&s, &map, &p, FRS_SORTED, steps,
			    ns, 0, &r), -1);
			assert_non_null(strstr(frs_errmsg(), "the lists hold"));
			frs_clearerr();
			frs_prep_free(&p);
			frs_result_free(&ref);
			imap_free(&map);
		}
	frd_free(&m);
}

/* Progressive: the union of the steps is the one-shot set at the last
 * count, and each step adds about its share. */
static void progressive(void **state)
{
	struct frs_matrix m;
	struct frs_imap map;
	struct frs_setup s;
	struct frs_result one, prog;
	uint64_t steps[3] = { 256, 1024, 4096 }, cnt[3] = { 0 };
	struct frs_elem *a, *b;
	(void)state;

	tu_perm_matrix(&m, 256, 256, 3);
	tu_map_of("blob", 64, 64, &map);
	assert_int_equal(frs_setup(&s, &map, &m, 4096, 8.0, 2), 0);
	run(&s, &map, &m, FRS_SORTED, steps + 2, 1, &one);
	run(&s, &map, &m, FRS_SORTED, steps, 3, &prog);
	assert_true(one.count == prog.count);
	a = tu_elems(&one, 1);
	b = tu_elems(&prog, 1);
	for (uint64_t i = 0; i < one.count; i++) {
		assert_true(a[i].x == b[i].x && a[i].y == b[i].y);
		cnt[b[i].step]++;
	}
	print_message("steps: %llu %llu %llu\n", (unsigned long long)cnt[0],
	    (unsigned long long)cnt[1], (unsigned long long)cnt[2]);
	assert_true(llabs((long long)cnt[0] - 256) < 40);
	assert_true(llabs((long long)(cnt[0] + cnt[1]) - 1024) < 80);
	free(a);
	free(b);
	frs_result_free(&one);
	frs_result_free(&prog);
	imap_free(&map);
	frd_free(&m);
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(setup_closed_form),
	cmocka_unit_test(implementations_agree),
	cmocka_unit_test(thread_order),
	cmocka_unit_test(progressive),
	cmocka_unit_test(sorted_lists),
	cmocka_unit_test(minmap_levels),
	cmocka_unit_test(lists_below),
	cmocka_unit_test(sorted_below))
