/* Forced Random Sampling on OpenCL (PoCL in make check): every
 * implementation gives frs_sample's elements in frs_sample's order, Flat 1
 * gives Stack's, with progressive steps, both threshold rules, and window
 * math past 32 bits. */
#include "testutil.h"
#include "frsutil.h"
#include "oclutil.h"
#include "formats/frdio.h"
#include "sample/frscore.h"
#include "sample/frscl.h"
#include "maps/imap.h"
#include "base/par.h"
#include "base/rng.h"

static int teardown(void **state)
{
	frscl_release(&tu_ocl);
	return tu_ocl_teardown(state);
}

static void same(const struct frs_result *a, const struct frs_result *b,
    const char *what)
{
	struct frs_elem *ea, *eb;
	if (a->count != b->count)
		print_error("%s: %llu elements vs %llu\n", what,
		    (unsigned long long)a->count, (unsigned long long)b->count);
	assert_true(a->count == b->count);
	ea = tu_elems(a, 0);
	eb = tu_elems(b, 0);
	for (uint64_t i = 0; i < a->count; i++)
		if (memcmp(&ea[i], &eb[i], sizeof *ea) != 0) {
			print_error("%s: element %llu: (%u %u %u) vs (%u %u %u)\n",
			    what, (unsigned long long)i, ea[i].x, ea[i].y,
			    ea[i].step, eb[i].x, eb[i].y, eb[i].step);
			fail();
		}
	free(ea);
	free(eb);
}

/* Every implementation on four maps, two counts, single and progressive
 * steps, both rules and every jitter. */
static void implementations_match_cpu(void **state)
{
	static const char *maps[] = { "const", "blob:x=0.3,sigma=0.1", "ramp",
	    "sky" };
	static const uint64_t st1[] = { 300, 700, 1000 };
	static const uint64_t st2[] = { 500, 1000, 4000, 20000 };
	struct frs_matrix m;
	struct frs_prep pm;
	(void)state;

	tu_perm_matrix(&m, 256, 256, 3);
	assert_int_equal(frs_prepare(&pm, &m, 1, 0), 0);
	for (unsigned mi = 0; mi < 4; mi++)
		for (unsigned v = 0; v < 4; v++) {
			const uint64_t *steps = v & 1 ? st2 : st1;
			unsigned nsteps = v & 1 ? 4 : 3;
			struct frs_imap map;
			struct frs_setup s;
			struct frs_prep ps;
			struct frs_result cpu[FRS_NALGO];
			uint32_t b;
			char what[128];
			if (v < 2) {		/* one step */
				steps += nsteps - 1;
				nsteps = 1;
			}
			tu_map_of(maps[mi], 24 + 8 * mi, 20, &map);
			assert_int_equal(frs_setup(&s, &map, &m, steps[nsteps - 1],
			    mi == 3 ? 4.0 : 8.0, 11 + 3 * mi + v), 0);
			s.rule = (mi + v) % 2 ? FRS_THESIS : FRS_UNBIASED;
			s.jitter = (enum frs_place)((mi + v) % 3);
			s.tiles = v % 2 ? FRS_TILES_SHUFFLE : FRS_TILES_PLAIN;
			b = s.ns < m.w ? s.ns : m.w;
			b = b < frs_tile_max_block(&s) ? b : frs_tile_max_block(&s);
			assert_int_equal(frs_prepare(&ps, &m, 0, b), 0);
			frs_set_threads(1 + v % 2);
			for (int a = 0; a < FRS_NALGO; a++)
				assert_int_equal(frs_sample(&s, &map, a == FRS_SORTED ?
				    &ps : &pm, (enum frs_impl)a, steps, nsteps, 0,
				    &cpu[a]), 0);
			for (int a = 0; a <= FRS_FLAT1; a++) {
				struct frs_result r;
				int ref = a == FRS_FLAT1 ? FRS_STACK : a;
				snprintf(what, sizeof what, "%s on %s, n %llu, %u steps, "
				    "%s", frs_impl_name((enum frs_impl)a), maps[mi],
				    (unsigned long long)steps[nsteps - 1], nsteps,
				    s.rule == FRS_THESIS ? "thesis" : "unbiased");
				if (frs_sample_cl(&tu_ocl, &s, &map, a == FRS_SORTED ? &ps :
				    &pm, a, steps, nsteps, 0, &r) != 0)
					print_error("%s: %s\n", what, frs_errmsg());
				assert_non_null(r.chunk);
				same(&r, &cpu[ref], what);
				/* The points too (jitter is the host's). */
				if (r.count > 0) {
					struct frs_elem *e0 = tu_elems(&r, 0), *e1 = tu_elems(&cpu[ref], 0);
					for (uint64_t i = 0; i < r.count; i += 97) {
						double x0, y0, x1, y1;
						frs_point(&s, &e0[i], &x0, &y0);
						frs_point(&s, &e1[i], &x1, &y1);
						assert_true(x0 == x1 && y0 == y1);
					}
					free(e0);
					free(e1);
				}
				frs_result_free(&r);
				/* Counting alone gives the same count. */
				assert_int_equal(frs_sample_cl(&tu_ocl, &s, &map,
				    a == FRS_SORTED ? &ps : &pm, a, steps, nsteps, 1,
				    &r), 0);
				assert_true(r.count == cpu[ref].count);
				frs_result_free(&r);
			}
			for (int a = 0; a < FRS_NALGO; a++)
				frs_result_free(&cpu[a]);
			frs_prep_free(&ps);
			imap_free(&map);
		}
	frs_prep_free(&pm);
	frd_free(&m);
	frs_set_threads(1);
}

