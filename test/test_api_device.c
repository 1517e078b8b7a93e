/*
 * The public API's OpenCL devices (frs_device_*, frs_sampler_set_device)
 * on PoCL's CPU device: a sampler on a device gives the CPU's samples bit
 * for bit, Flat 1 gives Stack's, a sampler taken back to the CPU its own
 * again; the device's times add up every call of a run (one a level);
 * the errors.  The helpers: apiutil.h.
 */
#include "apiutil.h"
#include "sample/frscl.h"

static frs_device *dev;

static int dev_setup(void **state)
{
	frs_error e;

	if (setup(state) < 0)
		return -1;
	if (frs_device_open(&dev, -1, &e) != FRS_OK) {
		fprintf(stderr, "frs_device_open: %s\n", e.message);
		return -1;
	}
	return 0;
}

static int dev_teardown(void **state)
{
	frs_device_free(dev);
	return teardown(state);
}

/* A sampler of blob with algorithm a and tiling t, on the device when
 * flags >= 0 (with those flags). */
static frs_sampler *sampler_on(enum frs_algorithm a,
    enum frs_tiling_mode t, int flags)
{
	struct frs_options o;
	frs_sampler *s;

	frs_options_init(&o);
	o.algorithm = a;
	o.tiling = t;
	o.jitter = FRS_JIT_RANDOM;
	s = sampler_f64(mask, &blob, &o);
	if (flags >= 0)
		EXPECT(FRS_OK, frs_sampler_set_device(s, dev, flags, E));
	return s;
}

/* Every algorithm on the device against the CPU (levels and plain
 * tiles), Flat 1 against Stack, and a sampler taken back to the CPU. */
static void test_same_samples(void **state)
{
	static const enum frs_algorithm algs[] = { FRS_ALG_SORTED,
	    FRS_ALG_NAIVE, FRS_ALG_STACK, FRS_ALG_LEVEL1, FRS_ALG_LEVEL2 };
	frs_sampler *cpu, *gpu;

	(void)state;
	assert_non_null(frs_device_name(dev));
	assert_true(frs_device_name(dev)[0] != '\0');
	for (size_t i = 0; i < sizeof algs / sizeof *algs; i++) {
		enum frs_tiling_mode t = i % 2 ? FRS_TILING_PLAIN :
		    FRS_TILING_LEVELS;
		cpu = sampler_on(algs[i], t, -1);
		gpu = sampler_on(algs[i], t, 0);
		same_draw(cpu, gpu, 3000, 5);
		frs_sampler_free(gpu);
		if (algs[i] == FRS_ALG_STACK) {	/* Flat 1 gives Stack's */
			gpu = sampler_on(FRS_ALG_SORTED, t, FRS_DEVICE_FLAT1);
			same_draw(cpu, gpu, 3000, 5);
			EXPECT(FRS_OK, frs_sampler_set_device(gpu, NULL, 0, E));
			frs_sampler_free(cpu);
			cpu = sampler_on(FRS_ALG_SORTED, t, -1);
			same_draw(cpu, gpu, 3000, 5);	/* Sorted's, on the CPU */
			frs_sampler_free(gpu);
		}
		frs_sampler_free(cpu);
	}
}

/* The times of a draw of several levels: every level's call counted,
 * not the last one's alone (each at least as long as its own kernel). */
static void test_times(void **state)
{
	struct frs_device_times t0, t1;
	struct frscl_times last;
	struct frs_level_info lv[8];
	frs_sampler *s = sampler_on(FRS_ALG_SORTED, FRS_TILING_LEVELS, 0);
	unsigned nl = 0;
	uint64_t n = 200000;
	struct drawn d;

	(void)state;
	EXPECT(FRS_OK, frs_sampler_levels(s, n, 1, lv, 8, &nl, E));
	assert_true(nl >= 2);
	frs_device_times(dev, &t0);
	d = draw(s, &n, 1, 1, 0);
	frs_device_times(dev, &t1);
	frscl_last_times(&last);	/* the last level's call */
	assert_true(t1.upload > t0.upload && t1.kernel > t0.kernel &&
	    t1.download > t0.download && t1.build >= t0.build);
	assert_true(t1.kernel - t0.kernel > last.kernel &&
	    t1.upload - t0.upload > last.upload);
	drawn_free(&d);
	frs_sampler_free(s);
	frs_device_times(NULL, &t0);
	assert_true(t0.build == 0 && t0.upload == 0 && t0.kernel == 0 &&
	    t0.download == 0);
}

static void test_device_errors(void **state)
{
	frs_device *d = (frs_device *)&d;
	frs_sampler *s = sampler_on(FRS_ALG_SORTED, FRS_TILING_LEVELS, -1);

	(void)state;
	EXPECT(FRS_E_ARG, frs_device_open(NULL, -1, E));
	EXPECT(FRS_E_ARG, frs_device_open(&d, -2, E));
	assert_null(d);
	EXPECT(FRS_E_IO, frs_device_open(&d, 999, E));
	assert_null(d);
	EXPECT(FRS_E_ARG, frs_sampler_set_device(NULL, dev, 0, E));
	EXPECT(FRS_E_ARG, frs_sampler_set_device(s, dev, 2, E));
	EXPECT(FRS_E_ARG, frs_sampler_set_device(s, NULL, FRS_DEVICE_FLAT1,
	    E));
	assert_null(frs_device_name(NULL));
	frs_device_free(NULL);
	frs_sampler_free(s);
}

TU_MAIN(dev_setup, dev_teardown,
	cmocka_unit_test(test_same_samples),
	cmocka_unit_test(test_times),
	cmocka_unit_test(test_device_errors))
