/* 3-D Forced Random Sampling: setup against closed forms, sorted against
 * naive, and the statistics of what comes out against the volume. */
#include "testutil.h"
#include "frsutil.h"
#include "formats/frdio.h"
#include "sample/frs3.h"
#include "base/par.h"
#include "base/rng.h"
#include "maps/vol.h"
#include "maps/mapload.h"

#include <math.h>

/* A random permutation of w*h*d values: enough for agreement and for
 * density; an FRD matrix only improves the spacing. */
static void perm3(struct frs_matrix *m, uint32_t w, uint32_t h, uint32_t d,
    uint64_t seed)
{
	assert_int_equal(frd_alloc(m, 3, w, h, d, ""), 0);
	tu_perm_fill(m, seed);
}

static void vol_of(const char *spec, uint32_t w, uint32_t h, uint32_t d,
    struct frs_vol *v)
{
	if (vol_load(spec, w, h, d, 0, v) != 0)
		print_error("%s\n", frs_errmsg());
	assert_non_null(v->v);
}

/* Setup by hand: constant 16^3 volume, n = 512, sigma 8: the window
 * needs 8^3 * 512 = 2^18 elements, 64^3, so n_s = 4; tau = n S_M / S_W. */
static void setup_closed_form(void **state)
{
	struct frs_matrix m = { .dims = 3, .w = 64, .h = 64, .d = 64,
	    .n = (size_t)1 << 18 };
	struct frs_vol v;
	struct frs3_setup s;
	(void)state;

	vol_of("const", 16, 16, 16, &v);
	assert_int_equal(frs3_setup(&s, &v, &m, 512, 8.0, 1), 0);
	assert_int_equal(s.ns, 4);
	assert_true(s.sw == 64 && s.sh == 64 && s.sd == 64);
	assert_double_equal(s.tau, 512.0, 1e-12);
	assert_true(s.wx % 4 == 0 && s.wy % 4 == 0 && s.wz % 4 == 0);
	assert_true(s.wx < 64 && s.wy < 64 && s.wz < 64);
	assert_double_equal(frs3_unique(&s), 512.0, 0);
	/* One more sample needs the next power of two. */
	assert_int_equal(frs3_setup(&s, &v, &m, 513, 8.0, 1), 0);
	assert_int_equal(s.ns, 8);
	/* 2^40 samples: 2^49 window elements, far past 32 bits; tau stays
	 * exact, 2^40 2^18 / 2^51. */
	assert_int_equal(frs3_setup(&s, &v, &m, (uint64_t)1 << 40, 8.0, 1), 0);
	assert_int_equal(s.ns, 1 << 13);
	assert_true(s.sw == (uint64_t)1 << 17);
	assert_double_equal(s.tau, 128.0, 1e-12);
	vol_free(&v);
	/* 8 x 16 x 32: a = 8, the smallest side sets n_s: (8 n_s)^3 8 >=
	 * 8^3 4096 gives n_s = 8. */
	vol_of("const", 8, 16, 32, &v);
	assert_int_equal(frs3_setup(&s, &v, &m, 4096, 8.0, 1), 0);
	assert_int_equal(s.ns, 8);
	assert_true(s.sw == 64 && s.sh == 128 && s.sd == 256);
	/* A 2-D matrix, no count, sigma below 1. */
	m.dims = 2;
	assert_int_equal(frs3_setup(&s, &v, &m, 10, 8.0, 1), -1);
	m.dims = 3;
	assert_int_equal(frs3_setup(&s, &v, &m, 0, 8.0, 1), -1);
	assert_int_equal(frs3_setup(&s, &v, &m, 10, 0.5, 1), -1);
	vol_free(&v);
}

/* Two results hold the same elements (in the same order unless sort);
 * both are released. */
static void same_elems(struct frs3_result *a, struct frs3_result *b,
    int sort)
{
	TU_SAME_ELEMS(struct frs3_elem, a, b, sort ? tu_elem3_cmp : NULL);
	frs3_result_free(a);
	frs3_result_free(b);
}

static void sample(const struct frs3_setup *s, const struct frs_vol *v,
    const struct frs_matrix *m, enum frs_impl a, const uint64_t *steps,
    unsigned nsteps, struct frs3_result *r)
{
	struct frs3_prep p;

	assert_int_equal(frs3_prepare(&p, m, a == FRS_SORTED ?
	    frs3_block(s) : 0), 0);
	if (frs3_sample(s, v, &p, a, steps, nsteps, 0, r) != 0)
		print_error("%s\n", frs_errmsg());
	assert_non_null(r->chunk);
	frs3_prep_free(&p);
}

/* Sorted gives naive's elements, for either rule, several counts
 * (n_s below, at and above the matrix side), progressive steps and
 * thread counts. */