/* n = 2^24 on a 128x128 map: windows past 2^16 a side, products of
 * window sizes past 2^32 (the authors' code overflowed there); Sorted
 * counts as the CPU does, and Flat 1's candidate lists, sized from
 * counts, hold 2^22 samples and more. */
static void large_counts(void **state)
{
	struct frs_matrix m;
	struct frs_imap map;
	struct frs_setup s;
	struct frs_prep ps, pm;
	struct frs_result a, b;
	uint64_t n = (uint64_t)1 << 24, n2 = (uint64_t)1 << 23;
	(void)state;

	tu_perm_matrix(&m, 256, 256, 5);
	tu_map_of("blob", 128, 128, &map);
	assert_int_equal(frs_setup(&s, &map, &m, n, 8.0, 3), 0);
	assert_true(s.sw * s.sh > UINT32_MAX);
	assert_int_equal(frs_prepare(&ps, &m, 0, s.ns < m.w ? s.ns : m.w), 0);
	assert_int_equal(frs_sample(&s, &map, &ps, FRS_SORTED, &n, 1, 1, &a), 0);
	assert_int_equal(frs_sample_cl(&tu_ocl, &s, &map, &ps, FRS_SORTED, &n, 1, 1,
	    &b), 0);
	assert_true(a.count == b.count);
	assert_true(a.count > n - n / 100 && a.count < n + n / 100);
	frs_result_free(&a);
	frs_result_free(&b);
	/* Flat 1 at 2^23, against Sorted. */
	assert_int_equal(frs_setup(&s, &map, &m, n2, 8.0, 4), 0);
	frs_prep_free(&ps);
	assert_int_equal(frs_prepare(&ps, &m, 0, s.ns < m.w ? s.ns : m.w), 0);
	assert_int_equal(frs_prepare(&pm, &m, 1, 0), 0);
	assert_int_equal(frs_sample(&s, &map, &ps, FRS_SORTED, &n2, 1, 1, &a),
	    0);
	assert_int_equal(frs_sample_cl(&tu_ocl, &s, &map, &pm, FRS_FLAT1, &n2, 1, 1,
	    &b), 0);
	assert_true(a.count == b.count);
	frs_result_free(&a);
	frs_result_free(&b);
	frs_prep_free(&pm);
	frs_prep_free(&ps);
	imap_free(&map);
	frd_free(&m);
}

/* What cannot run is refused with a message. */
static void refusals(void **state)
{
	struct frs_matrix m;
	struct frs_imap map;
	struct frs_setup s;
	struct frs_prep p;
	struct frs_result r;
	uint64_t n = 1000, bad[2] = { 500, 400 };
	(void)state;

	tu_perm_matrix(&m, 64, 64, 1);
	tu_map_of("blob", 16, 16, &map);
	assert_int_equal(frs_setup(&s, &map, &m, n, 8.0, 1), 0);
	assert_int_equal(frs_prepare(&p, &m, 0, 0), 0);
	assert_int_equal(frs_sample_cl(&tu_ocl, &s, &map, &p, FRS_FLAT1, &n, 1, 0,
	    &r), -1);
	assert_err_has("no minmap");
	/* Sorted without lists walks the minmap, which p lacks too; lists
	 * of blocks larger than n_s do not fit. */
	assert_int_equal(frs_sample_cl(&tu_ocl, &s, &map, &p, FRS_SORTED, &n, 1, 0,
	    &r), -1);
	assert_err_has("no minmap");
	frs_prep_free(&p);
	n = 10;
	assert_int_equal(frs_setup(&s, &map, &m, n, 8.0, 1), 0);
	assert_true(s.ns < 64);
	assert_int_equal(frs_prepare(&p, &m, 0, 64), 0);
	assert_int_equal(frs_sample_cl(&tu_ocl, &s, &map, &p, FRS_SORTED, &n, 1, 0,
	    &r), -1);
	assert_err_has("do not fit");
	n = 1000;
	assert_int_equal(frs_setup(&s, &map, &m, n, 8.0, 1), 0);
	assert_int_equal(frs_sample_cl(&tu_ocl, &s, &map, &p, FRS_NAIVE, bad, 2, 0,
	    &r), -1);
	assert_err_has("increase");
	/* The implementations' names, as frs-sample(1)'s -a spells them. */
	assert_string_equal(frs_impl_name(FRS_SORTED), "sorted");
	assert_string_equal(frs_impl_name(FRS_NAIVE), "naive");
	assert_string_equal(frs_impl_name(FRS_STACK), "stack");
	assert_string_equal(frs_impl_name(FRS_LEVEL1), "level1");
	assert_string_equal(frs_impl_name(FRS_LEVEL2), "level2");
	assert_string_equal(frs_impl_name(FRS_FLAT1), "flat1");
	assert_null(frs_names(FRS_NAMES_ALGORITHM)[FRS_FLAT1]);
	frs_prep_free(&p);
	imap_free(&map);
	frd_free(&m);
}

TU_MAIN(tu_ocl_setup, teardown,
	cmocka_unit_test(implementations_match_cpu),
	cmocka_unit_test(large_counts),
	cmocka_unit_test(refusals))
