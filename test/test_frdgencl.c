/* frd-gen on OpenCL (PoCL in make check): the same matrix as the CPU
 * generator, byte for byte, over sizes, seeds, candidate fractions,
 * tolerances, non-square and 3-D matrices; a permutation; checkpoints
 * and devices without fp64 refused with a message. */
#include "oclutil.h"
#include "frsutil.h"
#include "frd-gen/frdgen.h"
#include "frd-gen/frdgencl.h"

/* CPU and OpenCL give the same values for these parameters. */
static void same(const struct frdgen_params *pr)
{
	struct frs_matrix a, b;

	assert_int_equal(frdgen_run(pr, &a, NULL), 0);
	if (frdgen_run_cl(pr, &tu_ocl, &b, NULL) != 0)
		fail_msg("%s", frs_errmsg());
	assert_int_equal(a.n, b.n);
	if (memcmp(a.v, b.v, a.n * sizeof *a.v) != 0) {
		size_t i = 0;
		while (a.v[i] == b.v[i])
			i++;
		fail_msg("%ux%ux%u p=%g seed=%llu tol=%g reach=%g: cell %zu "
		    "differs (cpu %u, cl %u)", pr->w, pr->h, pr->d, pr->p,
		    (unsigned long long)pr->seed, pr->tol, pr->reach, i, a.v[i],
		    b.v[i]);
	}
	tu_assert_permutation(&b);
	frd_free(&a);
	frd_free(&b);
}

static void params(struct frdgen_params *pr, uint32_t w, uint32_t h,
    double p, uint64_t seed)
{
	frdgen_defaults(pr);
	pr->w = w;
	pr->h = h;
	pr->d = 1;
	pr->p = p;
	pr->seed = seed;
}

static void square_sizes(void **state)
{
	static const uint32_t sizes[] = { 16, 32, 64 };
	static const double ps[] = { 1.0, 0.5, 0.1, 0.01 };
	struct frdgen_params pr;
	(void)state;
	for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++)
		for (size_t j = 0; j < sizeof ps / sizeof ps[0]; j++)
			for (uint64_t seed = 1; seed <= (sizes[i] < 64 ? 3u : 1u);
			    seed++) {
				params(&pr, sizes[i], sizes[i], ps[j], seed);
				same(&pr);
			}
}

static void non_square(void **state)
{
	struct frdgen_params pr;
	(void)state;
	params(&pr, 48, 20, 0.5, 7);
	same(&pr);
	params(&pr, 20, 48, 0.25, 8);
	same(&pr);
	params(&pr, 37, 13, 1.0, 9);	/* partial tiles on both axes */
	same(&pr);
	params(&pr, 2, 2, 0.5, 1);
	same(&pr);
}

/* Exact forces (the whole torus every time), no reach, a wide and a
 * narrow radius, another force function: the window rules. */
static void radii(void **state)
{
	struct frdgen_params pr;
	(void)state;
	params(&pr, 48, 20, 1.0, 3);
	pr.tol = 0.0;
	same(&pr);
	params(&pr, 64, 64, 0.5, 4);
	pr.reach = 0.0;
	same(&pr);
	params(&pr, 64, 32, 0.5, 5);
	pr.tol = 0.3;
	pr.reach = 0.0;
	same(&pr);
	params(&pr, 32, 32, 0.2, 6);
	pr.s = 1.5;
	pr.q = 2.0;
	same(&pr);
	params(&pr, 40, 40, 0.5, 7);	/* the hard cut-off, no cap */
	pr.taper = 0;
	pr.cap = 0.0;
	same(&pr);
}

/* The authors' integer table: its ties and its reach. */
static void int32_field(void **state)
{
	struct frdgen_params pr;
	(void)state;
	params(&pr, 32, 32, 0.5, 1);
	pr.field = FRDGEN_FIELD_INT32;
	same(&pr);
	params(&pr, 48, 24, 0.5, 2);
	pr.field = FRDGEN_FIELD_INT32;
	same(&pr);
}

static void three_d(void **state)
{
	struct frdgen_params pr;
	(void)state;
	frdgen_defaults(&pr);
	pr.dims = 3;
	pr.w = pr.h = pr.d = 12;
	same(&pr);
	pr.w = 10;
	pr.h = 6;
	pr.d = 9;
	pr.p = 1.0;
	pr.seed = 2;
	same(&pr);
}

static void refusals(void **state)
{
	struct frdgen_params pr;
	struct frs_matrix m;
	struct ocl no64;
	(void)state;
	params(&pr, 16, 16, 0.5, 1);
	pr.checkpoint = tu_path("ck");
	assert_int_equal(frdgen_run_cl(&pr, &tu_ocl, &m, NULL), -1);
	assert_non_null(strstr(frs_errmsg(), "checkpoint"));
	pr.checkpoint = NULL;
	no64 = tu_ocl;
	no64.fp64 = 0;
	assert_int_equal(frdgen_run_cl(&pr, &no64, &m, NULL), -1);
	assert_non_null(strstr(frs_errmsg(), "cl_khr_fp64"));
	pr.p = 0.0;
	assert_int_equal(frdgen_run_cl(&pr, &tu_ocl, &m, NULL), -1);
	assert_non_null(strstr(frs_errmsg(), "share p"));
}

TU_MAIN(tu_ocl_setup, tu_ocl_teardown,
	cmocka_unit_test(square_sizes),
	cmocka_unit_test(non_square),
	cmocka_unit_test(radii),
	cmocka_unit_test(int32_field),
	cmocka_unit_test(three_d),
	cmocka_unit_test(refusals))