static void sorted_agrees(void **state)
{
	static const char *specs[] = { "blob3:x=0.3,sigma=0.1", "ramp3",
	    "shell3:floor=0" };
	static const uint64_t ns[] = { 1, 300, 5000, 40000 };
	struct frs_matrix m;
	(void)state;

	perm3(&m, 16, 16, 16, 5);
	for (size_t si = 0; si < 3; si++)
		for (size_t ni = 0; ni < 4; ni++)
			for (int rule = 0; rule < 2; rule++) {
				struct frs_vol v;
				struct frs3_setup s;
				struct frs3_result a, b;
				uint64_t steps[2] = { ns[ni] / 3 + 1, ns[ni] + 1 };
				vol_of(specs[si], 8, 8, 8, &v);
				assert_int_equal(frs3_setup(&s, &v, &m, steps[1], 4.0,
				    ni + 7), 0);
				s.rule = rule ? FRS_THESIS : FRS_UNBIASED;
				frs_set_threads(1);
				sample(&s, &v, &m, FRS_NAIVE, steps, 2, &a);
				frs_set_threads(2);
				sample(&s, &v, &m, FRS_SORTED, steps, 2, &b);
				assert_true(a.count > 0);
				same_elems(&a, &b, 1);
				vol_free(&v);
			}
	frd_free(&m);
	frs_set_threads(1);
}

/* The same elements, in the same order, for any thread count. */
static void threads_same_order(void **state)
{
	struct frs_matrix m;
	struct frs_vol v;
	struct frs3_setup s;
	struct frs3_result a, b;
	uint64_t n = 20000;
	(void)state;

	perm3(&m, 32, 32, 32, 2);
	vol_of("blob3:sigma=0.2,floor=0.05", 12, 10, 9, &v);
	assert_int_equal(frs3_setup(&s, &v, &m, n, 8.0, 3), 0);
	frs_set_threads(1);
	sample(&s, &v, &m, FRS_SORTED, &n, 1, &a);
	frs_set_threads(2);
	sample(&s, &v, &m, FRS_SORTED, &n, 1, &b);
	same_elems(&a, &b, 0);
	vol_free(&v);
	frd_free(&m);
	frs_set_threads(1);
}

/* Statistics of one large set by voxel: count, and the mean and second
 * moment of each coordinate of the voxel centres the samples fall in,
 * against the volume's own.  FRS promises n I / sum I samples per voxel
 * in expectation; where they sit inside a voxel is the matrix's business
 * (with n_s at the matrix side every voxel sees the same tile). */
struct mom {
	double n, m1[3], m2[3];
};

static void volume_moments(const struct frs_vol *v, struct mom *o)
{
	const uint32_t side[3] = { v->w, v->h, v->d };
	double tot = 0.0;

	memset(o, 0, sizeof *o);
	for (uint64_t i = 0; i < (uint64_t)v->w * v->h * v->d; i++) {
		const uint64_t c[3] = { i % v->w, i / v->w % v->h, i / v->w / v->h };
		tot += v->v[i];
		for (int a = 0; a < 3; a++) {
			double x = (c[a] + 0.5) / side[a];
			o->m1[a] += v->v[i] * x;
			o->m2[a] += v->v[i] * x * x;
		}
	}
	for (int a = 0; a < 3; a++) {
		o->m1[a] /= tot;
		o->m2[a] /= tot;
	}
}

static void point_moments(const struct frs3_setup *s,
    const struct frs3_result *r, struct mom *o)
{
	const uint32_t side[3] = { s->iw, s->ih, s->id };

	memset(o, 0, sizeof *o);
	for (uint64_t c = 0; c < r->nchunk; c++)
		for (uint64_t i = 0; i < r->chunk[c].n; i++) {
			double p[3];
			frs3_point(s, &r->chunk[c].e[i], p);
			for (int a = 0; a < 3; a++) {
				double x = (floor(p[a] * side[a]) + 0.5) / side[a];
				assert_true(p[a] >= 0.0 && p[a] < 1.0);
				o->m1[a] += x;
				o->m2[a] += x * x;
			}
			o->n++;
		}
	for (int a = 0; a < 3; a++) {
		o->m1[a] /= o->n;
		o->m2[a] /= o->n;
	}
}

/* Density follows importance: over 8 seeds of 20000 samples each, the
 * count is n within 1 % and centroid and spread are the volume's within
 * a few standard errors (FRS sets are more even than random ones, so
 * the random-sampling error is an upper bound). */
static void density_follows_importance(void **state)
{
	static const char *specs[] = { "blob3:x=0.35,y=0.6,z=0.45,sigma=0.12",
	    "ramp3:from=0.1,to=2", "ramp3:axis=0", "shell3" };
	static const enum frs_place jit[] = { FRS_PLACE_CENTRE,
	    FRS_PLACE_RANDOM, FRS_PLACE_HALTON, FRS_PLACE_RANDOM };
	struct frs_matrix m;
	(void)state;

	perm3(&m, 32, 32, 32, 11);
	for (size_t si = 0; si < 4; si++) {
		struct frs_vol v;
		struct mom want, got, sum = { 0 };
		uint64_t n = 20000;
		vol_of(specs[si], 16, 16, 16, &v);
		volume_moments(&v, &want);
		for (uint64_t seed = 1; seed <= 8; seed++) {
			struct frs3_setup s;
			struct frs3_result r;
			assert_int_equal(frs3_setup(&s, &v, &m, n, 4.0, seed), 0);
			s.jitter = jit[si];
			sample(&s, &v, &m, FRS_SORTED, &n, 1, &r);
			point_moments(&s, &r, &got);
			sum.n += got.n;
			for (int a = 0; a < 3; a++) {
				sum.m1[a] += got.m1[a] / 8;
				sum.m2[a] += got.m2[a] / 8;
			}
			frs3_result_free(&r);
		}
		assert_true(fabs(sum.n / (8.0 * (double)n) - 1.0) < 0.01);
		for (int a = 0; a < 3; a++) {
			double var = want.m2[a] - want.m1[a] * want.m1[a];
			double se = sqrt(var / sum.n);
			if (fabs(sum.m1[a] - want.m1[a]) > 5 * se ||
			    fabs(sum.m2[a] - want.m2[a]) > 10 * se)
				fail_msg("%s axis %d: mean %.5f want %.5f, m2 %.5f want "
				    "%.5f (se %.5f)", specs[si], a, sum.m1[a],
				    want.m1[a], sum.m2[a], want.m2[a], se);
		}
		vol_free(&v);
	}
	frd_free(&m);
}

/* Zero-importance voxels get nothing; a voxel's points stay inside it
 * whatever the jitter. */
static void zero_voxels_and_jitter(void **state)
{
	struct frs_matrix m;
	struct frs_vol v;
	uint64_t n = 5000;
	(void)state;

	perm3(&m, 16, 16, 16, 4);
	assert_int_equal(vol_alloc(&v, 8, 8, 8), 0);
	for (uint64_t i = 0; i < 512; i++)
		v.v[i] = (i / 64) % 2 ? 1.0 : 0.0;	/* odd z slices only */
	for (int j = 0; j < 3; j++) {
		struct frs3_setup s;
		struct frs3_result r;
		assert_int_equal(frs3_setup(&s, &v, &m, n, 8.0, 9), 0);
		s.jitter = (enum frs_place)j;
		sample(&s, &v, &m, FRS_SORTED, &n, 1, &r);
		assert_true(r.count > n / 2);
		for (uint64_t c = 0; c < r.nchunk; c++)
			for (uint64_t i = 0; i < r.chunk[c].n; i++) {
				double p[3];
				const struct frs3_elem *e = &r.chunk[c].e[i];
				frs3_point(&s, e, p);
				assert_true((uint32_t)(p[2] * 8) % 2 == 1);
				assert_true((uint64_t)(p[0] * (double)s.sw) == e->x);
				assert_true((uint64_t)(p[1] * (double)s.sh) == e->y);
				assert_true((uint64_t)(p[2] * (double)s.sd) == e->z);
				assert_double_equal(frs3_pdf(&s, &v, e), 2.0, 1e-12);
			}
		frs3_result_free(&r);
	}
	vol_free(&v);
	frd_free(&m);
}

/* Importance only matters in ratio: a volume of denormals, one of 1e300
 * and one of 1 give the same elements (power-of-two scaling). */
static void extreme_importance(void **state)
{
	static const double scale[] = { 0x1p-1070, 1e300, 1.0 };
	struct frs_matrix m;
	struct frs3_elem *ref = NULL;
	uint64_t cref = 0, n = 3000;
	(void)state;

	perm3(&m, 16, 16, 16, 6);
	for (int k = 0; k < 3; k++) {
		struct frs_vol v;
		struct frs3_setup s;
		struct frs3_result r;
		struct frs3_elem *e;
		assert_int_equal(vol_alloc(&v, 4, 4, 4), 0);
		for (uint64_t i = 0; i < 64; i++)
			v.v[i] = scale[k] * (double)(1 + i % 4);
		assert_int_equal(frs3_setup(&s, &v, &m, n, 8.0, 2), 0);
		assert_true(isfinite(s.tau) && s.tau > 0.0);
		sample(&s, &v, &m, FRS_SORTED, &n, 1, &r);
		TU_ELEMS(e, &r, tu_elem3_cmp);
		if (k == 0) {
			ref = e;
			cref = r.count;
		} else {
			assert_true(r.count == cref);
			assert_memory_equal(ref, e, cref * sizeof *e);
			free(e);
		}
		frs3_result_free(&r);
		vol_free(&v);
	}
	free(ref);
	frd_free(&m);
}

/* 2^22 samples of a one-voxel volume: a window of 2048^3 = 2^33
 * elements, whose size overflows 32-bit products; tau = 2^22 2^12 / 2^33
 * = 2 exactly, so the values 0 and 1 of each of the 2^21 tiles pass and
 * the count (counted, not stored) is n exactly. */
static void huge_count(void **state)
{
	struct frs_matrix m;
	struct frs_vol v;
	struct frs3_setup s;
	struct frs3_prep p;
	struct frs3_result r;
	uint64_t n = (uint64_t)1 << 22;
	(void)state;

	perm3(&m, 16, 16, 16, 8);
	vol_of("const", 1, 1, 1, &v);
	assert_int_equal(frs3_setup(&s, &v, &m, n, 8.0, 1), 0);
	assert_int_equal(s.ns, 2048);
	assert_double_equal(s.tau, 2.0, 0);
	assert_int_equal(frs3_prepare(&p, &m, frs3_block(&s)), 0);
	frs_set_threads(2);
	assert_int_equal(frs3_sample(&s, &v, &p, FRS_SORTED, &n, 1, 1, &r), 0);
	assert_true(r.count == n);
	assert_true(r.chunk[0].n == 0);		/* counted, not stored */
	frs3_result_free(&r);
	frs3_prep_free(&p);
	/* 2^40 samples of the same 16^3 matrix would visit 2^39 blocks:
	 * refused up front, as is naive's 2^39 elements at 2^36. */
	n = (uint64_t)1 << 40;
	assert_int_equal(frs3_setup(&s, &v, &m, n, 8.0, 1), 0);
	assert_int_equal(frs3_prepare(&p, &m, frs3_block(&s)), 0);
	assert_int_equal(frs3_sample(&s, &v, &p, FRS_SORTED, &n, 1, 1, &r), -1);
	assert_non_null(strstr(frs_errmsg(), "larger matrix"));
	assert_int_equal(frs3_sample(&s, &v, &p, FRS_NAIVE, &n, 1, 1, &r), -1);
	assert_non_null(strstr(frs_errmsg(), "sorted would not"));
	frs3_prep_free(&p);
	frs_set_threads(1);
	vol_free(&v);
	frd_free(&m);
}

/* Bad arguments: unsupported implementations, blocks that do not fit,
 * non-power-of-two matrices for sorted. */
static void bad_arguments(void **state)
{
	struct frs_matrix m, odd;
	struct frs_vol v;
	struct frs3_setup s;
	struct frs3_prep p;
	struct frs3_result r;
	uint64_t n = 100;
	(void)state;

	perm3(&m, 16, 16, 16, 1);
	perm3(&odd, 12, 16, 16, 1);
	vol_of("const", 4, 4, 4, &v);
	assert_int_equal(frs3_setup(&s, &v, &m, n, 8.0, 1), 0);
	assert_int_equal(frs3_prepare(&p, &m, 0), 0);
	assert_int_equal(frs3_sample(&s, &v, &p, FRS_STACK, &n, 1, 0, &r), -1);
	assert_non_null(strstr(frs_errmsg(), "naive and sorted"));
	assert_int_equal(frs3_sample(&s, &v, &p, FRS_SORTED, &n, 1, 0, &r), -1);
	frs3_prep_free(&p);
	assert_int_equal(frs3_prepare(&p, &odd, 4), -1);
	assert_non_null(strstr(frs_errmsg(), "power-of-two"));
	assert_int_equal(frs3_prepare(&p, &m, 32), -1);
	/* Naive takes any matrix. */
	assert_int_equal(frs3_setup(&s, &v, &odd, n, 8.0, 1), 0);
	assert_int_equal(frs3_prepare(&p, &odd, 0), 0);
	assert_int_equal(frs3_sample(&s, &v, &p, FRS_NAIVE, &n, 1, 0, &r), 0);
	assert_true(r.count > 50 && r.count < 150);
	frs3_result_free(&r);
	frs3_prep_free(&p);
	vol_free(&v);
	frd_free(&odd);
	frd_free(&m);
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(setup_closed_form),
	cmocka_unit_test(sorted_agrees),
	cmocka_unit_test(threads_same_order),
	cmocka_unit_test(density_follows_importance),
	cmocka_unit_test(zero_voxels_and_jitter),
	cmocka_unit_test(extreme_importance),
	cmocka_unit_test(huge_count),
	cmocka_unit_test(bad_arguments))
